//! Timing: the median of repeated runs of a batch, with the spread of the
//! runs, and the machine's own noise on a fixed loop.
//!
//! One run times a batch (every test of a case, or one whole render) enough
//! times back to back to last at least `min_batch`, so the clock's
//! resolution and the cost of reading it vanish; the time per item is the
//! run's time over the items it did. The figure reported is the median of
//! the runs, never the mean (one run disturbed by another process would move
//! a mean), and the spread min–max of the runs says how much to trust it.
//! Book: §9.10 Measuring a hierarchy (the same method).

use std::hint::black_box;
use std::time::{Duration, Instant};

use serde::{Deserialize, Serialize};

/// What repeated runs of one batch measured, in one unit (ns per test, or ms
/// per render).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Timing {
    pub median: f64,
    pub min: f64,
    pub max: f64,
    /// How many runs the figures come from.
    pub runs: usize,
}

impl Timing {
    /// The median, min and max of `values` (one per run); `values` must not be empty.
    pub fn from_runs(values: &mut [f64]) -> Timing {
        assert!(!values.is_empty(), "a timing needs at least one run");
        values.sort_by(f64::total_cmp);
        Timing {
            median: crate::tools::bench::median(values),
            min: values[0],
            max: values[values.len() - 1],
            runs: values.len(),
        }
    }

    /// The spread of the runs relative to the median, (max − min)/median (0 for one run).
    pub fn spread(&self) -> f64 {
        if self.median > 0.0 { (self.max - self.min) / self.median } else { 0.0 }
    }

    /// The same figures in another unit (every value times `factor`).
    pub fn scaled(self, factor: f64) -> Timing {
        Timing { median: self.median * factor, min: self.min * factor, max: self.max * factor, ..self }
    }
}

/// How hard the measurements work: how many tests per case, how many runs
/// per timing and how long each run lasts at least, and how big and how
/// sampled the renders are.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Effort {
    /// Rays (or hit points) per case of the geometric pairs.
    pub samples: usize,
    /// Timed runs per figure (the median of these), at least 5 for a report.
    pub runs: usize,
    /// The shortest run: a batch is repeated within a run until it lasts this long.
    pub min_batch: Duration,
    /// Renders are made at 1/`image_divisor` of the scene's size in each direction.
    pub image_divisor: u32,
    /// The largest samples per pixel of the spp sweep (a power of two), and of its reference.
    pub max_spp: u32,
    pub reference_spp: u32,
}

impl Effort {
    /// What `grader tradeoffs` measures: the whole sweep in well under two minutes per
    /// precision in a release build on two cores.
    pub const FULL: Effort = Effort {
        samples: 20_000,
        runs: 7,
        min_batch: Duration::from_millis(5),
        image_divisor: 1,
        max_spp: 64,
        reference_spp: 256,
    };

    /// A reduced run (`--quick`, and the tests): every row, fewer samples, smaller images.
    pub const QUICK: Effort = Effort {
        samples: 2_000,
        runs: 5,
        min_batch: Duration::from_micros(200),
        image_divisor: 4,
        max_spp: 16,
        reference_spp: 64,
    };
}

/// Times `work`, which does `items` tests, `effort.runs` times; returns ns per item.
///
/// One untimed call first (warms the caches and measures how many calls make a run of
/// `effort.min_batch`), then each run calls `work` that many times.
pub fn time_per_item(effort: &Effort, items: usize, mut work: impl FnMut()) -> Timing {
    let start = Instant::now();
    work();
    let once = start.elapsed().max(Duration::from_nanos(1));
    let calls = (effort.min_batch.as_nanos() / once.as_nanos()).clamp(1, 1_000_000) as usize;
    let mut per_item: Vec<f64> = (0..effort.runs.max(1))
        .map(|_| {
            let start = Instant::now();
            for _ in 0..calls {
                work();
            }
            start.elapsed().as_nanos() as f64 / (calls * items.max(1)) as f64
        })
        .collect();
    Timing::from_runs(&mut per_item)
}

/// The machine's noise: a fixed arithmetic loop (no memory traffic, no
/// branches that depend on data) timed like any batch. Its spread is what the
/// machine alone adds to every figure of the tables.
pub fn machine_noise(effort: &Effort) -> Timing {
    time_per_item(effort, 10_000, || {
        let mut x: u64 = black_box(0x9E37_79B9_7F4A_7C15);
        for _ in 0..10_000 {
            x = black_box(x).wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        }
        black_box(x);
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn timing_keeps_the_median_and_the_extremes() {
        // Runs 3, 1, 2, 10 ns: sorted 1 2 3 10, median (2 + 3)/2 = 2.5, spread (10 − 1)/2.5 = 3.6.
        let t = Timing::from_runs(&mut [3.0, 1.0, 2.0, 10.0]);
        assert_eq!((t.median, t.min, t.max, t.runs), (2.5, 1.0, 10.0, 4));
        assert_eq!(t.spread(), 3.6);
        // Halving is exact in binary: 1.25.
        assert_eq!(t.scaled(0.5).median, 1.25);
    }

    #[test]
    fn time_per_item_divides_by_calls_and_items() {
        // Work that sleeps 1 ms and claims 1000 items: at least 1 µs per item in every run.
        let effort = Effort { runs: 5, min_batch: Duration::ZERO, ..Effort::QUICK };
        let t = time_per_item(&effort, 1000, || std::thread::sleep(Duration::from_millis(1)));
        assert_eq!(t.runs, 5);
        assert!(t.min >= 1000.0 && t.min <= t.median && t.median <= t.max, "{t:?}");
    }
}
