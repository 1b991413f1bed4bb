//! Lecture 03, polygons and triangles: boxes by slabs, point in polygon,
//! ray–polygon, three ray–triangle tests, interpolated normals, meshes.

// Built without its lecture (which does not compile), the crate is its checks' declarations alone.
#![cfg_attr(not(feature = "l03"), allow(unused))]

// The core's modules at the crate's root, where the checks name them (`crate::check::close`).
#[allow(unused_imports)]
use raylab_checks_core::{check, declare_checks, judge, path, remote, rows, stages, trees};

use crate::check::Meta;

declare_checks! {
    "l03", judged;
    Meta::unit(
        "hit_slabs",
        "the span inside a box: generic rays both ways, from inside, misses, an edge touch",
    ) => slabs_cases(hit_slabs),
    Meta::extreme(
        "hit_slabs",
        "axis-parallel-rays",
        "axis-parallel rays, origins on a slab plane (±0 directions), flat boxes, edges and corners, and \
            4,000 rays against exact integer arithmetic: no false misses, never NaN, entry and exit t \
            within 4γ₃",
    ) => slabs_extreme(hit_slabs),
    Meta::unit("hit_box", "the face hit and its normal on all six faces, from outside and from inside")
        .needs(&["03/hit_slabs"]) => box_cases(hit_box),
    Meta::unit(
        "inside_crossings",
        "even–odd: convex, concave, pentagram, test rays through vertices, shared edges",
    ) => crossings_cases(inside_crossings),
    Meta::unit("winding_number", "signed crossings: orientation, pentagram (2), vertices on the test ray")
        => winding_cases(winding_number),
    Meta::unit("newell_normal", "Newell's normal is twice the area along the counter-clockwise normal")
        => newell_cases(newell_normal),
    Meta::unit(
        "hit_polygon",
        "squares in the three axis planes from front and back, a tilted quad, degenerate ones",
    )
    .needs(&["03/newell_normal", "03/inside_crossings", "02/hit_plane"]) => polygon_cases(hit_polygon),
    Meta::unit("hit_triangle_cramer", "t and (β, γ) at vertices, inside, from behind, misses, parallel rays")
        => triangle_cases(hit_triangle_cramer),
    Meta::unit(
        "hit_triangle_moller_trumbore",
        "t and (β, γ) at vertices, inside, from behind, misses, parallel rays",
    ) => triangle_cases(hit_triangle_moller_trumbore),
    Meta::unit(
        "edge_function",
        "e(p, q) = p.x·q.y − p.y·q.x, exactly antisymmetric, its sign decided when it rounds to 0",
    ) => edge_cases(edge_function),
    Meta::unit(
        "hit_triangle_watertight",
        "t and (β, γ) at vertices, inside, from behind, misses, parallel rays",
    )
    .needs(&["03/edge_function"]) => triangle_cases(hit_triangle_watertight),
    Meta::extreme(
        "hit_triangle_watertight",
        "no-leaks",
        "closed meshes, rays from inside aimed exactly at every vertex and edge: zero leaks",
    )
    .needs(&["03/edge_function"]) => triangle_no_leaks(hit_triangle_watertight),
    Meta::unit(
        "interpolate_normal",
        "the blend (1 − β − γ)n₀ + βn₁ + γn₂, normalised; zero (not NaN) when it cancels",
    ) => interpolate_cases(interpolate_normal),
    Meta::unit(
        "hit_triangle",
        "the hit record: normal against the ray, front_face, uv = (β, γ), shading normals",
    )
    .needs(&["03/hit_triangle_watertight", "03/interpolate_normal"]) => hit_triangle_cases(hit_triangle),
    Meta::unit(
        "hit_mesh",
        "the closest triangle whatever the order, mesh uvs (on both triangles) and normals interpolated",
    )
    .needs(&["03/hit_triangle"]) => mesh_cases(hit_mesh),
    Meta::extreme(
        "hit_mesh",
        "no-leaks",
        "closed meshes, rays from inside aimed at every vertex and edge: all hit",
    )
    .needs(&["03/hit_triangle"]) => mesh_no_leaks(hit_mesh),
}

#[cfg(feature = "l03")]
pub mod common;
#[cfg(feature = "l03")]
mod mesh;
#[cfg(feature = "l03")]
mod polygon;
#[cfg(feature = "l03")]
mod slabs;
#[cfg(feature = "l03")]
mod triangle;

#[cfg(feature = "l03")]
pub mod stage;

/// What the rows above run: the checks of each of the lecture's files.
#[cfg(feature = "l03")]
mod code {
    pub(super) use super::{common::*, mesh::*, polygon::*, slabs::*, triangle::*};
}

#[cfg(all(test, feature = "l03"))]
mod tests {
    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }
}
