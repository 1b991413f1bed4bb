//! Lecture 08: the recursive ray tree and the complete Whitted tracer.
//!
//! A ray's colour is its hit's local shading (05, with the shadow rays of
//! 06) plus what the mirror and the transmitted ray of 07 see from there,
//! each traced the same way: the ray tree. [`trace`] grows it, stopping at
//! a depth limit and where a branch weighs too little to matter
//! ([`TraceSettings`]), and spawns only the rays a scene needs: no mirror
//! ray without k_r, no transmitted ray without k_t, no shadow ray for a light
//! that casts none. [`trace_recorded`] shows one pixel's [`RayTree`];
//! [`render`] and [`render_scene`] make the picture. Book: chapter 8.

mod ray_tree;
mod render;
#[cfg(test)]
mod scenes;
mod settings;
#[cfg(test)]
mod testing;
mod trace;
mod world;

pub use ray_tree::{RayKind, RayTree, trace_recorded};
pub use render::{render, render_scene};
pub use settings::TraceSettings;
pub use trace::trace;
pub use world::{SurfaceMaterial, World};
