//! The orthographic (parallel) camera.

use raylab::{Float, Interval, Mat4, Ray, Vec3};

use crate::look_at::{CameraError, look_at};
use crate::transforms::{transform_point, transform_vector};

/// A parallel projection: all rays share the view direction and start on
/// the plane through the eye, across a window `height` world units tall and
/// `aspect`·`height` wide. Objects keep their size at any distance.
///
/// `height` > 0 in world units; `aspect` = width / height of the image, > 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrthographicCamera {
    pub world_from_camera: Mat4,
    pub height: Float,
    pub aspect: Float,
}

impl OrthographicCamera {
    /// The camera at `eye` looking at `at` with `up` roughly up (see
    /// [`look_at`] and its errors); [`CameraError::NotFinite`] when `height`
    /// or `aspect` is NaN or infinite. Requires height > 0 and aspect > 0.
    pub fn new(eye: Vec3, at: Vec3, up: Vec3, height: Float, aspect: Float) -> Result<Self, CameraError> {
        if !(height.is_finite() && aspect.is_finite()) {
            return Err(CameraError::NotFinite);
        }
        debug_assert!(height > 0.0, "height {height} must be positive");
        debug_assert!(aspect > 0.0, "aspect {aspect} must be positive");
        Ok(Self { world_from_camera: look_at(eye, at, up)?, height, aspect })
    }

    /// The ray through screen point (sx, sy) ∈ [−1, 1]² (see
    /// [`crate::screen_coords`]).
    ///
    /// In camera space the ray starts on the plane z = 0 at
    ///
    /// ```text
    /// o = (sx·aspect·h/2, sy·h/2, 0)        d = (0, 0, −1)
    /// ```
    ///
    /// and both go to the world by `world_from_camera` (o as a point, d as a
    /// vector). The direction is unit length and the same for every ray.
    /// Book: §1.9 The orthographic camera.
    pub fn generate_ray(&self, sx: Float, sy: Float) -> Ray {
        // SOLUTION BEGIN
        let half_height = 0.5 * self.height;
        let origin_camera = Vec3::new(sx * self.aspect * half_height, sy * half_height, 0.0);
        // From camera space to world space.
        let origin = transform_point(&self.world_from_camera, origin_camera);
        let dir = transform_vector(&self.world_from_camera, Vec3::NEG_Z).normalize();
        Ray::new(origin, dir)
        // SOLUTION END
    }

    /// The ray parameters that count as seen: in front of the eye's plane,
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

    #[test]
    fn rays_are_parallel_and_spaced_a_pixel_apart() {
        // A 200 × 100 image of a window 4 units tall (aspect 2, so 8 wide):
        // one pixel is 4/100 = 0.04 units in both directions.
        let (eye, at) = (Vec3::new(1.0, 2.0, 3.0), Vec3::new(-2.0, 0.0, -1.0));
        let cam = OrthographicCamera::new(eye, at, Vec3::Y, 4.0, 2.0).unwrap();
        let (u, v) = (cam.world_from_camera.x_axis.truncate(), cam.world_from_camera.y_axis.truncate());
        let ray = |x, y| {
            let (sx, sy) = screen_coords(x, y, 200, 100);
            cam.generate_ray(sx, sy)
        };
        let first = ray(0, 0);
        // Positions of size ≤ 8 through a rigid map: a few ε·8; 16ε·8 (1.5e-5 in f32).
        let tol = 16.0 * Float::EPSILON * 8.0;
        for (x, y) in [(0, 0), (57, 13), (198, 98)] {
            let (r, right, below) = (ray(x, y), ray(x + 1, y), ray(x, y + 1));
            // The same direction for every ray, bit for bit (one computation).
            assert_eq!(r.dir, first.dir);
            // One pixel right is 0.04·u, one pixel down is −0.04·v.
            assert_abs_diff_eq!(right.origin - r.origin, 0.04 * u, epsilon = tol);
            assert_abs_diff_eq!(below.origin - r.origin, -0.04 * v, epsilon = tol);
        }
        // The direction is the view direction, unit length.
        assert_abs_diff_eq!(first.dir, (at - eye).normalize(), epsilon = 4.0 * Float::EPSILON);
    }

    #[test]
    fn window_corners_by_hand() {
        // At the origin looking down −z: the screen corner (1, 1) starts at
        // (aspect·h/2, h/2, 0) = (1.5·1, 1, 0) for h = 2, aspect 1.5.
        let cam = OrthographicCamera::new(Vec3::ZERO, Vec3::NEG_Z, Vec3::Y, 2.0, 1.5).unwrap();
        let r = cam.generate_ray(1.0, 1.0);
        assert_eq!(r.origin, Vec3::new(1.5, 1.0, 0.0));
        assert_eq!(r.dir, Vec3::NEG_Z);
        assert_eq!(cam.generate_ray(-1.0, -1.0).origin, Vec3::new(-1.5, -1.0, 0.0));
        // The centre ray starts at the eye.
        assert_eq!(cam.generate_ray(0.0, 0.0).origin, Vec3::ZERO);
        assert_eq!(cam.t_range(), Interval::POSITIVE);
    }

    #[test]
    fn bad_inputs_are_errors_not_nan() {
        let nan = Float::NAN;
        assert_eq!(
            OrthographicCamera::new(Vec3::Z, Vec3::ZERO, Vec3::Y, nan, 1.0),
            Err(CameraError::NotFinite)
        );
        assert_eq!(
            OrthographicCamera::new(Vec3::Z, Vec3::Z, Vec3::Y, 1.0, 1.0),
            Err(CameraError::EyeAtTarget)
        );
        assert_eq!(
            OrthographicCamera::new(Vec3::Z, Vec3::ZERO, -Vec3::Z, 1.0, 1.0),
            Err(CameraError::UpParallelToView)
        );
    }
}
