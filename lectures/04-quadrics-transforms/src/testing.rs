//! Helpers shared by the unit tests: f64 vector arithmetic for independent
//! reference computations (plain arrays, so the reference never goes through
//! the `Float` code under test), angle measures and a reference unit sphere
//! for the transform tests. The seeded generator is the kit's
//! `raylab::random::Rng`.

use raylab::scene::Transform;
use raylab::{Float, Hit, Interval, Mat4, Ray, Vec3};

/// Machine epsilon of the precision under test.
pub const EPS: Float = Float::EPSILON;

/// A vector as f64 numbers (exact: every `Float` is an f64).
pub fn d3(v: Vec3) -> [f64; 3] {
    [v.x as f64, v.y as f64, v.z as f64]
}

pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

pub fn length(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

pub fn unit(a: [f64; 3]) -> [f64; 3] {
    let l = length(a);
    [a[0] / l, a[1] / l, a[2] / l]
}

/// The angle between two directions, in radians, as atan2(|a × b|, a·b):
/// accurate for tiny angles, where acos(a·b) loses half the digits.
pub fn angle_between(a: [f64; 3], b: [f64; 3]) -> f64 {
    length(cross(a, b)).atan2(dot(a, b))
}

/// The angle between a computed normal and an f64 reference direction.
pub fn angle_to(n: Vec3, reference: [f64; 3]) -> f64 {
    angle_between(d3(n), reference)
}

/// v rotated by `angle` about the unit `axis` (Rodrigues), in f64:
/// v cos θ + (k × v) sin θ + k (k·v)(1 − cos θ).
pub fn rotate(v: [f64; 3], axis: [f64; 3], angle: f64) -> [f64; 3] {
    let (s, c) = angle.sin_cos();
    let kxv = cross(axis, v);
    let kv = dot(axis, v);
    [0, 1, 2].map(|i| v[i] * c + kxv[i] * s + axis[i] * kv * (1.0 - c))
}

/// The roots t₀ ≤ t₁ of |u + t·v|² = 1 (the unit sphere at the origin), in
/// f64, by Newton's method: no closed form, the quadratic formulas being
/// lecture 02's exercises. t_c = −u·v / v·v is the point of the line nearest
/// the centre; when g(t_c) > 0, g(t) = |u + t·v|² − 1, the line misses, else
/// both roots lie within t_c ∓ 1/|v|, where g ≥ 0. g is a convex parabola,
/// so Newton's steps from those two ends move toward their roots and never
/// past them (by halves, at worst, where the roots nearly meet: ≤ ~60 steps).
/// p = u + t·v is formed directly, so a root is as accurate as the line's
/// conditioning allows (an error of about ε·|u|/|v| in t).
pub fn unit_sphere_roots(u: [f64; 3], v: [f64; 3]) -> Option<(f64, f64)> {
    let g = |t: f64| {
        let p = [0, 1, 2].map(|i| u[i] + t * v[i]);
        (dot(p, p) - 1.0, 2.0 * dot(p, v))
    };
    let a = dot(v, v);
    let t_c = -dot(u, v) / a;
    if g(t_c).0 > 0.0 {
        return None;
    }
    let newton = |mut t: f64| {
        for _ in 0..200 {
            let (value, slope) = g(t);
            let next = t - value / slope;
            if value <= 0.0 || slope == 0.0 || next == t {
                break;
            }
            t = next;
        }
        t
    };
    let half = 1.0 / a.sqrt();
    Some((newton(t_c - half), newton(t_c + half)))
}

/// An ellipsoid solved directly in world space, in f64: centre `center`,
/// semi-axes `semi` along the coordinate axes turned by `angle` about the
/// unit `axis`, i.e. Σ (uᵢ/sᵢ)² = 1 with u = R⁻¹(p − center). Returns the
/// first t > 0 of the ray and the unit outward normal there, the gradient
/// R·(u_x/a², u_y/b², u_z/c²). The roots by [`unit_sphere_roots`], in f64,
/// well ahead of the `Float` code.
pub fn ellipsoid_f64(
    origin: [f64; 3],
    dir: [f64; 3],
    center: [f64; 3],
    semi: [f64; 3],
    axis: [f64; 3],
    angle: f64,
) -> Option<(f64, [f64; 3])> {
    let to_local = |v: [f64; 3]| rotate(v, axis, -angle);
    let u0 = to_local([0, 1, 2].map(|i| origin[i] - center[i]));
    let v = to_local(dir);
    let (u0, v) = ([0, 1, 2].map(|i| u0[i] / semi[i]), [0, 1, 2].map(|i| v[i] / semi[i]));
    let (t0, t1) = unit_sphere_roots(u0, v)?;
    let t = [t0, t1].into_iter().find(|&t| t > 0.0)?;
    let gradient = [0, 1, 2].map(|i| (u0[i] + t * v[i]) / semi[i]);
    Some((t, unit(rotate(gradient, axis, angle))))
}

/// A unit sphere at the origin, written independently of lecture 02 so that
/// these tests check the transform machinery alone: the roots of
/// [`unit_sphere_roots`] (in f64, rounded to `Float`), outward normal = the
/// hit point.
pub fn unit_sphere(ray: &Ray, range: Interval) -> Option<Hit> {
    let (t0, t1) = unit_sphere_roots(d3(ray.origin), d3(ray.dir))?;
    let t = [t0, t1].into_iter().map(|t| t as Float).find(|&t| range.contains(t))?;
    Some(Hit::new(ray, t, ray.at(t)))
}

/// The placement T(center)·R(axis, angle)·S(semi) of a unit sphere that makes
/// the ellipsoid of [`ellipsoid_f64`], rounded to `Float`.
pub fn ellipsoid_transform(center: [f64; 3], semi: [f64; 3], axis: [f64; 3], angle: f64) -> Transform {
    let v = |a: [f64; 3]| Vec3::new(a[0] as Float, a[1] as Float, a[2] as Float);
    let world_from_object = Mat4::from_translation(v(center))
        * Mat4::from_axis_angle(v(axis), angle as Float)
        * Mat4::from_scale(v(semi));
    Transform::new(world_from_object).expect("an invertible placement")
}

/// How far the exact normal of [`ellipsoid_f64`] moves when the ray origin
/// moves by one rounding (ε·(|origin|∞ + |center|∞) along each axis): the
/// error that no `Float` computation can avoid. Rays with a large value are
/// ill-conditioned, not badly computed.
pub fn ellipsoid_normal_sensitivity(
    origin: [f64; 3],
    dir: [f64; 3],
    center: [f64; 3],
    semi: [f64; 3],
    axis: [f64; 3],
    angle: f64,
) -> f64 {
    let Some((_, n)) = ellipsoid_f64(origin, dir, center, semi, axis, angle) else { return f64::INFINITY };
    let max_abs = |a: [f64; 3]| a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let delta = EPS as f64 * (max_abs(origin) + max_abs(center));
    (0..3)
        .map(|k| {
            let mut moved = origin;
            moved[k] += delta;
            ellipsoid_f64(moved, dir, center, semi, axis, angle)
                .map_or(f64::INFINITY, |(_, m)| angle_between(m, n))
        })
        .fold(0.0, f64::max)
}
