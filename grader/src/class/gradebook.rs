// INSTRUCTOR ONLY: left out of the handout, with the rest of `grader class`.
//! `DIR/gradebook.csv`: the class's grades as a spreadsheet and an LMS's import take them.

use std::collections::BTreeMap;
use std::path::Path;

use super::{StudentGrade, export};

/// `gradebook.csv`: a header row, then one row per student: name, student id, email, their
/// submission's folder, total, possible, then the points of every exercise and of every check
/// (the columns of every student's checks, in course order), and why a submission was not
/// graded. Empty where a student has no such check (not graded). A submission without named
/// students (a folder of folders) is one row, named as its folder; one with several (a group
/// on Gradescope) is a row per student, as an LMS's import takes them.
pub fn write_gradebook(file: &Path, grades: &[StudentGrade]) -> Result<(), String> {
    let mut exercises: Vec<String> = Vec::new();
    let mut checks: Vec<String> = Vec::new();
    for grade in grades {
        for check in &grade.checks {
            if !exercises.contains(&check.exercise) {
                exercises.push(check.exercise.clone());
            }
            if !checks.contains(&check.id) {
                checks.push(check.id.clone());
            }
        }
    }
    let mut writer = csv::Writer::from_path(file).map_err(|e| format!("{}: {e}", file.display()))?;
    let mut header: Vec<String> =
        ["student", "sid", "email", "submission", "total", "possible"].map(str::to_owned).into();
    header.extend(exercises.iter().cloned());
    header.extend(checks.iter().cloned());
    header.push("not graded".to_owned());
    writer.write_record(&header).map_err(|e| e.to_string())?;
    for grade in grades {
        let by_exercise: BTreeMap<&str, u32> = grade.checks.iter().fold(BTreeMap::new(), |mut sums, c| {
            *sums.entry(c.exercise.as_str()).or_default() += c.points;
            sums
        });
        let by_check: BTreeMap<&str, u32> = grade.checks.iter().map(|c| (c.id.as_str(), c.points)).collect();
        let mut points = vec![grade.score.to_string(), grade.max_score.to_string()];
        points.extend(
            exercises.iter().map(|e| by_exercise.get(e.as_str()).map_or(String::new(), u32::to_string)),
        );
        points.extend(checks.iter().map(|c| by_check.get(c.as_str()).map_or(String::new(), u32::to_string)));
        points.push(text_cell(grade.error.as_deref().unwrap_or_default()));
        let folder = export::Submitter { name: grade.student.clone(), ..Default::default() };
        for who in if grade.submitters.is_empty() { std::slice::from_ref(&folder) } else { &grade.submitters }
        {
            let mut row = [&who.name, &who.sid, &who.email, &grade.student].map(|t| text_cell(t)).to_vec();
            row.extend(points.iter().cloned());
            writer.write_record(&row).map_err(|e| e.to_string())?;
        }
    }
    writer.flush().map_err(|e| format!("{}: {e}", file.display()))
}

/// A cell of text (a name, a folder, a reason) as a spreadsheet shows it: one that starts like a
/// formula (`=`, `+`, `-`, `@`, a tab or a return) starts with `'`, which shows it as text
/// (a student names themselves on Gradescope, and an export's folder is named by its zip).
fn text_cell(text: &str) -> String {
    if text.starts_with(['=', '+', '-', '@', '\t', '\r']) { format!("'{text}") } else { text.to_owned() }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::class::CheckGrade;

    fn check(id: &str, points: u32, max_points: u32) -> CheckGrade {
        let exercise = id.rsplit_once('/').map_or(id, |(e, _)| e).to_owned();
        CheckGrade {
            id: id.into(),
            exercise,
            points,
            max_points,
            status: "passed".into(),
            cause: None,
            picture: None,
        }
    }

    #[test]
    fn the_gradebook_has_a_row_per_student_and_a_column_per_exercise_and_check() {
        let dir = std::env::temp_dir().join(format!("raylab-gradebook-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let student = |name: &str, checks: Vec<CheckGrade>, error: Option<&str>| StudentGrade {
            error: error.map(str::to_owned),
            ..StudentGrade::new(name, checks)
        };
        let grades = [
            student("ada", vec![check("02/hit_plane/unit", 1, 1), check("02/hit_plane/grazing", 2, 2)], None),
            student(
                "Lovelace, A.",
                vec![check("02/hit_plane/unit", 0, 1), check("02/hit_plane/grazing", 2, 2)],
                None,
            ),
            student("bob", Vec::new(), Some("no lectures/ folder")),
            student("=HYPERLINK(\"http://x\")", Vec::new(), Some("-")),
            StudentGrade {
                submitters: vec![
                    export::Submitter {
                        name: "Ben Ng".into(),
                        sid: "2001".into(),
                        email: "ben@example.edu".into(),
                    },
                    export::Submitter { name: "Cy Ortiz".into(), sid: "2002".into(), email: String::new() },
                ],
                ..student("submission_102", vec![check("02/hit_plane/unit", 1, 1)], None)
            },
        ];
        let file = dir.join("gradebook.csv");
        write_gradebook(&file, &grades).unwrap();
        let text = std::fs::read_to_string(&file).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines[0],
            "student,sid,email,submission,total,possible,02/hit_plane,02/hit_plane/unit,02/hit_plane/grazing,not graded"
        );
        assert_eq!(lines[1], "ada,,,ada,3,3,3,1,2,");
        // A name with a comma is quoted, as spreadsheets read it.
        assert_eq!(lines[2], "\"Lovelace, A.\",,,\"Lovelace, A.\",2,3,2,0,2,");
        assert_eq!(lines[3], "bob,,,bob,0,0,,,,no lectures/ folder");
        // A name a spreadsheet would take for a formula is text.
        assert_eq!(
            lines[4],
            "\"'=HYPERLINK(\"\"http://x\"\")\",,,\"'=HYPERLINK(\"\"http://x\"\")\",0,0,,,,'-"
        );
        // A group's submission: a row per student, each with the group's points.
        assert_eq!(lines[5], "Ben Ng,2001,ben@example.edu,submission_102,1,1,1,1,,");
        assert_eq!(lines[6], "Cy Ortiz,2002,,submission_102,1,1,1,1,,");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
