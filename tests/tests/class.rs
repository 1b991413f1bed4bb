//! `grader class` on a class made to be known: 40 students built from the catalogue of mistakes
//! (`tests/mistakes`), each with 0–3 planted mistakes in different lectures, plus the reference,
//! the handout and a folder that holds no submission. Graded at once, the class's page must
//! group each planted mistake's students — in one cluster of wrong pictures where the check that
//! catches it draws one, in one cause group otherwise — with no one else; the gradebook's
//! totals must be the single grades; a second run must grade again only what changed.
//!
//! The class is graded on lectures 01, 02 and 05, its mistakes' lectures: those between, built
//! for 05, hold the course's slowest checks, the meshes' (a mistake-free submission's grade takes
//! 3.7 s with 03–04, 1.4 s without); the class takes about two minutes.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;
use std::process::Command;

mod support;

use support::*;

/// The lectures graded, and the mistakes planted: per lecture, (the check that catches it, a
/// piece of its cause) as the catalogue names them. Two kinds: those a picture's check catches
/// (its students must form one cluster of that picture) and those a function's check catches
/// (one cause group).
const LECTURES: [&str; 3] = ["01", "02", "05"];
const POOL: [&[(&str, &str)]; 3] = [
    &[
        ("01/image/perspective", "tan(fovy/2)"),
        ("01/rotate_z/unit", "wrong way"),
        ("01/look_at/unit", "backwards"),
    ],
    &[
        ("02/image/overlapping-depths", "closest_hit keeps the nearest hit"),
        ("02/hit_plane/unit", "t = (offset − n·o)/(n·d)"),
        ("02/hit_sphere_stable/unit", "zero discriminant"),
        ("02/depth_image/unit", "closest hit's t"),
    ],
    &[
        ("05/image/coloured-lights", "max(N·L, 0)"),
        ("05/blinn_specular/unit", "normalise the half vector"),
        ("05/spot_falloff/unit", "smoothstep"),
        ("05/distance_falloff/unit", "square of the distance"),
    ],
];

/// The 40 students: each mistake alone once; then, to 36, students with two or three mistakes in
/// different lectures, chosen by turns; then 4 with none. Named in the order of their lectures'
/// states (lecture 01's mistake, then 02's, then 05's), which the class is graded in: cargo then
/// rebuilds an early lecture, and every lecture after it, a few times rather than at every
/// submission.
fn class(pool: &[Vec<&Mistake>]) -> Vec<(String, Vec<usize>)> {
    let index = |lecture: usize, k: usize| pool[..lecture].iter().map(Vec::len).sum::<usize>() + k;
    let mut students = Vec::new();
    for (lecture, mistakes) in pool.iter().enumerate() {
        for k in 0..mistakes.len() {
            students.push(vec![index(lecture, k)]);
        }
    }
    for s in 0..36 - students.len() {
        let count = 2 + s % 2;
        let mut lectures: Vec<usize> = (0..count).map(|i| (s + 2 * i) % pool.len()).collect();
        lectures.sort();
        students.push(lectures.iter().map(|&l| index(l, (s + l) % pool[l].len())).collect());
    }
    students.extend(std::iter::repeat_n(Vec::new(), 4));
    assert_eq!(students.len(), 40);
    let state = |planted: &Vec<usize>| -> Vec<Option<usize>> {
        (0..pool.len())
            .map(|l| planted.iter().copied().find(|&m| (index(l, 0)..index(l, pool[l].len())).contains(&m)))
            .collect()
    };
    students.sort_by_key(state);
    students.into_iter().enumerate().map(|(i, m)| (format!("s{:02}", i + 1), m)).collect()
}

/// The class's page, read back: per check, its groups of students (the cause groups of
/// `tr[data-check]`, the clusters of `tr.clusters`), each with its cause or none.
struct Page {
    causes: BTreeMap<String, Vec<(String, BTreeSet<String>)>>,
    clusters: BTreeMap<String, Vec<BTreeSet<String>>>,
    /// The mistakes at a glance: the checks failed together, and by whom.
    glance: Vec<(BTreeSet<String>, BTreeSet<String>)>,
}

impl Page {
    fn read(file: &Path) -> Page {
        let html = std::fs::read_to_string(file).unwrap();
        let (mut causes, mut clusters, mut glance) = (BTreeMap::new(), BTreeMap::new(), Vec::new());
        let attribute = |tag: &str, name: &str| -> Option<String> {
            let start = tag.find(&format!("{name}=\""))? + name.len() + 2;
            Some(tag[start..start + tag[start..].find('"')?].to_owned())
        };
        let students = |list: String| -> BTreeSet<String> { list.split('\n').map(str::to_owned).collect() };
        for row in html.split("<tr ").skip(1) {
            let row = &row[..row.find("</tr>").unwrap_or(row.len())];
            if let (Some(checks), Some(list)) =
                (attribute(row, "data-checks"), attribute(row, "data-students"))
            {
                glance.push((students(checks), students(list)));
                continue;
            }
            let Some(check) = attribute(row, "data-check") else { continue };
            if row.starts_with("class=\"clusters\"") {
                let groups = row
                    .split("<figure class=\"cluster\"")
                    .skip(1)
                    .map(|f| students(attribute(f, "data-students").unwrap()))
                    .collect();
                clusters.insert(check, groups);
            } else if let Some(list) = attribute(row, "data-students") {
                let cause = attribute(row, "data-cause").unwrap_or_default();
                causes.entry(check).or_insert_with(Vec::new).push((cause, students(list)));
            }
        }
        Page { causes, clusters, glance }
    }
}

#[test]
#[ignore = "the whole workbench (minutes): cargo test -p workbench-tests -- --ignored; CI runs it"]
fn a_class_of_planted_mistakes_clusters_by_mistake_into_a_gradebook_of_the_single_grades() {
    let _turn = work_turn();
    let catalogue = catalogue();
    let pool: Vec<Vec<&Mistake>> = POOL
        .iter()
        .map(|mistakes| {
            mistakes
                .iter()
                .map(|(check, cause)| {
                    catalogue
                        .iter()
                        .find(|m| m.caught_by == *check && m.cause.contains(cause))
                        .unwrap_or_else(|| panic!("no mistake caught by {check} with cause {cause}"))
                })
                .collect()
        })
        .collect();
    let mistakes: Vec<&Mistake> = pool.iter().flatten().copied().collect();
    let students = class(&pool);
    // The student with only the mistake that `check` catches.
    let alone = |check: &str| -> String {
        let m = mistakes.iter().position(|m| m.caught_by == check).unwrap();
        students.iter().find(|(_, planted)| *planted == [m]).unwrap().0.clone()
    };

    let dir = scratch().join("class");
    let _ = std::fs::remove_dir_all(&dir);
    let (submissions, out) = (dir.join("submissions"), dir.join("out"));
    for (name, planted) in &students {
        let patches: Vec<(&str, &str, &str)> = planted
            .iter()
            .map(|&m| (mistakes[m].file.as_str(), mistakes[m].find.as_str(), mistakes[m].replace.as_str()))
            .collect();
        copy_tree(&submission("class", &patches), &submissions.join(name));
    }
    copy_tree(&submission("class", &[]), &submissions.join("reference"));
    let handout = dir.join("handout");
    let made = Command::new(grader_binary()).args(["handout", "--force"]).arg(&handout).output().unwrap();
    assert!(made.status.success(), "{}", String::from_utf8_lossy(&made.stderr));
    copy_tree(&handout.join("lectures"), &submissions.join("handout").join("lectures"));
    std::fs::create_dir_all(submissions.join("nobody")).unwrap();
    std::fs::write(submissions.join("nobody/notes.txt"), "I could not finish").unwrap();

    let run = || {
        let mut command = Command::new(grader_binary());
        incremental(&mut command);
        let output = command
            .current_dir(root())
            .arg("class")
            .arg(&submissions)
            .arg("-o")
            .arg(&out)
            .arg("--workdir")
            .arg(scratch().join("work"))
            .args(LECTURES)
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
        assert!(output.status.success(), "{stderr}");
        let gradebook = std::fs::read_to_string(out.join("gradebook.csv"))
            .unwrap_or_else(|e| panic!("no gradebook ({e}):\n{stderr}"));
        (gradebook, stderr)
    };
    let (gradebook, stderr) = run();
    println!("{stderr}");
    let rows: Vec<Vec<&str>> = gradebook.lines().map(|l| l.split(',').collect()).collect();
    let column =
        |name: &str| rows[0].iter().position(|c| *c == name).unwrap_or_else(|| panic!("no column {name}"));
    let row =
        |student: &str| rows.iter().find(|r| r[0] == student).unwrap_or_else(|| panic!("no row {student}"));
    let (total, possible) = (column("total"), column("possible"));

    // Nothing fails without a mistake; the handout scores nothing; a folder without `lectures/`
    // is a row that says so.
    let clean: Vec<&str> =
        students.iter().filter(|(_, m)| m.is_empty()).map(|(n, _)| n.as_str()).chain(["reference"]).collect();
    for name in &clean {
        assert_eq!(row(name)[total], row(name)[possible], "{name} has no mistake");
    }
    assert_eq!(row("handout")[total], "0");
    assert!(row("nobody").last().unwrap().contains("has no lectures/ folder"), "{:?}", row("nobody"));

    // Each planted mistake's students, where its check judged it (not blocked by another of their
    // mistakes), form one group of that check, and no one else is in it.
    let page = Page::read(&out.join("class.html"));
    let grade = |student: &str| -> serde_json::Value {
        let file = out.join("students").join(student).join("grade.json");
        serde_json::from_str(&std::fs::read_to_string(file).unwrap()).unwrap()
    };
    let mut problems = Vec::new();
    for (m, mistake) in mistakes.iter().enumerate() {
        let planted: Vec<&str> =
            students.iter().filter(|(_, p)| p.contains(&m)).map(|(n, _)| n.as_str()).collect();
        let mut judged = BTreeSet::new();
        for student in &planted {
            let grade = grade(student);
            let check = grade["checks"].as_array().unwrap().iter().find(|c| c["id"] == *mistake.caught_by);
            let status = check.map_or("absent", |c| c["status"].as_str().unwrap());
            match status {
                "FAILED" => {
                    judged.insert(student.to_string());
                }
                // Blocked: another of this student's mistakes is in an earlier lecture.
                "blocked" => {
                    let own = &mistake.caught_by[..2];
                    let planted = &students.iter().find(|(n, _)| n == student).unwrap().1;
                    if !planted.iter().any(|&o| mistakes[o].caught_by[..2] < *own) {
                        problems
                            .push(format!("{student}: {} blocked by no earlier mistake", mistake.caught_by));
                    }
                }
                other => problems
                    .push(format!("{student}: {} is {other}, planted {}", mistake.caught_by, mistake.name)),
            }
        }
        if judged.is_empty() {
            problems.push(format!("{}: no student's {} judged it", mistake.name, mistake.caught_by));
            continue;
        }
        let first = judged.iter().next().unwrap();
        let group = if mistake.caught_by.contains("/image/") {
            page.clusters.get(&mistake.caught_by).and_then(|c| c.iter().find(|g| g.contains(first))).cloned()
        } else {
            let groups = page.causes.get(&mistake.caught_by);
            let found = groups.and_then(|g| g.iter().find(|(_, students)| students.contains(first)));
            if let Some((cause, _)) = found
                && !cause.contains(&mistake.cause)
            {
                problems.push(format!(
                    "{}: the group's cause is {cause:?}, not {:?}",
                    mistake.name, mistake.cause
                ));
            }
            found.map(|(_, students)| students.clone())
        };
        // At a glance, its students fail its check together (with those its mistake costs them).
        if judged.len() >= 2
            && !page
                .glance
                .iter()
                .any(|(checks, students)| *students == judged && checks.contains(&mistake.caught_by))
        {
            problems.push(format!(
                "{}: not at a glance as {judged:?} failing {}",
                mistake.name, mistake.caught_by
            ));
        }
        if group.as_ref() != Some(&judged) {
            problems.push(format!(
                "{} ({}): planted in {planted:?}, judged in {judged:?}, grouped as {group:?}",
                mistake.name, mistake.caught_by
            ));
        }
    }
    assert!(
        problems.is_empty(),
        "the class's groups are not its planted mistakes:\n{}\n{stderr}",
        problems.join("\n")
    );

    // The totals are the single grades, `grade --submission` as a student's own run: the
    // reference, one mistake alone, and three mistakes at once.
    let three = students.iter().find(|(_, m)| m.len() == 3).unwrap().0.clone();
    let camera = alone("01/image/perspective");
    for student in ["reference", &camera, &three] {
        let (single, _) = grade_submission(&submissions.join(student), &LECTURES, "class-single.json");
        assert_eq!(row(student)[total], single["score"].to_string(), "{student}'s total");
        assert_eq!(row(student)[possible], single["max_score"].to_string(), "{student}'s possible");
    }
    assert!(out.join("students").join(&camera).join("results.json").is_file(), "Gradescope's results");

    // The page, in a browser: the check most students fail first, every picture shown; the heat
    // map counts the 42 graded (the 40, the reference and the handout).
    let mut failed: BTreeMap<String, usize> = BTreeMap::new();
    for (student, _) in students.iter().chain([&("reference".to_owned(), Vec::new())]) {
        for check in grade(student)["checks"].as_array().unwrap() {
            if check["status"] == "FAILED" {
                *failed.entry(check["id"].as_str().unwrap().to_owned()).or_default() += 1;
            }
        }
    }
    // The most failed, ties to the first by name: the page's order.
    let first = failed.iter().max_by(|a, b| a.1.cmp(b.1).then(b.0.cmp(a.0))).unwrap().0;
    browser_check(
        "tests/class_check.py",
        &[out.join("class.html").to_str().unwrap(), "--first", first, "--students", "42", "--pictures"],
    );

    // Again, with one submission changed, and for two students the checks of a lecture as if
    // changed since their grade (their grade's print of it altered): the one is graded again, the
    // lectures of those two that depend on the change, and no one else, to the same grades.
    let changed = submissions.join(&camera).join(&mistakes[0].file);
    let text = std::fs::read_to_string(&changed).unwrap();
    std::fs::write(&changed, text + "// resubmitted\n").unwrap();
    let pretend = |student: &str, lecture: &str| {
        let file = out.join("students").join(student).join("grade.json");
        let mut grade: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(&file).unwrap()).unwrap();
        grade["judge"]["lectures"][lecture] = "a check since fixed".into();
        std::fs::write(&file, grade.to_string()).unwrap();
    };
    // One has lecture 05's picture mistake, the other lecture 02's plane (02 is used by 05).
    let (lambert, plane) = (alone("05/image/coloured-lights"), alone("02/hit_plane/unit"));
    pretend(&lambert, "05");
    pretend(&plane, "02");
    let (again, stderr) = run();
    assert_eq!(again, gradebook, "the same grades");
    let said =
        |student: &str| stderr.lines().find(|l| l.contains(&format!("] {student}: "))).unwrap_or_default();
    let untouched = &students.iter().rfind(|(_, m)| m.is_empty()).unwrap().0;
    assert!(said(untouched).contains("unchanged since its last grade"), "{stderr}");
    assert!(
        said(&camera).ends_with(" s") && !said(&camera).contains("unchanged"),
        "{camera} is graded again: {stderr}"
    );
    assert!(said(&lambert).contains("lectures 05 graded again"), "{stderr}");
    assert!(said(&plane).contains("lectures 02, 05 graded again"), "{stderr}");
    let regraded = Page::read(&out.join("class.html"));
    assert_eq!(regraded.clusters, page.clusters, "the same clusters of wrong pictures");
    assert_eq!(regraded.causes, page.causes, "the same causes");

    // The class graded on Gradescope instead: an export whose metadata holds each submission's
    // results (our `results.json`; YAML reads JSON) and its students. `class --results` makes
    // the same gradebook's points, a row per student, and the same causes, from it alone.
    let export = dir.join("export/assignment_1_export");
    std::fs::create_dir_all(&export).unwrap();
    let mut metadata = String::from("---\n");
    for (i, (student, _)) in students.iter().enumerate() {
        let results =
            std::fs::read_to_string(out.join("students").join(student).join("results.json")).unwrap();
        let results: serde_json::Value = serde_json::from_str(&results).unwrap();
        metadata.push_str(&format!(
            "submission_{student}:\n  :submitters:\n  - :name: Student {student}\n    :sid: {}\n    :email: {student}@example.edu\n  :results: {results}\n",
            1000 + i
        ));
    }
    std::fs::write(export.join("submission_metadata.yml"), metadata).unwrap();
    let from_export = dir.join("from-export");
    let made = Command::new(grader_binary())
        .args(["class", "--results"])
        .arg(&export)
        .arg("-o")
        .arg(&from_export)
        .output()
        .unwrap();
    assert!(made.status.success(), "{}", String::from_utf8_lossy(&made.stderr));
    let exported = std::fs::read_to_string(from_export.join("gradebook.csv")).unwrap();
    let exported: Vec<Vec<&str>> = exported.lines().map(|l| l.split(',').collect()).collect();
    assert_eq!(exported[0], rows[0], "the same columns");
    for (i, (student, _)) in students.iter().enumerate() {
        let row = exported.iter().find(|r| r[3] == format!("submission_{student}")).unwrap();
        assert_eq!(
            row[..3],
            [&format!("Student {student}"), &format!("{}", 1000 + i), &format!("{student}@example.edu")]
        );
        assert_eq!(row[4..], rows.iter().find(|r| r[0] == student).unwrap()[4..], "{student}'s points");
    }
    let renamed =
        |causes: &BTreeMap<String, Vec<(String, BTreeSet<String>)>>| -> Vec<(String, String, usize)> {
            causes
                .iter()
                .flat_map(|(check, groups)| {
                    groups.iter().map(move |(c, s)| (check.clone(), c.clone(), s.len()))
                })
                .collect()
        };
    let exported = Page::read(&from_export.join("class.html"));
    // Without pictures, a picture's check's students are grouped by cause: compare the others.
    let unit = |page: &Page| -> Vec<(String, String, usize)> {
        renamed(&page.causes).into_iter().filter(|(check, _, _)| !check.contains("/image/")).collect()
    };
    assert_eq!(unit(&exported), unit(&page), "the same causes, each as many students");
    assert!(exported.clusters.is_empty(), "no pictures in an export");
}
