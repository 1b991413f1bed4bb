//! The checks of `lambert.rs`: lambert.

use super::common::*;

pub(super) fn lambert_cases(lambert: LambertFn) -> CheckResult {
    // cos 0° = 1 exactly; a sign slip (n·(−l)) gives 0 here.
    let case = "n = +y, l = +y (the light straight above)";
    let f = lambert(Vec3::Y, Vec3::Y);
    let cause = if f == 0.0 {
        "l points from the point toward the light: the factor is n·l itself, 1 head-on"
    } else {
        "the factor is the cosine n·l of unit vectors"
    };
    close(case, f, 1.0, 0.0, cause)?;
    // cos 60° = ½ on either side of the normal. Vectors from sin/cos of a rounded angle: 4ε.
    for degrees in [60.0, -60.0] {
        let case = format!("n = +y, l at {degrees}° from it");
        close(&case, lambert(Vec3::Y, at_angle(degrees)), 0.5, 4.0 * EPS, "the factor is the cosine n·l")?;
    }
    // Grazing (l ⟂ n, exact 0) and from behind: exactly 0, never negative.
    for degrees in [90.0, 120.0, 180.0] {
        let l = if degrees == 90.0 { Vec3::X } else { at_angle(degrees) };
        let case = format!("n = +y, l at {degrees}° from it (behind the surface or grazing)");
        let f = lambert(Vec3::Y, l);
        let cause = if f < 0.0 {
            "clamp: max(n·l, 0) — a light behind the surface gives 0, not negative light"
        } else {
            "a light behind the surface gives 0: max(n·l, 0)"
        };
        close(&case, f, 0.0, 0.0, cause)?;
    }
    Ok("6 cases".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    #[test]
    fn lambert_mistakes_are_caught() {
        caught(lambert_cases(|n, l| n.dot(l)), "not negative light");
        caught(lambert_cases(|n, l| n.dot(-l).max(0.0)), "toward the light");
    }
}
