//! Where a pixel's samples go: regular, jittered and multi-jittered
//! patterns in the unit square.

use raylab::random::Rng;
use raylab::{Float, Vec2};

/// How [`sample_offsets`] places n samples in the unit square [0, 1)². All
/// three cut the square into the `cols × rows` cells of [`grid`]`(n)` (√n × √n
/// when n is a square) and list the samples row by row (j outer, i inner).
/// Book: §10.6 Sampling patterns.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pattern {
    /// The centres of the cells, ((i + ½)/cols, (j + ½)/rows): no randomness,
    /// and n = 1 is the pixel centre. Edges converge in steps, and a pattern
    /// finer than the grid aliases into a false coarse one (moiré).
    Regular,
    /// Jittered (stratified random) sampling: one uniform sample in each cell,
    /// ((i + ξ₁)/cols, (j + ξ₂)/rows). Trades the aliasing for noise; at an
    /// edge only the cells it crosses can be wrong.
    Jittered,
    /// Multi-jittered sampling (Chiu, Shirley and Wang 1994): one sample in
    /// each cell *and* one in each of the n columns [k/n, (k+1)/n) × [0, 1)
    /// and each of the n rows [0, 1) × [k/n, (k+1)/n), an n-rooks (Latin
    /// hypercube) arrangement that is also jittered. Nearly vertical or
    /// horizontal edges then converge like n samples in 1D, not √n.
    Stratified,
}

/// The grid of n cells: rows = the largest divisor of n not above √n and
/// cols = n / rows, so cols·rows = n and cols ≥ rows. √n × √n for a square
/// n (1, 4, 16, 64), 3 × 2 for 6, n × 1 strips for a prime; (0, 0) for 0.
pub fn grid(n: u32) -> (u32, u32) {
    if n == 0 {
        return (0, 0);
    }
    let mut rows = n.isqrt();
    while !n.is_multiple_of(rows) {
        rows -= 1;
    }
    (n / rows, rows)
}

/// The point a fraction ξ ∈ [0, 1) of the way through stratum `i` of [0, 1)
/// cut into `count` equal strata: (i + ξ)/count, kept below the stratum's end
/// (i + 1)/count. Rounding can carry i + ξ up to i + 1 (in f32, 7 + (1 − 2⁻²⁴)
/// rounds to 8), which would put the sample in the next stratum, or at 1 for
/// the last one; the result is at most the float below the end, so every
/// sample stays in its stratum and in [0, 1). Requires i < count.
pub fn in_stratum(i: u32, count: u32, xi: Float) -> Float {
    debug_assert!(i < count && (0.0..1.0).contains(&xi), "in_stratum({i}, {count}, {xi})");
    let end = (i + 1) as Float / count as Float;
    ((i as Float + xi) / count as Float).min(end.next_down())
}

/// n sample positions in the unit square [0, 1)², placed by `pattern` (see
/// [`Pattern`] for each), in the cells of [`grid`]`(n)` listed row by row.
/// Jittered draws ξ₁, ξ₂ per cell in that order; multi-jittered draws its
/// shuffles then ξ₁, ξ₂ per cell; both put each coordinate in its stratum
/// with [`in_stratum`]. The same `rng` state gives the same samples.
///
/// Multi-jittered, for cols × rows cells: the fine columns of cell column i
/// are i·rows + s (s < rows) and the fine rows of cell row j are j·cols + t
/// (t < cols). Start from cell (i, j) taking s = j and t = i (every fine row
/// and column used once), shuffle the s of each cell column and the t of each
/// cell row (Fisher–Yates with `rng.int`), and place the sample uniformly in
/// fine column i·rows + s and fine row j·cols + t. The shuffles keep both
/// properties and decorrelate the cells.
///
/// n = 0 gives no samples. Book: §10.6 Sampling patterns.
pub fn sample_offsets(pattern: Pattern, n: u32, rng: &mut Rng) -> Vec<Vec2> {
    // SOLUTION BEGIN
    let (cols, rows) = grid(n);
    let mut samples = Vec::with_capacity(n as usize);
    match pattern {
        Pattern::Regular => {
            // The centre of each cell.
            for j in 0..rows {
                for i in 0..cols {
                    let x = (i as Float + 0.5) / cols as Float;
                    let y = (j as Float + 0.5) / rows as Float;
                    samples.push(Vec2::new(x, y));
                }
            }
        }
        Pattern::Jittered => {
            // One uniform point in each cell.
            for j in 0..rows {
                for i in 0..cols {
                    let x = in_stratum(i, cols, rng.next_float());
                    let y = in_stratum(j, rows, rng.next_float());
                    samples.push(Vec2::new(x, y));
                }
            }
        }
        Pattern::Stratified => {
            // The canonical arrangement: cell k = j·cols + i takes s = j and t = i.
            let mut s: Vec<u32> = (0..n).map(|k| k / cols).collect();
            let mut t: Vec<u32> = (0..n).map(|k| k % cols).collect();
            // Shuffle the s within each cell column and the t within each cell row.
            let cell = |i: u32, j: u32| (j * cols + i) as usize;
            for i in 0..cols {
                for j in 0..rows {
                    let other = rng.int(i64::from(j), i64::from(rows) - 1) as u32;
                    s.swap(cell(i, j), cell(i, other));
                }
            }
            for j in 0..rows {
                for i in 0..cols {
                    let other = rng.int(i64::from(i), i64::from(cols) - 1) as u32;
                    t.swap(cell(i, j), cell(other, j));
                }
            }
            // One uniform point in each cell's fine column and fine row.
            for j in 0..rows {
                for i in 0..cols {
                    let k = cell(i, j);
                    let x = in_stratum(i * rows + s[k], n, rng.next_float());
                    let y = in_stratum(j * cols + t[k], n, rng.next_float());
                    samples.push(Vec2::new(x, y));
                }
            }
        }
    }
    samples
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    const SIZES: [u32; 4] = [1, 4, 16, 64];

    /// The (column, row) cell of each sample in a cols × rows grid, by floor. Exact for the
    /// power-of-two grids tested (multiplying by a power of two does not round).
    fn cells(samples: &[Vec2], cols: u32, rows: u32) -> HashSet<(i64, i64)> {
        samples
            .iter()
            .map(|p| ((p.x * cols as Float).floor() as i64, (p.y * rows as Float).floor() as i64))
            .collect()
    }

    fn all_in_unit_square(samples: &[Vec2]) -> bool {
        samples.iter().all(|p| (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y))
    }

    #[test]
    fn grid_is_the_most_square_factorisation() {
        assert_eq!([1, 4, 16, 64].map(grid), [(1, 1), (2, 2), (4, 4), (8, 8)]);
        // 6 = 3·2, 12 = 4·3, 7 prime: strips; 0: nothing.
        assert_eq!([6, 12, 7, 2, 0].map(grid), [(3, 2), (4, 3), (7, 1), (2, 1), (0, 0)]);
    }

    #[test]
    fn in_stratum_stays_in_its_stratum_when_rounding_reaches_the_end() {
        // ξ = 1 − 2⁻ᵖ (the largest next_float) in stratum 7 of 8: 7 + ξ rounds to 8 in f32;
        // the result must still be below 8/8 = 1 and at least 7/8.
        let xi = 1.0 - Float::EPSILON / 2.0;
        let x = in_stratum(7, 8, xi);
        assert!((0.875..1.0).contains(&x), "{x}");
        assert!((0.375..0.5).contains(&in_stratum(3, 8, xi)));
        assert_eq!(in_stratum(3, 8, 0.0), 0.375);
    }

    #[test]
    fn regular_samples_are_the_cell_centres() {
        // n = 4: the centres of the 2 × 2 cells, by hand, row by row.
        let mut rng = Rng::new(1);
        let expected = [(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)].map(|(x, y)| Vec2::new(x, y));
        assert_eq!(sample_offsets(Pattern::Regular, 4, &mut rng), expected);
        assert_eq!(sample_offsets(Pattern::Regular, 1, &mut rng), [Vec2::splat(0.5)]);
        // k × k: each coordinate is an odd multiple of 1/2k (the centre of its cell), n
        // distinct points, one per cell, and no random number drawn.
        for n in SIZES {
            let k = n.isqrt();
            let samples = sample_offsets(Pattern::Regular, n, &mut rng);
            for p in &samples {
                for c in [p.x, p.y] {
                    let twice = c * (2 * k) as Float;
                    assert!(twice.fract() == 0.0 && twice as u32 % 2 == 1, "{c} for n = {n}");
                }
            }
            assert_eq!((samples.len(), cells(&samples, k, k).len()), (n as usize, n as usize));
        }
        assert_eq!(rng, Rng::new(1));
    }

    #[test]
    fn jittered_puts_exactly_one_sample_in_each_cell() {
        // n samples in n distinct cells of the k × k grid: exactly one in each.
        let mut rng = Rng::new(2);
        for n in SIZES {
            let k = n.isqrt();
            let samples = sample_offsets(Pattern::Jittered, n, &mut rng);
            assert_eq!(samples.len(), n as usize);
            assert!(all_in_unit_square(&samples));
            assert_eq!(cells(&samples, k, k).len(), n as usize, "n = {n}");
        }
    }

    #[test]
    fn stratified_has_one_sample_per_cell_row_and_column_stratum() {
        // Multi-jittered: one per cell of the k × k grid, and the n samples fall in n distinct
        // columns [m/n, (m+1)/n) and n distinct rows: the n-rooks property.
        let mut rng = Rng::new(3);
        for n in SIZES {
            let k = n.isqrt();
            for _ in 0..20 {
                let samples = sample_offsets(Pattern::Stratified, n, &mut rng);
                assert_eq!(samples.len(), n as usize);
                assert!(all_in_unit_square(&samples));
                assert_eq!(cells(&samples, k, k).len(), n as usize, "cells, n = {n}");
                let fine = cells(&samples, n, n);
                let columns: HashSet<i64> = fine.iter().map(|c| c.0).collect();
                let rows: HashSet<i64> = fine.iter().map(|c| c.1).collect();
                assert_eq!((columns.len(), rows.len()), (n as usize, n as usize), "strata, n = {n}");
            }
        }
    }

    #[test]
    fn non_square_counts_are_stratified_on_their_grid() {
        // n = 6 on 3 × 2 cells, n = 8 on 4 × 2: one per cell, and n-rooks for multi-jittered.
        // The grids are not all powers of two, so cells are found by in_stratum's own bounds:
        // sample coordinates are below the float (i + 1)/count, and at least i/count.
        let mut rng = Rng::new(4);
        for n in [6u32, 8, 12] {
            let (cols, rows) = grid(n);
            for pattern in [Pattern::Regular, Pattern::Jittered, Pattern::Stratified] {
                let samples = sample_offsets(pattern, n, &mut rng);
                assert!(all_in_unit_square(&samples));
                for (k, p) in samples.iter().enumerate() {
                    let (i, j) = (k as u32 % cols, k as u32 / cols);
                    assert!(i as Float / cols as Float <= p.x && p.x < (i + 1) as Float / cols as Float);
                    assert!(j as Float / rows as Float <= p.y && p.y < (j + 1) as Float / rows as Float);
                }
            }
        }
    }

    #[test]
    fn the_same_seed_gives_the_same_samples() {
        for pattern in [Pattern::Jittered, Pattern::Stratified] {
            let a = sample_offsets(pattern, 16, &mut Rng::new(99));
            let b = sample_offsets(pattern, 16, &mut Rng::new(99));
            let c = sample_offsets(pattern, 16, &mut Rng::new(100));
            assert_eq!(a, b);
            assert_ne!(a, c);
        }
        assert!(sample_offsets(Pattern::Stratified, 0, &mut Rng::new(1)).is_empty());
    }
}
