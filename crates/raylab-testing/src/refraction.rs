//! Refraction at the edge of total internal reflection, found by search
//! rather than by hand: the inputs lecture 07's tests and checks both give
//! `refract` where its contract's sin²θ_t rounds to exactly 1.

use raylab::{Float, Vec3};

/// An incoming direction `i` onto the normal +y, and a ratio `eta`, for which
/// sin²θ_t = (η·η)(1 − cos θ_i·cos θ_i) is exactly 1 in `Float`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExactlyOne {
    /// cos θ_i = k/64.
    pub k: u32,
    /// 1 − cos²θ_i, exact.
    pub sin2_i: Float,
    /// (sin θ_i, −cos θ_i, 0): i·n = −cos θ_i exactly, whatever the rounding of sin θ_i.
    pub i: Vec3,
    pub eta: Float,
}

/// Every case where sin²θ_t = (η·η)(1 − cos θ_i·cos θ_i) rounds to exactly
/// 1: cos θ_i = k/64 for k = 1..63 (so 1 − cos²θ_i is exact) and η among
/// the 17 floats nearest 1/√(1 − cos²θ_i), the product evaluated as the
/// contract states it. Exactly 1 is θ_t = 90°: no transmitted ray.
pub fn sin2_t_exactly_one() -> Vec<ExactlyOne> {
    let mut cases = Vec::new();
    for k in 1..64 {
        let cos_i = k as Float / 64.0;
        let sin2_i = 1.0 - cos_i * cos_i;
        let i = Vec3::new(sin2_i.sqrt(), -cos_i, 0.0);
        let nearest = 1.0 / sin2_i.sqrt();
        for step in -8i64..=8 {
            let eta = Float::from_bits((nearest.to_bits() as i64 + step) as _);
            if eta * eta * sin2_i == 1.0 {
                cases.push(ExactlyOne { k, sin2_i, i, eta });
            }
        }
    }
    cases
}
