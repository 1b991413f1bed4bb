//! The checks of `sah.rs`: sah_split.

use super::common::*;

/// A unit cube from x = `x` (y, z in [0, 1]) holding `count` primitives.
pub(super) fn cube_bin(x: Float, count: u32) -> Bin {
    Bin { bounds: Aabb::new(v(x, 0.0, 0.0), v(x + 1.0, 1.0, 1.0)), count }
}

pub(super) fn show_split(split: &Option<(usize, Float)>) -> String {
    maybe(split, |(k, c)| format!("split after bin {k}, cost {}", num(*c)))
}

pub(super) fn sah_cases(sah: SahFn) -> CheckResult {
    // Relative tolerance on a cost of a few units: sums and quotients of exact areas, 4ε.
    let tol = |c: Float| 4.0 * EPS * c;
    // Bin 0 = [0, 1]³ with 2 primitives, bin 11 = [10, 11] × [0, 1]² with 2. Node area
    // 2(11 + 1 + 11) = 46; every k from 0 to 10 puts one cube on each side:
    // C = 1/8 + (6·2 + 6·2)/46; the lowest k wins ties.
    let mut bins = [Bin::EMPTY; BINS];
    bins[0] = cube_bin(0.0, 2);
    bins[11] = cube_bin(10.0, 2);
    let case = "bins 0 and 11 hold a unit cube of 2 primitives each, the rest empty";
    let expected = TRAVERSAL_COST + 24.0 / 46.0;
    let got = sah(&bins);
    let Some((k, cost)) = got else {
        return Err(fail(
            case,
            show_split(&Some((0, expected))),
            show_split(&got),
            "a split with primitives on both sides exists",
        ));
    };
    if (cost - 24.0).abs() <= tol(24.0) || (cost - (TRAVERSAL_COST + 24.0)).abs() <= tol(24.0) {
        return Err(fail(
            case,
            show_split(&Some((0, expected))),
            show_split(&got),
            "divide by the node's area: C = C_trav + (A(L)·N(L) + A(R)·N(R)) / A(node)",
        ));
    }
    if (cost - 24.0 / 46.0).abs() <= tol(1.0) {
        return Err(fail(
            case,
            show_split(&Some((0, expected))),
            show_split(&got),
            "add the traversal cost C_trav = TRAVERSAL_COST",
        ));
    }
    close(
        case,
        cost,
        expected,
        tol(1.0),
        "C = C_trav + (A(L)·N(L) + A(R)·N(R)) / A(node), A the surface areas",
    )?;
    ensure(
        k == 0,
        case,
        "split after bin 0",
        format!("split after bin {k}"),
        "among equal costs keep the lowest k (test cost < best, not ≤)",
    )?;
    // Cubes at x = 0 (bin 0), 1 (bin 1), 10 (bin 11), one primitive each. k = 0: L area 6,
    // N 1; R = [1, 11], area 42, N 2: 90. k ≥ 1: L = [0, 2], area 10, N 2; R area 6, N 1:
    // 26. The cheapest is k = 1, C = 1/8 + 26/46.
    let mut bins = [Bin::EMPTY; BINS];
    bins[0] = cube_bin(0.0, 1);
    bins[1] = cube_bin(1.0, 1);
    bins[11] = cube_bin(10.0, 1);
    let case = "unit cubes of one primitive in bins 0 (x = 0), 1 (x = 1) and 11 (x = 10)";
    let cost = TRAVERSAL_COST + 26.0 / 46.0;
    let expected = Some((1, cost));
    let got = sah(&bins);
    let ok = got.is_some_and(|(k, c)| k == 1 && (c - cost).abs() <= tol(1.0));
    ensure(
        ok,
        case,
        show_split(&expected),
        show_split(&got),
        "L is the union of bins 0..=k and R of bins k+1..: sweep from both sides, and keep the cheapest k",
    )?;
    // No split: everything in one bin, all empty, zero area (points on one segment).
    let mut one = [Bin::EMPTY; BINS];
    one[5] = cube_bin(0.0, 7);
    let point = |x: Float| Bin { bounds: Aabb::new(v(x, 0.0, 0.0), v(x, 0.0, 0.0)), count: 1 };
    let mut segment = [Bin::EMPTY; BINS];
    segment[0] = point(0.0);
    segment[11] = point(1.0);
    for (case, bins, cause) in [
        (
            "all 7 primitives in bin 5",
            one,
            "skip the splits that leave one side empty: None when none is left",
        ),
        (
            "every bin empty",
            [Bin::EMPTY; BINS],
            "skip the splits that leave one side empty: None when none is left",
        ),
        (
            "two points on a segment, bins 0 and 11 (node area 0)",
            segment,
            "a node of area 0 has nothing to weigh: None (and no division by 0)",
        ),
    ] {
        let got = sah(&bins);
        ensure(got.is_none(), case, "None", show_split(&got), cause)?;
    }
    Ok("5 bin sets".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l09_acceleration::{Aabb, BINS, Bin, TRAVERSAL_COST, sah_split};

    use raylab::Float;

    /// The slips planted in the copy of the reference SAH.
    #[derive(Clone, Copy, PartialEq, Eq)]
    enum SahSlip {
        Faithful,
        /// No traversal cost.
        NoTraversalCost,
        /// No division by the node's area.
        NoAreaDivision,
        /// Ties go to the highest k.
        LastTie,
        /// Empty sides allowed.
        EmptySides,
    }

    /// The reference SAH with a slip.
    fn sah(slip: SahSlip, bins: &[Bin; BINS]) -> Option<(usize, Float)> {
        let node = bins.iter().fold(Aabb::EMPTY, |b, bin| b.union(bin.bounds)).surface_area();
        if !(node > 0.0 && node.is_finite()) {
            return None;
        }
        let mut best: Option<(usize, Float)> = None;
        for k in 0..BINS - 1 {
            let side = |r: std::ops::Range<usize>| {
                bins[r].iter().fold((Aabb::EMPTY, 0), |(b, n), bin| (b.union(bin.bounds), n + bin.count))
            };
            let ((lb, ln), (rb, rn)) = (side(0..k + 1), side(k + 1..BINS));
            if slip != SahSlip::EmptySides && (ln == 0 || rn == 0) {
                continue;
            }
            let weighted = lb.surface_area() * ln as Float + rb.surface_area() * rn as Float;
            let cost = match slip {
                SahSlip::NoTraversalCost => weighted / node,
                SahSlip::NoAreaDivision => TRAVERSAL_COST + weighted,
                _ => TRAVERSAL_COST + weighted / node,
            };
            let better =
                best.is_none_or(|(_, c)| if slip == SahSlip::LastTie { cost <= c } else { cost < c });
            if better {
                best = Some((k, cost));
            }
        }
        best
    }

    macro_rules! sah_slips {
        ($($name:ident => $slip:expr),* $(,)?) => {
            $(fn $name(bins: &[Bin; BINS]) -> Option<(usize, Float)> { sah($slip, bins) })*
        };
    }

    sah_slips! {
        sah_ok => SahSlip::Faithful,
        no_traversal => SahSlip::NoTraversalCost,
        no_area => SahSlip::NoAreaDivision,
        last_tie => SahSlip::LastTie,
        empty_sides => SahSlip::EmptySides,
    }

    #[test]
    fn planted_sah_mistakes_are_caught() {
        assert!(sah_cases(sah_ok).is_ok() && sah_cases(sah_split).is_ok());
        caught(sah_cases(no_traversal), "traversal cost");
        caught(sah_cases(no_area), "divide by the node's area");
        caught(sah_cases(last_tie), "lowest k");
        caught(sah_cases(empty_sides), "one side empty");
    }
}
