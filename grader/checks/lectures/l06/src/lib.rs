//! Lecture 06, shadows: shadow rays and where they start, transparent
//! blockers, shading with shadows, and soft shadows from area lights.
//!
//! The checks intersect their scenes with a small intersector of their own
//! (spheres, planes and a half plane, below), so that a shadow check is not
//! blocked by lectures 02–04; the offset checks decide "self-hit or not" in
//! f64, on which side of the surface the new origin lies.

// Built without its lecture (which does not compile), the crate is its checks' declarations alone.
#![cfg_attr(not(feature = "l06"), allow(unused))]

// The core's modules at the crate's root, where the checks name them (`crate::check::close`).
#[allow(unused_imports)]
use raylab_checks_core::{check, declare_checks, judge, path, remote, rows, stages, trees};

use crate::check::Meta;

declare_checks! {
    "l06", judged;
    Meta::unit(
        "offset_origin",
        "along ±n to the side dir leaves to, by a few ulp of p and of the ray's origin, never zero",
    ) => offset_cases(offset_origin),
    Meta::extreme(
        "offset_origin",
        "large-coordinates",
        "spheres at 10⁴ and 10⁵ and a floor seen from 860 away: no shadow ray starts inside, moves ≤ 97 ulp",
    ) => large_coordinates(offset_origin),
    Meta::unit("offset_origin_fixed_t", "the naive method: p + 10⁻⁴·dir")
        => fixed_t_cases(offset_origin_fixed_t),
    Meta::unit("offset_origin_fixed_normal", "the naive method: p + 10⁻⁴·n, whatever dir")
        => fixed_normal_cases(offset_origin_fixed_normal),
    Meta::unit(
        "occluded",
        "a blocker between, beside, beyond the light and behind the point; one any-hit shadow ray",
    ) => occluded_cases(occluded),
    Meta::unit(
        "transmittance",
        "Π k_t over the surfaces crossed: a sphere ¼, a plane ½, by channel, opaque stops, the light nearer",
    )
    .needs(&["06/offset_origin"]) => transmittance_cases(transmittance),
    Meta::unit("visibility", "opaque or filtered by mode, from just off a floor seen from far away")
        .needs(&["06/offset_origin", "06/occluded", "06/transmittance"]) => visibility_cases(visibility),
    Meta::unit(
        "shade_with_shadows",
        "under and beside a ball, a transparent ball, lights without shadows or behind: values and ray counts",
    )
    .needs(&["05/illuminate", "05/shade_light", "06/visibility", "06/shade_area_light"])
        => shade_cases(shade_with_shadows),
    Meta::unit("stratified", "n samples, one per cell of the √n × √n grid or the n strips, row by row, in [0, 1)²")
        => stratified_cases(stratified),
    Meta::unit(
        "shade_area_light",
        "the average over n samples of V·(N·L) against the same points in f64: umbra, penumbra, half below",
    )
    .needs(&["05/sample_light", "05/shade_light", "06/visibility", "06/stratified"])
        => area_cases(shade_area_light),
}

#[cfg(feature = "l06")]
mod common;
#[cfg(feature = "l06")]
mod occlusion;
#[cfg(feature = "l06")]
mod offset;
#[cfg(feature = "l06")]
mod shade;
#[cfg(feature = "l06")]
mod soft;

#[cfg(feature = "l06")]
pub mod stage;

/// What the rows above run: the checks of each of the lecture's files.
#[cfg(feature = "l06")]
mod code {
    pub(super) use super::{common::*, occlusion::*, offset::*, shade::*, soft::*};
}

#[cfg(all(test, feature = "l06"))]
mod tests {
    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }
}
