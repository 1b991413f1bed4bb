//! The checks of every lecture: a table of declarations per lecture
//! (always compiled, so the grader knows every check and its points even when
//! a lecture does not compile) and, behind the lecture's feature, the code.
//!
//! To add a check: a row of the lecture's `declare_checks!`, its `Meta` and
//! the expression that runs it (a function of the lecture's `code` module).
//! Each lecture's test calls `check::testing::every_check_passes`, and
//! `grader --strict` (CI, on the reference) grades every check. The list of
//! lectures below is generated from the lecture crates' Cargo.toml.

use crate::check::{CheckResult, Info, Meta};

/// A lecture's checks, each declared once: its [`Meta`] and the expression
/// that runs it, evaluated among the items of the lecture's `code` module
/// (those the expressions name are `pub(super)` there). Yields `CHECKS`
/// (always compiled: the grader lists a lecture's checks, with their points,
/// even when the lecture does not compile) and, with the lecture's feature,
/// `run`, which runs the row whose `exercise/name` is asked.
macro_rules! declare_checks {
    // `judged`: every check below takes the student's values through `judge::student`.
    ($feature:literal, judged; $($meta:expr => $run:expr),+ $(,)?) => {
        declare_checks!(@ $feature, true; $($meta => $run),+);
    };
    ($feature:literal; $($meta:expr => $run:expr),+ $(,)?) => {
        declare_checks!(@ $feature, false; $($meta => $run),+);
    };
    (@ $feature:literal, $judged:literal; $($meta:expr => $run:expr),+) => {
        pub const CHECKS: &[crate::check::Meta] = &[$($meta.judged($judged)),+];

        #[cfg(feature = $feature)]
        pub fn run(name: &str) -> Option<crate::check::CheckResult> {
            let row = CHECKS.iter().position(|meta| meta.short_id() == name)?;
            // In a block of their own, so that the code's names cannot shadow `name`.
            let runs: Vec<fn() -> crate::check::CheckResult> = {
                #[allow(unused_imports)]
                use code::*;
                vec![$(|| $run),+]
            };
            Some(runs[row]())
        }
    };
}

/// The calls of the student's code the subject answers for a hidden check (`remote.rs`), by
/// name: the rows of `rows::student_fns!` marked `remote`.
pub const ANSWERS: &[(&str, crate::remote::Answer)] = &[
    #[cfg(feature = "l01")]
    (l01::common::rotate_z::NAME, l01::common::rotate_z::answer),
    #[cfg(feature = "l01")]
    (l01::common::transform_vector::NAME, l01::common::transform_vector::answer),
    #[cfg(feature = "l02")]
    (l02::common::hit_sphere_stable::NAME, l02::common::hit_sphere_stable::answer),
    #[cfg(feature = "l03")]
    (l03::common::hit_slabs::NAME, l03::common::hit_slabs::answer),
    #[cfg(feature = "l05")]
    (l05::common::lambert::NAME, l05::common::lambert::answer),
    #[cfg(feature = "l07")]
    (l07::common::refract::NAME, l07::common::refract::answer),
    #[cfg(feature = "l09")]
    (l09::common::aabb_surface_area::NAME, l09::common::aabb_surface_area::answer),
];

// BEGIN GENERATED modules: written by `cargo run -p grader -- dev sync` from lectures/*/Cargo.toml; edit those, not this.
pub mod l01;
pub mod l02;
pub mod l03;
pub mod l04;
pub mod l05;
pub mod l06;
pub mod l07;
pub mod l08;
pub mod l09;
pub mod l10;
// END GENERATED modules
// INSTRUCTOR BEGIN
#[cfg(feature = "hidden")]
pub mod hidden;
// INSTRUCTOR END

/// One lecture's checks: declarations, and the runner when its code is built.
pub struct Lecture {
    /// `02`.
    pub number: &'static str,
    pub checks: &'static [Meta],
    /// Runs `exercise/name`; `None` for a name it does not know.
    pub run: Option<fn(&str) -> Option<CheckResult>>,
    pub hidden: bool,
}

/// `Some(run)` when the lecture's feature is on (its code is built), else `None`.
macro_rules! runner {
    ($feature:literal, $run:path) => {{
        #[cfg(feature = $feature)]
        let run: Option<fn(&str) -> Option<crate::check::CheckResult>> = Some($run);
        #[cfg(not(feature = $feature))]
        let run: Option<fn(&str) -> Option<crate::check::CheckResult>> = None;
        run
    }};
}
// INSTRUCTOR BEGIN
#[cfg(feature = "hidden")]
pub(crate) use runner;
// INSTRUCTOR END

/// Every lecture's checks, in lecture order (hidden ones last).
pub fn lectures() -> Vec<Lecture> {
    #[allow(unused_mut)]
    let mut all = vec![
        // BEGIN GENERATED lectures: written by `cargo run -p grader -- dev sync` from lectures/*/Cargo.toml; edit those, not this.
        Lecture { number: "01", checks: l01::CHECKS, run: runner!("l01", l01::run), hidden: false },
        Lecture { number: "02", checks: l02::CHECKS, run: runner!("l02", l02::run), hidden: false },
        Lecture { number: "03", checks: l03::CHECKS, run: runner!("l03", l03::run), hidden: false },
        Lecture { number: "04", checks: l04::CHECKS, run: runner!("l04", l04::run), hidden: false },
        Lecture { number: "05", checks: l05::CHECKS, run: runner!("l05", l05::run), hidden: false },
        Lecture { number: "06", checks: l06::CHECKS, run: runner!("l06", l06::run), hidden: false },
        Lecture { number: "07", checks: l07::CHECKS, run: runner!("l07", l07::run), hidden: false },
        Lecture { number: "08", checks: l08::CHECKS, run: runner!("l08", l08::run), hidden: false },
        Lecture { number: "09", checks: l09::CHECKS, run: runner!("l09", l09::run), hidden: false },
        Lecture { number: "10", checks: l10::CHECKS, run: runner!("l10", l10::run), hidden: false },
        // END GENERATED lectures
    ];
    // INSTRUCTOR BEGIN
    #[cfg(feature = "hidden")]
    all.extend(hidden::lectures());
    // INSTRUCTOR END
    all
}

/// Every declared check, as the grader lists them.
pub fn infos() -> Vec<Info> {
    let mut infos = Vec::new();
    for lecture in lectures() {
        for meta in lecture.checks {
            infos.push(crate::check::info(lecture.number, meta, lecture.hidden, lecture.run.is_some()));
        }
    }
    infos
}

/// Runs the unit or extreme check `id` (`NN/exercise/name`); `None` when no
/// built lecture has it.
pub fn run(id: &str) -> Option<CheckResult> {
    let (number, rest) = id.split_once('/')?;
    lectures().into_iter().filter(|l| l.number == number).find_map(|l| {
        let declared = l.checks.iter().any(|m| format!("{}/{}", m.exercise, m.name) == rest);
        if declared { (l.run?)(rest) } else { None }
    })
}
