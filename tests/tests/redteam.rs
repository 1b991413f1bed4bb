//! Red team: submissions that attack the grading instead of solving the
//! exercise, graded as an instructor grades a class (`grader grade
//! --submission`). Each must end with no points for the checks it attacks and a
//! plain verdict ("failed" or "crashed", never "passed"), and leave every
//! other check's verdict as the reference's.
//!
//! Every check of a submission is judged (`grader/checks/core/src/judge.rs`): the
//! process that runs the student's code reports values and never a verdict,
//! and what only the judge may read (the snapshots, the hidden checks) is not
//! in the tree where the student's code is built and run.
//!
//! The attacks on the verdict and the grading user's take minutes: `#[ignore]`d,
//! run by `cargo test -p workbench-tests -- --ignored` and by CI every time.

mod support;

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;
use support::*;

/// (a) writes a "passed" verdict to the path after `--verdict` in its own
/// arguments (where the checks' process once wrote its outcome), then exits.
const FORGE_VERDICT_FILE: &str = r##"
    let args: Vec<String> = std::env::args().collect();
    if let Some(at) = args.iter().position(|a| a == "--verdict") {
        let _ = std::fs::write(&args[at + 1], r#"{"status":"passed","detail":"forged"}"#);
    }
    std::process::exit(0);
"##;

/// (a) prints the line a judge prints with its verdict, then exits.
const FORGE_VERDICT_LINE: &str = r##"
    println!(r#"verdict {{"status":"passed","detail":"forged"}}"#);
    std::process::exit(0);
"##;

/// (b) ends the process before the check does, writing nothing.
const EXIT_EARLY: &str = "
    std::process::exit(0);
";

/// (e) starts a process that outlives it, holding its output pipes (once per
/// check: a process per call would be a fork bomb, another attack), and
/// answers wrongly: the grader must neither wait for that process nor pass.
const OUTLIVE: &str = r#"
    static STARTED: std::sync::Once = std::sync::Once::new();
    STARTED.call_once(|| {
        let _ = std::process::Command::new("sleep").arg("600").spawn();
    });
    if objects.len() > 1 {
        return None;
    }
"#;

/// Where each attack goes: at the start of the exercise's solution.
const ATTACKS: &[(&str, &str, &str)] = &[
    ("lectures/02-ray-casting/src/sphere.rs", "hit_sphere_geometric", FORGE_VERDICT_FILE),
    ("lectures/02-ray-casting/src/sphere.rs", "hit_sphere_algebraic", FORGE_VERDICT_LINE),
    ("lectures/02-ray-casting/src/plane.rs", "hit_plane", EXIT_EARLY),
    ("lectures/02-ray-casting/src/group.rs", "closest_hit", OUTLIVE),
];

/// The submission's patches: each attack inserted after its function's `// SOLUTION BEGIN`.
fn attacked() -> Vec<(String, String, String)> {
    ATTACKS
        .iter()
        .map(|(file, function, attack)| {
            let text = std::fs::read_to_string(root().join(file)).unwrap();
            let at =
                text.find(&format!("pub fn {function}(")).unwrap_or_else(|| panic!("{file}: {function}"));
            let begin = at + text[at..].find("// SOLUTION BEGIN\n").unwrap() + "// SOLUTION BEGIN\n".len();
            // The function's first lines, up to its solution, make the patch's anchor unique.
            let anchor = text[at..begin].to_owned();
            ((*file).to_owned(), anchor.clone(), format!("{anchor}{attack}"))
        })
        .collect()
}

#[test]
#[ignore = "the whole workbench (minutes): cargo test -p workbench-tests -- --ignored; CI runs it"]
fn attacks_on_the_verdict_score_nothing_and_change_nothing_else() {
    let _turn = work_turn();
    let patches = attacked();
    let patches: Vec<(&str, &str, &str)> =
        patches.iter().map(|(f, a, r)| (f.as_str(), a.as_str(), r.as_str())).collect();
    let dir = submission("redteam", &patches);
    let (grade, stderr) = grade_submission(&dir, &["02"], "redteam.json");
    let attacked = [
        ("02/hit_sphere_geometric/unit", "crashed", "the process ended before the check did"),
        ("02/hit_sphere_algebraic/unit", "crashed", "the process ended before the check did"),
        ("02/hit_plane/unit", "crashed", "the process ended before the check did"),
        ("02/closest_hit/unit", "failed", "object 1 at t = 4"),
    ];
    for (id, status, says) in attacked {
        let check = status_of(&grade, id);
        assert_eq!(check["status"], status, "{id}: {}\n{stderr}", check["summary"]);
        assert_eq!(check["points"], 0, "{id}");
        assert!(check["summary"].as_str().unwrap().contains(says), "{id}: {}", check["summary"]);
    }
    // The process left running held the pipes of each check that called closest_hit: none waited
    // for it (its sleep is 600 s; a check that waited would take that long).
    for check in checks(&grade) {
        let seconds = check["seconds"].as_f64().unwrap_or_default();
        assert!(seconds < 60.0, "{} took {seconds} s", check["info"]["id"]);
    }
    // What calls none of the attacked functions is graded as the reference is.
    for id in [
        "02/hit_sphere_stable/unit",
        "02/hit_sphere_stable/far-small-sphere",
        "02/hit_sphere_stable/hidden-off-axis",
    ] {
        assert_eq!(status_of(&grade, id)["status"], "passed", "{id}\n{stderr}");
    }
    // Nothing attacked passed (the scenes draw with closest_hit and hit_plane).
    let forged: Vec<&str> = checks(&grade)
        .iter()
        .filter(|c| c["status"] == "passed" && c["summary"].as_str().is_some_and(|s| s.contains("forged")))
        .filter_map(|c| c["info"]["id"].as_str())
        .collect();
    assert!(forged.is_empty(), "forged verdicts passed: {forged:?}");
    for check in checks(&grade).iter().filter(|c| c["info"]["exercise"] == "image") {
        assert_ne!(check["status"], "passed", "{} draws with the attacked closest_hit", check["info"]["id"]);
    }
}

/// (f) a submission's files outside `lectures/*/src` are not its to change: a
/// lecture's `Cargo.toml` with a build script that would fail the build, the
/// build script, a file beside `src/`, and a checks file of the grader's.
#[test]
fn files_outside_the_lectures_sources_change_nothing() {
    let _turn = work_turn();
    let dir = submission("outside", &[]);
    let lecture = dir.join("lectures/02-ray-casting");
    let manifest = std::fs::read_to_string(root().join("lectures/02-ray-casting/Cargo.toml")).unwrap();
    let manifest = manifest.replacen("[package]\n", "[package]\nbuild = \"build.rs\"\n", 1);
    std::fs::write(lecture.join("Cargo.toml"), manifest).unwrap();
    std::fs::write(lecture.join("build.rs"), "fn main() { panic!(\"the submission's build script ran\") }\n")
        .unwrap();
    std::fs::create_dir_all(lecture.join("extra")).unwrap();
    std::fs::write(lecture.join("extra/forged.rs"), "compile_error!(\"a file beside src/\");\n").unwrap();
    let checks_file = dir.join("grader/checks/lectures/l02/src/lib.rs");
    std::fs::create_dir_all(checks_file.parent().unwrap()).unwrap();
    std::fs::write(&checks_file, "compile_error!(\"the grader's checks, replaced\");\n").unwrap();
    let (grade, stderr) = grade_submission(&dir, &["02"], "outside.json");
    assert!(grade["compile_errors"].as_array().unwrap().is_empty(), "{}\n{stderr}", grade["compile_errors"]);
    for check in checks(&grade) {
        assert_eq!(check["status"], "passed", "{}: {}\n{stderr}", check["info"]["id"], check["summary"]);
    }
}

/// A lecture's `src/` (or its folder, or `lectures/`) submitted as a link to the instructor's
/// reference, which the grader may read: before, graded as the student's work (full marks for a
/// handout's stubs); now the submission is refused, naming the link, and nothing is graded.
#[cfg(unix)]
#[test]
fn a_link_out_of_the_submission_is_refused_not_graded() {
    let _turn = work_turn();
    let base = submission("linked-source", &[]);
    let dir = scratch().join("submissions/linked");
    for (link, to) in [
        ("lectures/01-transforms/src", "lectures/01-transforms/src"),
        ("lectures/01-transforms", "lectures/01-transforms"),
        ("lectures", "lectures"),
    ] {
        let _ = std::fs::remove_dir_all(&dir);
        copy_tree(&base, &dir);
        let path = dir.join(link);
        std::fs::remove_dir_all(&path).unwrap();
        std::os::unix::fs::symlink(root().join(to), &path).unwrap();
        let work = scratch().join("work");
        let out = Command::new(grader_binary())
            .args(["grade", "--submission", dir.to_str().unwrap(), "--workdir", work.to_str().unwrap(), "01"])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            !out.status.success(),
            "{link}: graded
{stderr}"
        );
        assert!(
            stderr.contains("a link to a folder outside the submission")
                && stderr.contains("01-transforms/src"),
            "{link}: {stderr}"
        );
        assert!(
            !stderr.contains("points"),
            "{link}: nothing is graded
{stderr}"
        );
    }
}

/// (c) returns, as its geometry image, the snapshot of that kind and size read from its lecture's
/// folder (where the work folder once had the snapshots), else a blank image: the student has no
/// solution of their own.
const COPY_SNAPSHOT: &str = r#"
    let snapshots = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("snapshots");
    let mut paths: Vec<std::path::PathBuf> = std::fs::read_dir(&snapshots)
        .map(|entries| entries.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    paths.sort();
    for path in paths {
        let name = path.to_string_lossy().into_owned();
        let image = if name.ends_with(SUFFIX) && name.ends_with(".png") {
            Image::load_png(&path).ok()
        } else if name.ends_with(SUFFIX) {
            Image::load_exr(&path).ok()
        } else {
            None
        };
        if let Some(image) = image.filter(|i| (i.width, i.height) == (width, height)) {
            return image;
        }
    }
    return Image::new(width, height);
"#;

/// (d) reads the hidden checks' source from the tree it is built in (at run time; at compile
/// time `include_str!` of the same path would not compile) and shows it in its panic, which the
/// verdict quotes; else answers wrongly.
const READ_HIDDEN: &str = r#"
    let hidden = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../grader/checks/src/lectures/hidden.rs");
    if let Ok(text) = std::fs::read_to_string(hidden) {
        panic!("the hidden checks: {text}");
    }
    return 0.5;
"#;

/// (d) at compile time: the hidden checks' source taken into the binary, by its path in the tree
/// the lecture is built in.
const INCLUDE_HIDDEN: &str = r#"
    let _hidden: &str = include_str!("../../../grader/checks/src/lectures/hidden.rs");
"#;

/// A line of the hidden checks' source that no verdict quotes (a comment of lecture 05's).
const HIDDEN_SECRET: &str = "cos θ = 0.8; the light mirrored behind the surface";

/// The start of the function `function` in `file`, up to its `// SOLUTION BEGIN` line, and that
/// text with `attack` after it.
fn patch(file: &str, function: &str, attack: &str) -> (String, String, String) {
    let text = std::fs::read_to_string(root().join(file)).unwrap();
    let at = text.find(&format!("pub fn {function}(")).unwrap_or_else(|| panic!("{file}: {function}"));
    let begin = at + text[at..].find("// SOLUTION BEGIN\n").unwrap() + "// SOLUTION BEGIN\n".len();
    let anchor = text[at..begin].to_owned();
    (file.to_owned(), anchor.clone(), format!("{anchor}{attack}"))
}

#[test]
fn snapshots_and_hidden_checks_are_out_of_the_students_reach() {
    let _turn = work_turn();
    let images = "lectures/02-ray-casting/src/images.rs";
    let patches = [
        patch(images, "object_id_image", &COPY_SNAPSHOT.replace("SUFFIX", "\".id.png\"")),
        patch(images, "depth_image", &COPY_SNAPSHOT.replace("SUFFIX", "\".depth.exr\"")),
        patch(images, "normal_image", &COPY_SNAPSHOT.replace("SUFFIX", "\".normal.exr\"")),
        patch("lectures/05-shading/src/lambert.rs", "lambert", READ_HIDDEN),
        patch("lectures/09-acceleration/src/bounds.rs", "sphere_bounds", INCLUDE_HIDDEN),
    ];
    let patches: Vec<(&str, &str, &str)> =
        patches.iter().map(|(f, a, r)| (f.as_str(), a.as_str(), r.as_str())).collect();
    let dir = submission("out-of-reach", &patches);
    let (grade, stderr) = grade_submission(&dir, &["02", "05", "09"], "out-of-reach.json");
    // (c) No geometry picture passes: the snapshots are not where the student's code runs.
    let geometry: Vec<&Value> = checks(&grade)
        .iter()
        .filter(|c| c["info"]["exercise"] == "geometry" && c["info"]["lecture"] == "02")
        .collect();
    assert!(!geometry.is_empty(), "no 02/geometry checks graded\n{stderr}");
    for check in geometry {
        assert_eq!(check["status"], "failed", "{}: {}\n{stderr}", check["info"]["id"], check["summary"]);
        assert_eq!(check["points"], 0, "{}", check["info"]["id"]);
    }
    // (d) At compile time the file is not there: lecture 09 does not compile, and scores nothing.
    for check in checks(&grade).iter().filter(|c| c["info"]["lecture"] == "09") {
        assert_eq!(
            check["status"], "does_not_compile",
            "{}: {}\n{stderr}",
            check["info"]["id"], check["summary"]
        );
        assert_eq!(check["points"], 0, "{}", check["info"]["id"]);
    }
    // (d) The hidden lambert check fails on the wrong answer, and no verdict quotes the hidden checks.
    let hidden = status_of(&grade, "05/lambert/hidden-3-4-5");
    assert_eq!(hidden["status"], "failed", "{}\n{stderr}", hidden["summary"]);
    let everything = grade.to_string();
    assert!(!everything.contains(HIDDEN_SECRET), "a verdict quotes the hidden checks' source");
    // Nor is the hidden checks' code in the binary that runs the student's code: the judge alone
    // has it (the check's name, and a line of its case, are in the judge's binary only).
    let subject = scratch().join("work/target/debug/raylab-checks");
    let bytes = std::fs::read(&subject).unwrap_or_else(|e| panic!("{}: {e}", subject.display()));
    for secret in ["hidden-3-4-5", "n = (0, 0, 1), l = (0, 0.6, 0.8)"] {
        let found = bytes.windows(secret.len()).any(|w| w == secret.as_bytes());
        assert!(!found, "the student's build holds {secret:?}");
    }
    // (c) The image functions' own checks fail too: a copied snapshot is no object-id image of
    // the scene their check answers.
    for id in ["02/object_id_image/unit", "02/depth_image/unit", "02/normal_image/unit"] {
        let check = status_of(&grade, id);
        assert_eq!(check["status"], "failed", "{id}: {}\n{stderr}", check["summary"]);
        assert_eq!(check["points"], 0, "{id}");
    }
    // Everything else of the two lectures is graded as the reference is.
    for check in checks(&grade) {
        let id = check["info"]["id"].as_str().unwrap_or_default();
        let attacked = id.contains("/geometry/")
            || id.starts_with("05/lambert/")
            || id.starts_with("02/image/")
            || id.contains("_image/");
        if !attacked && check["info"]["lecture"] == "02" && check["info"]["kind"] != "image" {
            assert_eq!(check["status"], "passed", "{id}: {}\n{stderr}", check["summary"]);
        }
    }
}

/// (g) code that runs before the checks binary's `main` (the attack that earned 207 of 213 points
/// when the list of checks came from the student's build): a constructor in `.init_array` that
/// forges the list the binary prints and the verdict file it is given. Appended to lecture 09's
/// `lib.rs` (in lecture 01 it would cost every lecture; lecture 09 has hidden checks, which the
/// judge's list holds and the student's build does not).
const BEFORE_MAIN: &str = include_str!("../redteam/before-main.rs");

/// The last line of lecture 09's `lib.rs`, after which [`BEFORE_MAIN`] goes.
const LECTURE_09_LAST: &str = "pub use traverse::{Closest, STACK_SIZE, Waiting};\n";

#[test]
fn code_that_would_run_before_main_does_not_compile_and_the_list_is_the_judges() {
    let _turn = work_turn();
    let attack = format!("{LECTURE_09_LAST}{BEFORE_MAIN}");
    let patches = [("lectures/09-acceleration/src/lib.rs", LECTURE_09_LAST, attack.as_str())];
    let dir = submission("before-main", &patches);
    let (grade, stderr) = grade_submission(&dir, &["09"], "before-main.json");
    let nines: Vec<&Value> = checks(&grade).iter().filter(|c| c["info"]["lecture"] == "09").collect();
    // Every check the judge declares for lecture 09, hidden ones included: the list is its.
    assert!(nines.len() > 10, "{} checks of lecture 09\n{stderr}", nines.len());
    assert!(nines.iter().any(|c| c["info"]["hidden"] == true), "no hidden check of lecture 09 listed");
    for check in &nines {
        let summary = check["summary"].as_str().unwrap_or_default();
        assert_eq!(check["status"], "does_not_compile", "{}: {summary}\n{stderr}", check["info"]["id"]);
        assert_eq!(check["points"], 0, "{}", check["info"]["id"]);
        assert!(
            summary.contains("unsafe code is not allowed in a submission")
                && summary.contains("lectures/09-acceleration/src/lib.rs:"),
            "{}: {summary}",
            check["info"]["id"]
        );
    }
    assert!(!grade.to_string().contains("forged"), "a forged verdict or list reached the grade");
}

/// Attacks by the student's code run as the grading user (`grade --run-as`, what the Gradescope
/// bundle does), one per exercise of lectures 02 and 03, each once per check's process:
///
/// - (e) a kill of its parent, the grader, and a process left behind;
/// - (h) its own built binary rewritten, which the later checks would run;
/// - (i) a process that leaves the check's process group and session (setsid, a double fork)
///   and waits to rewrite every `.json` file named on a command line (the grade's output);
/// - (j) every command line under /proc read for a judge's token;
/// - (k) a fork bomb that left the check's process group;
/// - (l) the disk filled: the work folder and the temporary folder written to.
///
/// Each attacked exercise scores nothing, every other check is graded as the reference's, the
/// grade completes with its results written, and no process or temporary file of the user's is
/// left. Every process the student's code ran in recorded its user: the grading user's, always.
/// Needs root on Linux (useradd, a change of user); elsewhere it says SKIPPED.
#[test]
#[ignore = "the whole workbench (minutes): cargo test -p workbench-tests -- --ignored; CI runs it"]
fn as_the_grading_user_the_students_code_can_neither_forge_nor_disturb_the_grade() {
    // No turn of the shared work folder: this grade has a work folder of its own (the grading
    // user's), and runs beside the others.
    let root_user = Command::new("id").arg("-u").output().is_ok_and(|o| o.stdout.trim_ascii() == b"0");
    if !cfg!(target_os = "linux") || !root_user {
        eprintln!(
            "SKIPPED as_the_grading_user_the_students_code_can_neither_forge_nor_disturb_the_grade: needs \
             root on Linux"
        );
        return;
    }
    // Two grading users, one per job, as the Gradescope bundle makes one per core.
    let users = ["raylab-student", "raylab-student-2"];
    let user = users[0];
    let mut uids = Vec::new();
    for user in users {
        let known = Command::new("id").arg(user).output().is_ok_and(|o| o.status.success());
        if !known {
            let made = Command::new("useradd")
                .args(["--system", "--no-create-home", "--shell", "/usr/sbin/nologin", user])
                .status()
                .expect("useradd runs");
            assert!(made.success(), "useradd {user}");
        }
        let uid = Command::new("id").args(["-u", user]).output().expect("id runs");
        uids.push(String::from_utf8_lossy(&uid.stdout).trim().to_owned());
    }
    // What setup.sh gives the grading user: read-only copies of the toolchain and of the crates'
    // sources (hard links), nothing of root's home.
    let shared = scratch().join("as-user");
    let sysroot = Command::new("rustc").args(["--print", "sysroot"]).output().expect("rustc runs");
    let sysroot = PathBuf::from(String::from_utf8_lossy(&sysroot.stdout).trim());
    let cargo_home = std::env::var_os("CARGO_HOME")
        .map(PathBuf::from)
        .or_else(|| std::env::var_os("HOME").map(|h| PathBuf::from(h).join(".cargo")))
        .expect("a cargo home");
    for (from, to) in
        [(sysroot, shared.join("toolchain")), (cargo_home.join("registry"), shared.join("cargo/registry"))]
    {
        if !to.exists() {
            std::fs::create_dir_all(to.parent().unwrap()).unwrap();
            let linked =
                Command::new("cp").arg("-al").arg(&from).arg(&to).status().is_ok_and(|s| s.success());
            if !linked {
                let _ = std::fs::remove_dir_all(&to);
                assert!(Command::new("cp").arg("-a").arg(&from).arg(&to).status().unwrap().success());
            }
        }
    }
    assert!(Command::new("chmod").arg("-R").arg("a+rX").arg(&shared).status().unwrap().success());
    let reachable = Command::new("runuser")
        .args(["-u", user, "--"])
        .arg(shared.join("toolchain/bin/cargo"))
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !reachable {
        eprintln!(
            "SKIPPED as_the_grading_user_the_students_code_can_neither_forge_nor_disturb_the_grade: {user} \
             cannot reach {}",
            shared.display()
        );
        return;
    }
    // Where the student's processes say who they ran as: a folder anyone may write to.
    let records = shared.join("uids");
    let _ = std::fs::remove_dir_all(&records);
    std::fs::create_dir_all(&records).unwrap();
    assert!(Command::new("chmod").arg("1777").arg(&records).status().unwrap().success());
    let record = |name: &str| RECORD_UID.replace("UIDS", records.to_str().unwrap()).replace("NAME", name);
    let with_record = |name: &str, attack: &str| format!("{}{attack}", record(name));
    let sphere = "lectures/02-ray-casting/src/sphere.rs";
    let triangle = "lectures/03-polygons-triangles/src/triangle.rs";
    let patches = [
        patch(
            "lectures/02-ray-casting/src/plane.rs",
            "hit_plane",
            &with_record("hit_plane", KILL_THE_GRADER),
        ),
        patch(sphere, "hit_sphere_geometric", &with_record("geometric", REWRITE_THE_BINARY)),
        patch(sphere, "hit_sphere_algebraic", &with_record("algebraic", ESCAPE_AND_WAIT)),
        // Hidden checks call it through `serve`: a subject of that kind records its user too.
        patch(sphere, "hit_sphere_stable", &record("stable")),
        patch(triangle, "hit_triangle_cramer", &with_record("cramer", READ_PROC)),
        patch(
            "lectures/03-polygons-triangles/src/polygon.rs",
            "winding_number",
            &with_record("winding", FORK_BOMB),
        ),
        patch(triangle, "hit_triangle_moller_trumbore", &with_record("moller", FILL_THE_DISK)),
    ];
    let patches: Vec<(&str, &str, &str)> =
        patches.iter().map(|(f, a, r)| (f.as_str(), a.as_str(), r.as_str())).collect();
    let dir = submission("as-the-grading-user", &patches);
    let json = scratch().join("as-the-grading-user.json");
    let _ = std::fs::remove_file(&json);
    let path =
        format!("{}:{}", shared.join("toolchain/bin").display(), std::env::var("PATH").unwrap_or_default());
    let out = incremental(&mut Command::new(grader_binary()))
        .current_dir(root())
        .args(["grade", "--submission", dir.to_str().unwrap(), "--workdir"])
        .arg(shared.join("work"))
        .args(["--run-as", &users.join(","), "02", "03", "--format", "json", "-o", json.to_str().unwrap()])
        // The student's cargo: the shared toolchain, offline, none of root's (the test's own cargo
        // is a rustup proxy in root's home).
        .env_remove("CARGO")
        .env_remove("RUSTC")
        .env_remove("RUSTUP_TOOLCHAIN")
        .env("PATH", path)
        .env("CARGO_HOME", shared.join("cargo"))
        .env("CARGO_NET_OFFLINE", "true")
        // The judge (root's) builds beside the instructor's build, not in it: with this cargo home
        // every registry crate's path differs, and in the instructor's build folder cargo built
        // the judge whole again, here and then for the next grade of another test (84 s each in
        // CI). The student's build stays in its work folder, whatever this says.
        .env("CARGO_BUILD_BUILD_DIR", shared.join("judge-build"))
        .output()
        .expect("the grader runs");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "the grader did not finish: {:?}\n{stderr}", out.status);
    // The student's crates were built in the work folder, not in the build folder the grader's
    // environment names (the judge's): the grading user could not have written there.
    let built_in = |dir: &Path| {
        std::fs::read_dir(dir.join("debug/.fingerprint"))
            .map(|d| {
                d.filter_map(Result::ok)
                    .any(|e| e.file_name().to_string_lossy().starts_with("l02-ray-casting-"))
            })
            .unwrap_or(false)
    };
    assert!(
        built_in(&shared.join("work/target/student")),
        "the student's lecture 02 is not in its work folder"
    );
    assert!(built_in(&shared.join("judge-build")), "the judge's lecture 02 is not in its build folder");
    // (i) The results are the grader's, whole.
    let text = std::fs::read_to_string(&json).unwrap();
    let grade: Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text:.200}"));
    let attacked = [
        ("02/hit_plane/", "the kill refused"),
        ("02/hit_sphere_geometric/", "the binary not rewritten"),
        ("02/hit_sphere_algebraic/", "the escaped process ended"),
        ("03/hit_triangle_cramer/", "no token found"),
        ("03/winding_number/", "the bomb capped and ended"),
        ("03/hit_triangle_moller_trumbore/", "the files refused or ended"),
    ];
    for check in checks(&grade) {
        let id = check["info"]["id"].as_str().unwrap_or_default();
        let summary = check["summary"].as_str().unwrap_or_default();
        assert!(!summary.contains("token found"), "{id}: {summary}");
        // A check that relies on an attacked exercise (`needs`) is blocked by it where its answer
        // goes through the attacked function, else passes.
        let needs_attacked = check["info"]["needs"].as_array().is_some_and(|needs| {
            needs.iter().any(|n| {
                attacked.iter().any(|(prefix, _)| *prefix == format!("{}/", n.as_str().unwrap_or("-")))
            })
        });
        if attacked.iter().any(|(prefix, _)| id.starts_with(prefix)) {
            assert_ne!(check["status"], "passed", "{id}: {summary}");
            assert_eq!(check["points"], 0, "{id}");
        } else if needs_attacked {
            assert!(check["status"] == "blocked" || check["status"] == "passed", "{id}: {summary}");
        } else if check["info"]["kind"] != "image" || !uses_an_attacked_function(id) {
            // Everything else is graded as the reference's.
            assert_eq!(check["status"], "passed", "{id}: {summary}\n{stderr}");
        }
    }
    for (prefix, _) in attacked {
        assert!(
            checks(&grade).iter().any(|c| c["info"]["id"].as_str().unwrap().starts_with(prefix)),
            "{prefix}"
        );
    }
    // (h) The binary the checks ran is the one cargo built (the check that tried ran as root's file).
    let subject = shared.join("work/target/student/debug/raylab-checks");
    let head = std::fs::read(&subject).map(|b| b[..4].to_vec()).unwrap_or_default();
    assert_eq!(head, b"\x7fELF", "{} was rewritten", subject.display());
    // (l) Nothing was written in the work folder, and the temporary folders hold nothing of theirs.
    for place in [
        shared.join("work/target/student/debug/fill"),
        shared.join("work/lectures/03-polygons-triangles/fill"),
        PathBuf::from("/tmp/raylab-fill"),
    ] {
        assert!(!place.exists(), "{} was written", place.display());
    }
    for user in users {
        let theirs = Command::new("find")
            .args(["/tmp", "/var/tmp", "/dev/shm", "-maxdepth", "1", "-user", user])
            .output()
            .unwrap();
        assert!(
            theirs.stdout.is_empty(),
            "files of {user} left: {}",
            String::from_utf8_lossy(&theirs.stdout)
        );
        // Every process the checks left is gone (a killed one not yet reaped by init is a zombie: gone).
        let listed = Command::new("ps").args(["-u", user, "-o", "stat=,pid=,comm="]).output().unwrap();
        let listed = String::from_utf8_lossy(&listed.stdout).into_owned();
        let left: Vec<&str> = listed.lines().filter(|l| !l.trim_start().starts_with('Z')).collect();
        assert!(left.is_empty(), "processes of {user} outlived their checks: {left:?}");
    }
    // Every process that ran the student's code ran as a grading user: a check's (`run`) and a
    // hidden check's (`serve`) alike.
    let recorded: Vec<(String, String)> = std::fs::read_dir(&records)
        .unwrap()
        .map(|e| {
            let e = e.unwrap();
            (e.file_name().to_string_lossy().into_owned(), std::fs::read_to_string(e.path()).unwrap())
        })
        .collect();
    for name in ["hit_plane", "geometric", "algebraic", "stable", "cramer", "winding", "moller"] {
        assert!(
            recorded.iter().any(|(file, _)| file.starts_with(&format!("{name}-"))),
            "{name} recorded nothing"
        );
    }
    for (file, line) in &recorded {
        let real = line.split_whitespace().nth(1).unwrap_or_default();
        assert!(uids.iter().any(|u| u == real), "{file}: {line}, not one of the grading users {uids:?}");
    }
}

/// Whether scene check `id` draws with a function attacked in the test above: lecture 02's and
/// 03's pictures draw with `hit_plane`; none with the others.
fn uses_an_attacked_function(id: &str) -> bool {
    id.starts_with("02/") || id.starts_with("03/")
}

/// Records, once per process, the user the student's code runs as: `UIDS/NAME-PID` holds its
/// `Uid:` line (real, effective, saved, file system).
const RECORD_UID: &str = r#"
    {
        static RECORDED: std::sync::Once = std::sync::Once::new();
        RECORDED.call_once(|| {
            let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
            let uid = status.lines().find(|l| l.starts_with("Uid:")).unwrap_or("Uid: unknown").to_owned();
            let _ = std::fs::write(format!("UIDS/NAME-{}", std::process::id()), uid);
        });
    }
"#;

/// (h) replaces the binary it runs in (removed, then written anew: a running binary cannot be
/// written in place) with a script that prints a passed verdict; then answers wrongly.
const REWRITE_THE_BINARY: &str = include_str!("../redteam/rewrite-the-binary.rs");

/// (i) once per check: a process out of the check's group and session, which waits and then,
/// ten times a second, writes over every `.json` file named on any command line (the grade's
/// output, `-o FILE`); then a wrong answer.
const ESCAPE_AND_WAIT: &str = include_str!("../redteam/escape-and-wait.rs");

/// (j) reads every process's command line for a judge's token (`--token`, where the driver once
/// gave it); a token found would connect to that judge as its subject.
const READ_PROC: &str = include_str!("../redteam/read-proc.rs");

/// (k) once per check: a fork bomb out of the check's process group; then a wrong answer.
const FORK_BOMB: &str = include_str!("../redteam/fork-bomb.rs");

/// (l) once per check: 256 MiB written beside its binary, in its lecture's folder and in the
/// temporary folder, as far as each goes; then a wrong answer.
const FILL_THE_DISK: &str = include_str!("../redteam/fill-the-disk.rs");

/// (e) once per check: a kill of the parent process (the grader), a process left behind; then a
/// wrong answer.
const KILL_THE_GRADER: &str = include_str!("../redteam/kill-the-grader.rs");
