//! How much light a dielectric surface reflects: the Fresnel equations and
//! Schlick's approximation of them.
//!
//! The tracer of lecture 08 weighs the mirror ray by R and the transmitted ray
//! by 1 − R (times the material's `reflective` and `transparent` colours).

use raylab::Float;

/// Schlick's approximation of the Fresnel reflectance of a dielectric:
///
///   R₀ = ((η_i − η_t)/(η_i + η_t))²,  R = R₀ + (1 − R₀)(1 − cos θ)⁵,
///
/// where θ is the angle **on the side of the smaller index**: cos θ = cos θ_i
/// when η_i ≤ η_t, and cos θ = cos θ_t (from Snell's law,
/// cos²θ_t = 1 − (η_i/η_t)²(1 − cos²θ_i)) when η_i > η_t; under total
/// internal reflection (sin²θ_t ≥ 1) R = 1.
///
/// Why θ_t when leaving the denser medium (the slides' choice): the exact
/// reflectance is the same for a path and its reverse, R(η_i → η_t, θ_i) =
/// R(η_t → η_i, θ_t), and Schlick's curve fits the exact one as a function of
/// the angle in the less dense medium, rising from R₀ at 0° to 1 at 90°.
/// Inside glass, that angle reaches 90° at the critical angle, so R rises
/// continuously to 1 where total internal reflection begins. With cos θ_i
/// instead, R stays near R₀ up to the critical angle and then jumps to 1 — a
/// visible seam at the rim of every glass object seen from inside.
///
/// `cos_i` = cos θ_i = −d·n for the unit incoming direction d and the normal n
/// facing it; it is clamped to [0, 1] first, so a cosine rounded a little past
/// either end gives a value in [0, 1], never NaN. The indices must be positive
/// and finite. Book: §7.6 Schlick's approximation.
pub fn schlick(cos_i: Float, eta_i: Float, eta_t: Float) -> Float {
    debug_assert!(eta_i > 0.0 && eta_i.is_finite(), "η_i must be positive, got {eta_i}");
    debug_assert!(eta_t > 0.0 && eta_t.is_finite(), "η_t must be positive, got {eta_t}");
    // SOLUTION BEGIN
    // Reflectance at normal incidence.
    let r0 = ((eta_i - eta_t) / (eta_i + eta_t)).powi(2);

    // The cosine of the angle on the less dense side.
    let cos_i = cos_i.clamp(0.0, 1.0);
    let cos = if eta_i <= eta_t {
        cos_i
    } else {
        let eta = eta_i / eta_t;
        let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
        if sin2_t >= 1.0 {
            // Total internal reflection.
            return 1.0;
        }
        (1.0 - sin2_t).sqrt()
    };

    // Schlick's polynomial.
    r0 + (1.0 - r0) * (1.0 - cos).powi(5)
    // SOLUTION END
}

/// The exact Fresnel reflectance of unpolarised light at a smooth dielectric
/// interface: R = ½(r_s² + r_p²), with the amplitude ratios
///
///   r_s = (η_i cos θ_i − η_t cos θ_t) / (η_i cos θ_i + η_t cos θ_t)  (⊥ the plane of incidence),
///   r_p = (η_t cos θ_i − η_i cos θ_t) / (η_t cos θ_i + η_i cos θ_t)  (∥ the plane of incidence),
///
/// and cos θ_t = √(1 − sin²θ_t), sin²θ_t = (η_i/η_t)²(1 − cos²θ_i) (Snell).
/// R = 1 under total internal reflection (sin²θ_t ≥ 1). The transmitted
/// fraction is 1 − R (no absorption at the surface).
///
/// Landmarks: R = ((η_i − η_t)/(η_i + η_t))² at normal incidence (0.04 for
/// glass, η = 1.5), R = 1 at grazing incidence, and r_p = 0 at Brewster's
/// angle tan θ_B = η_t/η_i. The same for a path and its reverse:
/// R(η_i → η_t, θ_i) = R(η_t → η_i, θ_t).
///
/// `cos_i` as for [`schlick`] (clamped to [0, 1]); the result is in [0, 1],
/// never NaN: outside total internal reflection cos θ_t > 0, so no denominator
/// is zero. Book: §7.5 The Fresnel equations.
pub fn fresnel_dielectric(cos_i: Float, eta_i: Float, eta_t: Float) -> Float {
    debug_assert!(eta_i > 0.0 && eta_i.is_finite(), "η_i must be positive, got {eta_i}");
    debug_assert!(eta_t > 0.0 && eta_t.is_finite(), "η_t must be positive, got {eta_t}");
    // SOLUTION BEGIN
    // The transmitted angle by Snell's law; none past the critical angle.
    let cos_i = cos_i.clamp(0.0, 1.0);
    let eta = eta_i / eta_t;
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).sqrt();

    // The amplitude ratios of the two polarisations.
    let r_s = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
    let r_p = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);

    // Unpolarised light: the mean of the two reflectances.
    0.5 * (r_s * r_s + r_p * r_p)
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab_testing::wide;

    const EPS: Float = Float::EPSILON;

    /// cos of an angle given in degrees, computed in f64 and rounded once.
    fn cos_deg(degrees: f64) -> Float {
        degrees.to_radians().cos() as Float
    }

    /// The exact reflectance computed independently in f64 from the angle (not the cosine):
    /// θ_t = arcsin(η sin θ_i), then the Fresnel equations in their sine/tangent form,
    /// r_s = −sin(θ_i − θ_t)/sin(θ_i + θ_t), r_p = tan(θ_i − θ_t)/tan(θ_i + θ_t).
    /// Only for 0 < θ_i < 90° below the critical angle.
    fn fresnel_by_angles(degrees: f64, eta_i: f64, eta_t: f64) -> f64 {
        let theta_i = degrees.to_radians();
        let theta_t = (eta_i / eta_t * theta_i.sin()).asin();
        let r_s = -(theta_i - theta_t).sin() / (theta_i + theta_t).sin();
        let r_p = (theta_i - theta_t).tan() / (theta_i + theta_t).tan();
        0.5 * (r_s * r_s + r_p * r_p)
    }

    #[test]
    fn normal_incidence_reflects_four_percent_of_glass() {
        // R₀ = ((1 − 1.5)/(1 + 1.5))² = (−0.2)² = 0.04, from either side (the square hides the
        // sign). Tolerance 8ε: 0.2 is not a binary fraction; a few roundings of values below 1.
        for (eta_i, eta_t) in [(1.0, 1.5), (1.5, 1.0)] {
            let r = schlick(1.0, eta_i, eta_t);
            assert!((r - 0.04).abs() <= 8.0 * EPS, "Schlick {eta_i} → {eta_t}: {r}");
            let r = fresnel_dielectric(1.0, eta_i, eta_t);
            assert!((r - 0.04).abs() <= 8.0 * EPS, "exact {eta_i} → {eta_t}: {r}");
        }
        // Equal in both directions at normal incidence, to the last bit: cos θ_t = √(1 − 0) = 1.
        assert_eq!(schlick(1.0, 1.0, 1.5), schlick(1.0, 1.5, 1.0));
        assert_eq!(fresnel_dielectric(1.0, 1.0, 1.5), fresnel_dielectric(1.0, 1.5, 1.0));
    }

    #[test]
    fn no_interface_reflects_nothing() {
        // η_i = η_t: r_s = r_p = 0 at every angle (cos θ_t = cos θ_i up to the rounding of
        // √(1 − sin²θ_i), about ε/cos θ_i, so r_s, r_p ≲ ε/cos²θ_i). Schlick is not tested
        // here: with R₀ = 0 it still gives (1 − cos θ)⁵, one of its known flaws.
        for degrees in [0.0, 30.0, 60.0, 85.0] {
            let c = cos_deg(degrees);
            let r = fresnel_dielectric(c, 1.3, 1.3);
            assert!(r <= (EPS / (c * c)).powi(2), "{degrees}°: R = {r}");
        }
    }

    #[test]
    fn grazing_incidence_reflects_everything() {
        // cos θ_i = 0: Schlick gives R₀ + (1 − R₀)·1 = 1 (up to one rounding of 1 − R₀); exactly,
        // r_s = −η_t cos θ_t/(η_t cos θ_t) = −1 and r_p = −1, so R = 1.
        let r = schlick(0.0, 1.0, 1.5);
        assert!((r - 1.0).abs() <= EPS, "Schlick: {r}");
        assert_eq!(fresnel_dielectric(0.0, 1.0, 1.5), 1.0);
    }

    #[test]
    fn total_internal_reflection_reflects_everything() {
        // Glass to air at 60°: sin²θ_t = 1.5²·0.75 = 1.6875 ≥ 1. At grazing from inside, and at a
        // cosine rounded a little past 0, too.
        for cos_i in [cos_deg(60.0), cos_deg(42.0), 0.0, -EPS] {
            assert_eq!(schlick(cos_i, 1.5, 1.0), 1.0, "cos θ_i = {cos_i}");
            assert_eq!(fresnel_dielectric(cos_i, 1.5, 1.0), 1.0, "cos θ_i = {cos_i}");
        }
    }

    #[test]
    fn brewster_angle_reflects_only_s_polarisation() {
        // At tan θ_B = η_t/η_i, θ_t = 90° − θ_B, so cos θ_t = sin θ_B and r_p = 0. Air to glass:
        // tan θ_B = 1.5 (θ_B = 56.31°), cos θ_B = 1/√3.25, sin θ_B = 1.5/√3.25, and
        // r_s = (1 − 1.5·1.5)/(1 + 1.5·1.5) = −1.25/3.25 = −5/13, so R = r_s²/2 = 25/338.
        // Glass to air: tan θ_B = 1/1.5 (33.69°), r_s = +5/13, the same R.
        // Tolerance 32ε relative: cos θ_B is rounded once, and R changes slowly there
        // (dR/dcos θ ≈ −0.6), plus a dozen roundings in the formula.
        let expected = 25.0 / 338.0;
        for (eta_i, eta_t) in [(1.0f64, 1.5f64), (1.5, 1.0)] {
            let cos_b = (1.0 / (1.0 + (eta_t / eta_i).powi(2)).sqrt()) as Float;
            let r = fresnel_dielectric(cos_b, eta_i as Float, eta_t as Float);
            assert!((r - expected).abs() <= 32.0 * EPS * expected, "{eta_i} → {eta_t}: R = {r}");
        }
    }

    #[test]
    fn exact_fresnel_at_45_degrees_matches_the_closed_form() {
        // Air to glass at 45°: cos θ_i = √2/2, sin θ_t = √2/3, cos θ_t = √7/3, so
        // r_s = (√2 − √7)/(√2 + √7) = −0.3033370 and r_p = (9√2 − 4√7)/(9√2 + 4√7) = 0.0920134,
        // R = ½(r_s² + r_p²) = 0.0502399. Tolerance 32ε relative (as for Brewster).
        let (s2, s7) = ((2.0 as Float).sqrt(), (7.0 as Float).sqrt());
        let r_s = (s2 - s7) / (s2 + s7);
        let r_p = (9.0 * s2 - 4.0 * s7) / (9.0 * s2 + 4.0 * s7);
        let expected = 0.5 * (r_s * r_s + r_p * r_p);
        assert!((expected - 0.050_239_9).abs() < 1e-7);
        let r = fresnel_dielectric(s2 / 2.0, 1.0, 1.5);
        assert!((r - expected).abs() <= 32.0 * EPS * expected, "R = {r}, expected {expected}");
    }

    #[test]
    fn exact_fresnel_agrees_with_the_angle_form() {
        // An independent method: the sine/tangent form of the Fresnel equations evaluated in f64
        // from the angles. Both directions, 0.5° to 89.5° (below the critical angle from inside).
        // Tolerance: 64ε absolute in the precision under test (cos θ rounded once, and near the
        // critical angle cos θ_t = √(1 − sin²θ_t) amplifies the rounding of sin²θ_t).
        for (eta_i, eta_t) in [(1.0f64, 1.5f64), (1.5, 1.0), (1.0, 2.4), (1.0, 1.1)] {
            let critical = if eta_i > eta_t { (eta_t / eta_i).asin().to_degrees() } else { 90.0 };
            for tenth in (5..=895).step_by(5) {
                let degrees = tenth as f64 / 10.0;
                if degrees > critical - 1.0 {
                    break;
                }
                let expected = fresnel_by_angles(degrees, eta_i, eta_t);
                let r = wide(fresnel_dielectric(cos_deg(degrees), eta_i as Float, eta_t as Float));
                let tolerance = 64.0 * wide(EPS);
                assert!(
                    (r - expected).abs() <= tolerance,
                    "{eta_i} → {eta_t}, {degrees}°: {r} vs {expected}"
                );
            }
        }
    }

    #[test]
    fn reflectance_is_the_same_along_a_path_and_its_reverse() {
        // Air to glass at θ_i and glass to air at θ_t (sin θ_t = sin θ_i/1.5) reflect the same.
        // Exactly true of the Fresnel equations; true of Schlick only because it uses cos θ_t
        // on the dense side. cos θ_t is computed in f64 and rounded once. Tolerance 64ε: near
        // grazing the glass-side √(1 − sin²) loses digits.
        for degrees in (0..=88).map(|d| d as f64) {
            let sin_t = degrees.to_radians().sin() / 1.5;
            let cos_t = (1.0 - sin_t * sin_t).sqrt() as Float;
            let (from_air, from_glass) =
                (fresnel_dielectric(cos_deg(degrees), 1.0, 1.5), fresnel_dielectric(cos_t, 1.5, 1.0));
            assert!((from_air - from_glass).abs() <= 64.0 * EPS, "exact at {degrees}°");
            let (from_air, from_glass) = (schlick(cos_deg(degrees), 1.0, 1.5), schlick(cos_t, 1.5, 1.0));
            assert!((from_air - from_glass).abs() <= 64.0 * EPS, "Schlick at {degrees}°");
        }
    }

    #[test]
    fn schlick_rises_to_one_at_the_critical_angle() {
        // Glass to air 0.001° below θ_c = 41.8103149°: cos θ_t ≈ 6.247·10⁻³ (see refract's test),
        // so Schlick gives 0.04 + 0.96·(1 − 0.006247)⁵ = 0.97039. Tolerance 10⁻³: cos θ_t is good
        // to 5 % in f32, and dR/dcos θ ≈ −4.7 there. With cos θ_i (the mistake) it would be
        // 0.04 + 0.96·(1 − 0.745)⁵ ≈ 0.041, and then jump to 1 at the critical angle.
        let below = cos_deg(41.810_314_9 - 0.001);
        let r = schlick(below, 1.5, 1.0);
        assert!((r - 0.970_39).abs() <= 1e-3, "R = {r}");
        assert_eq!(schlick(cos_deg(41.810_314_9 + 0.001), 1.5, 1.0), 1.0);
        // The exact reflectance is continuous there too: above 0.8 just below θ_c.
        assert!(fresnel_dielectric(below, 1.5, 1.0) > 0.8);
    }

    #[test]
    fn schlick_stays_close_to_exact_for_glass() {
        // Measured against the angle form in f64 (independent of both routines), air to glass,
        // every 0.1° over [0°, 80°]: the largest error is 0.0222 at 80° (Schlick above exact;
        // a second bump of 0.0196 at 62.3°, Schlick below). Within 0.01 only up to 47.5°
        // (0.0082 at 45°). Bounds: 0.025 over [0°, 80°], 0.01 over [0°, 45°].
        let error = |degrees: f64| {
            let exact = if degrees == 0.0 { 0.04 } else { fresnel_by_angles(degrees, 1.0, 1.5) };
            (wide(schlick(cos_deg(degrees), 1.0, 1.5)) - exact).abs()
        };
        let worst = |tenths: std::ops::RangeInclusive<i32>| {
            tenths
                .map(|t| (error(t as f64 / 10.0), t as f64 / 10.0))
                .fold((0.0, 0.0), |a, b| if b.0 > a.0 { b } else { a })
        };
        let (max_80, at_80) = worst(0..=800);
        let (max_45, at_45) = worst(0..=450);
        println!(
            "Schlick vs exact, η = 1.5: max {max_80:.4} at {at_80}° over [0°, 80°], {max_45:.4} at {at_45}° over [0°, 45°]"
        );
        assert!(max_80 <= 0.025, "max error {max_80} at {at_80}°");
        assert!(max_45 <= 0.01, "max error {max_45} at {at_45}°");
    }

    #[test]
    fn cosines_rounded_past_the_ends_give_a_reflectance_in_range() {
        // −d·n can round to a little over 1 or under 0; both are clamped.
        for cos_i in [1.0 + EPS, 1.0 + 4.0 * EPS, -EPS, -4.0 * EPS] {
            for (eta_i, eta_t) in [(1.0, 1.5), (1.5, 1.0), (1.0, 2.4)] {
                for r in [schlick(cos_i, eta_i, eta_t), fresnel_dielectric(cos_i, eta_i, eta_t)] {
                    assert!((0.0..=1.0).contains(&r), "cos θ_i = {cos_i}, {eta_i} → {eta_t}: {r}");
                }
            }
        }
    }
}
