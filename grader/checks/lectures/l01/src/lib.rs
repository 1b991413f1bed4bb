//! Lecture 01, transforms: matrices built column by column, points and
//! vectors, frames and the test for a basis, look-at, screen coordinates and
//! the two cameras.

// Built without its lecture (which does not compile), the crate is its checks' declarations alone.
#![cfg_attr(not(feature = "l01"), allow(unused))]

// The core's modules at the crate's root, where the checks name them (`crate::check::close`).
#[allow(unused_imports)]
use raylab_checks_core::{check, declare_checks, judge, path, remote, rows, stages, trees};

use crate::check::Meta;

/// The cameras apply `world_from_camera` through the lecture's own helpers.
const CAMERA_NEEDS: &[&str] = &["01/transform_point", "01/transform_vector"];

declare_checks! {
    "l01", judged;
    Meta::unit("translate", "translate(t): the origin goes to t (the last column), the axes stay")
        => translate_cases(translate),
    Meta::unit("scale", "scale(s) is diag(sₓ, s_y, s_z, 1): the origin stays, w stays 1")
        => scale_cases(scale),
    Meta::unit("rotate_x", "right-handed turns about x in radians: a quarter turn takes +y to +z")
        => rotation_cases(0, rotate_x),
    Meta::unit("rotate_y", "right-handed turns about y in radians: a quarter turn takes +z to +x")
        => rotation_cases(1, rotate_y),
    Meta::unit("rotate_z", "right-handed turns about z in radians: a quarter turn takes +x to +y")
        => rotation_cases(2, rotate_z),
    Meta::unit(
        "rotate_axis",
        "Rodrigues' formula: fixes its axis, orthonormal, right-handed, the coordinate axes, any axis length",
    ) => rotate_axis_cases(rotate_axis),
    Meta::unit("transform_point", "m·(p, 1): the translation applies, and w' ≠ 1 divides")
        => transform_point_cases(transform_point),
    Meta::unit("transform_vector", "m·(v, 0): the linear part only, no translation")
        => transform_vector_cases(transform_vector),
    Meta::unit("frame", "world_from_frame has the columns i, j, k and the origin") => frame_cases(frame),
    Meta::unit(
        "is_basis",
        "independent, dependent and nearly coplanar triples, judged by a relative \
        threshold",
    ) => is_basis_cases(is_basis),
    Meta::extreme(
        "is_basis",
        "any-units",
        "axes whose length product overflows or underflows: the verdict must not depend on units",
    ) => is_basis_any_units(is_basis),
    Meta::unit("look_at", "the columns u, v, w, eye for views along the axes and a generic one; eye = at")
        => look_at_cases(look_at),
    Meta::extreme(
        "look_at",
        "degenerate-up",
        "up parallel to the view: an error, never NaN; up nearly parallel, views near −z, tiny and huge \
            distances: an error or an orthonormal basis within 1e-6",
    ) => look_at_degenerate(look_at),
    Meta::unit("screen_coords", "pixel centres: corners, the centre pixel, a one-pixel image, large images")
        => screen_cases(screen_coords),
    Meta::unit(
        "PerspectiveCamera::generate_ray",
        "directions (sx·aspect·tan(fovy/2), sy·tan(fovy/2), −1) taken to the world and normalised, from the \
            eye",
    )
    .needs(CAMERA_NEEDS) => perspective_cases(perspective_ray),
    Meta::unit(
        "OrthographicCamera::generate_ray",
        "origins (sx·aspect·h/2, sy·h/2, 0) taken to the world as points, one direction −w for every ray",
    )
    .needs(CAMERA_NEEDS) => orthographic_cases(orthographic_ray),
}

#[cfg(feature = "l01")]
mod axis_angle;
#[cfg(feature = "l01")]
pub mod common;
#[cfg(feature = "l01")]
mod frame;
#[cfg(feature = "l01")]
mod look_at;
#[cfg(feature = "l01")]
mod orthographic;
#[cfg(feature = "l01")]
mod perspective;
#[cfg(feature = "l01")]
mod screen;
#[cfg(feature = "l01")]
mod transforms;

#[cfg(feature = "l01")]
pub mod stage;

/// What the rows above run: the checks of each of the lecture's files.
#[cfg(feature = "l01")]
mod code {
    pub(super) use super::{
        axis_angle::*, common::*, frame::*, look_at::*, orthographic::*, perspective::*, screen::*,
        transforms::*,
    };
}

#[cfg(all(test, feature = "l01"))]
mod tests {
    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }
}
