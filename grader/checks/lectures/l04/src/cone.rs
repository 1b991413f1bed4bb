//! The checks of `cone.rs`: hit_cone.

use super::common::*;
use super::cylinder::{FROM_INSIDE, expect_hit, no_rim_leaks};

pub(super) fn cone_cases(hit: ShapeFn) -> CheckResult {
    let name = "the unit cone x² + y² ≤ (1 − z)², 0 ≤ z ≤ 1";
    let case = |r: &Ray| format!("{name}, {}", show_ray(r));
    let gradient = "the side's outward normal is the gradient (x, y, 1 − z), normalised: out and up";
    let side_out = Vec3::new(-SQRT_HALF, 0.0, SQRT_HALF);
    // Side: at z = ½ the radius is ½, x = −½ at t = 2.5; normal (−1, 0, 1)/√2.
    let r = ray([-3.0, 0.0, 0.5], [1.0, 0.0, 0.0]);
    expect_hit(
        &case(&r),
        hit(&r, ALL),
        2.5,
        side_out,
        true,
        &[(Vec3::new(-SQRT_HALF, 0.0, -SQRT_HALF), gradient), (-Vec3::X, gradient)],
        "solve x² + y² = (1 − z)² along the ray",
    )?;
    // Base from below at x = ¼: t = 1, normal −z.
    let r = ray([0.25, 0.0, -1.0], [0.0, 0.0, 1.0]);
    expect_hit(
        &case(&r),
        hit(&r, ALL),
        1.0,
        -Vec3::Z,
        true,
        &[(Vec3::Z, "the base z = 0 has the outward normal −z")],
        "the base z = 0 at t = −o_z/d_z, inside the unit disc; a vertical ray is a steep ray (a < 0): \
            the solid is the part of the line outside the roots, on the lower nappe",
    )?;
    // From above at x = ¼: the side where 1 − z = ¼, t = 3 − 0.75 = 2.25 (the upper nappe, at
    // z = 1.25, is not part of the solid).
    let r = ray([0.25, 0.0, 3.0], [0.0, 0.0, -1.0]);
    let nappe = "keep the lower nappe: the slab 0 ≤ z ≤ 1 cuts the double cone x² + y² = (1 − z)²";
    let got = hit(&r, ALL);
    let cause = if got.is_some_and(|h| (h.t - 1.75).abs() < 1e-3) {
        nappe
    } else {
        "a steep ray (a < 0) is inside the cone outside its roots; the lower nappe is the half-line \
            after the roots when d_z < 0"
    };
    expect_hit(&case(&r), got, 2.25, Vec3::new(SQRT_HALF, 0.0, SQRT_HALF), true, &[], cause)?;
    let r = ray([1.5, 0.0, -1.0], [0.0, 0.0, 1.0]);
    let got = hit(&r, ALL);
    ensure(got.is_none(), case(&r), "None", show_hit(&got), "x = 1.5 is outside the base disc and the cone")?;
    // From inside at z = ¼ (radius ¾): t = 0.75, outward (1, 0, 1)/√2 faced back.
    let r = ray([0.0, 0.0, 0.25], [1.0, 0.0, 0.0]);
    expect_hit(
        &case(&r),
        hit(&r, ALL),
        0.75,
        Vec3::new(-SQRT_HALF, 0.0, -SQRT_HALF),
        false,
        &[(Vec3::new(SQRT_HALF, 0.0, SQRT_HALF), FROM_INSIDE)],
        "starting inside, the hit is where the ray leaves",
    )?;
    // The apex: down the axis from z = 3, t = 2, normal +z by definition (the gradient vanishes).
    let r = ray([0.0, 0.0, 3.0], [0.0, 0.0, -1.0]);
    let apex = "at the apex the gradient (x, y, 1 − z) is zero: use +z there, never a NaN normal";
    expect_hit(&case(&r), hit(&r, ALL), 2.0, Vec3::Z, true, &[], apex)?;
    // Through the apex, steeper than the sides: in at t = 2.
    let r = ray([-1.0, 0.0, 3.0], [0.5, 0.0, -1.0]);
    let got = hit(&r, ALL);
    let Some(h) = got else { return Err(fail(case(&r), "t = 2", "None (no hit)", apex)) };
    close(case(&r), h.t, 2.0, TOL, apex)?;
    ensure(h.normal.is_normalized(), case(&r), "a unit normal", vec3(h.normal), apex)?;
    // Parallel to a side line (a = 0): the base at t = 1, then out through the side at t = 1.5.
    let linear = "a = 0 for a ray parallel to a side line: f = 2bt + c is linear, one root t = −c/(2b); \
        do not divide by a";
    let r = ray([1.0, 0.0, -1.0], [-1.0, 0.0, 1.0]);
    expect_hit(&case(&r), hit(&r, ALL), 1.0, -Vec3::Z, true, &[], linear)?;
    let case2 = format!("{}, range (1, ∞)", case(&r));
    expect_hit(
        &case2,
        hit(&r, Interval::new(1.0, Float::INFINITY)),
        1.5,
        Vec3::new(SQRT_HALF, 0.0, -SQRT_HALF),
        false,
        &[],
        linear,
    )?;
    // Straight down beside the apex (a = −1): the side at z = ½, t = 1.5.
    let r = ray([0.5, 0.0, 2.0], [0.0, 0.0, -1.0]);
    expect_hit(
        &case(&r),
        hit(&r, ALL),
        1.5,
        Vec3::new(SQRT_HALF, 0.0, SQRT_HALF),
        true,
        &[],
        "a steep ray (a < 0): the lower nappe is the half-line beyond the larger root when d_z < 0",
    )?;
    // Parallel to a side line with b = 0 (a = 0 and f = c along the whole ray): beside the cone,
    // from (−1, 1, 0) along (1, 0, 1), c = 1 > 0: no hit. Along a side line itself, c = 0: the
    // ray lies in the surface, and the solid is where the slab cuts it. From (−2, 0, −1) it
    // meets the base's rim at t = 1 (a rim: the base's −z or the side's (−1, 0, 1)/√2); from
    // (−1, 0, 2) the apex at t = 1, where the normal is +z.
    let flat_f = "a = 0 and b = 0: f = c along the whole ray, inside everywhere when c ≤ 0 (on the surface \
        at c = 0), nowhere when c > 0";
    let r = ray([-1.0, 1.0, 0.0], [1.0, 0.0, 1.0]);
    let got = hit(&r, ALL);
    ensure(got.is_none(), case(&r), "None", show_hit(&got), flat_f)?;
    let r = ray([-2.0, 0.0, -1.0], [1.0, 0.0, 1.0]);
    let got = hit(&r, ALL);
    let Some(h) = got else {
        return Err(fail(case(&r), "t = 1 at the rim (−1, 0, 0)", "None (no hit)", flat_f));
    };
    close(case(&r), h.t, 1.0, TOL, flat_f)?;
    let rim = near3(h.normal, -Vec3::Z, TOL) || near3(h.normal, side_out, TOL);
    ensure(rim, case(&r), "the normal −z or (−1, 0, 1)/√2 (a rim)", vec3(h.normal), gradient)?;
    let r = ray([-1.0, 0.0, 2.0], [1.0, 0.0, -1.0]);
    expect_hit(&case(&r), hit(&r, ALL), 1.0, Vec3::Z, true, &[], apex)?;
    // Parallel to a side line with |b| ≠ 1: from (−0.375, −0.5, 0) on the base along (3, 4, 5),
    // b = 1.875, c = −0.609375, the one root t = −c/(2b) = 0.1625, leaving through the side at
    // (0.1125, 0.15, 0.8125).
    let r = ray([-0.375, -0.5, 0.0], [3.0, 4.0, 5.0]);
    let t = (0.609375 / 3.75) as Float;
    let outward = Vec3::new(0.1125, 0.15, 0.1875).normalize();
    expect_hit(&case(&r), hit(&r, ALL), t, -outward, false, &[], linear)?;
    // Tangent to the side, flatter than it (a = 1 > 0): along x at y = z = ½, the discriminant
    // is 0 exactly, one touching point t = 2 at (0, ½, ½).
    let r = ray([-2.0, 0.5, 0.5], [1.0, 0.0, 0.0]);
    let touch = "a zero discriminant is one double root, a touching ray: reject only b² − ac < 0";
    let got = hit(&r, ALL);
    let Some(h) = got else { return Err(fail(case(&r), "t = 2 at (0, ½, ½)", "None (no hit)", touch)) };
    close(case(&r), h.t, 2.0, TOL * 2.0, touch)?;
    // The normal is across the ray there: either way round is facing it.
    let n = Vec3::new(0.0, SQRT_HALF, SQRT_HALF);
    ensure(
        near3(h.normal, n, TOL) || near3(h.normal, -n, TOL),
        case(&r),
        "the normal ±(0, 1, 1)/√2",
        vec3(h.normal),
        gradient,
    )?;
    // From just inside the side at z = ½ (x = −0.4999, radius 0.5), out along +x: the far root
    // t = 0.5 − x (in f64) is free of cancellation, c ≈ −10⁻⁴ notwithstanding.
    let x0: Float = -0.4999;
    let r = ray([x0, 0.0, 0.5], [1.0, 0.0, 0.0]);
    expect_hit(
        &case(&r),
        hit(&r, ALL),
        (0.5 - x0 as f64) as Float,
        Vec3::new(-SQRT_HALF, 0.0, -SQRT_HALF),
        false,
        &[],
        "the far root loses nothing to cancellation: q = −(b + sign(b)·√(b² − ac)) adds two numbers of one \
            sign, then t = q/a and c/q",
    )?;
    no_rim_leaks(hit, true)?;
    Ok("16 hand cases and 1,000 rim rays".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use crate::cylinder::{Quadric, far_origin};
    use l04_quadrics_transforms::{first_crossing, slab_z_span};

    use raylab::{Float, Hit, Interval, Ray, Vec3};

    /// The reference cone with switches: `naive` b² − ac, `down_normal` (x, y, z − 1),
    /// `both_nappes` f ≤ 0 taken between the roots whatever the sign of a.
    fn cone(ray: &Ray, range: Interval, naive: bool, down_normal: bool, both_nappes: bool) -> Option<Hit> {
        let (o, d) = (ray.origin, ray.dir);
        let w = 1.0 - o.z;
        let a = d.x * d.x + d.y * d.y - d.z * d.z;
        let b = o.x * d.x + o.y * d.y + w * d.z;
        let c = o.x * o.x + o.y * o.y - w * w;
        let (side_in, side_out) = if a == 0.0 {
            if b == 0.0 {
                if c > 0.0 {
                    return None;
                }
                (Float::NEG_INFINITY, Float::INFINITY)
            } else {
                let t = -c / (2.0 * b);
                if b > 0.0 { (Float::NEG_INFINITY, t) } else { (t, Float::INFINITY) }
            }
        } else {
            let m = Vec3::new(o.x, o.y, w).cross(Vec3::new(d.x, d.y, -d.z));
            let disc = if naive { b * b - a * c } else { m.x * m.x + m.y * m.y - m.z * m.z };
            if disc < 0.0 && a > 0.0 {
                return None;
            }
            let q = -(b + disc.max(0.0).sqrt().copysign(b));
            let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
            let (r0, r1) = (t0.min(t1), t0.max(t1));
            if a > 0.0 || both_nappes {
                (r0, r1)
            } else if d.z > 0.0 {
                (Float::NEG_INFINITY, r0)
            } else {
                (r1, Float::INFINITY)
            }
        };
        let (t, on_cap) = first_crossing((side_in, side_out), slab_z_span(o.z, d.z)?, range)?;
        let p = ray.at(t);
        let outward = if on_cap {
            Vec3::new(0.0, 0.0, if p.z > 0.5 { 1.0 } else { -1.0 })
        } else if down_normal {
            Vec3::new(p.x, p.y, p.z - 1.0)
        } else {
            Vec3::new(p.x, p.y, 1.0 - p.z)
        };
        Some(Hit::new(ray, t, outward.try_normalize().unwrap_or(Vec3::Z)))
    }

    #[test]
    fn cone_mistakes() {
        assert!(cone_cases(|r, i| cone(r, i, false, false, false)).is_ok());
        assert!(far_origin(|r, i| cone(r, i, false, false, false), Quadric::Cone).is_ok());
        caught(cone_cases(|r, i| cone(r, i, false, true, false)), "gradient");
        caught(cone_cases(|r, i| cone(r, i, false, false, true)), "steep ray");
        caught(far_origin(|r, i| cone(r, i, true, false, false), Quadric::Cone), "cancels");
    }
}
