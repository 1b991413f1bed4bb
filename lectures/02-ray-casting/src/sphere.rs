//! Ray–sphere intersection, three ways: the textbook quadratic, the slides'
//! geometric construction, and the robust form the tracer uses.
//!
//! All three solve |o + t·d − c|² = r² for the sphere of centre c and radius
//! r > 0, return the nearer root inside `range` (else the farther one inside
//! `range`, else `None`), and build the hit with [`Hit::new`] from the outward
//! normal p − c, so the stored normal faces the ray and `front_face` is false
//! for a ray that meets the sphere from the inside. `dir` need not be unit:
//! t is in units of `dir`. A tangent ray (discriminant exactly zero) counts as
//! one hit at the double root.
//!
//! In a scene file: `{ type = "sphere", center = [0, 0, 0], radius = 1 }`.

use raylab::{Float, Hit, Interval, Ray, Vec3};

/// The textbook solution: with f = o − c, the quadratic a t² + b t + c = 0 has
/// a = d·d, b = 2 f·d, c = f·f − r², discriminant Δ = b² − 4ac and roots
/// t = (−b ∓ √Δ) / 2a.
///
/// Exact in exact arithmetic; in floating point b² − 4ac cancels badly when
/// the sphere is small and far (b² ≈ 4ac) and near the silhouette, and
/// −b + √Δ cancels for the root nearer to zero. `dir` must not be zero,
/// `radius` must be positive. Book: §2.2 The algebraic solution.
pub fn hit_sphere_algebraic(ray: &Ray, center: Vec3, radius: Float, range: Interval) -> Option<Hit> {
    debug_assert!(radius > 0.0, "radius must be positive");
    debug_assert!(ray.dir != Vec3::ZERO, "the ray needs a direction");
    // SOLUTION BEGIN
    // The quadratic's coefficients.
    let f = ray.origin - center;
    let a = ray.dir.dot(ray.dir);
    let b = 2.0 * f.dot(ray.dir);
    let c = f.dot(f) - radius * radius;
    // The discriminant: no real root, no hit.
    let discriminant = b * b - 4.0 * a * c;
    if discriminant < 0.0 {
        return None;
    }
    // The two roots, nearer first (a > 0).
    let sqrt_discriminant = discriminant.sqrt();
    let t0 = (-b - sqrt_discriminant) / (2.0 * a);
    let t1 = (-b + sqrt_discriminant) / (2.0 * a);
    // The nearer root inside the range, else the farther one.
    let t = if range.contains(t0) {
        t0
    } else if range.contains(t1) {
        t1
    } else {
        return None;
    };
    Some(Hit::new(ray, t, ray.at(t) - center))
    // SOLUTION END
}

/// The slides' geometric solution. With the unit direction d̂ = d/|d| and
/// L = c − o: t_ca = L·d̂ is the distance along the ray to the point closest
/// to the centre, d² = L·L − t_ca² the squared distance from the centre to the
/// ray; the ray misses when d² > r², else the half chord is
/// t_hc = √(r² − d²) and the hits are at distances t_ca ∓ t_hc, i.e.
/// t = (t_ca ∓ t_hc)/|d| in units of `dir`.
///
/// The slides' early exits ("origin outside and t_ca < 0: miss") are left to
/// the range test, which also handles ranges that start below zero.
/// L·L − t_ca² cancels like b² − 4ac for a small far sphere. `dir` must not
/// be zero, `radius` must be positive. Book: §2.3 The geometric solution.
pub fn hit_sphere_geometric(ray: &Ray, center: Vec3, radius: Float, range: Interval) -> Option<Hit> {
    debug_assert!(radius > 0.0, "radius must be positive");
    debug_assert!(ray.dir != Vec3::ZERO, "the ray needs a direction");
    // SOLUTION BEGIN
    // Distance to the point of closest approach.
    let dir_length = ray.dir.length();
    let unit_dir = ray.dir / dir_length;
    let to_center = center - ray.origin;
    let t_ca = to_center.dot(unit_dir);
    // Squared distance from the centre to the ray: farther than r, a miss.
    let d2 = to_center.dot(to_center) - t_ca * t_ca;
    let r2 = radius * radius;
    if d2 > r2 {
        return None;
    }
    // Half chord, and the two hits in units of `dir`, nearer first.
    let t_hc = (r2 - d2).sqrt();
    let t0 = (t_ca - t_hc) / dir_length;
    let t1 = (t_ca + t_hc) / dir_length;
    // The nearer root inside the range, else the farther one.
    let t = if range.contains(t0) {
        t0
    } else if range.contains(t1) {
        t1
    } else {
        return None;
    };
    Some(Hit::new(ray, t, ray.at(t) - center))
    // SOLUTION END
}

/// The robust solution the tracer uses (Hearn–Baker discriminant; Ray Tracing
/// Gems ch. 7, pbrt-v4 §6.8). With f = o − c, a = d·d, b' = f·d (half of b)
/// and c = f·f − r²:
///
/// - the discriminant b'² − ac equals a·(r² − |f − (b'/a)·d|²), where
///   f − (b'/a)·d is the vector from the centre to the point of the ray closest
///   to it; computed in that form, as a·(r − l)(r + l) with l its length,
///   nothing large cancels, so small far spheres and silhouettes stay exact;
/// - q = −(b' + sign(b')·√(b'² − ac)) adds two numbers of the same sign, and
///   the roots are c/q and q/a (their product is c/a, their sum −2b'/a), so
///   neither root comes from a cancelling subtraction.
///
/// `dir` must not be zero, `radius` must be positive.
/// Book: §2.4 A robust quadratic.
pub fn hit_sphere_stable(ray: &Ray, center: Vec3, radius: Float, range: Interval) -> Option<Hit> {
    debug_assert!(radius > 0.0, "radius must be positive");
    debug_assert!(ray.dir != Vec3::ZERO, "the ray needs a direction");
    // SOLUTION BEGIN
    // The quadratic's coefficients, with b' = b/2.
    let f = ray.origin - center;
    let a = ray.dir.dot(ray.dir);
    let b_half = f.dot(ray.dir);
    let c = f.dot(f) - radius * radius;
    // The discriminant b'² − ac = a·(r − l)(r + l), l = |f − (b'/a)·d|.
    let l = (f - (b_half / a) * ray.dir).length();
    let discriminant = a * (radius - l) * (radius + l);
    if discriminant < 0.0 {
        return None;
    }
    // The roots c/q and q/a without cancellation; q = 0 only for the double root t = 0.
    let q = -(b_half + b_half.signum() * discriminant.sqrt());
    let (t0, t1) = if q == 0.0 {
        (0.0, 0.0)
    } else {
        let (u, v) = (c / q, q / a);
        (u.min(v), u.max(v))
    };
    // The nearer root inside the range, else the farther one.
    let t = if range.contains(t0) {
        t0
    } else if range.contains(t1) {
        t1
    } else {
        return None;
    };
    Some(Hit::new(ray, t, ray.at(t) - center))
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::random::Rng;
    use raylab_testing::roots::{sphere_roots_reference, ulp_wide};
    use raylab_testing::{v, wide};

    type HitSphere = fn(&Ray, Vec3, Float, Interval) -> Option<Hit>;

    const ROUTINES: [(&str, HitSphere); 3] = [
        ("algebraic", hit_sphere_algebraic),
        ("geometric", hit_sphere_geometric),
        ("stable", hit_sphere_stable),
    ];

    const EPS: Float = Float::EPSILON;

    /// The hit is finite, its normal unit and facing against the ray.
    fn assert_well_formed(hit: &Hit, ray: &Ray, what: &str) {
        assert!(hit.t.is_finite() && hit.point.is_finite() && hit.normal.is_finite(), "{what}: {hit:?}");
        // |n| = 1 up to the few roundings of one normalisation.
        assert!((hit.normal.length() - 1.0).abs() <= 4.0 * EPS, "{what}: normal {}", hit.normal);
        assert!(hit.normal.dot(ray.dir) <= 0.0, "{what}: the normal must face the ray");
    }

    #[test]
    fn hits_unit_sphere_from_outside_at_t4() {
        // From (0, 0, 5) toward −z the unit sphere is first met at the pole (0, 0, 1):
        // t = |o − c| − r = 5 − 1 = 4. Every intermediate is a small integer, so t is exact.
        let ray = Ray::new(v(0.0, 0.0, 5.0), -Vec3::Z);
        for (name, hit_sphere) in ROUTINES {
            let hit = hit_sphere(&ray, Vec3::ZERO, 1.0, Interval::POSITIVE).expect(name);
            assert_eq!(hit.t, 4.0, "{name}");
            assert_eq!(hit.point, v(0.0, 0.0, 1.0), "{name}");
            assert_eq!(hit.normal, Vec3::Z, "{name}: the outward normal at the pole");
            assert!(hit.front_face, "{name}: arrived from outside");
        }
    }

    #[test]
    fn ray_from_the_centre_hits_inside_at_t1() {
        // From the centre every direction meets the sphere at t = r = 1, from inside: the
        // outward normal (0, 0, −1) at (0, 0, −1) is flipped to +z, toward the ray's origin.
        let ray = Ray::new(Vec3::ZERO, -Vec3::Z);
        for (name, hit_sphere) in ROUTINES {
            let hit = hit_sphere(&ray, Vec3::ZERO, 1.0, Interval::POSITIVE).expect(name);
            assert_eq!(hit.t, 1.0, "{name}");
            assert_eq!(hit.point, v(0.0, 0.0, -1.0), "{name}");
            assert!(!hit.front_face, "{name}: the hit is from inside");
            assert_eq!(hit.normal, Vec3::Z, "{name}: the normal faces the ray");
            assert_eq!(hit.outward_normal(), -Vec3::Z, "{name}");
        }
    }

    #[test]
    fn longer_direction_gives_proportionally_smaller_t() {
        // p(t) = o + t·d: doubling d halves t. The pole is 4 away: t = 4/|d|, i.e. 2 for
        // |d| = 2 and 8 for |d| = 1/2 (exact: powers of two scale every intermediate exactly).
        for (name, hit_sphere) in ROUTINES {
            for (length, t) in [(2.0, 2.0), (0.5, 8.0)] {
                let ray = Ray::new(v(0.0, 0.0, 5.0), v(0.0, 0.0, -length));
                let hit = hit_sphere(&ray, Vec3::ZERO, 1.0, Interval::POSITIVE).expect(name);
                assert_eq!(hit.t, t, "{name}, |d| = {length}");
                assert_eq!(hit.point, v(0.0, 0.0, 1.0), "{name}, |d| = {length}");
            }
        }
    }

    #[test]
    fn scaling_dir_scales_t_on_generic_rays() {
        // The same line with d·k: t·k is the same distance. For k = 2 every intermediate of
        // every routine is scaled by a power of two, so t/2 is exact; for k = 3 the roundings
        // differ, and the algebraic form's cancellation (≈ 2ε·|f|²/t_hc of distance, see the
        // random-ray test; here |f| ≤ 8, t_hc ≥ 0.6) is ≤ 27ε·|f| in each of the two
        // solves: allow 64ε·scale of distance (measured: 8 in f32, 11 in f64).
        let mut rng = Rng::new(0x5eed_0002);
        for _ in 0..200 {
            let center = rng.in_ball(3.0);
            let origin = center + rng.unit_vector() * rng.range(3.0, 8.0);
            let dir = center + rng.in_ball(0.8) - origin;
            for (name, hit_sphere) in ROUTINES {
                let base = hit_sphere(&Ray::new(origin, dir), center, 1.0, Interval::POSITIVE).expect(name);
                let doubled = hit_sphere(&Ray::new(origin, 2.0 * dir), center, 1.0, Interval::POSITIVE);
                assert_eq!(doubled.map(|h| h.t), Some(base.t / 2.0), "{name}");
                let tripled = hit_sphere(&Ray::new(origin, 3.0 * dir), center, 1.0, Interval::POSITIVE);
                let t3 = tripled.expect(name).t;
                let scale = (origin - center).length() + 1.0;
                let error = (3.0 * t3 - base.t).abs() * dir.length() / (EPS * scale);
                assert!(error <= 64.0, "{name}: {} vs {} ({error} ε·scale)", 3.0 * t3, base.t);
            }
        }
    }

    #[test]
    fn range_excludes_hits_behind_and_beyond() {
        // The unit sphere seen from (0, 0, 5) along −z has roots 4 and 6 (exact, as above).
        let toward = Ray::new(v(0.0, 0.0, 5.0), -Vec3::Z);
        let away = Ray::new(v(0.0, 0.0, 5.0), Vec3::Z);
        for (name, hit_sphere) in ROUTINES {
            let t_of = |ray: &Ray, min: Float, max: Float| {
                hit_sphere(ray, Vec3::ZERO, 1.0, Interval::new(min, max)).map(|h| h.t)
            };
            // Behind the origin: roots −6 and −4.
            assert_eq!(t_of(&away, 0.0, Float::INFINITY), None, "{name}: behind");
            // Both roots beyond max.
            assert_eq!(t_of(&toward, 0.0, 3.9), None, "{name}: beyond max");
            // The near root beyond max, the far root too: still nothing.
            assert_eq!(t_of(&toward, 0.0, 4.0), None, "{name}: t = max is excluded");
            // The near root before min: the far root, met from inside.
            let far = hit_sphere(&toward, Vec3::ZERO, 1.0, Interval::new(4.5, 100.0)).expect(name);
            assert_eq!((far.t, far.front_face, far.normal), (6.0, false, Vec3::Z), "{name}: far root");
            // t exactly at min is excluded (the open interval): min = 4 gives the far root.
            assert_eq!(t_of(&toward, 4.0, 100.0), Some(6.0), "{name}: t = min is excluded");
            // Both roots exactly at the ends: nothing.
            assert_eq!(t_of(&toward, 4.0, 6.0), None, "{name}: (4, 6) is open");
        }
    }

    #[test]
    fn exactly_tangent_ray_hits_once_or_misses_never_nan() {
        // Rays at distance exactly r from the centre (in real numbers): the double root is
        // t = s, the distance from the origin to the touching point. Rounding may tip the ray
        // just in or just out; near a double root t moves with the square root of the
        // rounding error, so allow |t − s| ≤ √(64ε)·(s + r).
        let cases = [
            // Unit sphere from (0, 1, 5) along −z: every intermediate is exact, Δ = 0, t = 5.
            (Vec3::ZERO, 1.0, Vec3::Y, -Vec3::Z, 5.0),
            (v(3.0, -2.0, 7.0), 0.01, Vec3::X, Vec3::Y, 0.05),
            (v(300.0, -200.0, 700.0), 100.0, -Vec3::Z, Vec3::X, 500.0),
            (v(1e3, 2e3, -3e3), 10.0, v(0.6, 0.8, 0.0), v(0.8, -0.6, 0.0), 25.0),
        ];
        for (center, r, touch_dir, dir, s) in cases {
            let origin = center + r * touch_dir - s * dir;
            let ray = Ray::new(origin, dir);
            for (name, hit_sphere) in ROUTINES {
                if let Some(hit) = hit_sphere(&ray, center, r, Interval::POSITIVE) {
                    assert_well_formed(&hit, &ray, name);
                    let tolerance = (64.0 * EPS).sqrt() * (s + r);
                    assert!((hit.t - s).abs() <= tolerance, "{name}, r = {r}: t = {} vs {s}", hit.t);
                }
            }
        }
        // The exact case hits once, at t = 5, in all three: the far root is the same root.
        let ray = Ray::new(v(0.0, 1.0, 5.0), -Vec3::Z);
        for (name, hit_sphere) in ROUTINES {
            assert_eq!(
                hit_sphere(&ray, Vec3::ZERO, 1.0, Interval::POSITIVE).map(|h| h.t),
                Some(5.0),
                "{name}"
            );
            assert!(
                hit_sphere(&ray, Vec3::ZERO, 1.0, Interval::new(5.0, 10.0)).is_none(),
                "{name}: one root"
            );
        }
    }

    #[test]
    fn silhouette_is_resolved_to_a_thousandth_of_the_radius() {
        // Rays along −z from (0, y, 5r) past the centre: y = (1 − 10⁻³)·r hits at
        // t = 5r ∓ √(r² − y²) ≈ 5r ∓ 0.0447r; y = (1 + 10⁻³)·r misses.
        // Tolerances against the double-double reference for the same (rounded) inputs:
        // - algebraic, geometric: Δ = b² − 4ac (or L·L − t_ca²) carries an absolute error
        //   of about 4ε·b² = 400ε·r²; t_hc = √Δ/2 turns it into δΔ/(8·t_hc) ≈ 1100ε·r;
        //   allow 2000ε·r (measured: at most 175ε·r in f32 and f64);
        // - stable: no cancellation, c/q carries a few roundings of t ≈ 5r: allow 16ε·r
        //   (measured: at most 6.3ε·r).
        for r in [1.0, 0.01, 100.0] {
            for center in [Vec3::ZERO, v(3.0, -2.0, 7.0) * r] {
                let inside = Ray::new(center + v(0.0, r * (1.0 - 1e-3), 5.0 * r), -Vec3::Z);
                let outside = Ray::new(center + v(0.0, r * (1.0 + 1e-3), 5.0 * r), -Vec3::Z);
                let (t0, t1) = sphere_roots_reference(inside.origin, inside.dir, center, r).unwrap();
                for (name, hit_sphere) in ROUTINES {
                    let what = format!("{name}, r = {r}, centre {center}");
                    assert!(hit_sphere(&outside, center, r, Interval::POSITIVE).is_none(), "{what}: outside");
                    let near = hit_sphere(&inside, center, r, Interval::POSITIVE).expect(&what);
                    let far_range = Interval::new(near.t, Float::INFINITY);
                    let far = hit_sphere(&inside, center, r, far_range).expect(&what);
                    let factor = if name == "stable" { 16.0 } else { 2000.0 };
                    let tolerance = wide(factor * EPS * r);
                    assert!((wide(near.t) - t0).abs() <= tolerance, "{what}: near {} vs {t0}", near.t);
                    assert!((wide(far.t) - t1).abs() <= tolerance, "{what}: far {} vs {t1}", far.t);
                    assert!(near.front_face && !far.front_face, "{what}: enters, then leaves");
                }
            }
        }
    }

    #[test]
    fn grazing_ray_finds_both_close_roots() {
        // A ray passing the centre at l = (1 − δ)·r meets the sphere twice, t_hc = r·√(2δ)
        // either side of the closest point; δ goes down to 1024ε (3·10⁻⁵ in f32).
        // Only the stable form is expected to resolve it: its l = |f − (b'/a)·d| carries a
        // few roundings of |f| ≈ 5r, and t_hc = √(r² − l²) amplifies an error in l by
        // l/t_hc ≤ r/t_hc; allow 16ε·r·(1 + r/t_hc) with t_hc from the reference
        // (measured: at most 2.2 in f32, 1.9 in f64).
        // The other two may lose the chord entirely (in f32 at δ = 10⁻⁶ both roots collapse
        // to one, off by ~10³ε·r), so for them we only ask for a well-formed hit or a miss.
        let mut rng = Rng::new(0x9_1a2e);
        let mut worst = 0.0f64;
        for delta in [1e-3, 1e-4, 1024.0 * wide(EPS)] {
            for _ in 0..200 {
                let r = rng.range(0.1, 10.0);
                let center = rng.in_ball(10.0);
                let dir = rng.unit_vector() * rng.range(0.5, 2.0);
                let across = dir.normalize().any_orthonormal_vector();
                let origin = center + across * (r * (1.0 - delta) as Float) - dir.normalize() * (5.0 * r);
                let ray = Ray::new(origin, dir);
                let (t0, t1) =
                    sphere_roots_reference(origin, dir, center, r).expect("passes inside by ≈ δ·r");
                let t_hc = (t1 - t0) / 2.0 * wide(dir.length());
                let tolerance = wide(EPS * r) * (1.0 + wide(r) / t_hc);
                let near = hit_sphere_stable(&ray, center, r, Interval::POSITIVE).expect("near root");
                let far = hit_sphere_stable(&ray, center, r, Interval::new(near.t, Float::INFINITY));
                let far = far.expect("far root");
                for (t, reference) in [(near.t, t0), (far.t, t1)] {
                    let error = (wide(t) - reference).abs() * wide(dir.length()) / tolerance;
                    worst = worst.max(error);
                    assert!(error <= 16.0, "δ = {delta}: t = {t} vs {reference} ({error})");
                }
                for (name, hit_sphere) in ROUTINES {
                    if let Some(hit) = hit_sphere(&ray, center, r, Interval::POSITIVE) {
                        assert_well_formed(&hit, &ray, name);
                    }
                }
            }
        }
        println!("grazing: worst stable error {worst:.2} ε·r·(1 + r/t_hc)");
    }

    #[test]
    fn far_small_sphere_stable_within_a_few_ulp_algebraic_worse() {
        // Radius 1 at distance D = 10³…10⁵ along random directions, rays from near the
        // origin aimed within 0.5 of the centre (well inside the silhouette). Errors are
        // in ulp of t (t·ε), against the double-double reference on the same inputs.
        // The stable form: f·f − r² and q carry about three roundings each, so c/q is
        // within γ₆ ≈ 3 ulp; allow 4 (measured: at most 1.8 ulp in f32, 1.6 in f64).
        // The algebraic and geometric forms cancel b² ≈ 4ac (L·L ≈ t_ca²), which have
        // magnitude D²: they lose about log₂(D²) bits.
        let mut rng = Rng::new(0xfa2_5fe2e);
        let mut worst_algebraic_at_1e5 = 0.0;
        for distance in [1e3, 1e4, 1e5] {
            let mut worst = [0.0f64; 3];
            let mut misses = [0usize; 3];
            for _ in 0..500 {
                let origin = rng.in_ball(1.0);
                let center = rng.unit_vector() * distance;
                let dir = (center + rng.in_ball(0.5) - origin).normalize();
                let (t0, _) = sphere_roots_reference(origin, dir, center, 1.0).expect("aimed at the sphere");
                for (i, (_, hit_sphere)) in ROUTINES.iter().enumerate() {
                    match hit_sphere(&Ray::new(origin, dir), center, 1.0, Interval::POSITIVE) {
                        Some(hit) => worst[i] = f64::max(worst[i], (wide(hit.t) - t0).abs() / ulp_wide(t0)),
                        None => misses[i] += 1,
                    }
                }
            }
            println!(
                "far sphere at {distance:e}: worst error in ulp of t (misses of 500): \
                 algebraic {:.0} ({}), geometric {:.0} ({}), stable {:.1} ({})",
                worst[0], misses[0], worst[1], misses[1], worst[2], misses[2]
            );
            assert_eq!(misses[2], 0, "stable: no ray aimed inside the silhouette may miss");
            assert!(worst[2] <= 4.0, "stable at {distance:e}: {} ulp", worst[2]);
            if distance == 1e5 {
                // Measured in f32: algebraic ~4600 ulp and 23% misses; in f64: 1.1·10⁵ ulp.
                worst_algebraic_at_1e5 = if misses[0] > 0 { f64::INFINITY } else { worst[0] };
            }
        }
        // The trade made visible: at 10⁵ the textbook quadratic is at least 100× worse.
        assert!(worst_algebraic_at_1e5 > 400.0, "algebraic at 1e5: {worst_algebraic_at_1e5} ulp");
    }

    #[test]
    fn origin_on_the_surface_no_self_hit_going_out_far_side_going_in() {
        // A ray starting on the sphere (rounded to Float) has one root at t ≈ 0, off by a few
        // ε·scale, where scale = |c| + r; with range.min = 10⁻⁴·scale that root is excluded.
        // Going out (d·n > 0), the other root is behind: no hit. Going in (d·n < 0), the
        // other root is the far side, at the chord length t = −2r·(d·n) for unit d;
        // allow 10⁻⁴·scale (the same margin as the range) plus 64ε·scale.
        let mut rng = Rng::new(0x5e1f);
        let spheres = [(Vec3::ZERO, 1.0), (v(3.0, 1.0, -2.0), 0.05), (v(1e3, -2e3, 5e2), 10.0)];
        for (center, r) in spheres {
            let scale = center.length() + r;
            let range = Interval::new(1e-4 * scale, Float::INFINITY);
            for _ in 0..200 {
                let n = rng.unit_vector();
                let origin = center + r * n;
                let mut dir = rng.unit_vector();
                if dir.dot(n).abs() < 0.1 {
                    continue; // keep off the tangent plane: that is the grazing test's business
                }
                if dir.dot(n) < 0.0 {
                    dir = -dir;
                }
                for (name, hit_sphere) in ROUTINES {
                    let what = format!("{name}, centre {center}, r = {r}, n = {n}");
                    let out = hit_sphere(&Ray::new(origin, dir), center, r, range);
                    assert!(out.is_none(), "{what}: self-hit going out at t = {:?}", out.map(|h| h.t));
                    let inward = Ray::new(origin, -dir);
                    let hit = hit_sphere(&inward, center, r, range).expect(&what);
                    let chord = 2.0 * r * dir.dot(n);
                    assert!(
                        (hit.t - chord).abs() <= 1e-4 * scale + 64.0 * EPS * scale,
                        "{what}: t = {}",
                        hit.t
                    );
                    assert!(!hit.front_face, "{what}: the far side is met from inside");
                    assert_well_formed(&hit, &inward, &what);
                }
            }
        }
    }

    #[test]
    fn all_three_agree_on_random_ordinary_rays() {
        // 10,000 rays in ordinary conditions: origins not within 5% of the surface, lines not
        // within 5% of tangency, |d| in [0.25, 4]. Then all three must agree on hit or miss
        // and on front_face, and on t up to the cancellation in b² − 4ac (or L·L − t_ca²):
        // for unit d its absolute error is about 4ε·b² ≤ 16ε·|f|², and t_hc = √Δ/2 turns
        // that into 2ε·|f|²/t_hc of distance; with |f| ≤ 10r and t_hc ≥ r·√(1 − 0.95²) ≈ 0.31r
        // that is ≤ 65ε·|f|: allow 128ε·scale, scale = |f| + r (measured: 28 in f32, 30 in f64).
        let mut rng = Rng::new(0xa9_4ee);
        let mut worst = 0.0f64;
        let mut hits = 0;
        let mut tested = 0;
        while tested < 10_000 {
            let center = rng.in_ball(10.0);
            let r = rng.range(0.25, 4.0);
            let distance =
                if rng.next_float() < 0.2 { rng.range(0.0, 0.95) } else { rng.range(1.05, 10.0) } * r;
            let origin = center + rng.unit_vector() * distance;
            let dir = (center + rng.in_ball(1.5 * r) - origin).normalize_or(Vec3::X) * rng.range(0.25, 4.0);
            let f = origin - center;
            let l = (f - f.dot(dir) / dir.dot(dir) * dir).length();
            if (l / r - 1.0).abs() < 0.05 || ((f.length() / r) - 1.0).abs() < 0.05 {
                continue;
            }
            tested += 1;
            let ray = Ray::new(origin, dir);
            let stable = hit_sphere_stable(&ray, center, r, Interval::POSITIVE);
            hits += stable.is_some() as usize;
            let scale = wide(f.length() + r);
            for (name, hit_sphere) in &ROUTINES[..2] {
                let other = hit_sphere(&ray, center, r, Interval::POSITIVE);
                assert_eq!(other.is_some(), stable.is_some(), "{name} vs stable: {ray:?}");
                if let (Some(a), Some(b)) = (other, stable) {
                    let error = wide(((a.t - b.t) * dir.length()).abs()) / (wide(EPS) * scale);
                    worst = worst.max(error);
                    assert!(error <= 128.0, "{name} vs stable: {} vs {} ({error} ε·scale)", a.t, b.t);
                    assert_eq!(a.front_face, b.front_face, "{name} vs stable: {ray:?}");
                }
            }
        }
        println!("random rays: {hits} hits of 10000, worst disagreement {worst:.1} ε·scale");
        assert!(hits > 3000, "the rays must exercise hits as well as misses: {hits}");
    }
}
