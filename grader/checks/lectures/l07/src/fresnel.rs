//! The checks of `fresnel.rs`: schlick and fresnel_dielectric.

use super::common::*;

/// Schlick's R = R₀ + (1 − R₀)(1 − cos θ)⁵, with θ on the less dense side.
pub(super) fn schlick_cases(schlick: FresnelFn) -> CheckResult {
    // Normal incidence: R₀ = ((1 − 1.5)/(1 + 1.5))² = 0.2² = 0.04 from either side.
    // Tolerance 8ε: 0.2 is not a binary fraction; a few roundings of values below 1.
    for (eta_i, eta_t) in [(1.0, 1.5), (1.5, 1.0)] {
        let case = format!("cos θ_i = 1 (normal incidence), η_i = {eta_i}, η_t = {eta_t}");
        let r = schlick(1.0, eta_i, eta_t);
        let cause = if (r.abs() - 0.2).abs() < 1e-3 {
            "R₀ is the square of the amplitude: ((η_i − η_t)/(η_i + η_t))²"
        } else {
            "at normal incidence 1 − cos θ = 0, so R = R₀ = ((η_i − η_t)/(η_i + η_t))²"
        };
        close(case, r, 0.04, 8.0 * EPS, cause)?;
    }
    // From air at 60°: cos θ = ½ exactly, R = 0.04 + 0.96·(½)⁵ = 0.04 + 0.03 = 0.07.
    // A fourth power would give 0.04 + 0.96/16 = 0.1. Tolerance 8ε as above.
    let case = "air to glass (η_i = 1, η_t = 1.5) at 60°: cos θ_i = 0.5";
    let r = schlick(0.5, 1.0, 1.5);
    let cause = if (r - 0.1).abs() < 1e-3 {
        "the power is the fifth: (1 − cos θ)⁵"
    } else {
        "from the less dense side R = R₀ + (1 − R₀)(1 − cos θ_i)⁵"
    };
    close(case, r, 0.07, 8.0 * EPS, cause)?;
    // Grazing from air: R₀ + (1 − R₀)·1 = 1, up to one rounding of 1 − R₀.
    let case = "air to glass at grazing incidence: cos θ_i = 0";
    close(case, schlick(0.0, 1.0, 1.5), 1.0, 2.0 * EPS, "at grazing incidence (1 − 0)⁵ = 1, so R = 1")?;
    // Inside glass at 30° and 0.001° below the critical angle: θ on the air side, by
    // Snell cos θ_t = √(1 − 1.5²·sin²θ_i), computed here in f64.
    for (degrees, tolerance, why) in [
        // At 30°: cos θ_t = √(1 − 2.25·0.25) = 0.661438, R = 0.0442703. The cosine is
        // rounded once and dR/dcos θ ≈ −0.06 there: 64ε covers it and a few roundings.
        (30.0, 64.0 * EPS, "30°"),
        // 0.001° below θ_c = 41.8103149°: cos θ_t ≈ 6.2·10⁻³, R ≈ 0.9704. cos θ_t is
        // good only to ~1 % in f32 (1 − sin²θ_t cancels), and dR/dcos θ ≈ −4.7: 10⁻³.
        (41.810_314_9 - 0.001, 1e-3, "0.001° below the critical angle"),
    ] {
        let cos_i = cos_deg(degrees);
        let sin2_t = 2.25 * (1.0 - wide(cos_i) * wide(cos_i));
        let cos_t = (1.0 - sin2_t).sqrt();
        let expected = 0.04 + 0.96 * (1.0 - cos_t).powi(5);
        let with_cos_i = 0.04 + 0.96 * (1.0 - wide(cos_i)).powi(5);
        let case = format!("glass to air (η_i = 1.5, η_t = 1) at {why}: cos θ_i = {}", num(cos_i));
        let r = schlick(cos_i, 1.5, 1.0);
        let cause = if r.is_nan() {
            "inside glass take cos θ_t = √(1 − sin²θ_t) only when sin²θ_t < 1"
        } else if (wide(r) - with_cos_i).abs() < 1e-4 {
            "leaving the denser medium (η_i > η_t) use the angle on the air side: cos θ_t from Snell's law, not cos θ_i"
        } else {
            "inside glass R = R₀ + (1 − R₀)(1 − cos θ_t)⁵ with cos²θ_t = 1 − (η_i/η_t)²(1 − cos²θ_i)"
        };
        close(case, r, expected as Float, tolerance, cause)?;
    }
    // Glass to water at 30°, the ratio η_i/η_t = 1.5/1.33 ≠ η_i: sin²θ_t = 1.1278²·0.25 = 0.318,
    // cos θ_t = 0.8258, R₀ = (0.17/2.83)² = 0.003608, R = 0.003768 (in f64 below, from the f32
    // inputs). With η_i·η_t for the ratio, sin²θ_t = 0.995 and R ≈ 0.69. Tolerance 8ε: R is small
    // and dR/dcos θ ≈ −0.005 there, so the roundings of the cosines barely move it.
    let (eta_i, eta_t): (Float, Float) = (1.5, 1.33);
    let cos_i = cos_deg(30.0);
    let eta = wide(eta_i) / wide(eta_t);
    let cos_t = (1.0 - eta * eta * (1.0 - wide(cos_i) * wide(cos_i))).sqrt();
    let r0 = ((wide(eta_i) - wide(eta_t)) / (wide(eta_i) + wide(eta_t))).powi(2);
    let expected = r0 + (1.0 - r0) * (1.0 - cos_t).powi(5);
    let case = format!("glass to water (η_i = 1.5, η_t = 1.33) at 30°: cos θ_i = {}", num(cos_i));
    let cause = "Snell's law takes the ratio of the indices: sin θ_t = (η_i/η_t)·sin θ_i";
    close(case, schlick(cos_i, eta_i, eta_t), expected as Float, 8.0 * EPS, cause)?;
    // Past the critical angle: 60° and grazing from inside glass, sin²θ_t ≥ 1: R = 1.
    for cos_i in [0.5, 0.0] {
        let case = format!("glass to air at cos θ_i = {cos_i}: past the critical angle");
        let r = schlick(cos_i, 1.5, 1.0);
        close(case, r, 1.0, 0.0, "total internal reflection (sin²θ_t ≥ 1) reflects everything: R = 1")?;
    }
    Ok("9 cases".into())
}

/// The exact reflectance in f64 from the angle, by the sine/tangent form of the
/// Fresnel equations (a different formula from the cosine form the exercise uses):
/// r_s = −sin(θ_i − θ_t)/sin(θ_i + θ_t), r_p = tan(θ_i − θ_t)/tan(θ_i + θ_t).
/// Only for 0 < θ_i < 90°, below the critical angle.
pub(super) fn fresnel_by_angles(degrees: f64, eta_i: f64, eta_t: f64) -> f64 {
    let theta_i = degrees.to_radians();
    let theta_t = (eta_i / eta_t * theta_i.sin()).asin();
    let r_s = -(theta_i - theta_t).sin() / (theta_i + theta_t).sin();
    let r_p = (theta_i - theta_t).tan() / (theta_i + theta_t).tan();
    0.5 * (r_s * r_s + r_p * r_p)
}

pub(super) fn fresnel_cases(fresnel: FresnelFn) -> CheckResult {
    // Normal incidence: r_s = −r_p = (1 − 1.5)/2.5 = −0.2, R = ½(0.04 + 0.04) = 0.04.
    for (eta_i, eta_t) in [(1.0, 1.5), (1.5, 1.0)] {
        let case = format!("cos θ_i = 1 (normal incidence), η_i = {eta_i}, η_t = {eta_t}");
        let r = fresnel(1.0, eta_i, eta_t);
        let cause = if (r - 0.08).abs() < 1e-3 {
            "unpolarised light is the mean of the two polarisations: R = ½(r_s² + r_p²)"
        } else {
            "R = ½(r_s² + r_p²), each r the ratio of amplitudes"
        };
        close(case, r, 0.04, 8.0 * EPS, cause)?;
    }
    // Air to glass at 45°, by hand: cos θ_i = √2/2, sin θ_t = √2/3, cos θ_t = √7/3, so
    // r_s = (√2 − √7)/(√2 + √7) = −0.3033370, r_p = (9√2 − 4√7)/(9√2 + 4√7) = 0.0920134,
    // R = 0.0502399. Tolerance 32ε: cos θ_i rounded once, a dozen roundings below 1.
    let (s2, s7) = (2f64.sqrt(), 7f64.sqrt());
    let (r_s, r_p) = ((s2 - s7) / (s2 + s7), (9.0 * s2 - 4.0 * s7) / (9.0 * s2 + 4.0 * s7));
    let expected = 0.5 * (r_s * r_s + r_p * r_p);
    let case = "air to glass (η_i = 1, η_t = 1.5) at 45°: cos θ_i = √2/2";
    let r = fresnel((0.5 as Float).sqrt(), 1.0, 1.5);
    let cause = if (r - 1.0).abs() < 1e-3 {
        "this is no total internal reflection: sin²θ_t = (η_i/η_t)²(1 − cos²θ_i) with η_i/η_t = 1/1.5"
    } else if (wide(r) - r_s * r_s).abs() < 1e-4 {
        "r_p = (η_t cos θ_i − η_i cos θ_t)/(η_t cos θ_i + η_i cos θ_t): the indices trade places against r_s"
    } else if (wide(r) - 2.0 * expected).abs() < 1e-4 {
        "unpolarised light is the mean of the two polarisations: R = ½(r_s² + r_p²)"
    } else {
        "r_s = (η_i cos θ_i − η_t cos θ_t)/(η_i cos θ_i + η_t cos θ_t), r_p with η_i and η_t swapped"
    };
    close(case, r, expected as Float, 32.0 * EPS, cause)?;
    // Brewster's angle tan θ_B = η_t/η_i: r_p = 0, r_s = ∓(η_t² − η_i²)/(η_t² + η_i²) = ∓5/13
    // for 1 and 1.5, so R = r_s²/2 = 25/338 from either side. Tolerance 32ε as above.
    for (eta_i, eta_t) in [(1.0f64, 1.5f64), (1.5, 1.0)] {
        let cos_b = 1.0 / (1.0 + (eta_t / eta_i).powi(2)).sqrt();
        let case = format!("η_i = {eta_i}, η_t = {eta_t} at Brewster's angle: cos θ_i = {cos_b:.6}");
        let r = fresnel(cos_b as Float, eta_i as Float, eta_t as Float);
        let cause = "at Brewster's angle r_p = 0 and R = r_s²/2: check r_p = (η_t cos θ_i − η_i cos θ_t)/(η_t cos θ_i + η_i cos θ_t)";
        close(case, r, (25.0 / 338.0) as Float, 32.0 * EPS, cause)?;
    }
    // Grazing from air: r_s = r_p = −1, R = 1; past the critical angle from glass: R = 1.
    let case = "air to glass at grazing incidence: cos θ_i = 0";
    close(case, fresnel(0.0, 1.0, 1.5), 1.0, 4.0 * EPS, "at grazing incidence r_s = r_p = −1: R = 1")?;
    for cos_i in [0.5, 0.0] {
        let case = format!("glass to air at cos θ_i = {cos_i}: past the critical angle");
        let r = fresnel(cos_i, 1.5, 1.0);
        close(
            case,
            r,
            1.0,
            0.0,
            "when sin²θ_t ≥ 1 (total internal reflection) return R = 1 before the square root",
        )?;
    }
    // A sweep against the sine/tangent form in f64: four pairs of media, 0.5° to 89.5°,
    // stopping 1° short of the critical angle. Tolerance 64ε: cos θ_i rounded once,
    // and near θ_c, √(1 − sin²θ_t) amplifies the rounding of sin²θ_t.
    let mut count = 0;
    for (eta_i, eta_t) in [(1.0f64, 1.5f64), (1.5, 1.0), (1.0, 2.4), (1.0, 1.1)] {
        let critical = if eta_i > eta_t { (eta_t / eta_i).asin().to_degrees() } else { 90.0 };
        for tenths in (5..=895).step_by(10) {
            let degrees = f64::from(tenths) / 10.0;
            if degrees > critical - 1.0 {
                break;
            }
            let expected = fresnel_by_angles(degrees, eta_i, eta_t);
            let case = format!("η_i = {eta_i}, η_t = {eta_t} at {degrees}°");
            let r = fresnel(cos_deg(degrees), eta_i as Float, eta_t as Float);
            let cause = "R = ½(r_s² + r_p²) with cos θ_t = √(1 − (η_i/η_t)²(1 − cos²θ_i))";
            close(case, r, expected as Float, 64.0 * EPS, cause)?;
            count += 1;
        }
    }
    Ok(format!("{} cases", count + 7))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    use raylab::Float;

    fn schlick_with_cos_i(cos_i: Float, eta_i: Float, eta_t: Float) -> Float {
        let r0 = ((eta_i - eta_t) / (eta_i + eta_t)).powi(2);
        let cos_i = cos_i.clamp(0.0, 1.0);
        if eta_i > eta_t && (eta_i / eta_t).powi(2) * (1.0 - cos_i * cos_i) >= 1.0 {
            return 1.0;
        }
        r0 + (1.0 - r0) * (1.0 - cos_i).powi(5)
    }

    fn schlick_unsquared(cos_i: Float, eta_i: Float, eta_t: Float) -> Float {
        let r0 = (eta_i - eta_t) / (eta_i + eta_t);
        r0 + (1.0 - r0) * (1.0 - cos_i).powi(5)
    }

    fn schlick_fourth_power(cos_i: Float, eta_i: Float, eta_t: Float) -> Float {
        let r0 = ((eta_i - eta_t) / (eta_i + eta_t)).powi(2);
        r0 + (1.0 - r0) * (1.0 - cos_i).powi(4)
    }

    fn schlick_no_tir(cos_i: Float, eta_i: Float, eta_t: Float) -> Float {
        let r0 = ((eta_i - eta_t) / (eta_i + eta_t)).powi(2);
        let cos = if eta_i <= eta_t {
            cos_i
        } else {
            (1.0 - (eta_i / eta_t).powi(2) * (1.0 - cos_i * cos_i)).sqrt()
        };
        r0 + (1.0 - r0) * (1.0 - cos).powi(5)
    }

    #[test]
    fn schlick_mistakes_are_caught() {
        caught(schlick_cases(schlick_with_cos_i), "not cos θ_i");
        caught(schlick_cases(schlick_unsquared), "square of the amplitude");
        caught(schlick_cases(schlick_fourth_power), "fifth");
        caught(schlick_cases(schlick_no_tir), "reflects everything: R = 1");
    }

    /// The exact Fresnel equations with a chosen slip.
    fn fresnel_with(
        cos_i: Float,
        eta_i: Float,
        eta_t: Float,
        half: Float,
        swap_p: bool,
        invert: bool,
    ) -> Float {
        let eta = if invert { eta_t / eta_i } else { eta_i / eta_t };
        let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
        if sin2_t >= 1.0 {
            return 1.0;
        }
        let cos_t = (1.0 - sin2_t).sqrt();
        let r_s = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
        let r_p =
            if swap_p { r_s } else { (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t) };
        half * (r_s * r_s + r_p * r_p)
    }

    #[test]
    fn fresnel_mistakes_are_caught() {
        caught(fresnel_cases(|c, i, t| fresnel_with(c, i, t, 1.0, false, false)), "mean of the two");
        caught(fresnel_cases(|c, i, t| fresnel_with(c, i, t, 0.5, true, false)), "trade places");
        caught(fresnel_cases(|c, i, t| fresnel_with(c, i, t, 0.5, false, true)), "no total internal");
        // The reference formula with the slips off passes.
        assert!(fresnel_cases(|c, i, t| fresnel_with(c, i, t, 0.5, false, false)).is_ok());
    }
}
