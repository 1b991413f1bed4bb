//! The checks of `aabb.rs`: Aabb::union, union_point, surface_area and the slab test Aabb::hit.

use super::common::*;
use crate::check::{ray, show_span};
use raylab_testing::boxes::FACE_PLANE_RAYS;
use raylab_testing::exact::{Ratio, exact_span};

pub(super) fn union_cases(union: UnionFn) -> CheckResult {
    // Componentwise min of the mins and max of the maxes; every value exact.
    let a = Aabb::new(v(0.0, 1.0, 2.0), v(1.0, 2.0, 3.0));
    let b = Aabb::new(v(-1.0, 1.5, 2.5), v(0.5, 4.0, 2.75));
    let expected = Aabb::new(v(-1.0, 1.0, 2.0), v(1.0, 4.0, 3.0));
    let cause = "the union is Aabb::new(min of the mins, max of the maxes), componentwise";
    same_box("[0, 1, 2 … 1, 2, 3] ∪ [−1, 1.5, 2.5 … 0.5, 4, 2.75]", union(a, b), expected, cause)?;
    same_box("[−1, 1.5, 2.5 … 0.5, 4, 2.75] ∪ [0, 1, 2 … 1, 2, 3]", union(b, a), expected, cause)?;
    // The empty box (min = +∞, max = −∞) changes nothing, on either side.
    let cause = "the empty box is the identity: min(+∞, x) = x and max(−∞, x) = x, no special case needed";
    same_box("EMPTY ∪ [0, 1, 2 … 1, 2, 3]", union(Aabb::EMPTY, a), a, cause)?;
    same_box("[0, 1, 2 … 1, 2, 3] ∪ EMPTY", union(a, Aabb::EMPTY), a, cause)?;
    same_box("EMPTY ∪ EMPTY", union(Aabb::EMPTY, Aabb::EMPTY), Aabb::EMPTY, cause)?;
    Ok("5 unions".into())
}

pub(super) fn union_point_cases(union_point: UnionPointFn) -> CheckResult {
    let a = Aabb::new(v(0.0, 1.0, 2.0), v(1.0, 2.0, 3.0));
    let cause = "grow the box to the point: Aabb::new(min.min(p), max.max(p))";
    same_box(
        "[0, 1, 2 … 1, 2, 3] with the point (5, 0, 2.5)",
        union_point(a, v(5.0, 0.0, 2.5)),
        Aabb::new(v(0.0, 0.0, 2.0), v(5.0, 2.0, 3.0)),
        cause,
    )?;
    same_box(
        "[0, 1, 2 … 1, 2, 3] with the inside point (0.5, 1.5, 2.5)",
        union_point(a, v(0.5, 1.5, 2.5)),
        a,
        cause,
    )?;
    let p = v(1.0, -2.0, 3.0);
    same_box(
        "EMPTY with the point (1, −2, 3)",
        union_point(Aabb::EMPTY, p),
        Aabb::new(p, p),
        "the empty box and a point make the flat box min = max = p",
    )?;
    Ok("3 cases".into())
}

pub(super) fn area_cases(area: AreaFn) -> CheckResult {
    // Sums of products of small integers: exact.
    let cases = [
        ("the box 2 × 3 × 4: 2·(6 + 12 + 8)", Aabb::new(Vec3::ZERO, v(2.0, 3.0, 4.0)), 52.0),
        (
            "the flat 2 × 3 rectangle (z from 0 to 0): both sides",
            Aabb::new(Vec3::ZERO, v(2.0, 3.0, 0.0)),
            12.0,
        ),
        ("a segment of length 2", Aabb::new(Vec3::ZERO, v(2.0, 0.0, 0.0)), 0.0),
        ("a point", Aabb::new(Vec3::ONE, Vec3::ONE), 0.0),
        ("the empty box", Aabb::EMPTY, 0.0),
        ("the infinite box", Aabb::INFINITE, Float::INFINITY),
    ];
    for (case, b, expected) in cases {
        let got = area(b.min, b.max);
        let cause = if b == Aabb::EMPTY {
            "the empty box has area 0: return 0 when is_empty() (its diagonal is −∞)"
        } else if got * 2.0 == expected {
            "the factor 2: a box has six faces, two of each d_i·d_j"
        } else if got == 1.0 / 0.0 || got.is_nan() {
            "d = max − min; 2(dₓd_y + d_yd_z + d_zdₓ)"
        } else {
            "2(dₓd_y + d_yd_z + d_zdₓ) with d = max − min: each pair of axes once"
        };
        ensure(got == expected, case, num(expected), num(got), cause)?;
    }
    Ok("6 boxes".into())
}

/// The widening of the box test (2γ₃ < 4ε, relative) plus a rounding or two: 8ε of t.
pub(super) const SPAN_TOL: Float = 8.0 * EPS;

/// `got` near `expected` for an entry and an exit: within SPAN_TOL relative (1 absolute floor
/// for t = 0), so a test with or without the widening passes.
pub(super) fn span_near(got: (Float, Float), expected: (Float, Float)) -> bool {
    let ok = |g: Float, e: Float| (g - e).abs() <= SPAN_TOL * e.abs().max(1.0) || g == e;
    ok(got.0, expected.0) && ok(got.1, expected.1)
}

pub(super) fn expect_span(
    hit: SlabFn,
    b: &Aabb,
    r: &Ray,
    range: Interval,
    expected: Option<(Float, Float)>,
    case: &str,
    cause: &str,
) -> Result<(), Failure> {
    let got = hit(b, r, r.dir.recip(), range);
    let nan = got.is_some_and(|(a, b)| a.is_nan() || b.is_nan());
    if nan {
        return Err(fail(
            case,
            show_span(&expected),
            show_span(&got),
            "0·∞ = NaN where the origin is on a slab plane of a parallel ray: take the entry with max and \
             the exit with min, which pass over a NaN",
        ));
    }
    let ok = match (got, expected) {
        (Some(g), Some(e)) => span_near(g, e),
        (None, None) => true,
        _ => false,
    };
    ensure(ok, case, show_span(&expected), show_span(&got), cause)
}

pub(super) fn cube() -> Aabb {
    Aabb::new(Vec3::splat(-1.0), Vec3::ONE)
}

pub(super) fn slab_cases(hit: SlabFn) -> CheckResult {
    let all = Interval::POSITIVE;
    // From (−3, −2, 0) along (2, 1.5, 0.25): x in [1, 2], y in [2/3, 2], z in [−4, 4].
    expect_span(
        hit,
        &cube(),
        &ray([-3.0, -2.0, 0.0], [2.0, 1.5, 0.25]),
        all,
        Some((1.0, 2.0)),
        "cube [−1, 1]³, ray from (−3, −2, 0) along (2, 1.5, 0.25)",
        "each slab i gives t = (minᵢ − oᵢ)·inv_dirᵢ and (maxᵢ − oᵢ)·inv_dirᵢ; the box holds [latest entry, \
         earliest exit]",
    )?;
    // Reversed: from (3, 2, 0) along (−2, −1.5, −0.25), the same span.
    expect_span(
        hit,
        &cube(),
        &ray([3.0, 2.0, 0.0], [-2.0, -1.5, -0.25]),
        all,
        Some((1.0, 2.0)),
        "cube [−1, 1]³, ray from (3, 2, 0) along (−2, −1.5, −0.25)",
        "where inv_dirᵢ < 0 the max plane is entered first: swap each slab's pair by the sign of inv_dir",
    )?;
    // Beside the box: x span [2, 4], y span [−1, 1], disjoint.
    expect_span(
        hit,
        &cube(),
        &ray([-3.0, 0.0, 0.0], [1.0, 1.0, 0.0]),
        all,
        None,
        "cube [−1, 1]³, ray from (−3, 0, 0) along (1, 1, 0) passes beside it",
        "a miss when the latest entry comes after the earliest exit",
    )?;
    // Behind the origin: the span [−4, −2].
    expect_span(
        hit,
        &cube(),
        &ray([3.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
        all,
        None,
        "cube [−1, 1]³ behind the ray from (3, 0, 0) along +x",
        "clip to the range: None when the exit is at or before range.min",
    )?;
    // Beyond the range: the span [2, 4] starts after range.max = 1.5.
    expect_span(
        hit,
        &cube(),
        &ray([-3.0, 0.0, 0.0], [1.0, 0.0, 0.0]),
        Interval::new(0.0, 1.5),
        None,
        "cube [−1, 1]³, ray from (−3, 0, 0) along +x, range (0, 1.5)",
        "clip to the range: None when the entry is at or after range.max (the closest hit so far)",
    )?;
    // From inside: the span [−0.5, 0.5] clipped to (0, ∞): (0, 0.5).
    expect_span(
        hit,
        &cube(),
        &ray([0.0, 0.0, 0.0], [0.0, 0.0, -2.0]),
        all,
        Some((0.0, 0.5)),
        "cube [−1, 1]³, ray from its centre along (0, 0, −2)",
        "clip the span to the range: (max(t_enter, range.min), min(t_exit, range.max)); t in units of dir",
    )?;
    // The empty box is never hit; the infinite box is the whole range.
    expect_span(
        hit,
        &Aabb::EMPTY,
        &ray([-3.0, -2.0, 0.0], [2.0, 1.5, 0.25]),
        Interval::new(Float::NEG_INFINITY, Float::INFINITY),
        None,
        "the empty box, any ray, range (−∞, ∞)",
        "the empty box is never hit: order each slab's pair by the sign of inv_dir (Vec3::select), not by \
         min/max, which turn min = +∞, max = −∞ into all of space",
    )?;
    expect_span(
        hit,
        &Aabb::INFINITE,
        &ray([-3.0, -2.0, 0.0], [2.0, 1.5, 0.25]),
        all,
        Some((0.0, Float::INFINITY)),
        "the infinite box, range (0, ∞)",
        "the infinite box holds the whole range",
    )?;
    Ok("8 rays".into())
}

pub(super) fn slab_boundaries(hit: SlabFn) -> CheckResult {
    let all = Interval::POSITIVE;
    // Origins exactly on the planes y = ±1 (and on an edge line), moving along ±x with ±0 in
    // the other components: 0·(±∞) = NaN must count as inside; the x span is [2, 4].
    for (o, d) in FACE_PLANE_RAYS {
        let r = ray(o, d);
        let case =
            format!("cube [−1, 1]³, ray from {} along {} (on a face plane)", vec3(r.origin), vec3(r.dir));
        expect_span(
            hit,
            &cube(),
            &r,
            all,
            Some((2.0, 4.0)),
            &case,
            "an origin on the plane of a slab the ray runs along is inside it: 0·∞ = NaN must not decide \
             (max and min pass over NaN; a comparison with NaN is false)",
        )?;
    }
    // Strictly inside a slab along a parallel ray, and just outside it.
    expect_span(
        hit,
        &cube(),
        &ray([-3.0, 0.5, 0.0], [1.0, 0.0, 0.0]),
        all,
        Some((2.0, 4.0)),
        "cube [−1, 1]³, ray from (−3, 0.5, 0) along +x",
        "a parallel ray strictly inside a slab: 1/0 = ∞ gives (−∞, +∞) for it",
    )?;
    expect_span(
        hit,
        &cube(),
        &ray([-3.0, 1.0 + 4.0 * EPS, 0.0], [1.0, 0.0, 0.0]),
        all,
        None,
        "cube [−1, 1]³, ray from 4ε above the plane y = 1 along +x",
        "a parallel ray outside a slab: the slab's span is empty (both ends ±∞ of the same sign)",
    )?;
    // The flat square x = 0, −1 ≤ y, z ≤ 1: across it (t = 1) and along its plane (y span [2, 4]).
    let flat = Aabb::new(v(0.0, -1.0, -1.0), v(0.0, 1.0, 1.0));
    expect_span(
        hit,
        &flat,
        &ray([-1.0, 0.5, 0.5], [1.0, 0.0, 0.0]),
        all,
        Some((1.0, 1.0)),
        "flat box x = 0, y, z in [−1, 1], ray from (−1, 0.5, 0.5) along +x",
        "a flat box is entered and left at the same t: accept t_enter ≤ t_exit, not <",
    )?;
    expect_span(
        hit,
        &flat,
        &ray([0.0, -3.0, 0.0], [0.0, 1.0, 0.0]),
        all,
        Some((2.0, 4.0)),
        "flat box x = 0, ray from (0, −3, 0) along +y, in its plane",
        "a ray in the plane of a flat box: both of that slab's t are 0·∞ = NaN, which must count as inside",
    )?;
    // Random axis-parallel rays on the cube's face planes: never NaN, and hit exactly when
    // the other two coordinates are within [−1, 1] (a closed box), by hand.
    let mut rng = Rng::new(0x09ab);
    for n in 0..400 {
        let axis = n % 3;
        let mut o = rng.in_cube(1.5);
        o[(axis + 1) % 3] = if rng.next_float() < 0.5 { -1.0 } else { 1.0 };
        o[axis] = -5.0;
        let mut d = Vec3::ZERO;
        d[axis] = 1.0;
        if rng.next_float() < 0.5 {
            d[(axis + 2) % 3] = -0.0;
        }
        let r = Ray::new(o, d);
        let other = o[(axis + 2) % 3];
        let expected = (-1.0..=1.0).contains(&other).then_some((4.0, 6.0));
        let case = format!("cube [−1, 1]³, ray from {} along {}", vec3(o), vec3(d));
        expect_span(hit, &cube(), &r, all, expected, &case, "a ray along a face is inside that slab")?;
    }
    // The range is open: a span that touches it only at an end is no hit. The box's own span
    // first, over (0, ∞), then the ranges that end where it starts and start where it ends.
    let r = ray([-3.0, 0.25, 0.5], [1.0, 0.125, -0.0625]);
    let case = format!("cube [−1, 1]³, ray from {} along {}", vec3(r.origin), vec3(r.dir));
    let Some((t0, t1)) = hit(&cube(), &r, r.dir.recip(), all) else {
        return Err(fail(
            case,
            "a hit, about (2, 4)",
            "None",
            "the ray crosses the cube from x = −1 to x = 1",
        ));
    };
    for (range, end) in [
        (Interval::new(0.0, t0), "ends at the span's entry"),
        (Interval::new(t1, 100.0), "starts at its exit"),
    ] {
        let case = format!("{case}, range ({}, {}): {end}", num(range.min), num(range.max));
        let got = hit(&cube(), &r, r.dir.recip(), range);
        ensure(
            got.is_none(),
            case,
            "None",
            show_span(&got),
            "the range is open, min < t < max: test t_enter < range.max and t_exit > range.min",
        )?;
    }
    // Random rays on a 1/16 grid (exact in any float), half aimed exactly at a face, an edge or a
    // corner, half of them in a range that reaches back, against exact arithmetic: no false miss,
    // and both ends of the span conservative (the entry not above the exact one, the exit not
    // below, beyond the rounding of the exact fraction to f64) and within SPAN_TOL of them.
    let cast = |v: [i64; 3]| Vec3::new(v[0] as Float, v[1] as Float, v[2] as Float) / 16.0;
    let mut rng = Rng::new(0x09e);
    let mut spans = 0;
    for n in 0..2000 {
        let lo: [i64; 3] = std::array::from_fn(|_| rng.int(-40, 40));
        let hi: [i64; 3] = std::array::from_fn(|i| lo[i] + rng.int(0, 40));
        let o: [i64; 3] = std::array::from_fn(|_| rng.int(-100, 100));
        let d: [i64; 3] = if n % 2 == 0 {
            std::array::from_fn(|_| if rng.int(0, 3) == 0 { 0 } else { rng.int(-60, 60) })
        } else {
            std::array::from_fn(|i| [lo[i], hi[i]][rng.int(0, 1) as usize] - o[i])
        };
        if d == [0; 3] {
            continue;
        }
        let (range, min, max) = if n % 4 < 2 {
            (all, Ratio::from(0), None)
        } else {
            let (a, b) = (rng.int(0, 40), rng.int(1, 40));
            (Interval::new(-(a as Float) / 4.0, b as Float / 4.0), Ratio::new(-a, 4), Some(Ratio::new(b, 4)))
        };
        let r = Ray::new(cast(o), cast(d));
        let b = Aabb::new(cast(lo), cast(hi));
        let got = hit(&b, &r, r.dir.recip(), range);
        let case = format!(
            "box {}..{}, ray from {} along {}, range ({}, {})",
            vec3(b.min),
            vec3(b.max),
            vec3(r.origin),
            vec3(r.dir),
            num(range.min),
            num(range.max)
        );
        let Some((enter, exit)) = exact_span(o, d, lo, hi) else { continue };
        let hits = enter <= exit && max.is_none_or(|m| enter < m) && exit > min;
        let Some((t0, t1)) = got else {
            if hits {
                return Err(fail(
                    case,
                    "a hit (exact arithmetic)",
                    "None",
                    "widen t_enter down and t_exit up by 2γ₃",
                ));
            }
            continue;
        };
        if !hits {
            // A box the ray passes by within the widening may be hit: conservative.
            continue;
        }
        spans += 1;
        let (want0, want1) = (enter.max(min).to_f64(), max.map_or(exit, |m| exit.min(m)).to_f64());
        let (t0, t1) = (t0 as f64, t1 as f64);
        let slack = |x: f64| f64::EPSILON * x.abs();
        let near = |t: f64, want: f64, of: Ratio| {
            (t - want).abs() <= SPAN_TOL as f64 * of.to_f64().abs() + slack(want)
        };
        let cause = if t0 > want0 + slack(want0) {
            "the entry rounded above the exact one: lower t_enter by 2γ₃, t·(1 − 2γ₃) for t ≥ 0, t·(1 + 2γ₃) below 0"
        } else if t1 < want1 - slack(want1) {
            "the exit rounded below the exact one: raise t_exit by 2γ₃, t·(1 + 2γ₃) for t ≥ 0, t·(1 − 2γ₃) below 0"
        } else if !near(t0, want0, enter) || !near(t1, want1, exit) {
            "each end within 2γ₃ and a rounding of the exact one: the latest entry and the earliest exit, widened once"
        } else {
            continue;
        };
        return Err(fail(
            case,
            format!("({want0:.9}, {want1:.9}) (exact arithmetic), the entry not above, the exit not below"),
            format!("({t0:.9}, {t1:.9})"),
            cause,
        ));
    }
    Ok(format!(
        "411 rays on slab boundaries, none NaN; the open range's ends; 2000 random rays, {spans} spans \
         conservative against exact arithmetic"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l09_acceleration::Aabb;

    use raylab::math::gamma;
    use raylab::{Float, Interval, Ray, Vec3};

    #[test]
    fn planted_box_mistakes_are_caught() {
        caught(union_cases(|a, b| Aabb::new(a.min.min(b.min), a.max.min(b.max))), "max of the maxes");
        caught(
            union_cases(|a, b| if a.is_empty() { a } else { Aabb::new(a.min.min(b.min), a.max.max(b.max)) }),
            "identity",
        );
        caught(union_point_cases(|a, p| Aabb::new(a.min.min(p), a.max)), "grow the box");
        caught(
            area_cases(|min, max| {
                let d = Aabb::new(min, max).diagonal();
                2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
            }),
            "the empty box has area 0",
        );
        caught(
            area_cases(|min, max| {
                let b = Aabb::new(min, max);
                if b.is_empty() {
                    return 0.0;
                }
                let d = b.diagonal();
                d.x * d.y + d.y * d.z + d.z * d.x
            }),
            "the factor 2",
        );
    }

    /// The slips planted in the copy of the reference slab test.
    #[derive(Clone, Copy, PartialEq, Eq)]
    /// (A strict t_enter < t_exit is no slip: with the widening it changes nothing here.)
    enum SlabSlip {
        Faithful,
        /// No swap by the sign of 1/d.
        NoSwap,
        /// NaN taken as a miss (hand-written comparisons).
        NanMiss,
        /// No range test.
        NoRange,
        /// Ordered by min/max rather than by the sign of 1/d.
        MinMax,
    }

    /// A copy of the reference slab test with a slip.
    fn slab(slip: SlabSlip, b: &Aabb, r: &Ray, inv: Vec3, range: Interval) -> Option<(Float, Float)> {
        let t0 = (b.min - r.origin) * inv;
        let t1 = (b.max - r.origin) * inv;
        let negative = inv.cmplt(Vec3::ZERO);
        let (near, far) = match slip {
            SlabSlip::NoSwap => (t0, t1),
            SlabSlip::MinMax => (t0.min(t1), t0.max(t1)),
            _ => (Vec3::select(negative, t1, t0), Vec3::select(negative, t0, t1)),
        };
        let (enter, exit) = if slip == SlabSlip::NanMiss {
            // A hand-written max that a NaN poisons.
            let pick = |a: Float, b: Float, larger: bool| if (a > b) == larger { a } else { b };
            (pick(pick(near.x, near.y, true), near.z, true), pick(pick(far.x, far.y, false), far.z, false))
        } else {
            (near.x.max(near.y).max(near.z), far.x.min(far.y).min(far.z))
        };
        // The reference's widening by 2γ₃ at both ends.
        let (up, down) = (1.0 + 2.0 * gamma(3), 1.0 - 2.0 * gamma(3));
        let enter = enter * if enter >= 0.0 { down } else { up };
        let exit = exit * if exit >= 0.0 { up } else { down };
        let overlap = enter <= exit;
        let in_range = slip == SlabSlip::NoRange || (enter < range.max && exit > range.min);
        (overlap && in_range).then(|| (enter.max(range.min), exit.min(range.max)))
    }

    macro_rules! slab_slips {
        ($($name:ident => $slip:expr),* $(,)?) => {
            $(fn $name(b: &Aabb, r: &Ray, inv: Vec3, range: Interval) -> Option<(Float, Float)> {
                slab($slip, b, r, inv, range)
            })*
        };
    }

    slab_slips! {
        slab_ok => SlabSlip::Faithful,
        no_swap => SlabSlip::NoSwap,
        nan_miss => SlabSlip::NanMiss,
        slab_no_range => SlabSlip::NoRange,
        min_max => SlabSlip::MinMax,
    }

    #[test]
    fn planted_slab_mistakes_are_caught() {
        assert!(slab_cases(slab_ok).is_ok(), "{:?}", slab_cases(slab_ok));
        assert!(slab_boundaries(slab_ok).is_ok(), "{:?}", slab_boundaries(slab_ok));
        caught(slab_cases(no_swap), "swap each slab's pair");
        caught(slab_boundaries(nan_miss), "NaN");
        caught(slab_cases(slab_no_range), "clip to the range");
        caught(slab_cases(min_max), "sign of inv_dir");
    }
}
