//! The checks of `patterns.rs`: sample_offsets.

use super::common::*;

/// The grid cell of each sample in a cols × rows grid, by floor: exact for power-of-two grids.
pub(super) fn cells(samples: &[Vec2], cols: u32, rows: u32) -> HashSet<(i64, i64)> {
    samples
        .iter()
        .map(|p| ((p.x * cols as Float).floor() as i64, (p.y * rows as Float).floor() as i64))
        .collect()
}

pub(super) fn show_samples(samples: &[Vec2]) -> String {
    let shown: Vec<String> = samples.iter().take(6).map(|p| show2(*p)).collect();
    let more = if samples.len() > 6 { format!(", … ({} in all)", samples.len()) } else { String::new() };
    format!("[{}{more}]", shown.join(", "))
}

pub(super) fn sampling_cases(sample_offsets: SamplesFn) -> CheckResult {
    // Regular, n = 4: the centres of the 2 × 2 cells, row by row; n = 1: the pixel centre.
    let mut rng = Rng::new(1);
    let expected: Vec<Vec2> =
        [(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)].map(|(x, y)| uv(x, y)).to_vec();
    let got = sample_offsets(Pattern::Regular, 4, &mut rng);
    let cause = if got.len() == 4 && got.iter().zip(&expected).all(|(g, e)| *g == *e - Vec2::splat(0.25)) {
        "the cells' centres, ((i + ½)/cols, (j + ½)/rows), not their corners"
    } else {
        "regular samples are the cells' centres ((i + ½)/cols, (j + ½)/rows), listed row by row (j outer, i inner)"
    };
    ensure(got == expected, "regular pattern, n = 4", show_samples(&expected), show_samples(&got), cause)?;
    let got = sample_offsets(Pattern::Regular, 1, &mut rng);
    ensure(
        got == [Vec2::splat(0.5)],
        "regular pattern, n = 1",
        "[(0.5000, 0.5000)]",
        show_samples(&got),
        "one regular sample is the centre of the pixel",
    )?;
    ensure(
        rng == Rng::new(1),
        "regular patterns of 4 and 1 samples",
        "no random number drawn",
        "the generator advanced",
        "the regular pattern draws nothing from the generator",
    )?;
    // Every pattern: n samples in [0, 1)², one in each cell of the k × k grid (power-of-two
    // sizes: the cells by floor are exact). Multi-jittered also puts one in each of the n
    // columns [m/n, (m+1)/n) and each of the n rows.
    for pattern in [Pattern::Regular, Pattern::Jittered, Pattern::Stratified] {
        let mut rng = Rng::new(3);
        for n in [1u32, 4, 16, 64] {
            let k = n.isqrt();
            for _ in 0..10 {
                let samples = sample_offsets(pattern, n, &mut rng);
                let case = format!("{pattern:?} pattern, n = {n}");
                ensure(
                    samples.len() == n as usize,
                    &case,
                    format!("{n} samples"),
                    samples.len(),
                    "n samples, one per cell",
                )?;
                let inside = samples.iter().all(|p| (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y));
                ensure(
                    inside,
                    &case,
                    "every sample in [0, 1)²",
                    show_samples(&samples),
                    "keep each coordinate in its stratum with in_stratum(i, count, ξ): (i + ξ)/count can round up to \
                     the next one",
                )?;
                let occupied = cells(&samples, k, k).len();
                ensure(
                    occupied == n as usize,
                    &case,
                    format!("one sample in each of the {k} × {k} cells"),
                    format!("{occupied} cells occupied: {}", show_samples(&samples)),
                    "one sample per cell: x = (i + ξ₁)/cols, y = (j + ξ₂)/rows for cell (i, j), not anywhere in \
                     the square",
                )?;
                if pattern == Pattern::Stratified {
                    let fine = cells(&samples, n, n);
                    let columns: HashSet<i64> = fine.iter().map(|c| c.0).collect();
                    let rows: HashSet<i64> = fine.iter().map(|c| c.1).collect();
                    ensure(
                        columns.len() == n as usize && rows.len() == n as usize,
                        &case,
                        format!("one sample in each of the {n} columns and {n} rows [m/n, (m+1)/n)"),
                        format!("{} columns and {} rows occupied", columns.len(), rows.len()),
                        "multi-jittered: cell (i, j) takes fine column i·rows + s and fine row j·cols + t, with s \
                         and t shuffled within each cell column and row (n-rooks)",
                    )?;
                }
                if pattern == Pattern::Regular {
                    break;
                }
            }
        }
    }
    // Non-square counts on their cols × rows grid (cols ≥ rows), listed row by row: sample
    // k in cell (k mod cols, k div cols). 6 = 3 × 2, 8 = 4 × 2, 12 = 4 × 3, 7 = 7 × 1.
    let mut rng = Rng::new(4);
    for n in [6u32, 8, 12, 7] {
        let (cols, rows) = match n {
            6 => (3, 2),
            8 => (4, 2),
            12 => (4, 3),
            _ => (7, 1),
        };
        for pattern in [Pattern::Regular, Pattern::Jittered, Pattern::Stratified] {
            let samples = sample_offsets(pattern, n, &mut rng);
            let case = format!("{pattern:?} pattern, n = {n} ({cols} columns × {rows} rows)");
            ensure(
                samples.len() == n as usize,
                &case,
                format!("{n} samples"),
                samples.len(),
                "n samples for any n",
            )?;
            for (k, p) in samples.iter().enumerate() {
                let (i, j) = (k as u32 % cols, k as u32 / cols);
                let ok = i as Float / cols as Float <= p.x
                    && p.x < (i + 1) as Float / cols as Float
                    && j as Float / rows as Float <= p.y
                    && p.y < (j + 1) as Float / rows as Float;
                ensure(
                    ok,
                    &case,
                    format!("sample {k} in cell ({i}, {j}) of the {cols} × {rows} grid"),
                    show2(*p),
                    "n samples on grid(n): rows = the largest divisor of n not above √n, cols = n/rows, listed \
                     row by row",
                )?;
            }
        }
    }
    // n = 0: nothing; the same generator state: the same samples.
    for pattern in [Pattern::Regular, Pattern::Jittered, Pattern::Stratified] {
        let got = sample_offsets(pattern, 0, &mut Rng::new(1));
        ensure(
            got.is_empty(),
            format!("{pattern:?} pattern, n = 0"),
            "no samples",
            show_samples(&got),
            "n = 0 gives no samples",
        )?;
        let (a, b) =
            (sample_offsets(pattern, 16, &mut Rng::new(99)), sample_offsets(pattern, 16, &mut Rng::new(99)));
        ensure(
            a == b,
            format!("{pattern:?} pattern, n = 16, twice from Rng::new(99)"),
            show_samples(&a),
            show_samples(&b),
            "draw only from the rng given: the same state gives the same samples",
        )?;
    }
    Ok("3 patterns at 1, 4, 16, 64 and 4 non-square counts".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    use l10_textures_sampling::{Pattern, grid, in_stratum, sample_offsets};

    use raylab::random::Rng;

    use raylab::{Float, Vec2};

    /// The slips planted in the reference patterns, each in one pattern.
    #[derive(Clone, Copy, PartialEq, Eq)]
    enum PatternSlip {
        /// Regular samples at the cells' corners.
        RegularAtCorners,
        /// Jittered anywhere in the square.
        JitterAnywhere,
        /// Multi-jittered without the shuffles' n-rooks (plain jitter).
        NoRooks,
    }

    /// The reference patterns with a slip.
    fn samples(slip: PatternSlip, pattern: Pattern, n: u32, rng: &mut Rng) -> Vec<Vec2> {
        let (cols, rows) = grid(n);
        match (pattern, slip) {
            (Pattern::Regular, PatternSlip::RegularAtCorners) => (0..n)
                .map(|k| Vec2::new((k % cols) as Float / cols as Float, (k / cols) as Float / rows as Float))
                .collect(),
            (Pattern::Jittered, PatternSlip::JitterAnywhere) => {
                (0..n).map(|_| Vec2::new(rng.next_float(), rng.next_float())).collect()
            }
            (Pattern::Stratified, PatternSlip::NoRooks) => (0..n)
                .map(|k| {
                    let (i, j) = (k % cols, k / cols);
                    Vec2::new(in_stratum(i, cols, rng.next_float()), in_stratum(j, rows, rng.next_float()))
                })
                .collect(),
            _ => sample_offsets(pattern, n, rng),
        }
    }

    #[test]
    fn planted_sampling_mistakes_are_caught() {
        caught(
            sampling_cases(|p, n, r| samples(PatternSlip::RegularAtCorners, p, n, r)),
            "not their corners",
        );
        caught(
            sampling_cases(|p, n, r| samples(PatternSlip::JitterAnywhere, p, n, r)),
            "one sample per cell",
        );
        caught(sampling_cases(|p, n, r| samples(PatternSlip::NoRooks, p, n, r)), "n-rooks");
    }
}
