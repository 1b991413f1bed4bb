//! `grader watch`: re-grades a lecture whenever one of its source files
//! changes. It builds only that lecture and those it uses, and runs only its
//! checks, its image checks included (each lecture's stage draws with that
//! lecture and earlier ones), so a verdict and a picture come back in seconds.

use std::collections::BTreeMap;
use std::path::PathBuf;
use std::time::{Duration, SystemTime};

use crate::grade::{GradeOptions, Selection, grade};
use crate::output::table;
use crate::workspace::Workspace;

/// How often the sources are looked at.
const POLL: Duration = Duration::from_millis(400);

/// The modification time of every `.rs` file of every lecture's `src/`.
fn snapshot(ws: &Workspace) -> BTreeMap<PathBuf, (String, SystemTime)> {
    let mut times = BTreeMap::new();
    for lecture in &ws.lectures {
        let mut stack = vec![ws.root.join("lectures").join(&lecture.folder).join("src")];
        while let Some(dir) = stack.pop() {
            let Ok(entries) = std::fs::read_dir(&dir) else { continue };
            for entry in entries.flatten() {
                let path = entry.path();
                if path.is_dir() {
                    stack.push(path);
                } else if let Ok(modified) = entry.metadata().and_then(|m| m.modified()) {
                    times.insert(path, (lecture.number.clone(), modified));
                }
            }
        }
    }
    times
}

pub fn watch(ws: &Workspace, mut options: GradeOptions) -> Result<bool, String> {
    options.only_prerequisites = true;
    let mut seen = snapshot(ws);
    println!("watching lectures/*/src for changes (Ctrl-C to stop)");
    loop {
        std::thread::sleep(POLL);
        let now = snapshot(ws);
        let changed: Vec<String> = now
            .iter()
            .filter(|(path, (_, time))| seen.get(*path).is_none_or(|(_, old)| old != time))
            .map(|(_, (lecture, _))| lecture.clone())
            .chain(
                seen.keys()
                    .filter(|p| !now.contains_key(*p))
                    .filter_map(|p| ws.lecture_of_path(&p.to_string_lossy())),
            )
            .collect();
        seen = now;
        // The latest lecture touched: editing 05 re-grades 05.
        let Some(lecture) = changed.into_iter().max() else { continue };
        options.selection = Selection::parse(&[&lecture])?;
        println!("\n=== lecture {lecture} changed: grading it");
        match grade(ws, &options) {
            Ok(g) => {
                print!("{}", table(ws, &g));
                // The lecture's pictures (expected, yours, difference) in the report.
                match crate::report::write(ws, &g, &crate::grade::out_dir(ws, &options)) {
                    Ok(path) => println!("report: {}", path.display()),
                    Err(e) => eprintln!("the report could not be written: {e}"),
                }
            }
            Err(e) => eprintln!("error: {e}"),
        }
    }
}
