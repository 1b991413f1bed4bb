// INSTRUCTOR ONLY: left out of the handout (students grade themselves, not a class).
//! `grader class SUBMISSIONS -o DIR`: a whole class graded at once.
//!
//! SUBMISSIONS is a folder of submissions, one folder per student (the folder's name is the
//! student's), each holding `lectures/NN-name/src` itself or one folder down (an unpacked zip),
//! or a zip of such folders; Gradescope's "Export Submissions" is one (`export.rs`: its metadata
//! names each submission's students).
//! Each is graded exactly as `grader grade --submission` grades it: its lectures' sources copied
//! into a pristine work folder, built (as the grading users, where given), and every check judged
//! by the judge built once from this tree. A work folder is reused from one submission to the
//! next, so cargo rebuilds only the lectures that differ; with four cores or more, several
//! submissions are graded at once, each in its own work folder with its share of the cores.
//!
//! DIR gets, per student, `students/NAME/results.json` (Gradescope's format),
//! `students/NAME/grade.json` (the points of every check) and the pictures a check failed, and
//! for the class `gradebook.csv` (`gradebook.rs`: a row per student, the total, then the points
//! per exercise and per check) and `class.html` (what the class gets wrong: `report.rs`, its
//! clusters of wrong pictures `clusters.rs`). Resumable: a student whose files are unchanged
//! since their last grade is not graded again but in the lectures whose checks changed since
//! (`regrade.rs`). One submission that does not compile, loops or crashes costs only itself (its
//! verdicts say so); one that cannot be graded at all (no `lectures/`) is a row with the reason.
//!
//! Past one machine: `--report-only` writes the gradebook and the page from the grades in
//! DIR/students (several machines' DIRs copied together), and `--results EXPORT` from a
//! Gradescope export's results alone, graded in Gradescope's containers, without regrading.

use std::collections::{BTreeMap, BTreeSet};
use std::hash::Hasher;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::Instant;

use serde::{Deserialize, Serialize};

mod clusters;
mod export;
mod gradebook;
mod regrade;
mod report;

use crate::grade::{GradeOptions, Selection};
use crate::platform::RunAs;

/// `grader class`'s arguments.
#[derive(clap::Args, Debug)]
pub struct ClassArgs {
    /// A folder of submissions, one folder per student (named as the student), each holding
    /// `lectures/NN-name/src` or a folder that does; or a zip of them (Gradescope's export).
    #[arg(required_unless_present_any = ["report_only", "results"])]
    submissions: Option<PathBuf>,
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
    /// Grade nothing: write the gradebook and the class's page again from the grades in
    /// DIR/students (graded earlier, or on other machines and copied together).
    #[arg(long, conflicts_with_all = ["submissions", "select", "results"])]
    report_only: bool,
    /// Grade nothing: the gradebook and the class's page from a Gradescope export's results (a
    /// zip or its folder, graded there by this course's autograder), without pictures.
    #[arg(long, value_name = "EXPORT", conflicts_with_all = ["submissions", "select"])]
    results: Option<PathBuf>,
}

/// `grader class`: `base` is the grading options of this build (precision, profile, cores).
pub fn command(args: &ClassArgs, base: &GradeOptions) -> Result<bool, String> {
    if let Some(export) = &args.results {
        let grades = results_grades(export, &args.output)?;
        return write_class(&args.output, &grades).map(|()| true);
    }
    let Some(submissions) = args.submissions.clone().filter(|_| !args.report_only) else {
        let grades = kept_grades(&args.output)?;
        return write_class(&args.output, &grades).map(|()| true);
    };
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
        submissions,
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
const GRADE_FORMAT: u32 = 2;

/// One student's grade, as `students/NAME/grade.json` keeps it.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct StudentGrade {
    /// The submission's folder.
    pub student: String,
    /// Its students, where an export names them (a group submission has several).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub submitters: Vec<export::Submitter>,
    /// The submission's files (and the selection), hashed: unchanged, the grade stands as far as
    /// `judge` does.
    pub fingerprint: String,
    /// What each lecture's checks depended on when graded (`regrade.rs`).
    #[serde(default)]
    pub judge: regrade::JudgePrint,
    pub score: u32,
    pub max_score: u32,
    pub seconds: f64,
    /// Why the submission could not be graded at all (no `lectures/`, too large).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
    pub checks: Vec<CheckGrade>,
}

impl StudentGrade {
    /// The grade of `checks`, its points and the points possible summed from them.
    pub fn new(student: &str, checks: Vec<CheckGrade>) -> Self {
        Self {
            student: student.to_owned(),
            score: checks.iter().map(|c| c.points).sum(),
            max_score: checks.iter().map(|c| c.max_points).sum(),
            checks,
            ..Self::default()
        }
    }

    /// A submission that could not be graded, and why.
    pub fn not_graded(student: &str, error: String) -> Self {
        Self { student: student.to_owned(), error: Some(error), ..Self::default() }
    }
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
    /// A failed picture's folder, relative to the class's output: `yours.png` and `diff.png`
    /// (its difference from `pictures/CHECK/expected.png`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub picture: Option<String>,
}

/// Grades every submission in `options.submissions` (`base` is the grading options of this
/// build: precision, profile) and writes DIR.
pub fn class(root: &Path, options: &ClassOptions, base: &GradeOptions) -> Result<bool, String> {
    let folder = export::submissions_folder(&options.submissions, &options.out.join("submissions"))?;
    let submitters = export::metadata(&folder)?;
    let students = discover(&folder)?;
    if students.is_empty() {
        return Err(format!("{} holds no submission folders", options.submissions.display()));
    }
    std::fs::create_dir_all(options.out.join("students"))
        .map_err(|e| format!("{}: {e}", options.out.display()))?;
    let judge = crate::submission::judge(root, base)?;
    let ws = crate::workspace::Workspace::open(root)?;
    let build = format!(
        "{} {}",
        if base.f64 { "f64" } else { "f32" },
        if base.release { "release" } else { "debug" }
    );
    let print = regrade::judge_print(&ws, &build)?;
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
    let class = Class {
        root,
        ws: &ws,
        judge: &judge,
        print: &print,
        options,
        base,
        jobs: per_job,
        submitters: &submitters,
    };
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
                    let (grade, graded) = class.grade(name, path, &work, &users);
                    let count = done.lock().map(|mut d| {
                        *d += 1;
                        *d
                    });
                    let (score, max) = (grade.score, grade.max_score);
                    let said = match (&grade.error, graded) {
                        (Some(error), _) => format!("not graded: {error}"),
                        (None, Graded::Kept) => format!("{score}/{max} points, unchanged since its last grade"),
                        (None, Graded::Partly(lectures)) => format!(
                            "{score}/{max} points, lectures {} graded again (their checks changed) in {:.1} s",
                            lectures.into_iter().collect::<Vec<_>>().join(", "),
                            grade.seconds
                        ),
                        (None, Graded::Whole) => format!("{score}/{max} points in {:.1} s", grade.seconds),
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
    eprintln!("{} submissions in {:.1} s", grades.len(), started.elapsed().as_secs_f64());
    write_class(&options.out, &grades)?;
    // A submission that could not be graded is its student's row, with the reason: not a failure
    // of the run.
    Ok(true)
}

/// Writes `out`'s gradebook and class page for `grades`.
fn write_class(out: &Path, grades: &[StudentGrade]) -> Result<(), String> {
    let csv = out.join("gradebook.csv");
    gradebook::write_gradebook(&csv, grades)?;
    let page = out.join("class.html");
    std::fs::write(&page, report::html(grades, out)).map_err(|e| format!("{}: {e}", page.display()))?;
    eprintln!("gradebook: {}; the class: {}", csv.display(), page.display());
    Ok(())
}

/// The grades in a Gradescope export's results (`export`, a zip or its folder), each kept as
/// `out/students/NAME/grade.json` as if graded here.
fn results_grades(export: &Path, out: &Path) -> Result<Vec<StudentGrade>, String> {
    let folder = export::submissions_folder(export, &out.join("export"))?;
    let metadata = export::metadata(&folder)?;
    if metadata.is_empty() {
        return Err(format!("{}: no {} (not a Gradescope export)", export.display(), export::METADATA));
    }
    let mut grades = Vec::new();
    for (name, submission) in metadata {
        let mut grade = match &submission.results {
            Some(results) => export::grade_from_results(&name, results),
            None => StudentGrade::not_graded(&name, "no autograder results in the export".to_owned()),
        };
        grade.submitters = submission.submitters;
        let dir = out.join("students").join(&name);
        std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        let json = serde_json::to_string_pretty(&grade).map_err(|e| e.to_string())?;
        std::fs::write(dir.join("grade.json"), json).map_err(|e| format!("{}: {e}", dir.display()))?;
        grades.push(grade);
    }
    Ok(grades)
}

/// The grades kept in `out/students`, by student.
fn kept_grades(out: &Path) -> Result<Vec<StudentGrade>, String> {
    let students = out.join("students");
    let mut grades = Vec::new();
    let entries = std::fs::read_dir(&students).map_err(|e| {
        format!("{}: {e} (no grades to report: grade the class into it first)", students.display())
    })?;
    for entry in entries {
        let folder = entry.map_err(|e| format!("{}: {e}", students.display()))?.path();
        let file = folder.join("grade.json");
        let text = std::fs::read_to_string(&file).map_err(|e| format!("{}: {e}", file.display()))?;
        grades.push(serde_json::from_str(&text).map_err(|e| format!("{}: {e}", file.display()))?);
    }
    grades.sort_by(|a: &StudentGrade, b| a.student.cmp(&b.student));
    Ok(grades)
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
    ws: &'a crate::workspace::Workspace,
    judge: &'a Path,
    /// What each lecture's checks depend on, hashed: a grade is kept while its part is unchanged.
    print: &'a regrade::JudgePrint,
    options: &'a ClassOptions,
    base: &'a GradeOptions,
    /// Checks run at once for one submission.
    jobs: usize,
    /// Who submitted each folder, where an export says.
    submitters: &'a BTreeMap<String, export::Submission>,
}

impl Class<'_> {
    /// One student graded in the work folder `work` as `users`; or their earlier grade, kept
    /// whole if nothing it depends on changed, or in part (the lectures whose checks did not):
    /// never an error, which would cost the others; a submission that cannot be graded is a grade
    /// with the reason.
    fn grade(&self, name: &str, path: &Path, work: &Path, users: &[RunAs]) -> (StudentGrade, Graded) {
        let Class { root, ws: _, judge, print, options, base, jobs, submitters } = *self;
        let submitters = submitters.get(name).map(|s| s.submitters.clone()).unwrap_or_default();
        let start = Instant::now();
        let folder = options.out.join("students").join(name);
        let fingerprint = crate::submission::lecture_files(path)
            .and_then(|files| fingerprint_files(path, &files))
            .map(|files| format!("{GRADE_FORMAT}-{files}-{}", options.selection.0.join(",")))
            .unwrap_or_default();
        // The same files graded before: what the tree's changes since may have moved, if anything.
        let earlier = earlier_grade(&folder)
            .filter(|e| !fingerprint.is_empty() && e.fingerprint == fingerprint && e.error.is_none());
        let stale = earlier.as_ref().and_then(|e| self.stale(e));
        // Kept in part only with its Gradescope results to merge into (read only then).
        let file = folder.join("results.json");
        let kept_results: Option<serde_json::Value> = stale
            .as_ref()
            .filter(|s| !s.is_empty())
            .and_then(|_| std::fs::read_to_string(&file).ok())
            .and_then(|t| serde_json::from_str(&t).ok());
        let stale = stale.filter(|s| s.is_empty() || kept_results.is_some());
        let earlier = earlier.filter(|_| stale.is_some());
        if let (Some(earlier), Some(stale)) = (&earlier, &stale)
            && stale.is_empty()
        {
            let kept = StudentGrade { submitters, judge: print.clone(), ..earlier.clone() };
            save_grade(&folder, &kept);
            return (kept, Graded::Kept);
        }
        let regraded = stale.unwrap_or_default();
        let graded = (|| {
            // The work folder is this grade's until the closure ends (its pictures are read there).
            let prepared = crate::submission::prepare(root, path, Some(work), users.first())?;
            let (ws, target) = (&prepared.ws, prepared.target.clone());
            let mut grading = base.clone();
            grading.selection = if regraded.is_empty() {
                options.selection.clone()
            } else {
                Selection(regraded.iter().cloned().collect())
            };
            grading.only_prerequisites = true;
            grading.hidden = true;
            grading.target_dir = Some(target);
            grading.judge = Some(crate::submission::Judge::built(judge.to_owned()));
            grading.run_as = users.to_vec();
            grading.out_dir = Some(ws.root.join("target").join("grader"));
            grading.show_progress = false;
            grading.jobs = jobs;
            let grade = crate::grade::grade(ws, &grading)?;
            std::fs::create_dir_all(&folder).map_err(|e| format!("{}: {e}", folder.display()))?;
            // The pictures of the last grade are not this one's (those of the lectures graded
            // again, when only some are).
            forget_pictures(&folder.join(PICTURES), &regraded);
            let mut results = crate::output::gradescope(&grade);
            if let Some(kept) = kept_results.as_ref().filter(|_| !regraded.is_empty()) {
                results = regrade::merge_results(kept, &results, &regraded);
            }
            let results = serde_json::to_string_pretty(&results).map_err(|e| e.to_string())?;
            std::fs::write(&file, results).map_err(|e| format!("{}: {e}", file.display()))?;
            let written = grading.out_dir.as_deref().unwrap_or(work);
            let pictures = keep_pictures(&grade, written, &options.out, name);
            Ok::<_, String>((grade, pictures))
        })();
        let seconds = start.elapsed().as_secs_f64();
        let student = match graded {
            Ok((grade, mut pictures)) => {
                let mut checks: Vec<CheckGrade> = grade
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
                        picture: pictures.remove(&v.info.id),
                    })
                    .collect();
                if let Some(earlier) = earlier.filter(|_| !regraded.is_empty()) {
                    checks = regrade::merge(earlier.checks, checks, &regraded);
                }
                StudentGrade::new(name, checks)
            }
            Err(error) => StudentGrade::not_graded(name, error),
        };
        let student = StudentGrade { submitters, fingerprint, judge: print.clone(), seconds, ..student };
        save_grade(&folder, &student);
        let graded = if regraded.is_empty() || student.error.is_some() {
            Graded::Whole
        } else {
            Graded::Partly(regraded)
        };
        (student, graded)
    }

    /// The lectures of `earlier` (a grade of the same files) that the tree's changes since may
    /// have moved, among those graded: `None` to grade it all again (its common part changed, or
    /// the class selects exercises or checks, which a lecture's regrade would not match).
    fn stale(&self, earlier: &StudentGrade) -> Option<BTreeSet<String>> {
        let stale = regrade::stale_lectures(self.ws, &earlier.judge, self.print)?;
        let selected = &self.options.selection.0;
        if selected.iter().any(|s| s.len() != 2) {
            return if stale.is_empty() { Some(stale) } else { None };
        }
        Some(stale.into_iter().filter(|l| selected.is_empty() || selected.contains(l)).collect())
    }
}

/// How a student's grade came to be.
enum Graded {
    /// Kept: their files and what their checks depend on are unchanged.
    Kept,
    /// These lectures graded again (their checks changed), the others kept.
    Partly(BTreeSet<String>),
    Whole,
}

/// Writes a student's `grade.json` (a grade that cannot be written is graded again next time).
fn save_grade(folder: &Path, grade: &StudentGrade) {
    let _ = std::fs::create_dir_all(folder);
    if let Ok(json) = serde_json::to_string_pretty(grade) {
        let _ = std::fs::write(folder.join("grade.json"), json);
    }
}

/// Removes a student's pictures: those of the lectures `only`, or all of them when it is empty.
fn forget_pictures(pictures: &Path, only: &BTreeSet<String>) {
    if only.is_empty() {
        let _ = std::fs::remove_dir_all(pictures);
        return;
    }
    for entry in std::fs::read_dir(pictures).into_iter().flatten().flatten() {
        // A check's folder starts with its lecture: `02-image-overlapping-depths`.
        let name = entry.file_name().to_string_lossy().into_owned();
        if only.iter().any(|l| name.starts_with(&format!("{l}-"))) {
            let _ = std::fs::remove_dir_all(entry.path());
        }
    }
}

/// The folder of the pictures, the students' (`students/NAME/pictures/CHECK`) and the expected
/// ones (`pictures/CHECK/expected.png`).
const PICTURES: &str = "pictures";

/// Copies the failed pictures of `grade` (written by the judge into `written`) into the class's
/// output `out`: each student's `yours.png` and `diff.png`, each check's `expected.png` once.
/// Returns each failed picture's folder by check, relative to `out`; a picture that cannot be
/// copied is left out (the report's clusters only miss it).
fn keep_pictures(
    grade: &crate::grade::Grade,
    written: &Path,
    out: &Path,
    student: &str,
) -> BTreeMap<String, String> {
    let mut kept = BTreeMap::new();
    for v in grade.verdicts.iter().filter(|v| v.status == crate::verdict::Status::Failed) {
        let Some(picture) = crate::report::PictureDir::of(&v.info) else { continue };
        let from = picture.under(written, &v.info);
        // `02/image/overlapping-depths` → `02-image-overlapping-depths`.
        let check = v.info.id.replace('/', "-");
        let yours = format!("students/{student}/{PICTURES}/{check}");
        let expected = out.join(PICTURES).join(&check);
        let copied = std::fs::create_dir_all(out.join(&yours))
            .and_then(|()| std::fs::create_dir_all(&expected))
            .and_then(|()| std::fs::copy(from.join("yours.png"), out.join(&yours).join("yours.png")))
            .and_then(|_| std::fs::copy(from.join("diff.png"), out.join(&yours).join("diff.png")))
            .and_then(|_| std::fs::copy(from.join("expected.png"), expected.join("expected.png")));
        if copied.is_ok() {
            kept.insert(v.info.id.clone(), yours);
        }
    }
    kept
}

/// The grade kept in `folder`, if any.
fn earlier_grade(folder: &Path) -> Option<StudentGrade> {
    let text = std::fs::read_to_string(folder.join("grade.json")).ok()?;
    serde_json::from_str(&text).ok()
}

/// A hash of `files`' names (relative to `dir`, so that a class moved elsewhere is not graded
/// again) and contents, in order: a cache key, not a security boundary (a grade is only ever
/// reused for the same files).
fn fingerprint_files(dir: &Path, files: &[PathBuf]) -> Result<String, String> {
    let mut hasher = std::hash::DefaultHasher::new();
    for file in files {
        hasher.write(file.strip_prefix(dir).unwrap_or(file).to_string_lossy().as_bytes());
        hasher.write(&std::fs::read(file).map_err(|e| format!("{}: {e}", file.display()))?);
    }
    Ok(format!("{:016x}", hasher.finish()))
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
