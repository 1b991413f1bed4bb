// INSTRUCTOR ONLY: left out of the handout (students do not add lectures).
//! `grader dev sync`: writes the lists of lectures that a tool cannot read
//! from the course's manifest (the lecture crates' `Cargo.toml`, read by
//! [`Workspace::open`]): Cargo's features and dependencies of the checks and
//! of the book's doctests, the checks' table of lectures, mdBook's SUMMARY,
//! and the tables of the README and the book's introduction.
//!
//! Each list is a region of a hand-written file, between a `BEGIN GENERATED`
//! line that names the region and says what writes it, and an `END
//! GENERATED` line; the rest of the file is left alone. `grader dev sync
//! --check` (and the test below, which CI runs) fails naming every stale
//! region and the command that rewrites it.

use std::path::Path;

use crate::workspace::{Lecture, Workspace};

/// The command that rewrites the regions, as the messages give it.
pub const COMMAND: &str = "cargo run -p grader -- dev sync";

/// One generated region: the file (relative to the root), its name, its lines.
struct Region {
    file: String,
    name: &'static str,
    text: String,
}

/// Lecture `l`'s checks crate: its folder, relative to the root.
pub fn checks_crate(l: &Lecture) -> String {
    format!("grader/checks/lectures/l{}", l.number)
}

/// The manifest `grader dev sync` writes for a lecture's checks crate that has none (a new
/// lecture's): the package, and the regions it fills; the rest is the instructors' to edit.
fn checks_manifest(l: &Lecture) -> String {
    let n = &l.number;
    format!(
        "[package]\nname = \"raylab-checks-l{n}\"\nversion = \"0.1.0\"\n\
         description = \"Lecture {n}'s checks, and the code it lends the stages.\"\n\
         edition.workspace = true\nrust-version.workspace = true\nlicense.workspace = true\n\
         publish.workspace = true\n\n\
         # `l{n}`: the checks' code, with the lecture and the checks of the lectures it uses; without it\n\
         # (the grader's build where the lecture does not compile) their declarations alone.\n\
         [features]\ndefault = [\"l{n}\"]\n# BEGIN GENERATED features:\n# END GENERATED features\n\n\
         [dependencies]\nraylab.workspace = true\nraylab-checks-core.workspace = true\n\
         raylab-testing.workspace = true\n\
         # BEGIN GENERATED dependencies:\n# END GENERATED dependencies\n\n[lints]\nworkspace = true\n"
    )
}

/// Every region's text, from the manifest.
fn regions(ws: &Workspace) -> Vec<Region> {
    let lectures = &ws.lectures;
    let region = |file: &str, name, text: String| Region { file: file.to_owned(), name, text };
    let feature = |l: &Lecture| format!("l{}", l.number);
    let mut regions = vec![
        region(
            "grader/checks/Cargo.toml",
            "features",
            std::iter::once("default = [\"complete\", \"tools\"]\n".to_owned())
                .chain(std::iter::once(format!(
                    "# Every lecture built (the grader adds it then): the complete tracer and the final \
                     images.\ncomplete = [{}]\n",
                    quoted(lectures.iter().map(feature))
                )))
                .chain(lectures.iter().map(|l| {
                    let mut enables: Vec<String> = l.uses.iter().map(|n| format!("l{n}")).collect();
                    enables.push(format!("raylab-checks-l{0}/l{0}", l.number));
                    format!("{} = [{}]\n", feature(l), quoted(enables))
                }))
                .chain(std::iter::once(format!(
                    "# The tools on the complete tracer (`render`, `bless`, `bench-rays`, and the instructors'\n\
                     # `tradeoffs`): `grader render` and the others build them, and so does a submission's build\n\
                     # (made once); a local grade does not, so that the binary a student's edit relinks holds\n\
                     # only what grades.\ntools = [\"complete\", \"dep:plotters\", {}]\n",
                    quoted(lectures.iter().map(|l| format!("dep:{}", l.package)))
                )))
                .collect(),
        ),
        region(
            "grader/checks/Cargo.toml",
            "dependencies",
            lectures
                .iter()
                .map(|l| format!("raylab-checks-l{0} = {{ path = \"lectures/l{0}\", default-features = false }}\n", l.number))
                .chain(lectures.iter().map(|l| {
                    format!("{} = {{ path = \"../../lectures/{}\", optional = true }}\n", l.package, l.folder)
                }))
                .collect(),
        ),
        region(
            "grader/checks/src/lectures/mod.rs",
            "modules",
            lectures.iter().map(|l| format!("pub use raylab_checks_l{0} as l{0};\n", l.number)).collect(),
        ),
        region(
            "grader/checks/src/lectures/mod.rs",
            "lectures",
            lectures
                .iter()
                .map(|l| {
                    let n = &l.number;
                    format!("        lecture!(\"{n}\", l{n}, \"l{n}\"),\n")
                })
                .collect(),
        ),
        region(
            "Cargo.toml",
            "checks-members",
            lectures.iter().map(|l| format!("    \"{}\",\n", checks_crate(l))).collect(),
        ),
        region(
            "Cargo.toml",
            "checks-profiles",
            lectures
                .iter()
                .map(|l| {
                    format!(
                        "[profile.dev.package.raylab-checks-l{}]\nopt-level = 0\ndebug = \"line-tables-only\"\n\
                         codegen-units = 16\n",
                        l.number
                    )
                })
                .collect(),
        ),
        region(
            "book/doctests/Cargo.toml",
            "dependencies",
            lectures
                .iter()
                .map(|l| format!("{} = {{ path = \"../../lectures/{}\" }}\n", l.package, l.folder))
                .collect(),
        ),
        region(
            "book/doctests/src/lib.rs",
            "chapters",
            lectures
                .iter()
                .map(|l| {
                    let module = l.folder.replace('-', "_");
                    format!("#[doc = include_str!(\"../../src/{}.md\")]\npub mod ch{module} {{}}\n", l.folder)
                })
                .collect::<Vec<_>>()
                .join("\n"),
        ),
        region(
            "book/src/SUMMARY.md",
            "chapters",
            lectures.iter().map(|l| format!("- [{} {}]({}.md)\n", chapter(l), l.title, l.folder)).collect(),
        ),
        region(
            "book/src/introduction.md",
            "lectures",
            std::iter::once("| folder | chapter | what you write |\n|---|---|---|\n".to_owned())
                .chain(lectures.iter().map(|l| {
                    format!(
                        "| `lectures/{}` | [{}]({}.md) | {} |\n",
                        l.folder,
                        chapter(l),
                        l.folder,
                        l.summary
                    )
                }))
                .collect(),
        ),
        region(
            "README.md",
            "lectures",
            std::iter::once("| lecture | chapter | what it teaches |\n|---|---|---|\n".to_owned())
                .chain(lectures.iter().map(|l| {
                    format!(
                        "| [`lectures/{}`](lectures/{}) | [{} {}](book/src/{}.md) | {} |\n",
                        l.folder,
                        l.folder,
                        chapter(l),
                        l.title,
                        l.folder,
                        l.summary
                    )
                }))
                .collect(),
        ),
    ];
    // Each lecture's checks crate: with its feature, the lecture and every lecture it uses, directly
    // or not, and their checks (a stage draws with the earlier stages' code).
    for l in lectures {
        let used: Vec<&Lecture> = ws
            .prerequisites(&l.number)
            .iter()
            .filter(|n| **n != l.number)
            .filter_map(|n| ws.lecture(n))
            .collect();
        let file = format!("{}/Cargo.toml", checks_crate(l));
        let mut enables = vec![format!("dep:{}", l.package)];
        enables.extend(used.iter().map(|u| format!("dep:{}", u.package)));
        enables.extend(used.iter().map(|u| format!("raylab-checks-l{0}/l{0}", u.number)));
        regions.push(region(&file, "features", format!("l{} = [{}]\n", l.number, quoted(enables))));
        let lecture = |u: &Lecture| {
            format!("{} = {{ path = \"../../../../lectures/{}\", optional = true }}\n", u.package, u.folder)
        };
        let dependencies = std::iter::once(lecture(l))
            .chain(used.iter().map(|u| lecture(u)))
            .chain(used.iter().map(|u| {
                format!(
                    "raylab-checks-l{0} = {{ path = \"../l{0}\", optional = true, default-features = false }}\n",
                    u.number
                )
            }))
            .collect();
        regions.push(region(&file, "dependencies", dependencies));
    }
    regions
}

/// The chapter's number as the book writes it: `7`, `10`.
fn chapter(l: &Lecture) -> &str {
    l.number.trim_start_matches('0')
}

/// `"a", "b"`.
fn quoted(items: impl IntoIterator<Item = String>) -> String {
    items.into_iter().map(|i| format!("\"{i}\"")).collect::<Vec<_>>().join(", ")
}

/// A file's comment delimiters, by its extension.
fn comment(file: &str) -> (&'static str, &'static str) {
    match file.rsplit('.').next() {
        Some("rs") => ("// ", ""),
        Some("md") => ("<!-- ", " -->"),
        _ => ("# ", ""),
    }
}

/// `text` with region `name`'s lines replaced by `lines`; an error names the
/// file and what is missing.
fn replace_region(file: &str, text: &str, name: &str, lines: &str) -> Result<String, String> {
    let (open, close) = comment(file);
    let begin_tag = format!("BEGIN GENERATED {name}:");
    let end_tag = format!("END GENERATED {name}");
    let begin = text.find(&begin_tag).ok_or_else(|| {
        format!(
            "{file}: no line `{open}{begin_tag} …{close}` for the region `{name}` that `{COMMAND}` writes"
        )
    })?;
    let line_start = |at: usize| text[..at].rfind('\n').map_or(0, |i| i + 1);
    let after_begin = text[begin..].find('\n').map_or(text.len(), |i| begin + i + 1);
    let end = text[after_begin..].find(&end_tag).map(|i| line_start(after_begin + i)).ok_or_else(|| {
        format!("{file}: the region `{name}` has no line `{open}{end_tag}{close}` after its start")
    })?;
    if text[end..].contains(&begin_tag) {
        return Err(format!("{file}: the region `{name}` is there twice"));
    }
    let begin_line = line_start(begin);
    let indent: String = text[begin_line..].chars().take_while(|c| *c == ' ').collect();
    Ok(format!(
        "{}{indent}{open}{begin_tag} written by `{COMMAND}` from lectures/*/Cargo.toml; edit those, not \
         this.{close}\n{lines}{}",
        &text[..begin_line],
        &text[end..]
    ))
}

/// A file whose generated regions differ from the manifest.
struct Stale {
    file: String,
    /// The regions that differ.
    regions: Vec<&'static str>,
    /// The file with every region rewritten.
    text: String,
}

/// The files whose regions are not what the manifest writes.
fn stale(ws: &Workspace) -> Result<Vec<Stale>, String> {
    let mut files: Vec<(Stale, String)> = Vec::new();
    for region in regions(ws) {
        if !files.iter().any(|(f, _)| f.file == region.file) {
            let path = ws.root.join(&region.file);
            // A new lecture's checks crate gets its manifest written, regions and all.
            let new = ws.lectures.iter().find(|l| region.file == format!("{}/Cargo.toml", checks_crate(l)));
            let (text, old) = match (std::fs::read_to_string(&path), new) {
                (Ok(text), _) => (text.clone(), text),
                (Err(e), Some(l)) if e.kind() == std::io::ErrorKind::NotFound => {
                    (checks_manifest(l), String::new())
                }
                (Err(e), _) => return Err(format!("{}: {e}", path.display())),
            };
            files.push((Stale { file: region.file.clone(), regions: Vec::new(), text }, old));
        }
        let (file, _) = files.iter_mut().find(|(f, _)| f.file == region.file).expect("pushed above");
        let text = replace_region(&region.file, &file.text, region.name, &region.text)?;
        if text != file.text {
            file.regions.push(region.name);
            file.text = text;
        }
    }
    Ok(files.into_iter().filter(|(new, old)| new.text != *old).map(|(new, _)| new).collect())
}

/// `grader dev sync`: rewrites the stale regions (or, with `check`, names them
/// and fails). `Ok(true)` when everything is, or now is, in step.
pub fn sync(root: &Path, check: bool) -> Result<bool, String> {
    let ws = Workspace::open(root)?;
    let stale = stale(&ws)?;
    for Stale { file, regions, text } in &stale {
        if check {
            eprintln!("{file}: stale: {}", regions.join(", "));
        } else {
            let path = root.join(file);
            if let Some(parent) = path.parent() {
                std::fs::create_dir_all(parent).map_err(|e| format!("{}: {e}", parent.display()))?;
            }
            std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
            println!("{file}: rewrote {}", regions.join(", "));
        }
    }
    if check && !stale.is_empty() {
        eprintln!("the lists above differ from the lectures' Cargo.toml: run `{COMMAND}`");
        return Ok(false);
    }
    if !check && stale.is_empty() {
        println!("every generated list is in step with lectures/*/Cargo.toml");
    }
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::workspace::own_root;

    #[test]
    fn the_generated_lists_are_in_step_with_the_lectures() {
        let ws = Workspace::open(&own_root()).unwrap();
        let stale = stale(&ws).unwrap();
        let names: Vec<String> =
            stale.iter().map(|s| format!("{} ({})", s.file, s.regions.join(", "))).collect();
        assert!(
            stale.is_empty(),
            "stale lists of lectures: {}; run `{COMMAND}`, which rewrites them from lectures/*/Cargo.toml",
            names.join("; ")
        );
    }

    #[test]
    fn a_region_is_replaced_between_its_lines_and_nothing_else_moves() {
        let text = "a = 1\n  # BEGIN GENERATED list: old words\nold\n  # END GENERATED list\nb = 2\n";
        let new = replace_region("x.toml", text, "list", "one\ntwo\n").unwrap();
        assert_eq!(
            new,
            format!(
                "a = 1\n  # BEGIN GENERATED list: written by `{COMMAND}` from lectures/*/Cargo.toml; edit those, \
                 not this.\none\ntwo\n  # END GENERATED list\nb = 2\n"
            )
        );
        // Writing again changes nothing.
        assert_eq!(replace_region("x.toml", &new, "list", "one\ntwo\n").unwrap(), new);
        let md =
            replace_region("x.md", "<!-- BEGIN GENERATED t: -->\n<!-- END GENERATED t -->\n", "t", "| a |\n");
        assert_eq!(
            md.unwrap(),
            format!(
                "<!-- BEGIN GENERATED t: written by `{COMMAND}` from lectures/*/Cargo.toml; edit those, not \
                 this. -->\n| a |\n<!-- END GENERATED t -->\n"
            )
        );
    }

    #[test]
    fn a_missing_or_broken_region_is_named_with_its_file() {
        let missing = replace_region("grader/checks/Cargo.toml", "a = 1\n", "features", "").unwrap_err();
        assert!(
            missing.starts_with("grader/checks/Cargo.toml: no line `# BEGIN GENERATED features: …`"),
            "{missing}"
        );
        assert!(missing.contains(COMMAND), "{missing}");
        let open = replace_region("README.md", "<!-- BEGIN GENERATED t: x -->\n", "t", "").unwrap_err();
        assert_eq!(open, "README.md: the region `t` has no line `<!-- END GENERATED t -->` after its start");
    }
}
