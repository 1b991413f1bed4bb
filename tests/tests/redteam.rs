//! Red team: submissions that attack the grading instead of solving the
//! exercise, graded as an instructor grades a class (`grader grade
//! --submission`). Each must end with no points for the checks it attacks and a
//! plain verdict ("failed" or "crashed", never "passed"), and leave every
//! other check's verdict as the reference's.
//!
//! Every check of a submission is judged (`grader/checks/src/judge.rs`): the
//! process that runs the student's code reports values and never a verdict,
//! and what only the judge may read (the snapshots, the hidden checks) is not
//! in the tree where the student's code is built and run.

mod support;

use std::path::PathBuf;
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
fn attacks_on_the_verdict_score_nothing_and_change_nothing_else() {
    let _turn = WORK.lock().unwrap_or_else(|e| e.into_inner());
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
    let _turn = WORK.lock().unwrap_or_else(|e| e.into_inner());
    let dir = submission("outside", &[]);
    let lecture = dir.join("lectures/02-ray-casting");
    let manifest = std::fs::read_to_string(root().join("lectures/02-ray-casting/Cargo.toml")).unwrap();
    let manifest = manifest.replacen("[package]\n", "[package]\nbuild = \"build.rs\"\n", 1);
    std::fs::write(lecture.join("Cargo.toml"), manifest).unwrap();
    std::fs::write(lecture.join("build.rs"), "fn main() { panic!(\"the submission's build script ran\") }\n")
        .unwrap();
    std::fs::create_dir_all(lecture.join("extra")).unwrap();
    std::fs::write(lecture.join("extra/forged.rs"), "compile_error!(\"a file beside src/\");\n").unwrap();
    let checks_file = dir.join("grader/checks/src/lectures/l02/mod.rs");
    std::fs::create_dir_all(checks_file.parent().unwrap()).unwrap();
    std::fs::write(&checks_file, "compile_error!(\"the grader's checks, replaced\");\n").unwrap();
    let (grade, stderr) = grade_submission(&dir, &["02"], "outside.json");
    assert!(grade["compile_errors"].as_array().unwrap().is_empty(), "{}\n{stderr}", grade["compile_errors"]);
    for check in checks(&grade) {
        assert_eq!(check["status"], "passed", "{}: {}\n{stderr}", check["info"]["id"], check["summary"]);
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
    let _turn = WORK.lock().unwrap_or_else(|e| e.into_inner());
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
    // Everything else of the two lectures is graded as the reference is.
    for check in checks(&grade) {
        let id = check["info"]["id"].as_str().unwrap_or_default();
        let attacked =
            id.contains("/geometry/") || id.starts_with("05/lambert/") || id.starts_with("02/image/");
        if !attacked && check["info"]["lecture"] == "02" && check["info"]["kind"] != "image" {
            assert_eq!(check["status"], "passed", "{id}: {}\n{stderr}", check["summary"]);
        }
    }
}

/// (e) kills its parent, the grader, and leaves a process behind, then answers wrongly: graded
/// as a Gradescope run grades (`grade --run-as`, the student's code built and run as a user of
/// its own), the kill is refused, the check fails and nothing else changes. As the instructor's
/// own user the kill would succeed (the grader would end without a grade: no points, but no
/// verdicts either), which is why the bundle grades as another user. Needs root on Linux
/// (useradd, a change of user); elsewhere it says SKIPPED.
#[test]
fn as_the_grading_user_the_students_code_cannot_kill_the_grader() {
    let _turn = WORK.lock().unwrap_or_else(|e| e.into_inner());
    let root_user = Command::new("id").arg("-u").output().is_ok_and(|o| o.stdout.trim_ascii() == b"0");
    if !cfg!(target_os = "linux") || !root_user {
        eprintln!(
            "SKIPPED as_the_grading_user_the_students_code_cannot_kill_the_grader: needs root on Linux"
        );
        return;
    }
    let user = "raylab-student";
    let known = Command::new("id").arg(user).output().is_ok_and(|o| o.status.success());
    if !known {
        let made = Command::new("useradd")
            .args(["--system", "--no-create-home", "--shell", "/usr/sbin/nologin", user])
            .status()
            .expect("useradd runs");
        assert!(made.success(), "useradd {user}");
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
            "SKIPPED as_the_grading_user_the_students_code_cannot_kill_the_grader: {user} cannot reach {}",
            shared.display()
        );
        return;
    }
    let patches = [patch("lectures/02-ray-casting/src/plane.rs", "hit_plane", KILL_THE_GRADER)];
    let patches: Vec<(&str, &str, &str)> =
        patches.iter().map(|(f, a, r)| (f.as_str(), a.as_str(), r.as_str())).collect();
    let dir = submission("kill-the-grader", &patches);
    let json = scratch().join("kill-the-grader.json");
    let _ = std::fs::remove_file(&json);
    let path =
        format!("{}:{}", shared.join("toolchain/bin").display(), std::env::var("PATH").unwrap_or_default());
    let out = Command::new(grader_binary())
        .current_dir(root())
        .args(["grade", "--submission", dir.to_str().unwrap(), "--workdir"])
        .arg(shared.join("work"))
        .args(["--run-as", user, "02", "--format", "json", "-o", json.to_str().unwrap()])
        // The student's cargo: the shared toolchain, offline, none of root's (the test's own cargo
        // is a rustup proxy in root's home).
        .env_remove("CARGO")
        .env_remove("RUSTC")
        .env_remove("RUSTUP_TOOLCHAIN")
        .env("PATH", path)
        .env("CARGO_HOME", shared.join("cargo"))
        .env("CARGO_NET_OFFLINE", "true")
        .output()
        .expect("the grader runs");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "the grader did not finish: {:?}\n{stderr}", out.status);
    let grade: Value = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let attacked = status_of(&grade, "02/hit_plane/unit");
    assert_eq!(attacked["status"], "failed", "{}\n{stderr}", attacked["summary"]);
    assert_eq!(attacked["points"], 0);
    for id in
        ["02/hit_sphere_stable/unit", "02/hit_sphere_geometric/unit", "02/hit_sphere_stable/hidden-off-axis"]
    {
        assert_eq!(status_of(&grade, id)["status"], "passed", "{id}\n{stderr}");
    }
    // Every process the checks left is gone (a killed one not yet reaped by init is a zombie: gone).
    let listed = Command::new("ps").args(["-u", user, "-o", "stat=,pid=,comm="]).output().unwrap();
    let listed = String::from_utf8_lossy(&listed.stdout).into_owned();
    let left: Vec<&str> = listed.lines().filter(|l| !l.trim_start().starts_with('Z')).collect();
    assert!(left.is_empty(), "processes of {user} outlived their checks: {left:?}");
}

/// (e) once per check: a kill of the parent process (the grader), a process left behind; then a
/// wrong answer.
const KILL_THE_GRADER: &str = r#"
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let parent = std::os::unix::process::parent_id().to_string();
        let _ = std::process::Command::new("kill").args(["-9", &parent]).status();
        let _ = std::process::Command::new("sleep").arg("600").spawn();
    });
    return None;
"#;
