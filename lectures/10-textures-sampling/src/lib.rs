//! Lecture 10: texture mapping and supersampling.
//!
//! A texture gives a surface a colour that varies over it. A hit point gets
//! texture coordinates (u, v) by the shape's own parametrisation
//! ([`sphere_uv`], [`plane_uv`], [`triangle_uv`]); a procedural texture
//! ([`checker`], [`checker_3d`]) or an image looked up with [`bilinear`]
//! filtering turns them into a colour. A solid texture needs no (u, v): a
//! pattern in 3D, from gradient [`noise`] summed over octaves
//! ([`fractal_noise`]) to [`marble`] and [`wood`], blends two materials. One ray per pixel samples the picture
//! at one point and aliases (jagged edges, moiré); supersampling traces
//! several rays per pixel, placed by a [`Pattern`] ([`sample_offsets`]), and
//! averages them weighted by a reconstruction [`Filter`]
//! ([`filter_weight`]): [`render_supersampled`]. More samples cost more rays
//! and buy less error: the speed/accuracy trade of chapter 10. Lecture 08's
//! tracer asks [`surface_material`] for each hit's material; [`render_textured`]
//! renders a scene with both.
//! Book: chapter 10.

mod bilinear;
mod checker;
mod filter;
mod noise;
mod patterns;
mod supersample;
mod surface;
#[cfg(test)]
mod testing;
mod uv;

pub use bilinear::bilinear;
pub use checker::{checker, checker_3d};
pub use filter::{Filter, filter_weight};
pub use noise::{NOISE_BOUND, fade, fractal_noise, lattice_gradient, marble, noise, wood};
pub use patterns::{Pattern, grid, in_stratum, sample_offsets};
pub use supersample::{pixel_rng, render_supersampled};
pub use surface::{plane_axes, render_textured, solid_value, surface_material, surface_uv};
pub use uv::{plane_uv, sphere_uv, triangle_uv};
