//! Lecture 10: texture mapping and supersampling.
//!
//! A texture gives a surface a colour that varies over it. A hit point gets
//! texture coordinates (u, v) by the shape's own parametrisation
//! ([`sphere_uv`], [`plane_uv`], [`triangle_uv`]); a procedural texture
//! ([`checker`], [`checker_3d`]) or an image looked up with [`bilinear`]
//! filtering turns them into a colour. One ray per pixel samples the picture
//! at one point and aliases (jagged edges, moiré); supersampling traces
//! several rays per pixel, placed by a [`Pattern`] ([`sample_offsets`]), and
//! averages them weighted by a reconstruction [`Filter`]
//! ([`filter_weight`]): [`render_supersampled`]. More samples cost more rays
//! and buy less error: the speed/accuracy trade of chapter 10. Lecture 08's
//! tracer asks [`surface_color`] for each hit's colour; [`render_textured`]
//! renders a scene with both.
//! Book: chapter 10.

mod bilinear;
mod checker;
mod filter;
mod patterns;
mod supersample;
mod surface;
#[cfg(test)]
mod testing;
mod uv;

pub use bilinear::bilinear;
pub use checker::{checker, checker_3d};
pub use filter::{Filter, filter_weight};
pub use patterns::{Pattern, grid, in_stratum, sample_offsets};
pub use supersample::{pixel_rng, render_supersampled};
pub use surface::{plane_axes, render_textured, surface_color, surface_uv};
pub use uv::{plane_uv, sphere_uv, triangle_uv};
