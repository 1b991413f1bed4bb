//! Red team: submissions that attack the grading instead of solving the
//! exercise, graded as an instructor grades a class (`grader grade
//! --submission`). Each must end with no points for the checks it attacks and a
//! plain verdict ("failed" or "crashed", never "passed"), and leave every
//! other check's verdict as the reference's.
//!
//! The attacks sit in lecture 02, whose unit checks are judged
//! (`grader/checks/src/judge.rs`, as are lectures 01–05, 07 and 10's): the
//! process that runs the student's code reports values and never a verdict.
//! The scene checks, the hidden checks and lectures 06, 08 and 09 are not
//! judged yet (issue 18).

mod support;

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
