//! Test support: f64 views of `Float` values, for independent references. The
//! seeded generator is the kit's `raylab::random::Rng`.

use raylab::{Float, Vec3};

/// A `Float` widened to `f64` without rounding (the identity when `Float` is f64).
#[allow(clippy::unnecessary_cast)]
pub fn to_f64(x: Float) -> f64 {
    x as f64
}

/// A `Float` vector widened to `f64` without rounding.
pub fn wide(v: Vec3) -> [f64; 3] {
    [to_f64(v.x), to_f64(v.y), to_f64(v.z)]
}
