//! The checks of `capped.rs`: slab_z_span and first_crossing.

use super::common::*;

pub(super) fn span_cases(span: SpanFn) -> CheckResult {
    let inf = Float::INFINITY;
    // (o_z, d_z, the span, the cause when it differs)
    type Case = (Float, Float, Option<(Float, Float)>, &'static str);
    let cases: [Case; 8] = [
        // z = −1 + 2t: the planes z = 0 and z = 1 at t = ½ and 1.
        (-1.0, 2.0, Some((0.5, 1.0)), "the cap planes give t = −o_z/d_z and t = (1 − o_z)/d_z"),
        // z = 2 − t: z = 1 at t = 1 first, z = 0 at t = 2.
        (
            2.0,
            -1.0,
            Some((1.0, 2.0)),
            "return (entry, exit) with entry ≤ exit: going down, the plane z = 1 comes first",
        ),
        (0.25, 0.5, Some((-0.5, 1.5)), "the cap planes give t = −o_z/d_z and t = (1 − o_z)/d_z"),
        (
            0.5,
            0.0,
            Some((-inf, inf)),
            "d_z = 0 inside the slab: the whole line, (−∞, ∞); never divide by zero",
        ),
        (1.0, 0.0, Some((-inf, inf)), "the slab is closed: o_z = 1 with d_z = 0 is inside, (−∞, ∞)"),
        (0.0, 0.0, Some((-inf, inf)), "the slab is closed: o_z = 0 with d_z = 0 is inside, (−∞, ∞)"),
        (1.5, 0.0, None, "d_z = 0 outside the slab: None"),
        (-0.5, -0.0, None, "d_z = −0 outside the slab: None"),
    ];
    for (o_z, d_z, expected, cause) in cases {
        let got = span(o_z, d_z);
        let case = format!("slab_z_span(o_z = {o_z}, d_z = {d_z})");
        let ok = match (got, expected) {
            (None, None) => true,
            (Some((a, b)), Some((x, y))) => {
                let same =
                    |p: Float, q: Float| p == q || (q.is_finite() && (p - q).abs() <= TOL * q.abs().max(1.0));
                same(a, x) && same(b, y)
            }
            _ => false,
        };
        ensure(ok, case, show_span(&expected), show_span(&got), cause)?;
    }
    Ok("8 spans".into())
}

pub(super) fn crossing_cases(crossing: CrossingFn) -> CheckResult {
    let inf = Float::INFINITY;
    let ahead = ALL;
    // (side span, caps span, range, the crossing, the cause when it differs)
    type Case = ((Float, Float), (Float, Float), Interval, Option<(Float, bool)>, &'static str);
    let cases: [Case; 8] = [
        (
            (1.0, 4.0),
            (2.0, 3.0),
            ahead,
            Some((2.0, true)),
            "the solid starts at the later entry: the caps' 2, so a cap (true)",
        ),
        (
            (2.0, 3.0),
            (1.0, 4.0),
            ahead,
            Some((2.0, false)),
            "the solid starts at the later entry: the side's 2, so the side (false)",
        ),
        (
            (-2.0, 3.0),
            (-1.0, 4.0),
            ahead,
            Some((3.0, false)),
            "starting inside (entry behind), the crossing is the earlier exit: the side's 3",
        ),
        (
            (-2.0, 4.0),
            (-1.0, 3.0),
            ahead,
            Some((3.0, true)),
            "starting inside, the crossing is the earlier exit: the caps' 3, so a cap (true)",
        ),
        (
            (2.0, 2.0),
            (1.0, 4.0),
            ahead,
            Some((2.0, false)),
            "a tangent ray touches once: t_in = t_out is a hit (a miss is t_in > t_out)",
        ),
        (
            (-inf, inf),
            (1.0, 3.0),
            ahead,
            Some((1.0, true)),
            "a ray inside the tube everywhere enters through a cap",
        ),
        ((1.0, 2.0), (3.0, 4.0), ahead, None, "disjoint spans: the ray misses the solid"),
        (
            (1.0, 2.0),
            (0.0, 4.0),
            Interval::new(2.5, 9.0),
            None,
            "both crossings (1 and 2) are outside the range (2.5, 9)",
        ),
    ];
    for (side, caps, range, expected, cause) in cases {
        let got = crossing(side, caps, range);
        let case = format!(
            "first_crossing(side ({}, {}), caps ({}, {}), range ({}, {}))",
            num(side.0),
            num(side.1),
            num(caps.0),
            num(caps.1),
            num(range.min),
            num(range.max)
        );
        let show = |c: &Option<(Float, bool)>| maybe(c, |(t, cap)| format!("t = {}, cap {cap}", num(*t)));
        ensure(got == expected, case, show(&expected), show(&got), cause)?;
    }
    Ok("8 span pairs".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l04_quadrics_transforms::first_crossing;

    #[test]
    fn span_and_crossing_mistakes() {
        caught(span_cases(|o, d| Some((-o / d, (1.0 - o) / d))), "entry ≤ exit");
        caught(
            span_cases(|o, d| {
                let (t0, t1) = (-o / d, (1.0 - o) / d);
                Some((t0.min(t1), t0.max(t1)))
            }),
            "closed",
        );
        caught(
            crossing_cases(|side, caps, range| first_crossing(side, caps, range).map(|(t, cap)| (t, !cap))),
            "so a cap (true)",
        );
        caught(
            crossing_cases(|side, caps, range| {
                let (t_in, t_out) = (side.0.max(caps.0), side.1.min(caps.1));
                if t_in >= t_out {
                    return None;
                }
                first_crossing(side, caps, range)
            }),
            "tangent",
        );
    }
}
