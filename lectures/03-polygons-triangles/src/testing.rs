//! Test support: a seeded pseudo-random generator, so the tests draw the same
//! rays on every machine without the `rand` crate.

use raylab::{Float, Vec3};

/// SplitMix64 (Steele, Lea, Flood 2014).
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1), with 53 random bits.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi), rounded to `Float`.
    pub fn range(&mut self, lo: f64, hi: f64) -> Float {
        (lo + (hi - lo) * self.unit()) as Float
    }

    /// A uniform integer in lo..=hi.
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as i64
    }

    /// A point uniform in the cube [−h, h]³.
    pub fn in_cube(&mut self, h: f64) -> Vec3 {
        Vec3::new(self.range(-h, h), self.range(-h, h), self.range(-h, h))
    }
}

/// A `Float` widened to `f64` without rounding (the identity when `Float` is f64).
#[allow(clippy::unnecessary_cast)]
pub fn to_f64(x: Float) -> f64 {
    x as f64
}

/// A `Float` vector widened to `f64` without rounding.
pub fn wide(v: Vec3) -> [f64; 3] {
    [to_f64(v.x), to_f64(v.y), to_f64(v.z)]
}
