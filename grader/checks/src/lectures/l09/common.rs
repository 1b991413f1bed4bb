//! What the checks of lecture 09's files share.

// Widening `Float` to f64 for exact comparisons is a cast in f32 builds and none in f64 ones.
#![allow(clippy::unnecessary_cast)]

pub(super) use std::sync::Arc;

pub(super) use l04_quadrics_transforms::BruteForce;
pub(super) use l09_acceleration::{
    Aabb, BINS, Bin, Bvh, TRAVERSAL_COST, sah_split, sphere_bounds, transform_bounds, triangle_bounds,
};
pub(super) use raylab::random::Rng;
pub(super) use raylab::scene::{Mesh, Object, Shape};
pub(super) use raylab::{Float, Hit, Intersector, Interval, Mat4, Ray, Vec3};

pub(super) use crate::check::{CheckResult, Failure, close, ensure, fail, maybe, num, v, vec3};

pub(super) type UnionFn = fn(Aabb, Aabb) -> Aabb;
pub(super) type UnionPointFn = fn(Aabb, Vec3) -> Aabb;
pub(super) type AreaFn = fn(&Aabb) -> Float;
pub(super) type SlabFn = fn(&Aabb, &Ray, Vec3, Interval) -> Option<(Float, Float)>;
pub(super) type SphereBoundsFn = fn(Vec3, Float) -> Aabb;
pub(super) type TriangleBoundsFn = fn(&[Vec3; 3]) -> Aabb;
pub(super) type TransformBoundsFn = fn(&Aabb, &Mat4) -> Aabb;
pub(super) type SahFn = fn(&[Bin; BINS]) -> Option<(usize, Float)>;
pub(super) type ClosestFn = fn(&Bvh, &Ray, Interval) -> Option<Hit>;
pub(super) type AnyFn = fn(&Bvh, &Ray, Interval) -> bool;

pub(super) const EPS: Float = Float::EPSILON;

pub(super) fn show(b: &Aabb) -> String {
    format!("[{} … {}]", vec3(b.min), vec3(b.max))
}

pub(super) fn same_box(case: &str, got: Aabb, expected: Aabb, cause: &str) -> Result<(), Failure> {
    ensure(got == expected, case, show(&expected), show(&got), cause)
}
