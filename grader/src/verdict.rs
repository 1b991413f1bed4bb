//! From how a check's process ended to a verdict a student can act on.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::run::Ran;

use raylab_protocol::Outcome;
pub use raylab_protocol::{Failure, Info, Kind};

/// The verdicts a check can have (ARCHITECTURE.md, "How the grader grades").
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    Passed,
    Failed,
    NotStarted,
    /// It cannot pass before another exercise does: that one is not started,
    /// fails, or its lecture does not compile.
    Blocked,
    DoesNotCompile,
    Crashed,
    TimedOut,
}

impl Status {
    pub fn label(self) -> &'static str {
        match self {
            Self::Passed => "passed",
            Self::Failed => "FAILED",
            Self::NotStarted => "not started",
            Self::Blocked => "blocked",
            Self::DoesNotCompile => "does not compile",
            Self::Crashed => "CRASHED",
            Self::TimedOut => "TIMED OUT",
        }
    }
}

/// The verdict on one check.
#[derive(Clone, Debug, Serialize)]
pub struct Verdict {
    pub info: Info,
    pub status: Status,
    /// One line: what happened.
    pub summary: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub failure: Option<Failure>,
    /// The exercise it waits for (`02/hit_sphere_geometric`), when blocked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub needs: Option<String>,
    pub points: u32,
    pub seconds: f64,
    /// The end of what the check printed, when it did not pass.
    #[serde(skip_serializing_if = "String::is_empty")]
    pub output: String,
}

impl Verdict {
    pub fn new(info: Info, status: Status, summary: impl Into<String>) -> Self {
        let points = if status == Status::Passed { info.points } else { 0 };
        Self {
            info,
            status,
            summary: summary.into(),
            failure: None,
            needs: None,
            points,
            seconds: 0.0,
            output: String::new(),
        }
    }

    pub fn blocked(info: Info, needs: &str, summary: impl Into<String>) -> Self {
        Self { needs: Some(needs.to_owned()), ..Self::new(info, Status::Blocked, summary) }
    }
}

/// The exercise named by a handout's `todo!("NN/exercise: …")`, from the
/// panic message "not yet implemented: NN/exercise: …".
fn todo_exercise(message: &str) -> Option<String> {
    let rest = message.strip_prefix("not yet implemented")?;
    let rest = rest.strip_prefix(": ").unwrap_or("");
    // The id ends at ": " or a space; `::` inside it (a method) stays.
    let id = rest.split(": ").next().unwrap_or_default().split_whitespace().next().unwrap_or_default();
    let (lecture, exercise) = id.split_once('/')?;
    (lecture.len() == 2 && lecture.chars().all(|c| c.is_ascii_digit()) && !exercise.is_empty())
        .then(|| id.to_owned())
}

/// `0` for "not started" panics without an exercise id (a bare `todo!()`).
fn is_todo(message: &str) -> bool {
    message.starts_with("not yet implemented") || message.starts_with("not implemented")
}

/// Turns how the process ended into a verdict. `lecture_of_file` maps a
/// source path to its lecture number.
pub fn classify(info: Info, ran: &Ran, lecture_of_file: impl Fn(&str) -> Option<String>) -> Verdict {
    let written = ran.verdict.as_deref().and_then(|text| serde_json::from_str::<Outcome>(text).ok());
    let mut verdict = match (written, ran) {
        (_, Ran { timed_out: true, .. }) => Verdict::new(
            info.clone(),
            Status::TimedOut,
            format!(
                "stopped after {} s: an infinite loop, or a recursion that never reaches its base case?",
                info.timeout_s
            ),
        ),
        (_, Ran { too_much_output: true, .. }) => Verdict::new(
            info.clone(),
            Status::Crashed,
            format!(
                "stopped after printing more than {} MB: a print inside a loop?",
                crate::run::MAX_OUTPUT >> 20
            ),
        ),
        (Some(Outcome::Passed { detail, .. }), Ran { status: Some(s), .. }) if s.success() => {
            Verdict::new(info.clone(), Status::Passed, detail)
        }
        (Some(Outcome::Failed(failure)), Ran { status: Some(s), .. }) if s.success() => {
            let summary = if failure.case.is_empty() {
                failure.got.clone()
            } else {
                format!("{}: expected {}, got {}", failure.case, failure.expected, failure.got)
            };
            Verdict { failure: Some(failure), ..Verdict::new(info.clone(), Status::Failed, summary) }
        }
        (Some(Outcome::Panicked { message, file, line }), _) => {
            let where_ = format!("{file}:{line}");
            let lecture = lecture_of_file(&file);
            if is_todo(&message) {
                let exercise = todo_exercise(&message);
                let own = exercise.as_deref().map_or(lecture.as_deref() == Some(&info.lecture[..]), |e| {
                    e == info.exercise_id() || (info.kind == Kind::Image && e.starts_with(&info.lecture))
                });
                if own {
                    Verdict::new(info.clone(), Status::NotStarted, format!("todo!() at {where_}"))
                } else {
                    let needs =
                        exercise.unwrap_or_else(|| format!("{} ({where_})", lecture.unwrap_or_default()));
                    Verdict::blocked(
                        info.clone(),
                        &needs,
                        format!("needs {}: not started yet", pretty(&needs)),
                    )
                }
            } else {
                let hint = panic_hint(&message);
                Verdict::new(info.clone(), Status::Crashed, format!("panicked at {where_}: {message}{hint}"))
            }
        }
        (_, ran) => Verdict::new(info.clone(), Status::Crashed, abnormal_end(ran)),
    };
    verdict.seconds = ran.seconds;
    if verdict.status != Status::Passed {
        verdict.output = tail(&format!("{}{}", ran.stdout, ran.stderr), 2000);
    }
    verdict
}

/// The last `n` bytes of `text` (at a character boundary).
fn tail(text: &str, n: usize) -> String {
    let start = text.len().saturating_sub(n);
    let start = (start..=text.len()).find(|&i| text.is_char_boundary(i)).unwrap_or(text.len());
    text[start..].to_owned()
}

/// A hint for panics students meet often.
fn panic_hint(message: &str) -> &'static str {
    if message.contains("index out of bounds") {
        " (an index past the end: check the loop bounds and x < width, y < height)"
    } else if message.contains("attempt to subtract with overflow") || message.contains("overflow") {
        " (an integer went below 0 or past its maximum: check unsigned arithmetic)"
    } else if message.contains("called `Option::unwrap()` on a `None` value") {
        " (unwrap on None: return None instead, or handle the miss)"
    } else {
        ""
    }
}

/// Why a process without a verdict ended.
fn abnormal_end(ran: &Ran) -> String {
    let stderr = &ran.stderr;
    if stderr.contains("has overflowed its stack") {
        return "stack overflow: a recursion without a base case (a depth limit?)".into();
    }
    if let Some(at) = stderr.find("memory allocation of ") {
        let what: String = stderr[at..].lines().next().unwrap_or_default().into();
        return format!("ran out of memory ({what}): an allocation sized by a wrong or huge number?");
    }
    match ran.status {
        Some(s) if s.success() => {
            "the process ended before the check did (std::process::exit in the code?)".into()
        }
        Some(s) => match s.code() {
            Some(code) => {
                format!("the process exited with code {code} before the check finished (std::process::exit?)")
            }
            None => format!("the process was killed ({})", crate::platform::signal_name(s)),
        },
        None => "the process did not finish".into(),
    }
}

/// "02 hit_sphere_geometric" for `02/hit_sphere_geometric`.
pub fn pretty(exercise: &str) -> String {
    exercise.replacen('/', " ", 1)
}

/// Marks checks blocked whose declared `needs` did not all pass: their own
/// failure may be the other exercise's.
pub fn apply_needs(verdicts: &mut [Verdict]) {
    let mut exercise_ok: BTreeMap<String, bool> = BTreeMap::new();
    for v in verdicts.iter() {
        let ok = exercise_ok.entry(v.info.exercise_id()).or_insert(true);
        *ok &= v.status == Status::Passed;
    }
    for v in verdicts.iter_mut() {
        if !matches!(v.status, Status::Failed | Status::Crashed | Status::TimedOut) {
            continue;
        }
        if let Some(need) = v.info.needs.iter().find(|n| exercise_ok.get(*n) == Some(&false)) {
            let own = std::mem::take(&mut v.summary);
            v.summary = format!("needs {} to pass first (then: {own})", pretty(need));
            v.needs = Some(need.clone());
            v.status = Status::Blocked;
        }
    }
}

/// The declaration of a visible unit check `id` (`NN/exercise/name`) worth 2
/// points, built and with no needs: the driver's tests' fixture.
#[cfg(test)]
pub fn test_info(id: &str) -> Info {
    let mut parts = id.split('/');
    Info {
        id: id.into(),
        lecture: parts.next().unwrap().into(),
        exercise: parts.next().unwrap().into(),
        kind: Kind::Unit,
        points: 2,
        needs: vec![],
        about: String::new(),
        hidden: false,
        timeout_s: 10,
        available: true,
        judged: false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn info(id: &str) -> Info {
        test_info(id)
    }

    #[test]
    fn a_todo_names_its_exercise() {
        assert_eq!(
            todo_exercise("not yet implemented: 02/hit_sphere_geometric: Book §2.3").as_deref(),
            Some("02/hit_sphere_geometric")
        );
        assert_eq!(
            todo_exercise("not yet implemented: 01/PerspectiveCamera::generate_ray: Book §1.7").as_deref(),
            Some("01/PerspectiveCamera::generate_ray")
        );
        assert_eq!(todo_exercise("not yet implemented"), None);
        assert!(is_todo("not implemented: x") && !is_todo("index out of bounds"));
    }

    #[test]
    fn failed_needs_block_the_checks_that_declare_them() {
        let mut a = Verdict::new(info("02/hit_sphere_stable/unit"), Status::Failed, "wrong t");
        a.points = 0;
        let mut b = Verdict::new(info("02/closest_hit/unit"), Status::Failed, "wrong object");
        b.info.needs = vec!["02/hit_sphere_stable".into()];
        let c = Verdict::new(info("02/hit_plane/unit"), Status::Passed, "ok");
        let mut all = vec![a, b, c];
        apply_needs(&mut all);
        assert_eq!(all[0].status, Status::Failed);
        assert_eq!(all[1].status, Status::Blocked);
        assert_eq!(all[1].needs.as_deref(), Some("02/hit_sphere_stable"));
        assert!(all[1].summary.starts_with("needs 02 hit_sphere_stable to pass first"), "{}", all[1].summary);
        assert_eq!((all[2].status, all[2].points), (Status::Passed, 2));
    }
}
