//! Grading a student's tree in a work folder, and the judge it is graded with.
//!
//! `grader grade --submission DIR` takes only `lectures/*/src` from DIR into
//! a pristine copy of the instructor's workspace (the work folder), so edited
//! checks, snapshots or manifests change nothing, and grades it with the
//! hidden checks. A lecture missing from the submission is graded as the
//! handout has it (`todo!()` everywhere). Files are written only when their
//! content changes, so the work folder's build stays incremental: on
//! Gradescope, `setup.sh` builds it once and each submission rebuilds only
//! the lectures it changed. The Gradescope bundle that does so is `gradescope.rs`.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};
use std::thread::JoinHandle;

use crate::handout::stub_solutions;
use crate::workspace::Workspace;

/// Folders of the instructor's workspace not copied into the work folder.
pub(crate) const NOT_COPIED: &[&str] = &["target", ".git", "book/book"];

/// The largest submission read, in bytes: a lecture's sources are ~100 kB.
const MAX_SUBMISSION_BYTES: u64 = 20 << 20;

/// What only the judge may read (`submission::judge`), kept out of the work folder where the
/// student's code is built and run: the snapshots (a render that copies its snapshot would pass),
/// the book's figures (copies of them) and the hidden checks (their inputs and answers).
fn judges_only(relative: &str) -> bool {
    let parts: Vec<&str> = relative.split('/').collect();
    (parts.len() >= 3 && parts[0] == "lectures" && parts[2] == "snapshots")
        || under(relative, &["book/src/figures", HIDDEN_CHECKS])
}

/// The hidden checks' source: the judge's alone.
const HIDDEN_CHECKS: &str = "grader/checks/src/lectures/hidden.rs";

/// Whether `relative` is one of `folders` or inside one.
pub(crate) fn under(relative: &str, folders: &[&str]) -> bool {
    folders.iter().any(|f| relative == *f || relative.starts_with(&format!("{f}/")))
}

/// `lectures/NN-name/src` or a file in it: what a submission replaces.
fn is_lecture_source(relative: &str) -> bool {
    let parts: Vec<&str> = relative.split('/').collect();
    parts.len() >= 3 && parts[0] == "lectures" && parts[2] == "src"
}

/// A work folder prepared for one submission ([`prepare`]), held by its grade until dropped.
pub struct Prepared {
    /// The work folder's workspace: the instructor's tree with the submission's lectures.
    pub ws: Workspace,
    /// Where cargo builds the student's code (`work/target`; as another user,
    /// `work/target/student`, theirs).
    pub target: PathBuf,
    /// The lock on `work/target/grade.lock` ([`hold`]).
    _held: std::fs::File,
}

/// Prepares the work folder for `submission`, which it holds until the [`Prepared`] is dropped.
pub fn prepare(
    root: &Path,
    submission: &Path,
    workdir: Option<&Path>,
    run_as: Option<&crate::platform::RunAs>,
) -> Result<Prepared, String> {
    let root = root.canonicalize().map_err(|e| format!("{}: {e}", root.display()))?;
    let submitted = find_lectures(submission)?;
    let work = workdir.map_or_else(|| root.join("target/grader/submission"), Path::to_owned);
    if work.starts_with(submission) || submission.starts_with(&work) {
        return Err("the work folder and the submission must not contain each other".into());
    }
    std::fs::create_dir_all(&work).map_err(|e| format!("{}: {e}", work.display()))?;
    let work = work.canonicalize().map_err(|e| format!("{}: {e}", work.display()))?;
    let held = hold(&work)?;
    mirror(&root, &work, &|relative| {
        !under(relative, NOT_COPIED) && !is_lecture_source(relative) && !judges_only(relative)
    })?;
    remove_judges_only(&work)?;
    let ws = Workspace::open(&root)?;
    // What the submission's folder holds, links resolved: a link out of it (to the instructor's
    // reference, which the grader may read) is not the student's work.
    let inside = submission.canonicalize().map_err(|e| format!("{}: {e}", submission.display()))?;
    let mut taken = Vec::new();
    for lecture in &ws.lectures {
        let source = submitted.join(&lecture.folder).join("src");
        let target = work.join("lectures").join(&lecture.folder).join("src");
        if source.is_dir() {
            if !source.canonicalize().is_ok_and(|real| real.starts_with(&inside)) {
                return Err(format!(
                    "{}: a link to a folder outside the submission (submit the files themselves)",
                    source.display()
                ));
            }
            check_size(&source)?;
            mirror(&source, &target, &|_| true)?;
            taken.push(lecture.number.clone());
        } else {
            // Not submitted: the handout's stubs.
            stub_lecture(&root, lecture, &target)?;
        }
    }
    eprintln!(
        "grading {} (lectures {}) in {}",
        submission.display(),
        if taken.is_empty() { "none".to_owned() } else { taken.join(", ") },
        work.display()
    );
    // Where cargo builds the student's code.
    let target = match run_as {
        Some(user) => {
            eprintln!("the student's code is built and run as {}", user.name);
            student_target(&work, user)?
        }
        None => work.join("target"),
    };
    Ok(Prepared { ws: Workspace::open(&work)?, target, _held: held })
}

/// Holds the work folder `work` for one grade: a lock on `work/target/grade.lock` (the file
/// system's, so it holds across processes and ends with the process). A second grader given the
/// same folder, a class and a single grade say, waits for the first to end: the two would write
/// their lectures over each other's and build and run each other's code, each grade then reporting
/// the other submission's answers as its own.
fn hold(work: &Path) -> Result<std::fs::File, String> {
    let dir = work.join("target");
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let waiting =
        format!("{} is another grade's work folder now; waiting for that grade to end", work.display());
    take_lock(&dir.join("grade.lock"), &waiting)
}

/// A lock on the file `path` (made if missing), held until the file is dropped: at once, or after
/// saying `waiting` when another process holds it. Where the file system has no locks (some
/// network file systems), a warning, and no lock.
fn take_lock(path: &Path, waiting: &str) -> Result<std::fs::File, String> {
    let file = std::fs::File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
    match file.try_lock() {
        Ok(()) => {}
        Err(std::fs::TryLockError::WouldBlock) => {
            eprintln!("{waiting}");
            file.lock().map_err(|e| format!("{}: {e}", path.display()))?;
        }
        Err(std::fs::TryLockError::Error(e)) if e.kind() == std::io::ErrorKind::Unsupported => eprintln!(
            "warning: {} cannot be locked on this file system ({e}): give it to one grader at a time",
            path.display()
        ),
        Err(std::fs::TryLockError::Error(e)) => return Err(format!("{}: {e}", path.display())),
    }
    Ok(file)
}

/// Removes from the work folder `work` what an earlier grader put there and only the judge may
/// read ([`judges_only`]).
fn remove_judges_only(work: &Path) -> Result<(), String> {
    let mut gone: Vec<PathBuf> = vec![work.join("book/src/figures"), work.join(HIDDEN_CHECKS)];
    if let Ok(entries) = std::fs::read_dir(work.join("lectures")) {
        gone.extend(entries.filter_map(Result::ok).map(|e| e.path().join("snapshots")));
    }
    for path in gone {
        let removed = if path.is_dir() {
            std::fs::remove_dir_all(&path)
        } else if path.is_file() {
            std::fs::remove_file(&path)
        } else {
            Ok(())
        };
        removed.map_err(|e| format!("{}: {e}", path.display()))?;
    }
    Ok(())
}

/// Where `user` builds the student's code: `work/target/student`, theirs while cargo builds, and
/// nothing else of the work folder. The sources stay the grader's (the user reads them), and so does the grader's
/// output, `work/target/grader`, which the judge writes as root: in a folder the user owned, a
/// link could turn those writes elsewhere.
fn student_target(work: &Path, user: &crate::platform::RunAs) -> Result<PathBuf, String> {
    let student = work.join("target").join("student");
    std::fs::create_dir_all(&student).map_err(|e| format!("{}: {e}", student.display()))?;
    crate::platform::reclaim(work)?;
    crate::platform::reclaim(&work.join("target"))?;
    // Theirs while cargo builds in it; the grader's again once built (`grade`).
    crate::platform::give_tree(&student, user)?;
    Ok(student)
}

/// Writes lecture `lecture`'s sources into `target` as the handout has them:
/// every exercise `todo!()`.
fn stub_lecture(root: &Path, lecture: &crate::workspace::Lecture, target: &Path) -> Result<(), String> {
    let reference = root.join("lectures").join(&lecture.folder).join("src");
    mirror_as(&reference, target, &|_| true, &|relative, bytes| {
        if !relative.ends_with(".rs") {
            return Ok(bytes);
        }
        let text = String::from_utf8(bytes).map_err(|e| format!("{relative}: {e}"))?;
        let (stubbed, _) = stub_solutions(&text, &lecture.number, relative)?;
        Ok(stubbed.into_bytes())
    })
}

/// The judge of a grade: its binary, or its build still running on a thread of its own beside the
/// submission's ([`Judge::building`]). The two cold builds overlap: the judge's is mostly the
/// chain kit → lectures → checks, one crate at a time, which leaves a core free that the
/// submission's build takes.
#[derive(Clone)]
pub struct Judge {
    building: Arc<Mutex<Option<JoinHandle<JudgeBuilt>>>>,
    binary: Arc<OnceLock<JudgeBuilt>>,
}

/// What [`judge`] returns: the judge's binary, or why there is none.
type JudgeBuilt = Result<PathBuf, String>;

impl Judge {
    // INSTRUCTOR BEGIN
    /// A judge already built (`judge`): `grader class` builds its one judge first.
    pub fn built(binary: PathBuf) -> Judge {
        Judge { building: Arc::default(), binary: Arc::new(OnceLock::from(Ok(binary))) }
    }

    // INSTRUCTOR END
    /// [`judge`] for `root`, built on a thread from now on.
    pub fn building(root: &Path, options: &crate::grade::GradeOptions) -> Judge {
        let (root, options) = (root.to_owned(), options.clone());
        let handle = std::thread::spawn(move || judge(&root, &options));
        Judge { building: Arc::new(Mutex::new(Some(handle))), binary: Arc::default() }
    }

    /// The judge's binary, once built (waits for its build), or why there is none.
    pub fn binary(&self) -> Result<&Path, String> {
        let built = self.binary.get_or_init(|| {
            let handle = self.building.lock().unwrap_or_else(|e| e.into_inner()).take();
            match handle.map(JoinHandle::join) {
                Some(Ok(built)) => built,
                Some(Err(_)) => Err("the judge's build panicked".to_owned()),
                None => Err("the judge's build was waited for twice".to_owned()),
            }
        });
        built.as_deref().map_err(Clone::clone)
    }
}

impl std::fmt::Debug for Judge {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.binary.get() {
            Some(built) => f.debug_tuple("Judge").field(built).finish(),
            None => f.write_str("Judge(building)"),
        }
    }
}

/// The judge of submissions: the instructor's workspace with every exercise
/// stubbed (`todo!()`), the snapshots and the hidden checks in, built in
/// `ROOT/target/grader/judge` (`judge-f64`, `judge-release`, … for the other builds, which
/// then neither rebuild nor replace it under a run of another), outside every work folder (on Gradescope,
/// inside the autograder's source, which the student's user cannot read). It
/// runs no student code and no reference solution: a check that called either
/// without `judge::student` would stop on a stub (the reference graded as a
/// submission proves there is none). Built once; later submissions find it up
/// to date.
pub fn judge(root: &Path, options: &crate::grade::GradeOptions) -> Result<PathBuf, String> {
    let root = root.canonicalize().map_err(|e| format!("{}: {e}", root.display()))?;
    let build = match (options.f64, options.release) {
        (false, false) => "",
        (true, false) => "-f64",
        (false, true) => "-release",
        (true, true) => "-f64-release",
    };
    let tree = root.join("target").join("grader").join(format!("judge{build}"));
    // Two graders at once (a class graded in parallel) would rewrite the tree under each
    // other's cargo: the second waits here until the first has built, then finds it up to date.
    let lock_path = tree.with_extension("lock");
    std::fs::create_dir_all(root.join("target").join("grader"))
        .map_err(|e| format!("{}: {e}", lock_path.display()))?;
    let _lock = take_lock(&lock_path, "another grader is building the judge; waiting for its build")?;
    let keep = |relative: &str| !under(relative, NOT_COPIED) && !is_lecture_source(relative);
    mirror_as(&root, &tree, &keep, &|relative, bytes| {
        if relative.ends_with("Cargo.toml") && relative != "Cargo.toml" {
            judges_version(relative, bytes)
        } else if relative == "Cargo.lock" {
            judges_lock(bytes)
        } else {
            Ok(bytes)
        }
    })?;
    let ws = Workspace::open(&root)?;
    for lecture in &ws.lectures {
        stub_lecture(&root, lecture, &tree.join("lectures").join(&lecture.folder).join("src"))?;
    }
    let judge_ws = Workspace::open(&tree)?;
    let built = crate::compile::build(
        &judge_ws,
        &crate::compile::BuildOptions {
            lectures: judge_ws.lectures.iter().map(|l| l.number.clone()).collect(),
            tools: false,
            hidden: true,
            release: options.release,
            f64: options.f64,
            target_dir: Some(tree.join("target")),
            build_dir: build_dir(&root),
            show_progress: options.show_progress,
            run_as: None,
            submission: false,
        },
    )?;
    if let Some((lecture, error)) = built.failed.iter().next() {
        return Err(format!("the judge does not compile (lecture {lecture}): {error:?}"));
    }
    Ok(built.binary)
}

/// A package's manifest in the judge's tree, its version marked as the judge's (`0.1.0` →
/// `0.1.0-judge`). The judge builds in the instructor's build-dir ([`build_dir`]), and cargo names
/// a path package's files by its name, version and path *within its workspace*, the same in both
/// trees: without the mark, the judge's stubbed crates would be written over the instructor's (and
/// the instructor's grade once ran the judge's stubs). With it, every crate of the judge's tree is
/// a file of its own, and only the registry crates are shared.
fn judges_version(relative: &str, bytes: Vec<u8>) -> Result<Vec<u8>, String> {
    let text = String::from_utf8(bytes).map_err(|e| format!("{relative}: {e}"))?;
    let mut section = "";
    let mut marked = false;
    let mut lines: Vec<String> = Vec::new();
    for line in text.lines() {
        let trimmed = line.trim();
        if trimmed.starts_with('[') {
            section = trimmed;
        }
        let version = trimmed.strip_prefix("version").map(str::trim_start);
        match (section, version.and_then(|v| v.strip_prefix('='))) {
            ("[package]", Some(value)) if !marked => {
                let value = value.trim();
                let Some(number) = value.strip_prefix('"').and_then(|v| v.strip_suffix('"')) else {
                    return Err(format!(
                        "{relative}: the package's version is not a literal (`version = \"0.1.0\"`), \
                         which the judge's build marks as its own"
                    ));
                };
                lines.push(format!("version = \"{number}-judge\""));
                marked = true;
            }
            _ => lines.push(line.to_owned()),
        }
    }
    if text.contains("[package]") && !marked {
        return Err(format!(
            "{relative}: the package has no `version = \"…\"` line, which the judge's build marks as its own"
        ));
    }
    Ok((lines.join("\n") + "\n").into_bytes())
}

/// The workspace's `Cargo.lock` in the judge's tree: each path package (the `[[package]]` entries
/// without a `source`, the workspace's members) at its version marked as [`judges_version`] marks
/// it. The lock then still holds for the judge's tree, and cargo resolves nothing again (offline,
/// as a grading machine may be, it could not: a registry crate it had not fetched stopped the build).
fn judges_lock(bytes: Vec<u8>) -> Result<Vec<u8>, String> {
    let text = String::from_utf8(bytes).map_err(|e| format!("Cargo.lock: {e}"))?;
    let mut out = String::with_capacity(text.len() + 1024);
    for entry in text.split_inclusive("[[package]]") {
        let is_path_package = !entry.lines().any(|l| l.starts_with("source = "));
        for line in entry.split_inclusive('\n') {
            match line.strip_prefix("version = \"").and_then(|v| v.strip_suffix("\"\n")) {
                Some(number) if is_path_package => out.push_str(&format!("version = \"{number}-judge\"\n")),
                _ => out.push_str(line),
            }
        }
    }
    Ok(out.into_bytes())
}

/// Where cargo builds the instructor's workspace on the way (its `build-dir`, the target folder
/// unless configured), as cargo reports it; `None` if it does not say. The judge builds there too:
/// the registry crates, the larger half of a cold build, are then built once for the instructor's
/// checks and the judge (the same crates with the same features and profile), while the judge's
/// own crates, versioned as the judge's ([`judges_version`]), are files of their own, and its
/// binary still goes to its own target folder. Nothing of a student's is ever built there: their
/// work folder has its own.
fn build_dir(root: &Path) -> Option<PathBuf> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let output = std::process::Command::new(cargo)
        .args(["metadata", "--no-deps", "--format-version", "1", "--manifest-path"])
        .arg(root.join("Cargo.toml"))
        .stdin(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .output()
        .ok()?;
    let metadata: serde_json::Value = serde_json::from_slice(&output.stdout).ok()?;
    metadata["build_directory"].as_str().map(PathBuf::from)
}

// INSTRUCTOR BEGIN
/// Every file of `submission`'s lectures' sources (what a grade of it takes), in a fixed order.
pub fn lecture_files(submission: &Path) -> Result<Vec<PathBuf>, String> {
    let lectures = find_lectures(submission)?;
    let mut files = Vec::new();
    for entry in std::fs::read_dir(&lectures).map_err(|e| format!("{}: {e}", lectures.display()))? {
        let source = entry.map_err(|e| e.to_string())?.path().join("src");
        if source.is_dir() {
            files.extend(walk(&source)?);
        }
    }
    files.sort();
    Ok(files)
}
// INSTRUCTOR END

/// The folder of `submission` that holds the lecture folders: its
/// `lectures/`, or that of its one subfolder that has one (an unpacked zip).
fn find_lectures(submission: &Path) -> Result<PathBuf, String> {
    if submission.join("lectures").is_dir() {
        return Ok(submission.join("lectures"));
    }
    let entries = std::fs::read_dir(submission).map_err(|e| format!("{}: {e}", submission.display()))?;
    let nested: Vec<PathBuf> =
        entries.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.join("lectures").is_dir()).collect();
    match &nested[..] {
        [one] => Ok(one.join("lectures")),
        [] => Err(format!(
            "{} has no lectures/ folder (submit the workspace with lectures/NN-name/src)",
            submission.display()
        )),
        _ => Err(format!("{} has several folders with a lectures/ folder", submission.display())),
    }
}

fn check_size(dir: &Path) -> Result<(), String> {
    let mut total = 0;
    for file in walk(dir)? {
        total += std::fs::metadata(&file).map(|m| m.len()).unwrap_or(0);
    }
    if total > MAX_SUBMISSION_BYTES {
        return Err(format!(
            "{} holds {} MB; a lecture's sources are well under 1 MB",
            dir.display(),
            total >> 20
        ));
    }
    Ok(())
}

/// Every regular file under `dir` (symbolic links are not followed).
fn walk(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut files = Vec::new();
    let mut stack = vec![dir.to_owned()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).map_err(|e| format!("{}: {e}", d.display()))? {
            let entry = entry.map_err(|e| e.to_string())?;
            let kind = entry.file_type().map_err(|e| e.to_string())?;
            if kind.is_dir() {
                stack.push(entry.path());
            } else if kind.is_file() {
                files.push(entry.path());
            }
        }
    }
    files.sort();
    Ok(files)
}

/// Makes `to` hold the files of `from` that `keep` (given the path relative
/// to `from`, with `/`) accepts: new or changed files are written, files
/// that are gone are removed, unchanged ones are left alone.
pub(crate) fn mirror(from: &Path, to: &Path, keep: &dyn Fn(&str) -> bool) -> Result<(), String> {
    mirror_as(from, to, keep, &|_, bytes| Ok(bytes))
}

/// A file's content as written: from its path relative to the mirror's root and its bytes.
type Content<'a> = dyn Fn(&str, Vec<u8>) -> Result<Vec<u8>, String> + 'a;

/// [`mirror`], each file's content as `content(relative path, bytes)` makes it:
/// an unchanged result is not written again, so cargo sees nothing new.
fn mirror_as(
    from: &Path,
    to: &Path,
    keep: &dyn Fn(&str) -> bool,
    content: &Content<'_>,
) -> Result<(), String> {
    let mut wanted = BTreeSet::new();
    let mut stack = vec![from.to_owned()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))? {
            let entry = entry.map_err(|e| e.to_string())?;
            let path = entry.path();
            let relative =
                path.strip_prefix(from).map_err(|e| e.to_string())?.to_string_lossy().replace('\\', "/");
            if !keep(&relative) {
                continue;
            }
            let kind = entry.file_type().map_err(|e| e.to_string())?;
            if kind.is_dir() {
                stack.push(path);
            } else if kind.is_file() {
                let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
                write_if_changed(&to.join(&relative), &content(&relative, bytes)?)?;
                wanted.insert(relative);
            }
        }
    }
    // Files of an earlier submission that this one does not have.
    if to.is_dir() {
        for file in walk(to)? {
            let relative =
                file.strip_prefix(to).map_err(|e| e.to_string())?.to_string_lossy().replace('\\', "/");
            if keep(&relative) && !wanted.contains(&relative) {
                std::fs::remove_file(&file).map_err(|e| format!("{}: {e}", file.display()))?;
            }
        }
    }
    Ok(())
}

fn write_if_changed(path: &Path, bytes: &[u8]) -> Result<(), String> {
    if std::fs::read(path).is_ok_and(|old| old == bytes) {
        return Ok(());
    }
    if let Some(parent) = path.parent() {
        std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
    }
    std::fs::write(path, bytes).map_err(|e| format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("raylab-submission-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    #[test]
    fn the_judges_packages_are_versions_of_their_own() {
        let manifest = "[package]\nname = \"l01-x\"\nversion = \"0.1.0\"\n\n[dependencies]\n\
                        serde = { version = \"1\" }\n\n[dependencies.glam]\nversion = \"0.34\"\n";
        let marked = String::from_utf8(judges_version("l/Cargo.toml", manifest.into()).unwrap()).unwrap();
        assert_eq!(marked, manifest.replacen("0.1.0", "0.1.0-judge", 1));
        // A version the judge cannot mark stops the judge's build rather than sharing files.
        for unmarkable in ["[package]\nname = \"x\"\nversion.workspace = true\n", "[package]\nname = \"x\"\n"]
        {
            let said = judges_version("x/Cargo.toml", unmarkable.into()).unwrap_err();
            assert!(said.starts_with("x/Cargo.toml: ") && said.contains("version"), "{said}");
        }
        // The lock marks the same packages (those without a source), and only them.
        let lock = "version = 4\n\n[[package]]\nname = \"l01-x\"\nversion = \"0.1.0\"\ndependencies = [\n \"serde\",\n]\n\n\
                    [[package]]\nname = \"serde\"\nversion = \"1.0.2\"\nsource = \"registry+https://x\"\n";
        let marked = String::from_utf8(judges_lock(lock.into()).unwrap()).unwrap();
        assert_eq!(marked, lock.replacen("\"0.1.0\"", "\"0.1.0-judge\"", 1));
        // A manifest without a package (a virtual workspace's) is left as it is.
        let virtual_manifest = "[workspace]\nmembers = [\"a\"]\n";
        assert_eq!(
            judges_version("v/Cargo.toml", virtual_manifest.into()).unwrap(),
            virtual_manifest.as_bytes()
        );
    }

    #[test]
    fn mirroring_writes_only_changes_and_removes_what_is_gone() {
        let (from, to) = (temp("from"), temp("to"));
        std::fs::write(from.join("a.rs"), "a").unwrap();
        std::fs::create_dir_all(from.join("sub")).unwrap();
        std::fs::write(from.join("sub/b.rs"), "b").unwrap();
        std::fs::write(to.join("stale.rs"), "old").unwrap();
        mirror(&from, &to, &|_| true).unwrap();
        assert_eq!(std::fs::read_to_string(to.join("sub/b.rs")).unwrap(), "b");
        assert!(!to.join("stale.rs").exists());
        // An unchanged file keeps its modification time: cargo does not rebuild it.
        let before = std::fs::metadata(to.join("a.rs")).unwrap().modified().unwrap();
        std::thread::sleep(std::time::Duration::from_millis(20));
        mirror(&from, &to, &|_| true).unwrap();
        assert_eq!(std::fs::metadata(to.join("a.rs")).unwrap().modified().unwrap(), before);
    }

    #[test]
    fn the_lectures_folder_may_sit_one_folder_down() {
        let dir = temp("nested");
        assert!(find_lectures(&dir).unwrap_err().contains("no lectures/ folder"));
        std::fs::create_dir_all(dir.join("raylab-main/lectures")).unwrap();
        assert_eq!(find_lectures(&dir).unwrap(), dir.join("raylab-main/lectures"));
    }
}
