//! Points of the unit sphere whose texture coordinates are known without
//! the forward map: lecture 10's sphere_uv tests and checks both use them.

use raylab::math::consts::{PI, TAU};
use raylab::{Float, Vec2, Vec3};

/// Every (u, v) of the 9 × 9 grid u, v ∈ {0.1, …, 0.9} (inside the seam and
/// the poles) with its point of the unit sphere by the inverse map, written
/// from the definition (independent of the code): φ = 2π(u − ½),
/// λ = π(v − ½), p = (cos λ cos φ, sin λ, −cos λ sin φ).
pub fn sphere_grid() -> Vec<(Vec2, Vec3)> {
    let mut points = Vec::new();
    for i in 1..10 {
        for j in 1..10 {
            let (u, v) = (i as Float / 10.0, j as Float / 10.0);
            let (phi, lambda) = (TAU * (u - 0.5), PI * (v - 0.5));
            let p = Vec3::new(lambda.cos() * phi.cos(), lambda.sin(), -lambda.cos() * phi.sin());
            points.push((Vec2::new(u, v), p));
        }
    }
    points
}
