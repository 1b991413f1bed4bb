//! Lecture 02, ray casting: spheres three ways, the plane, the closest hit of a group.

// Built without its lecture (which does not compile), the crate is its checks' declarations alone.
#![cfg_attr(not(feature = "l02"), allow(unused))]

// The core's modules at the crate's root, where the checks name them (`crate::check::close`).
#[allow(unused_imports)]
use raylab_checks_core::{check, declare_checks, judge, path, remote, rows, stages, trees};

use crate::check::Meta;

const SPHERE_CAUSE: &str =
    "solve |o + t·d − c|² = r², keep the nearer root inside the range, else the farther one";

declare_checks! {
    "l02", judged;
    Meta::unit(
        "hit_sphere_algebraic",
        "the textbook quadratic at ordinary rays: front, inside, miss, behind, tangent",
    ) => sphere_cases(hit_sphere_algebraic),
    Meta::unit("hit_sphere_geometric", "the slides' geometric construction at ordinary rays")
        => sphere_cases(hit_sphere_geometric),
    Meta::unit("hit_sphere_stable", "the robust quadratic at ordinary rays")
        => sphere_cases(hit_sphere_stable),
    Meta::extreme(
        "hit_sphere_stable",
        "far-small-sphere",
        "a unit sphere 10⁴ away: t within 16 ulp of the distance, computed in f64 by hand's formula",
    )
    .points(2) => far_small_sphere(),
    Meta::unit("hit_plane", "a plane n·p = offset from both sides and a parallel ray") => plane_cases(),
    Meta::unit(
        "closest_hit",
        "three spheres in scrambled order: the nearest wins and its index is the object id",
    )
    .needs(&["02/hit_sphere_stable"]) => closest_of_three(),
    Meta::unit(
        "object_id_image",
        "a 7 × 5 image of a scene the check answers: one ray per pixel in the camera's range, id colours, black misses",
    )
    .needs(CAMERA) => object_id_cases(),
    Meta::unit("depth_image", "the same scene: each pixel the hit's t, black misses").needs(CAMERA) => depth_cases(),
    Meta::unit("normal_image", "the same scene: each pixel the hit's normal as it comes, black misses")
        .needs(CAMERA) => normal_cases(),
}

/// The camera the image checks ask for their pixels' rays (lecture 01's).
const CAMERA: &[&str] = &["01/look_at", "01/screen_coords", "01/PerspectiveCamera::generate_ray"];

#[cfg(feature = "l02")]
pub mod common;
#[cfg(feature = "l02")]
mod group;
#[cfg(feature = "l02")]
mod images;
#[cfg(feature = "l02")]
mod plane;
#[cfg(feature = "l02")]
mod sphere;

#[cfg(feature = "l02")]
pub mod stage;

/// What the rows above run: the checks of each of the lecture's files.
#[cfg(feature = "l02")]
mod code {
    pub(super) use super::{common::*, group::*, images::*, plane::*, sphere::*};
}

#[cfg(all(test, feature = "l02"))]
mod tests {
    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }
}
