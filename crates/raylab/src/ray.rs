//! Rays and parameter intervals.

use crate::math::{Float, Vec3};

/// A ray p(t) = origin + t·dir.
///
/// `dir` need not be unit length: a ray taken into an object's space by an
/// affine map keeps its t, so a hit's t stays in world units. Primary rays
/// from the cameras have unit directions. Book: §0.3 Rays.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Ray {
    pub origin: Vec3,
    pub dir: Vec3,
}

impl Ray {
    #[inline]
    pub const fn new(origin: Vec3, dir: Vec3) -> Self {
        Self { origin, dir }
    }

    /// The point at parameter `t`: origin + t·dir.
    #[inline]
    pub fn at(&self, t: Float) -> Vec3 {
        self.origin + t * self.dir
    }
}

/// An open interval of ray parameters: a hit counts when `min < t < max`.
///
/// Intersection routines take the interval and shrink `max` to the closest
/// hit found so far. Book: §0.3 Rays.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Interval {
    pub min: Float,
    pub max: Float,
}

impl Interval {
    /// Everything in front of the origin: (0, ∞).
    pub const POSITIVE: Interval = Interval { min: 0.0, max: Float::INFINITY };

    #[inline]
    pub const fn new(min: Float, max: Float) -> Self {
        Self { min, max }
    }

    /// True when `min < t < max` (never for NaN).
    #[inline]
    pub fn contains(&self, t: Float) -> bool {
        self.min < t && t < self.max
    }

    /// The same interval ending at `max`.
    #[inline]
    pub fn with_max(self, max: Float) -> Self {
        Self { min: self.min, max }
    }

    /// True when no t satisfies `min < t < max` (also when an end is NaN).
    #[allow(clippy::neg_cmp_op_on_partial_ord)] // the negation is what makes NaN ends empty
    pub fn is_empty(&self) -> bool {
        !(self.min < self.max)
    }
}
