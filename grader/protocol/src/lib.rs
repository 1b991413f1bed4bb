//! What the `grader` driver and the `raylab-checks` binary exchange, as JSON:
//! `raylab-checks list` prints every check's [`Info`]; `raylab-checks run ID
//! --verdict FILE` writes the check's [`Outcome`] to FILE. One definition for
//! both sides, so the two cannot drift apart.

use serde::{Deserialize, Serialize};

/// The 3D view of ray trees over a scene, a small hand-written WebGL module: the checks' pages
/// (`grader render SCENE --tree X,Y --view FILE`) and the grader's report draw with it.
pub const VIEW3D_SCRIPT: &str = include_str!("../assets/view3d.js");

/// The 3D view's styles, for the same pages.
pub const VIEW3D_STYLE: &str = include_str!("../assets/view3d.css");

/// The first line a judge prints: this, then the loopback address the
/// subject is to connect to (`raylab-checks run ID --channel ADDR`).
/// Both read their token from standard input first ([`token_line`]).
pub const JUDGE_LISTENING: &str = "listening ";

/// The first eight bytes a subject sends its judge: the token the driver gave them both
/// ([`token_line`]). A judge takes the connection that sends it for the subject's, and no other: a
/// connection meant for an earlier judge whose loopback port this one was given is not mistaken
/// for its subject.
pub fn hello(token: u64) -> [u8; 8] {
    token.to_le_bytes()
}

/// How the driver hands a judge and its subject their token: on their standard input, as this
/// line (16 hex digits), never on a command line, which any process of the machine can read
/// under `/proc`.
pub fn token_line(token: u64) -> String {
    format!("{token:016x}\n")
}

/// Reads the token the driver wrote on standard input ([`token_line`]).
pub fn read_token(input: &mut impl std::io::BufRead) -> Result<u64, String> {
    let mut line = String::new();
    input.read_line(&mut line).map_err(|e| format!("the token on standard input: {e}"))?;
    u64::from_str_radix(line.trim(), 16).map_err(|_| "no token on standard input (16 hex digits)".to_owned())
}

/// What the driver sends a judge instead, once the subject has ended without connecting: the
/// judge stops waiting and ends with [`NO_VERDICT`].
pub fn no_subject(token: u64) -> [u8; 8] {
    (!token).to_le_bytes()
}

/// How a judge's verdict line starts: this, then the outcome as JSON.
pub const JUDGE_VERDICT: &str = "verdict ";

/// A judge's exit code when it writes no verdict: the subject's values ended
/// before the check did, and how the subject ended is the verdict.
pub const NO_VERDICT: i32 = 3;

/// What a failed scene's check writes beside its pictures for the report's 3D view (the checks
/// write it, the driver's report loads it): the view's data as a script, or why there is none.
pub const VIEW_DATA: &str = "view3d-data.js";
pub const VIEW_MISSING: &str = "view3d-missing.txt";

/// The kinds of check (ARCHITECTURE.md, "The exercise contract").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    /// Exact expectations with stated tolerances, at ordinary inputs.
    Unit,
    /// The stability cases of the lecture: far, tiny, grazing, degenerate.
    Extreme,
    /// A lecture scene rendered with the student's code against its snapshot.
    Image,
}

/// A check as `raylab-checks list` declares it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Info {
    /// `NN/exercise/name`.
    pub id: String,
    pub lecture: String,
    /// The function's name (`hit_slabs`, `PerspectiveCamera::generate_ray`), or
    /// `image`, `geometry`, `final` for scenes.
    pub exercise: String,
    pub kind: Kind,
    pub points: u32,
    /// Other exercises whose result this check relies on, as `NN/function`.
    pub needs: Vec<String>,
    /// What the check tests, in one line.
    pub about: String,
    /// Seen only by `grader grade --submission`.
    pub hidden: bool,
    /// Wall-clock seconds before the grader stops it.
    pub timeout_s: u32,
    /// Its code is in this build (its lecture compiled).
    pub available: bool,
    /// Graded as a submission, it is judged by a process that runs no student
    /// code (`raylab-checks judge`), the student's values sent to it by the
    /// process that runs them (`raylab-checks run --channel`).
    #[serde(default)]
    pub judged: bool,
}

impl Info {
    /// `exercise/name`, the id without the lecture.
    pub fn short(&self) -> &str {
        self.id.split_once('/').map_or(&self.id, |(_, rest)| rest)
    }

    /// `NN/exercise`.
    pub fn exercise_id(&self) -> String {
        format!("{}/{}", self.lecture, self.exercise)
    }
}

/// Images an image check wrote, relative to the workspace root.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Images {
    pub expected: String,
    pub yours: String,
    pub diff: String,
    /// Mean FLIP error of yours against expected (0 = identical, 1 = opposite).
    pub flip_mean: f64,
    /// The fraction of pixels whose FLIP error is above the image checks' threshold.
    pub flip_fraction_over: f64,
}

/// A failed expectation: what was expected, what came, and the likely cause.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Failure {
    /// The case, e.g. "ray from (0, 0, 5) along −z, sphere r = 1 at the origin".
    pub case: String,
    pub expected: String,
    pub got: String,
    /// One line: the likely cause in the student's code.
    pub cause: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub images: Option<Box<Images>>,
}

/// How a check's process came out, as it writes it to the verdict file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "status", rename_all = "lowercase")]
pub enum Outcome {
    Passed {
        /// What was measured, e.g. "0.02 % of pixels differ".
        detail: String,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        images: Option<Images>,
    },
    Failed(Failure),
    /// The check panicked (the student's code, most often): the panic's message and place.
    Panicked {
        message: String,
        file: String,
        line: u32,
    },
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outcomes_are_tagged_by_status_in_json() {
        let passed = Outcome::Passed { detail: "7 cases".into(), images: None };
        assert_eq!(serde_json::to_string(&passed).unwrap(), r#"{"status":"passed","detail":"7 cases"}"#);
        let panicked = r#"{"status":"panicked","message":"not yet","file":"lectures/02-ray-casting/src/sphere.rs","line":9}"#;
        let read: Outcome = serde_json::from_str(panicked).unwrap();
        assert_eq!(
            read,
            Outcome::Panicked {
                message: "not yet".into(),
                file: "lectures/02-ray-casting/src/sphere.rs".into(),
                line: 9
            }
        );
        let failed = Outcome::Failed(Failure { case: "c".into(), cause: "why".into(), ..Failure::default() });
        let json = serde_json::to_string(&failed).unwrap();
        assert_eq!(json, r#"{"status":"failed","case":"c","expected":"","got":"","cause":"why"}"#);
        assert_eq!(serde_json::from_str::<Outcome>(&json).unwrap(), failed);
    }

    #[test]
    fn an_info_knows_its_short_id_and_exercise() {
        let info = Info {
            id: "03/hit_slabs/unit".into(),
            lecture: "03".into(),
            exercise: "hit_slabs".into(),
            kind: Kind::Unit,
            points: 1,
            needs: vec![],
            about: String::new(),
            hidden: false,
            timeout_s: 10,
            available: true,
            judged: false,
        };
        assert_eq!(info.short(), "hit_slabs/unit");
        assert_eq!(info.exercise_id(), "03/hit_slabs");
        assert_eq!(serde_json::to_value(&info).unwrap()["kind"], "unit");
        // A list from a checks binary without the field reads as not judged.
        let mut value = serde_json::to_value(&info).unwrap();
        value.as_object_mut().unwrap().remove("judged");
        assert!(!serde_json::from_value::<Info>(value).unwrap().judged);
    }
}
