//! Where a student stands and where to go next: the exercises passed, per
//! lecture, and the first exercise in course order that is not passed, with
//! its file, line and book section. Every grade ends with it (the terminal
//! table, the report, `grader watch`), so a student always knows which one
//! file to open, as rustlings does.

use std::fmt::Write as _;
use std::path::Path;

use serde::Serialize;

use crate::grade::Grade;
use crate::verdict::{Status, Verdict};
use crate::workspace::Workspace;

/// Exercises passed, per lecture, and the next step.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Progress {
    /// (lecture, exercises passed, exercises graded), in course order.
    pub lectures: Vec<(String, usize, usize)>,
    pub passed: usize,
    pub total: usize,
    /// `None` when every check graded passed.
    pub next: Option<Next>,
}

/// The exercise to work on next.
#[derive(Clone, Debug, Serialize, PartialEq)]
pub struct Next {
    /// `01/translate`, or an image check's id (`02/image/spheres-on-plane`)
    /// when every exercise passes but a picture does not.
    pub exercise: String,
    /// `lectures/01-transforms/src/transforms.rs:12`, relative to the workspace root.
    pub location: Option<String>,
    /// `Book §1.2 Translation and scaling`.
    pub book: Option<String>,
    /// Why it is next: its verdict in one word.
    pub status: String,
}

/// An exercise is a function the checks name (`NN/function`): it is passed
/// when every check of it graded passed. Image, geometry and final checks
/// grade pictures, not one function; they count toward no exercise, but a
/// failing picture is the next step once every exercise passes.
fn is_exercise(v: &Verdict) -> bool {
    !matches!(v.info.exercise.as_str(), "image" | "geometry" | "final")
}

pub fn progress(ws: &Workspace, grade: &Grade) -> Progress {
    // Exercises in course order: lecture by lecture, in the order the checks are declared.
    let mut exercises: Vec<(String, bool)> = Vec::new();
    for v in grade.verdicts.iter().filter(|v| is_exercise(v)) {
        let id = v.info.exercise_id();
        let passed = v.status == Status::Passed;
        match exercises.iter_mut().find(|(e, _)| *e == id) {
            Some((_, ok)) => *ok &= passed,
            None => exercises.push((id, passed)),
        }
    }
    let mut lectures: Vec<(String, usize, usize)> = Vec::new();
    for (id, passed) in &exercises {
        let lecture = &id[..2];
        match lectures.iter_mut().find(|(l, _, _)| l == lecture) {
            Some((_, p, t)) => {
                *p += usize::from(*passed);
                *t += 1;
            }
            None => lectures.push((lecture.to_owned(), usize::from(*passed), 1)),
        }
    }
    let passed = exercises.iter().filter(|(_, ok)| *ok).count();
    // The first check in course order (lecture by lecture, its exercises before its pictures)
    // that is not passed: an exercise's own check, or, where it is blocked, the exercise it
    // waits for; a picture's check once the lecture's exercises pass.
    let first = grade.verdicts.iter().find(|v| v.status != Status::Passed);
    let next = first.map(|v| {
        let waits_for =
            v.needs.as_deref().and_then(|n| n.split_whitespace().next()).filter(|n| n.contains('/'));
        let exercise = match waits_for {
            Some(need) if v.status == Status::Blocked => need.to_owned(),
            _ if is_exercise(v) => v.info.exercise_id(),
            _ => v.info.id.clone(),
        };
        let found = locate(ws, &exercise);
        // A lecture that does not compile: its first error is the place to go.
        let error =
            grade.compile_errors.iter().find(|(l, _)| *l == v.info.lecture).map(|(_, e)| e.location.clone());
        Next {
            location: error
                .filter(|_| v.status == Status::DoesNotCompile)
                .or_else(|| found.as_ref().map(|(path, line, _)| format!("{path}:{line}"))),
            book: found.and_then(|(_, _, book)| book),
            status: v.status.label().to_lowercase(),
            exercise,
        }
    });
    Progress { lectures, passed, total: exercises.len(), next }
}

/// The lines that end every grade: progress per lecture, then the next exercise.
pub fn text(progress: &Progress) -> String {
    let mut text = String::from("\n");
    // A selection of image checks alone (`grader 05/image`) grades no exercise: no count to show.
    if progress.total > 0 {
        let per: Vec<String> = progress.lectures.iter().map(|(l, p, t)| format!("{l} {p}/{t}")).collect();
        let _ = writeln!(
            text,
            "exercises passed: {} of {}  ({})",
            progress.passed,
            progress.total,
            per.join(", ")
        );
    }
    match &progress.next {
        None => text.push_str("every check graded passes\n"),
        Some(next) => {
            let name = next.exercise.split_once('/').map_or(next.exercise.as_str(), |(_, n)| n);
            let place = next.location.clone().unwrap_or_else(|| "target/grader/report.html".to_owned());
            let book = next.book.as_deref().map(|b| format!(" — {b}")).unwrap_or_default();
            let _ = writeln!(text, "next: {place}  {name}{book} ({})", next.status);
            if next.location.is_some() {
                let _ = writeln!(text, "      stuck? cargo run -p grader -- hint {}", next.exercise);
            }
        }
    }
    text
}

/// Where exercise `NN/function` (or `NN/Type::method`) is defined: the file
/// relative to the workspace root, the 1-based line of its `fn`, and the
/// book section its doc comment names.
pub fn locate(ws: &Workspace, exercise: &str) -> Option<(String, usize, Option<String>)> {
    let (lecture, name) = exercise.split_once('/')?;
    let folder = &ws.lecture(lecture)?.folder;
    let (owner, function) = match name.split_once("::") {
        Some((owner, function)) => (Some(owner), function),
        None => (None, name),
    };
    let src = ws.root.join("lectures").join(folder).join("src");
    let mut files: Vec<_> = std::fs::read_dir(&src).ok()?.filter_map(|e| e.ok().map(|e| e.path())).collect();
    files.sort();
    for file in files.iter().filter(|f| f.extension().is_some_and(|e| e == "rs")) {
        let Ok(text) = std::fs::read_to_string(file) else { continue };
        let lines: Vec<&str> = text.lines().collect();
        let mut in_owner = owner.is_none();
        for (i, line) in lines.iter().enumerate() {
            let t = line.trim_start();
            if let Some(owner) = owner
                && line.starts_with("impl")
            {
                in_owner = line.split(|c: char| !(c.is_alphanumeric() || c == '_')).any(|w| w == owner);
            }
            let defines = ["fn ", "pub fn "].iter().any(|p| {
                t.strip_prefix(p).is_some_and(|rest| {
                    rest.strip_prefix(function).is_some_and(|r| r.starts_with('(') || r.starts_with('<'))
                })
            });
            if in_owner && defines && (owner.is_some() || !line.starts_with(char::is_whitespace)) {
                let relative = relative(&ws.root, file);
                return Some((relative, i + 1, book_of(&lines[..i])));
            }
        }
    }
    None
}

/// The `Book: §N.M Title` of the doc comment just above a line (its first
/// section, read across the comment's line breaks up to the sentence's end).
fn book_of(before: &[&str]) -> Option<String> {
    let docs = before.iter().rev().take_while(|l| {
        let t = l.trim();
        t.starts_with("///") || t.starts_with("#[")
    });
    let mut docs: Vec<&str> = docs.filter_map(|l| l.trim().strip_prefix("///")).map(str::trim).collect();
    docs.reverse();
    let text = docs.join(" ");
    let at = text.find("Book: §")?;
    let reference = &text[at + "Book: ".len()..];
    // The section number (its dots are not a sentence's end), then the title up to the first
    // '.', ',', '(' or ';'.
    let number = reference.find(' ').unwrap_or(reference.len());
    let end = reference[number..].find(['.', ',', '(', ';']).map_or(reference.len(), |i| number + i);
    Some(format!("Book {}", reference[..end].trim()))
}

fn relative(root: &Path, file: &Path) -> String {
    file.strip_prefix(root).unwrap_or(file).to_string_lossy().replace('\\', "/")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::workspace::own_root;

    fn verdict(id: &str, status: Status) -> Verdict {
        Verdict::new(crate::verdict::test_info(id), status, "")
    }

    #[test]
    fn every_exercise_the_checks_name_is_found_with_its_line_and_book_section() {
        let ws = Workspace::open(&own_root()).unwrap();
        let list =
            std::fs::read_to_string(own_root().join("lectures/01-transforms/src/transforms.rs")).unwrap();
        let (file, line, book) = locate(&ws, "01/translate").unwrap();
        assert_eq!(file, "lectures/01-transforms/src/transforms.rs");
        assert!(list.lines().nth(line - 1).unwrap().contains("pub fn translate("), "line {line}");
        assert_eq!(book.as_deref(), Some("Book §1.2 Translation and scaling"));
        let (file, line, _) = locate(&ws, "01/PerspectiveCamera::generate_ray").unwrap();
        assert_eq!(file, "lectures/01-transforms/src/perspective.rs");
        let text = std::fs::read_to_string(own_root().join(&file)).unwrap();
        assert!(text.lines().nth(line - 1).unwrap().contains("fn generate_ray("));
        let (file, _, _) = locate(&ws, "09/Aabb::union").unwrap();
        assert_eq!(file, "lectures/09-acceleration/src/aabb.rs");
        assert_eq!(locate(&ws, "01/no_such_function"), None);
    }

    #[test]
    fn the_next_exercise_is_the_first_not_passed_or_what_it_waits_for() {
        let ws = Workspace::open(&own_root()).unwrap();
        let mut blocked = verdict("02/closest_hit/unit", Status::Blocked);
        blocked.needs = Some("02/hit_sphere_stable".into());
        let grade = Grade {
            verdicts: vec![
                verdict("01/translate/unit", Status::Passed),
                verdict("01/scale/unit", Status::Passed),
                blocked,
                verdict("02/hit_sphere_stable/unit", Status::NotStarted),
                verdict("02/image/spheres-on-plane", Status::NotStarted),
            ],
            compile_errors: vec![],
            seconds: 0.0,
        };
        let p = progress(&ws, &grade);
        assert_eq!((p.passed, p.total), (2, 4));
        assert_eq!(p.lectures, [("01".to_owned(), 2, 2), ("02".to_owned(), 0, 2)]);
        let next = p.next.unwrap();
        assert_eq!(next.exercise, "02/hit_sphere_stable");
        assert!(next.location.unwrap().starts_with("lectures/02-ray-casting/src/sphere.rs:"));
        let shown = text(&progress(&ws, &grade));
        assert!(shown.contains("exercises passed: 2 of 4  (01 2/2, 02 0/2)"), "{shown}");
        assert!(shown.contains("hint 02/hit_sphere_stable"), "{shown}");
        // A selection without an exercise's check shows no count of none.
        let none = Progress { lectures: vec![], passed: 0, total: 0, next: None };
        assert_eq!(text(&none), "\nevery check graded passes\n");
    }
}
