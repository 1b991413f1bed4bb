//! What the checks of lecture 09's files share.

pub(super) use std::sync::Arc;

pub(super) use l04_quadrics_transforms::BruteForce;
pub(super) use l09_acceleration::{Aabb, BINS, Bin, Bvh, TRAVERSAL_COST};
pub(super) use raylab::random::Rng;
pub(super) use raylab::scene::{Mesh, Object, Shape};
pub(super) use raylab::{Float, Hit, Intersector, Interval, Mat4, Ray, Vec3};

pub(super) use crate::check::{CheckResult, Failure, close, ensure, fail, lazy, maybe, num, v, vec3};

pub(super) use crate::judge::student;

// The student's functions, each value taken through `judge::student` (the lecture is `judged`);
// a box crosses as its two corners.
crate::rows::student_fns! { l09_acceleration:
    fn sah_split(bins: &[Bin; BINS]) -> Option<(usize, Float)> as SahFn;
    fn aabb_surface_area(min: Vec3, max: Vec3) -> Float as AreaFn = Aabb::new(min, max).surface_area(), remote;
    fn aabb_hit(b: &Aabb, ray: &Ray, inv_dir: Vec3, range: Interval) -> Option<(Float, Float)> as SlabFn
        = b.hit(ray, inv_dir, range);
    fn aabb_union(a: Aabb, b: Aabb) -> Aabb as UnionFn => boxed(|| a.union(b));
    fn aabb_union_point(a: Aabb, p: Vec3) -> Aabb as UnionPointFn => boxed(|| a.union_point(p));
    fn sphere_bounds(center: Vec3, radius: Float) -> Aabb as SphereBoundsFn
        => boxed(|| l09_acceleration::sphere_bounds(center, radius));
    fn triangle_bounds(vertices: &[Vec3; 3]) -> Aabb as TriangleBoundsFn
        => boxed(|| l09_acceleration::triangle_bounds(vertices));
    fn transform_bounds(local: &Aabb, world_from_object: &Mat4) -> Aabb as TransformBoundsFn
        => boxed(|| l09_acceleration::transform_bounds(local, world_from_object));
}

/// A box of the student's code, through `judge::student` as its corners.
#[track_caller]
fn boxed(f: impl FnOnce() -> Aabb) -> Aabb {
    let (min, max) = student(|| {
        let b = f();
        (b.min, b.max)
    });
    Aabb::new(min, max)
}

pub(super) type ClosestFn = fn(&Bvh, &Ray, Interval) -> Option<Hit>;
pub(super) type AnyFn = fn(&Bvh, &Ray, Interval) -> bool;

pub(super) const EPS: Float = Float::EPSILON;

pub(super) fn show(b: &Aabb) -> String {
    format!("[{} … {}]", vec3(b.min), vec3(b.max))
}

pub(super) fn same_box(case: &str, got: Aabb, expected: Aabb, cause: &str) -> Result<(), Failure> {
    ensure(got == expected, case, show(&expected), show(&got), cause)
}
