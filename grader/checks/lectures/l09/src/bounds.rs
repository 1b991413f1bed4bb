//! The checks of `bounds.rs`: sphere_bounds, triangle_bounds, transform_bounds.

use super::common::*;

/// One step outward from the sum (in f64) is what the box may give at most; at least the
/// exact sum. For an f32 build the f64 sum of two f32 is exact; in an f64 build it is the
/// rounded sum, which the box may equal.
/// Knuth's two-sum: a + b exactly, as the rounded sum s and its error e (a + b = s + e).
pub(super) fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let b_part = s - a;
    (s, (a - (s - b_part)) + (b - b_part))
}

/// Whether x ≤ a + b, the exact sum.
pub(super) fn at_most_sum(x: f64, a: f64, b: f64) -> bool {
    let (s, e) = two_sum(a, b);
    x < s || (x == s && e >= 0.0)
}

/// Whether x ≥ a + b, the exact sum.
pub(super) fn at_least_sum(x: f64, a: f64, b: f64) -> bool {
    let (s, e) = two_sum(a, b);
    x > s || (x == s && e <= 0.0)
}

pub(super) fn sphere_cases(bounds: SphereBoundsFn) -> CheckResult {
    // (0.1, −2, 3) and r = 0.3 in f32: 0.1 + 0.3 rounds down (to 0.4000000060 below the exact
    // 0.4000000134), so a box without outward rounding misses the sphere's rim by 7·10⁻⁹. In
    // f64, 0.7 + 0.1 rounds down (to 0.79999999999999993 below the exact
    // 0.79999999999999996): the same mistake, caught in either precision. The box must hold
    // c ± r exactly (compared with Knuth's two-sum, exact in both precisions).
    for (center, radius) in [
        (v(1.0, -2.0, 3.0), 0.5),
        (v(0.1, -3.7, 1e3), 0.3),
        (v(0.1, 0.2, -0.3), 0.3),
        (v(0.7, -0.7, 0.1), 0.1),
        (v(5.0, 6.0, 7.0), 0.0),
    ] {
        let b = bounds(center, radius);
        let case = format!("sphere at {} of radius {}", vec3(center), num(radius));
        for k in 0..3 {
            let (c, r) = (center[k] as f64, radius as f64);
            let (lo, hi) = (c - r, c + r);
            let slack = 4.0 * (c.abs() + r) * EPS as f64;
            let (got_lo, got_hi) = (b.min[k] as f64, b.max[k] as f64);
            if (got_lo - (c + r)).abs() <= slack && (got_hi - (c - r)).abs() <= slack && radius > 0.0 {
                return Err(fail(
                    &case,
                    show(&Aabb::new(center - radius, center + radius)),
                    show(&b),
                    "min is c − r and max is c + r",
                ));
            }
            let centre_missing = (got_lo + r).abs() <= slack && radius > 0.0 && c != 0.0;
            let holds = at_most_sum(got_lo, c, -r) && at_least_sum(got_hi, c, r);
            let cause = if centre_missing {
                "the box is around the centre: c − r ≤ p ≤ c + r, not −r ≤ p ≤ r"
            } else if !holds {
                "round each end outward by one step, (c − r).next_down() and (c + r).next_up(): c ± r is \
                 rounded and may land inside the sphere"
            } else {
                "c − r ≤ p ≤ c + r on every axis, rounded outward by one step"
            };
            ensure(
                holds && lo - got_lo <= slack && got_hi - hi <= slack,
                &case,
                format!("[{lo:.9}, {hi:.9}] on axis {k}, rounded outward by at most {slack:.1e}"),
                format!("[{got_lo:.9}, {got_hi:.9}]"),
                cause,
            )?;
        }
    }
    Ok("5 spheres".into())
}

pub(super) fn triangle_cases(bounds: TriangleBoundsFn) -> CheckResult {
    let cause = "the componentwise min and max of all three corners, a.min(b).min(c) and a.max(b).max(c)";
    // Corners chosen so that each of a, b, c holds an extreme: no two-corner shortcut works.
    let tri = [v(0.0, 1.0, 2.0), v(-1.0, 4.0, 2.5), v(3.0, 0.5, -2.0)];
    same_box(
        "triangle (0, 1, 2), (−1, 4, 2.5), (3, 0.5, −2)",
        bounds(&tri),
        Aabb::new(v(-1.0, 0.5, -2.0), v(3.0, 4.0, 2.5)),
        cause,
    )?;
    // Flat in z = 2: the box too.
    let flat = [v(0.0, 1.0, 2.0), v(-1.0, 4.0, 2.0), v(3.0, 0.5, 2.0)];
    same_box(
        "triangle (0, 1, 2), (−1, 4, 2), (3, 0.5, 2) in the plane z = 2",
        bounds(&flat),
        Aabb::new(v(-1.0, 0.5, 2.0), v(3.0, 4.0, 2.0)),
        "a triangle in an axis plane gives a flat box: no padding, no arithmetic on the corners",
    )?;
    Ok("2 triangles".into())
}

/// The image of `p` under `m`, in f64 from the matrix's own entries (an independent, nearly
/// exact computation).
pub(super) fn image_f64(m: &Mat4, p: Vec3) -> [f64; 3] {
    let c = m.to_cols_array();
    std::array::from_fn(|i| (0..3).map(|j| c[j * 4 + i] as f64 * p[j] as f64).sum::<f64>() + c[12 + i] as f64)
}

pub(super) fn transform_cases(bounds: TransformBoundsFn) -> CheckResult {
    // The cube [−1, 1]³ turned 45° about z: its corners (±1, ±1) reach x, y = ±√2; z stays ±1.
    // Only the 8 corners show it: (−1, −1, −1) and (1, 1, 1) alone go to x = 0.
    let cube = Aabb::new(Vec3::splat(-1.0), Vec3::ONE);
    let turn = Mat4::from_rotation_z(0.25 * raylab::math::consts::PI);
    let b = bounds(&cube, &turn);
    let s = Float::sqrt(2.0);
    let case = "the cube [−1, 1]³ turned 45° about z";
    // Tolerance: the widening γ₅(|M||p| + |t|) ≤ γ₅·2 per component, plus the rotation's own
    // rounding of sin and cos: 16ε covers both.
    if b.max.x < 0.5 {
        return Err(fail(
            case,
            format!("x up to {}", num(s)),
            show(&b),
            "transform all 8 corners: under a rotation the min and max corners are not the extreme ones",
        ));
    }
    close(case, b.max.x, s, 16.0 * EPS, "the box of the 8 transformed corners")?;
    close(case, b.min.y, -s, 16.0 * EPS, "the box of the 8 transformed corners")?;
    close(case, b.max.z, 1.0, 16.0 * EPS, "the box of the 8 transformed corners")?;
    // A placement with every difficulty: non-uniform scale, a rotation about a skew axis, a
    // far translation. The box must hold every corner's image computed in f64 from the
    // matrix entries, and be no more than the rounding's worth larger.
    let local = Aabb::new(v(-1.0, 0.25, 3.0), v(0.7, 1.5, 3.9));
    let m = Mat4::from_translation(v(-40.0, 7.0, 300.0))
        * Mat4::from_axis_angle(v(1.0, 2.0, -0.5).normalize(), 0.9)
        * Mat4::from_scale(v(3.0, 0.01, 70.0));
    let b = bounds(&local, &m);
    let case = "the box [−1, 0.25, 3 … 0.7, 1.5, 3.9] scaled (3, 0.01, 70), turned 0.9 about (1, 2, −0.5), \
                moved to (−40, 7, 300)";
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for corner in 0..8 {
        let pick = |k: usize| if corner & (1 << k) == 0 { local.min[k] } else { local.max[k] };
        let q = image_f64(&m, v(pick(0), pick(1), pick(2)));
        for k in 0..3 {
            lo[k] = lo[k].min(q[k]);
            hi[k] = hi[k].max(q[k]);
        }
    }
    // The widening pbrt's bound allows: γ₅ of the sum of |terms|, ≤ 400 here, plus one step.
    let slack = 8.0 * EPS as f64 * 600.0;
    for k in 0..3 {
        let (got_lo, got_hi) = (b.min[k] as f64, b.max[k] as f64);
        let expected = format!("[{:.6}, {:.6}] on axis {k}, within {slack:.1e}", lo[k], hi[k]);
        let got = format!("[{got_lo:.6}, {got_hi:.6}]");
        ensure(
            got_lo >= lo[k] - slack && got_hi <= hi[k] + slack,
            case,
            &expected,
            &got,
            "the box of the 8 transformed corners, widened only by their rounding error",
        )?;
        ensure(
            got_lo <= lo[k] && got_hi >= hi[k],
            case,
            &expected,
            &got,
            "widen each transformed corner by its rounding error, γ₅·(|M|·|p| + |t|), so the box holds the \
             exact image",
        )?;
    }
    Ok("2 placements".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l09_acceleration::{Aabb, sphere_bounds, transform_bounds};

    use raylab::{Float, Vec3};

    #[test]
    fn planted_bounds_mistakes_are_caught() {
        caught(sphere_cases(|_, r| Aabb::new(-Vec3::splat(r), Vec3::splat(r))), "around the centre");
        // f32 rounds 0.1 + 0.3 inward, f64 0.7 + 0.1: caught in both precisions.
        caught(sphere_cases(|c, r| Aabb::new(c - r, c + r)), "outward");
        caught(triangle_cases(|t| Aabb::new(t[0].min(t[1]), t[0].max(t[1]))), "all three corners");
        caught(
            transform_cases(|b, m| {
                let (p, q) = (m.transform_point3(b.min), m.transform_point3(b.max));
                Aabb::new(p.min(q), p.max(q))
            }),
            "all 8 corners",
        );
        // Unwidened corners: in f32 the f64 images show the inward rounding; in f64 the check's
        // own f64 arithmetic rounds alike and cannot see it.
        if Float::MANTISSA_DIGITS == 24 {
            caught(
                transform_cases(|b, m| {
                    (0..8).fold(Aabb::EMPTY, |acc, i: usize| {
                        let pick = |k: usize| if i & (1 << k) == 0 { b.min[k] } else { b.max[k] };
                        acc.union_point(m.transform_point3(Vec3::new(pick(0), pick(1), pick(2))))
                    })
                }),
                "widen",
            );
        }
        // A correct bound passes.
        assert!(sphere_cases(sphere_bounds).is_ok() && transform_cases(transform_bounds).is_ok());
    }
}
