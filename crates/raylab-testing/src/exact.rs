//! Exact ground truth for ray against box (lecture 03's slabs, lecture 09's
//! boxes): decided on integer coordinates with no rounding.

/// An exact rational num/den with den > 0.
#[derive(Clone, Copy, Debug)]
struct Ratio(i64, i64);

impl Ratio {
    fn le(self, o: Ratio) -> bool {
        // |values| < 2³¹ here, so the products are exact in i64.
        self.0 * o.1 <= o.0 * self.1
    }
}

/// Exact ground truth on integer coordinates: does o + t·d meet the closed
/// box [lo, hi] for some t > 0? Each slab holds t in [near, far], two
/// fractions compared by cross-multiplication; a zero dᵢ keeps the slab whole
/// when lo ≤ oᵢ ≤ hi (an origin on a face plane included) and empty
/// otherwise. The ray meets the box iff the latest entry ≤ the earliest exit
/// and that exit is > 0. No rounding anywhere.
pub fn exact_hits(o: [i64; 3], d: [i64; 3], lo: [i64; 3], hi: [i64; 3]) -> bool {
    let mut enter: Option<Ratio> = None; // −∞
    let mut exit: Option<Ratio> = None; // +∞
    for i in 0..3 {
        if d[i] == 0 {
            if o[i] < lo[i] || o[i] > hi[i] {
                return false;
            }
            continue;
        }
        let (near, far) = if d[i] > 0 {
            (Ratio(lo[i] - o[i], d[i]), Ratio(hi[i] - o[i], d[i]))
        } else {
            (Ratio(o[i] - hi[i], -d[i]), Ratio(o[i] - lo[i], -d[i]))
        };
        if enter.is_none_or(|e| e.le(near)) {
            enter = Some(near);
        }
        if exit.is_none_or(|x| far.le(x)) {
            exit = Some(far);
        }
    }
    let ordered = match (enter, exit) {
        (Some(e), Some(x)) => e.le(x),
        _ => true,
    };
    ordered && exit.is_none_or(|x| x.0 > 0)
}

#[cfg(test)]
mod tests {
    use super::exact_hits;

    #[test]
    fn the_faces_count_and_a_ray_beside_them_misses() {
        // The box [0, 16]³ (integers stand for sixteenths).
        let (lo, hi) = ([0, 0, 0], [16, 16, 16]);
        assert!(exact_hits([-16, 8, 8], [16, 0, 0], lo, hi), "across at t = 1");
        assert!(exact_hits([0, -16, 8], [0, 16, 0], lo, hi), "along its own face plane");
        assert!(!exact_hits([-1, -16, 8], [0, 16, 0], lo, hi), "beside its face plane");
        assert!(!exact_hits([-16, 8, 8], [-16, 0, 0], lo, hi), "pointing away");
        assert!(exact_hits([8, 8, 8], [1, 2, 3], lo, hi), "from inside");
    }
}
