//! The canonical capped cylinder.
//!
//! In a scene file: `{ type = "cylinder", transform = [...] }`; every other
//! cylinder is this one placed by a transform (see [`crate::hit_transformed`]).

use raylab::{Float, Hit, Interval, Ray, Vec3};

use crate::capped::{first_crossing, slab_z_span};

/// The first crossing of `ray` with the canonical capped cylinder
/// x² + y² ≤ 1, 0 ≤ z ≤ 1 (radius 1, axis along +z, caps at z = 0 and z = 1).
///
/// The solid is the intersection of the infinite cylinder x² + y² ≤ 1 and the
/// slab 0 ≤ z ≤ 1, both convex, so along the ray it is one span
/// [t_in, t_out]: the later of the two entries and the earlier of the two
/// exits. The side gives the quadratic a t² + 2b t + c = 0 with
/// a = d_x² + d_y², b = o_x d_x + o_y d_y, c = o_x² + o_y² − 1, solved with
/// the stable root q = −(b + sign(b)·√(b² − ac)), t = q/a and t = c/q.
/// The discriminant is computed as b² − ac = a − m², with
/// m = o_x d_y − o_y d_x (Lagrange's identity (o·d)² + (o×d)² = |o|²|d|²):
/// b² and ac are both about |o|²|d|² and cancel for a far-away origin (a
/// thin cylinder seen from afar, or one squashed by a transform), m² does
/// not. When a = 0 the ray is parallel to the axis and is inside the tube
/// everywhere (c ≤ 0) or nowhere. The caps give t = −o_z/d_z and
/// t = (1 − o_z)/d_z. Intersecting the spans instead of testing "z in
/// [0, 1]" on the side and "inside the unit disc" on the caps separately
/// means a ray through a rim can never slip between the two tests.
///
/// Returns the smallest of t_in, t_out inside `range` (t_out when the ray
/// starts inside), with outward normals (x, y, 0) on the side, −z on the
/// cap z = 0 and +z on the cap z = 1, faced against the ray by [`Hit::new`].
/// `dir` need not be unit length (t is in the ray's own units) but must not
/// be zero. A ray tangent to the side touches it once (t_in = t_out).
///
/// Book: §4.2 Cylinders and their caps.
pub fn hit_cylinder(ray: &Ray, range: Interval) -> Option<Hit> {
    debug_assert!(ray.dir != Vec3::ZERO, "the ray direction must not be zero");
    // SOLUTION BEGIN
    let (o, d) = (ray.origin, ray.dir);

    // The side: the span inside the infinite cylinder x² + y² ≤ 1.
    let a = d.x * d.x + d.y * d.y;
    let b = o.x * d.x + o.y * d.y;
    let c = o.x * o.x + o.y * o.y - 1.0;
    let (side_in, side_out) = if a == 0.0 {
        // Parallel to the axis: the quadratic degenerates to the constant c.
        if c > 0.0 {
            return None;
        }
        (Float::NEG_INFINITY, Float::INFINITY)
    } else {
        // The discriminant b² − ac = a − m² (Lagrange), m the moment about the axis.
        let m = o.x * d.y - o.y * d.x;
        let discriminant = a - m * m;
        if discriminant < 0.0 {
            return None;
        }
        // The stable root: never subtract two nearly equal numbers.
        let q = -(b + discriminant.sqrt().copysign(b));
        let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
        (t0.min(t1), t0.max(t1))
    };

    // The caps: the span inside the slab 0 ≤ z ≤ 1.
    let caps = slab_z_span(o.z, d.z)?;

    // The solid's first crossing inside the range, and whether a cap made it.
    let (t, on_cap) = first_crossing((side_in, side_out), caps, range)?;
    let p = ray.at(t);
    let outward = if on_cap {
        Vec3::new(0.0, 0.0, if p.z > 0.5 { 1.0 } else { -1.0 })
    } else {
        Vec3::new(p.x, p.y, 0.0)
    };
    // (x, y) vanishes only when rounding has lost the point (an origin some 1e8 radii
    // away in f32): any unit normal is better than a NaN.
    Some(Hit::new(ray, t, outward.try_normalize().unwrap_or(Vec3::Z)))
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{EPS, angle_to, d3};
    use approx::{assert_abs_diff_eq, assert_relative_eq};
    use raylab::math::consts::TAU;
    use raylab::random::Rng;
    use raylab_testing::ray;

    fn hit(o: [Float; 3], d: [Float; 3]) -> Option<Hit> {
        hit_cylinder(&ray(o, d), Interval::POSITIVE)
    }

    // Hand-derived values below use dyadic inputs, so most are exact; the
    // tolerance of 4ε (relative) or 4ε (absolute, for unit normals) covers
    // the few roundings of the quadratic and of the normalisation.

    #[test]
    fn side_hit_from_outside() {
        // x² + 0.6² = 1 gives x = −0.8 on the near side: t = −0.8 − (−3) = 2.2.
        let h = hit([-3.0, 0.6, 0.25], [1.0, 0.0, 0.0]).expect("the side is in the way");
        assert_relative_eq!(h.t, 2.2, max_relative = 4.0 * EPS);
        assert_abs_diff_eq!(h.point, Vec3::new(-0.8, 0.6, 0.25), epsilon = 4.0 * EPS);
        assert_abs_diff_eq!(h.normal, Vec3::new(-0.8, 0.6, 0.0), epsilon = 4.0 * EPS);
        assert!(h.front_face);
    }

    #[test]
    fn t_is_in_the_rays_own_units() {
        // The same ray with dir ×2 reaches x = −1 at half the t: 2/2 = 1.
        let h = hit([-3.0, 0.0, 0.5], [2.0, 0.0, 0.0]).unwrap();
        assert_relative_eq!(h.t, 1.0, max_relative = 4.0 * EPS);
        assert_abs_diff_eq!(h.normal, Vec3::new(-1.0, 0.0, 0.0), epsilon = 4.0 * EPS);
    }

    #[test]
    fn both_caps_from_outside() {
        // Bottom cap: z goes from −1 to 0 at t = 1 (slanted ray, x = 0.3 inside the disc).
        let h = hit([0.0, 0.0, -1.0], [0.3, 0.0, 1.0]).unwrap();
        assert_relative_eq!(h.t, 1.0, max_relative = 4.0 * EPS);
        assert_eq!(h.normal, Vec3::new(0.0, 0.0, -1.0));
        assert!(h.front_face);
        // Top cap: z goes from 3 to 1 at t = 2, normal +z.
        let h = hit([0.5, 0.0, 3.0], [0.0, 0.0, -1.0]).unwrap();
        assert_relative_eq!(h.t, 2.0, max_relative = 4.0 * EPS);
        assert_eq!(h.normal, Vec3::Z);
        assert!(h.front_face);
    }

    #[test]
    fn from_inside_hits_the_exit_with_the_normal_turned_in() {
        // Centre of the cylinder, going +x: the wall at x = 1, t = 1.
        let h = hit([0.0, 0.0, 0.5], [1.0, 0.0, 0.0]).unwrap();
        assert_relative_eq!(h.t, 1.0, max_relative = 4.0 * EPS);
        assert_eq!(h.normal, Vec3::new(-1.0, 0.0, 0.0));
        assert!(!h.front_face);
        assert_eq!(h.outward_normal(), Vec3::X);
        // Going +z: the top cap at t = 0.5, normal faced back down.
        let h = hit([0.0, 0.0, 0.5], [0.0, 0.0, 1.0]).unwrap();
        assert_relative_eq!(h.t, 0.5, max_relative = 4.0 * EPS);
        assert_eq!(h.normal, Vec3::new(0.0, 0.0, -1.0));
        assert!(!h.front_face);
    }

    #[test]
    fn axis_parallel_rays_degenerate_without_nan() {
        // d = ±z makes a = d_x² + d_y² = 0: only the caps can be hit.
        let h = hit([0.0, 0.0, -1.0], [0.0, 0.0, 1.0]).unwrap();
        assert_eq!((h.t, h.normal), (1.0, Vec3::new(0.0, 0.0, -1.0)));
        let h = hit([-0.7, 0.7, 5.0], [0.0, 0.0, -0.5]).unwrap();
        assert_eq!((h.t, h.normal), (8.0, Vec3::Z)); // (5 − 1)/0.5
        // The second crossing: the bottom cap at (5 − 0)/0.5 = 10, from inside.
        let h2 = hit_cylinder(&ray([-0.7, 0.7, 5.0], [0.0, 0.0, -0.5]), Interval::new(8.0, 100.0)).unwrap();
        assert_eq!((h2.t, h2.normal, h2.front_face), (10.0, Vec3::Z, false));
        // Outside the tube (1.5² > 1): a miss, not a NaN.
        assert_eq!(hit([1.5, 0.0, -1.0], [0.0, 0.0, 1.0]), None);
    }

    #[test]
    fn ray_in_a_cap_plane_hits_the_side() {
        // d_z = 0 with o_z = 1 exactly: the slab test keeps the whole line, the side
        // decides: x = −1 at t = 1, normal −x.
        let h = hit([-2.0, 0.0, 1.0], [1.0, 0.0, 0.0]).unwrap();
        assert_eq!((h.t, h.normal), (1.0, Vec3::new(-1.0, 0.0, 0.0)));
        // Just above the top plane: a miss.
        assert_eq!(hit([-2.0, 0.0, 1.0 + 4.0 * EPS], [1.0, 0.0, 0.0]), None);
    }

    #[test]
    fn grazing_ray_hits_the_side_once() {
        // The line x = 1 is tangent to the circle at (1, 0): the discriminant is
        // b² − ac = 4 − 1·4 = 0 and the double root is t = 2.
        let r = ray([1.0, -2.0, 0.5], [0.0, 1.0, 0.0]);
        let h = hit_cylinder(&r, Interval::POSITIVE).unwrap();
        assert_eq!(h.t, 2.0);
        assert!(h.normal.is_finite() && h.normal.dot(r.dir).abs() <= EPS);
        // Nothing beyond the touching point.
        assert_eq!(hit_cylinder(&r, Interval::new(2.0, Float::INFINITY)), None);
        // A hair outside misses; a little inside hits twice, close together.
        assert_eq!(hit([1.0 + 1e-3, -2.0, 0.5], [0.0, 1.0, 0.0]), None);
        let h = hit([0.75, -2.0, 0.5], [0.0, 1.0, 0.0]).unwrap();
        assert_relative_eq!(h.t, 2.0 - (1.0 - 0.75 * 0.75 as Float).sqrt(), max_relative = 4.0 * EPS);
    }

    #[test]
    fn rays_through_the_rims_never_leak() {
        // Aim at a rim point P = (cos φ, sin φ, 0 or 1) from O = P + s·(cos φ, sin φ, 0)
        // + k·(0, 0, ±1), s, k in [0.25, 2]: the ray d = P − O comes from outside, so it
        // enters exactly at the rim (t = 1), on the side or the cap, at 7° or more to
        // both. Testing "z in [0, 1]" on the side and "inside the disc" on the caps
        // separately lets ~5% of these rays slip between the two tests and hit the far
        // wall; intersecting the spans never does. Tolerance: O and d carry a few
        // roundings on |O| ≤ 4, so t = 1 ± 16ε; 64ε leaves room for the 1/sin 7° stretch
        // of grazing entries (measured: 4ε). Normals: unit vectors from p, 1e-4.
        let mut rng = Rng::new(2);
        for _ in 0..5_000 {
            let phi = rng.range(0.0, TAU);
            let top = rng.next_float() < 0.5;
            let rim = Vec3::new(phi.cos(), phi.sin(), if top { 1.0 } else { 0.0 });
            let radial = Vec3::new(phi.cos(), phi.sin(), 0.0);
            let axial = Vec3::new(0.0, 0.0, if top { 1.0 } else { -1.0 });
            let origin = rim + radial * rng.range(0.25, 2.0) + axial * rng.range(0.25, 2.0);
            let h = hit_cylinder(&Ray::new(origin, rim - origin), Interval::POSITIVE)
                .unwrap_or_else(|| panic!("missed the rim point {rim} from {origin}"));
            assert!((h.t - 1.0).abs() <= 64.0 * EPS, "leaked through the rim at {rim}: t = {}", h.t);
            let n = h.outward_normal();
            assert!(
                n.abs_diff_eq(radial, 1e-4) || n.abs_diff_eq(axial, 1e-4),
                "normal {n} at the rim {rim} is neither the side's nor the cap's"
            );
        }
    }

    #[test]
    fn far_origin_keeps_its_digits() {
        // From 1000 radii away: x² + 0.6² = 1 at x = −0.8, t = 1000 − 0.8 = 999.2. In f32,
        // b² − ac = 10⁶ − 999999.375 = 0.625 would give t ≈ 999.209; a − m² = 1 − 0.36 keeps
        // the discriminant exact. Tolerance 4ε·t (c = |o|² − 1 rounds once, relative ε).
        let h = hit([-1000.0, 0.6, 0.5], [1.0, 0.0, 0.0]).unwrap();
        assert!((h.t - 999.2).abs() <= 4.0 * EPS * 999.2, "t = {}", h.t);
        // The point −1000 + t carries ulp(1000) ≈ 6e-5 (f32): the normal within 1e-3.
        assert_abs_diff_eq!(h.normal, Vec3::new(-0.8, 0.6, 0.0), epsilon = 1e-3);
    }

    #[test]
    fn far_away_origin_gives_no_nan() {
        // At 1e8 radii (f32) the constant −1 of c is lost and the side point rounds
        // onto the axis: whatever t comes out, the normal must be a unit vector.
        if let Some(h) = hit([1e8, 0.0, 0.5], [-1.0, 0.0, 0.0]) {
            assert!(h.t.is_finite() && h.normal.is_normalized());
        }
    }

    /// The classic algorithm, in f64: side roots kept when 0 ≤ z ≤ 1, caps kept
    /// inside the unit disc, the nearest t > 0 wins. Stable roots, so that in an f64 build
    /// the reference is no less accurate than the code under test. Returns t and the outward normal.
    fn classic_f64(o: [f64; 3], d: [f64; 3]) -> Option<(f64, [f64; 3])> {
        let at = |t: f64| [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
        let mut candidates = Vec::new();
        let a = d[0] * d[0] + d[1] * d[1];
        let b = o[0] * d[0] + o[1] * d[1];
        let c = o[0] * o[0] + o[1] * o[1] - 1.0;
        let disc = b * b - a * c;
        if a > 0.0 && disc >= 0.0 {
            let q = -(b + disc.sqrt().copysign(b));
            for t in [q / a, c / q] {
                let p = at(t);
                if (0.0..=1.0).contains(&p[2]) {
                    candidates.push((t, [p[0], p[1], 0.0]));
                }
            }
        }
        if d[2] != 0.0 {
            for (z, nz) in [(0.0, -1.0), (1.0, 1.0)] {
                let t = (z - o[2]) / d[2];
                let p = at(t);
                if p[0] * p[0] + p[1] * p[1] <= 1.0 {
                    candidates.push((t, [0.0, 0.0, nz]));
                }
            }
        }
        candidates.into_iter().filter(|c| c.0 > 0.0).min_by(|x, y| x.0.total_cmp(&y.0))
    }

    #[test]
    fn agrees_with_the_classic_algorithm_in_f64() {
        // 10,000 rays from anywhere in [−3, 3]³ through a point at least 0.1 inside
        // the solid, so every ray must hit and none is near-tangent at its hit
        // (the crossing angle is then above ~25°, condition number below ~3).
        // Tolerances: t within 16ε·max(1, t) (a few roundings, times that conditioning);
        // normals within 128ε rad (the hit point carries the error of t, on |p| ≲ 10).
        // Normals are compared away from the rims (1e-3), where side and cap meet.
        let mut rng = Rng::new(4);
        for _ in 0..10_000 {
            let origin = rng.in_cube(3.0);
            let (r, phi) = (0.9 * rng.next_float().sqrt(), rng.range(0.0, TAU));
            let target = Vec3::new(r * phi.cos(), r * phi.sin(), rng.range(0.1, 0.9));
            let ray = Ray::new(origin, (target - origin) * rng.range(0.5, 2.0));
            let h = hit_cylinder(&ray, Interval::POSITIVE).expect("a ray through the inside hits");
            let (t, n) = classic_f64(d3(ray.origin), d3(ray.dir)).expect("the reference hits");
            assert!((h.t as f64 - t).abs() <= 16.0 * EPS as f64 * t.max(1.0), "t {} vs {t}", h.t);
            let p = d3(ray.at(h.t));
            let rim_distance = (1.0 - p[0].hypot(p[1])).abs().hypot(p[2].min(1.0 - p[2]).abs());
            if rim_distance > 1e-3 {
                assert!(
                    angle_to(h.outward_normal(), n) < 128.0 * EPS as f64,
                    "normal {} vs {n:?}",
                    h.outward_normal()
                );
            }
        }
    }
}
