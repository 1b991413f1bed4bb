//! Image comparison by pixels (never by bytes: the same pixels can encode to
//! different PNG bytes).

use crate::image::{Image, Srgb8};

/// How two images of the same size differ, judged on 8-bit sRGB values (what
/// a viewer sees, and what a PNG snapshot stores).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    /// Pixels whose largest channel difference exceeds the threshold.
    pub pixels_over: usize,
    pub pixels: usize,
    /// The largest channel difference anywhere, in 8-bit steps.
    pub max_difference: u8,
    /// The first pixel over the threshold, row-major.
    pub first_over: Option<(u32, u32)>,
}

impl Comparison {
    /// The fraction of pixels over the threshold.
    pub fn fraction_over(&self) -> f64 {
        self.pixels_over as f64 / self.pixels.max(1) as f64
    }
}

/// Compares `actual` with `expected` pixel by pixel: a pixel differs when any
/// of its 8-bit sRGB channels differs by more than `threshold` steps.
/// Errors when the sizes differ.
pub fn compare(expected: &Image, actual: &Image, threshold: u8) -> Result<Comparison, String> {
    compare_srgb8(&expected.to_srgb8(), &actual.to_srgb8(), threshold, &actual.non_finite_pixels())
}

/// [`compare`] on pictures already turned into 8-bit values (each pixel encoded once, where a
/// caller needs the values again: to show them, to write them). `wrong` lists, in order, the
/// pixels of `actual` that differ whatever their values say: the NaN or infinite ones
/// ([`Image::non_finite_pixels`]), which encode to 0 (or to a colour that shows them) and count
/// as maximally wrong instead.
pub fn compare_srgb8(
    expected: &Srgb8,
    actual: &Srgb8,
    threshold: u8,
    mut wrong: &[usize],
) -> Result<Comparison, String> {
    if (expected.width, expected.height) != (actual.width, actual.height)
        || expected.bytes.len() != actual.bytes.len()
    {
        return Err(format!(
            "image size differs: expected {}×{}, found {}×{}",
            expected.width, expected.height, actual.width, actual.height
        ));
    }
    let pixels = expected.bytes.len() / 3;
    let mut result = Comparison { pixels_over: 0, pixels, max_difference: 0, first_over: None };
    for (i, (e, a)) in expected.bytes.chunks_exact(3).zip(actual.bytes.chunks_exact(3)).enumerate() {
        let d = (0..3).map(|c| e[c].abs_diff(a[c])).max().unwrap_or(0);
        let d = match wrong.split_first() {
            Some((&w, rest)) if w == i => {
                wrong = rest;
                u8::MAX
            }
            _ => d,
        };
        result.max_difference = result.max_difference.max(d);
        if d > threshold {
            result.pixels_over += 1;
            if result.first_over.is_none() {
                let w = expected.width as usize;
                result.first_over = Some(((i % w) as u32, (i / w) as u32));
            }
        }
    }
    Ok(result)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Color, Float};

    #[test]
    fn counts_pixels_over_the_threshold_only() {
        let a = Image::filled(4, 2, Color::splat(0.5));
        let mut b = a.clone();
        // Linear 0.5 encodes to 188 (255·0.7354 + 0.5); 0.51 to 189
        // (1.055·0.51^(1/2.4) − 0.055 = 0.7419): a 1-step difference.
        b.set(1, 0, Color::new(0.51, 0.5, 0.5));
        b.set(3, 1, Color::new(0.5, 0.0, 0.5));
        let c = compare(&a, &b, 1).unwrap();
        assert_eq!((c.pixels_over, c.first_over), (1, Some((3, 1))));
        assert_eq!(c.max_difference, 188);
        assert_eq!(compare(&a, &b, 0).unwrap().pixels_over, 2);
    }

    #[test]
    fn nan_pixels_always_differ_and_sizes_must_match() {
        let a = Image::new(2, 2);
        let mut b = a.clone();
        b.set(0, 1, Color::new(Float::NAN, 0.0, 0.0));
        assert_eq!(compare(&a, &b, 254).unwrap().pixels_over, 1);
        assert!(compare(&a, &Image::new(2, 3), 0).unwrap_err().contains("expected 2×2, found 2×3"));
    }

    #[test]
    fn eight_bit_values_compare_as_their_images_do_and_a_wrong_pixel_always_differs() {
        let a = Image::filled(4, 2, Color::splat(0.5));
        let mut b = a.clone();
        b.set(1, 0, Color::new(0.51, 0.5, 0.5));
        b.set(3, 1, Color::new(0.5, 0.0, 0.5));
        let (a8, b8) = (a.to_srgb8(), b.to_srgb8());
        assert_eq!(compare_srgb8(&a8, &b8, 1, &[]), compare(&a, &b, 1));
        // Pixel 2 has a's values but is wrong (a NaN shown in a colour): it differs at any threshold.
        let c = compare_srgb8(&a8, &b8, 254, &[2]).unwrap();
        assert_eq!((c.pixels_over, c.first_over, c.max_difference), (1, Some((2, 0)), u8::MAX));
        // Values that do not fill the picture they claim are an error, not a panic.
        let short = Srgb8 { bytes: vec![0; 5], ..a8.clone() };
        assert!(compare_srgb8(&a8, &short, 0, &[]).is_err());
    }
}
