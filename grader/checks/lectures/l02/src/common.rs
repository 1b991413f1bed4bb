//! What the checks of lecture 02's files share.

pub(super) use l02_ray_casting::Group;
pub(super) use raylab::scene::{Object, Shape};
pub(super) use raylab::{Float, Hit, Intersector, Interval, Ray, Vec3};

pub(super) use super::SPHERE_CAUSE;
pub(super) use crate::check::{
    CheckResult, close, close3, ensure, fail, maybe, num, ray, show_hit, vec3, wide,
};

/// Tolerance on t, points and normals of a unit sphere a few units away:
/// the three methods round differently, each by a few ulp of 1.
pub(super) const TOL: Float = 64.0 * Float::EPSILON;

// The student's functions, each value taken through `judge::student` (the lecture is `judged`).
crate::rows::student_fns! { l02_ray_casting:
    fn hit_sphere_algebraic(ray: &Ray, center: Vec3, radius: Float, range: Interval) -> Option<Hit> as SphereFn;
    fn hit_sphere_geometric(ray: &Ray, center: Vec3, radius: Float, range: Interval) -> Option<Hit>;
    fn hit_sphere_stable(ray: &Ray, center: Vec3, radius: Float, range: Interval) -> Option<Hit>, remote;
    fn hit_plane(ray: &Ray, normal: Vec3, offset: Float, range: Interval) -> Option<Hit>;
}
