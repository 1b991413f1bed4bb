//! Lecture 09, acceleration: boxes (union, area, the slab test with reciprocals), the bounds of
//! every shape, the SAH split, and the BVH's two traversals against brute force.

// Built without its lecture (which does not compile), the crate is its checks' declarations alone.
#![cfg_attr(not(feature = "l09"), allow(unused))]

// The core's modules at the crate's root, where the checks name them (`crate::check::close`).
#[allow(unused_imports)]
use raylab_checks_core::{check, declare_checks, judge, path, remote, rows, stages, trees};

use crate::check::Meta;

/// What building a BVH over spheres, a plane and a mesh calls, and what brute force (the
/// reference the traversals are compared with) calls.
const BVH_NEEDS: &[&str] = &[
    "02/hit_sphere_stable",
    "02/hit_plane",
    "02/closest_hit",
    "03/hit_triangle_watertight",
    "03/hit_triangle",
    "03/hit_mesh",
    "09/Aabb::union",
    "09/Aabb::union_point",
    "09/Aabb::surface_area",
    "09/Aabb::hit",
    "09/sphere_bounds",
    "09/triangle_bounds",
    "09/sah_split",
];

declare_checks! {
    "l09", judged;
    Meta::unit("Aabb::union", "unions by hand, in both orders, and the empty box as the identity")
        => union_cases(aabb_union),
    Meta::unit("Aabb::union_point", "a point outside, inside, and added to the empty box")
        => union_point_cases(aabb_union_point),
    Meta::unit("Aabb::surface_area", "2(dₓd_y + d_yd_z + d_zdₓ) by hand; flat, segment, point, empty and infinite boxes")
        => area_cases(aabb_surface_area),
    Meta::unit("Aabb::hit", "slab spans by hand: through, beside, behind, beyond the range, from inside, reversed")
        => slab_cases(aabb_hit),
    Meta::extreme(
        "Aabb::hit",
        "slab-boundaries",
        "axis-parallel rays with ±0 components starting on a slab plane, flat boxes across and along: no \
         false miss, never NaN; the range open at both ends; random spans conservative against exact \
         arithmetic",
    ) => slab_boundaries(aabb_hit),
    Meta::unit("sphere_bounds", "c ± r on every axis, holding the exact sphere (outward rounding)")
        => sphere_cases(sphere_bounds),
    Meta::unit("triangle_bounds", "the min and max of the three corners, flat in an axis plane")
        => triangle_cases(triangle_bounds),
    Meta::unit(
        "transform_bounds",
        "a rotated, scaled and moved box holds the images of all 8 corners, computed in f64",
    ) => transform_cases(transform_bounds),
    Meta::unit("sah_split", "binned SAH costs by hand: two clusters, neighbours together, no split")
        => sah_cases(sah_split),
    Meta::unit(
        "Bvh::closest_hit",
        "the hit brute force finds, on a row of spheres listed far first and 3000 random rays in a mixed scene",
    )
    .needs(BVH_NEEDS) => closest_cases(|bvh, r, range| bvh.closest_hit(r, range)),
    Meta::extreme(
        "Bvh::closest_hit",
        "shared-edges",
        "rays from inside a closed icosphere at its every vertex and edge: each hits, as brute force does",
    )
    .needs(BVH_NEEDS) => shared_edges(|bvh, r, range| bvh.closest_hit(r, range)),
    Meta::extreme(
        "Bvh::closest_hit",
        "nearest-first",
        "a row of 200 spheres, down it and up it: the nearest found in at most two leaves' tests",
    )
    .needs(BVH_NEEDS) => nearest_first(|bvh, r, range| bvh.closest_hit(r, range)),
    Meta::unit("Bvh::any_hit", "true exactly when brute force finds a hit: random rays and ranges, blockers beyond the range")
        .needs(BVH_NEEDS) => any_cases(|bvh, r, range| bvh.any_hit(r, range)),
}

#[cfg(feature = "l09")]
mod aabb;
#[cfg(feature = "l09")]
mod bounds;
#[cfg(feature = "l09")]
pub mod common;
#[cfg(feature = "l09")]
mod sah;
#[cfg(feature = "l09")]
mod traverse;

#[cfg(feature = "l09")]
pub mod stage;

/// What the rows above run: the checks of each of the lecture's files.
#[cfg(feature = "l09")]
mod code {
    pub(super) use super::{aabb::*, bounds::*, common::*, sah::*, traverse::*};
}

#[cfg(all(test, feature = "l09"))]
mod tests {
    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }
}
