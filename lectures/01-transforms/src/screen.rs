//! From pixel indices to screen coordinates.

use raylab::Float;

/// The screen coordinates (sx, sy) of the centre of pixel (x, y) in a
/// `width × height` image:
///
/// ```text
/// sx = 2(x + ½)/w − 1        sy = 1 − 2(y + ½)/h
/// ```
///
/// Both run over (−1, 1): sx from left to right, sy from bottom to top, while
/// pixel (0, 0) is the top-left one (rows go down, sy goes up). The pixel
/// centre sits at x + ½, so no ray passes through the image's edge.
/// Written as sx = (2x + 1 − w)/w the numerator is an exact integer and sx
/// is correctly rounded, so the coordinates are exactly symmetric about the
/// image centre.
///
/// Requires x < width and y < height (so both are at least 1). Book: §1.7
/// Screen coordinates.
pub fn screen_coords(x: u32, y: u32, width: u32, height: u32) -> (Float, Float) {
    debug_assert!(x < width && y < height, "pixel ({x}, {y}) outside a {width}×{height} image");
    // SOLUTION BEGIN
    let (w, h) = (width as Float, height as Float);
    // The pixel centre's offset from the image centre, in half-widths and half-heights.
    let sx = (2.0 * x as Float + 1.0 - w) / w;
    let sy = (h - 2.0 * y as Float - 1.0) / h;
    (sx, sy)
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab_testing::wide;

    #[test]
    fn corner_pixels_by_hand() {
        // 200 × 100: pixel (0, 0) is at sx = 1/200 − 1 = −0.995, sy = 1 − 1/100 = 0.99.
        assert_eq!(screen_coords(0, 0, 200, 100), (-0.995, 0.99));
        // The bottom-right pixel (199, 99) mirrors it.
        assert_eq!(screen_coords(199, 99, 200, 100), (0.995, -0.99));
        // The other two corners.
        assert_eq!(screen_coords(199, 0, 200, 100), (0.995, 0.99));
        assert_eq!(screen_coords(0, 99, 200, 100), (-0.995, -0.99));
    }

    #[test]
    fn centre_pixel_of_an_odd_image_is_the_origin() {
        // 3 × 5: pixel (1, 2) has centre (1.5, 2.5) = (w/2, h/2).
        assert_eq!(screen_coords(1, 2, 3, 5), (0.0, 0.0));
        // One pixel: the whole screen, centre (0, 0).
        assert_eq!(screen_coords(0, 0, 1, 1), (0.0, 0.0));
        // Even widths have no centre pixel: the two middle ones sit at ±1/w.
        assert_eq!(screen_coords(99, 49, 200, 100), (-0.005, 0.01));
        assert_eq!(screen_coords(100, 50, 200, 100), (0.005, -0.01));
    }

    #[test]
    fn coordinates_are_symmetric_and_inside_the_screen() {
        for (w, h) in [(7u32, 3u32), (640, 480), (1, 9), (16384, 3)] {
            for x in [0, w / 3, w / 2, w - 1] {
                let (sx, _) = screen_coords(x, 0, w, h);
                let (mirror, _) = screen_coords(w - 1 - x, 0, w, h);
                assert_eq!(sx, -mirror, "x = {x} of {w}");
                assert!(-1.0 < sx && sx < 1.0);
            }
            for y in [0, h / 2, h - 1] {
                let (_, sy) = screen_coords(0, y, w, h);
                let (_, mirror) = screen_coords(0, h - 1 - y, w, h);
                assert_eq!(sy, -mirror, "y = {y} of {h}");
                assert!(-1.0 < sy && sy < 1.0);
            }
        }
    }

    #[test]
    fn agrees_with_the_formula_in_f64() {
        // The book's formula evaluated in f64 rounds twice (the quotient at
        // size ≤ 2, then the subtraction of 1), at most ¾ ε_f64 together; ours
        // rounds the exact value once to Float, at most ½ ε. So in either
        // precision they differ by less than 2ε of Float.
        for (w, h) in [(200u32, 150u32), (33, 17), (16384, 16384)] {
            for (x, y) in [(0, 0), (w / 2, h / 3), (w - 1, h - 1), (w / 7, h / 5)] {
                let sx = 2.0 * (x as f64 + 0.5) / w as f64 - 1.0;
                let sy = 1.0 - 2.0 * (y as f64 + 0.5) / h as f64;
                let (ours_x, ours_y) = screen_coords(x, y, w, h);
                let err = (wide(ours_x) - sx).abs().max((wide(ours_y) - sy).abs());
                assert!(err <= 2.0 * wide(Float::EPSILON), "({x}, {y}) of {w}×{h}: off by {err:e}");
            }
        }
    }
}
