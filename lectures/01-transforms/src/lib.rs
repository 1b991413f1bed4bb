//! Lecture 01: vectors, transforms, look-at and the pinhole camera.
//!
//! Points and vectors in homogeneous coordinates (w = 1 and w = 0); the
//! affine transforms as 4×4 matrices built column by column (translation,
//! scaling, rotations about the axes and about any axis); coordinate frames
//! and the test for a basis; the look-at frame of a camera, which looks down
//! its −z axis; screen coordinates of pixel centres; and the rays of the
//! perspective and orthographic cameras. Book: chapter 1.

mod axis_angle;
mod camera;
mod frame;
mod look_at;
mod orthographic;
mod perspective;
#[cfg(test)]
mod scenes;
mod screen;
#[cfg(test)]
mod testing;
mod transforms;

pub use axis_angle::rotate_axis;
pub use camera::Camera;
pub use frame::{frame, is_basis};
pub use look_at::{CameraError, look_at};
pub use orthographic::OrthographicCamera;
pub use perspective::PerspectiveCamera;
pub use screen::screen_coords;
pub use transforms::{rotate_x, rotate_y, rotate_z, scale, transform_point, transform_vector, translate};
