//! The grade as a table for the terminal, as JSON, and as Gradescope's
//! `results.json`.

use std::collections::BTreeMap;
use std::fmt::Write;

use serde_json::{Value, json};

use crate::grade::Grade;
use crate::verdict::{Status, Verdict};
use crate::workspace::Workspace;

/// The terminal table: one block per lecture, a line per check, and under
/// each check that did not pass what was expected, what came and the likely
/// cause. A lecture with nothing started is one line.
pub fn table(ws: &Workspace, grade: &Grade) -> String {
    let mut text = String::new();
    let mut by_lecture: BTreeMap<&str, Vec<&Verdict>> = BTreeMap::new();
    for v in &grade.verdicts {
        by_lecture.entry(&v.info.lecture).or_default().push(v);
    }
    let width = grade.verdicts.iter().map(|v| v.info.short().chars().count()).max().unwrap_or(20).min(48);
    for (lecture, verdicts) in &by_lecture {
        let folder = ws.lecture(lecture).map_or_else(|| lecture.to_string(), |l| l.folder.clone());
        let got: u32 = verdicts.iter().map(|v| v.points).sum();
        let max: u32 = verdicts.iter().map(|v| v.info.points).sum();
        let _ = writeln!(text, "\n{folder:<width$}  {:>13}  {got:>3}/{max}", "", width = width + 2);
        let untouched = |v: &&Verdict| matches!(v.status, Status::NotStarted | Status::Blocked);
        if verdicts.iter().all(untouched) && verdicts.iter().any(|v| v.status == Status::NotStarted) {
            let _ =
                writeln!(text, "  {:<width$}  nothing started yet", format!("({} checks)", verdicts.len()));
            continue;
        }
        if verdicts.iter().all(|v| v.status == Status::DoesNotCompile) {
            let _ = writeln!(text, "  {:<width$}  does not compile", format!("({} checks)", verdicts.len()));
            let _ = writeln!(text, "      {}", verdicts[0].summary);
            continue;
        }
        for v in verdicts {
            let _ = writeln!(
                text,
                "  {:<width$}  {:<13}  {:>3}/{}",
                v.info.short(),
                v.status.label(),
                v.points,
                v.info.points
            );
            match v.status {
                Status::Passed | Status::NotStarted => {}
                Status::Failed => {
                    if let Some(f) = &v.failure {
                        let _ = writeln!(text, "      case:     {}", f.case);
                        let _ = writeln!(text, "      expected: {}", f.expected);
                        let _ = writeln!(text, "      got:      {}", f.got);
                        if !f.cause.is_empty() {
                            let _ = writeln!(text, "      likely:   {}", f.cause);
                        }
                        if let Some(images) = &f.images {
                            let _ = writeln!(
                                text,
                                "      images:   {} (and expected.png, yours.png)",
                                images.diff
                            );
                        }
                    } else {
                        let _ = writeln!(text, "      {}", v.summary);
                    }
                }
                _ => {
                    let _ = writeln!(text, "      {}", v.summary);
                }
            }
        }
    }
    let (got, max) = grade.points();
    let count = |s: Status| grade.verdicts.iter().filter(|v| v.status == s).count();
    let _ = writeln!(
        text,
        "\ntotal {got}/{max} points: {} passed, {} failed, {} not started, {} blocked, {} do not compile, {} crashed, \
         {} timed out ({:.1} s)",
        count(Status::Passed),
        count(Status::Failed),
        count(Status::NotStarted),
        count(Status::Blocked),
        count(Status::DoesNotCompile),
        count(Status::Crashed),
        count(Status::TimedOut),
        grade.seconds
    );
    text.push_str(&crate::progress::text(&crate::progress::progress(ws, grade)));
    text
}

/// The grade as JSON: totals, compile errors, progress (the next exercise) and every verdict.
pub fn json(ws: &Workspace, grade: &Grade) -> Value {
    let (got, max) = grade.points();
    let errors: Vec<Value> = grade
        .compile_errors
        .iter()
        .map(|(lecture, e)| json!({"lecture": lecture, "location": e.location, "message": e.message, "in_checks": e.in_checks}))
        .collect();
    json!({
        "score": got,
        "max_score": max,
        "all_passed": grade.all_passed(),
        "compile_errors": errors,
        "progress": crate::progress::progress(ws, grade),
        "checks": grade.verdicts,
    })
}

/// Gradescope's `results.json`: the score, and one test per check with its
/// output; hidden checks are shown to students after the grades are published.
pub fn gradescope(grade: &Grade) -> Value {
    let (got, _) = grade.points();
    let tests: Vec<Value> = grade
        .verdicts
        .iter()
        .map(|v| {
            let mut output = format!("{}: {}\n", v.status.label(), v.summary);
            if let Some(f) = &v.failure {
                let _ =
                    write!(output, "expected: {}\ngot: {}\nlikely cause: {}\n", f.expected, f.got, f.cause);
            }
            json!({
                "name": format!("{} {}", v.info.lecture, v.info.short()),
                "name_format": "text",
                "score": v.points,
                "max_score": v.info.points,
                "status": if v.status == Status::Passed { "passed" } else { "failed" },
                "output": output,
                "output_format": "text",
                "visibility": if v.info.hidden { "after_published" } else { "visible" },
            })
        })
        .collect();
    let mut summary = String::new();
    for (lecture, e) in &grade.compile_errors {
        let _ = writeln!(summary, "lecture {lecture} does not compile: {} at {}", e.message, e.location);
    }
    json!({
        "score": got,
        "output": summary,
        "output_format": "text",
        "stdout_visibility": "visible",
        "tests": tests,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verdict::{Failure, Info, test_info};

    fn verdict(id: &str, status: Status, hidden: bool) -> Verdict {
        Verdict::new(Info { hidden, ..test_info(id) }, status, "summary")
    }

    /// The fields Gradescope reads (its autograder specification): a total
    /// `score`, and per test `name`, `score`, `max_score`, `output`, `visibility`.
    #[test]
    fn gradescope_results_carry_scores_outputs_and_hidden_visibility() {
        let mut failed = verdict("02/hit_plane/unit", Status::Failed, false);
        failed.failure = Some(Failure {
            case: "a ray".into(),
            expected: "t = 4".into(),
            got: "t = 6".into(),
            cause: "the far root".into(),
            images: None,
        });
        let grade = Grade {
            verdicts: vec![
                verdict("02/hit_sphere_stable/unit", Status::Passed, false),
                failed,
                verdict("02/hit_sphere_stable/hidden-off-axis", Status::Passed, true),
            ],
            compile_errors: vec![],
            seconds: 1.0,
        };
        let results = gradescope(&grade);
        assert_eq!(results["score"], 4);
        let tests = results["tests"].as_array().unwrap();
        assert_eq!(tests.len(), 3);
        assert_eq!(tests[0]["name"], "02 hit_sphere_stable/unit");
        assert_eq!((tests[0]["score"].as_u64(), tests[0]["max_score"].as_u64()), (Some(2), Some(2)));
        assert_eq!((tests[1]["score"].as_u64(), tests[1]["status"].as_str()), (Some(0), Some("failed")));
        let output = tests[1]["output"].as_str().unwrap();
        assert!(
            output.contains("expected: t = 4") && output.contains("likely cause: the far root"),
            "{output}"
        );
        assert_eq!(tests[0]["visibility"], "visible");
        assert_eq!(tests[2]["visibility"], "after_published");
    }
}
