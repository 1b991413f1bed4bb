//! The checks of `mirror.rs`: mirror_direction.

use super::common::*;

pub(super) fn mirror_cases(mirror: MirrorFn) -> CheckResult {
    let s = (0.5 as Float).sqrt();
    // By hand r = d − 2(d·n)n: the tangential part kept, the normal part flipped.
    // The 3-4-5 case is exact (d·n = −0.8, −0.8 + 1.6 rounds to 0.8); at 45°, a few
    // roundings of √½: 2ε; a tilted normal (2, −1, 2)/3 rounded: 4ε; the scaled case is
    // exact (powers of two).
    let n_tilted = v(2.0, -1.0, 2.0) / 3.0;
    let cases = [
        ("d = (0.6, −0.8, 0) onto the floor n = +y", v(0.6, -0.8, 0.0), Vec3::Y, v(0.6, 0.8, 0.0), 0.0),
        ("d = (−1, 0, −1)/√2 onto the wall n = +x", v(-s, 0.0, -s), Vec3::X, v(s, 0.0, -s), 2.0 * EPS),
        ("d = −n at normal incidence, n = (2, −1, 2)/3", -n_tilted, n_tilted, n_tilted, 4.0 * EPS),
        ("d = (24, −32, 0) (not unit) onto the floor", v(24.0, -32.0, 0.0), Vec3::Y, v(24.0, 32.0, 0.0), 0.0),
        ("d = (1, 0, −3) along the floor (grazing)", v(1.0, 0.0, -3.0), Vec3::Y, v(1.0, 0.0, -3.0), 0.0),
    ];
    for (case, d, n, expected, tolerance) in cases {
        let r = mirror(d, n);
        let cause = if (r + expected).abs().max_element() <= tolerance + 4.0 * EPS && expected.dot(n) != 0.0 {
            "the incoming direction goes in as it is, toward the surface: r = reflect(dir, n), leaving on the normal's side"
        } else if d.length() != 1.0 && (r - expected.normalize()).abs().max_element() <= 1e-4 {
            "keep |r| = |dir|: do not normalise (t along the mirror ray stays in the units of dir)"
        } else {
            "r = dir − 2(dir·n)n: call 05's reflect(dir, n), the one mirror formula of the course"
        };
        close3(case, r, expected, tolerance, cause)?;
    }
    Ok("5 cases".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    #[test]
    fn mirror_mistakes_are_caught() {
        // reflect(−dir, n): the ray goes back into the surface.
        caught(mirror_cases(|d, n| l05_shading::reflect(-d, n)), "goes in as it is");
        // Normalised: a non-unit direction changes length.
        caught(mirror_cases(|d, n| l05_shading::reflect(d, n).normalize()), "do not normalise");
        // The sign typo d + 2(d·n)n.
        caught(mirror_cases(|d, n| d + 2.0 * d.dot(n) * n), "reflect(dir, n)");
    }
}
