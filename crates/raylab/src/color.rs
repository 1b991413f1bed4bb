//! Linear RGB colours and the sRGB transfer function.

use crate::math::{Float, Vec3};

/// A linear RGB colour (r, g, b) = (x, y, z). Light adds and multiplies
/// component-wise; only the image writer encodes to sRGB.
pub type Color = Vec3;

/// Black, the colour of no light.
pub const BLACK: Color = Vec3::ZERO;
/// White, unit reflectance or unit light.
pub const WHITE: Color = Vec3::ONE;

/// Encodes a linear value in [0, 1] with the sRGB transfer curve (IEC 61966-2-1):
/// 12.92·c below 0.0031308, else 1.055·c^(1/2.4) − 0.055. Values outside
/// [0, 1] are clamped first.
pub fn linear_to_srgb(c: Float) -> Float {
    let c = c.clamp(0.0, 1.0);
    if c <= 0.003_130_8 { 12.92 * c } else { 1.055 * c.powf(1.0 / 2.4) - 0.055 }
}

/// Decodes an sRGB-encoded value in [0, 1] to linear: the inverse of
/// [`linear_to_srgb`].
pub fn srgb_to_linear(s: Float) -> Float {
    let s = s.clamp(0.0, 1.0);
    if s <= 0.040_45 { s / 12.92 } else { ((s + 0.055) / 1.055).powf(2.4) }
}

/// A linear colour as three 8-bit sRGB values (rounded to nearest).
pub fn to_srgb8(c: Color) -> [u8; 3] {
    let q = |v: Float| (linear_to_srgb(v) * 255.0 + 0.5) as u8;
    [q(c.x), q(c.y), q(c.z)]
}

/// Three 8-bit sRGB values as a linear colour.
pub fn from_srgb8(p: [u8; 3]) -> Color {
    let d = |v: u8| SRGB8_TO_LINEAR[v as usize];
    Color::new(d(p[0]), d(p[1]), d(p[2]))
}

/// [`srgb_to_linear`] of each 8-bit value v / 255, computed once: a picture read from a PNG decodes
/// three values per pixel, each one of these 256 (the same values, a `powf` fewer each).
static SRGB8_TO_LINEAR: std::sync::LazyLock<[Float; 256]> =
    std::sync::LazyLock::new(|| std::array::from_fn(|v| srgb_to_linear(v as Float / 255.0)));

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_matches_the_standard_at_known_points() {
        // Linear 0.5 is sRGB 0.7353569 (from the closed form 1.055·0.5^(1/2.4) − 0.055).
        approx::assert_abs_diff_eq!(linear_to_srgb(0.5), 0.735_356_9, epsilon = 1e-6);
        // Below the knee the curve is linear with slope 12.92.
        approx::assert_abs_diff_eq!(linear_to_srgb(0.001), 0.01292, epsilon = 1e-7);
        assert_eq!(to_srgb8(Color::new(0.0, 1.0, 2.0)), [0, 255, 255]);
    }

    #[test]
    fn the_table_holds_the_curve_s_own_values() {
        for v in 0..=255u8 {
            let linear = srgb_to_linear(Float::from(v) / 255.0);
            assert_eq!(from_srgb8([v, 0, 255]), Color::new(linear, 0.0, 1.0), "value {v}");
        }
    }

    #[test]
    fn every_8bit_value_survives_a_round_trip() {
        for v in 0..=255u8 {
            assert_eq!(to_srgb8(from_srgb8([v, v, v])), [v, v, v], "value {v}");
        }
    }
}
