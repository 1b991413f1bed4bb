//! The checks of `parametric.rs`: parametric_normal.

use super::common::*;

/// The unit sphere s(θ, φ) = (sin θ cos φ, sin θ sin φ, cos θ) and its partials.
pub(super) fn sphere(theta: Float, phi: Float) -> (Vec3, Vec3, Vec3) {
    let (st, ct, sp, cp) = (theta.sin(), theta.cos(), phi.sin(), phi.cos());
    (Vec3::new(st * cp, st * sp, ct), Vec3::new(ct * cp, ct * sp, -st), Vec3::new(-st * sp, st * cp, 0.0))
}

pub(super) fn parametric_cases(normal: ParametricFn) -> CheckResult {
    // ∂s/∂θ × ∂s/∂φ = sin θ · s: the outward radial direction. 16ε: |s| = 1 up to rounding.
    for (theta, phi) in [(0.3, 0.0), (1.0, 2.0), (2.5, -1.0), (1.55, 4.0)] {
        let (s, dt, dp) = sphere(theta, phi);
        let got = normal(dt, dp);
        let case =
            format!("unit sphere at θ = {theta}, φ = {phi}: ∂s/∂θ = {}, ∂s/∂φ = {}", vec3(dt), vec3(dp));
        let cause = if near3(got, -s, TOL) {
            "n = ∂s/∂α × ∂s/∂β in this order: swapping the factors flips the side"
        } else if near3(got, dt.cross(dp), TOL) {
            "normalise the cross product"
        } else {
            "n = (∂s/∂α × ∂s/∂β)/|∂s/∂α × ∂s/∂β|"
        };
        close3(&case, got, s, TOL, cause)?;
    }
    // The ellipsoid (2 sin θ cos φ, ½ sin θ sin φ, cos θ): the normal is the gradient (x/4, 4y, z),
    // normalised; 64ε: a few roundings times the axis ratio 4.
    let semi = Vec3::new(2.0, 0.5, 1.0);
    for (theta, phi) in [(0.7, 0.4), (2.0, 3.0)] {
        let (s, dt, dp) = sphere(theta, phi);
        let got = normal(dt * semi, dp * semi);
        let expected = (s / semi).normalize();
        let case = format!("ellipsoid with semi-axes (2, 0.5, 1) at θ = {theta}, φ = {phi}");
        close3(&case, got, expected, 64.0 * Float::EPSILON, "n = (∂s/∂α × ∂s/∂β)/|∂s/∂α × ∂s/∂β|")?;
    }
    // The pole θ = 0: ∂s/∂φ = 0, no normal: the zero vector, not NaN.
    let (_, dt, dp) = sphere(0.0, 1.0);
    close3(
        "unit sphere at the pole θ = 0 (∂s/∂φ = 0)",
        normal(dt, dp),
        Vec3::ZERO,
        0.0,
        "at a singular point (a zero or parallel partial) return the zero vector, never NaN",
    )?;
    Ok("4 sphere points, 2 ellipsoid points, a pole".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    #[test]
    fn parametric_mistakes() {
        caught(parametric_cases(|a, b| b.cross(a).normalize_or_zero()), "in this order");
        caught(parametric_cases(|a, b| a.cross(b)), "normalise");
        caught(parametric_cases(|a, b| a.cross(b).normalize()), "never NaN");
    }
}
