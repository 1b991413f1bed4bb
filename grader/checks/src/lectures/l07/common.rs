//! What the checks of lecture 07's files share.

// `Failure` is large (its optional images); see check.rs.
#![allow(clippy::result_large_err)]

pub(super) use l02_ray_casting::hit_sphere_stable;
pub(super) use l07_reflection_refraction::{
    Interface, fresnel_dielectric, interface, mirror_direction, refract, schlick,
};
pub(super) use raylab::{Float, Hit, Interval, Ray, Vec3};

pub(super) use crate::check::{CheckResult, close, close3, ensure, fail, maybe, num, v, vec3, wide, wide3};

pub(super) type FresnelFn = fn(Float, Float, Float) -> Float;
pub(super) type MirrorFn = fn(Vec3, Vec3) -> Vec3;
pub(super) type InterfaceFn = fn(&Hit, Float) -> Interface;
pub(super) type RefractFn = fn(Vec3, Vec3, Float) -> Option<Vec3>;

pub(super) const EPS: Float = Float::EPSILON;

/// cos of an angle in degrees, computed in f64 and rounded once.
pub(super) fn cos_deg(degrees: f64) -> Float {
    degrees.to_radians().cos() as Float
}

/// The unit direction meeting the floor y = 0 (normal +y) at `degrees` from
/// the normal, travelling toward +x and down; built in f64, rounded once.
pub(super) fn incoming(degrees: f64) -> Vec3 {
    let theta = degrees.to_radians();
    v(theta.sin() as Float, -theta.cos() as Float, 0.0)
}

pub(super) fn show(t: &Option<Vec3>) -> String {
    maybe(t, |t| vec3(*t)).replace("no hit", "total internal reflection")
}
