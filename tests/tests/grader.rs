//! The grader end to end, as students and instructors run it: real cargo
//! builds, real child processes, real source patches.
//!
//! - the reference scores full marks;
//! - the handout compiles and scores zero, every check "not started" or
//!   blocked by one that is, nothing crashed;
//! - chaos (panic, infinite loop, stack overflow, `process::exit`, a huge
//!   allocation, a flood of output, NaN pixels, a wrong image size, a type
//!   error) each ends in the right verdict, and a type error costs only its
//!   lecture and those built on it;
//! - every mistake of the catalogue (`tests/mistakes/*.toml`) fails the
//!   check that should catch it, with the cause it should name.
//!
//! The patched copies are graded with `grader grade --submission` in one work
//! folder under `target/workbench/`, kept between runs so that each patch
//! rebuilds only its lecture.
//!
//! The tests that take minutes (the handout, a type error graded whole, the
//! weeks, the accepted answers, the catalogue, the recipe) are `#[ignore]`d:
//! `cargo test -p workbench-tests -- --ignored` runs them, and CI does every
//! time. `cargo test --workspace` keeps the reference and one real submission
//! graded end to end through the judge (chaos).

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

mod support;

use support::*;

#[test]
fn the_reference_scores_full_marks() {
    let (grade, stderr) = grader(&["--strict"], &scratch().join("reference.json"));
    let failing = not_passed(&grade);
    assert!(failing.is_empty(), "{}\n{stderr}", failing.join("\n"));
    assert_eq!(grade["score"], grade["max_score"]);
    assert!(checks(&grade).len() >= 150, "{} checks", checks(&grade).len());
    the_checks_and_the_exercises_name_each_other(&grade);
}

/// Every exercise (a `todo!("NN/exercise: …")` of the handout) has a check of its own, and
/// every unit or extreme check tests an exercise: the checks' declarations and the lectures'
/// SOLUTION regions are two lists in two crates, kept in step here.
fn the_checks_and_the_exercises_name_each_other(grade: &Value) {
    let dir = scratch().join("handout-exercises");
    let out =
        Command::new(grader_binary()).args(["handout", "--force", dir.to_str().unwrap()]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let mut exercises = std::collections::BTreeSet::new();
    let mut stack = vec![dir.join("lectures")];
    while let Some(folder) = stack.pop() {
        for entry in std::fs::read_dir(&folder).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).unwrap();
                for stub in text.split("todo!(\"").skip(1) {
                    exercises.insert(stub.split(": ").next().unwrap().to_owned());
                }
            }
        }
    }
    assert!(exercises.len() >= 80, "{} exercises in the handout", exercises.len());
    let checked: std::collections::BTreeSet<String> = checks(grade)
        .iter()
        .filter(|c| c["info"]["kind"] != "image")
        .map(|c| {
            format!("{}/{}", c["info"]["lecture"].as_str().unwrap(), c["info"]["exercise"].as_str().unwrap())
        })
        .collect();
    // Every exercise is graded under its own name (lecture 02's three images too: a bug in
    // object_id_image is named there, not on closest_hit).
    let unchecked: Vec<_> = exercises.difference(&checked).collect();
    let no_exercise: Vec<_> = checked.difference(&exercises).collect();
    assert!(unchecked.is_empty(), "exercises without a check: {unchecked:?}");
    assert!(no_exercise.is_empty(), "checks of no exercise: {no_exercise:?}");
}

#[test]
#[ignore = "the whole workbench (minutes): cargo test -p workbench-tests -- --ignored; CI runs it"]
fn the_handout_compiles_and_scores_zero_without_a_crash() {
    let dir = scratch().join("handout");
    let out =
        Command::new(grader_binary()).args(["handout", "--force", dir.to_str().unwrap()]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    // Its README is the student's: what to edit and where to start, no instructor material.
    let readme = std::fs::read_to_string(dir.join("README.md")).unwrap();
    assert!(readme.contains("## What to edit") && readme.contains("cargo run -p grader"), "{readme}");
    for instructor in ["SOLUTION", "instructor", "bless", "gradescope", "handout", "--submission"] {
        assert!(
            !readme.to_lowercase().contains(&instructor.to_lowercase()),
            "the handout's README says {instructor}"
        );
    }
    for left_out in ["ARCHITECTURE.md", "grader/STUDENT-README.md", "book/ci.sh", "tests", "benches"] {
        assert!(!dir.join(left_out).exists(), "the handout has {left_out}");
    }
    no_solution_is_copied_into(&dir);
    let target = scratch().join("handout-target");
    seed_registry_crates(&target);
    // It compiles, tests and all, without a warning (from the stubs, or from instructor code
    // left half out: a field only `grader dev sync` reads) (checked, not built: its
    // grader below builds what it runs).
    let (_, stderr, ok) = cargo(&dir, &["check", "--workspace", "--all-targets"], Some(&target));
    assert!(ok, "the handout does not compile:\n{stderr}");
    assert!(!stderr.contains("warning:"), "the handout builds with warnings:\n{stderr}");
    // Its own grader: zero points, every check not started or blocked by one that is.
    let json = scratch().join("handout.json");
    let args = ["run", "-q", "-p", "grader", "--", "--format", "json", "-o", json.to_str().unwrap()];
    let (_, stderr, _) = cargo(&dir, &args, Some(&target));
    let grade: Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap_or_else(|e| panic!("{e}: {stderr}")))
            .unwrap();
    assert_eq!(grade["score"], 0);
    for check in checks(&grade) {
        let status = check["status"].as_str().unwrap();
        assert!(
            status == "not_started"
                || (status == "blocked" && check["summary"].as_str().unwrap().contains("not started")),
            "{} is {status}: {}",
            check["info"]["id"],
            check["summary"]
        );
    }
    // The grade names the one file to open first: lecture 01's first exercise.
    let next = &grade["progress"]["next"];
    assert_eq!(next["exercise"], "01/translate", "{next}");
    assert!(
        next["location"].as_str().unwrap().starts_with("lectures/01-transforms/src/transforms.rs:"),
        "{next}"
    );
    assert_eq!(grade["progress"]["passed"], 0);
    // One count of exercises: the stubs the handout wrote are the exercises progress counts.
    let said = String::from_utf8_lossy(&out.stdout);
    let stubbed = said.split_whitespace().nth(1).and_then(|n| n.parse::<u64>().ok());
    assert_eq!(stubbed, grade["progress"]["total"].as_u64(), "{said}");
    // Every lecture has exercises marked not started, so the table tells a student where to begin.
    let mut lectures: Vec<String> = std::fs::read_dir(dir.join("lectures"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy()[..2].to_owned())
        .collect();
    lectures.sort();
    assert_eq!(lectures.first().map(String::as_str), Some("01"), "{lectures:?}");
    for lecture in lectures {
        assert!(
            checks(&grade).iter().any(|c| c["info"]["lecture"] == lecture && c["status"] == "not_started"),
            "lecture {lecture} has no check marked not started"
        );
    }
    watch_regrades_the_lecture_that_changes(&dir, &target);
}

/// Nothing that ships is an exercise solved: no three consecutive lines of a SOLUTION
/// region (lines of code with an operator or a call, 12 characters or more, spaces
/// folded) stand anywhere in the handout's Rust files. It caught the checks' planted
/// mistakes (the reference with a switch), the tradeoffs' naive variants and f64
/// truths, and a lecture test's misprinted matrix three signs from the solution.
fn no_solution_is_copied_into(handout: &Path) {
    fn lines(text: &str) -> Vec<(usize, String)> {
        text.lines()
            .enumerate()
            .map(|(n, l)| (n + 1, l.split_whitespace().collect::<Vec<_>>().join(" ")))
            .filter(|(_, l)| {
                !l.starts_with("//") && l.len() >= 12 && l.contains(['=', '+', '-', '*', '/', '('])
            })
            .collect()
    }
    fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() && !path.ends_with("target") {
                rust_files(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }
    const WINDOW: usize = 3;
    let mut solutions = std::collections::HashMap::new();
    let mut files = Vec::new();
    rust_files(&root().join("lectures"), &mut files);
    for file in &files {
        let text = std::fs::read_to_string(file).unwrap();
        for region in text.split("// SOLUTION BEGIN").skip(1) {
            let body = region.split("// SOLUTION END").next().unwrap();
            let body = lines(body);
            for window in body.windows(WINDOW) {
                let key: Vec<&str> = window.iter().map(|(_, l)| l.as_str()).collect();
                solutions.entry(key.join("\n")).or_insert_with(|| file.display().to_string());
            }
        }
    }
    assert!(solutions.len() > 300, "{} windows of solution lines", solutions.len());
    let mut copies = Vec::new();
    let mut shipped = Vec::new();
    rust_files(handout, &mut shipped);
    for file in &shipped {
        let text = std::fs::read_to_string(file).unwrap();
        for window in lines(&text).windows(WINDOW) {
            let key: Vec<&str> = window.iter().map(|(_, l)| l.as_str()).collect();
            if let Some(from) = solutions.get(&key.join("\n")) {
                copies.push(format!("{}:{} copies {from}:\n{}", file.display(), window[0].0, key.join("\n")));
            }
        }
    }
    assert!(copies.is_empty(), "the handout holds solution lines:\n{}", copies.join("\n\n"));
}

/// `grader watch` in the handout: editing a file of lecture 02 re-grades lecture 02.
fn watch_regrades_the_lecture_that_changes(dir: &Path, target: &Path) {
    use std::io::{BufRead, BufReader};
    use std::time::{Duration, Instant};
    let mut command = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    command.current_dir(dir).args(["run", "-q", "-p", "grader"]);
    if size_of::<raylab::Float>() == 8 {
        command.args(["--features", "raylab/f64"]);
    }
    let mut watch = command
        .args(["--", "watch"])
        .env("CARGO_TARGET_DIR", target)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let (sender, lines) = std::sync::mpsc::channel();
    let stdout = watch.stdout.take().unwrap();
    std::thread::spawn(move || {
        for line in BufReader::new(stdout).lines().map_while(Result::ok) {
            let _ = sender.send(line);
        }
    });
    let mut seen = Vec::new();
    let mut wait_for = |text: &str, limit: Duration| {
        let start = Instant::now();
        while start.elapsed() < limit {
            if let Ok(line) = lines.recv_timeout(Duration::from_millis(200)) {
                seen.push(line.clone());
                if line.contains(text) {
                    return true;
                }
            }
        }
        false
    };
    let started = wait_for("watching", Duration::from_secs(300));
    let file = dir.join("lectures/02-ray-casting/src/plane.rs");
    let text = std::fs::read_to_string(&file).unwrap();
    std::fs::write(&file, text.clone() + "\n// An edit.\n").unwrap();
    let regraded = started
        && wait_for("lecture 02 changed", Duration::from_secs(30))
        && wait_for("total ", Duration::from_secs(300));
    let _ = watch.kill();
    let _ = watch.wait();
    std::fs::write(&file, text).unwrap();
    assert!(regraded, "grader watch did not re-grade lecture 02:\n{}", seen.join("\n"));
    assert!(seen.iter().any(|l| l.starts_with("02-ray-casting")), "{}", seen.join("\n"));
}

/// One chaos case: a patch, the check it hits and how that check must end.
struct Chaos {
    file: &'static str,
    /// The line the statement is inserted after (the function's signature).
    after: &'static str,
    insert: &'static str,
    check: &'static str,
    status: &'static str,
    summary: &'static str,
}

const CHAOS: &[Chaos] = &[
    // Each case hits an exercise the others' checks do not use, so that each verdict is its own.
    Chaos {
        file: "lectures/05-shading/src/area_lights.rs",
        after: "pub fn concentric_disk(u: Vec2) -> Vec2 {\n",
        insert: "    if u.is_finite() {\n        panic!(\"chaos: boom\");\n    }\n",
        check: "05/concentric_disk/unit",
        status: "crashed",
        summary: "chaos: boom",
    },
    Chaos {
        file: "lectures/07-reflection-refraction/src/fresnel.rs",
        after: "pub fn schlick(cos_i: Float, eta_i: Float, eta_t: Float) -> Float {\n",
        insert: "    while cos_i.is_finite() {\n        std::hint::black_box(cos_i);\n    }\n",
        check: "07/schlick/unit",
        status: "timed_out",
        summary: "infinite loop",
    },
    Chaos {
        file: "lectures/04-quadrics-transforms/src/parametric.rs",
        after: "pub fn parametric_normal(ds_dalpha: Vec3, ds_dbeta: Vec3) -> Vec3 {\n",
        insert: "    if ds_dalpha.is_finite() {\n        return std::hint::black_box(parametric_normal(std::hint::black_box(ds_dalpha), ds_dbeta));\n    }\n",
        check: "04/parametric_normal/unit",
        status: "crashed",
        summary: "stack overflow",
    },
    Chaos {
        file: "lectures/09-acceleration/src/aabb.rs",
        after: "    pub fn surface_area(&self) -> Float {\n",
        insert: "        if std::hint::black_box(true) {\n            std::process::exit(3);\n        }\n",
        check: "09/Aabb::surface_area/unit",
        status: "crashed",
        summary: "exited with code 3",
    },
    Chaos {
        file: "lectures/03-polygons-triangles/src/polygon.rs",
        after: "pub fn winding_number(polygon: &[Vec2], p: Vec2) -> i32 {\n",
        insert: "    let chaos = vec![1u8; usize::MAX >> 20];\n    std::hint::black_box(&chaos);\n",
        check: "03/winding_number/unit",
        status: "crashed",
        summary: "ran out of memory",
    },
    Chaos {
        file: "lectures/10-textures-sampling/src/uv.rs",
        after: "pub fn sphere_uv(p: Vec3) -> Vec2 {\n",
        insert: "    for _ in 0..100_000_000 {\n        println!(\"{}\", \"chaos \".repeat(100));\n    }\n",
        check: "10/sphere_uv/unit",
        status: "crashed",
        summary: "printing more than",
    },
    Chaos {
        file: "lectures/10-textures-sampling/src/checker.rs",
        after: "pub fn checker(uv: Vec2, scale: Float, a: Color, b: Color) -> Color {\n",
        insert: "    if scale.is_finite() {\n        return Color::splat(Float::NAN);\n    }\n",
        check: "10/image/checker-aliasing-16spp",
        status: "failed",
        summary: "NaN",
    },
    Chaos {
        file: "lectures/02-ray-casting/src/images.rs",
        after: "pub fn normal_image(camera: &Camera, scene: &impl Intersector, width: u32, height: u32) -> Image {\n",
        insert: "    if width > 0 {\n        return Image::new(width + 1, height);\n    }\n",
        check: "02/geometry/spheres-on-plane",
        status: "failed",
        summary: "201×150",
    },
];

#[test]
fn chaos_ends_in_the_right_verdicts() {
    let _turn = work_turn();
    let patches: Vec<(&str, &str, String)> =
        CHAOS.iter().map(|c| (c.file, c.after, format!("{}{}", c.after, c.insert))).collect();
    let patches: Vec<(&str, &str, &str)> = patches.iter().map(|(f, a, r)| (*f, *a, r.as_str())).collect();
    let dir = submission("chaos", &patches);
    let selected: Vec<&str> = CHAOS.iter().map(|c| c.check).collect();
    let (grade, stderr) = grade_submission(&dir, &selected, "chaos.json");
    for case in CHAOS {
        let check = status_of(&grade, case.check);
        let summary = check["summary"].as_str().unwrap_or_default().to_owned()
            + check["failure"]["cause"].as_str().unwrap_or_default();
        assert_eq!(check["status"], case.status, "{}: {summary}\n{stderr}", case.check);
        assert!(
            summary.contains(case.summary),
            "{}: {summary:?} does not say {:?}",
            case.check,
            case.summary
        );
    }
    // The report of this grade opens offline in a browser, images, ray tree and all; the failed
    // stage-10 scene (10/image/checker-aliasing-16spp) has its 3D view.
    let report = scratch().join("work/target/grader/report.html");
    browser_check("tests/report_check.py", &[report.to_str().unwrap(), "--expect-view"]);
    // The judge, built just now in the instructor's build-dir, left the instructor's crates alone:
    // the reference's lecture 01, built after it, is the reference's, not the judge's stubs (with
    // the judge's packages at the instructor's versions, cargo found the judge's stubbed lecture
    // fresh and the reference's grade said "not started").
    let (grade, stderr) = grader(&["--strict", "01"], &scratch().join("after-the-judge.json"));
    let failing = not_passed(&grade);
    assert!(failing.is_empty(), "after the judge's build:\n{}\n{stderr}", failing.join("\n"));
}

/// Every check of `grade` that did not pass, as `ID status: summary`.
fn not_passed(grade: &Value) -> Vec<String> {
    checks(grade)
        .iter()
        .filter(|c| c["status"] != "passed")
        .map(|c| format!("{} {}: {}", c["info"]["id"], c["status"], c["summary"]))
        .collect()
}

#[test]
#[ignore = "the whole workbench (minutes): cargo test -p workbench-tests -- --ignored; CI runs it"]
fn a_type_error_costs_only_its_lecture_and_those_built_on_it() {
    let _turn = work_turn();
    let file = "lectures/07-reflection-refraction/src/refract.rs";
    let text = std::fs::read_to_string(root().join(file)).unwrap();
    let signature =
        text.lines().find(|l| l.starts_with("pub fn refract(")).expect("refract's signature").to_owned()
            + "\n";
    let patch = format!("{signature}    let chaos: u32 = \"not a number\";\n");
    let dir = submission("type-error", &[(file, &signature, &patch)]);
    let (grade, stderr) = grade_submission(&dir, &[], "type-error.json");
    // 07 fails; 08 and 10, which use it, wait; every other lecture's checks, images included, are
    // graded and pass: each lecture's images are drawn by its own stage, which uses no later lecture.
    let mut images = 0;
    for check in checks(&grade) {
        let (lecture, status) =
            (check["info"]["lecture"].as_str().unwrap(), check["status"].as_str().unwrap());
        let expected = match lecture {
            "07" => "does_not_compile",
            "08" | "10" => "blocked",
            _ => "passed",
        };
        images += usize::from(lecture < "07" && check["info"]["exercise"] == "image" && status == "passed");
        assert_eq!(status, expected, "{}: {}\n{stderr}", check["info"]["id"], check["summary"]);
    }
    assert!(images >= 20, "only {images} image checks of lectures 01–06 passed");
    let error = &grade["compile_errors"][0];
    assert_eq!(error["lecture"], "07");
    assert!(error["location"].as_str().unwrap().starts_with(file), "{error}");
}

/// Two grades given one work folder at once (an instructor grading a class and a single
/// submission in the same folder, say) take turns: the second waits for the first, and each
/// reports its own submission's answers, not the other's.
#[test]
#[ignore = "the whole workbench (minutes): cargo test -p workbench-tests -- --ignored; CI runs it"]
fn two_grades_given_one_work_folder_take_turns_and_each_reports_its_own_code() {
    let _turn = work_turn();
    let mistake = catalogue()
        .into_iter()
        .find(|m| m.caught_by == "01/image/perspective")
        .expect("a planted mistake the perspective picture catches");
    let wrong = submission("turns-mistake", &[(&mistake.file, &mistake.find, &mistake.replace)]);
    let right = submission("turns-reference", &[]);
    // Both graders start while this test holds the work folder as a grade does (its lock file), so
    // both find it taken, and once it is let go they overlap: one grades, the other waits.
    let lock = scratch().join("work/target/grade.lock");
    std::fs::create_dir_all(lock.parent().unwrap()).unwrap();
    let held = std::fs::File::create(&lock).unwrap();
    held.lock().unwrap();
    let ((wrong, wrong_err), (right, right_err)) = std::thread::scope(|scope| {
        let wrong = scope.spawn(|| grade_submission(&wrong, &["01"], "turns-mistake.json"));
        let right = scope.spawn(|| grade_submission(&right, &["01"], "turns-reference.json"));
        std::thread::sleep(std::time::Duration::from_secs(3));
        drop(held);
        (wrong.join().unwrap(), right.join().unwrap())
    });
    assert_eq!(
        status_of(&wrong, "01/image/perspective")["status"],
        "failed",
        "{}\n{wrong_err}",
        mistake.name
    );
    for check in checks(&right) {
        assert_eq!(
            check["status"], "passed",
            "the reference's {}: {}\n{right_err}",
            check["info"]["id"], check["summary"]
        );
    }
    for stderr in [&wrong_err, &right_err] {
        assert!(stderr.contains("waiting for that grade to end"), "a grade that did not wait:\n{stderr}");
    }
}

/// "Week N" of the course: the reference's lectures up to N, the handout's stubs after it. Every
/// check of lectures 01–N passes, images included (each lecture's stage draws with lectures ≤ N
/// only); every check of a later lecture is not started or blocked, none crashed. The weeks are
/// graded in order in the shared work folder, so each rebuilds only lecture N and those after it.
#[test]
#[ignore = "the whole workbench (minutes): cargo test -p workbench-tests -- --ignored; CI runs it"]
fn each_week_grades_its_lectures_images_included() {
    let _turn = work_turn();
    let handout = scratch().join("week-handout");
    let out = Command::new(grader_binary())
        .args(["handout", "--force", handout.to_str().unwrap()])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let mut lectures: Vec<String> = std::fs::read_dir(root().join("lectures"))
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
        .filter(|name| name.len() > 3 && name[..2].chars().all(|c| c.is_ascii_digit()))
        .collect();
    lectures.sort();
    let mut problems = Vec::new();
    // Weeks 1 to 10, then week 6 again with a type error in lecture 07's stub (a student who
    // started 07 and left it broken): 01–06 still pass whole, 07 does not compile.
    let weeks = (1..=lectures.len()).map(|w| (w, false)).chain([(6, true)]);
    for (week, broken_next) in weeks {
        let dir = scratch().join("submissions").join("week");
        let _ = std::fs::remove_dir_all(&dir);
        for (index, lecture) in lectures.iter().enumerate() {
            let from = if index < week { root() } else { handout.clone() };
            copy_tree(
                &from.join("lectures").join(lecture).join("src"),
                &dir.join("lectures").join(lecture).join("src"),
            );
        }
        if broken_next {
            let lib = dir.join("lectures").join(&lectures[week]).join("src/lib.rs");
            let text = std::fs::read_to_string(&lib).unwrap();
            std::fs::write(&lib, text + "\npub const CHAOS: u32 = \"not a number\";\n").unwrap();
        }
        let name = if broken_next {
            format!("week {week} + a type error in the next")
        } else {
            format!("week {week}")
        };
        let (grade, stderr) = grade_submission(&dir, &[], "week.json");
        let mut images = 0;
        for check in checks(&grade) {
            let id = check["info"]["id"].as_str().unwrap();
            let number: usize = id[..2].parse().unwrap();
            let status = check["status"].as_str().unwrap();
            let ok = if number <= week {
                images += usize::from(check["info"]["exercise"] == "image");
                status == "passed"
            } else if broken_next && number == week + 1 {
                status == "does_not_compile"
            } else if check["info"]["exercise"] == "final" && id[9..11].parse::<usize>().unwrap() <= week {
                // The complete tracer on an earlier lecture's scene needs only what the scene
                // requires: no hierarchy below 32 primitives, no lecture 10 without textures or
                // supersampling. It may pass before lecture 10 is done; it must not fail.
                matches!(status, "passed" | "not_started" | "blocked")
            } else {
                status == "not_started" || status == "blocked"
            };
            if !ok {
                // What the check printed, to tell a student's crash from the grader's own.
                let output = check["output"].as_str().unwrap_or_default();
                problems
                    .push(format!("{name}: {id} is {status}: {}\n  its output: {output}", check["summary"]));
            }
        }
        assert!(images >= 3, "{name}: only {images} image checks graded\n{stderr}");
        // Where to go next: the first exercise of the next lecture (or its broken file).
        let next = &grade["progress"]["next"];
        match lectures.get(week) {
            Some(following) => {
                let location = next["location"].as_str().unwrap_or_default();
                assert!(
                    location.starts_with(&format!("lectures/{following}/src/")),
                    "{name}: next is {next}"
                );
            }
            None => assert!(next.is_null(), "{name}: next is {next}"),
        }
        println!(
            "{name}: {} checks, {images} image checks of lectures ≤ {week} passed",
            checks(&grade).len()
        );
        if !broken_next {
            problems.extend(render_at_week(week, &lectures));
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// `grader render` at week `week`, as the student runs it (the render tool of the checks binary
/// just built for the week, in the work folder): a scene of lecture `week` draws by its stage,
/// with a pixel's rays printed and written as a 3D view; a scene of the next lecture says which
/// exercise it waits for, with no panic.
fn render_at_week(week: usize, lectures: &[String]) -> Vec<String> {
    let work = scratch().join("work");
    let binary = work.join("target/debug/raylab-checks");
    let first_scene = |lecture: &str| {
        let mut scenes: Vec<PathBuf> = std::fs::read_dir(work.join("lectures").join(lecture).join("scenes"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "toml"))
            .collect();
        scenes.sort();
        scenes.remove(0)
    };
    let render = |scene: &Path, extra: &[&str]| {
        let image = scratch().join(format!("week-{week}.png"));
        let _ = std::fs::remove_file(&image);
        let out = Command::new(&binary)
            .current_dir(&work)
            .arg("render")
            .arg(scene)
            .arg("-o")
            .arg(&image)
            .args(extra)
            .output()
            .unwrap();
        (out, image)
    };
    let mut problems = Vec::new();
    let own = first_scene(&lectures[week - 1]);
    let view = scratch().join(format!("week-{week}.html"));
    let _ = std::fs::remove_file(&view);
    let (out, image) = render(&own, &["--tree", "20,20", "--view", view.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    if !out.status.success() || !image.is_file() || !view.is_file() || !stdout.starts_with("pixel (20, 20)") {
        problems.push(format!(
            "week {week}: render {} --tree 20,20 --view: {:?}, image {}, view {}\n{stdout}{}",
            own.display(),
            out.status,
            image.is_file(),
            view.is_file(),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    if let Some(next) = lectures.get(week) {
        let scene = first_scene(next);
        let (out, image) = render(&scene, &[]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        let said = stderr.contains("which is not started yet") && !stderr.contains("panicked");
        if out.status.success() || image.exists() || !said {
            problems.push(format!(
                "week {week}: render {} (the next lecture's): {:?}\n{stderr}",
                scene.display(),
                out.status
            ));
        }
    }
    problems
}

/// Lecture 01's camera wrong and lecture 02 right: `grader 02` (which grades 02 alone) says
/// 02's pictures are blocked by the camera exercise, not that 02's functions are wrong.
#[test]
fn an_earlier_lectures_bug_blocks_the_later_pictures_by_name() {
    let _turn = work_turn();
    let file = "lectures/01-transforms/src/perspective.rs";
    let find = "let half_height = (0.5 * self.fovy).tan();";
    let dir = submission("blame", &[(file, find, "let half_height = self.fovy.tan();")]);
    let (grade, stderr) = grade_submission(&dir, &["02"], "blame.json");
    let mut images = 0;
    for check in checks(&grade) {
        let id = check["info"]["id"].as_str().unwrap();
        assert!(id.starts_with("02/"), "{id} is not of the selection");
        let summary = check["summary"].as_str().unwrap_or_default();
        // Every picture through the perspective camera is blocked by it; the orthographic
        // scene's picture does not use it and passes.
        if id.ends_with("/orthographic") {
            assert_eq!(check["status"], "passed", "{id}: {summary}\n{stderr}");
        } else if id.contains("/image/") || id.contains("/geometry/") {
            images += 1;
            assert_eq!(check["status"], "blocked", "{id}: {summary}\n{stderr}");
            assert!(summary.contains("01 PerspectiveCamera::generate_ray"), "{id}: {summary}");
        }
    }
    assert!(images >= 6, "{images} image checks of 02 blocked");
}

fn accepted() -> Vec<Accepted> {
    catalogues().into_iter().flat_map(|c| c.accepted).collect()
}

/// Each accepted answer applied alone: every check of its lecture passes, graded as a
/// submission, and so do the lecture's own tests, run in the work folder it was graded in (a
/// lecture's test stricter than its checks would fail here).
#[test]
#[ignore = "the whole workbench (minutes): cargo test -p workbench-tests -- --ignored; CI runs it"]
fn every_accepted_answer_passes_the_lectures_checks_and_its_tests() {
    let _turn = work_turn();
    let answers = accepted();
    assert!(answers.len() >= 2, "{} accepted answers", answers.len());
    let target = scratch().join("accepted-target");
    seed_registry_crates(&target);
    let mut refused = Vec::new();
    for a in answers {
        let text = std::fs::read_to_string(root().join(&a.file)).unwrap();
        assert_eq!(
            text.matches(&a.find).count(),
            1,
            "{}: the find text must occur once in {}",
            a.name,
            a.file
        );
        let lecture = a.file.split('/').nth(1).unwrap()[..2].to_owned();
        let dir = submission("accepted", &[(&a.file, &a.find, &a.replace)]);
        let (grade, stderr) = grade_submission(&dir, &[&lecture], "accepted.json");
        for check in checks(&grade).iter().filter(|c| c["info"]["lecture"] == lecture.as_str()) {
            if check["status"] != "passed" {
                refused.push(format!(
                    "{}: {} {} ({})\n{stderr}",
                    a.name, check["info"]["id"], check["status"], check["summary"]
                ));
            }
        }
        let package = format!("l{}", a.file.split('/').nth(1).unwrap());
        let work = scratch().join("work");
        let (stdout, stderr, ok) = cargo(&work, &["test", "-q", "-p", &package, "--lib"], Some(&target));
        if !ok {
            refused.push(format!("{}: the lecture's own tests fail:\n{stdout}\n{stderr}", a.name));
        }
    }
    assert!(refused.is_empty(), "right answers refused:\n{}", refused.join("\n"));
}

#[test]
fn the_catalogue_has_thirty_mistakes_whose_patches_apply() {
    let mistakes = catalogue();
    assert!(mistakes.len() >= 30, "{} mistakes catalogued", mistakes.len());
    for m in &mistakes {
        let text =
            std::fs::read_to_string(root().join(&m.file)).unwrap_or_else(|e| panic!("{}: {e}", m.file));
        assert_eq!(
            text.matches(&m.find).count(),
            1,
            "{}: the find text must occur once in {}",
            m.name,
            m.file
        );
        assert_ne!(m.find, m.replace, "{}", m.name);
    }
}

/// Each mistake applied alone, graded on the check that must catch it.
#[test]
#[ignore = "the whole workbench (minutes): cargo test -p workbench-tests -- --ignored; CI runs it"]
fn every_catalogued_mistake_fails_the_check_that_should_catch_it() {
    let _turn = work_turn();
    let mut missed = Vec::new();
    for m in catalogue() {
        let dir = submission("mistake", &[(&m.file, &m.find, &m.replace)]);
        let (grade, stderr) = grade_submission(&dir, &[&m.caught_by], "mistake.json");
        let check = status_of(&grade, &m.caught_by);
        let said = format!(
            "{} {}",
            check["summary"].as_str().unwrap_or_default(),
            check["failure"]["cause"].as_str().unwrap_or_default()
        );
        let named = m.named.as_ref().is_none_or(|n| said.contains(&format!("Check {n}")));
        if check["status"] != "failed" || !said.contains(&m.cause) || !named {
            missed.push(format!(
                "{}: {} is {} ({said}){}",
                m.name,
                m.caught_by,
                check["status"],
                if check["status"] == "does_not_compile" { format!("\n{stderr}") } else { String::new() }
            ));
        }
    }
    assert!(missed.is_empty(), "mistakes not caught as catalogued:\n{}", missed.join("\n"));
}

#[test]
fn the_gradescope_bundle_has_its_scripts_and_the_pristine_workspace() {
    let dir = scratch().join("gradescope");
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(grader_binary()).args(["gradescope", dir.to_str().unwrap()]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    for script in ["setup.sh", "run_autograder"] {
        let path = dir.join(script);
        // Gradescope runs the bundle on Linux; Windows has no execute bit to check.
        #[cfg(unix)]
        {
            let mode =
                std::os::unix::fs::PermissionsExt::mode(&std::fs::metadata(&path).unwrap().permissions());
            assert_eq!(mode & 0o111, 0o111, "{script} is not executable");
        }
        let syntax = Command::new("bash").arg("-n").arg(&path).output().unwrap();
        assert!(syntax.status.success(), "{script}: {}", String::from_utf8_lossy(&syntax.stderr));
    }
    let run = std::fs::read_to_string(dir.join("run_autograder")).unwrap();
    assert!(run.contains("grade --submission /autograder/submission") && run.contains("results.json"));
    assert!(run.contains("--run-as \"$RAYLAB_USERS\""), "the student's code runs as the grading users");
    let setup = std::fs::read_to_string(dir.join("setup.sh")).unwrap();
    assert!(
        setup.contains("USER_NAME=raylab-student")
            && setup.contains("useradd")
            && setup.contains("RAYLAB_USERS="),
        "setup.sh makes the grading users, one per core, and names them for run_autograder"
    );
    // The pristine workspace at the top (Gradescope unzips the bundle into /autograder/source),
    // hidden checks included, no build products.
    assert!(dir.join("Cargo.toml").is_file());
    assert!(dir.join("grader/checks/src/lectures/hidden.rs").is_file());
    assert!(dir.join("lectures/02-ray-casting/src/sphere.rs").is_file());
    assert!(!dir.join("target").exists());
}

/// The recipe of ARCHITECTURE.md ("Adding a lecture"), followed in a copy of the tree: a
/// scratch lecture 11 (its crate, its checks crate's source, its chapter) and `grader dev sync`, no
/// other file edited by hand. The grader then lists and passes its check, the handout stubs
/// its exercise, and the book's checks (the exercise tables, the `Book: §` references, the
/// generated lists) pass with its chapter in SUMMARY.md.
#[test]
#[ignore = "the whole workbench (minutes): cargo test -p workbench-tests -- --ignored; CI runs it"]
fn a_lecture_added_by_the_recipe_alone_is_graded_handed_out_and_in_the_book() {
    let copy = scratch().join("recipe");
    let tree = copy.join("tree");
    let _ = std::fs::remove_dir_all(&tree);
    copy_tree(&root(), &tree);
    let added: &[(&str, &str)] = &[
        ("lectures/11-scratch/Cargo.toml", RECIPE_CARGO),
        ("lectures/11-scratch/src/lib.rs", RECIPE_LIB),
        ("lectures/11-scratch/README.md", RECIPE_README),
        ("lectures/11-scratch/hints.toml", "twice = [\"Scale it.\", \"By 2: v * 2.0.\"]\n"),
        ("grader/checks/lectures/l11/src/lib.rs", RECIPE_CHECKS),
        ("book/src/11-scratch.md", RECIPE_CHAPTER),
    ];
    for (path, text) in added {
        std::fs::create_dir_all(tree.join(path).parent().unwrap()).unwrap();
        std::fs::write(tree.join(path), text).unwrap();
    }
    // Its own target folder, kept between runs (the copy's crates are other packages than the
    // tree's, and two workspaces writing one target's binaries would race).
    let target = copy.join("target");
    seed_registry_crates(&target);
    let (out, stderr, ok) = cargo(&tree, &["run", "-q", "-p", "grader", "--", "dev", "sync"], Some(&target));
    assert!(ok, "grader dev sync failed:\n{out}\n{stderr}");

    // What the command wrote: the generated lists, and nothing else (Cargo.lock is cargo's).
    let mut changed = Vec::new();
    changed_files(&root(), &tree, &tree, &mut changed);
    changed.sort();
    let added_paths: Vec<String> = added.iter().map(|(p, _)| p.to_string()).collect();
    let written: Vec<&String> =
        changed.iter().filter(|p| !added_paths.contains(p) && p.as_str() != "Cargo.lock").collect();
    assert_eq!(
        written,
        [
            "Cargo.toml",
            "README.md",
            "book/doctests/Cargo.toml",
            "book/doctests/src/lib.rs",
            "book/src/SUMMARY.md",
            "book/src/introduction.md",
            "grader/checks/Cargo.toml",
            "grader/checks/lectures/l11/Cargo.toml",
            "grader/checks/src/lectures/mod.rs",
        ]
        .iter()
        .collect::<Vec<_>>(),
        "files written by the recipe's command"
    );
    let summary = std::fs::read_to_string(tree.join("book/src/SUMMARY.md")).unwrap();
    assert!(summary.contains("- [11 A scratch lecture](11-scratch.md)\n"), "{summary}");

    // The grader lists lecture 11's check, builds it with lecture 01 only, and it passes.
    let json = copy.join("grade.json");
    let args = [
        "run",
        "-q",
        "-p",
        "grader",
        "--",
        "11",
        "--strict",
        "--format",
        "json",
        "-o",
        json.to_str().unwrap(),
    ];
    let (_, stderr, ok) = cargo(&tree, &args, Some(&target));
    let grade: Value =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap_or_else(|e| panic!("{e}: {stderr}")))
            .unwrap();
    let ids: Vec<&str> = checks(&grade).iter().filter_map(|c| c["info"]["id"].as_str()).collect();
    assert_eq!(ids, ["11/twice/unit"], "{stderr}");
    assert!(
        ok && status_of(&grade, "11/twice/unit")["status"] == "passed",
        "{:#}\n{stderr}",
        grade["checks"]
    );

    // The handout stubs its exercise.
    let handout = copy.join("handout");
    let handout_arg = handout.to_str().unwrap();
    let (_, stderr, ok) =
        cargo(&tree, &["run", "-q", "-p", "grader", "--", "handout", "--force", handout_arg], Some(&target));
    assert!(ok, "{stderr}");
    let stub = std::fs::read_to_string(handout.join("lectures/11-scratch/src/lib.rs")).unwrap();
    assert!(stub.contains("todo!(\"11/twice: Book: §11.1 Twice\")") && !stub.contains("v * 2.0"), "{stub}");

    // The book's and the course's checks: exercise tables, `Book: §` references, hints, and
    // the generated lists in step (the grader's own tests, in the copy).
    let (out, stderr, ok) = cargo(&tree, &["test", "-q", "-p", "grader"], Some(&target));
    assert!(ok, "the grader's tests fail in the tree with lecture 11:\n{out}\n{stderr}");
}

/// The files under `dir` (a copy of `original` rooted at `copy`) that are new or differ.
fn changed_files(original: &Path, copy: &Path, dir: &Path, out: &mut Vec<String>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let relative = path.strip_prefix(copy).unwrap();
        if relative.starts_with("target") || relative.starts_with("book/book") {
            continue;
        }
        if path.is_dir() {
            changed_files(original, copy, &path, out);
        } else if std::fs::read(original.join(relative)).ok() != Some(std::fs::read(&path).unwrap()) {
            out.push(relative.to_string_lossy().replace('\\', "/"));
        }
    }
}

const RECIPE_CARGO: &str = r#"[package]
name = "l11-scratch"
version = "0.1.0"
description = "Lecture 11: a scratch lecture, added by the recipe."
edition.workspace = true
rust-version.workspace = true
license.workspace = true
publish.workspace = true

[package.metadata.raylab]
title = "A scratch lecture"
summary = "twice a vector"

[dependencies]
raylab.workspace = true
l01-transforms = { path = "../01-transforms" }

[lints]
workspace = true
"#;

const RECIPE_LIB: &str = "//! Lecture 11: a scratch lecture.

use raylab::Vec3;

/// `v` scaled by two. Book: §11.1 Twice
pub fn twice(v: Vec3) -> Vec3 {
    // SOLUTION BEGIN
    v * 2.0
    // SOLUTION END
}
";

const RECIPE_README: &str = "# Lecture 11 — a scratch lecture

## Exercises, in order

| # | file | function | book |
|---|---|---|---|
| 1 | `src/lib.rs` | `twice` — v scaled by two | §11.1 |
";

const RECIPE_CHECKS: &str = r#"//! Lecture 11, a scratch lecture: twice a vector.

#![cfg_attr(not(feature = "l11"), allow(unused))]

use raylab_checks_core::{check, declare_checks};

use crate::check::Meta;

declare_checks! {
    "l11";
    Meta::unit("twice", "(1, 2, 3) doubled is (2, 4, 6)") => twice_cases(),
}

#[cfg(feature = "l11")]
mod code {
    use crate::check::{CheckResult, ensure};
    use raylab::Vec3;

    pub(super) fn twice_cases() -> CheckResult {
        let got = l11_scratch::twice(Vec3::new(1.0, 2.0, 3.0));
        ensure(got == Vec3::new(2.0, 4.0, 6.0), "(1, 2, 3)", "(2, 4, 6)", got, "scale by two")?;
        Ok("1 case".into())
    }
}

/// What the lecture lends the stages: nothing, it has no pictures.
#[cfg(feature = "l11")]
pub mod stage {
    pub fn lend(_: &mut raylab_checks_core::stages::Lent) {}
}
"#;

const RECIPE_CHAPTER: &str = "# 11 A scratch lecture

## 11.1 Twice

Twice a vector is the vector scaled by two.

## Exercises

| # | file | function |
|---|---|---|
| 1 | `src/lib.rs` | `twice` (§11.1) |
";

/// What the student's documents name exists in the handout: the book, the student README and
/// the lectures' READMEs, read as the handout has them. A test name cited (a backquoted name of
/// four words or more, `exactly_tangent_ray_hits_once_or_misses_never_nan`) is in its sources; a
/// file path (`src/offset.rs`, `crates/raylab/SCENES.md`) is a file of the handout, of a lecture
/// or of the book; a `grader` command's subcommand and flags are the handout's grader's. No
/// instructor command is among them, and no count of the course's parts stands in their prose
/// outside a generated region ([`counts`]).
#[test]
fn what_the_students_documents_name_exists_in_the_handout() {
    let dir = scratch().join("docs-handout");
    let out =
        Command::new(grader_binary()).args(["handout", "--force", dir.to_str().unwrap()]).output().unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let problems = documents_problems(&dir);
    assert!(
        problems.is_empty(),
        "the student's documents name what the handout lacks:\n{}",
        problems.join("\n")
    );
    // Planted drifts are found: a test that is not there, a moved file, a flag the grader lacks,
    // an instructor's command.
    let planted = dir.join("lectures/02-ray-casting/README.md");
    let text = std::fs::read_to_string(&planted).unwrap();
    std::fs::write(
        &planted,
        format!(
            "{text}\nSee `grazing_ray_hits_once_or_twice` and `src/testing.rs`; the lecture's eight \
             exercises.\n\n```sh\ncargo run -p grader -- render X --no-such-flag\ncargo run -p grader -- \
             bless\n```\n"
        ),
    )
    .unwrap();
    let found = documents_problems(&dir).join("\n");
    for drift in
        ["grazing_ray_hits_once_or_twice", "src/testing.rs", "--no-such-flag", "bless", "eight exercises"]
    {
        assert!(found.contains(drift), "the planted {drift} is not found:\n{found}");
    }
}

/// Every name the student's documents in `handout` cite that the handout lacks, as `file: what`.
fn documents_problems(handout: &Path) -> Vec<String> {
    let read_all = |dir: &Path, ext: &str| -> Vec<(PathBuf, String)> {
        let mut found = Vec::new();
        let mut stack = vec![dir.to_owned()];
        while let Some(d) = stack.pop() {
            for entry in std::fs::read_dir(&d).into_iter().flatten().flatten() {
                let path = entry.path();
                if path.is_dir() && !path.ends_with("target") && !path.ends_with("book/book") {
                    stack.push(path);
                } else if path.extension().is_some_and(|e| e == ext) {
                    found.push((path.clone(), std::fs::read_to_string(&path).unwrap_or_default()));
                }
            }
        }
        found
    };
    let sources: String = read_all(handout, "rs").into_iter().map(|(_, t)| t).collect();
    let grader_sources: String =
        read_all(&handout.join("grader/src"), "rs").into_iter().map(|(_, t)| t).collect();
    let mut documents: Vec<(PathBuf, String)> = read_all(&handout.join("book/src"), "md");
    documents.extend(read_all(&handout.join("lectures"), "md"));
    documents.push((handout.join("README.md"), std::fs::read_to_string(handout.join("README.md")).unwrap()));
    // The commands of the instructors' (in the handout's grader or not): no student document names them.
    let instructors = ["handout", "bless", "grade", "gradescope", "tradeoffs", "dev"];
    let placeholder = |t: &str| {
        ["NN", "NAME", "SCENE", "FILE", "DIR", "*", "…", "X.", "MESH"].iter().any(|p| t.contains(p))
    };
    let mut problems = Vec::new();
    for (path, text) in &documents {
        let shown = path.strip_prefix(handout).unwrap_or(path).display().to_string();
        // A lecture's README, or its chapter, names the lecture's files from its folder.
        let own_lecture = if shown.starts_with("lectures/") {
            path.parent().map(Path::to_owned)
        } else {
            let stem = path.file_stem().unwrap_or_default();
            Some(handout.join("lectures").join(stem)).filter(|l| l.is_dir())
        };
        // Inline code spans and the lines of code blocks.
        let mut spans: Vec<String> = text.split('`').skip(1).step_by(2).map(str::to_owned).collect();
        let mut in_block = false;
        for line in text.lines() {
            if line.trim_start().starts_with("```") {
                in_block = !in_block;
            } else if in_block {
                spans.push(line.to_owned());
            }
        }
        for span in &spans {
            let token = span.trim();
            // A test's or a function's name of four words or more.
            let words = token.split('_').count();
            // (MIT 6.837's scene files, `scene6_16_wood_cubes`, are data, not sources.)
            let scene_file =
                token.starts_with("scene") && token[5..].starts_with(|c: char| c.is_ascii_digit());
            if words >= 4
                && !scene_file
                && token.chars().all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
                && !sources.contains(token)
            {
                problems.push(format!("{shown}: `{token}` is in no source of the handout"));
            }
            // A file path.
            let is_path = !token.contains(' ')
                && token.contains('/')
                && [".rs", ".toml", ".md", ".png", ".obj", ".exr", ".txt"].iter().any(|e| token.ends_with(e))
                && !token.starts_with("http")
                && !placeholder(token);
            if is_path {
                let exists = handout.join(token).exists()
                    || handout.join("book/src").join(token).exists()
                    || own_lecture.as_ref().is_some_and(|l| l.join(token).exists());
                if !exists {
                    problems.push(format!("{shown}: `{token}` is no file of the handout"));
                }
            }
            // A grader command: its subcommand and its flags.
            if let Some(rest) = token.split_once("-p grader -- ").map(|(_, r)| r) {
                let rest = rest.split('#').next().unwrap_or_default();
                let mut words = rest.split_whitespace();
                if let Some(first) = words.next() {
                    let is_selection = first.chars().next().is_some_and(|c| c.is_ascii_digit());
                    let variant: String = first
                        .split('-')
                        .map(|w| {
                            w.chars()
                                .next()
                                .map(|c| c.to_ascii_uppercase().to_string() + &w[1..])
                                .unwrap_or_default()
                        })
                        .collect();
                    let is_flag = first.starts_with("--");
                    if instructors.contains(&first) {
                        problems.push(format!("{shown}: `grader {first}` is an instructor's command"));
                    } else if !is_selection
                        && !is_flag
                        && !grader_sources.contains(&format!("    {variant} "))
                        && !grader_sources.contains(&format!("    {variant},"))
                    {
                        problems
                            .push(format!("{shown}: `grader {first}` is no command of the handout's grader"));
                    }
                }
                for flag in rest.split_whitespace().filter(|w| w.starts_with("--") && w.len() > 2) {
                    let name = flag.trim_start_matches('-').split('=').next().unwrap_or_default();
                    // A flag is a field of a clap struct (`allow_large: bool`) or a string of one.
                    let field = name.replace('-', "_");
                    let known = grader_sources.contains(&field)
                        || sources.contains(&format!("{field}:"))
                        || sources.contains(&format!("\"{name}\""));
                    if !known {
                        problems.push(format!("{shown}: `{flag}` is no flag of the handout's grader"));
                    }
                }
            }
        }
    }
    for (path, text) in &documents {
        let shown = path.strip_prefix(handout).unwrap_or(path).display().to_string();
        problems.extend(counts(text).into_iter().map(|count| {
            format!("{shown}: \"{count}\" is a count that drifts when the course changes: generate it or leave it out")
        }));
    }
    problems.sort();
    problems.dedup();
    problems
}

/// The counts of the course's parts in a document's prose — "three scenes", "8 exercises",
/// "0 of 86" — outside code blocks and `BEGIN GENERATED` regions (which `grader dev sync`
/// keeps true). A lecture that gains a scene or an exercise would leave such a count wrong.
fn counts(text: &str) -> Vec<String> {
    const NUMBERS: &[&str] =
        &["one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve"];
    const PARTS: &[&str] =
        &["exercises", "checks", "scenes", "stubs", "lectures", "chapters", "pictures", "functions", "hints"];
    // A lecture's number ("02") is a name, not a count.
    let is_number = |w: &str| {
        (!w.is_empty() && !w.starts_with('0') && w.chars().all(|c| c.is_ascii_digit()))
            || w == "0"
            || NUMBERS.contains(&w.to_lowercase().as_str())
    };
    let mut found = Vec::new();
    let (mut generated, mut block) = (false, false);
    for line in text.lines() {
        if line.contains("BEGIN GENERATED") {
            generated = true;
        } else if line.contains("END GENERATED") {
            generated = false;
            continue;
        }
        if line.trim_start().starts_with("```") {
            block = !block;
            continue;
        }
        if generated || block {
            continue;
        }
        // Words as they stand in the line ("02's" and "01-transforms" are one word each); a
        // number after a '.' is a version or a course code (MIT 6.837), not a count.
        let words: Vec<&str> = line
            .split(|c: char| !(c.is_alphanumeric() || ".'’-".contains(c)))
            .filter(|w| !w.is_empty())
            .map(|w| w.trim_end_matches('.'))
            .collect();
        for (i, word) in words.iter().enumerate() {
            // "stage 10", "lecture 9", "chapter 4": a name.
            let named = i > 0
                && ["stage", "lecture", "lectures", "chapter", "week"]
                    .contains(&words[i - 1].to_lowercase().as_str());
            if !is_number(word) || named {
                continue;
            }
            let next = |k: usize| words.get(i + k).copied().unwrap_or_default();
            // "three scenes", "four small scenes".
            if PARTS.contains(&next(1)) || PARTS.contains(&next(2)) {
                let upto = if PARTS.contains(&next(1)) { 1 } else { 2 };
                found.push(words[i..=i + upto].join(" "));
            }
            // "exercises passed: 0 of 86" (a count of parts, not "one of 12 gradients").
            let of_parts = words[i.saturating_sub(2)..i].iter().any(|w| PARTS.contains(w));
            if of_parts
                && next(1) == "of"
                && next(2).chars().all(|c| c.is_ascii_digit())
                && !next(2).is_empty()
            {
                found.push(words[i..=i + 2].join(" "));
            }
        }
    }
    found
}

#[test]
fn counts_of_the_course_s_parts_are_found_in_prose_only() {
    let text = "Lecture 02 has eight exercises and four small scenes; exercises passed: 0 of 86.\n\
                MIT 6.837 scenes, two images, 50 points, 02's scenes, 01-transforms scenes.\n\
                Stage 10 with lectures 01–10; one of 12 gradients.\n\
                ```\nexercises passed: 3 of 90\n```\n\
                <!-- BEGIN GENERATED table: x -->\n| 11 exercises |\n<!-- END GENERATED table -->\n";
    assert_eq!(counts(text), ["eight exercises", "four small scenes", "0 of 86"]);
    // The student README's example, as it stands: the total left out.
    assert!(counts("exercises passed: 0 of …").is_empty());
}
