// INSTRUCTOR ONLY: left out of the handout (students grade themselves, not a class).
//! `grader class SUBMISSIONS -o DIR`: a whole class graded at once.
//!
//! SUBMISSIONS is a folder of submissions, one folder per student (the folder's name is the
//! student's), each holding `lectures/NN-name/src` itself or one folder down (an unpacked zip).
//! Each is graded exactly as `grader grade --submission` grades it: its lectures' sources copied
//! into a pristine work folder, built (as the grading users, where given), and every check judged
//! by the judge built once from this tree. A work folder is reused from one submission to the
//! next, so cargo rebuilds only the lectures that differ; with four cores or more, several
//! submissions are graded at once, each in its own work folder with its share of the cores.
//!
//! DIR gets, per student, `students/NAME/results.json` (Gradescope's format) and
//! `students/NAME/grade.json` (the points of every check), and for the class `gradebook.csv`
//! (one row per student, the total, then the points per exercise and per check) and
//! `class.html` (what the class gets wrong: `report.rs`). Resumable: a
//! student whose files are unchanged since their last grade, by the same judge, is not graded
//! again. One submission that does not compile, loops or crashes costs only itself (its
//! verdicts say so); one that cannot be graded at all (no `lectures/`) is a row with the reason.

use std::collections::BTreeMap;
use std::hash::Hasher;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::Instant;

use serde::{Deserialize, Serialize};

mod report;

use crate::grade::{GradeOptions, Selection};
use crate::platform::RunAs;

/// `grader class`'s arguments.
#[derive(clap::Args, Debug)]
pub struct ClassArgs {
    /// A folder of submissions, one folder per student (named as the student), each holding
    /// `lectures/NN-name/src` or a folder that does.
    submissions: PathBuf,
    /// Where the results go.
    #[arg(long, short)]
    output: PathBuf,
    /// What to grade: lectures (03), exercises or checks [default: everything].
    select: Vec<String>,
    /// The work folders [default: DIR/work].
    #[arg(long)]
    workdir: Option<PathBuf>,
    /// Build and run the students' code as these users, as `grade --run-as`; shared out among
    /// the submissions graded at once.
    #[arg(long, value_name = "USER,…", value_delimiter = ',')]
    run_as: Vec<String>,
    /// Submissions graded at once, each in its own work folder [default: half the cores].
    #[arg(long)]
    parallel: Option<usize>,
    /// Checks run at once, in all [default: the number of cores].
    #[arg(long)]
    jobs: Option<usize>,
}

/// `grader class`: `base` is the grading options of this build (precision, profile, cores).
pub fn command(args: &ClassArgs, base: &GradeOptions) -> Result<bool, String> {
    // The students' code may run as this user: keep it out of this process's pipes.
    crate::platform::keep_others_out();
    let run_as = args.run_as.iter().map(|u| crate::platform::user(u)).collect::<Result<Vec<_>, _>>()?;
    if !run_as.is_empty() {
        // As `grade --run-as`: the grading users' processes capped, what a check leaves reaped.
        crate::platform::limit_user_processes(crate::platform::USER_PROCESSES)?;
        crate::platform::adopt_orphans();
    }
    let cores = base.jobs;
    let options = ClassOptions {
        submissions: args.submissions.clone(),
        out: args.output.clone(),
        selection: Selection::parse(&args.select)?,
        run_as,
        workdir: args.workdir.clone(),
        parallel: args.parallel.unwrap_or((cores / 2).max(1)),
        jobs: args.jobs.unwrap_or(cores),
    };
    class(&crate::workspace::own_root(), &options, base)
}

/// What `grader class` was asked.
pub struct ClassOptions {
    pub submissions: PathBuf,
    pub out: PathBuf,
    pub selection: Selection,
    /// The grading users (`--run-as`), shared out among the submissions graded at once.
    pub run_as: Vec<RunAs>,
    /// Where the work folders are [default: DIR/work].
    pub workdir: Option<PathBuf>,
    /// Submissions graded at once (each with its own work folder).
    pub parallel: usize,
    /// Checks run at once in all.
    pub jobs: usize,
}

/// The version of `grade.json`'s format, part of every fingerprint: a grade kept in an older
/// format is graded again.
const GRADE_FORMAT: u32 = 1;

/// One student's grade, as `students/NAME/grade.json` keeps it.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct StudentGrade {
    pub student: String,
    /// The submission's files and the judge, hashed: unchanged, the grade stands.
    pub fingerprint: String,
    pub score: u32,
    pub max_score: u32,
    pub seconds: f64,
    /// Why the submission could not be graded at all (no `lectures/`, too large).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    pub checks: Vec<CheckGrade>,
}

/// One check of a student's grade.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct CheckGrade {
    pub id: String,
    pub exercise: String,
    pub points: u32,
    pub max_points: u32,
    pub status: String,
    /// Why it did not pass: the check's likely cause, or what happened (a crash, a time-out).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cause: Option<String>,
}

/// Grades every submission in `options.submissions` (`base` is the grading options of this
/// build: precision, profile) and writes DIR.
pub fn class(root: &Path, options: &ClassOptions, base: &GradeOptions) -> Result<bool, String> {
    let students = discover(&options.submissions)?;
    if students.is_empty() {
        return Err(format!("{} holds no submission folders", options.submissions.display()));
    }
    std::fs::create_dir_all(options.out.join("students"))
        .map_err(|e| format!("{}: {e}", options.out.display()))?;
    let judge = crate::submission::judge(root, base)?;
    let judge_print = fingerprint_files(std::slice::from_ref(&judge))?;
    // Each submission graded at once has grading users of its own (a user's process limit is
    // one job's).
    let mut parallel = options.parallel.clamp(1, students.len());
    if !options.run_as.is_empty() {
        parallel = parallel.min(options.run_as.len());
    }
    let per_job = (options.jobs / parallel).max(1);
    let workdir = options.workdir.clone().unwrap_or_else(|| options.out.join("work"));
    eprintln!(
        "grading {} submissions, {parallel} at once ({per_job} checks each), in {}",
        students.len(),
        workdir.display()
    );
    let class = Class { root, judge: &judge, judge_print: &judge_print, options, base, jobs: per_job };
    let queue = Mutex::new(students.iter());
    let grades: Mutex<Vec<StudentGrade>> = Mutex::new(Vec::new());
    // On a terminal, a bar of the submissions graded and the time left; each submission's line
    // above it (and alone where there is no terminal).
    let bar = indicatif::ProgressBar::new(students.len() as u64);
    bar.set_style(
        indicatif::ProgressStyle::with_template("grading {bar:40} {pos}/{len} submissions, {eta} left")
            .map_err(|e| e.to_string())?,
    );
    let done = Mutex::new(0usize);
    let started = Instant::now();
    std::thread::scope(|scope| {
        for worker in 0..parallel {
            let users: Vec<RunAs> = options.run_as.iter().skip(worker).step_by(parallel).cloned().collect();
            let work = if parallel == 1 { workdir.clone() } else { workdir.join(format!("{worker}")) };
            let (queue, grades, done, class, bar) = (&queue, &grades, &done, &class, &bar);
            let total = students.len();
            scope.spawn(move || {
                while let Some((name, path)) = queue.lock().ok().and_then(|mut q| q.next()) {
                    let (grade, kept) = class.grade(name, path, &work, &users);
                    let count = done.lock().map(|mut d| {
                        *d += 1;
                        *d
                    });
                    let (score, max) = (grade.score, grade.max_score);
                    let said = match (&grade.error, kept) {
                        (Some(error), _) => format!("not graded: {error}"),
                        (None, true) => format!("{score}/{max} points, unchanged since its last grade"),
                        (None, false) => format!("{score}/{max} points in {:.1} s", grade.seconds),
                    };
                    bar.suspend(|| eprintln!("[{}/{total}] {name}: {said}", count.unwrap_or(0)));
                    bar.inc(1);
                    if let Ok(mut grades) = grades.lock() {
                        grades.push(grade);
                    }
                }
            });
        }
    });
    bar.finish_and_clear();
    let mut grades = grades.into_inner().map_err(|_| "a grading thread panicked")?;
    grades.sort_by(|a, b| a.student.cmp(&b.student));
    let csv = options.out.join("gradebook.csv");
    write_gradebook(&csv, &grades)?;
    let page = options.out.join("class.html");
    std::fs::write(&page, report::html(&grades)).map_err(|e| format!("{}: {e}", page.display()))?;
    eprintln!(
        "{} submissions in {:.1} s; gradebook: {}; the class: {}",
        grades.len(),
        started.elapsed().as_secs_f64(),
        csv.display(),
        page.display()
    );
    // A submission that could not be graded is its student's row, with the reason: not a failure
    // of the run.
    Ok(true)
}

/// The submissions: every folder of `dir`, by name, but hidden ones and the `__MACOSX` folder an
/// archive made on a Mac holds (no student's).
fn discover(dir: &Path) -> Result<Vec<(String, PathBuf)>, String> {
    let mut students = Vec::new();
    for entry in std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))? {
        let entry = entry.map_err(|e| format!("{}: {e}", dir.display()))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if entry.file_type().is_ok_and(|t| t.is_dir()) && !name.starts_with('.') && name != "__MACOSX" {
            students.push((name, entry.path()));
        }
    }
    students.sort();
    Ok(students)
}

/// What every student's grade shares: the instructor's tree, the judge, the options.
struct Class<'a> {
    root: &'a Path,
    judge: &'a Path,
    /// The judge's binary, hashed: part of every grade's fingerprint.
    judge_print: &'a str,
    options: &'a ClassOptions,
    base: &'a GradeOptions,
    /// Checks run at once for one submission.
    jobs: usize,
}

impl Class<'_> {
    /// One student graded in the work folder `work` as `users`, or their earlier grade if nothing
    /// changed (`true`): never an error, which would cost the others; a submission that cannot be
    /// graded is a grade with the reason.
    fn grade(&self, name: &str, path: &Path, work: &Path, users: &[RunAs]) -> (StudentGrade, bool) {
        let Class { root, judge, judge_print, options, base, jobs } = *self;
        let start = Instant::now();
        let folder = options.out.join("students").join(name);
        let fingerprint = crate::submission::lecture_files(path)
            .and_then(|files| fingerprint_files(&files))
            .map(|files| format!("{GRADE_FORMAT}-{files}-{judge_print}-{}", options.selection.0.join(",")))
            .unwrap_or_default();
        if let Some(earlier) = earlier_grade(&folder)
            && !fingerprint.is_empty()
            && earlier.fingerprint == fingerprint
            && earlier.error.is_none()
        {
            return (earlier, true);
        }
        let graded = (|| {
            let (ws, target) = crate::submission::prepare(root, path, Some(work), users.first())?;
            let mut grading = base.clone();
            grading.selection = options.selection.clone();
            grading.only_prerequisites = true;
            grading.hidden = true;
            grading.target_dir = Some(target);
            grading.judge = Some(judge.to_owned());
            grading.run_as = users.to_vec();
            grading.out_dir = Some(ws.root.join("target").join("grader"));
            grading.show_progress = false;
            grading.jobs = jobs;
            let grade = crate::grade::grade(&ws, &grading)?;
            std::fs::create_dir_all(&folder).map_err(|e| format!("{}: {e}", folder.display()))?;
            let results = serde_json::to_string_pretty(&crate::output::gradescope(&grade))
                .map_err(|e| e.to_string())?;
            let file = folder.join("results.json");
            std::fs::write(&file, results).map_err(|e| format!("{}: {e}", file.display()))?;
            Ok::<_, String>(grade)
        })();
        let seconds = start.elapsed().as_secs_f64();
        let student = match graded {
            Ok(grade) => {
                let (score, max_score) = grade.points();
                let checks = grade
                    .verdicts
                    .iter()
                    .map(|v| CheckGrade {
                        id: v.info.id.clone(),
                        exercise: v.info.exercise_id(),
                        points: v.points,
                        max_points: v.info.points,
                        status: v.status.label().to_owned(),
                        cause: match (&v.failure, v.status) {
                            (Some(failure), _) => Some(failure.cause.clone()),
                            (None, crate::verdict::Status::Passed) => None,
                            (None, _) => Some(v.summary.clone()),
                        },
                    })
                    .collect();
                StudentGrade {
                    student: name.to_owned(),
                    fingerprint,
                    score,
                    max_score,
                    seconds,
                    error: None,
                    checks,
                }
            }
            Err(error) => StudentGrade {
                student: name.to_owned(),
                fingerprint,
                score: 0,
                max_score: 0,
                seconds,
                error: Some(error),
                checks: Vec::new(),
            },
        };
        let _ = std::fs::create_dir_all(&folder);
        if let Ok(json) = serde_json::to_string_pretty(&student) {
            let _ = std::fs::write(folder.join("grade.json"), json);
        }
        (student, false)
    }
}

/// The grade kept in `folder`, if any.
fn earlier_grade(folder: &Path) -> Option<StudentGrade> {
    let text = std::fs::read_to_string(folder.join("grade.json")).ok()?;
    serde_json::from_str(&text).ok()
}

/// A hash of `files`' names and contents, in order (a cache key, not a security boundary: a
/// grade is only ever reused for the same files and judge).
fn fingerprint_files(files: &[PathBuf]) -> Result<String, String> {
    let mut hasher = std::hash::DefaultHasher::new();
    for file in files {
        hasher.write(file.to_string_lossy().as_bytes());
        hasher.write(&std::fs::read(file).map_err(|e| format!("{}: {e}", file.display()))?);
    }
    Ok(format!("{:016x}", hasher.finish()))
}

/// `gradebook.csv`: a header row, then one row per student: name, total, possible, then the
/// points of every exercise and of every check (the columns of every student's checks, in
/// course order), and why a submission was not graded. Empty where a student has no such check
/// (not graded).
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
    let mut header = vec!["student".to_owned(), "total".to_owned(), "possible".to_owned()];
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
        let mut row = vec![grade.student.clone(), grade.score.to_string(), grade.max_score.to_string()];
        row.extend(
            exercises.iter().map(|e| by_exercise.get(e.as_str()).map_or(String::new(), u32::to_string)),
        );
        row.extend(checks.iter().map(|c| by_check.get(c.as_str()).map_or(String::new(), u32::to_string)));
        row.push(grade.error.clone().unwrap_or_default());
        writer.write_record(&row).map_err(|e| e.to_string())?;
    }
    writer.flush().map_err(|e| format!("{}: {e}", file.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(id: &str, points: u32, max_points: u32) -> CheckGrade {
        let exercise = id.rsplit_once('/').map_or(id, |(e, _)| e).to_owned();
        CheckGrade { id: id.into(), exercise, points, max_points, status: "passed".into(), cause: None }
    }

    #[test]
    fn every_folder_is_a_student_but_hidden_ones_and_an_archives_mac_folder() {
        let dir = std::env::temp_dir().join(format!("raylab-class-{}", std::process::id()));
        for folder in ["zoe", "ada", ".git", "__MACOSX"] {
            std::fs::create_dir_all(dir.join(folder)).unwrap();
        }
        std::fs::write(dir.join("notes.txt"), "not a submission").unwrap();
        let names: Vec<String> = discover(&dir).unwrap().into_iter().map(|(name, _)| name).collect();
        assert_eq!(names, ["ada", "zoe"]);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn the_gradebook_has_a_row_per_student_and_a_column_per_exercise_and_check() {
        let dir = std::env::temp_dir().join(format!("raylab-gradebook-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let student = |name: &str, checks: Vec<CheckGrade>, error: Option<&str>| StudentGrade {
            student: name.into(),
            fingerprint: String::new(),
            score: checks.iter().map(|c| c.points).sum(),
            max_score: checks.iter().map(|c| c.max_points).sum(),
            seconds: 1.0,
            error: error.map(str::to_owned),
            checks,
        };
        let grades = [
            student("ada", vec![check("02/hit_plane/unit", 1, 1), check("02/hit_plane/grazing", 2, 2)], None),
            student(
                "Lovelace, A.",
                vec![check("02/hit_plane/unit", 0, 1), check("02/hit_plane/grazing", 2, 2)],
                None,
            ),
            student("bob", Vec::new(), Some("no lectures/ folder")),
        ];
        let file = dir.join("gradebook.csv");
        write_gradebook(&file, &grades).unwrap();
        let text = std::fs::read_to_string(&file).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines[0],
            "student,total,possible,02/hit_plane,02/hit_plane/unit,02/hit_plane/grazing,not graded"
        );
        assert_eq!(lines[1], "ada,3,3,3,1,2,");
        // A name with a comma is quoted, as spreadsheets read it.
        assert_eq!(lines[2], "\"Lovelace, A.\",2,3,2,0,2,");
        assert_eq!(lines[3], "bob,0,0,,,,no lectures/ folder");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
