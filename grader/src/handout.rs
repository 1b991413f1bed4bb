//! `grader handout DIR`: the student workspace, written from the instructor's.
//!
//! - every `// SOLUTION BEGIN … // SOLUTION END` region becomes
//!   `todo!("NN/exercise: Book §N.M Title")` — the id the grader reads back
//!   from the panic to say "not started" or "blocked: needs NN exercise";
//! - `// INSTRUCTOR BEGIN … // INSTRUCTOR END` regions (in Rust and TOML
//!   files) are removed, and files whose first line says `INSTRUCTOR ONLY`
//!   are left out, with the folders of instructor material: `tests/`,
//!   `benches/`, `scripts/`, `.ci/`, `book/doctests/`, the checks' own tests,
//!   the book's maintenance scripts and `ARCHITECTURE.md`;
//! - `README.md` is the student's (`grader/STUDENT-README.md`), not the
//!   instructors';
//! - workspace members that are left out leave the members list;
//! - each lecture's `lib.rs` gets an `allow` for the warnings the stubs
//!   cause (unused parameters and imports), to be deleted when done.

use std::path::{Path, PathBuf};

/// Folders and files (relative to the root) that stay out of the handout:
/// build output, the instructors' tests, benchmarks, scripts and CI, the
/// book's maintenance scripts (a student builds the book with `mdbook build
/// book` alone), and the instructors' documents (`ARCHITECTURE.md`, the
/// template of the student's README, which becomes its `README.md`).
const LEFT_OUT: &[&str] = &[
    "target",
    ".git",
    "tests",
    "benches",
    "scripts",
    ".ci",
    "book/doctests",
    "book/book",
    "book/README.md",
    "book/ci.sh",
    "book/browsercheck.py",
    "book/linkcheck.py",
    "book/figures.sh",
    "book/katex.sh",
    "book/regenerate.sh",
    "book/tradeoffs.sh",
    "grader/checks/tests",
    "grader/checks/src/tools/tradeoffs",
    "ARCHITECTURE.md",
    STUDENT_README,
];

/// The checks' sources (the binary's, the core's and each lecture's checks crate's): their tests
/// (planted mistakes, some of them the reference with a switch) stay out of the handout.
const CHECKS_SOURCE: &str = "grader/checks/";

/// The student's `README.md`, kept in the instructors' tree under this name.
const STUDENT_README: &str = "grader/STUDENT-README.md";

/// One exercise region found in a source file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Exercise {
    /// `02/hit_sphere_geometric`, `01/PerspectiveCamera::generate_ray`.
    pub id: String,
    /// `Book: §2.3 The geometric solution`, or the chapter.
    pub book: String,
    /// 1-based line of `// SOLUTION BEGIN`.
    pub line: usize,
}

/// Writes the handout of the workspace at `root` into `dir`.
pub fn write(root: &Path, dir: &Path, force: bool) -> Result<(), String> {
    if dir.exists() {
        if !force {
            return Err(format!("{} exists (use --force to replace it)", dir.display()));
        }
        if dir.join("lectures").is_dir() || std::fs::read_dir(dir).map_or(true, |mut d| d.next().is_none()) {
            std::fs::remove_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        } else {
            return Err(format!("{} exists and is not a raylab workspace: not replacing it", dir.display()));
        }
    }
    let root = root.canonicalize().map_err(|e| format!("{}: {e}", root.display()))?;
    let mut exercises = 0;
    for file in files(&root)? {
        let relative = file.strip_prefix(&root).map_err(|e| e.to_string())?;
        let target = dir.join(relative);
        if let Some(parent) = target.parent() {
            std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
        }
        let text = match std::fs::read(&file) {
            Ok(bytes) => match String::from_utf8(bytes) {
                Ok(text) => text,
                Err(e) => {
                    // Images, EXR files: copied as they are.
                    std::fs::write(&target, e.as_bytes())
                        .map_err(|e| format!("{}: {e}", target.display()))?;
                    continue;
                }
            },
            Err(e) => return Err(format!("{}: {e}", file.display())),
        };
        if text.lines().next().is_some_and(|l| l.contains("INSTRUCTOR ONLY")) {
            continue;
        }
        let relative_str = relative.to_string_lossy().replace('\\', "/");
        let mut text = strip_instructor(&text, &relative_str)?;
        if relative_str.starts_with("lectures/") && relative_str.ends_with(".rs") {
            let lecture: String = relative_str["lectures/".len()..].chars().take(2).collect();
            let (stubbed, found) = stub_solutions(&text, &lecture, &relative_str)?;
            exercises += found.len();
            text = stubbed;
            if relative_str.ends_with("/src/lib.rs") {
                text = allow_stub_warnings(&text);
            }
        }
        if relative_str.starts_with(CHECKS_SOURCE) && relative_str.ends_with(".rs") {
            text = without_tests(&text);
        }
        if relative_str == "Cargo.toml" {
            text = drop_missing_members(&text, &root);
        }
        if relative_str == "README.md" {
            let template = root.join(STUDENT_README);
            text = std::fs::read_to_string(&template).map_err(|e| format!("{}: {e}", template.display()))?;
        }
        std::fs::write(&target, text).map_err(|e| format!("{}: {e}", target.display()))?;
    }
    println!("handout: {} exercises stubbed, written to {}", exercises, dir.display());
    Ok(())
}

/// Every file under `root` that goes into the handout, sorted.
fn files(root: &Path) -> Result<Vec<PathBuf>, String> {
    let mut found = Vec::new();
    let mut stack = vec![root.to_owned()];
    while let Some(dir) = stack.pop() {
        let entries = std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        for entry in entries {
            let path = entry.map_err(|e| e.to_string())?.path();
            let relative =
                path.strip_prefix(root).map_err(|e| e.to_string())?.to_string_lossy().replace('\\', "/");
            if LEFT_OUT.contains(&relative.as_str()) || relative.ends_with("/target") {
                continue;
            }
            if path.is_dir() {
                stack.push(path);
            } else {
                found.push(path);
            }
        }
    }
    found.sort();
    Ok(found)
}

/// `text` without its `INSTRUCTOR BEGIN … END` regions (marker lines included),
/// and without the marker lines of its generated lists (their contents stay): those
/// name `grader dev sync`, an instructors' command the handout does not have.
fn strip_instructor(text: &str, file: &str) -> Result<String, String> {
    let mut out = String::with_capacity(text.len());
    let mut inside = None;
    for (n, line) in text.split_inclusive('\n').enumerate() {
        let trimmed = line.trim();
        if trimmed.ends_with("INSTRUCTOR BEGIN") && is_comment(trimmed) {
            if inside.is_some() {
                return Err(format!("{file}:{}: INSTRUCTOR BEGIN inside another region", n + 1));
            }
            inside = Some(n + 1);
        } else if trimmed.ends_with("INSTRUCTOR END") && is_comment(trimmed) {
            if inside.take().is_none() {
                return Err(format!("{file}:{}: INSTRUCTOR END without a BEGIN", n + 1));
            }
        } else if inside.is_none() && !is_generated_marker(trimmed) {
            out.push_str(line);
        }
    }
    match inside {
        Some(line) => Err(format!("{file}:{line}: INSTRUCTOR BEGIN without an END")),
        None => Ok(out),
    }
}

fn is_comment(line: &str) -> bool {
    line.starts_with("//") || line.starts_with('#')
}

/// `# BEGIN GENERATED name: …`, `<!-- END GENERATED name -->` (`sync.rs`).
fn is_generated_marker(line: &str) -> bool {
    let body =
        line.strip_prefix("<!--").or_else(|| line.strip_prefix("//")).or_else(|| line.strip_prefix('#'));
    body.is_some_and(|b| {
        b.trim_start().starts_with("BEGIN GENERATED ") || b.trim_start().starts_with("END GENERATED ")
    })
}

/// `text` with each solution region replaced by a `todo!` naming its
/// exercise, and the exercises found.
pub fn stub_solutions(text: &str, lecture: &str, file: &str) -> Result<(String, Vec<Exercise>), String> {
    let lines: Vec<&str> = text.split_inclusive('\n').collect();
    let mut out = String::with_capacity(text.len());
    let mut exercises = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        if line.trim() == "// SOLUTION END" {
            return Err(format!("{file}:{}: SOLUTION END without a BEGIN", i + 1));
        }
        if line.trim() != "// SOLUTION BEGIN" {
            out.push_str(line);
            i += 1;
            continue;
        }
        let end = (i + 1..lines.len())
            .find(|&j| lines[j].trim() == "// SOLUTION END" || lines[j].trim() == "// SOLUTION BEGIN")
            .filter(|&j| lines[j].trim() == "// SOLUTION END")
            .ok_or_else(|| format!("{file}:{}: SOLUTION BEGIN without an END", i + 1))?;
        let exercise = exercise_at(&lines[..i], lecture)
            .ok_or_else(|| format!("{file}:{}: a SOLUTION region outside any fn", i + 1))?;
        let indent: String = line.chars().take_while(|c| c.is_whitespace()).collect();
        out.push_str(&format!("{indent}todo!(\"{}: {}\")\n", exercise.id, exercise.book.replace('"', "'")));
        exercises.push(Exercise { line: i + 1, ..exercise });
        i = end + 1;
    }
    Ok((out, exercises))
}

/// The exercise whose body starts after `before`: the last `fn` line, its
/// `impl` type when the fn is a method, and the "Book: §…" reference of its
/// doc comment.
fn exercise_at(before: &[&str], lecture: &str) -> Option<Exercise> {
    let fn_line = before.iter().rposition(|l| fn_name(l).is_some())?;
    let mut name = fn_name(before[fn_line])?;
    if before[fn_line].starts_with(char::is_whitespace) {
        let impl_line = before[..fn_line].iter().rev().find(|l| l.starts_with("impl"))?;
        name = format!("{}::{name}", impl_type(impl_line)?);
    }
    // The doc comment (and attributes) right above the fn.
    let mut book = format!("Book: chapter {}", lecture.trim_start_matches('0'));
    for line in before[..fn_line].iter().rev() {
        let t = line.trim();
        if !(t.starts_with("///") || t.starts_with("#[")) {
            break;
        }
        if let Some(at) = t.find("Book: §") {
            let reference = t[at..].trim_end_matches('.');
            // A reference may run on past the sentence: keep "Book: §N.M Title".
            book = reference.split(". ").next().unwrap_or(reference).to_owned();
        }
    }
    Some(Exercise { id: format!("{lecture}/{name}"), book, line: 0 })
}

/// `hit_slabs` for a line declaring `pub fn hit_slabs(…`.
fn fn_name(line: &str) -> Option<String> {
    let t = line.trim_start();
    if t.starts_with("//") {
        return None;
    }
    let at = t.find("fn ")?;
    // `fn` as a word: at the start or after a space (`pub fn`, `pub(crate) const fn`).
    if at > 0 && !t[..at].ends_with(' ') {
        return None;
    }
    let name: String = t[at + 3..].chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
    (!name.is_empty()
        && t[..at].split_whitespace().all(|w| ["pub", "pub(crate)", "const", "unsafe"].contains(&w)))
    .then_some(name)
}

/// `Bvh` for `impl<'a> Bvh<'a> {` or `impl Intersector for Bvh<'_> {`.
fn impl_type(line: &str) -> Option<String> {
    let rest = line.strip_prefix("impl")?;
    let rest = if rest.starts_with('<') { &rest[rest.find('>')? + 1..] } else { rest };
    let rest = rest.split(" for ").last()?;
    let name: String = rest.trim().chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
    (!name.is_empty()).then_some(name)
}

/// A checks source without its tests: everything from the first top-level
/// `#[cfg(test)]` (or `#[cfg(all(test, …))]`) on. In the checks crate a file's tests come last (its planted
/// mistakes are a check's tests and may hold the reference with a switch: an
/// exercise solved); the handout compiling without a warning shows that nothing
/// the checks use came after them.
fn without_tests(text: &str) -> String {
    let lines: Vec<&str> = text.split_inclusive('\n').collect();
    let is_test_gate = |l: &&str| {
        l.starts_with("#[cfg(") && l.split(|c: char| !c.is_alphanumeric() && c != '_').any(|w| w == "test")
    };
    let Some(mut cut) = lines.iter().position(is_test_gate) else {
        return text.to_owned();
    };
    // With the doc comment and attributes above it.
    while cut > 0 && (lines[cut - 1].starts_with("///") || lines[cut - 1].starts_with("#[")) {
        cut -= 1;
    }
    let mut out = lines[..cut].concat().trim_end().to_owned();
    out.push('\n');
    out
}

/// Adds, after the crate's doc comment, an `allow` for what the stubs leave unused.
fn allow_stub_warnings(text: &str) -> String {
    let lines: Vec<&str> = text.split_inclusive('\n').collect();
    let after_docs = lines.iter().position(|l| !l.starts_with("//!")).unwrap_or(lines.len());
    let mut out: String = lines[..after_docs].concat();
    out.push_str(
        "\n// Handout: the todo!() stubs leave parameters, imports and helpers unused;\n\
         // delete this line once every exercise of the lecture is done.\n\
         #![allow(unused_variables, unused_imports, dead_code, unused_mut)]\n",
    );
    out.push_str(&lines[after_docs..].concat());
    out
}

/// The workspace manifest without the members the handout leaves out.
fn drop_missing_members(text: &str, root: &Path) -> String {
    text.split_inclusive('\n')
        .filter(|line| {
            let t = line.trim().trim_end_matches(',');
            let member = t.trim_matches('"');
            !(t.starts_with('"') && LEFT_OUT.contains(&member) && root.join(member).is_dir())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const SOURCE: &str = "\
use raylab::Vec3;

/// Mirror `v` about `n`. Book: §5.2 Reflection. More text.
pub fn reflect(v: Vec3, n: Vec3) -> Vec3 {
    // SOLUTION BEGIN
    v - 2.0 * v.dot(n) * n
    // SOLUTION END
}

impl<'a> Bvh<'a> {
    /// The nearest hit.
    pub fn closest_hit(&self) -> u32 {
        // SOLUTION BEGIN
        1
        // SOLUTION END
    }
}
";

    #[test]
    fn solutions_become_todos_that_name_the_exercise_and_the_book() {
        let (stubbed, found) = stub_solutions(SOURCE, "05", "x.rs").unwrap();
        assert!(stubbed.contains("    todo!(\"05/reflect: Book: §5.2 Reflection\")\n"), "{stubbed}");
        assert!(stubbed.contains("        todo!(\"05/Bvh::closest_hit: Book: chapter 5\")\n"), "{stubbed}");
        assert!(!stubbed.contains("SOLUTION") && !stubbed.contains("v.dot(n)"));
        let ids: Vec<&str> = found.iter().map(|e| e.id.as_str()).collect();
        assert_eq!(ids, ["05/reflect", "05/Bvh::closest_hit"]);
        assert_eq!(found[0].line, 5);
    }

    #[test]
    fn unbalanced_markers_are_errors_that_name_the_line() {
        let open = "fn f() {\n    // SOLUTION BEGIN\n    1\n}\n";
        assert_eq!(stub_solutions(open, "01", "a.rs").unwrap_err(), "a.rs:2: SOLUTION BEGIN without an END");
        let close = "fn f() {\n    1\n    // SOLUTION END\n}\n";
        assert_eq!(stub_solutions(close, "01", "a.rs").unwrap_err(), "a.rs:3: SOLUTION END without a BEGIN");
        assert!(strip_instructor("# INSTRUCTOR BEGIN\nx\n", "C.toml").unwrap_err().contains("C.toml:1"));
    }

    #[test]
    fn instructor_regions_go_in_rust_and_toml() {
        let text = "a\n// INSTRUCTOR BEGIN\nsecret\n// INSTRUCTOR END\nb\n# INSTRUCTOR BEGIN\nhidden = []\n# INSTRUCTOR END\n";
        assert_eq!(strip_instructor(text, "x").unwrap(), "a\nb\n");
    }

    #[test]
    fn generated_lists_keep_their_lines_and_lose_their_markers() {
        // Lines of a string, each quoted: a marker at the start of a source line would itself
        // be taken out of this file's handout copy.
        let text = [
            "<!-- BEGIN GENERATED t: by `x` -->",
            "| a |",
            "<!-- END GENERATED t -->",
            "# BEGIN GENERATED f: by `x`",
            "l01 = []",
            "    // END GENERATED f",
            "b = 1\n",
        ]
        .join("\n");
        assert_eq!(strip_instructor(&text, "x").unwrap(), "| a |\nl01 = []\nb = 1\n");
    }

    #[test]
    fn fn_and_impl_names_are_read_from_rustfmt_lines() {
        assert_eq!(fn_name("pub fn hit_slabs(ray: &Ray) -> bool {").as_deref(), Some("hit_slabs"));
        assert_eq!(fn_name("    pub(crate) const fn at(&self) {").as_deref(), Some("at"));
        assert_eq!(fn_name("// fn not_this()"), None);
        assert_eq!(fn_name("let f = |x| x; // a closure, fn-less"), None);
        assert_eq!(impl_type("impl Intersector for Bvh<'_> {").as_deref(), Some("Bvh"));
        assert_eq!(impl_type("impl<'a> BruteForce<'a> {").as_deref(), Some("BruteForce"));
        assert_eq!(impl_type("impl PerspectiveCamera {").as_deref(), Some("PerspectiveCamera"));
    }

    /// Every region of the reference lectures names a distinct exercise.
    #[test]
    fn the_reference_lectures_have_distinct_exercise_ids() {
        let root = crate::workspace::own_root();
        let mut ids = std::collections::BTreeSet::new();
        for file in files(&root).unwrap() {
            let relative = file.strip_prefix(&root).unwrap().to_string_lossy().replace('\\', "/");
            if !(relative.starts_with("lectures/") && relative.ends_with(".rs")) {
                continue;
            }
            let text = std::fs::read_to_string(&file).unwrap();
            let (_, found) = stub_solutions(&text, &relative[9..11], &relative).unwrap();
            for exercise in found {
                assert!(ids.insert(exercise.id.clone()), "{} appears twice ({relative})", exercise.id);
            }
        }
        assert!(ids.len() >= 80, "{} exercises", ids.len());
    }
}

#[cfg(test)]
mod hint_tests {
    use super::*;
    use crate::workspace::{Workspace, own_root};

    /// A lecture's exercises, by their SOLUTION regions: `translate`, `Aabb::union`.
    fn lecture_exercises(
        root: &Path,
        lecture: &crate::workspace::Lecture,
    ) -> std::collections::BTreeSet<String> {
        let mut exercises = std::collections::BTreeSet::new();
        for file in files(&root.join("lectures").join(&lecture.folder).join("src")).unwrap() {
            let text = std::fs::read_to_string(&file).unwrap();
            let (_, found) = stub_solutions(&text, &lecture.number, &file.display().to_string()).unwrap();
            exercises.extend(found.into_iter().map(|e| e.id[3..].to_owned()));
        }
        exercises
    }

    /// `grader hint` reads `lectures/NN-*/hints.toml`: every exercise has
    /// hints, and every hint names an exercise of its lecture.
    #[test]
    fn every_exercise_has_hints_and_every_hint_an_exercise() {
        let root = own_root();
        let ws = Workspace::open(&root).unwrap();
        for lecture in &ws.lectures {
            let exercises = lecture_exercises(&root, lecture);
            let hints = ws.hints(&lecture.number).unwrap();
            let hinted: std::collections::BTreeSet<String> = hints.keys().cloned().collect();
            assert_eq!(
                hinted, exercises,
                "lecture {}: hints.toml keys against the exercises",
                lecture.number
            );
            for (name, list) in &hints {
                assert!((2..=4).contains(&list.len()), "{}/{name}: {} hints", lecture.number, list.len());
            }
        }
    }

    /// Each lecture's exercises (its SOLUTION regions) are the ones its README's
    /// "Exercises" table and its book chapter's "Exercises" table list: a new or
    /// renamed exercise that one of them misses fails here, naming the file.
    #[test]
    fn the_readme_and_the_chapter_list_the_lectures_exercises() {
        let root = own_root();
        let ws = Workspace::open(&root).unwrap();
        let mut problems = Vec::new();
        for lecture in &ws.lectures {
            let exercises = lecture_exercises(&root, lecture);
            for place in
                [format!("lectures/{}/README.md", lecture.folder), format!("book/src/{}.md", lecture.folder)]
            {
                let text = std::fs::read_to_string(root.join(&place)).unwrap_or_default();
                let Some(listed) = crate::workspace::exercise_table(&text, "## Exercises") else {
                    problems.push(format!("{place}: no \"## Exercises\" table with a function column"));
                    continue;
                };
                let listed: std::collections::BTreeSet<String> = listed.into_iter().collect();
                let missing: Vec<_> = exercises.difference(&listed).collect();
                let extra: Vec<_> = listed.difference(&exercises).collect();
                if !missing.is_empty() || !extra.is_empty() {
                    problems.push(format!("{place}: missing {missing:?}, not exercises {extra:?}"));
                }
            }
        }
        assert!(problems.is_empty(), "{}", problems.join("\n"));
    }

    /// The README's "Exercises, in order" and the chapter's "Exercises" table are one list: the
    /// same functions in the same order (the order the grade reads in and `next:` follows).
    #[test]
    fn the_readme_and_the_chapter_list_the_exercises_in_one_order() {
        let root = own_root();
        let ws = Workspace::open(&root).unwrap();
        let mut problems = Vec::new();
        for lecture in &ws.lectures {
            let readme = ws.exercise_order(&lecture.number);
            let chapter_file = format!("book/src/{}.md", lecture.folder);
            let text = std::fs::read_to_string(root.join(&chapter_file)).unwrap_or_default();
            let chapter = crate::workspace::exercise_table(&text, "## Exercises").unwrap_or_default();
            if let Some(problem) = order_problem(&readme, &chapter) {
                problems
                    .push(format!("lectures/{}/README.md against {chapter_file}: {problem}", lecture.folder));
            }
        }
        assert!(problems.is_empty(), "{}", problems.join("\n"));
        // A planted drift: two rows swapped in one table.
        let swapped = ["translate", "rotate_x", "scale"].map(String::from);
        let said = order_problem(&["translate", "scale", "rotate_x"].map(String::from), &swapped);
        assert_eq!(said.as_deref(), Some("row 2 is `scale` in one, `rotate_x` in the other"));
    }

    /// Where two lists of exercises first differ, if they do.
    fn order_problem(a: &[String], b: &[String]) -> Option<String> {
        if let Some(i) = a.iter().zip(b).position(|(x, y)| x != y) {
            return Some(format!("row {} is `{}` in one, `{}` in the other", i + 1, a[i], b[i]));
        }
        (a.len() != b.len()).then(|| format!("{} rows against {}", a.len(), b.len()))
    }

    /// Every "Book: §N.M" of the lectures' and the kit's code names a section
    /// heading ("## N.M …") of the book.
    #[test]
    fn every_book_reference_in_the_code_names_a_heading() {
        let root = own_root();
        let mut headings = std::collections::BTreeSet::new();
        for entry in std::fs::read_dir(root.join("book/src")).unwrap() {
            let text = std::fs::read_to_string(entry.unwrap().path()).unwrap_or_default();
            for line in text.lines().filter(|l| l.starts_with("##")) {
                if let Some(number) = line.trim_start_matches('#').split_whitespace().next() {
                    headings.insert(number.to_owned());
                }
            }
        }
        let mut files_read = files(&root.join("lectures")).unwrap();
        files_read.extend(files(&root.join("crates/raylab/src")).unwrap());
        let (mut checked, mut problems) = (0, Vec::new());
        for file in files_read.iter().filter(|f| f.extension().is_some_and(|e| e == "rs")) {
            let text = std::fs::read_to_string(file).unwrap();
            for (n, line) in text.lines().enumerate().filter(|(_, l)| l.contains("Book: §")) {
                let after = &line[line.find("Book: §").unwrap()..];
                for reference in after.split('§').skip(1) {
                    let number: String =
                        reference.chars().take_while(|c| c.is_ascii_digit() || *c == '.').collect();
                    let number = number.trim_end_matches('.');
                    checked += 1;
                    if !headings.contains(number) {
                        problems.push(format!(
                            "{}:{}: §{number} is no heading of the book",
                            file.display(),
                            n + 1
                        ));
                    }
                }
            }
        }
        assert!(checked >= 100, "{checked} references");
        assert!(problems.is_empty(), "{}", problems.join("\n"));
    }
}
