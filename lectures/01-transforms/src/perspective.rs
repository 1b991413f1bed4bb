//! The pinhole (perspective) camera.

use raylab::{Float, Interval, Mat4, Ray, Vec3};

use crate::look_at::{CameraError, look_at};
use crate::transforms::{transform_point, transform_vector};

/// A pinhole camera: every ray starts at the eye and passes through a point
/// of the image plane z = −1 in camera space.
///
/// `fovy` is the full vertical field of view in radians, in (0, π);
/// `aspect` = width / height of the image, > 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PerspectiveCamera {
    pub world_from_camera: Mat4,
    pub fovy: Float,
    pub aspect: Float,
}

impl PerspectiveCamera {
    /// The camera at `eye` looking at `at` with `up` roughly up (see
    /// [`look_at`] and its errors); [`CameraError::NotFinite`] when `fovy` or
    /// `aspect` is NaN or infinite. Requires 0 < fovy < π and aspect > 0.
    pub fn new(eye: Vec3, at: Vec3, up: Vec3, fovy: Float, aspect: Float) -> Result<Self, CameraError> {
        if !(fovy.is_finite() && aspect.is_finite()) {
            return Err(CameraError::NotFinite);
        }
        debug_assert!(fovy > 0.0 && fovy < raylab::math::consts::PI, "fovy {fovy} outside (0, π)");
        debug_assert!(aspect > 0.0, "aspect {aspect} must be positive");
        Ok(Self { world_from_camera: look_at(eye, at, up)?, fovy, aspect })
    }

    /// The ray through screen point (sx, sy) ∈ [−1, 1]² (see
    /// [`crate::screen_coords`]).
    ///
    /// In camera space the image plane z = −1 spans ±tan(fovy/2) vertically
    /// and ±aspect·tan(fovy/2) horizontally, so the direction is
    ///
    /// ```text
    /// d = (sx·aspect·tan(fovy/2), sy·tan(fovy/2), −1)
    /// ```
    ///
    /// taken to the world by `world_from_camera` (a vector: no translation)
    /// and normalised; the origin is the eye, `world_from_camera`·(0, 0, 0, 1).
    /// The direction is unit length. Book: §1.8 The pinhole camera.
    pub fn generate_ray(&self, sx: Float, sy: Float) -> Ray {
        // SOLUTION BEGIN
        // The half-height of the image plane at distance 1.
        let half_height = (0.5 * self.fovy).tan();
        let dir_camera = Vec3::new(sx * self.aspect * half_height, sy * half_height, -1.0);
        // From camera space to world space.
        let origin = transform_point(&self.world_from_camera, Vec3::ZERO);
        let dir = transform_vector(&self.world_from_camera, dir_camera).normalize();
        Ray::new(origin, dir)
        // SOLUTION END
    }

    /// The ray parameters that count as seen: everything in front of the eye,
    /// (0, ∞).
    pub fn t_range(&self) -> Interval {
        Interval::POSITIVE
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::screen::screen_coords;
    use approx::assert_abs_diff_eq;
    use raylab::math::consts::FRAC_PI_2;
    use raylab::radians;

    /// tan(π/4) of the rounded π/4 is 1 ± ε; a product, the matrix and the
    /// normalisation add a few ε: 8ε on unit-length directions.
    const TOL: Float = 8.0 * Float::EPSILON;

    /// fovy 90° (tan(fovy/2) = 1), aspect 2, at the origin looking down −z.
    fn wide() -> PerspectiveCamera {
        PerspectiveCamera::new(Vec3::ZERO, Vec3::NEG_Z, Vec3::Y, FRAC_PI_2, 2.0).unwrap()
    }

    #[test]
    fn screen_corners_of_a_90_degree_camera_by_hand() {
        // d = (±2·1, ±1, −1) with |d| = √6.
        let cam = wide();
        let s6 = (6.0 as Float).sqrt();
        for (sx, sy) in [(-1.0, 1.0), (1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)] {
            let ray = cam.generate_ray(sx, sy);
            assert_eq!(ray.origin, Vec3::ZERO);
            assert_abs_diff_eq!(ray.dir, Vec3::new(2.0 * sx, sy, -1.0) / s6, epsilon = TOL);
        }
        // The centre looks straight down −z.
        assert_abs_diff_eq!(cam.generate_ray(0.0, 0.0).dir, Vec3::NEG_Z, epsilon = TOL);
    }

    #[test]
    fn corner_pixel_rays_by_hand() {
        // A 4 × 2 image: pixel (0, 0) has (sx, sy) = (−0.75, 0.5), so
        // d = (−0.75·2, 0.5, −1) = (−1.5, 0.5, −1), |d| = √3.5.
        let cam = wide();
        let n = (3.5 as Float).sqrt();
        let (sx, sy) = screen_coords(0, 0, 4, 2);
        assert_abs_diff_eq!(cam.generate_ray(sx, sy).dir, Vec3::new(-1.5, 0.5, -1.0) / n, epsilon = TOL);
        // Pixel (3, 1), the bottom-right: (0.75, −0.5) → (1.5, −0.5, −1)/√3.5.
        let (sx, sy) = screen_coords(3, 1, 4, 2);
        assert_abs_diff_eq!(cam.generate_ray(sx, sy).dir, Vec3::new(1.5, -0.5, -1.0) / n, epsilon = TOL);
    }

    #[test]
    fn rays_turn_with_the_camera() {
        // Looking along +x from (1, 2, 3) with up y: u = z, v = y, w = −x (see
        // look_at's tests), so camera (a, b, −1) is world (1, b, a).
        let eye = Vec3::new(1.0, 2.0, 3.0);
        let cam = PerspectiveCamera::new(eye, eye + Vec3::X, Vec3::Y, FRAC_PI_2, 2.0).unwrap();
        let n = (3.5 as Float).sqrt();
        let ray = cam.generate_ray(-0.75, 0.5);
        assert_abs_diff_eq!(ray.origin, eye, epsilon = TOL);
        assert_abs_diff_eq!(ray.dir, Vec3::new(1.0, 0.5, -1.5) / n, epsilon = TOL);
    }

    #[test]
    fn vertical_field_of_view_spans_fovy() {
        // The rays to the top and bottom edges (sy = ±1) meet at angle fovy,
        // and the left and right edges at 2·atan(aspect·tan(fovy/2)).
        for (fovy_deg, aspect) in [(30.0, 1.0), (60.0, 1.5), (120.0, 0.5)] {
            let fovy = radians(fovy_deg);
            let cam =
                PerspectiveCamera::new(Vec3::ONE, Vec3::new(4.0, -2.0, 0.0), Vec3::Y, fovy, aspect).unwrap();
            let top = cam.generate_ray(0.0, 1.0).dir;
            let bottom = cam.generate_ray(0.0, -1.0).dir;
            // acos near 1 loses half the digits: √ε-sized errors, so 1e-3 rad.
            assert_abs_diff_eq!(top.dot(bottom).acos(), fovy, epsilon = 1e-3);
            let left = cam.generate_ray(-1.0, 0.0).dir;
            let right = cam.generate_ray(1.0, 0.0).dir;
            let fovx = 2.0 * (aspect * (0.5 * fovy).tan()).atan();
            assert_abs_diff_eq!(left.dot(right).acos(), fovx, epsilon = 1e-3);
        }
    }

    #[test]
    fn centre_ray_goes_through_at_and_directions_are_unit() {
        let (eye, at) = (Vec3::new(-3.0, 1.0, 7.0), Vec3::new(2.0, 0.5, -1.0));
        let cam = PerspectiveCamera::new(eye, at, Vec3::Y, radians(40.0), 4.0 / 3.0).unwrap();
        let centre = cam.generate_ray(0.0, 0.0);
        // The centre ray's direction is (at − eye)/|at − eye|.
        assert_abs_diff_eq!(centre.dir, (at - eye).normalize(), epsilon = TOL);
        for (sx, sy) in [(-1.0, -1.0), (0.3, -0.7), (1.0, 1.0)] {
            let d = cam.generate_ray(sx, sy).dir;
            assert!((d.length() - 1.0).abs() <= 2.0 * Float::EPSILON, "|d| = {}", d.length());
        }
        assert_eq!(cam.t_range(), Interval::new(0.0, Float::INFINITY));
    }

    #[test]
    fn bad_inputs_are_errors_not_nan() {
        let nan = Float::NAN;
        assert_eq!(
            PerspectiveCamera::new(Vec3::Z, Vec3::ZERO, Vec3::Y, nan, 1.0),
            Err(CameraError::NotFinite)
        );
        assert_eq!(
            PerspectiveCamera::new(Vec3::Z, Vec3::ZERO, Vec3::Y, 1.0, Float::INFINITY),
            Err(CameraError::NotFinite)
        );
        assert_eq!(
            PerspectiveCamera::new(Vec3::Z, Vec3::Z, Vec3::Y, 1.0, 1.0),
            Err(CameraError::EyeAtTarget)
        );
        assert_eq!(
            PerspectiveCamera::new(Vec3::Z, Vec3::ZERO, Vec3::Z, 1.0, 1.0),
            Err(CameraError::UpParallelToView)
        );
    }
}
