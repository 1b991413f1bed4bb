//! Lecture 04, quadrics and transforms: capped cylinders and cones, rays
//! taken to object space, normals taken back with (M⁻¹)ᵀ, instancing.

// Built without its lecture (which does not compile), the crate is its checks' declarations alone.
#![cfg_attr(not(feature = "l04"), allow(unused))]

// The core's modules at the crate's root, where the checks name them (`crate::check::close`).
#[allow(unused_imports)]
use raylab_checks_core::{check, declare_checks, judge, path, remote, rows, stages, trees};

use crate::check::Meta;

const CAPPED_NEEDS: &[&str] = &["04/slab_z_span", "04/first_crossing"];

declare_checks! {
    "l04", judged;
    Meta::unit("slab_z_span", "the span of t in 0 ≤ z ≤ 1, ordered, and parallel rays inside or outside")
        => span_cases(slab_z_span),
    Meta::unit(
        "first_crossing",
        "the later entry or the earlier exit of two spans, and which surface made \
        it",
    ) => crossing_cases(first_crossing),
    Meta::unit(
        "hit_cylinder",
        "side and caps from outside and inside, axis-parallel, in a cap plane, tangent, 1,000 rays through \
            the rims",
    )
    .needs(CAPPED_NEEDS) => cylinder_cases(hit_cylinder),
    Meta::extreme(
        "hit_cylinder",
        "far-origin",
        "origins 10³ and 10⁷ radii away (what a squashing transform makes): t within 4ε·t of the f64 root",
    )
    .needs(CAPPED_NEEDS) => far_origin(hit_cylinder, Quadric::Cylinder),
    Meta::unit(
        "hit_cone",
        "side, base, apex (a normal, not NaN), steep rays, rays parallel to a side line, 1,000 rays through \
            the rim",
    )
    .needs(CAPPED_NEEDS) => cone_cases(hit_cone),
    Meta::extreme("hit_cone", "far-origin", "origins 10³ and 10⁷ away: t within 4ε·t of the f64 root")
        .needs(CAPPED_NEEDS) => far_origin(hit_cone, Quadric::Cone),
    Meta::unit(
        "parametric_normal",
        "∂s/∂α × ∂s/∂β normalised: sphere and ellipsoid, the order of factors, \
        a pole",
    ) => parametric_cases(parametric_normal),
    Meta::unit("ray_to_object", "origin as a point, direction as a vector, not renormalised: t is shared")
        => to_object_cases(ray_to_object),
    Meta::unit("normal_to_world", "(M⁻¹)ᵀn normalised for a rotated, squashed, moved object, and a mirror")
        => normal_cases(normal_to_world),
    Meta::unit(
        "hit_transformed",
        "a squashed sphere: world t, world point, the inverse-transpose normal faced against the ray, uv \
            and ids kept",
    )
    .needs(&["04/ray_to_object", "04/normal_to_world"]) => transformed_cases(hit_transformed),
    Meta::extreme(
        "hit_transformed",
        "extreme-scale",
        "a sphere scaled 1e-3 : 1 : 1e3: t in world units (4 rays by hand) and normals within 1e-4 rad of \
            the f64 ellipsoid (4,000 head-on rays)",
    )
    .needs(&["04/ray_to_object", "04/normal_to_world"]) => extreme_scale(hit_transformed),
}

#[cfg(feature = "l04")]
mod capped;
#[cfg(feature = "l04")]
mod common;
#[cfg(feature = "l04")]
mod cone;
#[cfg(feature = "l04")]
mod cylinder;
#[cfg(feature = "l04")]
mod parametric;
#[cfg(feature = "l04")]
mod transformed;

#[cfg(feature = "l04")]
pub mod stage;

/// What the rows above run: the checks of each of the lecture's files.
#[cfg(feature = "l04")]
mod code {
    pub(super) use super::{capped::*, common::*, cone::*, cylinder::*, parametric::*, transformed::*};
}

#[cfg(all(test, feature = "l04"))]
mod tests {
    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }
}
