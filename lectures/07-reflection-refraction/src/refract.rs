//! Refraction by Snell's law, total internal reflection, and which side of a
//! surface a ray comes from.
//!
//! In a scene file: `[materials.glass]` with `transparent = [0.9, 0.9, 0.9]`
//! and `ior = 1.5` (the outside of every object is vacuum, η = 1).

use raylab::{Float, Hit, Vec3};

/// The two media at a hit: the normal facing the incoming ray and the indices
/// of refraction on either side.
///
/// `eta_i` is the index of the medium the ray travels in, `eta_t` the index of
/// the medium it would be transmitted into. `entering` is true when the ray
/// arrives from outside the object (vacuum, η = 1) and goes into it.
/// Book: §7.4 Entering and leaving.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interface {
    /// Unit normal facing against the incoming ray (`normal·dir ≤ 0`).
    pub normal: Vec3,
    /// Index of refraction on the incoming side.
    pub eta_i: Float,
    /// Index of refraction on the transmitted side.
    pub eta_t: Float,
    /// True when the ray goes from outside into the object.
    pub entering: bool,
}

impl Interface {
    /// The ratio η = η_i/η_t that [`refract`] takes.
    pub fn eta_ratio(&self) -> Float {
        self.eta_i / self.eta_t
    }
}

/// The interface a ray crosses at `hit` on an object of index of refraction
/// `ior`, surrounded by vacuum.
///
/// `hit.normal` already faces the incoming ray and `hit.front_face` tells on
/// which side it arrived: from outside (front face), the ray enters, η_i = 1
/// and η_t = `ior`; from inside (back face), it leaves, η_i = `ior` and
/// η_t = 1. The normal is `hit.normal` in both cases — never the outward
/// normal, which points the wrong way for a ray leaving the object.
///
/// `ior` must be positive and finite (the scene loaders check it).
/// Book: §7.4 Entering and leaving.
pub fn interface(hit: &Hit, ior: Float) -> Interface {
    debug_assert!(ior > 0.0 && ior.is_finite(), "the index of refraction must be positive, got {ior}");
    // SOLUTION BEGIN
    if hit.front_face {
        // From outside: vacuum to the material.
        Interface { normal: hit.normal, eta_i: 1.0, eta_t: ior, entering: true }
    } else {
        // From inside: the material to vacuum.
        Interface { normal: hit.normal, eta_i: ior, eta_t: 1.0, entering: false }
    }
    // SOLUTION END
}

/// The direction of the ray transmitted through a surface, by Snell's law
/// η_i sin θ_i = η_t sin θ_t, or `None` on total internal reflection.
///
/// `i` is the unit direction of the incoming ray (toward the surface), `n` the
/// unit normal facing against it (i·n ≤ 0), `eta_ratio` = η = η_i/η_t (the
/// index of the side the ray comes from over the index of the side it goes
/// to). With cos θ_i = −i·n, clamped to [0, 1] first (rounding can put i·n a
/// little above 0 for a grazing ray or below −1 for a normal one), and
///
///   sin²θ_t = η²(1 − cos²θ_i), computed as (η·η)·(1 − cos θ_i·cos θ_i),
///
/// there is no transmitted ray when sin²θ_t ≥ 1: all light is reflected
/// (total internal reflection, possible only when η > 1, past the critical
/// angle θ_c = arcsin(1/η)). Otherwise cos θ_t = √(1 − sin²θ_t) and
///
///   t = η i + (η cos θ_i − cos θ_t) n,
///
/// the tangential part of i scaled by η plus the normal part −cos θ_t n. It is
/// unit length (|t|² = η² sin²θ_i + cos²θ_t = 1), lies in the plane of i and
/// n, and goes through the surface (t·n = −cos θ_t < 0). Never NaN for unit
/// inputs and a positive finite ratio. Book: §7.2 Snell's law and the
/// refracted ray, §7.3 Total internal reflection.
pub fn refract(i: Vec3, n: Vec3, eta_ratio: Float) -> Option<Vec3> {
    debug_assert!(i.is_normalized(), "the incoming direction must be unit length, got {i}");
    debug_assert!(n.is_normalized(), "the normal must be unit length, got {n}");
    debug_assert!(eta_ratio > 0.0 && eta_ratio.is_finite(), "η_i/η_t must be positive, got {eta_ratio}");
    // SOLUTION BEGIN
    // The cosine of the angle of incidence, kept in [0, 1] against rounding.
    let cos_i = (-i.dot(n)).clamp(0.0, 1.0);

    // Snell's law for the sine of the transmitted angle; past 1 there is none.
    let sin2_t = eta_ratio * eta_ratio * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return None;
    }

    // The transmitted direction: bent tangential part plus the new normal part.
    let cos_t = (1.0 - sin2_t).sqrt();
    Some(eta_ratio * i + (eta_ratio * cos_i - cos_t) * n)
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Ray;
    use raylab_testing::refraction::{ExactlyOne, sin2_t_exactly_one};
    use raylab_testing::{v, wide, wide3};

    const EPS: Float = Float::EPSILON;

    /// The unit direction that meets the surface y = 0 (normal +y) at `degrees`
    /// from the normal, travelling in +x and down; built in f64 and rounded once.
    fn incoming(degrees: f64) -> Vec3 {
        let theta = degrees.to_radians();
        v(theta.sin() as Float, -theta.cos() as Float, 0.0)
    }

    /// The angle between two directions, in degrees, computed in f64.
    fn angle_between(a: Vec3, b: Vec3) -> f64 {
        let ([ax, ay, az], [bx, by, bz]) = (wide3(a), wide3(b));
        let cross = [ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx];
        let sin = cross.iter().map(|c| c * c).sum::<f64>().sqrt();
        sin.atan2(ax * bx + ay * by + az * bz).to_degrees()
    }

    /// sin of the angle between a direction in the xy plane and the y axis, in f64.
    fn sin_from_y(a: Vec3) -> f64 {
        let [x, y, _] = wide3(a);
        x.abs() / x.hypot(y)
    }

    #[test]
    fn snell_air_to_glass_at_30_degrees() {
        // i = (sin 30°, −cos 30°, 0) = (1/2, −√3/2, 0), η = 1/1.5: sin θ_t = sin 30°/1.5 = 1/3,
        // cos θ_t = √(1 − 1/9) = 2√2/3, so t = (1/3, −2√2/3, 0).
        // Tolerance 8ε per component: √3/2 is rounded, then about six roundings of values ≤ 1.
        let i = v(0.5, -(3.0 as Float).sqrt() / 2.0, 0.0);
        let t = refract(i, Vec3::Y, 1.0 / 1.5).expect("air to glass always refracts");
        let expected = v(1.0 / 3.0, -(8.0 as Float).sqrt() / 3.0, 0.0);
        assert!((t - expected).abs().max_element() <= 8.0 * EPS, "t = {t}, expected {expected}");
    }

    #[test]
    fn glass_to_air_retraces_the_path() {
        // Light paths are reversible: t = (1/3, −2√2/3, 0) leaving glass (η = 1.5) at sin θ = 1/3
        // comes out at sin θ = 1.5/3 = 1/2, the 30° ray it came from.
        let t = v(1.0 / 3.0, -(8.0 as Float).sqrt() / 3.0, 0.0);
        let back = refract(t, Vec3::Y, 1.5).expect("below the critical angle");
        let expected = v(0.5, -(3.0 as Float).sqrt() / 2.0, 0.0);
        assert!((back - expected).abs().max_element() <= 16.0 * EPS, "back = {back}");
        // At every angle, into glass and out again gives the original direction. The way back
        // takes cos θ_i = √(1 − sin²θ_i), whose absolute error grows like ε/cos θ_i near grazing:
        // tolerance 16ε + 4ε/cos θ_i.
        for tenth in 0..=890 {
            let degrees = tenth as f64 / 10.0;
            let i = incoming(degrees);
            let t = refract(i, Vec3::Y, 1.0 / 1.5).expect("air to glass always refracts");
            let back = refract(t, Vec3::Y, 1.5).expect("the reverse path exists");
            let tolerance = 16.0 * EPS + 4.0 * EPS / degrees.to_radians().cos() as Float;
            let error = (back - i).abs().max_element();
            assert!(error <= tolerance, "{degrees}°: error {error:e} > {tolerance:e}");
        }
    }

    #[test]
    fn normal_incidence_keeps_the_direction() {
        // cos θ_i = 1, sin²θ_t = 0, cos θ_t = 1: t = η(−n) + (η − 1)n = −n for every η, no NaN.
        // Tolerance 4ε: the tilted normal is rounded, and η·(−n) + (η − 1)n rounds a few times.
        let tilted = v(1.0, 2.0, -2.0) / 3.0;
        for n in [Vec3::Y, -Vec3::Z, tilted.normalize()] {
            for eta in [1.0 / 1.5, 1.5, 1.0 / 2.4, 2.4, 1.0] {
                let t = refract(-n, n, eta).expect("normal incidence always refracts");
                assert!((t + n).abs().max_element() <= 4.0 * EPS, "n = {n}, η = {eta}: t = {t}");
            }
        }
    }

    #[test]
    fn eta_ratio_one_leaves_the_direction_unchanged() {
        // η = 1: sin θ_t = sin θ_i, so t = i + (cos θ_i − cos θ_t)n = i. The code takes
        // cos θ_t = √(1 − (1 − cos²θ_i)), which loses about ε/(2 cos θ_i) to cancellation:
        // tolerance 8ε + ε/cos θ_i.
        for degrees in [0.0, 10.0, 30.0, 45.0, 60.0, 80.0, 85.0, 89.0] {
            let i = incoming(degrees);
            let t = refract(i, Vec3::Y, 1.0).expect("no bending, no reflection");
            let tolerance = 8.0 * EPS + EPS / (degrees as Float).to_radians().cos();
            assert!((t - i).abs().max_element() <= tolerance, "{degrees}°: t = {t}, i = {i}");
        }
    }

    #[test]
    fn tir_returns_none_just_past_the_critical_angle() {
        // Glass to air, η = 1.5: sin θ_c = 1/1.5, θ_c = arcsin(2/3) = 41.8103149° (by hand:
        // asin 0.6667 in radians is 0.7297277, × 180/π).
        let critical = 41.810_314_9;
        assert!(((1.0 / 1.5f64).asin().to_degrees() - critical).abs() < 1e-7);

        // 0.001° below: sin θ_t = 1.5 sin(θ_c − δ) ≈ 1 − (√5/2)δ with δ = 0.001° = 1.745329·10⁻⁵
        // rad (1.5 cos θ_c = 1.5·√5/3 = √5/2), so cos²θ_t ≈ √5·δ = 3.9027·10⁻⁵ and
        // cos θ_t ≈ 6.247·10⁻³: the ray leaves nearly along the surface (θ_t ≈ 89.64°).
        // Tolerance 5 %: in f32, sin²θ_t ≈ 1 − 3.9·10⁻⁵ carries an absolute error of a few ε,
        // about 1 % of cos²θ_t, and rounding i to f32 moves cos²θ_t by another 0.3 %.
        let t = refract(incoming(critical - 0.001), Vec3::Y, 1.5).expect("just below critical");
        assert!(t.is_finite(), "t = {t}");
        let cos_t = -t.dot(Vec3::Y);
        assert!((cos_t - 6.247e-3).abs() <= 0.05 * 6.247e-3, "cos θ_t = {cos_t}");
        assert!((t.length() - 1.0).abs() <= 4.0 * EPS, "|t| = {}", t.length());

        // 0.001° above: sin²θ_t ≈ 1 + 3.9·10⁻⁵ > 1, total internal reflection.
        assert_eq!(refract(incoming(critical + 0.001), Vec3::Y, 1.5), None);
        // Far past it too, up to grazing.
        for degrees in [45.0, 60.0, 89.0, 90.0] {
            assert_eq!(refract(incoming(degrees), Vec3::Y, 1.5), None, "{degrees}°");
        }
    }

    #[test]
    fn tir_rule_is_sin2_at_least_one_even_when_it_rounds_to_one() {
        // Cases where sin²θ_t = (η·η)(1 − cos²θ_i) rounds to exactly 1: cos θ_i = k/64 (so
        // 1 − cos²θ_i is exact) and η among the floats nearest 1/√(1 − cos²θ_i). Exactly 1 means
        // θ_t = 90°: no transmitted ray, so None (a `>` test would send a ray along the surface).
        // The float just below such an η gives sin²θ_t < 1 and a ray.
        let mut cases = 0;
        // i·n = −cos θ_i exactly (n = +y), whatever the rounding of the x component.
        for ExactlyOne { k, sin2_i, i, eta } in sin2_t_exactly_one() {
            cases += 1;
            assert_eq!(refract(i, Vec3::Y, eta), None, "cos θ_i = {k}/64, η = {eta}: sin²θ_t = 1");
            let below = Float::from_bits(eta.to_bits() - 1);
            if below * below * sin2_i < 1.0 {
                let t = refract(i, Vec3::Y, below).expect("sin²θ_t < 1 refracts");
                assert!(t.is_finite() && t.dot(Vec3::Y) < 0.0, "η = {below}: t = {t}");
            }
        }
        println!("sin²θ_t rounds to exactly 1 in {cases} cases");
        // Measured: 28 such cases in f32, 32 in f64.
        assert!(cases >= 10, "only {cases} cases where sin²θ_t rounds to 1");
    }

    #[test]
    fn transmitted_direction_is_unit_and_obeys_snell() {
        // For every angle and ratio: |t| = 1 (4ε: a handful of roundings of values ≤ 1), t in the
        // plane of i and n, through the surface, and η sin θ_i = sin θ_t checked in f64; None
        // exactly when the f64 value of η² sin²θ_i exceeds 1 (cases within 10⁻⁴ of 1 skipped,
        // where f32 rounding may decide either way).
        for eta in [1.0 / 2.4, 1.0 / 1.5, 1.0 / 1.1, 1.1, 1.5, 2.4] {
            for tenth in 0..=900 {
                let degrees = tenth as f64 / 10.0;
                let i = incoming(degrees);
                let sin_i = sin_from_y(i);
                let sin2_t = (wide(eta) * sin_i).powi(2);
                if (sin2_t - 1.0).abs() < 1e-4 {
                    continue;
                }
                let Some(t) = refract(i, Vec3::Y, eta) else {
                    assert!(sin2_t > 1.0, "η = {eta}, {degrees}°: None but sin²θ_t = {sin2_t}");
                    continue;
                };
                assert!(sin2_t < 1.0, "η = {eta}, {degrees}°: a ray past the critical angle");
                assert!((t.length() - 1.0).abs() <= 4.0 * EPS, "η = {eta}, {degrees}°: |t| = {}", t.length());
                assert!(t.z == 0.0 && t.y < 0.0, "t = {t} leaves the plane or does not cross");
                let sin_t = sin_from_y(t);
                let tolerance = 16.0 * wide(EPS);
                assert!((sin_t - wide(eta) * sin_i).abs() <= tolerance, "η = {eta}: sin θ_t = {sin_t}");
            }
        }
    }

    #[test]
    fn ray_slightly_behind_the_surface_never_gives_nan() {
        // Rounding can leave i·n a little above 0 (a grazing ray) or below −1 (a normal one);
        // clamping cos θ_i to [0, 1] keeps every result finite and unit (or None).
        let grazing = v(1.0, 4.0 * EPS, 0.0).normalize();
        assert!(grazing.dot(Vec3::Y) > 0.0, "the case needs i·n > 0");
        let straight = -Vec3::Y * (1.0 + 2.0 * EPS);
        assert!(straight.dot(Vec3::Y) < -1.0, "the case needs i·n < −1");
        for i in [grazing, straight] {
            for eta in [1.0 / 1.5, 1.0, 1.5] {
                if let Some(t) = refract(i, Vec3::Y, eta) {
                    assert!(t.is_finite(), "i = {i}, η = {eta}: t = {t}");
                    assert!((t.length() - 1.0).abs() <= 8.0 * EPS, "|t| = {}", t.length());
                }
            }
        }
        // Grazing into glass bends to the critical angle: sin θ_t = 1/1.5, t ≈ (2/3, −√5/3, 0).
        let t = refract(grazing, Vec3::Y, 1.0 / 1.5).expect("into glass");
        let expected = v(2.0 / 3.0, -(5.0 as Float).sqrt() / 3.0, 0.0);
        assert!((t - expected).abs().max_element() <= 16.0 * EPS, "t = {t}");
        // Grazing out of glass (or with η = 1: sin²θ_t = 1 exactly) transmits nothing.
        assert_eq!(refract(grazing, Vec3::Y, 1.5), None);
        assert_eq!(refract(grazing, Vec3::Y, 1.0), None);
    }

    #[test]
    fn inverted_eta_ratio_is_visibly_wrong() {
        // The catalogued mistake: η_t/η_i instead of η_i/η_t. Air to glass at 30° must bend toward
        // the normal, to θ_t = arcsin(1/3) = 19.47°; the inverted ratio bends away, to
        // arcsin(0.75) = 48.59°, 29° off.
        let i = incoming(30.0);
        let right = refract(i, Vec3::Y, 1.0 / 1.5).expect("air to glass");
        let wrong = refract(i, Vec3::Y, 1.5 / 1.0).expect("1.5 sin 30° = 0.75 < 1");
        assert!((angle_between(right, -Vec3::Y) - 19.47).abs() < 0.01);
        assert!((angle_between(wrong, -Vec3::Y) - 48.59).abs() < 0.01);
        assert!(angle_between(right, wrong) > 25.0, "the mistake must show");
        // At 45° the inverted ratio even reflects everything (1.5 sin 45° = 1.06 > 1): a glass
        // sphere would turn into a mirror at its rim.
        assert!(refract(incoming(45.0), Vec3::Y, 1.0 / 1.5).is_some());
        assert_eq!(refract(incoming(45.0), Vec3::Y, 1.5), None);
    }

    #[test]
    fn entering_hit_goes_from_air_into_the_material() {
        // A ray down −z onto the unit sphere at (0, 0, 1), outward normal +z, from outside.
        let ray = Ray::new(v(0.0, 0.0, 5.0), -Vec3::Z);
        let hit = Hit::new(&ray, 4.0, Vec3::Z);
        let s = interface(&hit, 1.5);
        assert_eq!(s, Interface { normal: Vec3::Z, eta_i: 1.0, eta_t: 1.5, entering: true });
        assert_eq!(s.eta_ratio(), 1.0 / 1.5);
    }

    #[test]
    fn leaving_hit_goes_from_the_material_into_air() {
        // From the centre out along +z: the same point and outward normal, reached from inside,
        // so the normal faces the ray (−z) and the indices swap.
        let ray = Ray::new(Vec3::ZERO, Vec3::Z);
        let hit = Hit::new(&ray, 1.0, Vec3::Z);
        let s = interface(&hit, 1.5);
        assert_eq!(s, Interface { normal: -Vec3::Z, eta_i: 1.5, eta_t: 1.0, entering: false });
        assert_eq!(s.eta_ratio(), 1.5);
    }

    #[test]
    fn a_slab_shifts_a_ray_but_keeps_its_direction() {
        // Through a glass slab between y = 0 and y = −1 (outward normals +y on top, −y below):
        // in at the top, out at the bottom, the ray leaves parallel to how it came (Snell twice with
        // swapped indices). Each hit goes through `interface`, as the tracer does. Tolerance 16ε:
        // two refractions of a few roundings each.
        for degrees in [0.0, 20.0, 45.0, 70.0, 85.0] {
            let d = incoming(degrees);
            let ray = Ray::new(v(0.0, 1.0, 0.0), d);
            let top = Hit::new(&ray, 1.0 / -d.y, Vec3::Y);
            let into = interface(&top, 1.5);
            assert!(into.entering);
            let inside = refract(d, into.normal, into.eta_ratio()).expect("into glass");
            let ray = Ray::new(top.point, inside);
            let bottom = Hit::new(&ray, 1.0 / -inside.y, -Vec3::Y);
            let out = interface(&bottom, 1.5);
            assert!(!out.entering && out.normal == Vec3::Y, "{out:?}");
            let outside = refract(inside, out.normal, out.eta_ratio()).expect("the reverse path exists");
            let tolerance = 16.0 * EPS + 4.0 * EPS / (degrees as Float).to_radians().cos();
            assert!((outside - d).abs().max_element() <= tolerance, "{degrees}°: {outside} vs {d}");
        }
    }
}
