//! The non-uniform scale pair: lecture 04's normals by (M⁻¹)ᵀ against normals
//! by M, and its hits with t in world units against hits through a
//! renormalised object-space direction, on spheres squashed to 1e-3 : 1 : 1e3.

use std::hint::black_box;

use l02_ray_casting::hit_sphere_stable;
use l04_quadrics_transforms::{hit_transformed, normal_to_world, ray_to_object};
use raylab::random::Rng;
use raylab::scene::Transform;
use raylab::{Hit, Interval, Mat4, Ray, Vec3};

use super::reference::{angle, dot};
use super::row::{Pair, Row, own_precision};
use super::timing::{Effort, time_per_item};
use raylab_testing::{wide, wide3};

/// The catalogued naive normal: the object-space normal taken to the world by
/// M = `world_from_object` itself, as a direction, then normalised.
///
/// Right for rotations and uniform scales only: under S(1e-3, 1, 1e3) a normal
/// at 45° in object space comes out nearly along the long axis instead of the
/// short one, up to 90° off. Book: §4.5 Transforming normals.
pub fn normal_by_m(n: Vec3, transform: &Transform) -> Vec3 {
    transform.world_from_object.transform_vector3(n).normalize()
}

/// Lecture 04's `normal_to_world`, in the signature of [`normal_by_m`].
fn by_inverse_transpose(n: Vec3, transform: &Transform) -> Vec3 {
    normal_to_world(n, &transform.object_from_world)
}

type Normal = fn(Vec3, &Transform) -> Vec3;

/// The naive normal first, the reference method last.
pub const NORMAL_VARIANTS: [(&str, Normal); 2] =
    [("normal_by_m", normal_by_m), ("normal_to_world", by_inverse_transpose)];

/// The unit sphere at the origin in object space (lecture 02's stable sphere).
fn unit_sphere(ray: &Ray, range: Interval) -> Option<Hit> {
    hit_sphere_stable(ray, Vec3::ZERO, 1.0, range)
}

/// The catalogued naive instancing: the object-space direction renormalised
/// (and the range scaled to match), so the local t is a length in object
/// space and the hit's t is not the world t: off by the factor |M⁻¹d|, up to
/// 10³ under S(1e-3, 1, 1e3). Otherwise as lecture 04's `hit_transformed`.
/// Book: §4.4 Transforming the ray, not the object.
pub fn hit_renormalised(ray: &Ray, transform: &Transform, range: Interval) -> Option<Hit> {
    let mut local_ray = ray_to_object(ray, &transform.object_from_world);
    let length = local_ray.dir.length();
    local_ray.dir /= length;
    let local = unit_sphere(&local_ray, Interval::new(range.min * length, range.max * length))?;
    let outward = normal_to_world(local.outward_normal(), &transform.object_from_world);
    let normal = if local.front_face { outward } else { -outward };
    Some(Hit { point: ray.at(local.t), normal, ..local })
}

/// Lecture 04's `hit_transformed` on the unit sphere.
fn hit_reference(ray: &Ray, transform: &Transform, range: Interval) -> Option<Hit> {
    hit_transformed(ray, transform, range, unit_sphere)
}

type HitPlaced = fn(&Ray, &Transform, Interval) -> Option<Hit>;

/// The naive hit first, the reference method last.
pub const HIT_VARIANTS: [(&str, HitPlaced); 2] =
    [("renormalised_dir", hit_renormalised), ("hit_transformed", hit_reference)];

/// A normal farther than this from the truth, in radians, fails: lecture 04's
/// check allows 10⁻⁴ rad at 1e-3 : 1e3 (the reference is within a few ε).
pub const MAX_NORMAL_ERROR: f64 = 1e-4;

/// A relative t error above this fails. The object-space origin M⁻¹o carries
/// an absolute error of about ε·|M⁻¹|·|translation| (5·10³ε ≈ 6·10⁻⁴ object
/// radii in f32 at (5, −2, 300) with the 1e-3 axis), so t is good to a few
/// 10⁻⁴ there at best; 1 % is well above that and far below the factor |M⁻¹d|
/// of a renormalised direction.
pub const MAX_T_ERROR: f64 = 1e-2;

/// An ellipsoid: the unit sphere scaled by `semi`, maybe rotated, then moved to `center`.
struct Placement {
    name: &'static str,
    semi: Vec3,
    center: Vec3,
    /// Rotated by 0.7 rad about (1, 2, 3): for normals only. A world ray rounded at 10³ is
    /// already off by 10³ε ≈ 10⁻⁴ along the rotated 10⁻³ axis, a tenth of it, in f32, so
    /// no method finds its t to 1 %.
    rotated: bool,
}

impl Placement {
    fn world_from_object(&self) -> Mat4 {
        let rotation = if self.rotated {
            Mat4::from_axis_angle(Vec3::new(1.0, 2.0, 3.0).normalize(), 0.7)
        } else {
            Mat4::IDENTITY
        };
        Mat4::from_translation(self.center) * rotation * Mat4::from_scale(self.semi)
    }
}

/// The placements measured.
fn placements() -> [Placement; 4] {
    let squash = Vec3::new(1e-3, 1.0, 1e3);
    let at_origin = |name, semi| Placement { name, semi, center: Vec3::ZERO, rotated: false };
    [
        at_origin("S(0.5, 1, 2)", Vec3::new(0.5, 1.0, 2.0)),
        at_origin("S(1e-3, 1, 1e3)", squash),
        Placement {
            center: Vec3::new(5.0, -2.0, 300.0),
            ..at_origin("S(1e-3, 1, 1e3) at (5, −2, 300)", squash)
        },
        Placement { rotated: true, ..at_origin("R·S(1e-3, 1, 1e3), R 0.7 rad about (1, 2, 3)", squash) },
    ]
}

/// a·b − c·d to about one rounding (Kahan: the rounding of c·d recovered by a
/// fused multiply–add).
fn difference_of_products(a: f64, b: f64, c: f64, d: f64) -> f64 {
    let cd = c * d;
    let error = c.mul_add(-d, cd);
    a.mul_add(b, -cd) + error
}

fn cross_accurate(u: [f64; 3], v: [f64; 3]) -> [f64; 3] {
    [
        difference_of_products(u[1], v[2], u[2], v[1]),
        difference_of_products(u[2], v[0], u[0], v[2]),
        difference_of_products(u[0], v[1], u[1], v[0]),
    ]
}

/// The true world normal direction for the object-space normal `n` under
/// `world_from_object` = [A | c] (its `Float` entries taken as exact): the
/// cofactor matrix of A times n. Its columns are a₁ × a₂, a₂ × a₀, a₀ × a₁ (aᵢ
/// the columns of A), which is det A·(A⁻¹)ᵀ, so no inverse is rounded; each
/// cross product to about one f64 rounding.
pub fn normal_truth(n: Vec3, world_from_object: &Mat4) -> [f64; 3] {
    let a = [world_from_object.x_axis, world_from_object.y_axis, world_from_object.z_axis]
        .map(|c| wide3(c.truncate()));
    let cofactor = [cross_accurate(a[1], a[2]), cross_accurate(a[2], a[0]), cross_accurate(a[0], a[1])];
    let n = wide3(n);
    let sign = dot(a[0], cofactor[0]).signum(); // det A: keeps the outward side outward
    [0, 1, 2].map(|k| sign * (0..3).map(|j| cofactor[j][k] * n[j]).sum::<f64>())
}

/// The first root t > 0 of the world ray (o, d) with the ellipsoid c + S·(unit
/// sphere), S = diag(s), in f64: the object-space ray u = (o − c)/s, v = d/s
/// (t is shared), then the stable quadratic with discriminant |v|² − |u × v|².
pub fn t_truth(o: Vec3, d: Vec3, c: Vec3, s: Vec3) -> Option<f64> {
    let (o, d, c, s) = (wide3(o), wide3(d), wide3(c), wide3(s));
    let u = [0, 1, 2].map(|k| (o[k] - c[k]) / s[k]);
    let v = [0, 1, 2].map(|k| d[k] / s[k]);
    let m = super::reference::cross(u, v);
    let (a, b, cc) = (dot(v, v), dot(u, v), dot(u, u) - 1.0);
    let disc = a - dot(m, m);
    if disc < 0.0 {
        return None;
    }
    let q = -(b + disc.sqrt().copysign(b));
    let (t0, t1) = ((q / a).min(cc / q), (q / a).max(cc / q));
    [t0, t1].into_iter().find(|&t| t > 0.0)
}

/// Every variant on every placement: max normal error in rad (normals), misses and max
/// relative t error (hits), ns per call.
pub fn measure(effort: &Effort) -> Vec<Row> {
    let mut rows = Vec::new();
    for (k, placement) in placements().into_iter().enumerate() {
        let (name, world_from_object) = (placement.name, placement.world_from_object());
        let transform = Transform::new(world_from_object).expect("an invertible placement");
        let mut rng = Rng::new(0x5ca1e + k as u64);
        let normals: Vec<(Vec3, [f64; 3])> = (0..effort.samples)
            .map(|_| {
                let n = rng.unit_vector();
                (n, normal_truth(n, &world_from_object))
            })
            .collect();
        for (variant, normal) in NORMAL_VARIANTS {
            let worst = normals
                .iter()
                .map(|(n, truth)| angle(wide3(normal(*n, &transform)), *truth))
                .fold(0.0, |m: f64, e| if e.is_nan() { f64::NAN } else { m.max(e) });
            let time = time_per_item(effort, normals.len(), || {
                for (n, _) in &normals {
                    black_box(normal(black_box(*n), &transform));
                }
            });
            rows.push(Row {
                pair: Pair::Scale,
                case: format!("{name}: normals ({})", normals.len()),
                variant: variant.to_string(),
                precision: own_precision().to_string(),
                time,
                metrics: vec![("max normal error rad".into(), worst)],
                fails: worst.is_nan() || worst > MAX_NORMAL_ERROR,
                pareto: false,
            });
        }
        if placement.rotated {
            continue;
        }
        // Rays from 2–4 radii out in object space, aimed within half a radius of the centre.
        let (center, semi) = (placement.center, placement.semi);
        let rays: Vec<(Ray, f64)> = (0..effort.samples)
            .filter_map(|_| {
                let from = world_from_object.transform_point3(rng.unit_vector() * rng.range(2.0, 4.0));
                let to = world_from_object.transform_point3(rng.in_ball(0.5));
                let ray = Ray::new(from, (to - from).normalize());
                Some((ray, t_truth(ray.origin, ray.dir, center, semi)?))
            })
            .collect();
        for (variant, hit) in HIT_VARIANTS {
            let (mut misses, mut worst) = (0usize, 0.0f64);
            for (ray, truth) in &rays {
                match hit(ray, &transform, Interval::POSITIVE) {
                    None => misses += 1,
                    Some(h) => {
                        let error = (wide(h.t) - truth).abs() / truth;
                        worst = if error.is_nan() { f64::NAN } else { worst.max(error) };
                    }
                }
            }
            let time = time_per_item(effort, rays.len(), || {
                for (ray, _) in &rays {
                    black_box(hit(black_box(ray), &transform, Interval::POSITIVE));
                }
            });
            rows.push(Row {
                pair: Pair::Scale,
                case: format!("{name}: hits ({})", rays.len()),
                variant: variant.to_string(),
                precision: own_precision().to_string(),
                time,
                metrics: vec![("misses".into(), misses as f64), ("max |Δt|/t".into(), worst)],
                fails: misses > 0 || worst.is_nan() || worst > MAX_T_ERROR,
                pareto: false,
            });
        }
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Float;

    #[test]
    fn truths_on_hand_cases() {
        // S(1e-3, 1, 1e3): the object normal (1, 0, 1)/√2 goes to (1e3, 0, 1e-3) by (M⁻¹)ᵀ,
        // 10⁻⁶ rad from +x; by M to (1e-3, 0, 1e3), nearly +z.
        let m = Mat4::from_scale(Vec3::new(1e-3, 1.0, 1e3));
        let n = Vec3::new(1.0, 0.0, 1.0).normalize();
        let truth = normal_truth(n, &m);
        assert!(angle(truth, [1.0, 0.0, 0.0]) < 2e-6, "{truth:?}");
        let transform = Transform::new(m).unwrap();
        assert!(angle(wide3(normal_by_m(n, &transform)), [0.0, 0.0, 1.0]) < 2e-6);
        // A mirror keeps the outward side outward: S(−1, 1, 1) takes +x to −x.
        let mirror = normal_truth(Vec3::X, &Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0)));
        assert_eq!(mirror, [-1.0, 0.0, 0.0]);
        // The ellipsoid x/1e-3 from x = −1 along +x (unit d): the surface at x = −1e-3, t = 1 − 1e-3.
        let t = t_truth(Vec3::new(-1.0, 0.0, 0.0), Vec3::X, Vec3::ZERO, Vec3::new(1e-3, 1.0, 1e3));
        assert!((t.unwrap() - (1.0 - wide(1e-3 as Float))).abs() < 1e-12, "{t:?}");
    }

    #[test]
    fn a_reduced_run_fails_both_naive_forms_and_passes_the_reference() {
        // By M, normals are off by up to 90° under 1e-3 : 1e3 and ~0.3 rad under 0.5 : 2; the
        // renormalised direction's t is off by |M⁻¹d|; in f32 and f64 alike.
        let effort = Effort { samples: 300, runs: 1, min_batch: std::time::Duration::ZERO, ..Effort::QUICK };
        let rows = measure(&effort);
        for r in &rows {
            let reference = r.variant == "normal_to_world" || r.variant == "hit_transformed";
            assert_eq!(r.fails, !reference, "{r:#?}");
        }
        let by_m = rows.iter().find(|r| r.variant == "normal_by_m" && r.case.starts_with("S(1e-3, 1, 1e3):"));
        assert!(by_m.unwrap().metric("max normal error rad").unwrap() > 1.0, "{by_m:#?}");
    }
}
