//! Image textures: looking up a colour between the pixels.

use raylab::{BLACK, Color, Float, Image, Vec2};

/// The colour of `image` at texture coordinates `uv`, blended from the four
/// nearest pixel centres (bilinear filtering), the image repeating in both
/// directions (wrap addressing).
///
/// Conventions: pixel i of a row has its centre at u = (i + ½)/w, and v grows
/// upward, so row 0 (the top row) has its centre at v = 1 − ½/h and row j at
/// v = 1 − (j + ½)/h. In continuous pixel coordinates, centres at integers,
///
/// ```text
/// x = u·w − ½,   y = (1 − v)·h − ½,   i = ⌊x⌋, j = ⌊y⌋, fx = x − i, fy = y − j,
/// c = (1 − fy)·[(1 − fx)·P(i, j) + fx·P(i+1, j)] + fy·[(1 − fx)·P(i, j+1) + fx·P(i+1, j+1)],
/// ```
///
/// with column indices taken mod w and row indices mod h (Euclidean, so −1 is
/// the last one). At a pixel centre it returns that pixel; halfway between two
/// centres, their mean; at u = 0 (or 1), the mean of the first and the last
/// column. u and v are first reduced mod 1, which keeps x exact to the pixel
/// for any tiling. An empty image gives black; `uv` must be finite (a NaN
/// reads as NaN, never out of bounds). Book: §10.4 Image textures and filtering.
pub fn bilinear(image: &Image, uv: Vec2) -> Color {
    debug_assert!(uv.is_finite(), "bilinear: uv = {uv}");
    // SOLUTION BEGIN
    let (w, h) = (image.width, image.height);
    if w == 0 || h == 0 {
        return BLACK;
    }
    // Continuous pixel coordinates, centres at integers, rows going down as v goes up.
    let x = uv.x.rem_euclid(1.0) * w as Float - 0.5;
    let y = (1.0 - uv.y.rem_euclid(1.0)) * h as Float - 0.5;
    let (x0, y0) = (x.floor(), y.floor());
    let (fx, fy) = (x - x0, y - y0);
    // The four neighbours, wrapping around the edges.
    let column = |i: i64| i.rem_euclid(i64::from(w)) as u32;
    let row = |j: i64| j.rem_euclid(i64::from(h)) as u32;
    let (i, j) = (x0 as i64, y0 as i64);
    let (left, right, up, down) = (column(i), column(i + 1), row(j), row(j + 1));
    // Blend along each row, then between the rows.
    let top = (1.0 - fx) * image.get(left, up) + fx * image.get(right, up);
    let bottom = (1.0 - fx) * image.get(left, down) + fx * image.get(right, down);
    (1.0 - fy) * top + fy * bottom
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_abs_diff_eq;
    use raylab::Vec3;

    const EPS: Float = Float::EPSILON;

    /// A 4 × 2 image whose pixel (i, j) is (i, j, 1): every value exact, every mean of two or
    /// four of them exact (multiples of ¼), and u = (i + ½)/4, v = 1 − (j + ½)/2 exact too.
    fn ramp() -> Image {
        let pixels =
            (0..2).flat_map(|j| (0..4).map(move |i| Vec3::new(i as Float, j as Float, 1.0))).collect();
        Image::from_pixels(4, 2, pixels)
    }

    fn centre(i: u32, j: u32) -> Vec2 {
        Vec2::new((i as Float + 0.5) / 4.0, 1.0 - (j as Float + 0.5) / 2.0)
    }

    #[test]
    fn pixel_centres_return_the_pixel() {
        // fx = fy = 0 exactly at each centre (powers of two: no rounding), so weights 1 and 0.
        let image = ramp();
        for j in 0..2 {
            for i in 0..4 {
                assert_eq!(bilinear(&image, centre(i, j)), image.get(i, j), "pixel ({i}, {j})");
            }
        }
        // Row 0 is the top: v = 0.75 reads row 0, v = 0.25 row 1.
        assert_eq!(bilinear(&image, Vec2::new(0.125, 0.75)).y, 0.0);
        assert_eq!(bilinear(&image, Vec2::new(0.125, 0.25)).y, 1.0);
    }

    #[test]
    fn halfway_between_pixels_is_their_mean() {
        // Between the centres of (1, 0) and (2, 0): u = ½, v = ¾ → (1.5, 0, 1). Between rows 0
        // and 1 of column 3: u = ⅞, v = ½ → (3, 0.5, 1). Midway among four: (1.5, 0.5, 1).
        let image = ramp();
        assert_eq!(bilinear(&image, Vec2::new(0.5, 0.75)), Vec3::new(1.5, 0.0, 1.0));
        assert_eq!(bilinear(&image, Vec2::new(0.875, 0.5)), Vec3::new(3.0, 0.5, 1.0));
        assert_eq!(bilinear(&image, Vec2::new(0.5, 0.5)), Vec3::new(1.5, 0.5, 1.0));
        // A quarter of the way from (0, 0) to (1, 0): x = 0.25 → (0.25, 0, 1).
        assert_eq!(bilinear(&image, Vec2::new(0.1875, 0.75)), Vec3::new(0.25, 0.0, 1.0));
    }

    #[test]
    fn edges_wrap_around() {
        // u = 0 is x = −½: halfway between the last column (3) and the first (0): red 1.5.
        // v = 0 is y = 1.5: between the last row (1) and row 2 ≡ 0: green ½; v = 1 ≡ 0 the
        // same (y = −½ before the reduction). The corner (0, 0) mixes all four corners.
        let image = ramp();
        assert_eq!(bilinear(&image, Vec2::new(0.0, 0.75)), Vec3::new(1.5, 0.0, 1.0));
        assert_eq!(bilinear(&image, Vec2::new(1.0, 0.75)), Vec3::new(1.5, 0.0, 1.0));
        assert_eq!(bilinear(&image, Vec2::new(0.125, 1.0)), Vec3::new(0.0, 0.5, 1.0));
        assert_eq!(bilinear(&image, Vec2::new(0.125, 0.0)), Vec3::new(0.0, 0.5, 1.0));
        assert_eq!(bilinear(&image, Vec2::ZERO), Vec3::new(1.5, 0.5, 1.0));
        // Repeating: whole tiles away (negative ones too) the same colours, exactly here since
        // the shifts and reductions are exact for these dyadic values.
        for (i, j) in [(0, 0), (3, 1), (2, 0)] {
            let uv = centre(i, j);
            assert_eq!(bilinear(&image, uv + Vec2::new(3.0, -2.0)), image.get(i, j));
            assert_eq!(bilinear(&image, uv - Vec2::new(1.0, 5.0)), image.get(i, j));
        }
    }

    #[test]
    fn odd_sizes_hit_the_centres_within_rounding() {
        // 3 × 3: (i + ½)/3 is rounded, so x = u·3 − ½ is i within 2 roundings of values ≤ 3:
        // fx ≤ 8ε, and the blend of values ≤ 8 is off by at most 8·8ε = 64ε.
        let pixels = (0..9).map(|k| Vec3::splat(k as Float)).collect();
        let image = Image::from_pixels(3, 3, pixels);
        for j in 0..3 {
            for i in 0..3 {
                let uv = Vec2::new((i as Float + 0.5) / 3.0, 1.0 - (j as Float + 0.5) / 3.0);
                assert_abs_diff_eq!(bilinear(&image, uv), image.get(i, j), epsilon = 64.0 * EPS);
            }
        }
    }

    #[test]
    fn an_empty_image_is_black() {
        assert_eq!(bilinear(&Image::new(0, 5), Vec2::new(0.3, 0.3)), BLACK);
    }
}
