//! The numeric aliases of the workspace.
//!
//! `Float` is `f32` unless the kit's cargo feature `f64` is on; `Vec2`,
//! `Vec3`, `Mat3` and `Mat4` follow it. Every lecture writes `Float` and
//! these aliases, never `f32` or `glam::Vec3` directly, so the whole course
//! compiles and passes in both precisions. Book: §0.4 Precision.

#[cfg(not(feature = "f64"))]
mod precision {
    pub use glam::{Mat3, Mat4, Vec2, Vec3, Vec4};
    /// The floating-point type of the workspace.
    pub type Float = f32;
    pub use std::f32::consts;
}

#[cfg(feature = "f64")]
mod precision {
    pub use glam::{DMat3 as Mat3, DMat4 as Mat4, DVec2 as Vec2, DVec3 as Vec3, DVec4 as Vec4};
    /// The floating-point type of the workspace.
    pub type Float = f64;
    pub use std::f64::consts;
}

pub use precision::*;

/// Machine epsilon of `Float` (the distance from 1 to the next float).
pub const EPSILON: Float = Float::EPSILON;

/// Unit roundoff u = ε/2: one rounding changes a value by at most a factor (1 ± u).
pub const UNIT_ROUNDOFF: Float = Float::EPSILON * 0.5;

/// γₙ = n·u / (1 − n·u): the bound on the relative error of n successive
/// roundings (Higham; pbrt §6.8). Used for conservative bounds.
#[inline]
pub const fn gamma(n: i32) -> Float {
    let nu = n as Float * UNIT_ROUNDOFF;
    nu / (1.0 - nu)
}

/// Degrees to radians. Scene files speak degrees; the lectures take radians.
pub fn radians(degrees: Float) -> Float {
    degrees * (consts::PI / 180.0)
}

/// Radians to degrees.
pub fn degrees(radians: Float) -> Float {
    radians * (180.0 / consts::PI)
}
