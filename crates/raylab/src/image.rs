//! Images of linear colours: PNG out (8-bit sRGB) and in, float OpenEXR out.

use std::fmt;
use std::path::{Path, PathBuf};

use crate::color::{Color, from_srgb8, to_srgb8};
use crate::math::{Float, Vec3};

/// A `width × height` image of linear colours, row-major, pixel (0, 0) at the
/// top left.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<Color>,
}

/// What went wrong reading or writing an image, with the file it concerns.
#[derive(Debug)]
pub enum ImageError {
    /// The image holds NaN or infinite values; nothing was written.
    NotFinite { path: PathBuf, count: usize, first: (u32, u32) },
    /// The image could not be read, decoded, encoded or written.
    Io { path: PathBuf, message: String },
}

impl fmt::Display for ImageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ImageError::NotFinite { path, count, first } => write!(
                f,
                "{}: not written: {count} pixel(s) are NaN or infinite, the first at ({}, {})",
                path.display(),
                first.0,
                first.1
            ),
            ImageError::Io { path, message } => write!(f, "{}: {message}", path.display()),
        }
    }
}

impl std::error::Error for ImageError {}

impl Image {
    /// A black image.
    pub fn new(width: u32, height: u32) -> Self {
        Self::filled(width, height, Color::ZERO)
    }

    /// An image of one colour.
    pub fn filled(width: u32, height: u32, color: Color) -> Self {
        Self { width, height, pixels: vec![color; width as usize * height as usize] }
    }

    /// An image from row-major pixels; `pixels.len()` must be `width·height`.
    pub fn from_pixels(width: u32, height: u32, pixels: Vec<Color>) -> Self {
        assert_eq!(pixels.len(), width as usize * height as usize, "pixel count");
        Self { width, height, pixels }
    }

    /// The colour at pixel (x, y).
    pub fn get(&self, x: u32, y: u32) -> Color {
        self.pixels[self.index(x, y)]
    }

    /// Sets the colour at pixel (x, y).
    pub fn set(&mut self, x: u32, y: u32, c: Color) {
        let i = self.index(x, y);
        self.pixels[i] = c;
    }

    fn index(&self, x: u32, y: u32) -> usize {
        assert!(x < self.width && y < self.height, "pixel ({x}, {y}) outside {}×{}", self.width, self.height);
        y as usize * self.width as usize + x as usize
    }

    /// The indices (row-major) of the NaN or infinite pixels, in order.
    pub fn non_finite_pixels(&self) -> Vec<usize> {
        self.pixels.iter().enumerate().filter(|(_, c)| !c.is_finite()).map(|(i, _)| i).collect()
    }

    /// The number of NaN or infinite pixels, and the first one.
    pub fn non_finite(&self) -> Option<(usize, (u32, u32))> {
        let mut bad = self.pixels.iter().enumerate().filter(|(_, c)| !c.is_finite());
        let (first, _) = bad.next()?;
        let w = self.width as usize;
        Some((1 + bad.count(), ((first % w) as u32, (first / w) as u32)))
    }

    fn check_finite(&self, path: &Path) -> Result<(), ImageError> {
        match self.non_finite() {
            None => Ok(()),
            Some((count, first)) => Err(ImageError::NotFinite { path: path.to_owned(), count, first }),
        }
    }

    /// Writes an 8-bit sRGB PNG. Refuses (and writes nothing) if any pixel is
    /// NaN or infinite: a NaN image hides a bug.
    pub fn save_png(&self, path: impl AsRef<Path>) -> Result<(), ImageError> {
        let path = path.as_ref();
        self.check_finite(path)?;
        self.to_srgb8().save_png(path)
    }

    /// Reads a PNG (or any 8-bit RGB image the `image` crate reads) as linear colours.
    pub fn load_png(path: impl AsRef<Path>) -> Result<Self, ImageError> {
        Ok(Srgb8::load_png(path)?.to_linear())
    }

    /// The image as 8-bit sRGB values, rounded to nearest (a NaN channel is 0).
    pub fn to_srgb8(&self) -> Srgb8 {
        let bytes = self.pixels.iter().flat_map(|&c| to_srgb8(c)).collect();
        Srgb8 { width: self.width, height: self.height, bytes }
    }

    /// Decodes a PNG (or any 8-bit RGB image the `image` crate reads) held in
    /// `bytes`, read from `path` (named in errors), as linear colours. The
    /// decoder's default limits bound what a small file may decode to (512 MiB).
    pub fn decode_png(bytes: &[u8], path: impl AsRef<Path>) -> Result<Self, ImageError> {
        let path = path.as_ref();
        Ok(Srgb8::decode_png(bytes, path)?.to_linear())
    }

    /// Writes a 32-bit float RGB OpenEXR with the linear values unchanged
    /// (for depth and normal images). Refuses NaN and infinite values.
    pub fn save_exr(&self, path: impl AsRef<Path>) -> Result<(), ImageError> {
        let path = path.as_ref();
        self.check_finite(path)?;
        let data: Vec<f32> = self.pixels.iter().flat_map(|c| [c.x as f32, c.y as f32, c.z as f32]).collect();
        let buffer = image::Rgb32FImage::from_raw(self.width, self.height, data).expect("buffer size");
        image::DynamicImage::ImageRgb32F(buffer)
            .save_with_format(path, image::ImageFormat::OpenExr)
            .map_err(|e| io_error(path, e))
    }

    /// Reads a float OpenEXR written by [`Image::save_exr`].
    pub fn load_exr(path: impl AsRef<Path>) -> Result<Self, ImageError> {
        let path = path.as_ref();
        let decoded = image::open(path).map_err(|e| io_error(path, e))?.to_rgb32f();
        let (width, height) = decoded.dimensions();
        let pixels =
            decoded.pixels().map(|p| Vec3::new(p.0[0] as Float, p.0[1] as Float, p.0[2] as Float)).collect();
        Ok(Self { width, height, pixels })
    }
}

/// A picture as a PNG holds it: 8-bit sRGB values r, g, b per pixel, row-major from the top left.
/// What the grader compares and writes without going through linear colours and back.
#[derive(Clone, Debug, PartialEq)]
pub struct Srgb8 {
    pub width: u32,
    pub height: u32,
    /// `3 · width · height` values.
    pub bytes: Vec<u8>,
}

impl Srgb8 {
    /// Reads a PNG (or any 8-bit RGB image the `image` crate reads).
    pub fn load_png(path: impl AsRef<Path>) -> Result<Self, ImageError> {
        let path = path.as_ref();
        let decoded = image::open(path).map_err(|e| io_error(path, e))?.to_rgb8();
        let (width, height) = decoded.dimensions();
        Ok(Self { width, height, bytes: decoded.into_raw() })
    }

    /// Decodes a PNG (or any 8-bit RGB image the `image` crate reads) held in `bytes`, read from
    /// `path` (named in errors), within the decoder's default limits (512 MiB).
    pub fn decode_png(bytes: &[u8], path: impl AsRef<Path>) -> Result<Self, ImageError> {
        let path = path.as_ref();
        let decoded = image::load_from_memory(bytes).map_err(|e| io_error(path, e))?.to_rgb8();
        let (width, height) = decoded.dimensions();
        Ok(Self { width, height, bytes: decoded.into_raw() })
    }

    /// Writes a PNG.
    pub fn save_png(&self, path: impl AsRef<Path>) -> Result<(), ImageError> {
        let path = path.as_ref();
        let size = 3 * self.width as usize * self.height as usize;
        if self.bytes.len() != size {
            let message = format!(
                "{} values for a {}×{} picture (3 per pixel)",
                self.bytes.len(),
                self.width,
                self.height
            );
            return Err(ImageError::Io { path: path.to_owned(), message });
        }
        image::save_buffer_with_format(
            path,
            &self.bytes,
            self.width,
            self.height,
            image::ExtendedColorType::Rgb8,
            image::ImageFormat::Png,
        )
        .map_err(|e| io_error(path, e))
    }

    /// The picture as linear colours.
    pub fn to_linear(&self) -> Image {
        let pixels = self.bytes.chunks_exact(3).map(|p| from_srgb8([p[0], p[1], p[2]])).collect();
        Image { width: self.width, height: self.height, pixels }
    }
}

fn io_error(path: &Path, e: impl fmt::Display) -> ImageError {
    ImageError::Io { path: path.to_owned(), message: e.to_string() }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("raylab-image-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir.join(name)
    }

    #[test]
    fn png_round_trip_keeps_8bit_pixels() {
        let mut img = Image::new(3, 2);
        img.set(0, 0, Color::new(1.0, 0.0, 0.0));
        img.set(2, 1, Color::new(0.5, 0.25, 0.125));
        let path = temp("round.png");
        img.save_png(&path).unwrap();
        let back = Image::load_png(&path).unwrap();
        assert_eq!((back.width, back.height), (3, 2));
        for (a, b) in img.pixels.iter().zip(&back.pixels) {
            assert_eq!(to_srgb8(*a), to_srgb8(*b));
        }
        // The file is a real PNG: the signature bytes.
        assert_eq!(&std::fs::read(&path).unwrap()[..8], b"\x89PNG\r\n\x1a\n");
    }

    #[test]
    fn srgb8_pictures_are_written_and_read_byte_for_byte() {
        let bytes: Vec<u8> = (0..18).map(|i| (i * 15) as u8).collect();
        let picture = Srgb8 { width: 3, height: 2, bytes };
        let path = temp("srgb8.png");
        picture.save_png(&path).unwrap();
        assert_eq!(Srgb8::load_png(&path).unwrap(), picture);
        // The linear image it reads as is the one `Image::load_png` reads, and back the same bytes.
        assert_eq!(Image::load_png(&path).unwrap(), picture.to_linear());
        assert_eq!(picture.to_linear().to_srgb8(), picture);
        // A size its values do not fill is refused, naming the file.
        let short = Srgb8 { width: 4, height: 2, ..picture };
        let err = short.save_png(temp("short.png")).unwrap_err().to_string();
        assert!(err.contains("short.png") && err.contains("18 values for a 4×2 picture"), "{err}");
    }

    #[test]
    fn exr_round_trip_keeps_floats_exactly() {
        let mut img = Image::new(2, 2);
        img.set(1, 0, Color::new(1234.5, -0.75, 1e-3));
        let path = temp("round.exr");
        img.save_exr(&path).unwrap();
        let back = Image::load_exr(&path).unwrap();
        assert_eq!(back.get(1, 0), Color::new(1234.5, -0.75, Float::from(1e-3_f32)));
    }

    #[test]
    fn nan_images_are_refused_with_the_first_pixel() {
        let mut img = Image::new(4, 3);
        img.set(2, 1, Color::new(Float::NAN, 0.0, 0.0));
        img.set(3, 2, Color::new(Float::INFINITY, 0.0, 0.0));
        let path = temp("nan.png");
        let err = img.save_png(&path).unwrap_err().to_string();
        assert!(err.ends_with("not written: 2 pixel(s) are NaN or infinite, the first at (2, 1)"), "{err}");
        assert!(!path.exists());
    }
}
