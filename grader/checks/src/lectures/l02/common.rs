//! What the checks of lecture 02's files share.

pub(super) use l02_ray_casting::{
    Group, hit_plane, hit_sphere_algebraic, hit_sphere_geometric, hit_sphere_stable,
};
pub(super) use raylab::scene::{Object, Shape};
pub(super) use raylab::{Float, Hit, Intersector, Interval, Ray, Vec3};

pub(super) use super::SPHERE_CAUSE;
pub(super) use crate::check::{
    CheckResult, close, close3, ensure, fail, maybe, num, ray, show_hit, vec3, wide,
};

pub(super) type SphereFn = fn(&Ray, Vec3, Float, Interval) -> Option<Hit>;

/// Tolerance on t, points and normals of a unit sphere a few units away:
/// the three methods round differently, each by a few ulp of 1.
pub(super) const TOL: Float = 64.0 * Float::EPSILON;
