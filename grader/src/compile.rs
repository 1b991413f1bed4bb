//! Building the checks with the lectures that compile.
//!
//! `raylab-checks` has one cargo feature per lecture. The grader first asks
//! cargo for all of them (`--keep-going`, JSON diagnostics); every lecture
//! with an error is set aside with its first error, and so is every lecture
//! that uses it, and the rest is built again — as rustlings drives cargo for
//! its exercises. A compile error in lecture 07 costs 07, 08 and 10 and
//! leaves the grade of 01–06 and 09 standing.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use serde_json::Value;

use crate::workspace::Workspace;

/// A lecture's first compiler error.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CompileError {
    /// `lectures/07-…/src/refract.rs:42:13`, relative to the workspace root.
    pub location: String,
    /// The compiler's one-line message.
    pub message: String,
    /// The compiler's full text of that error.
    pub rendered: String,
    /// The error is in the grader's checks for the lecture, not in its code:
    /// the lecture compiles, but a signature the checks call has changed.
    pub in_checks: bool,
}

/// What the build produced.
#[derive(Debug)]
pub struct Built {
    /// The checks binary.
    pub binary: PathBuf,
    /// The lectures whose code is in it.
    pub lectures: BTreeSet<String>,
    /// The lectures that did not compile, with their first error.
    pub failed: BTreeMap<String, CompileError>,
    /// The lectures left out because one they use did not compile:
    /// lecture → the failed lecture it waits for.
    pub waiting: BTreeMap<String, String>,
}

/// How to build.
#[derive(Clone, Debug)]
pub struct BuildOptions {
    /// The lectures wanted (their prerequisites come in by themselves).
    pub lectures: BTreeSet<String>,
    /// The tools on the complete tracer (`render`, `bless`…), with every lecture: for the tools
    /// and a submission's build, not for a local grade.
    pub tools: bool,
    pub hidden: bool,
    pub release: bool,
    pub f64: bool,
    /// Where cargo builds (`None`: the workspace's own `target/`).
    pub target_dir: Option<PathBuf>,
    /// Where cargo keeps what it builds on the way (cargo's `build-dir`; `None`: cargo's own, the
    /// target folder unless configured, and for a submission's build always its target folder):
    /// the judge's is the instructor's, so that the registry crates are built once for both
    /// (`submission::judge`).
    pub build_dir: Option<PathBuf>,
    /// Print cargo's progress lines ("Compiling l05-shading") to stderr.
    pub show_progress: bool,
    /// Build as this user: the student's code (a build compiles its `include_bytes!`).
    pub run_as: Option<crate::platform::RunAs>,
    /// A submission's build: unsafe code is forbidden ([`SUBMISSION_RUSTFLAGS`]).
    pub submission: bool,
}

/// What a submission is built with: `unsafe_code` forbidden, so that no `#[allow]` in the
/// student's code lifts it (unsafe blocks, functions and impls, `no_mangle`, `export_name`,
/// `link_section`, `extern` blocks and `global_asm!` all fail to compile: no code of theirs runs
/// before `main`, stands in for a libc symbol or allocates for the checks), and the cfg
/// `raylab_submission`, which leaves out the reference's one unsafe kernel (lecture 09's AVX2
/// traversal, `fast.rs`: a reference graded as a submission traverses with its four-wide kernel,
/// the same answers). Registry crates keep their unsafe: cargo caps their lints.
pub const SUBMISSION_RUSTFLAGS: [&str; 4] = ["-F", "unsafe_code", "--cfg", "raylab_submission"];

/// Makes `command`, a cargo build, build with [`SUBMISSION_RUSTFLAGS`] added to the flags the
/// instructor's environment asks for (CARGO_ENCODED_RUSTFLAGS, which cargo reads before RUSTFLAGS).
fn forbid_unsafe(command: &mut Command) {
    let mut flags: Vec<String> = match std::env::var("CARGO_ENCODED_RUSTFLAGS") {
        Ok(encoded) => encoded.split('\x1f').filter(|f| !f.is_empty()).map(str::to_owned).collect(),
        Err(_) => {
            std::env::var("RUSTFLAGS").unwrap_or_default().split_whitespace().map(str::to_owned).collect()
        }
    };
    flags.extend(SUBMISSION_RUSTFLAGS.iter().map(|f| (*f).to_owned()));
    command.env_remove("RUSTFLAGS").env("CARGO_ENCODED_RUSTFLAGS", flags.join("\x1f"));
}

/// The summary of a compile error that is the submission's unsafe code.
pub const UNSAFE_REFUSED: &str = "unsafe code is not allowed in a submission";

/// Builds `raylab-checks` in `ws` with as many of the wanted lectures as compile.
pub fn build(ws: &Workspace, options: &BuildOptions) -> Result<Built, String> {
    let mut wanted: BTreeSet<String> = options.lectures.iter().flat_map(|l| ws.prerequisites(l)).collect();
    let mut failed = BTreeMap::new();
    let mut waiting = BTreeMap::new();
    // Each round sets aside at least one lecture, so there are at most as many rounds as lectures.
    for _ in 0..=ws.lectures.len() {
        let attempt = cargo_build(ws, options, &wanted)?;
        let Some(errors) = &attempt.errors else {
            let binary = attempt.binary.ok_or("cargo built the checks but named no executable")?;
            return Ok(Built { binary, lectures: wanted, failed, waiting });
        };
        let mut blamed = blame(ws, errors);
        blamed.retain(|lecture, _| wanted.contains(lecture));
        if blamed.is_empty() {
            // An error no lecture explains (the tracer or the image checks, which use every lecture):
            // set aside the last lecture still wanted, which they need, and try again.
            let Some(last) = wanted.iter().next_back().cloned() else {
                let said = errors.first().map_or_else(|| attempt.unlocated(), |e| e.error.rendered.clone());
                return Err(format!("the checks do not compile even without any lecture:\n{said}"));
            };
            let error = errors.first().map(|e| e.error.clone()).unwrap_or_else(|| CompileError {
                location: String::new(),
                message: "cargo failed without a compiler error that names a file".into(),
                rendered: attempt.unlocated(),
                in_checks: true,
            });
            blamed.insert(last, error);
        }
        for (lecture, error) in blamed {
            for dependent in ws.dependents(&lecture) {
                if wanted.remove(&dependent) && dependent != lecture {
                    waiting.insert(dependent, lecture.clone());
                }
            }
            failed.insert(lecture, error);
        }
    }
    Err("the checks did not build after setting every lecture aside".into())
}

/// The first error of each lecture that has one.
fn blame(ws: &Workspace, errors: &[Located]) -> BTreeMap<String, CompileError> {
    let mut blamed = BTreeMap::new();
    for located in errors {
        let package = &located.package;
        let lecture = checks_lecture(package).or_else(|| ws.by_package(package).map(|l| l.number.clone()));
        if let Some(lecture) = lecture {
            blamed.entry(lecture).or_insert_with(|| located.error.clone());
        }
    }
    blamed
}

/// `07` for an error in lecture 07's checks crate (`raylab-checks-l07`, `grader/checks/lectures/l07`):
/// what it checks changed under it, so the lecture is set aside with it.
fn checks_lecture(package: &str) -> Option<String> {
    let number = package.strip_prefix("raylab-checks-l")?;
    (number.len() == 2 && number.chars().all(|c| c.is_ascii_digit())).then(|| number.to_owned())
}

/// An error and the package it is in.
#[derive(Clone, Debug)]
struct Located {
    package: String,
    error: CompileError,
}

struct Attempt {
    binary: Option<PathBuf>,
    /// `None` when the build succeeded.
    errors: Option<Vec<Located>>,
    /// The compiler's errors that name no file ("linking with `cc` failed", "No space left on
    /// device"), as it rendered them.
    unlocated: Vec<String>,
    /// cargo's own messages (empty when they went to the terminal: `show_progress`).
    stderr: String,
}

impl Attempt {
    /// What to show of a failure no located error explains: the compiler's unlocated errors,
    /// else cargo's `error` lines and what follows each (a file it could not read, a process it
    /// could not run, a signal that ended rustc), else cargo's last lines.
    fn unlocated(&self) -> String {
        if !self.unlocated.is_empty() {
            return self.unlocated.join("\n");
        }
        if self.stderr.trim().is_empty() {
            return "(cargo printed its messages above)".into();
        }
        let lines: Vec<&str> = self.stderr.lines().collect();
        let errors: Vec<&str> = match lines.iter().position(|l| l.starts_with("error")) {
            Some(first) => lines[first..].to_vec(),
            None => lines[lines.len().saturating_sub(20)..].to_vec(),
        };
        errors.join("\n")
    }
}

fn cargo_build(
    ws: &Workspace,
    options: &BuildOptions,
    lectures: &BTreeSet<String>,
) -> Result<Attempt, String> {
    let mut features: Vec<String> = lectures.iter().map(|l| format!("raylab-checks/l{l}")).collect();
    // Every lecture built: the complete tracer and the final images (and the tools, asked for).
    if ws.lectures.iter().all(|l| lectures.contains(&l.number)) {
        features.push("raylab-checks/complete".into());
        if options.tools {
            features.push("raylab-checks/tools".into());
        }
    }
    if options.hidden {
        features.push("raylab-checks/hidden".into());
    }
    if options.f64 {
        features.push("raylab/f64".into());
    }
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(cargo);
    command
        .current_dir(&ws.root)
        .args(["build", "--manifest-path"])
        .arg(ws.root.join("Cargo.toml"))
        // `-p grader` builds nothing of the grader's (`--bin raylab-checks`): it is there so that the
        // registry crates have the features that `cargo build --workspace` gives them, where the
        // grader's own dependencies (the class's zip and csv) turn on some of memchr's, serde's and
        // flate2's. The checks alone resolved them otherwise, and the first grade after `cargo build
        // --workspace` built 20 registry crates and everything above them again; now it builds the
        // checks crate alone (7.7 s on a fresh clone).
        .args(["-p", "raylab-checks", "-p", "grader", "--bin", "raylab-checks"])
        .args(["--no-default-features", "--keep-going"])
        .args(["--message-format", "json"])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(if options.show_progress { Stdio::inherit() } else { Stdio::piped() });
    if !features.is_empty() {
        command.arg("--features").arg(features.join(","));
    }
    if options.release {
        command.arg("--release");
    }
    if let Some(dir) = &options.target_dir {
        command.env("CARGO_TARGET_DIR", dir);
    }
    if let Some(dir) = &options.build_dir {
        command.env("CARGO_BUILD_BUILD_DIR", dir);
    } else if let (true, Some(target)) = (options.submission, &options.target_dir) {
        // A submission's build keeps all it builds in its own target folder, whatever the
        // instructor's cargo configuration says: a `build-dir` shared by every workspace would put
        // the student's crates, named as the instructor's are (cargo names a path package by its
        // place in its workspace), over the instructor's, and out of the grading user's reach.
        command.env("CARGO_BUILD_BUILD_DIR", target);
    }
    if options.submission {
        forbid_unsafe(&mut command);
    }
    if let Some(user) = &options.run_as {
        crate::platform::run_as(&mut command, user);
    }
    let output = command.output().map_err(|e| format!("could not run cargo: {e}"))?;
    let stdout = String::from_utf8_lossy(&output.stdout);
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    let mut binary = None;
    let mut errors = Vec::new();
    let mut unlocated = Vec::new();
    for line in stdout.lines() {
        let Ok(message) = serde_json::from_str::<Value>(line) else { continue };
        match message["reason"].as_str() {
            Some("compiler-artifact") => {
                if let Some(exe) = message["executable"].as_str() {
                    binary = Some(PathBuf::from(exe));
                }
            }
            Some("compiler-message") if message["message"]["level"] == "error" => {
                let package = package_name(message["package_id"].as_str().unwrap_or_default());
                match compile_error(&ws.root, &message["message"]) {
                    Some(error) => errors.push(Located { package, error }),
                    None => {
                        let text = message["message"]["message"].as_str().unwrap_or_default();
                        if !text.starts_with("aborting due to") {
                            let rendered = message["message"]["rendered"].as_str().unwrap_or(text);
                            unlocated.push(rendered.trim_end().to_owned());
                        }
                    }
                }
            }
            _ => {}
        }
    }
    if output.status.success() {
        return Ok(Attempt { binary, errors: None, unlocated, stderr });
    }
    Ok(Attempt { binary, errors: Some(errors), unlocated, stderr })
}

/// The package name in a cargo package id, in either form cargo prints:
/// `path+file:///…/lectures/07-x#l07-x@0.1.0` or `l07-x 0.1.0 (path+file:///…)`.
fn package_name(id: &str) -> String {
    if let Some((_, rest)) = id.split_once('#') {
        let name = rest.split('@').next().unwrap_or(rest);
        // `…/raylab#0.1.0`: the name is the last path segment.
        if name.chars().next().is_some_and(|c| c.is_ascii_digit()) {
            return id
                .split('#')
                .next()
                .unwrap_or_default()
                .rsplit('/')
                .next()
                .unwrap_or_default()
                .to_owned();
        }
        return name.to_owned();
    }
    id.split_whitespace().next().unwrap_or_default().to_owned()
}

/// A compiler error message, located at its primary span.
fn compile_error(root: &Path, message: &Value) -> Option<CompileError> {
    let text = message["message"].as_str()?.to_owned();
    // "aborting due to 2 previous errors" and the like carry no span.
    let spans = message["spans"].as_array()?;
    let span = spans.iter().find(|s| s["is_primary"] == true).or_else(|| spans.first())?;
    let file = span["file_name"].as_str()?;
    let relative =
        Path::new(file).strip_prefix(root).map_or_else(|_| file.to_owned(), |p| p.display().to_string());
    let location = format!("{relative}:{}:{}", span["line_start"], span["column_start"]);
    // The submission's forbidden unsafe, or an `#[allow]` that tried to lift the ban (E0453).
    let code = message["code"]["code"].as_str().unwrap_or_default();
    let text = if code == "unsafe_code" || (code == "E0453" && text.contains("unsafe_code")) {
        format!("{UNSAFE_REFUSED} ({text})")
    } else {
        text
    };
    Some(CompileError {
        in_checks: relative.starts_with("grader/"),
        location,
        message: text,
        rendered: message["rendered"].as_str().unwrap_or_default().to_owned(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn package_names_come_out_of_both_id_forms() {
        assert_eq!(
            package_name("path+file:///w/lectures/07-r#l07-reflection-refraction@0.1.0"),
            "l07-reflection-refraction"
        );
        assert_eq!(package_name("path+file:///w/grader/checks#raylab-checks@0.1.0"), "raylab-checks");
        assert_eq!(package_name("path+file:///w/crates/raylab#0.1.0"), "raylab");
        assert_eq!(
            package_name("l02-ray-casting 0.1.0 (path+file:///w/lectures/02-ray-casting)"),
            "l02-ray-casting"
        );
    }

    #[test]
    fn an_error_in_a_lectures_checks_crate_is_that_lectures() {
        assert_eq!(checks_lecture("raylab-checks-l07"), Some("07".into()));
        assert_eq!(checks_lecture("raylab-checks-core"), None);
        assert_eq!(checks_lecture("raylab-checks"), None);
        assert_eq!(checks_lecture("l07-reflection-refraction"), None);
    }

    #[test]
    fn the_primary_span_locates_the_error_relative_to_the_root() {
        let message = serde_json::json!({
            "message": "mismatched types",
            "rendered": "error[E0308]: mismatched types\n --> lectures/07-r/src/refract.rs:42:13",
            "spans": [
                {"file_name": "/w/lectures/07-r/src/x.rs", "line_start": 1, "column_start": 1, "is_primary": false},
                {"file_name": "/w/lectures/07-r/src/refract.rs", "line_start": 42, "column_start": 13, "is_primary": true}
            ]
        });
        let error = compile_error(Path::new("/w"), &message).unwrap();
        assert_eq!(error.location, "lectures/07-r/src/refract.rs:42:13");
        assert_eq!(error.message, "mismatched types");
        assert!(!error.in_checks);
    }

    /// A build that fails with no error naming a file (a full disk, rustc killed for memory)
    /// says what cargo said, not an empty message: CI once showed only "the checks do not
    /// compile even without any lecture:" and nothing after it.
    #[test]
    fn a_failure_no_file_explains_shows_what_cargo_said() {
        let attempt = |unlocated: &[&str], stderr: &str| Attempt {
            binary: None,
            errors: Some(Vec::new()),
            unlocated: unlocated.iter().map(|s| s.to_string()).collect(),
            stderr: stderr.into(),
        };
        let killed = "   Compiling raylab v0.1.0\nerror: could not compile `raylab` (lib)\n\nCaused by:\n  \
                      process didn't exit successfully: `rustc …` (signal: 9, SIGKILL: kill)";
        let said = attempt(&[], killed).unlocated();
        assert!(said.starts_with("error: could not compile `raylab`"), "{said}");
        assert!(said.contains("SIGKILL"), "{said}");
        let full = attempt(&["error: failed to write …: No space left on device (os error 28)"], killed);
        assert_eq!(full.unlocated(), "error: failed to write …: No space left on device (os error 28)");
        let tail: String = (0..30).map(|i| format!("line {i}\n")).collect();
        let said = attempt(&[], &tail).unlocated();
        assert!(said.starts_with("line 10") && said.ends_with("line 29"), "{said}");
        assert_eq!(attempt(&[], "").unlocated(), "(cargo printed its messages above)");
    }

    /// Every way safe-looking code could run before `main`, stand in for a libc symbol, allocate
    /// for the checks or reach the machine's code directly is refused by a submission's build,
    /// `#[allow]` or not, and the error says so at its line. A real cargo build of a crate of
    /// one file each.
    #[test]
    fn a_submissions_build_refuses_every_form_of_unsafe_code_allow_or_not() {
        let cases: &[(&str, &str)] = &[
            (
                "a constructor that runs before main",
                "#[allow(unsafe_code)]\n#[unsafe(link_section = \".init_array\")]\n#[used]\n\
                 static RUN_FIRST: extern \"C\" fn() = first;\nextern \"C\" fn first() {}",
            ),
            ("a libc symbol interposed", "#[unsafe(no_mangle)]\npub extern \"C\" fn write() {}"),
            ("a symbol exported by name", "#[unsafe(export_name = \"getenv\")]\npub fn forged() {}"),
            (
                "a global allocator",
                "struct Forged;\nunsafe impl std::alloc::GlobalAlloc for Forged {\n\
                 unsafe fn alloc(&self, _: std::alloc::Layout) -> *mut u8 { std::ptr::null_mut() }\n\
                 unsafe fn dealloc(&self, _: *mut u8, _: std::alloc::Layout) {}\n}\n\
                 #[global_allocator]\nstatic A: Forged = Forged;",
            ),
            ("an extern block", "unsafe extern \"C\" { safe fn getpid() -> i32; }"),
            ("assembly", "core::arch::global_asm!(\"nop\");"),
            ("an unsafe block", "pub fn f() -> u8 { unsafe { *std::ptr::null::<u8>() } }"),
            ("the ban lifted for the crate", "#![allow(unsafe_code)]\npub fn f() {}"),
        ];
        let dir = std::env::temp_dir().join(format!("raylab-unsafe-{}", std::process::id()));
        for (i, (what, code)) in cases.iter().enumerate() {
            let krate = dir.join(format!("case{i}"));
            std::fs::create_dir_all(krate.join("src")).unwrap();
            std::fs::write(
                krate.join("Cargo.toml"),
                "[package]\nname = \"attack\"\nversion = \"0.1.0\"\nedition = \"2024\"\n[workspace]\n",
            )
            .unwrap();
            std::fs::write(krate.join("src/lib.rs"), format!("//! {what}\n{code}\n")).unwrap();
            let mut command = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
            command
                .current_dir(&krate)
                .args(["build", "--message-format", "json"])
                .env("CARGO_TARGET_DIR", krate.join("target"));
            forbid_unsafe(&mut command);
            let output = command.output().unwrap();
            assert!(!output.status.success(), "{what}: built");
            let errors: Vec<CompileError> = String::from_utf8_lossy(&output.stdout)
                .lines()
                .filter_map(|l| serde_json::from_str::<Value>(l).ok())
                .filter(|m| m["reason"] == "compiler-message" && m["message"]["level"] == "error")
                .filter_map(|m| compile_error(&krate, &m["message"]))
                .collect();
            let first = errors.first().unwrap_or_else(|| panic!("{what}: no located error"));
            assert!(first.message.starts_with(UNSAFE_REFUSED), "{what}: {}", first.message);
            assert!(
                first.location.starts_with("src/lib.rs:2:") || first.location.starts_with("src/lib.rs:3:"),
                "{what}: {}",
                first.location
            );
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
