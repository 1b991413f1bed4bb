//! Lecture 08, the ray tree: the recursive tracer's colours and its two stopping rules, and the
//! render loop around it.

// Built without its lecture (which does not compile), the crate is its checks' declarations alone.
#![cfg_attr(not(feature = "l08"), allow(unused))]

// The core's modules at the crate's root, where the checks name them (`crate::check::close`).
#[allow(unused_imports)]
use raylab_checks_core::{check, declare_checks, judge, path, remote, rows, stages, trees};

use crate::check::Meta;

/// What `trace` calls: the shapes of the check scenes (spheres, planes, boxes), the local
/// shading with and without shadow rays, the offset of new rays, and lecture 07's directions.
const TRACE_NEEDS: &[&str] = &[
    "02/hit_sphere_stable",
    "02/hit_plane",
    "02/closest_hit",
    "03/hit_box",
    "05/shade_local",
    "06/offset_origin",
    "06/shade_with_shadows",
    "07/mirror_direction",
    "07/interface",
    "07/refract",
    "07/fresnel_dielectric",
];

declare_checks! {
    "l08", judged;
    Meta::unit(
        "trace_ray",
        "by hand: a miss, a mirror, facing mirrors stopped by depth and by weight, total internal \
         reflection, Fresnel's 4 % at normal incidence",
    )
    .needs(TRACE_NEEDS) => trace_cases(trace),
    Meta::extreme(
        "trace_ray",
        "tiny-glass-sphere",
        "rays through a glass ball of radius 10⁻⁵: each enters and finds its exit (two refracted rays) \
         and sees the wall behind",
    )
    .needs(TRACE_NEEDS) => tiny_glass_sphere(trace),
    Meta::unit(
        "render",
        "each pixel is trace of 01's pixel_ray at depth 0, weight 1; one primary ray per pixel",
    )
    .needs(&["08/trace_ray", "01/PerspectiveCamera::generate_ray", "01/screen_coords"])
        => render_cases(render),
}

#[cfg(feature = "l08")]
mod common;
#[cfg(feature = "l08")]
mod render;
#[cfg(feature = "l08")]
mod trace;

#[cfg(feature = "l08")]
pub mod stage;

/// What the rows above run: the checks of each of the lecture's files.
#[cfg(feature = "l08")]
mod code {
    pub(super) use super::{common::*, render::*, trace::*};
}

#[cfg(all(test, feature = "l08"))]
mod tests {
    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }
}
