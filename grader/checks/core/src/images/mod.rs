//! Image checks: every `lectures/NN-name/scenes/S.toml` rendered with the
//! student's code and compared with the reference snapshots
//! `lectures/NN-name/snapshots/S.png` (lecture NN's stage), `S.final.png`
//! (the complete tracer), `S.id.png`, `S.depth.exr` and `S.normal.exr`, which
//! `grader bless` writes.
//!
//! Checks per scene:
//! - `NN/image/S`: the scene drawn by lecture NN's stage ([`crate::stages`]):
//!   the kit and lectures 01–NN only, so it is graded as soon as lecture NN
//!   is done. When it differs, the geometry is compared first (from stage 02
//!   on), and the differences are located to name the likely exercise.
//! - `NN/geometry/S` (lectures 02–04 and 09): the object-id, depth and normal
//!   images, made with the intersections of the lecture (02 for spheres and
//!   planes, 03 for boxes, polygons and meshes, 04 for quadrics and
//!   transforms, 09's hierarchy for its own big scenes).
//! - `10/final/NN-S` (lectures 01–09): the same scene from the complete tracer
//!   (lectures 01–10): the course's final pictures, graded with lecture 10.
//!
//! The module's parts: `geometry` (the geometry images and how they differ), `picture` (a
//! picture against its snapshot, the report's images and 3D view), `diagnosis` (what a
//! differing picture points to). The snapshots are written by the binary's `bless` tool.

mod diagnosis;
mod geometry;
pub mod picture;

use std::path::Path;

use crate::check::{CheckResult, Info, Kind, Meta};
use crate::scenes::{SceneFile, scene_files};
use crate::stages::{self, FINAL_STAGE};

use geometry::check_geometry;
use picture::check_image;

/// A pixel differs when one of its 8-bit sRGB channels moves by more than
/// this many steps: the f32 and f64 builds differ by a step or two where
/// shading rounds differently.
pub const CHANNEL_THRESHOLD: u8 = 2;

/// A render passes when at most this fraction of its pixels differ: f32 and
/// f64 disagree on hit or miss only for pixel rays within a few ulp of a
/// silhouette (measured: well under 0.1 % on the lecture scenes).
pub const MAX_FRACTION_OVER: f64 = 0.002;

/// A FLIP error above this is a difference a viewer notices at a glance
/// (FLIP's own scale: 0 identical, 1 opposite); the report counts such pixels.
pub const FLIP_THRESHOLD: f32 = 0.25;

/// Scenes that test precision itself, with the fraction they may differ by
/// and why.
/// - `06-shadows/far-from-origin` sits at 10⁴, where an f32 ulp is 0.001:
///   the f32 snapshot's highlight (normals from p − c) and shadow edges are
///   off by that much, and the f64 build draws them more accurately
///   (measured 0.41 % of pixels apart).
/// - `10-textures-sampling/checker-aliasing-16spp`: toward the horizon many
///   checker cells share a pixel, so a rounding-level shift of one of its 16
///   jittered rays flips the cell it lands in and moves the pixel by 1/16
///   (measured 0.33 % of pixels apart; the 1-spp twin matches exactly).
const PRECISION_SCENES: &[(&str, &str, f64)] =
    &[("06", "far-from-origin", 0.01), ("10", "checker-aliasing-16spp", 0.01)];

impl SceneFile {
    /// The fraction of pixels this scene may differ by.
    pub(super) fn allowed_fraction(&self) -> f64 {
        PRECISION_SCENES
            .iter()
            .find(|(lecture, scene, _)| *lecture == self.lecture && *scene == self.name())
            .map_or(MAX_FRACTION_OVER, |&(_, _, fraction)| fraction)
    }
}

/// The geometry, image and final checks of every scene, as the grader lists them.
pub fn infos() -> Vec<Info> {
    let mut infos = Vec::new();
    let mut finals = Vec::new();
    for file in scene_files(None).unwrap_or_default() {
        let name: &'static str = Box::leak(file.name().into_boxed_str());
        let geometry = Meta {
            exercise: "geometry",
            name,
            kind: Kind::Image,
            points: 1,
            needs: stages::needs(&file.lecture),
            about: "object-id, depth and normal images against the reference's",
            judged: true,
        };
        if has_geometry_check(&file.lecture) {
            infos.push(crate::check::info(&file.lecture, &geometry, false, stages::built(&file.lecture)));
        }
        let image = Meta { exercise: "image", about: stages::about(&file.lecture), ..geometry };
        infos.push(crate::check::info(&file.lecture, &image, false, stages::built(&file.lecture)));
        if file.lecture != FINAL_STAGE {
            let name: &'static str = Box::leak(format!("{}-{}", file.lecture, file.name()).into_boxed_str());
            let about =
                "the complete tracer (lectures 01–10) on an earlier lecture's scene, against the snapshot";
            let last = Meta { exercise: "final", name, needs: stages::needs(FINAL_STAGE), about, ..geometry };
            finals.push(crate::check::info(FINAL_STAGE, &last, false, stages::built(FINAL_STAGE)));
        }
    }
    infos.extend(finals);
    infos
}

/// Lectures 02–04 (intersections) and 09 (the hierarchy) are graded on their
/// scenes' geometry; for the others the geometry is only compared to explain
/// a failed image.
pub(super) fn has_geometry_check(lecture: &str) -> bool {
    stages::stage(lecture).is_some_and(|s| s.geometry_graded)
}

/// Runs `NN/geometry/S`, `NN/image/S` or `10/final/NN-S`, writing images
/// under `out`; `None` when the id names no scene check of this build.
pub fn run(id: &str, out: &Path) -> Option<CheckResult> {
    let mut parts = id.splitn(3, '/');
    let (lecture, kind, name) = (parts.next()?, parts.next()?, parts.next()?);
    let files = scene_files(None).ok()?;
    match kind {
        "geometry" if has_geometry_check(lecture) && stages::built(lecture) => {
            let file = files.into_iter().find(|f| f.lecture == lecture && f.name() == name)?;
            Some(check_geometry(&file))
        }
        "image" if stages::built(lecture) => {
            let file = files.into_iter().find(|f| f.lecture == lecture && f.name() == name)?;
            let dir = out.join(&file.lecture).join(file.name());
            Some(check_image(&file, lecture, &dir))
        }
        "final" if lecture == FINAL_STAGE && stages::built(FINAL_STAGE) => {
            let file = files
                .into_iter()
                .find(|f| f.lecture != FINAL_STAGE && format!("{}-{}", f.lecture, f.name()) == name)?;
            let dir = out.join(FINAL_STAGE).join(format!("final-{name}"));
            Some(check_image(&file, FINAL_STAGE, &dir))
        }
        _ => None,
    }
}

pub(super) fn no_snapshot(file: &SceneFile, e: impl std::fmt::Display) -> String {
    format!("no snapshot for {}/{}: {e} (an instructor runs `grader bless`)", file.folder, file.name())
}
