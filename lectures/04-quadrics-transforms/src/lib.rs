//! Lecture 04: cylinders and cones, transformed objects and their normals.
//!
//! Two more canonical quadrics, each with its caps: [`hit_cylinder`] and
//! [`hit_cone`] (axis along z, 0 ≤ z ≤ 1). Every other cylinder, cone,
//! ellipsoid or squashed box is a canonical shape placed by an affine map:
//! [`ray_to_object`] takes the ray into the object's space (keeping t),
//! [`normal_to_world`] brings the normal back with (A⁻¹)ᵀ, and
//! [`hit_transformed`] does both around any shape. [`parametric_normal`]
//! gives the normal of a surface written as s(α, β). [`hit_shape`],
//! [`hit_object`] and [`BruteForce`] put every shape of lectures 02–04 behind
//! one door for the rest of the course. Book: chapter 4.

mod capped;
mod cone;
mod cylinder;
mod parametric;
mod scene;
#[cfg(test)]
mod scenes;
mod transformed;

#[cfg(test)]
mod testing;

pub use capped::{first_crossing, slab_z_span};
pub use cone::hit_cone;
pub use cylinder::hit_cylinder;
pub use parametric::parametric_normal;
pub use scene::{BruteForce, hit_object, hit_shape};
pub use transformed::{hit_transformed, normal_to_world, ray_to_object};
