//! The checks of `offset.rs`: offset_origin and the two naive offsets.

use super::common::*;
use raylab_testing::offsets::{OffsetCase, random_offset_cases};

/// Checks one offset: moved along ±n only, to `side` (+1 or −1) of the surface, by
/// 4 to 97 ulp of the largest coordinate of p and from (the lecture's bound:
/// 8ε·(|p|₁ + |from|₁) ≤ 48ε·M ≤ 96 ulp(M), plus half an ulp storing it; and at
/// least 8ε·M ≥ 8 ulp(M) of which a unit n's largest component carries 1/√3).
pub(super) fn check_offset(
    case: &dyn Display,
    p: Vec3,
    n: Vec3,
    from: Vec3,
    moved: Vec3,
    side: Float,
) -> Result<(), Failure> {
    let step = moved - p;
    let along = step.dot(n);
    let sideways = (step - along * n).abs().max_element();
    let m = p.abs().max_element().max(from.abs().max_element());
    let in_ulp = step.abs().max_element() / ulp(m);
    let expected = lazy(|f| {
        let sign = if side > 0.0 { "+" } else { "−" };
        write!(f, "p moved along {sign}·n by 4 to 97 ulp of {}, at most 2 ulp sideways", num(m))
    });
    let got = lazy(|f| write!(f, "{} ({} ulp, {} along n)", vec3(moved), num(in_ulp), num(along)));
    ensure(
        moved != p,
        case,
        &expected,
        &got,
        "the point did not move: the step is below half an ulp of p — scale it to the coordinates, \
         8ε·(|p|₁ + |from|₁); a fixed 10⁻⁴ rounds away far from the origin",
    )?;
    ensure(
        sideways <= 2.0 * ulp(m) + Float::MIN_POSITIVE,
        case,
        &expected,
        &got,
        "move along the normal n, not along dir: the error of p that matters is across the surface",
    )?;
    ensure(
        along * side > 0.0,
        case,
        &expected,
        &got,
        "move to the side the new ray leaves to: p + d·n when dir·n ≥ 0, p − d·n when dir·n < 0, whichever way n faces",
    )?;
    ensure(
        in_ulp <= 97.0,
        case,
        &expected,
        &got,
        "at most a few dozen ulp: scale the offset to the coordinates, 8ε·(|p|₁ + |from|₁), not a fixed epsilon",
    )?;
    ensure(
        in_ulp >= 4.0 || (m == 0.0 && along * side > 0.0),
        case,
        &expected,
        &got,
        "scale by |p|₁ + |from|₁: where from + t·dir cancels, p carries the rounding error of from",
    )
}

pub(super) fn offset_cases(offset: OffsetFn) -> CheckResult {
    let p = v(2.0, 0.0, 0.0);
    let cases = [
        (
            "p = (2, 0, 0), n = +x, dir = (1, 1, 0), from the origin",
            Vec3::X,
            v(1.0, 1.0, 0.0),
            Vec3::ZERO,
            1.0,
        ),
        (
            "p = (2, 0, 0), n = +x, dir = (−1, 1, 0) (through the surface)",
            Vec3::X,
            v(-1.0, 1.0, 0.0),
            Vec3::ZERO,
            -1.0,
        ),
        (
            "p = (2, 0, 0), n = −x, dir = (1, 1, 0) (the normal faces away)",
            -Vec3::X,
            v(1.0, 1.0, 0.0),
            Vec3::ZERO,
            -1.0,
        ),
        ("p = (2, 0, 0), n = +x, dir = +y (tangent: the normal's side)", Vec3::X, Vec3::Y, Vec3::ZERO, 1.0),
        ("p = (2, 0, 0), n = +x, dir = +x, found from (0, −2, 0)", Vec3::X, Vec3::X, v(0.0, -2.0, 0.0), 1.0),
    ];
    for (case, n, dir, from, side) in cases {
        check_offset(&case, p, n, from, offset(p, n, dir, from), side)?;
    }
    // The world origin seen from the eye (0, 5, 7): p = 0, so only |from| can scale the
    // offset above the error p carries (a few ulp of 7).
    let case = "p = (0, 0, 0), n = +y, dir = +y, found from the eye (0, 5, 7)";
    let from = v(0.0, 5.0, 7.0);
    check_offset(&case, Vec3::ZERO, Vec3::Y, from, offset(Vec3::ZERO, Vec3::Y, Vec3::Y, from), 1.0)?;
    // The world origin from the world origin: nothing to scale by, yet p must move.
    let case = "p = (0, 0, 0), n = +y, dir = +y, found from (0, 0, 0)";
    let moved = offset(Vec3::ZERO, Vec3::Y, Vec3::Y, Vec3::ZERO);
    ensure(
        moved.y > 0.0 && moved.y <= 1e-30 && moved.x == 0.0 && moved.z == 0.0,
        case,
        "(0, y, 0) with 0 < y ≤ 1e-30",
        vec3(moved),
        "add a floor (the smallest normal float) so the point moves even when p = from = 0",
    )?;
    // Random points, origins and normals at scales 10⁻³⁰ to 10²⁰: within the bound.
    let mut largest: Float = 0.0;
    for OffsetCase { p, n, dir, from } in random_offset_cases(100) {
        let side = if dir.dot(n) < 0.0 { -1.0 } else { 1.0 };
        let case =
            lazy(|f| write!(f, "p = {}, n = {}, dir = {}, from {}", vec3(p), vec3(n), vec3(dir), vec3(from)));
        let moved = offset(p, n, dir, from);
        check_offset(&case, p, n, from, moved, side)?;
        let m = p.abs().max_element().max(from.abs().max_element());
        largest = largest.max((moved - p).abs().max_element() / ulp(m));
    }
    Ok(format!("7 cases and 2100 random ones, at most {largest:.0} ulp"))
}

/// Shadow rays from hits on spheres of radius 1 at (10⁴, 10⁴, 10⁴) and 10⁵ and on a
/// floor through the world origin seen from (0, 5, 7) and (0, 500, 700), toward
/// lights on the lit side. Hit points are computed as the tracer does, p = o + t·d in
/// `Float`, with t the exact root rounded once (f64); whether the offset origin is
/// still inside (a self-hit) is decided in f64.
pub(super) fn large_coordinates(offset: OffsetFn) -> CheckResult {
    let mut rng = Rng::new(0xac_4e);
    let mut largest: Float = 0.0;
    for d in [1e4, 1e5] {
        let center = Vec3::splat(d);
        let c = wide3(center);
        for _ in 0..2000 {
            let origin = center + rng.unit_vector() * rng.range(2.0, 10.0);
            let aim = center + rng.in_ball(0.95);
            let dir = (aim - origin).normalize();
            // The near root in f64: t = f·d̂ term minus the half chord.
            let (o, dd) = (wide3(origin), wide3(dir));
            let f = [o[0] - c[0], o[1] - c[1], o[2] - c[2]];
            let a = dd.iter().map(|x| x * x).sum::<f64>();
            let b = (0..3).map(|k| f[k] * dd[k]).sum::<f64>() / a;
            let off2 = (0..3).map(|k| (f[k] - b * dd[k]).powi(2)).sum::<f64>();
            let t = (-b - ((1.0 - off2) / a).sqrt()) as Float;
            let p = origin + t * dir;
            let n = (p - center).normalize();
            let l = rng.unit_vector();
            let l = if l.dot(n) < 0.0 { -l } else { l };
            let moved = offset(p, n, l, origin);
            let case = lazy(|f| {
                let (p, origin, l) = (vec3(p), vec3(origin), vec3(l));
                write!(f, "unit sphere at ({d:e}, {d:e}, {d:e}), hit p = {p} from {origin}, light along {l}")
            });
            let m = wide3(moved);
            let outside = (0..3).map(|k| (m[k] - c[k]).powi(2)).sum::<f64>() > 1.0;
            ensure(
                outside,
                &case,
                "a shadow ray starting outside the sphere",
                lazy(|f| write!(f, "{} is inside: the sphere shadows itself", vec3(moved))),
                "the offset must exceed the rounding error of p: 8ε·(|p|₁ + |from|₁) along n; a fixed 10⁻⁴ \
                 rounds away at 10⁴ (one ulp is 10⁻³ in f32)",
            )?;
            check_offset(&case, p, n, origin, moved, 1.0)?;
            largest = largest.max((moved - p).abs().max_element() / ulp(p.abs().max_element()));
        }
    }
    for eye in [v(0.0, 5.0, 7.0), v(0.0, 500.0, 700.0)] {
        for _ in 0..2000 {
            let aim = v(rng.range(-0.1, 0.1), 0.0, rng.range(-0.1, 0.1));
            let dir = (aim - eye).normalize();
            let t = (-wide(eye.y) / wide(dir.y)) as Float;
            let p = eye + t * dir;
            let l = rng.unit_vector();
            let l = if l.y < 0.0 { -l } else { l };
            let moved = offset(p, Vec3::Y, l, eye);
            let case = lazy(|f| {
                write!(f, "floor y = 0 seen from {}, hit p = {}, light along {}", vec3(eye), vec3(p), vec3(l))
            });
            ensure(
                moved.y > 0.0,
                &case,
                "a shadow ray starting above the floor",
                lazy(|f| write!(f, "{} is below it: the floor shadows itself", vec3(moved))),
                "scale by |p|₁ + |from|₁: here p ≈ 0 but carries the rounding error of the eye's coordinates",
            )?;
            check_offset(&case, p, Vec3::Y, eye, moved, 1.0)?;
        }
    }
    Ok(format!("8000 shadow rays, none starting inside; at most {largest:.0} ulp of p on the spheres"))
}

pub(super) fn fixed_t_cases(offset: OffsetFn) -> CheckResult {
    // p + 10⁻⁴·dir, the normal and the ray's origin unused. One product and a sum: half
    // an ulp of each coordinate (ulp(3) = 2.4·10⁻⁷ in f32).
    let p = v(1.0, 2.0, 3.0);
    for (case, n, dir) in [
        ("p = (1, 2, 3), n = +y, dir = (0, 0, 1)", Vec3::Y, Vec3::Z),
        ("p = (1, 2, 3), n = +y, dir = (0.6, 0, 0.8)", Vec3::Y, v(0.6, 0.0, 0.8)),
        ("p = (1, 2, 3), n = +y, dir = (0, −1, 0) (through the surface)", Vec3::Y, -Vec3::Y),
    ] {
        let moved = offset(p, n, dir, v(9.0, 9.0, 9.0));
        let expected = p + 1e-4 * dir;
        let cause = if (moved - (p + 1e-4 * n)).abs().max_element() <= ulp(3.0) {
            "the fixed-t method steps 10⁻⁴ along dir (the ray's own direction), not along n"
        } else {
            "p + NAIVE_EPSILON·dir: the ray from p with range.min = 10⁻⁴"
        };
        close3(case, moved, expected, ulp(3.0), cause)?;
    }
    Ok("3 cases".into())
}

pub(super) fn fixed_normal_cases(offset: OffsetFn) -> CheckResult {
    // p + 10⁻⁴·n, whatever dir (the naive method's flaw, kept on purpose).
    let p = v(1.0, 2.0, 3.0);
    for (case, n, dir) in [
        ("p = (1, 2, 3), n = +y, dir = (0.6, 0.8, 0)", Vec3::Y, v(0.6, 0.8, 0.0)),
        ("p = (1, 2, 3), n = +y, dir = (0, −1, 0) (through the surface)", Vec3::Y, -Vec3::Y),
        ("p = (1, 2, 3), n = (0.6, 0, 0.8), dir = +x", v(0.6, 0.0, 0.8), Vec3::X),
    ] {
        let moved = offset(p, n, dir, v(9.0, 9.0, 9.0));
        let expected = p + 1e-4 * n;
        let cause = if (moved - (p - 1e-4 * n)).abs().max_element() <= ulp(3.0) {
            "the fixed-normal method always steps along +n, whatever dir (its flaw, kept to compare)"
        } else if (moved - (p + 1e-4 * dir)).abs().max_element() <= ulp(3.0) {
            "step along the normal n, not along dir"
        } else {
            "p + NAIVE_EPSILON·n"
        };
        close3(case, moved, expected, ulp(3.0), cause)?;
    }
    Ok("3 cases".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    use raylab::Float;

    #[test]
    fn offset_mistakes_are_caught() {
        // Always along +n, whatever dir.
        caught(
            offset_cases(|p, n, _dir, from| {
                p + (8.0 * EPS * (p.abs().element_sum() + from.abs().element_sum()) + Float::MIN_POSITIVE) * n
            }),
            "side the new ray leaves to",
        );
        // Scaled by p alone (the catalogued patch): the world origin seen from the eye moves by
        // the floor only.
        caught(
            offset_cases(|p, n, dir, _from| {
                let d = 8.0 * EPS * p.abs().element_sum() + Float::MIN_POSITIVE;
                if dir.dot(n) < 0.0 { p - d * n } else { p + d * n }
            }),
            "carries the rounding error of from",
        );
        // A fixed 10⁻⁴.
        caught(
            offset_cases(|p, n, dir, _| if dir.dot(n) < 0.0 { p - 1e-4 * n } else { p + 1e-4 * n }),
            "not a fixed epsilon",
        );
        // No floor: p = from = 0 does not move.
        caught(
            offset_cases(|p, n, dir, from| {
                let d = 8.0 * EPS * (p.abs().element_sum() + from.abs().element_sum());
                if dir.dot(n) < 0.0 { p - d * n } else { p + d * n }
            }),
            "add a floor",
        );
        // Along dir instead of n.
        caught(
            offset_cases(|p, _n, dir, from| {
                p + (8.0 * EPS * (p.abs().element_sum() + from.abs().element_sum()) + Float::MIN_POSITIVE)
                    * dir.normalize()
            }),
            "not along dir",
        );
    }

    #[test]
    fn large_coordinates_catch_fixed_and_p_only_offsets() {
        // A fixed 10⁻⁴ along n: rounds away at 10⁴ in f32 (a self-hit), far above 97 ulp in f64.
        caught(large_coordinates(|p, n, _, _| p + 1e-4 * n), "fixed");
        // Scaled by p alone: the floor near the world origin seen from (0, 500, 700) shadows itself.
        caught(
            large_coordinates(|p, n, dir, _from| {
                let d = 8.0 * EPS * p.abs().element_sum() + Float::MIN_POSITIVE;
                if dir.dot(n) < 0.0 { p - d * n } else { p + d * n }
            }),
            "rounding error of",
        );
    }

    #[test]
    fn naive_offset_mistakes_are_caught() {
        caught(fixed_t_cases(|p, n, _, _| p + 1e-4 * n), "not along n");
        caught(
            fixed_normal_cases(|p, n, dir, _| if dir.dot(n) < 0.0 { p - 1e-4 * n } else { p + 1e-4 * n }),
            "always steps along +n",
        );
        caught(fixed_normal_cases(|p, _, dir, _| p + 1e-4 * dir), "not along dir");
    }
}
