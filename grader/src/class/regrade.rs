// INSTRUCTOR ONLY: left out of the handout, with the rest of `grader class`.
//! What a kept grade still holds after the instructor's tree changed (a check fixed, a snapshot
//! blessed again): the lectures whose checks may now judge otherwise are graded again, the rest
//! is kept.
//!
//! A lecture's verdicts depend on its own checks and those of the lectures it uses, nothing later
//! (ARCHITECTURE.md: a lecture's checks need that lecture and earlier ones). So the tree is
//! hashed in parts ([`JudgePrint`]): per lecture, its folder (scenes, snapshots, stubs) and its
//! checks' crate (`grader/checks/lectures/lNN/`, with the code it lends the stages); and in common, what every verdict may
//! depend on — the workspace's manifest and lock file, the kit, the protocol, the checks' shared
//! code and hidden checks, the driver that turns a check's end into a verdict, and the build's
//! precision and profile. A change in common grades everything again; a change in lecture NN
//! grades again NN and every lecture that uses it (`Workspace::dependents`), and keeps the others'
//! verdicts, which cannot have moved.

use std::collections::{BTreeMap, BTreeSet};
use std::hash::Hasher;

use serde::{Deserialize, Serialize};

use super::CheckGrade;
use crate::workspace::Workspace;

/// The instructor's tree, hashed in the parts a grade depends on.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct JudgePrint {
    /// What every verdict may depend on.
    pub common: String,
    /// Per lecture, what its own checks depend on.
    pub lectures: BTreeMap<String, String>,
}

/// The part of the tree a file (relative to the root, with `/`) belongs to: `Some(Some(NN))` a
/// lecture's, `Some(None)` the common part, `None` none (the book, the tests, the scripts, and
/// `grader class` itself, which decides no verdict).
fn part(ws: &Workspace, relative: &str) -> Option<Option<String>> {
    let parts: Vec<&str> = relative.split('/').collect();
    match parts.as_slice() {
        ["lectures", folder, _, ..] => {
            Some(Some(ws.lectures.iter().find(|l| l.folder == *folder)?.number.clone()))
        }
        ["grader", "checks", "lectures", module, _, ..] if module.len() == 3 && module.starts_with('l') => {
            Some(Some(module[1..].to_owned()))
        }
        ["grader", "src", "class", ..] => None,
        ["Cargo.toml" | "Cargo.lock"] | ["crates" | "grader", ..] => Some(None),
        _ => None,
    }
}

/// Hashes the tree at `ws.root` (without `target/`) in its parts; `build` names the precision and
/// profile.
pub fn judge_print(ws: &Workspace, build: &str) -> Result<JudgePrint, String> {
    let mut common = std::hash::DefaultHasher::new();
    common.write(build.as_bytes());
    let mut lectures: BTreeMap<String, std::hash::DefaultHasher> = BTreeMap::new();
    let mut stack = vec![ws.root.clone()];
    let mut files = Vec::new();
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))? {
            let entry = entry.map_err(|e| format!("{}: {e}", dir.display()))?;
            let path = entry.path();
            let relative = path.strip_prefix(&ws.root).unwrap_or(&path).to_string_lossy().replace('\\', "/");
            if entry.file_type().is_ok_and(|t| t.is_dir()) {
                if !matches!(relative.as_str(), "target" | ".git") && !relative.ends_with("/target") {
                    stack.push(path);
                }
            } else {
                files.push(relative);
            }
        }
    }
    files.sort();
    for relative in files {
        let Some(part) = part(ws, &relative) else { continue };
        let hasher = match part {
            Some(lecture) => lectures.entry(lecture).or_default(),
            None => &mut common,
        };
        let path = ws.root.join(&relative);
        hasher.write(relative.as_bytes());
        hasher.write(&std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?);
    }
    Ok(JudgePrint {
        common: format!("{:016x}", common.finish()),
        lectures: lectures.into_iter().map(|(l, h)| (l, format!("{:016x}", h.finish()))).collect(),
    })
}

/// The lectures a grade judged with `old` must be graded again in to be what `new` would judge:
/// `None` for all of them (the common part changed, or the grade has no print).
pub fn stale_lectures(ws: &Workspace, old: &JudgePrint, new: &JudgePrint) -> Option<BTreeSet<String>> {
    if old.common.is_empty() || old.common != new.common {
        return None;
    }
    let lectures: BTreeSet<&String> = old.lectures.keys().chain(new.lectures.keys()).collect();
    let changed = lectures.into_iter().filter(|l| old.lectures.get(*l) != new.lectures.get(*l));
    Some(changed.flat_map(|l| ws.dependents(l)).collect())
}

/// A kept grade's checks with those of the lectures `regraded` replaced by `new` (their grade
/// now), lecture by lecture in the course's order, as a whole grade reads.
pub fn merge(kept: Vec<CheckGrade>, new: Vec<CheckGrade>, regraded: &BTreeSet<String>) -> Vec<CheckGrade> {
    let lecture = |id: &str| id.get(..2).unwrap_or_default().to_owned();
    let mut checks: Vec<CheckGrade> =
        kept.into_iter().filter(|c| !regraded.contains(&lecture(&c.id))).chain(new).collect();
    // Stable: within a lecture, each grade's own order.
    checks.sort_by_key(|c| lecture(&c.id));
    checks
}

/// Gradescope's `results.json` of a kept grade with the tests of the lectures `regraded`
/// replaced by `new`'s (a test's name starts with its lecture: `02 hit_plane/unit`).
pub fn merge_results(
    kept: &serde_json::Value,
    new: &serde_json::Value,
    regraded: &BTreeSet<String>,
) -> serde_json::Value {
    let lecture = |test: &serde_json::Value| {
        test["name"].as_str().unwrap_or_default().get(..2).unwrap_or_default().to_owned()
    };
    let tests = |results: &serde_json::Value| results["tests"].as_array().cloned().unwrap_or_default();
    let mut merged: Vec<serde_json::Value> =
        tests(kept).into_iter().filter(|t| !regraded.contains(&lecture(t))).collect();
    merged.extend(tests(new));
    merged.sort_by_key(lecture);
    let score: f64 = merged.iter().filter_map(|t| t["score"].as_f64()).sum();
    let mut results = new.clone();
    results["tests"] = serde_json::Value::Array(merged);
    results["score"] = serde_json::json!(score);
    results
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;

    /// A tree of three lectures (02 uses 01; 03 uses none) with their checks' modules.
    fn tree(root: &Path) -> Workspace {
        let write = |relative: &str, text: &str| {
            let path = root.join(relative);
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(path, text).unwrap();
        };
        write("Cargo.toml", "[workspace]\nmembers = [\"lectures/*\"]\n");
        write("Cargo.lock", "");
        write("crates/raylab/src/lib.rs", "// the kit");
        write("book/src/intro.md", "# the book");
        write("grader/src/class/mod.rs", "// grader class");
        write("grader/checks/core/src/images/mod.rs", "// shared checks");
        for (folder, package, uses) in
            [("01-a", "l01-a", ""), ("02-b", "l02-b", "l01-a"), ("03-c", "l03-c", "")]
        {
            let deps =
                if uses.is_empty() { String::new() } else { format!("{uses} = {{ path = \"../01-a\" }}\n") };
            write(
                &format!("lectures/{folder}/Cargo.toml"),
                &format!(
                    "[package]\nname = \"{package}\"\n\n[package.metadata.raylab]\ntitle = \"{folder}\"\n\
                     summary = \"a lecture\"\n\n[dependencies]\n{deps}"
                ),
            );
            write(&format!("lectures/{folder}/src/lib.rs"), "");
            write(&format!("lectures/{folder}/snapshots/s.png"), "png");
            write(&format!("grader/checks/lectures/l{}/src/lib.rs", &folder[..2]), "// checks");
        }
        Workspace::open(root).unwrap()
    }

    #[test]
    fn a_lectures_change_grades_again_it_and_the_lectures_that_use_it_a_common_one_all() {
        let root = std::env::temp_dir().join(format!("raylab-regrade-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        let ws = tree(&root);
        let print = |ws: &Workspace| judge_print(ws, "f32 debug").unwrap();
        let before = print(&ws);
        assert_eq!(before.lectures.keys().collect::<Vec<_>>(), ["01", "02", "03"]);
        let set = |items: &[&str]| Some(items.iter().map(|s| s.to_string()).collect::<BTreeSet<String>>());
        // Nothing a verdict depends on: the book, `grader class`, build output.
        std::fs::write(root.join("book/src/intro.md"), "# the book, edited").unwrap();
        std::fs::write(root.join("grader/src/class/mod.rs"), "// grader class, edited").unwrap();
        std::fs::create_dir_all(root.join("target/debug")).unwrap();
        std::fs::write(root.join("target/debug/x"), "built").unwrap();
        assert_eq!(stale_lectures(&ws, &before, &print(&ws)), set(&[]));
        // Lecture 01's checks: 01 and 02, which uses it.
        std::fs::write(root.join("grader/checks/lectures/l01/src/lib.rs"), "// fixed").unwrap();
        assert_eq!(stale_lectures(&ws, &before, &print(&ws)), set(&["01", "02"]));
        // Lecture 03's snapshot, blessed again: 03 alone.
        let before = print(&ws);
        std::fs::write(root.join("lectures/03-c/snapshots/s.png"), "png, blessed again").unwrap();
        assert_eq!(stale_lectures(&ws, &before, &print(&ws)), set(&["03"]));
        // The checks' shared code, the kit, the precision: everything.
        let before = print(&ws);
        std::fs::write(root.join("grader/checks/core/src/images/mod.rs"), "// fixed").unwrap();
        assert_eq!(stale_lectures(&ws, &before, &print(&ws)), None);
        let before = print(&ws);
        assert_eq!(stale_lectures(&ws, &before, &judge_print(&ws, "f64 debug").unwrap()), None);
        assert_eq!(stale_lectures(&ws, &JudgePrint::default(), &before), None, "a grade without a print");
        std::fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn a_partial_grade_replaces_its_lectures_checks_and_tests_and_keeps_the_others() {
        let check = |id: &str, points: u32| CheckGrade {
            id: id.into(),
            exercise: id.rsplit_once('/').unwrap().0.into(),
            points,
            max_points: 1,
            status: if points == 1 { "passed" } else { "FAILED" }.into(),
            cause: None,
            picture: None,
        };
        let kept =
            vec![check("01/a/unit", 1), check("02/b/unit", 0), check("02/image/s", 0), check("03/c/unit", 1)];
        let new = vec![check("02/b/unit", 1), check("02/b/new-case", 1), check("02/image/s", 1)];
        let regraded = BTreeSet::from(["02".to_owned()]);
        let merged = merge(kept, new, &regraded);
        let ids: Vec<(&str, u32)> = merged.iter().map(|c| (c.id.as_str(), c.points)).collect();
        assert_eq!(
            ids,
            [("01/a/unit", 1), ("02/b/unit", 1), ("02/b/new-case", 1), ("02/image/s", 1), ("03/c/unit", 1)]
        );
        let test =
            |name: &str, score: f64| serde_json::json!({"name": name, "score": score, "max_score": 1.0});
        let kept = serde_json::json!({"score": 2.0, "tests": [test("01 a/unit", 1.0), test("02 b/unit", 0.0), test("03 c/unit", 1.0)]});
        let new = serde_json::json!({"score": 1.0, "tests": [test("02 b/unit", 1.0)]});
        let merged = merge_results(&kept, &new, &regraded);
        assert_eq!(merged["score"], 3.0);
        let names: Vec<&str> =
            merged["tests"].as_array().unwrap().iter().map(|t| t["name"].as_str().unwrap()).collect();
        assert_eq!(names, ["01 a/unit", "02 b/unit", "03 c/unit"]);
    }
}
