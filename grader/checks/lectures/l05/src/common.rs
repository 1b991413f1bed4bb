//! What the checks of lecture 05's files share.

pub(super) use l05_shading::LightSample;
pub(super) use raylab::scene::{Attenuation, Light, LightKind, Material, Specular};
pub(super) use raylab::{BLACK, Color, Float, Hit, Ray, Vec2, Vec3, WHITE, radians};

pub(super) use crate::check::{CheckResult, close, close3, ensure, num, v, vec3};

// The student's functions, each value taken through `judge::student` (the lecture is `judged`).
crate::rows::student_fns! { l05_shading:
    fn concentric_disk(u: Vec2) -> Vec2 as DiskFn;
    fn lambert(n: Vec3, l: Vec3) -> Float as LambertFn, remote;
    fn distance_falloff(attenuation: Attenuation, distance: Float) -> Float as FalloffFn;
    fn spot_falloff(cos_angle: Float, inner: Float, outer: Float) -> Float as SpotFn;
    fn phong_specular(n: Vec3, l: Vec3, v: Vec3, exponent: Float) -> Float as SpecularFn;
    fn blinn_specular(n: Vec3, l: Vec3, v: Vec3, exponent: Float) -> Float;
    fn reflect(v: Vec3, n: Vec3) -> Vec3 as ReflectFn;
    fn shade_light(material: &Material, diffuse: Color, n: Vec3, v: Vec3, sample: &LightSample) -> Color as ShadeLightFn;
    fn shade_local(material: &Material, diffuse: Color, hit: &Hit, v: Vec3, lights: &[Light], ambient: Color)
        -> Color as ShadeLocalFn;
    fn illuminate(light: &Light, point: Vec3) -> LightSample as IlluminateFn
        => sampled(|| l05_shading::illuminate(light, point));
    fn sample_light(light: &Light, point: Vec3, u: Vec2) -> LightSample as SampleFn
        => sampled(|| l05_shading::sample_light(light, point, u));
}

/// A light sample of the student's, taken through `judge::student` field by field (the
/// lecture's type is not the kit's).
#[track_caller]
fn sampled(sample: impl FnOnce() -> LightSample) -> LightSample {
    let (direction, distance, intensity) = crate::judge::student(|| {
        let s = sample();
        (s.direction, s.distance, s.intensity)
    });
    LightSample { direction, distance, intensity }
}

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
