//! Lecture 07: reflection and refraction.
//!
//! A mirror sends a ray on along 05's reflection vector ([`mirror_direction`]).
//! A transparent surface bends it by Snell's law ([`refract`]), on the side the
//! ray comes from ([`interface`]: entering or leaving, which index is which),
//! unless the angle is past critical and total internal reflection sends all
//! of it back (`None`). How much is reflected: the exact Fresnel equations
//! ([`fresnel_dielectric`]) and Schlick's cheap approximation of them
//! ([`schlick`]), compared angle by angle. Lecture 08 spawns these rays.
//! Book: chapter 7.

mod fresnel;
mod mirror;
mod refract;
#[cfg(test)]
mod scenes;

pub use fresnel::{fresnel_dielectric, schlick};
pub use mirror::mirror_direction;
pub use refract::{Interface, interface, refract};
