//! What the checks of lecture 05's files share.

// `Failure` is large (its optional images); see check.rs.
#![allow(clippy::result_large_err)]

pub(super) use l05_shading::{
    LightSample, blinn_specular, concentric_disk, distance_falloff, illuminate, lambert, phong_specular,
    reflect, sample_light, shade_light, shade_local, spot_falloff,
};
pub(super) use raylab::scene::{Attenuation, Light, LightKind, Material, Specular};
pub(super) use raylab::{BLACK, Color, Float, Hit, Ray, Vec2, Vec3, WHITE, radians};

pub(super) use crate::check::{CheckResult, close, close3, ensure, num, v, vec3};

pub(super) type DiskFn = fn(Vec2) -> Vec2;
pub(super) type SampleFn = fn(&Light, Vec3, Vec2) -> LightSample;
pub(super) type LambertFn = fn(Vec3, Vec3) -> Float;
pub(super) type FalloffFn = fn(Attenuation, Float) -> Float;
pub(super) type SpotFn = fn(Float, Float, Float) -> Float;
pub(super) type IlluminateFn = fn(&Light, Vec3) -> LightSample;
pub(super) type SpecularFn = fn(Vec3, Vec3, Vec3, Float) -> Float;
pub(super) type ReflectFn = fn(Vec3, Vec3) -> Vec3;
pub(super) type ShadeLightFn = fn(&Material, Color, Vec3, Vec3, &LightSample) -> Color;
pub(super) type ShadeLocalFn = fn(&Material, Color, &Hit, Vec3, &[Light], Color) -> Color;

pub(super) const EPS: Float = Float::EPSILON;
pub(super) const COLOR: Color = Color::new(1.0, 0.5, 0.25);

/// The unit vector in the xy plane at `degrees` from +y (the normal) toward +x.
pub(super) fn at_angle(degrees: Float) -> Vec3 {
    let a = radians(degrees);
    v(a.sin(), a.cos(), 0.0)
}

pub(super) fn v2(u: Vec2) -> String {
    format!("({}, {})", num(u.x), num(u.y))
}

pub(super) fn show(s: &LightSample) -> String {
    format!("L = {}, distance {}, intensity {}", vec3(s.direction), num(s.distance), vec3(s.intensity))
}

pub(super) fn attenuation(c: Float, l: Float, q: Float) -> Attenuation {
    Attenuation { constant: c, linear: l, quadratic: q }
}

pub(super) fn light(kind: LightKind) -> Light {
    Light { color: COLOR, shadows: true, kind }
}
