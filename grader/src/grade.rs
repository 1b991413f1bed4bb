//! Grading: build the checks with the lectures that compile, list the
//! checks, run each in its own process (as many at once as there are
//! cores), and collect the verdicts.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use crate::compile::{self, BuildOptions, Built};
use crate::run::{run_check, run_judged, scratch_dir};
use crate::verdict::{Info, Kind, Status, Verdict, apply_needs, classify, pretty};
use crate::workspace::Workspace;

/// Which checks to grade: all (empty), or any of lectures (`03`), exercises
/// (`03/hit_slabs`) and single checks (`03/hit_slabs/unit`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Selection(pub Vec<String>);

impl Selection {
    pub fn parse<S: AsRef<str>>(texts: &[S]) -> Result<Self, String> {
        let mut parts = Vec::new();
        for text in texts {
            let text = text.as_ref().trim_matches('/');
            let lecture: String = text.chars().take(2).collect();
            if lecture.len() != 2 || !lecture.chars().all(|c| c.is_ascii_digit()) {
                return Err(format!(
                    "expected a lecture (e.g. 03), an exercise (03/hit_slabs) or a check (03/hit_slabs/unit), \
                     found {text:?}"
                ));
            }
            // `03-polygons-triangles` means lecture 03.
            let rest = text[2..].trim_start_matches(|c: char| c != '/');
            parts.push(format!("{lecture}{rest}"));
        }
        Ok(Self(parts))
    }

    /// The lectures selected, none for all.
    pub fn lectures(&self) -> Vec<&str> {
        self.0.iter().map(|s| &s[..2]).collect()
    }

    pub fn matches(&self, info: &Info) -> bool {
        self.0.is_empty()
            || self.0.iter().any(|s| match s.len() {
                2 => info.lecture == *s,
                _ => info.id == *s || info.id.starts_with(&format!("{s}/")),
            })
    }
}

/// How to grade.
#[derive(Clone, Debug)]
pub struct GradeOptions {
    pub selection: Selection,
    pub hidden: bool,
    pub release: bool,
    pub f64: bool,
    pub target_dir: Option<PathBuf>,
    /// With a selection, build only the selected lectures and those they use
    /// (faster: each lecture's checks, its images included, need only it and
    /// the lectures it uses).
    pub only_prerequisites: bool,
    pub jobs: usize,
    pub show_progress: bool,
    /// An already built checks binary to use instead of building (tests).
    pub binary: Option<PathBuf>,
    /// A judge (the checks built with every exercise stubbed, `submission::judge`): every check
    /// runs in two processes, the verdict the judge's (`run_judged`), and the list of checks is
    /// the judge's.
    pub judge: Option<crate::submission::Judge>,
    /// The users the student's code is built and run as (`grade --run-as`): the first builds, and
    /// each runs one job's checks (at most as many jobs as users); the judge runs as this
    /// process's.
    pub run_as: Vec<crate::platform::RunAs>,
    /// Where the grader writes (images, the report), when not `grader/` beside the build.
    pub out_dir: Option<PathBuf>,
}

/// The grade of a workspace.
#[derive(Debug)]
pub struct Grade {
    pub verdicts: Vec<Verdict>,
    /// Lectures that did not compile: lecture → "location: message".
    pub compile_errors: Vec<(String, crate::compile::CompileError)>,
    pub seconds: f64,
}

impl Grade {
    /// Points scored and possible.
    pub fn points(&self) -> (u32, u32) {
        (self.verdicts.iter().map(|v| v.points).sum(), self.verdicts.iter().map(|v| v.info.points).sum())
    }

    pub fn all_passed(&self) -> bool {
        self.verdicts.iter().all(|v| v.status == Status::Passed)
    }
}

/// The folder the grader writes into: the option `out_dir`, else `grader/` in
/// the target directory cargo builds into (the option, else
/// `CARGO_TARGET_DIR`, else the workspace's `target/`).
pub fn out_dir(ws: &Workspace, options: &GradeOptions) -> PathBuf {
    if let Some(dir) = &options.out_dir {
        return dir.clone();
    }
    let from_env = std::env::var_os("CARGO_TARGET_DIR").filter(|d| !d.is_empty()).map(PathBuf::from);
    let target = options.target_dir.clone().or(from_env).unwrap_or_else(|| ws.root.join("target"));
    // A relative CARGO_TARGET_DIR is relative to where cargo runs: the current folder.
    let target = if target.is_relative() {
        std::env::current_dir().map(|d| d.join(&target)).unwrap_or(target)
    } else {
        target
    };
    target.join("grader")
}

pub fn grade(ws: &Workspace, options: &GradeOptions) -> Result<Grade, String> {
    let start = Instant::now();
    let selected = options.selection.lectures();
    let wanted: BTreeSet<String> = if options.only_prerequisites && !selected.is_empty() {
        selected.iter().flat_map(|l| ws.prerequisites(l)).collect()
    } else {
        ws.lectures.iter().map(|l| l.number.clone()).collect()
    };
    // A submission's build: the student's code, whose binary is only ever a subject.
    let submission = options.judge.is_some();
    let built = match &options.binary {
        Some(binary) => Built {
            binary: binary.clone(),
            lectures: wanted.clone(),
            failed: Default::default(),
            waiting: Default::default(),
        },
        None => compile::build(
            ws,
            &BuildOptions {
                lectures: wanted.clone(),
                // A student's local grade, rebuilt after every edit, links no tools. A submission is
                // built once, where they cost nothing measurable, and its binary is then the whole
                // of its week: the course's week test renders each week's scenes with it.
                tools: submission,
                // Graded with a judge, the hidden checks are the judge's alone: the student's build
                // has neither their code nor their answers (`grader/checks/core/src/remote.rs`).
                hidden: options.hidden && !submission,
                release: options.release,
                f64: options.f64,
                target_dir: options.target_dir.clone(),
                build_dir: None,
                show_progress: options.show_progress,
                run_as: options.run_as.first().cloned(),
                submission,
            },
        )?,
    };
    if let (false, Some(target)) = (options.run_as.is_empty(), &options.target_dir) {
        // Built: the student's build folder is the grader's again (the binary the checks run
        // cannot be rewritten by one of them), and nothing of the build is left running.
        crate::platform::reclaim_tree(target)?;
        for user in &options.run_as {
            crate::platform::sweep(user, &BTreeSet::new());
        }
    }
    let all = match &options.judge {
        // Which checks exist, their points, needs, limits and hidden flags are the judge's word (a
        // build of the instructor's tree); the student's build says only, through cargo, which
        // lectures compiled. Its binary is never asked for a list.
        Some(judge) => from_judge(judge.binary()?, &built)?,
        None => list(&built.binary)?,
    };
    let mut infos: Vec<Info> = all
        .iter()
        .filter(|i| (options.hidden || !i.hidden) && options.selection.matches(i))
        .cloned()
        .collect();
    if infos.is_empty() {
        return Err(format!("no check matches {}", options.selection.0.join(" ")));
    }
    // The earlier exercises the selected checks need (an image's stage draws with 01's camera) are
    // graded too, unseen, so a failure that is theirs says "blocked by 01/look_at", not this lecture's.
    let shown = infos.len();
    let needed: BTreeSet<String> = infos.iter().flat_map(|i| i.needs.iter().cloned()).collect();
    infos.extend(all.into_iter().filter(|i| {
        !i.hidden
            && !options.selection.matches(i)
            && needed.contains(&i.exercise_id())
            && built.lectures.contains(&i.lecture)
    }));
    let out = out_dir(ws, options);
    let scratch = scratch_dir(&out)?;
    // Verdicts that need no run, and the checks to run.
    let mut verdicts: Vec<Option<Verdict>> = Vec::with_capacity(infos.len());
    let (mut to_run, mut unseen) = (Vec::new(), Vec::new());
    for (index, info) in infos.iter().enumerate() {
        match not_runnable(info, &built) {
            Some(verdict) => verdicts.push(Some(verdict)),
            None => {
                verdicts.push(None);
                if index < shown { to_run.push(index) } else { unseen.push(index) }
            }
        }
    }
    let results = Mutex::new(verdicts);
    let run = |to_run: Vec<usize>| {
        run_checks(&infos, to_run, &results, (&built.binary, &out, &scratch), ws, options)
    };
    run(to_run);
    // The unseen checks change only the verdict of a check that failed (`apply_needs`): they run
    // when one did, those of the exercises it needs. Everything passing, they cost nothing.
    let failed_needs: BTreeSet<String> = results
        .lock()
        .map_err(|_| "a grading thread panicked")?
        .iter()
        .flatten()
        .filter(|v| matches!(v.status, Status::Failed | Status::Crashed | Status::TimedOut))
        .flat_map(|v| v.info.needs.iter().cloned())
        .collect();
    unseen.retain(|&index| failed_needs.contains(&infos[index].exercise_id()));
    run(unseen);
    let mut verdicts: Vec<Verdict> =
        results.into_inner().map_err(|_| "a grading thread panicked")?.into_iter().flatten().collect();
    apply_needs(&mut verdicts);
    verdicts.truncate(shown);
    course_order(ws, &mut verdicts);
    Ok(Grade {
        verdicts,
        compile_errors: built.failed.into_iter().collect(),
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// Runs the checks `to_run` (indices into `infos`), as many at once as `options.jobs` (one a
/// grading user), each verdict into its place in `results`.
fn run_checks(
    infos: &[Info],
    mut to_run: Vec<usize>,
    results: &Mutex<Vec<Option<Verdict>>>,
    (binary, out, scratch): (&Path, &Path, &Path),
    ws: &Workspace,
    options: &GradeOptions,
) {
    // The pictures first: they take the longest (a mesh drawn by brute force, 64 shadow rays a
    // pixel), and started last they would run on alone after the short checks, one core idle.
    to_run.sort_by_key(|&index| infos[index].kind != Kind::Image);
    let queue = Mutex::new(to_run.into_iter());
    // As other users, a job per user: a check's processes count against its user's limit only.
    let jobs = match options.run_as.len() {
        0 => options.jobs.max(1),
        users => options.jobs.clamp(1, users),
    };
    let lecture_of = |file: &str| ws.lecture_of_path(file);
    std::thread::scope(|scope| {
        for job in 0..jobs {
            let (queue, lecture_of) = (&queue, &lecture_of);
            let user = options.run_as.get(job);
            scope.spawn(move || {
                while let Some(index) = queue.lock().map(|mut q| q.next()).unwrap_or(None) {
                    let info = infos[index].clone();
                    let timeout = Duration::from_secs(info.timeout_s.into());
                    // A submission's every check is judged: nothing its process writes is a verdict.
                    let ran = match options.judge.as_ref().map(crate::submission::Judge::binary) {
                        Some(Ok(judge)) => run_judged(binary, judge, &info, out, timeout, user),
                        Some(Err(e)) => Err(e),
                        None => run_check(binary, &info.id, scratch, out, timeout),
                    };
                    let verdict = match ran {
                        Ok(ran) => classify(info, &ran, lecture_of),
                        Err(e) => Verdict::new(info, Status::Crashed, e),
                    };
                    if let Ok(mut results) = results.lock() {
                        results[index] = Some(verdict);
                    }
                }
            });
        }
    });
}

/// Sorts `verdicts` in the course's order: lecture by lecture, each lecture's exercises in the
/// order of its README's table (the chapter's, tested), then its pictures, each group as the
/// checks declare it. The table, the report, the JSON and `next:` read in it.
fn course_order(ws: &Workspace, verdicts: &mut [Verdict]) {
    let orders: std::collections::BTreeMap<String, Vec<String>> =
        ws.lectures.iter().map(|l| (l.number.clone(), ws.exercise_order(&l.number))).collect();
    let place = |v: &Verdict| {
        let order = orders.get(&v.info.lecture);
        let row = order.and_then(|o| o.iter().position(|e| *e == v.info.exercise)).unwrap_or(usize::MAX);
        (v.info.lecture.clone(), v.info.kind == raylab_protocol::Kind::Image, row)
    };
    // Stable: equal keys keep the declared order.
    verdicts.sort_by_cached_key(place);
}

/// The verdict of a check that cannot run in this build, or `None`.
fn not_runnable(info: &Info, built: &Built) -> Option<Verdict> {
    if let Some(error) = built.failed.get(&info.lecture) {
        let summary = if error.in_checks {
            format!(
                "lecture {} compiles, but the grader's checks do not compile against it: {} at {} — did a \
                 function's signature change? The checks call the names and parameters of the exercise contract",
                info.lecture, error.message, error.location
            )
        } else {
            format!("{} at {}", error.message, error.location)
        };
        return Some(Verdict::new(info.clone(), Status::DoesNotCompile, summary));
    }
    if let Some(failed) = built.waiting.get(&info.lecture) {
        let needs = format!("{failed} (does not compile)");
        let summary = format!("needs lecture {failed}, which does not compile");
        return Some(Verdict::blocked(info.clone(), &needs, summary));
    }
    if info.available {
        return None;
    }
    // Every check needs only its own lecture and the lectures that one uses (its stage's, for images):
    // built, failed or waiting, all handled above.
    let summary = format!("not in this build of the checks ({})", pretty(&info.exercise_id()));
    Some(Verdict::new(info.clone(), Status::Crashed, summary))
}

/// `raylab-checks list`.
fn list(binary: &Path) -> Result<Vec<Info>, String> {
    let output = Command::new(binary)
        .arg("list")
        .output()
        .map_err(|e| format!("could not run {}: {e}", binary.display()))?;
    if !output.status.success() {
        return Err(format!("{} list failed: {}", binary.display(), String::from_utf8_lossy(&output.stderr)));
    }
    serde_json::from_slice(&output.stdout).map_err(|e| format!("the list of checks: {e}"))
}

/// The checks of a submission: every check the judge declares (hidden ones included), each
/// runnable where its lecture is in the student's build (`built`, what cargo built: a lecture's
/// checks, its scenes' and the final pictures' included, need that lecture and those it uses,
/// and the final stage's lecture uses every lecture).
fn from_judge(judge: &Path, built: &Built) -> Result<Vec<Info>, String> {
    Ok(list(judge)?
        .into_iter()
        .map(|i| Info { available: built.lectures.contains(&i.lecture), ..i })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The checks declare lecture 01's rotations before its `transform_point`; its README (and
    /// chapter) teach `translate`, `scale`, then `transform_point`: the grade, and so `next:`,
    /// reads in the README's order, pictures last.
    #[test]
    fn the_grade_reads_in_the_readmes_order_pictures_last() {
        let ws = Workspace::open(&crate::workspace::own_root()).unwrap();
        let verdict = |id: &str, kind| {
            let info = Info { kind, ..crate::verdict::test_info(id) };
            Verdict::new(info, Status::Passed, String::new())
        };
        let unit = raylab_protocol::Kind::Unit;
        let mut verdicts = vec![
            verdict("02/hit_plane/unit", unit),
            verdict("01/image/camera", raylab_protocol::Kind::Image),
            verdict("01/rotate_x/unit", unit),
            verdict("01/transform_point/unit", unit),
            verdict("01/translate/unit", unit),
            verdict("01/translate/far", unit),
        ];
        course_order(&ws, &mut verdicts);
        let ids: Vec<&str> = verdicts.iter().map(|v| v.info.id.as_str()).collect();
        assert_eq!(
            ids,
            [
                "01/translate/unit",
                "01/translate/far",
                "01/transform_point/unit",
                "01/rotate_x/unit",
                "01/image/camera",
                "02/hit_plane/unit"
            ]
        );
    }

    #[test]
    fn selections_read_as_lecture_exercise_or_check() {
        let slabs = crate::verdict::test_info("03/hit_slabs/unit");
        let parse = |s: &[&str]| Selection::parse(s).unwrap();
        assert!(parse(&[]).matches(&slabs));
        assert!(parse(&["03"]).matches(&slabs));
        assert!(parse(&["03-polygons-triangles"]).matches(&slabs));
        assert!(parse(&["03/hit_slabs"]).matches(&slabs));
        assert!(parse(&["03/hit_slabs/unit"]).matches(&slabs));
        assert!(parse(&["02", "03/hit_slabs"]).matches(&slabs));
        assert!(!parse(&["03/hit_slab"]).matches(&slabs));
        assert!(!parse(&["02"]).matches(&slabs));
        assert!(Selection::parse(&["slabs"]).is_err());
        assert_eq!(parse(&["03/hit_slabs", "05"]).lectures(), ["03", "05"]);
    }
}
