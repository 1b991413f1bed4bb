//! What the checks of lecture 04's files share.

pub(super) use raylab::math::consts::{FRAC_PI_6, TAU};
pub(super) use raylab::random::Rng;
pub(super) use raylab::scene::Transform;
pub(super) use raylab::{Float, Hit, Interval, Mat4, Ray, Vec2, Vec3};

pub(super) use crate::check::{
    CheckResult, Failure, close, close3, ensure, fail, lazy, maybe, near3, num, ray, show_hit, show_ray,
    show_span, vec3,
};

// The student's functions, each value taken through `judge::student` (the lecture is `judged`).
crate::rows::student_fns! { l04_quadrics_transforms:
    fn slab_z_span(o_z: Float, d_z: Float) -> Option<(Float, Float)> as SpanFn;
    fn first_crossing(side: (Float, Float), caps: (Float, Float), range: Interval) -> Option<(Float, bool)> as CrossingFn;
    fn hit_cone(ray: &Ray, range: Interval) -> Option<Hit> as ShapeFn;
    fn hit_cylinder(ray: &Ray, range: Interval) -> Option<Hit>;
    fn parametric_normal(ds_dalpha: Vec3, ds_dbeta: Vec3) -> Vec3 as ParametricFn;
    fn ray_to_object(ray: &Ray, object_from_world: &Mat4) -> Ray as ToObjectFn;
    fn normal_to_world(n: Vec3, object_from_world: &Mat4) -> Vec3 as NormalFn;
    fn hit_transformed(ray: &Ray, transform: &Transform, range: Interval, hit_local: ShapeFn) -> Option<Hit> as TransformedFn;
}

/// t, points and unit normals of unit-sized shapes a few units away: the
/// inputs are dyadic, the roots, products and normalisations round a few
/// times on numbers ≤ 4; 16ε holds them (2e-6 in f32).
pub(super) const TOL: Float = 16.0 * Float::EPSILON;

pub(super) const ALL: Interval = Interval::POSITIVE;

pub(super) const SQRT_HALF: Float = std::f64::consts::FRAC_1_SQRT_2 as Float;
