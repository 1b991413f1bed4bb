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
use crate::stages::Lent;

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
pub use raylab_checks_l01 as l01;
pub use raylab_checks_l02 as l02;
pub use raylab_checks_l03 as l03;
pub use raylab_checks_l04 as l04;
pub use raylab_checks_l05 as l05;
pub use raylab_checks_l06 as l06;
pub use raylab_checks_l07 as l07;
pub use raylab_checks_l08 as l08;
pub use raylab_checks_l09 as l09;
pub use raylab_checks_l10 as l10;
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
    /// Lends the stages the lecture's code they draw with (its `stage` module).
    pub lend: Option<fn(&mut Lent)>,
    pub hidden: bool,
}

/// `Some(function)` when the lecture's feature is on (its code is built), else `None`.
macro_rules! built {
    ($feature:literal, $function:path) => {{
        #[cfg(feature = $feature)]
        let function = Some($function as _);
        #[cfg(not(feature = $feature))]
        let function = None;
        function
    }};
}
// INSTRUCTOR BEGIN
#[cfg(feature = "hidden")]
pub(crate) use built;
// INSTRUCTOR END

/// Lecture `number`'s row: its module's checks, and with its feature their code and its stage's.
macro_rules! lecture {
    ($number:literal, $module:ident, $feature:literal) => {
        Lecture {
            number: $number,
            checks: $module::CHECKS,
            run: built!($feature, $module::run),
            lend: built!($feature, $module::stage::lend),
            hidden: false,
        }
    };
}

/// Every lecture's checks, in lecture order (hidden ones last).
pub fn lectures() -> Vec<Lecture> {
    #[allow(unused_mut)]
    let mut all = vec![
        // BEGIN GENERATED lectures: written by `cargo run -p grader -- dev sync` from lectures/*/Cargo.toml; edit those, not this.
        lecture!("01", l01, "l01"),
        lecture!("02", l02, "l02"),
        lecture!("03", l03, "l03"),
        lecture!("04", l04, "l04"),
        lecture!("05", l05, "l05"),
        lecture!("06", l06, "l06"),
        lecture!("07", l07, "l07"),
        lecture!("08", l08, "l08"),
        lecture!("09", l09, "l09"),
        lecture!("10", l10, "l10"),
        // END GENERATED lectures
    ];
    // INSTRUCTOR BEGIN
    #[cfg(feature = "hidden")]
    all.extend(hidden::lectures());
    // INSTRUCTOR END
    all
}

/// Installs the code the built lectures lend the stages (`stages::install`): `main` does, before
/// a check runs, and so do the tests that draw.
pub fn install() {
    let mut lent = Lent::default();
    for lend in lectures().iter().filter_map(|lecture| lecture.lend) {
        lend(&mut lent);
    }
    crate::stages::install(lent);
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

/// The stages' code as every lecture lends it, against the stages' declaration and the blessed
/// files.
#[cfg(all(test, feature = "complete"))]
mod tests {
    /// With every lecture built, every stage is.
    #[test]
    fn every_stage_is_built_with_every_lecture() {
        super::install();
        for row in crate::stages::STAGES {
            assert!(
                crate::stages::built(row.lecture),
                "stage {} is not built with every lecture",
                row.lecture
            );
        }
    }

    /// Every scene, at each stage with calls, has its blessed calls, of its grid, and the
    /// reference's calls today agree with them at every grid pixel by the comparison a failed
    /// picture is explained with: the reference is never named. In f32, the precision they are
    /// blessed in, and in f64 but for area-light samples drawn from another seed: 06's
    /// `point_seed` hashes the hit point's cell, and a point within an ulp of a cell's wall
    /// falls on the other side in the other precision.
    #[test]
    fn the_reference_s_calls_agree_with_the_blessed_ones_at_every_grid_pixel() {
        use crate::path::{GridCalls, first_difference};
        use crate::scenes::{calls_snapshot, scene_files};
        use crate::stages;
        super::install();
        let (mut files, mut pixels) = (0, 0);
        let (mut wrong, mut reseeded) = (Vec::new(), Vec::new());
        let f64_build = size_of::<raylab::Float>() == 8;
        for file in scene_files(None).unwrap() {
            for stage in stages::drawing(&file) {
                let scene = file.drawn_by(stage).unwrap();
                let path = calls_snapshot(&file, stage);
                let has_calls = matches!(stage, "05" | "06" | "07" | "08" | "10");
                let Ok(text) = std::fs::read_to_string(&path) else {
                    assert!(!has_calls, "{}: missing (grader bless)", path.display());
                    continue;
                };
                assert!(has_calls, "{}: a stage without calls", path.display());
                let blessed: GridCalls = serde_json::from_str(&text).unwrap();
                assert_eq!(
                    (blessed.grid, blessed.width, blessed.height),
                    (crate::trees::GRID, scene.width, scene.height)
                );
                let grid = crate::trees::grid(scene.width, scene.height);
                assert_eq!(
                    (0..).take_while(|&i| blessed.pixel(i).is_some()).count(),
                    grid.len(),
                    "{}",
                    path.display()
                );
                for (index, &pixel) in grid.iter().enumerate() {
                    let traced = stages::calls(stage, &scene, pixel).unwrap();
                    match first_difference(&blessed.pixel(index).unwrap(), &traced) {
                        // In f64 a hit point can fall in another seed cell than f32's: another
                        // stream of area-light samples from there on (see the test's note).
                        Some((exercise, how)) if f64_build && exercise == "06/stratified" => {
                            reseeded.push(format!("{} pixel {pixel:?}: {how}", path.display()));
                        }
                        Some((_, how)) => wrong.push(format!("{} pixel {pixel:?}: {how}", path.display())),
                        None => {}
                    }
                    pixels += 1;
                }
                files += 1;
            }
        }
        println!(
            "{files} files, {pixels} pixels; in f64, reseeded area-light samples at:\n{}",
            reseeded.join("\n")
        );
        // Measured: one pixel of 4896 (06's soft-shadows-sphere at (168, 88), at stage 06; with
        // full-size final pictures, of 8565, at stage 10 too), where a failed picture's cause in an
        // f64 build could name 06/stratified wrongly.
        assert!(reseeded.len() <= 2, "{} pixels reseeded:\n{}", reseeded.len(), reseeded.join("\n"));
        // Lectures 05–08's 24 scenes at their own stage, the 41 of lectures 01–09 and the 5 of 10 at stage 10.
        assert_eq!(files, 24 + 41 + 5);
        assert!(
            wrong.is_empty(),
            "{} pixels differ:\n{}",
            wrong.len(),
            wrong[..wrong.len().min(20)].join("\n")
        );
    }

    /// The report's data for a failed scene of 08 (what `view3d-data.js` holds): the scene, the
    /// expected and your trees of all 130 grid pixels, and first the pair of the grid pixel
    /// nearest the first differing one, (150, 70) → (152, 72), whose expected tree is the
    /// printed tree (`view3d::tests::the_blessed_whitted_trees_are_the_printed_tree` holds its
    /// snapshot).
    #[test]
    fn the_report_s_view_of_a_failed_whitted_holds_the_grid_s_trees() {
        super::install();
        let file = crate::scenes::scene_files(Some("08"))
            .unwrap()
            .into_iter()
            .find(|f| f.name() == "whitted")
            .unwrap();
        let scene = raylab::scene::load(&file.scene).unwrap();
        let dir =
            std::env::temp_dir().join(format!("raylab-view-data-{}", std::process::id())).join("08/whitted");
        std::fs::create_dir_all(&dir).unwrap();
        // "Yours": the reference's own trees (a submission's differ in their numbers, not in form).
        let yours = serde_json::to_string(&crate::stages::grid_trees("08", &scene).unwrap()).unwrap();
        raylab_checks_core::images::picture::write_view(&file, "08", &scene, &yours, (150, 70), &dir)
            .unwrap();
        let script = std::fs::read_to_string(dir.join(raylab_protocol::VIEW_DATA)).unwrap();
        let prefix = "(window.raylabViewData = window.raylabViewData || {})[\"08/whitted\"] = ";
        let data: serde_json::Value =
            serde_json::from_str(script.strip_prefix(prefix).unwrap().trim_end().trim_end_matches(';'))
                .unwrap();
        let printed = crate::stages::pixel_tree("08", &scene, (152, 72)).unwrap();
        let printed = printed.split_once('\n').unwrap().1;
        assert_eq!(data["trees"][0]["label"], "expected");
        assert_eq!(data["trees"][1]["label"], "yours");
        for tree in data["trees"].as_array().unwrap() {
            assert_eq!(tree["pixel"], serde_json::json!([152, 72]));
            assert_eq!(tree["text"].as_str(), Some(printed));
        }
        assert_eq!(data["grid"]["step"], 16);
        assert_eq!(data["grid"]["expected"].as_array().unwrap().len(), 130);
        assert_eq!(data["grid"]["yours"].as_array().unwrap().len(), 130);
        assert_eq!(data["objects"].as_array().unwrap().len(), scene.objects.len());
        let _ = std::fs::remove_dir_all(dir.parent().unwrap().parent().unwrap());
    }
}
