//! Lecture 05: shading — Lambert, Phong and Blinn–Phong under ambient,
//! directional, point and spot lights.
//!
//! A hit becomes a colour by the local illumination model: the ambient term
//! kₐ·Iₐ plus, for every light, the diffuse term k_d·(N·L)⁺ ([`lambert`]) and
//! a specular highlight, Phong's (V·R)ⁿ ([`phong_specular`], with R from
//! [`reflect`]) or Blinn's (N·H)ⁿ ([`blinn_specular`]). [`illuminate`] says
//! how each light reaches a point (direction, distance, intensity after
//! [`distance_falloff`] and [`spot_falloff`]); [`shade_light`] and
//! [`shade_local`] put it together. An area light (a rect or a sphere) is
//! many point lights: [`sample_light`] picks one of its points from a
//! uniform sample, through [`concentric_disk`] for a sphere's silhouette.
//! Every vector is unit: N faces the eye, L points to the light, V to the
//! eye. Book: chapter 5.

mod area_lights;
mod lambert;
mod lights;
mod phong;
mod reflect;
#[cfg(test)]
mod scenes;
mod shade;

pub use area_lights::{concentric_disk, sample_light};
pub use lambert::lambert;
pub use lights::{LightSample, distance_falloff, illuminate, spot_falloff};
pub use phong::{blinn_specular, phong_specular};
pub use reflect::reflect;
pub use shade::{shade_light, shade_local};
