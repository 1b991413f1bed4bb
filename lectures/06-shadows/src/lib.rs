//! Lecture 06: shadows.
//!
//! A point is lit by a light only if nothing lies between them: a shadow ray
//! from the point toward the light answers it ([`occluded`], any hit, no
//! farther than the light). The ray must start just off the surface, or the
//! surface shadows itself in speckles (shadow acne): a fixed epsilon fails
//! far from the origin and for small objects, an offset scaled to the
//! rounding error of the point (from the point and the origin of the ray that
//! found it) does not ([`offset_origin`]). Transparent
//! blockers either block or filter the light by their transparent colour
//! ([`ShadowMode`], [`transmittance`]), and [`shade_with_shadows`] traces
//! only the shadow rays the scene requires. An area light is seen through n
//! shadow rays to [`stratified`] points of it ([`shade_area_light`]): soft
//! shadows, the same on every run ([`point_seed`]). Book: chapter 6.

mod occlusion;
mod offset;
#[cfg(test)]
mod scenes;
mod shade;
mod soft;
#[cfg(test)]
mod soft_scenes;
#[cfg(test)]
mod testing;

pub use occlusion::{LIGHT_MARGIN, MAX_BLOCKERS, ShadowMode, occluded, transmittance};
pub use offset::{
    NAIVE_EPSILON, OFFSET_FLOOR, OFFSET_SCALE, offset_origin, offset_origin_fixed_normal,
    offset_origin_fixed_t,
};
pub use shade::{ShadowSettings, Surface, shade_with_shadows, visibility};
pub use soft::{ONE_MINUS_EPSILON, SEED_CELL, point_seed, shade_area_light, stratified};
