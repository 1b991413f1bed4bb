//! Lecture 02: ray casting.
//!
//! Cast one ray per pixel and ask what it hits first. The sphere three ways:
//! the textbook quadratic, the slides' geometric construction, and the robust
//! form (no cancellation) that the tracer uses — and measured side by side on
//! far, small, grazing and tangent cases. The plane n·p = offset. The closest
//! hit of a group, shrinking the ray's interval as hits are found. Finally the
//! "scene signature": object-id, depth and normal images of a whole scene.
//! Book: chapter 2.

mod group;
mod images;
mod plane;
#[cfg(test)]
mod scenes;
mod sphere;

pub use group::{Group, closest_hit, hit_shape, hit_sphere_or_plane};
pub use images::{depth_image, id_color, normal_image, object_id_image};
pub use plane::hit_plane;
pub use sphere::{hit_sphere_algebraic, hit_sphere_geometric, hit_sphere_stable};
