//! What the checks of lecture 03's files share: imports, the function types they test,
//! tolerances and the show helpers.

#![allow(clippy::result_large_err)] // Failure is check.rs's report, returned by value as in every lecture
#![allow(clippy::unnecessary_cast)] // widening Float to f64 for references is the identity in an f64 build

pub(super) use l03_polygons_triangles::{
    TriangleHit, edge_function, hit_box, hit_mesh, hit_polygon, hit_slabs, hit_triangle, hit_triangle_cramer,
    hit_triangle_moller_trumbore, hit_triangle_watertight, inside_crossings, interpolate_normal,
    newell_normal, winding_number,
};
pub(super) use raylab::math::consts::PI;
pub(super) use raylab::random::Rng;
pub(super) use raylab::scene::Mesh;
pub(super) use raylab::{Float, Hit, Interval, Ray, Vec2, Vec3};

pub(super) use crate::check::{
    CheckResult, Failure, close, close3, ensure, fail, maybe, near3, num, ray, show_hit, show_ray, show_span,
    vec3,
};
pub(super) use raylab_testing::exact::exact_hits;

pub(super) type SlabsFn = fn(&Ray, Vec3, Vec3, Interval) -> Option<(Float, Float)>;
pub(super) type BoxFn = fn(&Ray, Vec3, Vec3, Interval) -> Option<Hit>;
pub(super) type InsideFn = fn(&[Vec2], Vec2) -> bool;
pub(super) type WindingFn = fn(&[Vec2], Vec2) -> i32;
pub(super) type NewellFn = fn(&[Vec3]) -> Vec3;
pub(super) type PolygonFn = fn(&Ray, &[Vec3], Interval) -> Option<Hit>;
pub(super) type TriangleFn = fn(&Ray, Vec3, Vec3, Vec3, Interval) -> Option<TriangleHit>;
pub(super) type EdgeFn = fn(Vec3, Vec3) -> Float;
pub(super) type InterpolateFn = fn(&[Vec3; 3], Float, Float) -> Vec3;
pub(super) type HitTriangleFn = fn(&Ray, &[Vec3; 3], Option<&[Vec3; 3]>, Interval) -> Option<Hit>;
pub(super) type MeshFn = fn(&Ray, &Mesh, Interval) -> Option<Hit>;

/// t, points and unit normals of unit-sized shapes a few units away: each
/// method rounds a handful of operations on numbers ≤ 4 (most inputs are
/// dyadic and exact); 16ε holds them (2e-6 in f32).
pub(super) const TOL: Float = 16.0 * Float::EPSILON;

pub(super) const ALL: Interval = Interval::POSITIVE;
