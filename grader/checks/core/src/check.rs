//! What a check is, what it reports, and the small vocabulary the lecture
//! checks are written in.
//!
//! A check tests one exercise (`02/hit_sphere_geometric`) or one scene of a
//! lecture. It runs alone in a child process (`raylab-checks run ID`), so a
//! panic, a loop or an abort in the student's code ends that process only;
//! the grader reads the verdict file the check wrote, or, when there is none,
//! how the process ended.

use std::fmt::{self, Display};

use raylab::{Float, Hit, Ray, Vec3};
pub use raylab_protocol::{Failure, Images, Info, Kind, Outcome};

pub use raylab_testing::{ray, v, wide, wide3};

/// Whether `a` and `b` agree within `tol` in every component; never with a NaN in either (glam's
/// `max_element`, like `f32::max`, drops a NaN beside a number: (NaN, 0, 0) would pass).
pub fn near3(a: Vec3, b: Vec3, tol: Float) -> bool {
    let d = (a - b).abs();
    !d.is_nan() && d.max_element() <= tol
}

/// `ray from (…) along (…)`.
pub fn show_ray(r: &Ray) -> String {
    format!("ray from {} along {}", vec3(r.origin), vec3(r.dir))
}

/// A hit as the messages write it: t, normal and front_face; or None.
pub fn show_hit(h: &Option<Hit>) -> String {
    maybe(h, |h| format!("t = {}, normal {}, front_face {}", num(h.t), vec3(h.normal), h.front_face))
}

/// A span of t, `(enter, exit)`; or None.
pub fn show_span(s: &Option<(Float, Float)>) -> String {
    maybe(s, |(a, b)| format!("({}, {})", num(*a), num(*b)))
}

/// A check as the lecture tables declare it.
#[derive(Clone, Copy, Debug)]
pub struct Meta {
    /// The exercise tested: the function's name (`hit_slabs`,
    /// `PerspectiveCamera::generate_ray`), or `image`/`geometry` for scenes.
    pub exercise: &'static str,
    /// Which check of the exercise (`unit`, `axis-parallel-rays`, …).
    pub name: &'static str,
    pub kind: Kind,
    pub points: u32,
    /// Other exercises whose result this check relies on, as `NN/function`:
    /// when one of them is not started or fails, the verdict says "blocked".
    pub needs: &'static [&'static str],
    /// What the check tests, in one line (shown with a failure and in the report).
    pub about: &'static str,
    /// Its code takes every value of the student's code through `judge::student`, so a
    /// submission's grade can come from a judge that runs none of it (`judge.rs`). Set for a
    /// lecture's checks at once, by `declare_checks!`.
    pub judged: bool,
}

impl Meta {
    pub const fn unit(exercise: &'static str, about: &'static str) -> Self {
        Self { exercise, name: "unit", kind: Kind::Unit, points: 1, needs: &[], about, judged: false }
    }

    pub const fn extreme(exercise: &'static str, name: &'static str, about: &'static str) -> Self {
        Self { exercise, name, kind: Kind::Extreme, points: 1, needs: &[], about, judged: false }
    }

    // INSTRUCTOR BEGIN
    /// A hidden check's name (`hidden-…`), so its id never collides with a visible one.
    pub const fn named_hidden(self, name: &'static str) -> Self {
        Self { name, ..self }
    }
    // INSTRUCTOR END

    /// `exercise/name`: the id within its lecture.
    pub fn short_id(&self) -> String {
        format!("{}/{}", self.exercise, self.name)
    }

    pub const fn points(self, points: u32) -> Self {
        Self { points, ..self }
    }

    pub const fn needs(self, needs: &'static [&'static str]) -> Self {
        Self { needs, ..self }
    }

    pub const fn judged(self, judged: bool) -> Self {
        Self { judged, ..self }
    }
}

/// A check as the grader sees it: `meta` declared in lecture `lecture`.
pub fn info(lecture: &str, meta: &Meta, hidden: bool, available: bool) -> Info {
    Info {
        id: format!("{lecture}/{}/{}", meta.exercise, meta.name),
        lecture: lecture.to_owned(),
        exercise: meta.exercise.to_owned(),
        kind: meta.kind,
        points: meta.points,
        needs: meta.needs.iter().map(|n| (*n).to_owned()).collect(),
        about: meta.about.to_owned(),
        hidden,
        timeout_s: match meta.kind {
            Kind::Image => IMAGE_TIMEOUT_S,
            _ => UNIT_TIMEOUT_S,
        },
        available,
        judged: meta.judged,
    }
}

/// A unit or extreme check's time limit. The reference runs each in well
/// under a second in a debug build; the limit leaves room for a loaded
/// machine and a slow but correct student solution, and still ends an
/// infinite loop quickly.
pub const UNIT_TIMEOUT_S: u32 = 10;

/// An image check's time limit: the reference renders the largest lecture
/// scene (64 area-light samples per pixel) in about 2 s in a debug build on
/// one thread.
pub const IMAGE_TIMEOUT_S: u32 = 60;

/// What a check function returns: a detail line when it passes.
pub type CheckResult = Result<String, Failure>;

/// A failure of `case`: `expected`, `got`, and the likely `cause`.
pub fn fail(case: impl Display, expected: impl Display, got: impl Display, cause: impl Display) -> Failure {
    Failure {
        case: case.to_string(),
        expected: expected.to_string(),
        got: got.to_string(),
        cause: cause.to_string(),
        images: None,
    }
}

/// Fails unless `condition`.
pub fn ensure(
    condition: bool,
    case: impl Display,
    expected: impl Display,
    got: impl Display,
    cause: impl Display,
) -> Result<(), Failure> {
    if condition { Ok(()) } else { Err(fail(case, expected, got, cause)) }
}

/// Fails unless `got` is within `tolerance` of `expected` (absolute); NaN
/// never passes.
pub fn close(
    case: impl Display,
    got: Float,
    expected: Float,
    tolerance: Float,
    cause: &str,
) -> Result<(), Failure> {
    // Formatted only on failure: the loops of cases that call this pass thousands of times.
    if (got - expected).abs() <= tolerance {
        return Ok(());
    }
    Err(fail(case, format!("{} (± {tolerance:.1e})", num(expected)), num(got), cause))
}

/// Fails unless every component of `got` is within `tolerance` of `expected`.
pub fn close3(
    case: impl Display,
    got: Vec3,
    expected: Vec3,
    tolerance: Float,
    cause: &str,
) -> Result<(), Failure> {
    if near3(got, expected, tolerance) {
        return Ok(());
    }
    Err(fail(case, format!("{} (± {tolerance:.1e} each)", vec3(expected)), vec3(got), cause))
}

/// Words written only when they are shown, a failure's: `lazy(|f| write!(f, "at {}", vec3(p)))`
/// in place of `format!(…)`, so that a check's loop over thousands of cases formats none of them
/// while they pass (formatting was a fifth of the unit checks' CPU, and 60 % of the largest's).
pub fn lazy<F: Fn(&mut fmt::Formatter<'_>) -> fmt::Result>(write: F) -> impl Display {
    struct Lazy<F>(F);
    impl<F: Fn(&mut fmt::Formatter<'_>) -> fmt::Result> Display for Lazy<F> {
        fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            (self.0)(f)
        }
    }
    Lazy(write)
}

/// A number printed for a student: four decimals, or scientific when tiny or huge, where that
/// names the number exactly; else every digit it takes (the shortest text that reads back as
/// it). So two numbers that differ never print alike: a failure one ulp off reads
/// "expected 0.7708, got 0.77083325", not "0.7708" twice.
pub fn num(x: Float) -> String {
    let a = x.abs();
    let short = if x == 0.0 || (1e-3..1e6).contains(&a) {
        format!("{x:.4}")
    } else if x.is_finite() {
        format!("{x:.4e}")
    } else {
        return format!("{x}");
    };
    if short.parse::<Float>().is_ok_and(|y| y == x) { short } else { format!("{x:?}") }
}

/// A vector printed for a student.
pub fn vec3(v: Vec3) -> String {
    format!("({}, {}, {})", num(v.x), num(v.y), num(v.z))
}

/// A lecture's checks, each declared once: its [`Meta`] and the expression
/// that runs it, evaluated among the items of the lecture's `code` module
/// (those the expressions name are `pub(super)` there). Yields `CHECKS`
/// (always compiled: the grader lists a lecture's checks, with their points,
/// even when the lecture does not compile) and, with the lecture's feature,
/// `run`, which runs the row whose `exercise/name` is asked.
#[macro_export]
macro_rules! declare_checks {
    // `judged`: every check below takes the student's values through `judge::student`.
    ($feature:literal, judged; $($meta:expr => $run:expr),+ $(,)?) => {
        $crate::declare_checks!(@ $feature, true; $($meta => $run),+);
    };
    ($feature:literal; $($meta:expr => $run:expr),+ $(,)?) => {
        $crate::declare_checks!(@ $feature, false; $($meta => $run),+);
    };
    (@ $feature:literal, $judged:literal; $($meta:expr => $run:expr),+) => {
        pub const CHECKS: &[$crate::check::Meta] = &[$($meta.judged($judged)),+];

        #[cfg(feature = $feature)]
        pub fn run(name: &str) -> Option<$crate::check::CheckResult> {
            let row = CHECKS.iter().position(|meta| meta.short_id() == name)?;
            // In a block of their own, so that the code's names cannot shadow `name`.
            let runs: Vec<fn() -> $crate::check::CheckResult> = {
                #[allow(unused_imports)]
                use code::*;
                vec![$(|| $run),+]
            };
            Some(runs[row]())
        }
    };
}

/// An optional value printed for a student: "no hit" for `None`.
pub fn maybe<T>(value: &Option<T>, show: impl Fn(&T) -> String) -> String {
    value.as_ref().map_or_else(|| "None (no hit)".to_owned(), show)
}

/// What the lecture files' tests share.
#[doc(hidden)]
pub mod testing {
    use super::{CheckResult, Meta};

    /// Asserts that a planted mistake failed its check with a cause containing `needle`.
    pub fn caught(result: CheckResult, needle: &str) {
        match result {
            Ok(detail) => panic!("the planted mistake passed ({detail}); expected a cause with {needle:?}"),
            Err(f) => {
                assert!(f.cause.contains(needle), "cause {:?} lacks {needle:?} (case {})", f.cause, f.case)
            }
        }
    }

    /// Every check of a lecture's table passes on the reference, and none lacks code.
    pub fn every_check_passes(checks: &[Meta], run: fn(&str) -> Option<CheckResult>) {
        for meta in checks {
            let name = format!("{}/{}", meta.exercise, meta.name);
            match run(&name) {
                Some(Ok(detail)) => println!("{name}: {detail}"),
                Some(Err(failure)) => panic!("{name} fails on the reference: {failure:?}"),
                None => panic!("{name} is declared but has no arm in run"),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// glam's `max_element` drops a NaN beside a number: |(NaN, 0, 0)| would be 0 and pass.
    #[test]
    fn a_nan_component_is_never_close() {
        let nan = Vec3::new(Float::NAN, 0.0, 0.0);
        for (a, b) in [(nan, Vec3::ZERO), (Vec3::ZERO, nan), (Vec3::new(0.0, 0.0, Float::NAN), Vec3::ZERO)] {
            assert!(!near3(a, b, 1.0), "{a} near {b}");
            assert!(close3("a NaN", a, b, 1.0, "never close").is_err(), "{a} close to {b}");
        }
        assert!(near3(Vec3::ONE, Vec3::ONE, 0.0));
    }

    #[test]
    fn outcomes_round_trip_through_json() {
        let failed = Outcome::Failed(fail("a ray", "t = 4", "t = 6", "the far root"));
        let text = serde_json::to_string(&failed).unwrap();
        assert!(text.starts_with(r#"{"status":"failed","case":"a ray""#), "{text}");
        assert_eq!(serde_json::from_str::<Outcome>(&text).unwrap(), failed);
        let passed = Outcome::Passed { detail: "ok".into(), images: None };
        assert_eq!(serde_json::to_string(&passed).unwrap(), r#"{"status":"passed","detail":"ok"}"#);
    }

    #[test]
    fn close_refuses_nan_and_shows_both_numbers() {
        assert!(close("x", 1.0, 1.0 + 1e-7, 1e-6, "").is_ok());
        let e = close("x", Float::NAN, 1.0, 1e-6, "a NaN").unwrap_err();
        assert_eq!((e.expected.as_str(), e.got.as_str()), ("1.0000 (± 1.0e-6)", "NaN"));
        assert_eq!(num(1.0e-5), "1.0000e-5");
        assert_eq!(num(-2.5), "-2.5000");
    }

    /// Two numbers that differ never print alike: one ulp apart, each gets the digits it takes
    /// (`10/render_supersampled/unit` once read "expected 0.7708, got 0.7708").
    #[test]
    fn numbers_one_ulp_apart_print_apart_and_plain_ones_stay_plain() {
        for x in [0.770_833_3 as Float, 1.0, 1.0e-5, 3.0e7, -2.5, 0.65] {
            let (below, above) = (x.next_down(), x.next_up());
            assert_ne!(num(below), num(x), "{x}");
            assert_ne!(num(above), num(x), "{x}");
            for y in [below, x, above] {
                assert_eq!(num(y).parse::<Float>().unwrap(), y, "{} reads back", num(y));
            }
        }
        assert_eq!(num(0.65), "0.6500");
        assert_eq!(num(1.0), "1.0000");
        assert_eq!(num(Float::INFINITY), "inf");
    }
}
