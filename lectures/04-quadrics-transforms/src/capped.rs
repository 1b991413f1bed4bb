//! What the capped cylinder and the capped cone share: the slab 0 ≤ z ≤ 1
//! that their caps bound, and the first crossing of the solid that a side
//! span and the slab span make together.

use raylab::{Float, Interval};

/// The span of t where the ray o + t·d lies in the slab 0 ≤ z ≤ 1, as
/// (entry, exit) with entry ≤ exit: the cap planes give t = −o_z/d_z and
/// t = (1 − o_z)/d_z. A ray parallel to the caps (d_z = 0) is inside for
/// every t (−∞, ∞) when 0 ≤ o_z ≤ 1 and nowhere (`None`) otherwise.
///
/// Book: §4.2 Cylinders and their caps.
pub fn slab_z_span(o_z: Float, d_z: Float) -> Option<(Float, Float)> {
    // SOLUTION BEGIN
    if d_z == 0.0 {
        return (0.0..=1.0).contains(&o_z).then_some((Float::NEG_INFINITY, Float::INFINITY));
    }
    let t0 = -o_z / d_z;
    let t1 = (1.0 - o_z) / d_z;
    Some((t0.min(t1), t0.max(t1)))
    // SOLUTION END
}

/// The first crossing inside `range` of a solid that is the intersection
/// of two convex pieces, given the ray's span in each: the side's and the
/// caps' (slab's). Along the ray the solid is the one span
/// [max(entries), min(exits)]; the crossing is its entry if that lies in
/// `range`, else its exit (the ray starts inside), else `None`. Returns t
/// and whether a cap (rather than the side) made that crossing.
///
/// Intersecting the spans, instead of testing "z in [0, 1]" on the side
/// and "inside the disc" on the caps separately, means a ray through a rim
/// can never slip between the two tests. Book: §4.2 Cylinders and their caps.
pub fn first_crossing(side: (Float, Float), caps: (Float, Float), range: Interval) -> Option<(Float, bool)> {
    // SOLUTION BEGIN
    // The solid: enter at the later entry, leave at the earlier exit.
    let t_in = side.0.max(caps.0);
    let t_out = side.1.min(caps.1);
    if t_in > t_out {
        return None;
    }
    // The first crossing inside the range, and the surface that made it.
    if range.contains(t_in) {
        Some((t_in, caps.0 > side.0))
    } else if range.contains(t_out) {
        Some((t_out, caps.1 < side.1))
    } else {
        None
    }
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slab_span_by_hand() {
        // From z = −1 going up at speed 2: the planes z = 0 and z = 1 at t = ½ and t = 1.
        assert_eq!(slab_z_span(-1.0, 2.0), Some((0.5, 1.0)));
        // Going down from z = 2: the same planes at t = 1 and t = 2, entry first.
        assert_eq!(slab_z_span(2.0, -1.0), Some((1.0, 2.0)));
        // Parallel to the caps: everywhere inside, or nowhere.
        assert_eq!(slab_z_span(0.5, 0.0), Some((Float::NEG_INFINITY, Float::INFINITY)));
        assert_eq!(slab_z_span(1.0, 0.0), Some((Float::NEG_INFINITY, Float::INFINITY)));
        assert_eq!(slab_z_span(1.5, 0.0), None);
    }

    #[test]
    fn crossing_is_the_later_entry_or_the_earlier_exit() {
        let ahead = Interval::new(0.0, Float::INFINITY);
        // Side [1, 4], caps [2, 3]: enter through a cap at 2.
        assert_eq!(first_crossing((1.0, 4.0), (2.0, 3.0), ahead), Some((2.0, true)));
        // Side [2, 3], caps [1, 4]: enter through the side at 2.
        assert_eq!(first_crossing((2.0, 3.0), (1.0, 4.0), ahead), Some((2.0, false)));
        // Starting inside (entry behind): leave at the earlier exit, here the side's 3.
        assert_eq!(first_crossing((-2.0, 3.0), (-1.0, 4.0), ahead), Some((3.0, false)));
        // Disjoint spans: the ray misses the solid.
        assert_eq!(first_crossing((1.0, 2.0), (3.0, 4.0), ahead), None);
        // Both crossings outside the range.
        assert_eq!(first_crossing((1.0, 2.0), (0.0, 4.0), Interval::new(2.5, 9.0)), None);
    }
}
