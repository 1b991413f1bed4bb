//! What the checks of lecture 07's files share.

pub(super) use l07_reflection_refraction::Interface;
pub(super) use raylab::{Float, Hit, Interval, Ray, Vec3};

pub(super) use crate::check::{CheckResult, close, close3, ensure, fail, maybe, num, v, vec3, wide, wide3};

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

// The student's functions, each value taken through `judge::student` (the lecture is `judged`).
crate::rows::student_fns! { l07_reflection_refraction:
    fn schlick(cos_i: Float, eta_i: Float, eta_t: Float) -> Float as FresnelFn;
    fn fresnel_dielectric(cos_i: Float, eta_i: Float, eta_t: Float) -> Float;
    fn mirror_direction(dir: Vec3, n: Vec3) -> Vec3 as MirrorFn;
    fn refract(i: Vec3, n: Vec3, eta_ratio: Float) -> Option<Vec3> as RefractFn, remote;
    fn interface(hit: &Hit, ior: Float) -> Interface as InterfaceFn
        => interfaced(|| l07_reflection_refraction::interface(hit, ior));
}
crate::rows::student_fns! { l02_ray_casting:
    fn hit_sphere_stable(ray: &Ray, center: Vec3, radius: Float, range: Interval) -> Option<Hit>;
}

/// An interface of the student's, taken through `judge::student` field by field (the lecture's
/// type is not the kit's).
#[track_caller]
fn interfaced(f: impl FnOnce() -> Interface) -> Interface {
    let (normal, eta_i, eta_t, entering) = crate::judge::student(|| {
        let i = f();
        (i.normal, i.eta_i, i.eta_t, i.entering)
    });
    Interface { normal, eta_i, eta_t, entering }
}
