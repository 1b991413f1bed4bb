//! The canonical capped cone.
//!
//! In a scene file: `{ type = "cone", transform = [...] }`; every other cone
//! is this one placed by a transform (see [`crate::hit_transformed`]).

use raylab::{Float, Hit, Interval, Ray, Vec3};

use crate::capped::{first_crossing, slab_z_span};

/// The first crossing of `ray` with the canonical capped cone
/// x² + y² ≤ (1 − z)², 0 ≤ z ≤ 1: base of radius 1 on the plane z = 0, apex
/// at (0, 0, 1).
///
/// The implicit function f = x² + y² − (1 − z)² is negative inside *both*
/// nappes of the double cone; the slab 0 ≤ z ≤ 1 keeps the lower one, which
/// is convex, so along the ray the solid is one span [t_in, t_out] as for
/// the cylinder. With w = 1 − o_z, f along the ray is a t² + 2b t + c with
/// a = d_x² + d_y² − d_z², b = o_x d_x + o_y d_y + w d_z, c = o_x² + o_y² − w²
/// Its sign set depends on a:
/// - a > 0 (flatter than the sides): f ≤ 0 between the two roots;
/// - a < 0 (steeper than the sides): f ≤ 0 outside the roots, one half-line
///   per nappe; the lower nappe is the one before the roots when d_z > 0;
/// - a = 0 (parallel to a side line): f = 2b t + c is linear, one root
///   t = −c/(2b), or none when b = 0 (then inside everywhere or nowhere).
///
/// Roots use the stable form q = −(b + sign(b)·√(b² − ac)), t = q/a, c/q.
/// As for the cylinder, the discriminant comes from the moment
/// m = (o_x, o_y, w) × (d_x, d_y, −d_z) instead of b² − ac, which cancels for a
/// far-away origin: b² − ac = m_x² + m_y² − m_z² (Lagrange's identity for the
/// form x² + y² − z² of the cone).
///
/// Outward normals: the gradient ∇f/2 = (x, y, 1 − z) on the side (length
/// √2·(1 − z) on the surface), −z on the base. At the apex the gradient
/// vanishes and the normal is defined as +z (the axis), so no NaN escapes.
/// `dir` need not be unit length but must not be zero.
///
/// Book: §4.3 Cones and the apex.
pub fn hit_cone(ray: &Ray, range: Interval) -> Option<Hit> {
    debug_assert!(ray.dir != Vec3::ZERO, "the ray direction must not be zero");
    // SOLUTION BEGIN
    let (o, d) = (ray.origin, ray.dir);

    // The side: the span where f = x² + y² − (1 − z)² ≤ 0 on the lower nappe.
    let w = 1.0 - o.z;
    let a = d.x * d.x + d.y * d.y - d.z * d.z;
    let b = o.x * d.x + o.y * d.y + w * d.z;
    let c = o.x * o.x + o.y * o.y - w * w;
    let (side_in, side_out) = if a == 0.0 {
        // Parallel to a side line: f is linear in t.
        if b == 0.0 {
            if c > 0.0 {
                return None;
            }
            (Float::NEG_INFINITY, Float::INFINITY)
        } else {
            let t = -c / (2.0 * b);
            if b > 0.0 { (Float::NEG_INFINITY, t) } else { (t, Float::INFINITY) }
        }
    } else {
        // The discriminant b² − ac = m_x² + m_y² − m_z², m = (o_x, o_y, w) × (d_x, d_y, −d_z).
        let m = Vec3::new(o.x, o.y, w).cross(Vec3::new(d.x, d.y, -d.z));
        let discriminant = m.x * m.x + m.y * m.y - m.z * m.z;
        // For a < 0 the roots always exist (f ≥ 0 where the ray crosses z = 1):
        // a negative discriminant there is rounding, read it as a double root.
        if discriminant < 0.0 && a > 0.0 {
            return None;
        }
        // The stable root: never subtract two nearly equal numbers.
        let q = -(b + discriminant.max(0.0).sqrt().copysign(b));
        let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
        let (r0, r1) = (t0.min(t1), t0.max(t1));
        if a > 0.0 {
            (r0, r1)
        } else if d.z > 0.0 {
            (Float::NEG_INFINITY, r0)
        } else {
            (r1, Float::INFINITY)
        }
    };

    // The base and the apex plane: the span inside the slab 0 ≤ z ≤ 1.
    let caps = slab_z_span(o.z, d.z)?;

    // The solid's first crossing inside the range, and whether a cap made it.
    let (t, on_cap) = first_crossing((side_in, side_out), caps, range)?;
    let p = ray.at(t);
    let outward = if on_cap {
        // The plane z = 1 touches the solid only at the apex: normal +z there.
        Vec3::new(0.0, 0.0, if p.z > 0.5 { 1.0 } else { -1.0 })
    } else {
        Vec3::new(p.x, p.y, 1.0 - p.z)
    };
    // The gradient vanishes at the apex: the axis +z is its normal.
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
        hit_cone(&ray(o, d), Interval::POSITIVE)
    }

    const SQRT_HALF: Float = std::f64::consts::FRAC_1_SQRT_2 as Float;

    // Inputs are dyadic, so the hand-derived values are nearly exact: 4ε covers
    // the few roundings of the roots and of normalising.

    #[test]
    fn side_hit_from_outside() {
        // At z = 0.5 the radius is 1 − z = 0.5: x = −0.5 at t = 2.5. The gradient
        // (x, y, 1 − z) = (−0.5, 0, 0.5) points out and up at 45°.
        let h = hit([-3.0, 0.0, 0.5], [1.0, 0.0, 0.0]).expect("the side is in the way");
        assert_relative_eq!(h.t, 2.5, max_relative = 4.0 * EPS);
        assert_abs_diff_eq!(h.normal, Vec3::new(-SQRT_HALF, 0.0, SQRT_HALF), epsilon = 4.0 * EPS);
        assert!(h.front_face);
    }

    #[test]
    fn base_from_below_and_side_from_above() {
        // Base: z from −1 to 0 at t = 1 (x = 0.25 inside the unit disc), normal −z.
        let h = hit([0.25, 0.0, -1.0], [0.0, 0.0, 1.0]).unwrap();
        assert_eq!((h.t, h.normal, h.front_face), (1.0, Vec3::new(0.0, 0.0, -1.0), true));
        // From above at x = 0.25 the side is met where 1 − z = 0.25, z = 0.75: t = 3 − 0.75.
        let h = hit([0.25, 0.0, 3.0], [0.0, 0.0, -1.0]).unwrap();
        assert_relative_eq!(h.t, 2.25, max_relative = 4.0 * EPS);
        assert_abs_diff_eq!(h.normal, Vec3::new(SQRT_HALF, 0.0, SQRT_HALF), epsilon = 4.0 * EPS);
        // The base's disc has radius 1: x = 1.5 misses.
        assert_eq!(hit([1.5, 0.0, -1.0], [0.0, 0.0, 1.0]), None);
    }

    #[test]
    fn from_inside_hits_the_exit_with_the_normal_turned_in() {
        // At z = 0.25 the radius is 0.75: t = 0.75; outward (1, 0, 1)/√2, faced back.
        let h = hit([0.0, 0.0, 0.25], [1.0, 0.0, 0.0]).unwrap();
        assert_relative_eq!(h.t, 0.75, max_relative = 4.0 * EPS);
        assert_abs_diff_eq!(h.normal, Vec3::new(-SQRT_HALF, 0.0, -SQRT_HALF), epsilon = 4.0 * EPS);
        assert!(!h.front_face);
        // Straight down to the base: t = 0.25, outward −z faced back up.
        let h = hit([0.0, 0.0, 0.25], [0.0, 0.0, -1.0]).unwrap();
        assert_eq!((h.t, h.normal, h.front_face), (0.25, Vec3::Z, false));
    }

    #[test]
    fn the_apex_gives_a_normal_not_a_nan() {
        // Down the axis from z = 3: the first point of the solid is the apex, t = 2;
        // there the gradient (x, y, 1 − z) is zero and the normal is +z by definition.
        let h = hit([0.0, 0.0, 3.0], [0.0, 0.0, -1.0]).unwrap();
        assert_eq!((h.t, h.normal, h.front_face), (2.0, Vec3::Z, true));
        // Up the axis: the base at t = 1, then the apex from inside at t = 2.
        let r = ray([0.0, 0.0, -1.0], [0.0, 0.0, 1.0]);
        assert_eq!(hit_cone(&r, Interval::POSITIVE).unwrap().t, 1.0);
        let h = hit_cone(&r, Interval::new(1.0, Float::INFINITY)).unwrap();
        assert_eq!((h.t, h.normal, h.front_face), (2.0, -Vec3::Z, false));
        // Through the apex, steeper than the sides (a = 0.25 − 1 < 0, f = a(t − 2)²):
        // in at the apex at t = 2.
        let h = hit([-1.0, 0.0, 3.0], [0.5, 0.0, -1.0]).unwrap();
        assert_eq!(h.t, 2.0);
        assert!(h.normal.is_normalized());
        // Skimming the apex horizontally (a double root at t = 2): one touch, finite.
        let h = hit([-2.0, 0.0, 1.0], [1.0, 0.0, 0.0]).unwrap();
        assert_eq!(h.t, 2.0);
        assert!(h.normal.is_normalized());
        // A hair above the apex: nothing.
        assert_eq!(hit([-2.0, 0.0, 1.0 + 4.0 * EPS], [1.0, 0.0, 0.0]), None);
    }

    #[test]
    fn rays_parallel_to_a_side_line_make_a_linear_equation() {
        // d = (−1, 0, 1) is parallel to the side line from (1, 0, 0) to the apex:
        // a = 1 − 1 = 0. From (1, 0, −1): f = (1 − t)² − (2 − t)² = 2t − 3, so the base
        // at t = 1 (x = 0), then out through the side at t = 1.5, point (−0.5, 0, 0.5).
        let r = ray([1.0, 0.0, -1.0], [-1.0, 0.0, 1.0]);
        let h = hit_cone(&r, Interval::POSITIVE).unwrap();
        assert_eq!((h.t, h.normal), (1.0, -Vec3::Z));
        let h = hit_cone(&r, Interval::new(1.0, Float::INFINITY)).unwrap();
        assert_relative_eq!(h.t, 1.5, max_relative = 4.0 * EPS);
        assert_abs_diff_eq!(h.outward_normal(), Vec3::new(-SQRT_HALF, 0.0, SQRT_HALF), epsilon = 4.0 * EPS);
        assert!(!h.front_face);
        // From (3, 0, −1) the same direction only meets the upper nappe (z = 1.5): a miss.
        assert_eq!(hit([3.0, 0.0, -1.0], [-1.0, 0.0, 1.0]), None);
        // Along the side line itself (f ≡ 0): touches the base rim at t = 1, no NaN.
        let h = hit([2.0, 0.0, -1.0], [-1.0, 0.0, 1.0]).unwrap();
        assert_eq!(h.t, 1.0);
        assert!(h.normal.is_normalized());
    }

    #[test]
    fn far_origin_keeps_its_digits() {
        // From 1000 away at z = 0.3: the side at x = −(1 − 0.3), t = 999.3. In f32 the plain
        // b² − ac = 10⁶ − fl(10⁶ − 0.49) = 0.5 would give t ≈ 999.293; the moment
        // m = (−1000, 0, 0.7) × (1, 0, 0) = (0, 0.7, 0) gives m_y² = 0.49. Tolerance 4ε·t.
        let h = hit([-1000.0, 0.0, 0.3], [1.0, 0.0, 0.0]).unwrap();
        assert!((h.t - 999.3).abs() <= 4.0 * EPS * 999.3, "t = {}", h.t);
        // The point −1000 + t carries ulp(1000) ≈ 6e-5 (f32): the normal within 1e-3.
        assert_abs_diff_eq!(h.normal, Vec3::new(-SQRT_HALF, 0.0, SQRT_HALF), epsilon = 1e-3);
    }

    #[test]
    fn axis_parallel_ray_beside_the_apex_meets_the_side() {
        // a = −1 (steeper than the sides). At x = 0.5 the side is at z = 0.5: from
        // z = 2 going down, t = 1.5; the outward normal there is (1, 0, 1)/√2.
        let h = hit([0.5, 0.0, 2.0], [0.0, 0.0, -1.0]).unwrap();
        assert_relative_eq!(h.t, 1.5, max_relative = 4.0 * EPS);
        assert_abs_diff_eq!(h.normal, Vec3::new(SQRT_HALF, 0.0, SQRT_HALF), epsilon = 4.0 * EPS);
    }

    #[test]
    fn rays_through_the_base_rim_never_leak() {
        // As for the cylinder: aim at P = (cos φ, sin φ, 0) from O = P + s·radial − k·z.
        // The solid near the rim is the wedge z ≥ 0, r + z ≤ 1, so the ray d = P − O
        // enters it at P (t = 1) only when it moves inward faster than up: s > k. With
        // k in [0.25, 2], s in [1.25k, 4k] it meets both surfaces at 6° or more.
        // Tolerance 64ε as for the cylinder (|O| ≤ 10; measured: a few ε).
        let mut rng = Rng::new(3);
        for _ in 0..5_000 {
            let phi = rng.range(0.0, TAU);
            let rim = Vec3::new(phi.cos(), phi.sin(), 0.0);
            let k = rng.range(0.25, 2.0);
            let origin = rim * (1.0 + k * rng.range(1.25, 4.0)) - Vec3::Z * k;
            let h = hit_cone(&Ray::new(origin, rim - origin), Interval::POSITIVE)
                .unwrap_or_else(|| panic!("missed the rim point {rim} from {origin}"));
            assert!((h.t - 1.0).abs() <= 64.0 * EPS, "leaked through the rim at {rim}: t = {}", h.t);
            let side = (rim + Vec3::Z) * SQRT_HALF;
            let n = h.outward_normal();
            assert!(
                n.abs_diff_eq(side, 1e-4) || n.abs_diff_eq(-Vec3::Z, 1e-4),
                "normal {n} at the rim {rim} is neither the side's nor the base's"
            );
        }
    }

    /// The classic algorithm, in f64: roots of x² + y² = (1 − z)² kept when
    /// 0 ≤ z ≤ 1, the base kept inside the unit disc, the nearest t > 0 wins. Stable roots, so that in an f64 build
    /// the reference is no less accurate than the code under test.
    fn classic_f64(o: [f64; 3], d: [f64; 3]) -> Option<(f64, [f64; 3])> {
        let at = |t: f64| [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
        let mut candidates = Vec::new();
        let w = 1.0 - o[2];
        let a = d[0] * d[0] + d[1] * d[1] - d[2] * d[2];
        let b = o[0] * d[0] + o[1] * d[1] + w * d[2];
        let c = o[0] * o[0] + o[1] * o[1] - w * w;
        let disc = b * b - a * c;
        if a != 0.0 && disc >= 0.0 {
            let q = -(b + disc.sqrt().copysign(b));
            for t in [q / a, c / q] {
                let p = at(t);
                if (0.0..=1.0).contains(&p[2]) {
                    candidates.push((t, [p[0], p[1], 1.0 - p[2]]));
                }
            }
        }
        if d[2] != 0.0 {
            let t = -o[2] / d[2];
            let p = at(t);
            if p[0] * p[0] + p[1] * p[1] <= 1.0 {
                candidates.push((t, [0.0, 0.0, -1.0]));
            }
        }
        candidates.into_iter().filter(|c| c.0 > 0.0).min_by(|x, y| x.0.total_cmp(&y.0))
    }

    #[test]
    fn agrees_with_the_classic_algorithm_in_f64() {
        // 10,000 rays from [−3, 3]³ through a point well inside the solid
        // (0.1 ≤ z ≤ 0.7, r ≤ 0.8(1 − z): at least 0.04 from the surface), so every
        // ray hits. Tolerances as for the cylinder, t within 16ε·max(1, t) and normals
        // within 128ε rad, both divided by the distance δ of the hit to the apex when
        // δ < 1: there the roots of the two nappes merge (a double root at the apex),
        // so the root's condition number, and the normal's, grow like 1/δ. Normals are
        // not compared within 1e-3 of the rim or the apex.
        let mut rng = Rng::new(5);
        for _ in 0..10_000 {
            let origin = rng.in_cube(3.0);
            let z = rng.range(0.1, 0.7);
            let (r, phi) = (0.8 * (1.0 - z) * rng.next_float().sqrt(), rng.range(0.0, TAU));
            let target = Vec3::new(r * phi.cos(), r * phi.sin(), z);
            let ray = Ray::new(origin, (target - origin) * rng.range(0.5, 2.0));
            let h = hit_cone(&ray, Interval::POSITIVE).expect("a ray through the inside hits");
            let (t, n) = classic_f64(d3(ray.origin), d3(ray.dir)).expect("the reference hits");
            // Where the reference hit lies, in f64.
            let (o, d) = (d3(ray.origin), d3(ray.dir));
            let p = [0, 1, 2].map(|i| o[i] + t * d[i]);
            let apex_distance = p[0].hypot(p[1]).hypot(1.0 - p[2]);
            let rim_distance = (1.0 - p[0].hypot(p[1])).abs().hypot(p[2]);
            let stretch = 1.0 / apex_distance.min(1.0);
            let eps = EPS as f64;
            assert!((h.t as f64 - t).abs() <= 16.0 * eps * t.max(1.0) * stretch, "t {} vs {t}", h.t);
            if rim_distance > 1e-3 && apex_distance > 1e-3 {
                let angle = angle_to(h.outward_normal(), n);
                assert!(angle < 128.0 * eps * stretch, "normal {} vs {n:?}", h.outward_normal());
            }
        }
    }
}
