//! What the whole-workbench tests share: the instructor's grader, built once
//! with the tests' precision, submissions patched from the reference, and the
//! shared work folder they are graded in.

// Each test binary (grader, class, redteam) includes this module and uses part of it.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

use serde_json::Value;

/// The shared work folder's turn: a test that builds or grades in it holds this lock on a file
/// beside it, for as long as it uses the folder. A lock of the file system's, not of the process:
/// CI runs the three test binaries side by side (`.ci/run`), and their tests take turns alike.
pub fn work_turn() -> std::fs::File {
    let path = scratch().join("work.lock");
    let file = std::fs::File::options().create(true).truncate(false).write(true).open(&path).unwrap();
    file.lock().unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    file
}

pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap().to_owned()
}

pub fn scratch() -> PathBuf {
    let dir = root().join("target/workbench");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `cargo run -p grader` in `dir` with the tests' precision; stdout, stderr, success.
pub fn cargo(dir: &Path, args: &[&str], target: Option<&Path>) -> (String, String, bool) {
    let mut command = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    // The precision's feature goes to cargo, before a `--` that starts the program's arguments.
    let split = args.iter().position(|a| *a == "--").unwrap_or(args.len());
    command.current_dir(dir).args(&args[..split]);
    if size_of::<raylab::Float>() == 8 {
        command.args(["--features", "raylab/f64"]);
    }
    command.args(&args[split..]);
    if let Some(target) = target {
        command.env("CARGO_TARGET_DIR", target);
    }
    let out = command.output().expect("cargo runs");
    (
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
        out.status.success(),
    )
}

/// The instructor's grader, built once with the tests' precision: as `cargo build --workspace`
/// builds it (`--workspace --bin grader`, the registry crates with the workspace's features),
/// which the README's test command has just done, so that nothing is built again whatever
/// features `-p grader` alone would resolve.
pub fn grader_binary() -> &'static Path {
    static BINARY: OnceLock<PathBuf> = OnceLock::new();
    BINARY.get_or_init(|| {
        let args = ["build", "-q", "--workspace", "--bin", "grader", "--message-format", "json"];
        let (stdout, stderr, ok) = cargo(&root(), &args, None);
        assert!(ok, "the grader does not build:\n{stderr}");
        stdout
            .lines()
            .filter_map(|line| serde_json::from_str::<Value>(line).ok())
            .filter(|m| m["reason"] == "compiler-artifact" && m["target"]["name"] == "grader")
            .find_map(|m| m["executable"].as_str().map(PathBuf::from))
            .expect("cargo names the grader's executable")
    })
}

/// The builds of submissions (the shared work folder, the judge) are incremental whatever the
/// environment says: the work folder is built again for every patch graded in it (the catalogue's
/// mistakes, the weeks), and an incremental rebuild of a lecture and the checks took 1.35 s
/// against 4.5 s without (median of 3, alternating; CI turns incremental builds off for the builds
/// it makes once). Every grade of a submission says the same, or the judge's build would flip
/// between the two and be rebuilt whole.
pub fn incremental(command: &mut Command) -> &mut Command {
    command.env("CARGO_INCREMENTAL", "1")
}

/// Gives `target`, the target folder of a scratch copy of the tree that cargo has not built in
/// yet, copies of what cargo compiled of the registry's crates in the instructor's build folder
/// (their `.fingerprint`, `build` and `deps` entries, modification times kept), so that the
/// copy's first build compiles its own crates only: the workspace's and the lectures', which
/// are the copy's to prove. A registry crate is the same package at the same version with the
/// same features in both workspaces, so cargo finds the copied unit fresh (same name and hash);
/// a unit the copy needs otherwise (other features, another profile) is compiled as before.
/// Path packages are never copied: a copy's `l01-transforms` hashes like the tree's (cargo
/// hashes a path package by its place in the workspace) and would pass for it.
///
/// A cold build of the grader and the checks on the 2-core machine: 75 s wall, 143 s CPU, of
/// which the registry crates 97 s (`cargo build -p grader -p raylab-checks --timings` in an
/// empty target). Copies, not links: a build in the copy that rewrote a seeded file would write
/// into the instructor's. Not for the work folder of a submission: its build adds flags of its own
/// (`-F unsafe_code`, grader/src/compile.rs), which reach every crate, so no unit of the
/// instructor's is fresh there.
pub fn seed_registry_crates(target: &Path) {
    if target.join("debug").exists() {
        return;
    }
    let (stdout, stderr, ok) = cargo(&root(), &["metadata", "--format-version", "1"], None);
    assert!(ok, "cargo metadata failed:\n{stderr}");
    let metadata: Value = serde_json::from_str(&stdout).expect("cargo metadata's JSON");
    let registry: std::collections::HashSet<String> = metadata["packages"]
        .as_array()
        .expect("packages")
        .iter()
        .filter(|p| p["source"].as_str().is_some_and(|s| s.starts_with("registry+")))
        .filter_map(|p| p["name"].as_str().map(|n| n.replace('-', "_")))
        .collect();
    let from = PathBuf::from(metadata["build_directory"].as_str().expect("a build directory")).join("debug");
    // `name-0123456789abcdef` (a unit's folder), `libname-0123456789abcdef.rlib` or
    // `name-0123456789abcdef.d` (its outputs): the package's or crate's name, `-` as `_`.
    let is_registry = |file: &str| -> bool {
        let stem = file.split('.').next().unwrap_or_default();
        let Some((name, hash)) = stem.rsplit_once('-') else { return false };
        let name = name.replace('-', "_");
        hash.len() == 16
            && hash.bytes().all(|b| b.is_ascii_hexdigit())
            && (registry.contains(&name) || name.strip_prefix("lib").is_some_and(|n| registry.contains(n)))
    };
    for folder in [".fingerprint", "build", "deps"] {
        let Ok(entries) = std::fs::read_dir(from.join(folder)) else { continue };
        for entry in entries.filter_map(Result::ok) {
            let name = entry.file_name().to_string_lossy().into_owned();
            if is_registry(&name) {
                copy_keeping_times(&entry.path(), &target.join("debug").join(folder).join(&name));
            }
        }
    }
}

/// Copies a file or folder, each file's modification time kept (cargo compares them).
fn copy_keeping_times(from: &Path, to: &Path) {
    if from.is_dir() {
        std::fs::create_dir_all(to).unwrap();
        for entry in std::fs::read_dir(from).unwrap().filter_map(Result::ok) {
            copy_keeping_times(&entry.path(), &to.join(entry.file_name()));
        }
    } else if from.is_file() {
        std::fs::create_dir_all(to.parent().unwrap()).unwrap();
        std::fs::copy(from, to).unwrap();
        let modified = std::fs::metadata(from).and_then(|m| m.modified()).unwrap();
        let file = std::fs::File::options().write(true).open(to).unwrap();
        file.set_modified(modified).unwrap();
    }
}

/// Runs the instructor's grader with `args` and reads the JSON it writes to `json`.
pub fn grader(args: &[&str], json: &Path) -> (Value, String) {
    let _ = std::fs::remove_file(json);
    let mut command = Command::new(grader_binary());
    if args.contains(&"--submission") {
        incremental(&mut command);
    }
    let out = command
        .current_dir(root())
        .args(args)
        .args(["--format", "json", "-o", json.to_str().unwrap()])
        .output()
        .expect("the grader runs");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    let text =
        std::fs::read_to_string(json).unwrap_or_else(|e| panic!("no JSON from the grader ({e}):\n{stderr}"));
    (serde_json::from_str(&text).unwrap(), stderr)
}

pub fn checks(grade: &Value) -> &Vec<Value> {
    grade["checks"].as_array().expect("a list of checks")
}

pub fn status_of<'a>(grade: &'a Value, id: &str) -> &'a Value {
    checks(grade).iter().find(|c| c["info"]["id"] == id).unwrap_or_else(|| panic!("no check {id}"))
}

/// A submission folder with a copy of the reference's `lectures/*/src`, each
/// `(file, find, replace)` applied (the find text must occur exactly once).
pub fn submission(name: &str, patches: &[(&str, &str, &str)]) -> PathBuf {
    let dir = scratch().join("submissions").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    for lecture in std::fs::read_dir(root().join("lectures")).unwrap() {
        let lecture = lecture.unwrap().path();
        copy_tree(&lecture.join("src"), &dir.join("lectures").join(lecture.file_name().unwrap()).join("src"));
    }
    for (file, find, replace) in patches {
        let path = dir.join(file);
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{file}: {e}"));
        assert_eq!(
            text.matches(find).count(),
            1,
            "{file}: the patch's text must occur exactly once: {find:?}"
        );
        std::fs::write(&path, text.replacen(find, replace, 1)).unwrap();
    }
    dir
}

/// Copies a folder, leaving out build output (`target`, the built book) and git's.
pub fn copy_tree(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap();
        if name == "target" || name == ".git" || path.ends_with("book/book") {
            continue;
        }
        let target = to.join(name);
        if path.is_dir() {
            copy_tree(&path, &target);
        } else {
            std::fs::copy(&path, &target).unwrap();
        }
    }
}

/// Grades `submission` in the shared work folder (hidden checks included).
pub fn grade_submission(submission: &Path, select: &[&str], json_name: &str) -> (Value, String) {
    let work = scratch().join("work");
    let mut args =
        vec!["grade", "--submission", submission.to_str().unwrap(), "--workdir", work.to_str().unwrap()];
    args.extend_from_slice(select);
    grader(&args, &scratch().join(json_name))
}

/// One entry of `tests/mistakes/*.toml`.
#[derive(serde::Deserialize)]
pub struct Mistake {
    pub name: String,
    pub file: String,
    pub find: String,
    pub replace: String,
    pub caught_by: String,
    pub cause: String,
    /// For a picture's check: the exercise its cause names as the first on the picture's path
    /// whose value differs (`Check NN/function`).
    #[serde(default)]
    pub named: Option<String>,
}

#[derive(serde::Deserialize)]
pub struct Catalogue {
    pub mistake: Vec<Mistake>,
    /// Right answers written another way (as the book writes them): they must pass.
    #[serde(default)]
    pub accepted: Vec<Accepted>,
}

/// One `[[accepted]]` entry of `tests/mistakes/*.toml`.
#[derive(serde::Deserialize)]
pub struct Accepted {
    pub name: String,
    pub file: String,
    pub find: String,
    pub replace: String,
}

/// Every `tests/mistakes/*.toml`, in the order of their names.
pub fn catalogues() -> Vec<Catalogue> {
    let dir = root().join("tests/mistakes");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    files.sort();
    files.retain(|f| f.extension().is_some_and(|e| e == "toml"));
    files
        .iter()
        .map(|f| {
            let text = std::fs::read_to_string(f).unwrap();
            toml::from_str::<Catalogue>(&text).unwrap_or_else(|e| panic!("{}: {e}", f.display()))
        })
        .collect()
}

pub fn catalogue() -> Vec<Mistake> {
    catalogues().into_iter().flat_map(|c| c.mistake).collect()
}

/// Runs a page's browser check (`python3 SCRIPT ARGS`, headless Chromium): passes or panics with
/// what it said. Without Chromium (its exit status 2) it says so loudly and passes, but not in CI,
/// which installs Chromium.
pub fn browser_check(script: &str, args: &[&str]) {
    let out = Command::new("python3").arg(root().join(script)).args(args).output().unwrap();
    let said = String::from_utf8_lossy(&out.stdout);
    match out.status.code() {
        Some(0) => println!("{said}"),
        Some(2) if std::env::var_os("CI").is_none() => println!("{said}"),
        _ => panic!("{script} failed:\n{said}{}", String::from_utf8_lossy(&out.stderr)),
    }
}
