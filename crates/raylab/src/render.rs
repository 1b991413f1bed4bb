//! The pixel loop: calls a closure once per pixel, in parallel over rows
//! (rayon), with a progress bar when a render takes more than a second and
//! standard error is a terminal.

use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;

use crate::color::Color;
use crate::image::Image;
use crate::stats::{RayStats, thread_totals};

/// Calls `f(x, y)` for every pixel of a `width × height` grid, rows in
/// parallel, and returns the values row-major with what the calls counted
/// in [`crate::stats`]. The counts are also added to the calling thread's
/// counters, so an enclosing [`crate::stats::measure`] sees them.
pub fn render_map<T, F>(width: u32, height: u32, f: F) -> (Vec<T>, RayStats)
where
    T: Send,
    F: Fn(u32, u32) -> T + Sync,
{
    let progress = Progress::new(height);
    let own_before = thread_totals();
    let total = Mutex::new(RayStats::default());
    let rows: Vec<Vec<T>> = (0..height)
        .into_par_iter()
        .map(|y| {
            let before = thread_totals();
            let row: Vec<T> = (0..width).map(|x| f(x, y)).collect();
            *total.lock().unwrap() += thread_totals() - before;
            progress.row_done();
            row
        })
        .collect();
    progress.finish();
    let total = total.into_inner().unwrap();
    // Hand the other threads' counts to this thread (its own rows are there already).
    crate::stats::add(total - (thread_totals() - own_before));
    (rows.into_iter().flatten().collect(), total)
}

/// [`render_map`] for colours: the image and the statistics.
pub fn render_image<F>(width: u32, height: u32, f: F) -> (Image, RayStats)
where
    F: Fn(u32, u32) -> Color + Sync,
{
    let (pixels, stats) = render_map(width, height, f);
    (Image::from_pixels(width, height, pixels), stats)
}

/// A progress bar that stays hidden for the first second.
struct Progress {
    bar: ProgressBar,
    start: Instant,
    shown: AtomicBool,
}

impl Progress {
    fn new(rows: u32) -> Self {
        let bar = ProgressBar::with_draw_target(Some(rows as u64), ProgressDrawTarget::hidden());
        bar.set_style(
            ProgressStyle::with_template("rendering {bar:40} {pos}/{len} rows, {eta} left")
                .expect("valid template"),
        );
        Self { bar, start: Instant::now(), shown: AtomicBool::new(false) }
    }

    fn row_done(&self) {
        self.bar.inc(1);
        if !self.shown.load(Ordering::Relaxed) && self.start.elapsed() > Duration::from_secs(1) {
            self.shown.store(true, Ordering::Relaxed);
            // Shown only on a terminal: indicatif draws nothing elsewhere.
            self.bar.set_draw_target(ProgressDrawTarget::stderr());
        }
    }

    fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::{Counter, count};

    #[test]
    fn every_pixel_once_row_major_with_summed_counts() {
        let (values, stats) = render_map(5, 3, |x, y| {
            count(Counter::PrimaryRays);
            (x, y)
        });
        let expected: Vec<(u32, u32)> = (0..3).flat_map(|y| (0..5).map(move |x| (x, y))).collect();
        assert_eq!(values, expected);
        assert_eq!(stats.get(Counter::PrimaryRays), 15);
    }

    #[test]
    fn an_enclosing_measure_sees_the_whole_render_once() {
        let ((_, inner), outer) =
            crate::stats::measure(|| render_map(64, 64, |_, _| count(Counter::ShadowRays)));
        assert_eq!(inner.get(Counter::ShadowRays), 64 * 64);
        assert_eq!(outer, inner);
    }
}
