//! What the checks of lecture 03's files share: imports, the function types they test,
//! tolerances and the show helpers.

pub(super) use l03_polygons_triangles::TriangleHit;
pub(super) use raylab::math::consts::PI;
pub(super) use raylab::math::gamma;
pub(super) use raylab::random::Rng;
pub(super) use raylab::scene::Mesh;
pub(super) use raylab::{Float, Hit, Interval, Ray, Vec2, Vec3};

pub(super) use crate::check::{
    CheckResult, Failure, close, close3, ensure, fail, lazy, maybe, near3, num, ray, show_hit, show_ray,
    show_span, vec3,
};
pub(super) use raylab_testing::boxes::{GridRay, grid_ray, sixteenths};
pub(super) use raylab_testing::exact::{Ratio, exact_span};
pub(super) use std::fmt::Display;

// The student's functions, each value taken through `judge::student` (the lecture is `judged`).
crate::rows::student_fns! { l03_polygons_triangles:
    fn hit_slabs(ray: &Ray, min: Vec3, max: Vec3, range: Interval) -> Option<(Float, Float)> as SlabsFn, remote;
    fn hit_box(ray: &Ray, min: Vec3, max: Vec3, range: Interval) -> Option<Hit> as BoxFn;
    fn inside_crossings(polygon: &[Vec2], p: Vec2) -> bool as InsideFn;
    fn winding_number(polygon: &[Vec2], p: Vec2) -> i32 as WindingFn;
    fn newell_normal(vertices: &[Vec3]) -> Vec3 as NewellFn;
    fn hit_polygon(ray: &Ray, vertices: &[Vec3], range: Interval) -> Option<Hit> as PolygonFn;
    fn edge_function(p: Vec3, q: Vec3) -> Float as EdgeFn;
    fn interpolate_normal(normals: &[Vec3; 3], beta: Float, gamma: Float) -> Vec3 as InterpolateFn;
    fn hit_triangle(ray: &Ray, vertices: &[Vec3; 3], normals: Option<&[Vec3; 3]>, range: Interval) -> Option<Hit> as HitTriangleFn;
    fn hit_mesh(ray: &Ray, mesh: &Mesh, range: Interval) -> Option<Hit> as MeshFn;
    fn hit_triangle_cramer(ray: &Ray, a: Vec3, b: Vec3, c: Vec3, range: Interval)
        -> Option<TriangleHit> as TriangleFn => triangle_hit(|| l03_polygons_triangles::hit_triangle_cramer(ray, a, b, c, range));
    fn hit_triangle_moller_trumbore(ray: &Ray, a: Vec3, b: Vec3, c: Vec3, range: Interval)
        -> Option<TriangleHit> => triangle_hit(|| l03_polygons_triangles::hit_triangle_moller_trumbore(ray, a, b, c, range));
    fn hit_triangle_watertight(ray: &Ray, a: Vec3, b: Vec3, c: Vec3, range: Interval)
        -> Option<TriangleHit> => triangle_hit(|| l03_polygons_triangles::hit_triangle_watertight(ray, a, b, c, range));
}

/// A triangle hit of the student's, taken through `judge::student` field by field (the
/// lecture's type is not the kit's).
#[track_caller]
fn triangle_hit(hit: impl FnOnce() -> Option<TriangleHit>) -> Option<TriangleHit> {
    crate::judge::student(|| hit().map(|h| (h.t, h.beta, h.gamma))).map(|(t, beta, gamma)| TriangleHit {
        t,
        beta,
        gamma,
    })
}

/// t, points and unit normals of unit-sized shapes a few units away: each
/// method rounds a handful of operations on numbers ≤ 4 (most inputs are
/// dyadic and exact); 16ε holds them (2e-6 in f32).
pub(super) const TOL: Float = 16.0 * Float::EPSILON;

pub(super) const ALL: Interval = Interval::POSITIVE;
