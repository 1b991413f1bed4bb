//! The checks of `phong.rs`: phong_specular and blinn_specular.

use super::common::*;

/// A cosine near 1 carries a few ε of rounding; raised to n, n times as much.
pub(super) fn tol(exponent: Float) -> Float {
    8.0 * EPS * exponent.max(1.0)
}

pub(super) fn phong_cases(phong: SpecularFn) -> CheckResult {
    // The mirror direction: N = y, L at 45° toward +x, V at 45° toward −x: V = R, 1.
    let (l, mirror) = (at_angle(45.0), at_angle(-45.0));
    for e in [1.0, 10.0, 200.0] {
        let case = format!("n = +y, l at +45°, v at −45° (the mirror direction), exponent {e}");
        let f = phong(Vec3::Y, l, mirror, e);
        let cause = if f < 0.5 {
            "R = reflect(−l, n): reflect takes the direction the light travels, −l"
        } else {
            "at V = R the highlight is 1 for every exponent"
        };
        close(&case, f, 1.0, tol(e), cause)?;
    }
    // Seen along N: R·V = cos 45°, so (√½)ⁿ: 0.7071, ½, 1/32.
    let half_angle = radians(22.5).cos();
    for (e, expected) in [(1.0, (0.5 as Float).sqrt()), (2.0, 0.5), (10.0, 1.0 / 32.0)] {
        let case = format!("n = +y, l at +45°, v = n, exponent {e}");
        let f = phong(Vec3::Y, l, Vec3::Y, e);
        let cause = if (f - half_angle.powf(e)).abs() < 1e-4 {
            "Phong's cosine is R·V with R the mirror of the light, not N·H with the half vector (that is Blinn)"
        } else if (f - (0.5 as Float).sqrt()).abs() < 1e-4 {
            "raise the cosine to the exponent: (R·V)ⁿ"
        } else {
            "(max(R·V, 0))ⁿ with R = reflect(−l, n)"
        };
        close(&case, f, expected, tol(e), cause)?;
    }
    // The light behind the surface (l at 100°), the eye near its below-surface mirror image
    // (v at −80°, above the surface): R·V = 0.94, yet no highlight: 0.
    let case = "n = +y, l at 100° (behind the surface), v at −80°, exponent 1";
    let f = phong(Vec3::Y, at_angle(100.0), at_angle(-80.0), 1.0);
    close(case, f, 0.0, 0.0, "no highlight when n·l ≤ 0: the light is behind the surface")?;
    // The eye away from the lobe: R at −45°, V at +80°, R·V = cos 125° < 0: 0 (exponent 1),
    // and 0, not NaN, for a fractional exponent.
    for e in [1.0, 2.5] {
        let case = format!("n = +y, l at +45°, v at +80° (R·V < 0), exponent {e}");
        let f = phong(Vec3::Y, l, at_angle(80.0), e);
        close(
            &case,
            f,
            0.0,
            0.0,
            "clamp R·V at 0 before the power: an eye away from the lobe sees no highlight",
        )?;
    }
    // Exponent 0 with the light in front: 1 everywhere (0⁰ = 1), here where R·V < 0.
    let case = "n = +y, l at +45°, v at +80°, exponent 0";
    close(
        case,
        phong(Vec3::Y, l, at_angle(80.0), 0.0),
        1.0,
        0.0,
        "x⁰ = 1 for every x ≥ 0 (0⁰ = 1): clamp, then powf",
    )?;
    // A huge exponent at the peak: within 10⁴·8ε of 1, finite.
    let case = "n = +y, l at +45°, v at −45°, exponent 10⁴";
    close(
        case,
        phong(Vec3::Y, l, mirror, 1e4),
        1.0,
        tol(1e4),
        "clamp the cosine to [0, 1] before the power",
    )?;
    Ok("11 cases".into())
}

pub(super) fn blinn_cases(blinn: SpecularFn) -> CheckResult {
    // L and V at ±45°: H = N, the peak 1; L = V = N: 1.
    for (what, l, v) in
        [("l at +45°, v at −45°", at_angle(45.0), at_angle(-45.0)), ("l = v = n", Vec3::Y, Vec3::Y)]
    {
        for e in [1.0, 80.0] {
            let case = format!("n = +y, {what}, exponent {e}");
            close(
                &case,
                blinn(Vec3::Y, l, v, e),
                1.0,
                tol(e),
                "H = (l + v)/|l + v|: both point away from the surface",
            )?;
        }
    }
    // Seen along N with L at 45°: H is at 22.5°, N·H = cos 22.5° = 0.92388; to the n.
    let l = at_angle(45.0);
    let c = radians(22.5).cos();
    for e in [1.0, 2.0, 10.0] {
        let case = format!("n = +y, l at +45°, v = n, exponent {e}");
        let f = blinn(Vec3::Y, l, Vec3::Y, e);
        let cause = if (f - radians(45.0).cos().powf(e)).abs() < 1e-4 {
            "Blinn's cosine is N·H with the half vector H = (l + v)/|l + v|, not R·V (that is Phong)"
        } else if f >= 1.0 - 1e-4 {
            "normalise the half vector: H = (l + v)/|l + v|"
        } else {
            "(max(N·H, 0))ⁿ with H = (l + v)/|l + v|"
        };
        close(&case, f, c.powf(e), tol(e), cause)?;
    }
    // l = −v: no half vector; the light in front (n·l = cos 30°), the eye below: 0, not NaN.
    for e in [0.0, 1.0] {
        let case = format!("n = +y, l at 30°, v = −l (l + v = 0), exponent {e}");
        let f = blinn(Vec3::Y, at_angle(30.0), -at_angle(30.0), e);
        close(&case, f, 0.0, 0.0, "l + v = 0 has no direction: no highlight (0), never NaN (try_normalize)")?;
    }
    // The light behind the surface: 0, even with H near N (l at 100°, v at −100°... v above:
    // v at −80°: H = (l + v)/|l + v| points along ±y, N·H = ±1).
    let case = "n = +y, l at 100° (behind the surface), v at −80°, exponent 1";
    let f = blinn(Vec3::Y, at_angle(100.0), at_angle(-80.0), 1.0);
    close(case, f, 0.0, 0.0, "no highlight when n·l ≤ 0: the light is behind the surface")?;
    Ok("10 cases".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l05_shading::{blinn_specular, phong_specular, reflect};

    #[test]
    fn specular_mistakes_are_caught() {
        // Phong with R = reflect(l, n).
        caught(
            phong_cases(
                |n, l, v, e| if n.dot(l) <= 0.0 { 0.0 } else { reflect(l, n).dot(v).clamp(0.0, 1.0).powf(e) },
            ),
            "reflect(−l, n)",
        );
        // Phong without the n·l test.
        caught(phong_cases(|n, l, v, e| reflect(-l, n).dot(v).clamp(0.0, 1.0).powf(e)), "behind the surface");
        // Phong without the clamp.
        caught(
            phong_cases(|n, l, v, e| if n.dot(l) <= 0.0 { 0.0 } else { reflect(-l, n).dot(v).powf(e) }),
            "clamp R·V",
        );
        // Phong computed with the half vector.
        caught(phong_cases(blinn_specular), "not N·H");
        // Blinn with H unnormalised.
        caught(
            blinn_cases(
                |n, l, v, e| if n.dot(l) <= 0.0 { 0.0 } else { n.dot(l + v).clamp(0.0, 1.0).powf(e) },
            ),
            "normalise the half vector",
        );
        // Blinn with a plain normalize: NaN at l = −v.
        caught(
            blinn_cases(|n, l, v, e| {
                if n.dot(l) <= 0.0 { 0.0 } else { n.dot((l + v).normalize()).clamp(0.0, 1.0).powf(e) }
            }),
            "never NaN",
        );
        // Blinn computed as Phong.
        caught(blinn_cases(phong_specular), "not R·V");
    }
}
