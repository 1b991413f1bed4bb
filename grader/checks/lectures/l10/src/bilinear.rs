//! The checks of `bilinear.rs`: bilinear.

use super::common::*;

/// A 4 × 2 image whose pixel (i, j) is (i, j, 1): every value, every mean of two or four of
/// them (multiples of ¼), and the centres u = (i + ½)/4, v = 1 − (j + ½)/2 are exact.
pub(super) fn ramp() -> Image {
    let pixels = (0..2).flat_map(|j| (0..4).map(move |i| v3(i as Float, j as Float, 1.0))).collect();
    Image::from_pixels(4, 2, pixels)
}

pub(super) fn bilinear_cases(bilinear: BilinearFn) -> CheckResult {
    let image = ramp();
    let centre = |i: u32, j: u32| uv((i as Float + 0.5) / 4.0, 1.0 - (j as Float + 0.5) / 2.0);
    // Pixel centres: fx = fy = 0 exactly, the pixel itself.
    for j in 0..2 {
        for i in 0..4 {
            let got = bilinear(&image, centre(i, j));
            let expected = image.get(i, j);
            if got == expected {
                continue;
            }
            let case = format!(
                "4 × 2 image, pixel (i, j) = (i, j, 1): the centre of pixel ({i}, {j}), uv {}",
                show2(centre(i, j))
            );
            let cause = if got.y == 1.0 - expected.y && got.x == expected.x {
                "v grows upward: row 0 (the top) is at v = 1 − ½/h, so y = (1 − v)·h − ½"
            } else if (got.x - expected.x).abs() == 0.5 {
                "pixel centres are at (i + ½)/w: x = u·w − ½ (and y = (1 − v)·h − ½)"
            } else {
                "x = u·w − ½, y = (1 − v)·h − ½; blend the four pixels around (x, y) by their fractions"
            };
            return Err(fail(case, vec3(expected), vec3(got), cause));
        }
    }
    // Halfway between centres: the means, exact. Between (1, 0) and (2, 0): u = ½, v = ¾;
    // rows 0 and 1 of column 3: u = ⅞, v = ½; among four: (½, ½); a quarter of the way from
    // (0, 0) to (1, 0): x = 0.25.
    let blend = "blend along x by fx = x − ⌊x⌋, then along y by fy: (1 − f)·left + f·right";
    for (p, expected, what) in [
        (uv(0.5, 0.75), v3(1.5, 0.0, 1.0), "halfway between pixels (1, 0) and (2, 0)"),
        (uv(0.875, 0.5), v3(3.0, 0.5, 1.0), "halfway between pixels (3, 0) and (3, 1)"),
        (uv(0.5, 0.5), v3(1.5, 0.5, 1.0), "amid pixels (1, 0), (2, 0), (1, 1), (2, 1)"),
        (uv(0.1875, 0.75), v3(0.25, 0.0, 1.0), "a quarter of the way from pixel (0, 0) to (1, 0)"),
    ] {
        let got = bilinear(&image, p);
        let case = format!("4 × 2 image, pixel (i, j) = (i, j, 1): uv {}, {what}", show2(p));
        ensure(got == expected, case, vec3(expected), vec3(got), blend)?;
    }
    // Wrapping: u = 0 is x = −½, between the last column (3) and the first: red 1.5; v = 0 and
    // v = 1 lie between the last row and the first: green ½; whole tiles away (negative ones
    // too) the same colours, exact for these dyadic values.
    let wrap = "the image repeats: take columns mod w and rows mod h with rem_euclid (−1 is the last), \
                after reducing u and v mod 1";
    for (p, expected, what) in [
        (uv(0.0, 0.75), v3(1.5, 0.0, 1.0), "u = 0: between the last column and the first"),
        (uv(1.0, 0.75), v3(1.5, 0.0, 1.0), "u = 1: between the last column and the first"),
        (uv(0.125, 1.0), v3(0.0, 0.5, 1.0), "v = 1: between the last row and the first"),
        (uv(0.125, 0.0), v3(0.0, 0.5, 1.0), "v = 0: between the last row and the first"),
        (uv(0.0, 0.0), v3(1.5, 0.5, 1.0), "the corner (0, 0): all four corner pixels"),
        (
            centre(3, 1) + uv(3.0, -2.0),
            v3(3.0, 1.0, 1.0),
            "the centre of pixel (3, 1) three tiles right, two down",
        ),
        (centre(2, 0) - uv(1.0, 5.0), v3(2.0, 0.0, 1.0), "the centre of pixel (2, 0) one tile left, five up"),
    ] {
        let got = bilinear(&image, p);
        let case = format!("4 × 2 image, pixel (i, j) = (i, j, 1): uv {}, {what}", show2(p));
        ensure(got == expected, case, vec3(expected), vec3(got), wrap)?;
    }
    // An empty image: black, no panic.
    let got = bilinear(&Image::new(0, 5), uv(0.3, 0.3));
    ensure(
        got == Color::ZERO,
        "an empty 0 × 5 image at (0.3, 0.3)",
        vec3(Color::ZERO),
        vec3(got),
        "an empty image gives black",
    )?;
    // A taller image, 2 × 4, pixel (i, j) = (i, j, 1): between rows 1 and 2 the next row down is
    // j + 1, which a 2-row image cannot tell from j − 1 (both wrap to the other row). At u = ¼
    // (column 0's centre), v = ½ is y = 1.5 and v = 0.5625 is y = 1.25: green 1.5 and 1.25, exact.
    let tall = Image::from_pixels(
        2,
        4,
        (0..4).flat_map(|j| (0..2).map(move |i| v3(i as Float, j as Float, 1.0))).collect(),
    );
    for (p, expected, what) in [
        (uv(0.25, 0.5), v3(0.0, 1.5, 1.0), "halfway between pixels (0, 1) and (0, 2)"),
        (uv(0.25, 0.5625), v3(0.0, 1.25, 1.0), "a quarter of the way from pixel (0, 1) to (0, 2)"),
    ] {
        let got = bilinear(&tall, p);
        let case = format!("2 × 4 image, pixel (i, j) = (i, j, 1): uv {}, {what}", show2(p));
        ensure(
            got == expected,
            case,
            vec3(expected),
            vec3(got),
            "the row below row j is j + 1 (y grows downward)",
        )?;
    }
    Ok("8 centres, 6 blends, 7 wrapped points, an empty image".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    use raylab::{BLACK, Color, Float, Image, Vec2};

    /// The slips planted in the copy of the reference lookup.
    #[derive(Clone, Copy, PartialEq, Eq)]
    enum LookupSlip {
        Faithful,
        /// v not flipped: row 0 at the bottom.
        VNotFlipped,
        /// No half-pixel shift in x.
        NoHalfPixel,
        /// Clamped at the edges instead of wrapped.
        Clamped,
    }

    /// The reference lookup with a slip.
    fn lookup(slip: LookupSlip, image: &Image, uv: Vec2) -> Color {
        let (w, h) = (image.width, image.height);
        if w == 0 || h == 0 {
            return BLACK;
        }
        let shift = if slip == LookupSlip::NoHalfPixel { 0.0 } else { 0.5 };
        let x = uv.x.rem_euclid(1.0) * w as Float - shift;
        let v = uv.y.rem_euclid(1.0);
        let y = if slip == LookupSlip::VNotFlipped { v } else { 1.0 - v } * h as Float - 0.5;
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let column = |i: i64| {
            if slip == LookupSlip::Clamped {
                i.clamp(0, i64::from(w) - 1) as u32
            } else {
                i.rem_euclid(i64::from(w)) as u32
            }
        };
        let row = |j: i64| {
            if slip == LookupSlip::Clamped {
                j.clamp(0, i64::from(h) - 1) as u32
            } else {
                j.rem_euclid(i64::from(h)) as u32
            }
        };
        let (i, j) = (x0 as i64, y0 as i64);
        let top = (1.0 - fx) * image.get(column(i), row(j)) + fx * image.get(column(i + 1), row(j));
        let bottom =
            (1.0 - fx) * image.get(column(i), row(j + 1)) + fx * image.get(column(i + 1), row(j + 1));
        (1.0 - fy) * top + fy * bottom
    }

    #[test]
    fn planted_bilinear_mistakes_are_caught() {
        assert!(bilinear_cases(|i, uv| lookup(LookupSlip::Faithful, i, uv)).is_ok());
        caught(bilinear_cases(|i, uv| lookup(LookupSlip::VNotFlipped, i, uv)), "v grows upward");
        caught(bilinear_cases(|i, uv| lookup(LookupSlip::NoHalfPixel, i, uv)), "(i + ½)/w");
        caught(bilinear_cases(|i, uv| lookup(LookupSlip::Clamped, i, uv)), "the image repeats");
    }
}
