//! The book's Rust code blocks, run as doctests against the workspace crates.
//!
//! Each module's documentation is one chapter of `book/src/`, included
//! verbatim, so rustdoc compiles and runs every ` ```rust ` block of the book
//! with the kit and every lecture crate in reach (`mdbook test` cannot see
//! workspace crates). Run: `cargo test -p book-doctests --doc` (and with
//! `--features raylab/f64`). Conventions for the chapters:
//! - a block that is not Rust is marked with its language (`sh`, `toml`,
//!   `text`): rustdoc would compile an unmarked block as Rust;
//! - a block that is a sketch (a signature with a placeholder) is
//!   `rust,ignore`, and the prose says it is one;
//! - a block that shows what a lecture's function does calls the lecture's
//!   function (`use l02_ray_casting::hit_sphere_stable;`), so the book cannot
//!   drift from the reference; setup lines start with `# `, which both mdBook
//!   and rustdoc hide from the reader.

#[doc = include_str!("../../src/introduction.md")]
pub mod introduction {}

#[doc = include_str!("../../src/00-conventions.md")]
pub mod ch00_conventions {}

// BEGIN GENERATED chapters: written by `cargo run -p grader -- dev sync` from lectures/*/Cargo.toml; edit those, not this.
#[doc = include_str!("../../src/01-transforms.md")]
pub mod ch01_transforms {}

#[doc = include_str!("../../src/02-ray-casting.md")]
pub mod ch02_ray_casting {}

#[doc = include_str!("../../src/03-polygons-triangles.md")]
pub mod ch03_polygons_triangles {}

#[doc = include_str!("../../src/04-quadrics-transforms.md")]
pub mod ch04_quadrics_transforms {}

#[doc = include_str!("../../src/05-shading.md")]
pub mod ch05_shading {}

#[doc = include_str!("../../src/06-shadows.md")]
pub mod ch06_shadows {}

#[doc = include_str!("../../src/07-reflection-refraction.md")]
pub mod ch07_reflection_refraction {}

#[doc = include_str!("../../src/08-ray-tree.md")]
pub mod ch08_ray_tree {}

#[doc = include_str!("../../src/09-acceleration.md")]
pub mod ch09_acceleration {}

#[doc = include_str!("../../src/10-textures-sampling.md")]
pub mod ch10_textures_sampling {}
// END GENERATED chapters
