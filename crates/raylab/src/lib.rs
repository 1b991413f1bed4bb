//! # raylab — the kit
//!
//! Everything the students use but do not write: the numeric aliases
//! ([`Float`], [`Vec3`], [`Mat4`], switched to `f64` by the `f64` feature),
//! [`Ray`], [`Interval`] and [`Hit`], linear colours and [`Image`]s (sRGB PNG
//! in and out, float OpenEXR out), the scene description and its loaders
//! ([`scene`]), the pixel loop ([`render`]), ray statistics ([`stats`]), a
//! deterministic random generator ([`random::Rng`]) and the [`Intersector`]
//! trait through which later lectures plug into earlier ones. The kit knows
//! no lecture.

pub mod color;
pub mod compare;
pub mod data;
pub mod hit;
pub mod image;
pub mod math;
pub mod random;
pub mod ray;
pub mod render;
pub mod scene;
pub mod stats;

pub use color::{BLACK, Color, WHITE};
pub use hit::{Hit, Intersector};
pub use image::{Image, ImageError};
pub use math::{Float, Mat3, Mat4, Vec2, Vec3, Vec4, degrees, radians};
pub use ray::{Interval, Ray};
pub use scene::{Scene, SceneError};
