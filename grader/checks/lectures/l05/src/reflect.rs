//! The checks of `reflect.rs`: reflect.

use super::common::*;

pub(super) fn reflect_cases(reflect: ReflectFn) -> CheckResult {
    let s = (0.5 as Float).sqrt();
    // v = (1, −1, 0)/√2 onto the floor: r = (1, 1, 0)/√2. A few roundings of √½: 2ε.
    let case = "v = (1, −1, 0)/√2 onto n = +y (45°)";
    let vin = v(s, -s, 0.0);
    let r = reflect(vin, Vec3::Y);
    let expected = v(s, s, 0.0);
    let near = |a: Vec3| (r - a).abs().max_element() <= 1e-4;
    let cause = if near(vin + 2.0 * vin.dot(Vec3::Y) * Vec3::Y) {
        "r = v − 2(v·n)n: subtract twice the normal part, do not add it"
    } else if near(vin - vin.dot(Vec3::Y) * Vec3::Y) {
        "twice the normal part: once reaches the tangent plane, once more mirrors it"
    } else if near(-expected) {
        "v points toward the surface and r away from it: r = v − 2(v·n)n, not its negative"
    } else {
        "r = v − 2(v·n)n"
    };
    close3(case, r, expected, 2.0 * EPS, cause)?;
    // Exact cases: normal incidence, a vector along the surface, a non-unit v.
    for (case, vin, n, expected) in [
        ("v = −n at normal incidence, n = +y", -Vec3::Y, Vec3::Y, Vec3::Y),
        ("v = (2, 0, −1) along the floor n = +y", v(2.0, 0.0, -1.0), Vec3::Y, v(2.0, 0.0, -1.0)),
        ("v = (0, 0, −3) (not unit) onto n = +z", v(0.0, 0.0, -3.0), Vec3::Z, v(0.0, 0.0, 3.0)),
    ] {
        let r = reflect(vin, n);
        let cause = if (r.length() - 1.0).abs() < 1e-4 && vin.length() != 1.0 {
            "keep |r| = |v|: do not normalise"
        } else {
            "r = v − 2(v·n)n: the tangential part kept, the normal part flipped"
        };
        close3(case, r, expected, 0.0, cause)?;
    }
    // Either side of the normal: r is even in n (exact).
    let (vin, n) = (v(0.6, -0.8, 0.0), v(0.0, 0.6, 0.8));
    let case = "v = (0.6, −0.8, 0) about n = (0, 0.6, 0.8) and about −n";
    let (a, b) = (reflect(vin, n), reflect(vin, -n));
    ensure(a == b, case, vec3(a), vec3(b), "r = v − 2(v·n)n does not change when n is negated")?;
    Ok("5 cases".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    #[test]
    fn reflect_mistakes_are_caught() {
        caught(reflect_cases(|v, n| v + 2.0 * v.dot(n) * n), "do not add it");
        caught(reflect_cases(|v, n| v - v.dot(n) * n), "twice the normal part");
        caught(reflect_cases(|v, n| 2.0 * v.dot(n) * n - v), "not its negative");
        caught(reflect_cases(|v, n| (v - 2.0 * v.dot(n) * n).normalize()), "do not normalise");
    }
}
