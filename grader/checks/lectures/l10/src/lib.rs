//! Lecture 10, textures and sampling: texture coordinates of spheres, planes and triangles,
//! checkerboards, noise, marble and wood, bilinear image lookup, sampling patterns, filters and supersampling.

// Built without its lecture (which does not compile), the crate is its checks' declarations alone.
#![cfg_attr(not(feature = "l10"), allow(unused))]

// The core's modules at the crate's root, where the checks name them (`crate::check::close`).
#[allow(unused_imports)]
use raylab_checks_core::{check, declare_checks, judge, path, remote, rows, stages, trees};

use crate::check::Meta;

declare_checks! {
    "l10", judged;
    Meta::unit(
        "sphere_uv",
        "poles, the equator's axis points, the inverse of longitude and latitude, points off the sphere",
    ) => sphere_cases(sphere_uv),
    Meta::unit("plane_uv", "perpendicular and skew axes, and a point off the plane, by hand")
        => plane_cases(plane_uv),
    Meta::unit("triangle_uv", "the vertices' uvs at the corners, their mean at the centroid and on an edge")
        => triangle_cases(triangle_uv),
    Meta::unit(
        "checker",
        "alternation across cell edges, the floor at negative coordinates, half-open cells",
    ) => checker_cases(checker),
    Meta::unit("checker_3d", "a solid board alternating across each face of a cube, at two scales")
        => checker_3d_cases(checker_3d),
    Meta::unit(
        "noise",
        "0 at lattice points, continuous across 300 cell faces, within its bound 1.0364, and Perlin's own \
         formulation at 2,007 points, negative cells and 10³⁰ included",
    ) => noise_cases(noise),
    Meta::unit("fractal_noise", "0 octaves is 0; 1, 2, 5 and 8 octaves against the sum, at 500 points")
        .needs(&["10/noise"]) => fractal_cases(fractal_noise),
    Meta::unit("marble", "(1 + sin(f·x + A·N))/2 at 600 points, with and without noise")
        .needs(&["10/fractal_noise"]) => marble_cases(marble),
    Meta::unit("wood", "(1 + sin(f·√(x² + z²) + A·N))/2 at 600 points, with and without noise")
        .needs(&["10/fractal_noise"]) => wood_cases(wood),
    Meta::unit(
        "bilinear",
        "pixel centres, halfway means, wrapping edges and tiles, v upward, on a 4 × 2 image",
    ) => bilinear_cases(bilinear),
    Meta::unit("filter_weight", "box and tent by hand, their rims, NaN, and both integrating to 1")
        => filter_cases(filter_weight),
    Meta::unit(
        "sample_offsets",
        "regular centres by hand; one jittered sample per cell; multi-jittered n-rooks; non-square counts",
    ) => sampling_cases(sample_offsets),
    Meta::unit(
        "render_supersampled",
        "one regular sample is 08's render; one primary ray per sample; a pixel under an edge converges to \
         its coverage, box and tent weighted",
    )
    .needs(&[
        "01/PerspectiveCamera::generate_ray",
        "01/OrthographicCamera::generate_ray",
        "02/hit_sphere_stable",
        "02/hit_plane",
        "03/hit_triangle",
        "08/trace_ray",
        "08/render",
        "10/sample_offsets",
        "10/filter_weight",
    ]) => supersampling_cases(render_supersampled),
}

#[cfg(feature = "l10")]
mod bilinear;
#[cfg(feature = "l10")]
mod checker;
#[cfg(feature = "l10")]
mod common;
#[cfg(feature = "l10")]
mod filter;
#[cfg(feature = "l10")]
mod noise;
#[cfg(feature = "l10")]
mod patterns;
#[cfg(feature = "l10")]
mod supersample;
#[cfg(feature = "l10")]
mod uv;

#[cfg(feature = "l10")]
pub mod stage;
#[cfg(feature = "l10")]
pub mod tracer;

/// What the rows above run: the checks of each of the lecture's files.
#[cfg(feature = "l10")]
mod code {
    pub(super) use super::{
        bilinear::*, checker::*, common::*, filter::*, noise::*, patterns::*, supersample::*, uv::*,
    };
}

#[cfg(all(test, feature = "l10"))]
mod tests {
    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }
}
