//! Ray statistics: how many rays of each kind were traced and how many
//! ray–primitive tests were made.
//!
//! Counting is always on and costs one thread-local add: lectures call
//! [`count`] where they spawn a ray or test a primitive; [`measure`] adds up
//! what a piece of work counted on the calling thread, and the pixel loop
//! hands the counts of its worker threads back to the thread that called it,
//! so `measure(|| render(…))` sees the whole render and concurrent renders
//! and tests never mix their figures.
//! The cost is measured in the kit's benchmark, not assumed.

use std::cell::Cell;
use std::fmt;
use std::ops::{Add, AddAssign, Sub};

/// What is counted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Counter {
    PrimaryRays,
    ShadowRays,
    ReflectionRays,
    RefractionRays,
    IntersectionTests,
}

impl Counter {
    pub const ALL: [Counter; 5] = [
        Counter::PrimaryRays,
        Counter::ShadowRays,
        Counter::ReflectionRays,
        Counter::RefractionRays,
        Counter::IntersectionTests,
    ];

    /// The key of the counter in reports and JSON (`rays.primary`, …).
    pub fn key(self) -> &'static str {
        match self {
            Counter::PrimaryRays => "rays.primary",
            Counter::ShadowRays => "rays.shadow",
            Counter::ReflectionRays => "rays.reflection",
            Counter::RefractionRays => "rays.refraction",
            Counter::IntersectionTests => "intersection_tests",
        }
    }
}

/// A set of counts, one per [`Counter`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct RayStats {
    pub counts: [u64; 5],
}

impl RayStats {
    pub fn get(&self, c: Counter) -> u64 {
        self.counts[c as usize]
    }

    /// All rays of every kind.
    pub fn total_rays(&self) -> u64 {
        self.counts[..4].iter().sum()
    }

    /// The counts as a JSON object with the keys of [`Counter::key`].
    pub fn to_json(&self) -> String {
        let fields: Vec<String> =
            Counter::ALL.iter().map(|&c| format!("  \"{}\": {}", c.key(), self.get(c))).collect();
        format!("{{\n{}\n}}", fields.join(",\n"))
    }
}

impl fmt::Display for RayStats {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for c in Counter::ALL {
            writeln!(f, "{:<20} {:>12}", c.key(), self.get(c))?;
        }
        Ok(())
    }
}

impl Add for RayStats {
    type Output = RayStats;
    fn add(mut self, rhs: RayStats) -> RayStats {
        self += rhs;
        self
    }
}

impl AddAssign for RayStats {
    fn add_assign(&mut self, rhs: RayStats) {
        for (a, b) in self.counts.iter_mut().zip(rhs.counts) {
            *a += b;
        }
    }
}

impl Sub for RayStats {
    type Output = RayStats;
    fn sub(mut self, rhs: RayStats) -> RayStats {
        for (a, b) in self.counts.iter_mut().zip(rhs.counts) {
            *a -= b;
        }
        self
    }
}

thread_local! {
    static COUNTS: [Cell<u64>; 5] = const { [const { Cell::new(0) }; 5] };
}

/// Counts one event on this thread.
#[inline]
pub fn count(c: Counter) {
    count_n(c, 1);
}

/// Counts `n` events on this thread.
#[inline]
pub fn count_n(c: Counter, n: u64) {
    COUNTS.with(|counts| {
        let cell = &counts[c as usize];
        cell.set(cell.get().wrapping_add(n));
    });
}

/// Adds a whole set of counts to this thread's counters.
pub fn add(stats: RayStats) {
    for c in Counter::ALL {
        count_n(c, stats.get(c));
    }
}

/// What this thread has counted since it started (monotonic).
pub fn thread_totals() -> RayStats {
    COUNTS.with(|counts| RayStats { counts: std::array::from_fn(|i| counts[i].get()) })
}

/// Runs `f` on this thread and returns what it counted.
pub fn measure<R>(f: impl FnOnce() -> R) -> (R, RayStats) {
    let before = thread_totals();
    let r = f();
    (r, thread_totals() - before)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measure_counts_only_the_work_inside() {
        count(Counter::PrimaryRays);
        let ((), stats) = measure(|| {
            count(Counter::ShadowRays);
            count_n(Counter::IntersectionTests, 7);
        });
        assert_eq!(stats.get(Counter::PrimaryRays), 0);
        assert_eq!(stats.get(Counter::ShadowRays), 1);
        assert_eq!(stats.get(Counter::IntersectionTests), 7);
        assert_eq!(stats.total_rays(), 1);
    }

    #[test]
    fn json_uses_the_documented_keys() {
        let s = RayStats { counts: [1, 2, 3, 4, 5] };
        insta::assert_snapshot!(s.to_json(), @r#"
        {
          "rays.primary": 1,
          "rays.shadow": 2,
          "rays.reflection": 3,
          "rays.refraction": 4,
          "intersection_tests": 5
        }
        "#);
    }
}
