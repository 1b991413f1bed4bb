//! Either camera, built from a scene's camera description: what the
//! renderers of the later lectures hold.

use raylab::{Float, Interval, Ray, scene};

use crate::look_at::CameraError;
use crate::orthographic::OrthographicCamera;
use crate::perspective::PerspectiveCamera;
use crate::screen::screen_coords;

/// A camera of either kind.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Camera {
    Perspective(PerspectiveCamera),
    Orthographic(OrthographicCamera),
}

impl Camera {
    /// The camera a scene describes, for a `width × height` image (aspect =
    /// width / height; both at least 1). Angles in [`scene::Camera`] are
    /// already radians.
    pub fn from_scene(camera: &scene::Camera, width: u32, height: u32) -> Result<Camera, CameraError> {
        debug_assert!(width > 0 && height > 0, "empty image {width}×{height}");
        let aspect = width as Float / height as Float;
        Ok(match *camera {
            scene::Camera::Perspective { eye, at, up, fovy } => {
                Camera::Perspective(PerspectiveCamera::new(eye, at, up, fovy, aspect)?)
            }
            scene::Camera::Orthographic { eye, at, up, height } => {
                Camera::Orthographic(OrthographicCamera::new(eye, at, up, height, aspect)?)
            }
        })
    }

    /// The ray through screen point (sx, sy) ∈ [−1, 1]²; its direction is unit length.
    pub fn generate_ray(&self, sx: Float, sy: Float) -> Ray {
        match self {
            Camera::Perspective(c) => c.generate_ray(sx, sy),
            Camera::Orthographic(c) => c.generate_ray(sx, sy),
        }
    }

    /// The primary ray through the centre of pixel (x, y) of a `width × height`
    /// image, pixel (0, 0) at the top left.
    pub fn pixel_ray(&self, x: u32, y: u32, width: u32, height: u32) -> Ray {
        let (sx, sy) = screen_coords(x, y, width, height);
        self.generate_ray(sx, sy)
    }

    /// The ray parameters that count as seen.
    pub fn t_range(&self) -> Interval {
        match self {
            Camera::Perspective(c) => c.t_range(),
            Camera::Orthographic(c) => c.t_range(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_abs_diff_eq;
    use raylab::math::consts::FRAC_PI_2;
    use raylab::{Vec3, radians};

    #[test]
    fn scene_cameras_become_the_right_kind_with_the_image_aspect() {
        let (eye, at, up) = (Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y);
        let persp = scene::Camera::Perspective { eye, at, up, fovy: FRAC_PI_2 };
        let Camera::Perspective(p) = Camera::from_scene(&persp, 400, 200).unwrap() else {
            panic!("expected a perspective camera")
        };
        assert_eq!((p.fovy, p.aspect), (FRAC_PI_2, 2.0));
        let ortho = scene::Camera::Orthographic { eye, at, up, height: 3.0 };
        let Camera::Orthographic(o) = Camera::from_scene(&ortho, 150, 200).unwrap() else {
            panic!("expected an orthographic camera")
        };
        assert_eq!((o.height, o.aspect), (3.0, 0.75));
    }

    #[test]
    fn pixel_ray_goes_through_the_pixel_centre() {
        // fovy 90°, 4 × 2 image: pixel (0, 0) → (−1.5, 0.5, −1)/√3.5 from the eye
        // (see the perspective camera's tests), here with the eye at (0, 0, 5).
        let persp = scene::Camera::Perspective {
            eye: Vec3::new(0.0, 0.0, 5.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
            fovy: radians(90.0),
        };
        let cam = Camera::from_scene(&persp, 4, 2).unwrap();
        let ray = cam.pixel_ray(0, 0, 4, 2);
        assert_eq!(ray.origin, Vec3::new(0.0, 0.0, 5.0));
        let n = (3.5 as Float).sqrt();
        assert_abs_diff_eq!(ray.dir, Vec3::new(-1.5, 0.5, -1.0) / n, epsilon = 8.0 * Float::EPSILON);
        assert_eq!(cam.t_range(), Interval::POSITIVE);
    }

    #[test]
    fn invalid_scene_cameras_are_errors() {
        let p = Vec3::ONE;
        let same = scene::Camera::Perspective { eye: p, at: p, up: Vec3::Y, fovy: 1.0 };
        assert_eq!(Camera::from_scene(&same, 10, 10), Err(CameraError::EyeAtTarget));
        let parallel = scene::Camera::Orthographic { eye: p, at: Vec3::ZERO, up: p, height: 1.0 };
        assert_eq!(Camera::from_scene(&parallel, 10, 10), Err(CameraError::UpParallelToView));
    }
}
