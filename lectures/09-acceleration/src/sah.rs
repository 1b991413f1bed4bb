//! The surface area heuristic: where to split a node's primitives.

use raylab::Float;

use crate::aabb::Aabb;

/// How many bins a node's centroid extent is cut into (pbrt uses 12; more
/// bins find slightly better splits for a slower build).
pub const BINS: usize = 12;

/// The cost of visiting one node (testing its box and reading it), in units
/// of one primitive intersection test (pbrt-v3's 1/8).
pub const TRAVERSAL_COST: Float = 0.125;

/// One bin of a node's primitives: the box around those whose centroid falls
/// in the bin, and how many they are.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bin {
    pub bounds: Aabb,
    pub count: u32,
}

impl Bin {
    /// A bin holding nothing.
    pub const EMPTY: Bin = Bin { bounds: Aabb::EMPTY, count: 0 };
}

/// The cheapest way, by the surface area heuristic, to split a node whose
/// primitives were sorted into `bins` by their centroid along one axis.
///
/// Splitting after bin k sends bins 0..=k to the left child L and bins
/// k+1.. to the right child R. A ray that meets the node meets a child with
/// probability A(child)/A(node) (surface areas, for rays in random
/// directions), and then tests its N primitives, so the expected cost, in
/// units of one primitive test, is
///
///   C(k) = C_trav + (A(L)·N(L) + A(R)·N(R)) / A(node),
///
/// with C_trav = [`TRAVERSAL_COST`], A(node) the area of the union of all
/// bins. One sweep from the right collects the bounds and counts of every R,
/// one from the left those of every L: O(BINS) unions, not O(BINS²).
///
/// Returns `Some((k, C(k)))` for the smallest cost (the lowest k among equal
/// costs, so the build is deterministic), among the splits that leave
/// primitives on both sides; `None` when there is no such split, or when the
/// node's area is zero (all primitives at one point or on one segment:
/// there is nothing to weigh) or infinite. The build compares C(k) with
/// the cost of a leaf, N(node) tests. Book: §9.4 The surface area heuristic.
pub fn sah_split(bins: &[Bin; BINS]) -> Option<(usize, Float)> {
    // SOLUTION BEGIN
    // Sweep from the right: the area and count of bins k+1.. for each split k.
    let mut right_area = [0.0; BINS];
    let mut right_count = [0u32; BINS];
    let (mut bounds, mut count) = (Aabb::EMPTY, 0);
    for k in (1..BINS).rev() {
        bounds = bounds.union(bins[k].bounds);
        count += bins[k].count;
        right_area[k - 1] = bounds.surface_area();
        right_count[k - 1] = count;
    }

    // The node's area: the union of every bin.
    let node_area = bounds.union(bins[0].bounds).surface_area();
    if !(node_area > 0.0 && node_area.is_finite()) {
        return None;
    }

    // Sweep from the left, pricing each split that leaves both sides non-empty.
    let mut best: Option<(usize, Float)> = None;
    let (mut bounds, mut count) = (Aabb::EMPTY, 0);
    for k in 0..BINS - 1 {
        bounds = bounds.union(bins[k].bounds);
        count += bins[k].count;
        if count == 0 || right_count[k] == 0 {
            continue;
        }
        let weighted = bounds.surface_area() * count as Float + right_area[k] * right_count[k] as Float;
        let cost = TRAVERSAL_COST + weighted / node_area;
        if best.is_none_or(|(_, lowest)| cost < lowest) {
            best = Some((k, cost));
        }
    }
    best
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use raylab::Vec3;

    /// A unit cube from x = `x` (y, z in [0, 1]) holding `count` primitives.
    fn cube_bin(x: Float, count: u32) -> Bin {
        Bin { bounds: Aabb::new(Vec3::new(x, 0.0, 0.0), Vec3::new(x + 1.0, 1.0, 1.0)), count }
    }

    #[test]
    fn two_clusters_split_between_them() {
        // Bin 0 = [0, 1]³ with 2 primitives, bin 11 = [10, 11] × [0, 1]² with 2, the rest
        // empty. Node [0, 11] × [0, 1]²: area 2(11 + 1 + 11) = 46. Every k from 0 to 10 puts
        // one cube on each side: C = 1/8 + (6·2 + 6·2)/46 = 1/8 + 24/46; the lowest k wins.
        let mut bins = [Bin::EMPTY; BINS];
        bins[0] = cube_bin(0.0, 2);
        bins[11] = cube_bin(10.0, 2);
        let (k, cost) = sah_split(&bins).unwrap();
        assert_eq!(k, 0);
        assert_relative_eq!(cost, 0.125 + 24.0 / 46.0, max_relative = 4.0 * Float::EPSILON);
    }

    #[test]
    fn the_cheapest_split_keeps_neighbours_together() {
        // Cubes at x = 0 (bin 0), x = 1 (bin 1) and x = 10 (bin 11), one primitive each.
        // k = 0: L = [0, 1], area 6, N 1; R = [1, 11], area 2(10 + 1 + 10) = 42, N 2: 90.
        // k ≥ 1: L = [0, 2], area 2(2 + 1 + 2) = 10, N 2; R = 6, N 1: 26. Node area 46.
        let mut bins = [Bin::EMPTY; BINS];
        bins[0] = cube_bin(0.0, 1);
        bins[1] = cube_bin(1.0, 1);
        bins[11] = cube_bin(10.0, 1);
        let (k, cost) = sah_split(&bins).unwrap();
        assert_eq!(k, 1);
        assert_relative_eq!(cost, 0.125 + 26.0 / 46.0, max_relative = 4.0 * Float::EPSILON);
    }

    #[test]
    fn no_split_without_two_sides_or_without_area() {
        // Everything in one bin: no split leaves both sides non-empty.
        let mut bins = [Bin::EMPTY; BINS];
        bins[5] = cube_bin(0.0, 7);
        assert_eq!(sah_split(&bins), None);
        // All empty.
        assert_eq!(sah_split(&[Bin::EMPTY; BINS]), None);
        // Two bins of points on one segment: the node's area is 0.
        let point =
            |x: Float| Bin { bounds: Aabb::new(Vec3::new(x, 0.0, 0.0), Vec3::new(x, 0.0, 0.0)), count: 1 };
        let mut bins = [Bin::EMPTY; BINS];
        bins[0] = point(0.0);
        bins[11] = point(1.0);
        assert_eq!(sah_split(&bins), None);
    }
}
