//! The workspace the grader grades: its root, its lectures and how they
//! depend on one another (read from their Cargo.toml files, so a lecture
//! that does not compile still has a name and a place), and their hints.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// One lecture crate.
#[derive(Clone, Debug)]
pub struct Lecture {
    /// `07`.
    pub number: String,
    /// `07-reflection-refraction`.
    pub folder: String,
    /// The cargo package, `l07-reflection-refraction`.
    pub package: String,
    /// The chapter's title, `Reflection and refraction` (`[package.metadata.raylab]`).
    #[allow(dead_code)] // read by `grader dev sync`, which the handout leaves out
    pub title: String,
    /// What a student writes in it, a line for the README and the book's tables.
    #[allow(dead_code)] // read by `grader dev sync`, which the handout leaves out
    pub summary: String,
    /// The lectures it uses directly: its crate's, and those its checks draw with
    /// (`stage-uses`: 05's stage draws with 04's intersections).
    pub uses: BTreeSet<String>,
}

/// The lectures of a workspace, and what each uses, read from their
/// Cargo.toml files: the course's manifest is the lecture crates themselves
/// (number and name from the folder, the lectures it uses from
/// `[dependencies]`, the rest from `[package.metadata.raylab]`). The lists
/// that Cargo and mdBook cannot derive are written from it by `grader dev sync`.
#[derive(Clone, Debug)]
pub struct Workspace {
    pub root: PathBuf,
    pub lectures: Vec<Lecture>,
}

/// The workspace this grader was built in: it lives in `<root>/grader`.
pub fn own_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("the grader has a parent folder").to_owned()
}

impl Workspace {
    /// Reads `root/lectures/NN-*/Cargo.toml`.
    pub fn open(root: &Path) -> Result<Self, String> {
        let dir = root.join("lectures");
        let mut lectures = Vec::new();
        let entries = std::fs::read_dir(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        let mut folders: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
        folders.sort();
        for folder in folders {
            let name = folder.file_name().unwrap_or_default().to_string_lossy().into_owned();
            let manifest = folder.join("Cargo.toml");
            if !manifest.is_file() || lecture_number(&name).is_none() {
                continue;
            }
            let text =
                std::fs::read_to_string(&manifest).map_err(|e| format!("{}: {e}", manifest.display()))?;
            let table: toml::Table = text.parse().map_err(|e| format!("{}: {e}", manifest.display()))?;
            let package = table
                .get("package")
                .and_then(|p| p.get("name"))
                .and_then(|n| n.as_str())
                .ok_or_else(|| format!("{}: no [package] name", manifest.display()))?
                .to_owned();
            let mut uses: BTreeSet<String> = table
                .get("dependencies")
                .and_then(|d| d.as_table())
                .map(|deps| deps.keys().filter_map(|k| lecture_number(k)).collect())
                .unwrap_or_default();
            let meta = Metadata::read(&table).map_err(|e| format!("{}: {e}", manifest.display()))?;
            uses.extend(meta.stage_uses);
            lectures.push(Lecture {
                number: lecture_number(&name).unwrap_or_default(),
                folder: name,
                package,
                title: meta.title,
                summary: meta.summary,
                uses,
            });
        }
        if lectures.is_empty() {
            return Err(format!("no lecture crates under {}", dir.display()));
        }
        for lecture in &lectures {
            if let Some(unknown) = lecture.uses.iter().find(|u| !lectures.iter().any(|l| &l.number == *u)) {
                return Err(format!(
                    "lectures/{}/Cargo.toml: uses lecture {unknown}, which is not under lectures/",
                    lecture.folder
                ));
            }
        }
        Ok(Self { root: root.to_owned(), lectures })
    }

    pub fn lecture(&self, number: &str) -> Option<&Lecture> {
        self.lectures.iter().find(|l| l.number == number)
    }

    /// The lecture whose package is `package`.
    pub fn by_package(&self, package: &str) -> Option<&Lecture> {
        self.lectures.iter().find(|l| l.package == package)
    }

    /// Lecture `number`'s exercises in course order: the function column of the "## Exercises"
    /// table of its README (the order its chapter's table repeats, tested, and the order the
    /// grade reads in and `next:` follows). Empty when the README has no such table.
    pub fn exercise_order(&self, number: &str) -> Vec<String> {
        let Some(lecture) = self.lecture(number) else { return Vec::new() };
        let readme = self.root.join("lectures").join(&lecture.folder).join("README.md");
        std::fs::read_to_string(readme)
            .ok()
            .and_then(|t| exercise_table(&t, "## Exercises"))
            .unwrap_or_default()
    }

    /// `number` and every lecture that uses it, directly or not.
    pub fn dependents(&self, number: &str) -> BTreeSet<String> {
        let mut found = BTreeSet::from([number.to_owned()]);
        loop {
            let more: Vec<String> = self
                .lectures
                .iter()
                .filter(|l| !found.contains(&l.number) && l.uses.iter().any(|u| found.contains(u)))
                .map(|l| l.number.clone())
                .collect();
            if more.is_empty() {
                return found;
            }
            found.extend(more);
        }
    }

    /// `number` and every lecture it uses, directly or not.
    pub fn prerequisites(&self, number: &str) -> BTreeSet<String> {
        let mut found = BTreeSet::from([number.to_owned()]);
        let mut stack = vec![number.to_owned()];
        while let Some(n) = stack.pop() {
            for used in self.lecture(&n).map(|l| l.uses.clone()).unwrap_or_default() {
                if found.insert(used.clone()) {
                    stack.push(used);
                }
            }
        }
        found
    }

    /// The lecture a source path belongs to (`lectures/07-…/src/x.rs`, absolute or not).
    pub fn lecture_of_path(&self, path: &str) -> Option<String> {
        let path = path.replace('\\', "/");
        self.lectures
            .iter()
            .find(|l| path.contains(&format!("lectures/{}/", l.folder)))
            .map(|l| l.number.clone())
    }

    /// The hints of lecture `number`: `lectures/NN-*/hints.toml`, a table of
    /// exercise name → list of hints, mildest first.
    pub fn hints(&self, number: &str) -> Result<BTreeMap<String, Vec<String>>, String> {
        let lecture = self.lecture(number).ok_or_else(|| format!("there is no lecture {number}"))?;
        let path = self.root.join("lectures").join(&lecture.folder).join("hints.toml");
        let text = match std::fs::read_to_string(&path) {
            Ok(text) => text,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(BTreeMap::new()),
            Err(e) => return Err(format!("{}: {e}", path.display())),
        };
        toml::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))
    }
}

/// A lecture's `[package.metadata.raylab]`.
#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct Metadata {
    title: String,
    summary: String,
    #[serde(default)]
    stage_uses: Vec<String>,
}

impl Metadata {
    fn read(table: &toml::Table) -> Result<Self, String> {
        let meta = table.get("package").and_then(|p| p.get("metadata")).and_then(|m| m.get("raylab")).ok_or(
            "no [package.metadata.raylab] (its title and summary: ARCHITECTURE.md, \"Adding a lecture\")",
        )?;
        let meta: Self = meta
            .clone()
            .try_into()
            .map_err(|e: toml::de::Error| format!("[package.metadata.raylab]: {}", e.message()))?;
        if let Some(bad) =
            meta.stage_uses.iter().find(|n| n.len() != 2 || !n.bytes().all(|b| b.is_ascii_digit()))
        {
            return Err(format!(
                "[package.metadata.raylab] stage-uses: {bad:?} is not a lecture number such as \"04\""
            ));
        }
        Ok(meta)
    }
}

/// `07` from `07-reflection-refraction` or `l07-reflection-refraction`.
fn lecture_number(name: &str) -> Option<String> {
    let digits = name.strip_prefix('l').unwrap_or(name);
    let number: String = digits.chars().take(2).collect();
    (number.len() == 2 && number.chars().all(|c| c.is_ascii_digit()) && digits[2..].starts_with('-'))
        .then_some(number)
}

/// The functions named in the first column headed "function" (or "exercise") of the table under
/// the first heading starting with `heading`, in the table's order, each once: backquoted names
/// before " — ", parenthesised notes left out.
pub fn exercise_table(text: &str, heading: &str) -> Option<Vec<String>> {
    let after = &text[text.find(heading)?..];
    let rows: Vec<&str> =
        after.lines().skip_while(|l| !l.starts_with('|')).take_while(|l| l.starts_with('|')).collect();
    let cells = |row: &str| -> Vec<String> {
        row.trim().trim_matches('|').split('|').map(|c| c.trim().to_owned()).collect()
    };
    let header = cells(rows.first()?);
    let column = header.iter().position(|h| ["function", "exercise"].contains(&h.to_lowercase().as_str()))?;
    let mut names: Vec<String> = Vec::new();
    for row in rows.iter().skip(2) {
        let mut cell = cells(row).get(column)?.split(" — ").next()?.to_owned();
        // Parenthesised notes ("(§1.2)", "(the body of `trace`)", "(p, n, dir, from)") are no names.
        while let (Some(open), Some(close)) = (cell.find('('), cell.find(')')) {
            if close < open {
                break;
            }
            cell.replace_range(open..=close, "");
        }
        for quoted in cell.split('`').skip(1).step_by(2) {
            let name: String =
                quoted.chars().take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':').collect();
            if !names.contains(&name) {
                names.push(name);
            }
        }
    }
    Some(names)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lectures_and_their_dependencies_come_from_the_manifests() {
        let ws = Workspace::open(&own_root()).unwrap();
        // Every folder under lectures/ with a Cargo.toml, in order.
        let mut folders: Vec<String> = std::fs::read_dir(own_root().join("lectures"))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.join("Cargo.toml").is_file())
            .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
            .collect();
        folders.sort();
        assert_eq!(ws.lectures.iter().map(|l| l.folder.clone()).collect::<Vec<_>>(), folders);
        assert!(folders.len() >= 10, "{folders:?}");
        assert_eq!(ws.lecture("07").unwrap().package, "l07-reflection-refraction");
        // 07 uses 05 only (its Cargo.toml and its checks' feature), so a compile error in 07
        // costs 07, 08 (which uses 07) and 10 (which uses 08), and leaves 09 and 01–06 standing.
        assert_eq!(ws.dependents("07"), BTreeSet::from(["07".into(), "08".into(), "10".into()]));
        // 05's crate uses 01; its checks draw with 04's intersections, which use 01–03.
        assert_eq!(ws.prerequisites("05"), ["01", "02", "03", "04", "05"].map(String::from).into());
        assert_eq!(ws.lecture_of_path("/x/lectures/03-polygons-triangles/src/slabs.rs"), Some("03".into()));
        assert_eq!(lecture_number("l10-textures-sampling"), Some("10".into()));
        assert_eq!(lecture_number("raylab"), None);
    }
}
