//! Exact ground truth for ray against box (lecture 03's slabs, lecture 09's
//! boxes): decided on integer coordinates with no rounding.

use std::cmp::Ordering;
use std::fmt;

/// An exact rational num/den with den > 0, compared by cross-multiplication.
///
/// |num| and den stay below 2³¹ here (coordinates of a few hundred units), so
/// the products are exact in i64.
#[derive(Clone, Copy, Debug)]
pub struct Ratio {
    num: i64,
    den: i64,
}

impl Ratio {
    /// num/den; `den` must be positive.
    pub fn new(num: i64, den: i64) -> Self {
        debug_assert!(den > 0, "the denominator of {num}/{den} must be positive");
        Self { num, den }
    }

    /// The nearest f64: num and den are exact in f64 (|·| < 2⁵³), so the
    /// quotient rounds once, a relative error of at most 2⁻⁵³.
    pub fn to_f64(self) -> f64 {
        self.num as f64 / self.den as f64
    }
}

impl From<i64> for Ratio {
    fn from(n: i64) -> Self {
        Self::new(n, 1)
    }
}

impl Ord for Ratio {
    fn cmp(&self, o: &Self) -> Ordering {
        (self.num * o.den).cmp(&(o.num * self.den))
    }
}

impl PartialOrd for Ratio {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl PartialEq for Ratio {
    fn eq(&self, o: &Self) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}

impl Eq for Ratio {}

/// In lowest terms: `-4/3`, `2`.
impl fmt::Display for Ratio {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (mut a, mut b) = (self.num.abs(), self.den);
        while b != 0 {
            (a, b) = (b, a % b);
        }
        let (num, den) = (self.num / a.max(1), self.den / a.max(1));
        if den == 1 { write!(f, "{num}") } else { write!(f, "{num}/{den}") }
    }
}

/// The latest slab entry and the earliest slab exit of o + t·d against the
/// box [lo, hi], each `None` while unbounded (±∞: no slab with dᵢ ≠ 0); `None`
/// overall when a slab with dᵢ = 0 does not hold the origin (no t at all).
/// Each slab with dᵢ ≠ 0 holds t in [near, far], two exact fractions; a zero
/// dᵢ keeps the slab whole when lo ≤ oᵢ ≤ hi (an origin on a face plane
/// included).
fn slab_ends(o: [i64; 3], d: [i64; 3], lo: [i64; 3], hi: [i64; 3]) -> Option<(Option<Ratio>, Option<Ratio>)> {
    let mut enter: Option<Ratio> = None; // −∞
    let mut exit: Option<Ratio> = None; // +∞
    for i in 0..3 {
        if d[i] == 0 {
            if o[i] < lo[i] || o[i] > hi[i] {
                return None;
            }
            continue;
        }
        let (near, far) = if d[i] > 0 {
            (Ratio::new(lo[i] - o[i], d[i]), Ratio::new(hi[i] - o[i], d[i]))
        } else {
            (Ratio::new(o[i] - hi[i], -d[i]), Ratio::new(o[i] - lo[i], -d[i]))
        };
        enter = Some(enter.map_or(near, |e| e.max(near)));
        exit = Some(exit.map_or(far, |x| x.min(far)));
    }
    Some((enter, exit))
}

/// Exact ground truth on integer coordinates: does o + t·d meet the closed
/// box [lo, hi] for some t > 0? Each slab holds t in [near, far], two
/// fractions compared by cross-multiplication; a zero dᵢ keeps the slab whole
/// when lo ≤ oᵢ ≤ hi (an origin on a face plane included) and empty
/// otherwise. The ray meets the box iff the latest entry ≤ the earliest exit
/// and that exit is > 0. No rounding anywhere.
pub fn exact_hits(o: [i64; 3], d: [i64; 3], lo: [i64; 3], hi: [i64; 3]) -> bool {
    let Some((enter, exit)) = slab_ends(o, d, lo, hi) else { return false };
    let ordered = match (enter, exit) {
        (Some(e), Some(x)) => e <= x,
        _ => true,
    };
    ordered && exit.is_none_or(|x| x > Ratio::from(0))
}

/// The exact span of o + t·d in the closed box [lo, hi] on integer
/// coordinates, before any range: `Some((enter, exit))`, the latest slab
/// entry and the earliest slab exit as exact fractions. The line meets the
/// box iff enter ≤ exit (enter > exit: it passes beside it); `None` when a
/// slab with dᵢ = 0 does not hold the origin. No rounding anywhere.
///
/// `d` must not be zero (a slab with dᵢ ≠ 0 bounds both ends).
pub fn exact_span(o: [i64; 3], d: [i64; 3], lo: [i64; 3], hi: [i64; 3]) -> Option<(Ratio, Ratio)> {
    assert!(d != [0; 3], "exact_span needs a nonzero direction");
    let (enter, exit) = slab_ends(o, d, lo, hi)?;
    Some((enter.expect("a slab with dᵢ ≠ 0 bounds the entry"), exit.expect("and the exit")))
}

#[cfg(test)]
mod tests {
    use super::{Ratio, exact_hits, exact_span};

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

    #[test]
    fn the_span_is_the_latest_entry_and_the_earliest_exit() {
        let (lo, hi) = ([0, 0, 0], [16, 16, 16]);
        // x: [16/16, 32/16] = [1, 2]; y: [(0 − 4)/3, (16 − 4)/3] = [−4/3, 4]; z whole.
        let (enter, exit) = exact_span([-16, 4, 8], [16, 3, 0], lo, hi).unwrap();
        assert_eq!((enter, exit), (Ratio::from(1), Ratio::from(2)));
        // Pointing away: x [(0 − 32)/16, (16 − 32)/16] = [−2, −1], behind the origin.
        let (enter, exit) = exact_span([32, 8, 8], [16, 0, 0], lo, hi).unwrap();
        assert_eq!((enter, exit), (Ratio::from(-2), Ratio::from(-1)));
        assert_eq!(Ratio::new(-4, 3).to_string(), "-4/3");
        assert_eq!(
            (Ratio::new(-39, 39).to_string(), Ratio::new(6, 4).to_string()),
            ("-1".into(), "3/2".into())
        );
        assert_eq!(Ratio::new(0, 7).to_string(), "0");
        // Beside the box: x [1, 2] and y [(40 − 16)/3, (40 − 0)/3] = [8, 40/3]: enter > exit.
        let (enter, exit) = exact_span([-16, 40, 8], [16, -3, 0], lo, hi).unwrap();
        assert!(enter > exit && enter == Ratio::new(24, 3) && exit == Ratio::from(2));
        // A parallel ray outside a slab meets no t of it.
        assert!(exact_span([-1, -16, 8], [0, 16, 0], lo, hi).is_none());
    }
}
