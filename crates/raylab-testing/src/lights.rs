//! Lights and their falloff worked out by hand, as lecture 05's tests and
//! checks both use them: attenuations at distance 2, and a spot over a floor.

use raylab::scene::{Attenuation, LightKind};
use raylab::{Float, Vec3, radians};

/// Attenuations (c, l, q) and the factor 1/(c + l·d + q·d²) at d = 2, by hand:
/// 1/(c + 2l + 4q): (1,0,0) → 1, (0,1,0) → ½, (0,0,1) → ¼, (1,1,1) → 1/7,
/// (½,¼,⅛) → 1/(½ + ½ + ½) = ⅔.
pub const FALLOFF_AT_2: [((Float, Float, Float), Float); 5] = [
    ((1.0, 0.0, 0.0), 1.0),
    ((0.0, 1.0, 0.0), 0.5),
    ((0.0, 0.0, 1.0), 0.25),
    ((1.0, 1.0, 1.0), 1.0 / 7.0),
    ((0.5, 0.25, 0.125), 2.0 / 3.0),
];

/// A spot at (0, 1, 0) shining straight down, no attenuation, its cones
/// `inner_degrees` and `outer_degrees` from the axis.
pub fn spot_down(inner_degrees: Float, outer_degrees: Float) -> LightKind {
    LightKind::Spot {
        position: Vec3::Y,
        direction: -Vec3::Y,
        inner: radians(inner_degrees),
        outer: radians(outer_degrees),
        attenuation: Attenuation::default(),
    }
}

/// The point of the floor y = 0 seen from [`spot_down`]'s light at `degrees`
/// off its axis: (tan α, 0, 0).
pub fn floor_at(degrees: Float) -> Vec3 {
    Vec3::new(radians(degrees).tan(), 0.0, 0.0)
}
