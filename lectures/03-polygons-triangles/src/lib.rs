//! Lecture 03: boxes by slabs, polygons and triangles.
//!
//! The flat-sided shapes of a ray tracer: an axis-aligned box as the
//! intersection of three slabs ([`hit_slabs`], [`hit_box`]), made robust for
//! axis-parallel rays and rounding; the point-in-polygon tests by crossing
//! number and winding number ([`inside_crossings`], [`winding_number`]) and
//! the ray–polygon intersection ([`hit_polygon`]); ray–triangle intersection
//! three ways, compared for speed and for leaks through shared edges
//! ([`hit_triangle_cramer`], [`hit_triangle_moller_trumbore`],
//! [`hit_triangle_watertight`]); smooth shading normals
//! ([`interpolate_normal`], [`hit_triangle`]); and triangle meshes by brute
//! force ([`hit_mesh`]). [`hit_flat_shape`] puts the shapes of lectures 02–03
//! behind one door to render this lecture's scenes. Book: chapter 3.

mod mesh;
mod object;
mod polygon;
#[cfg(test)]
mod scenes;
mod slabs;
mod triangle;

pub use mesh::hit_mesh;
pub use object::{hit_flat_shape, hit_shape};
pub use polygon::{dominant_axis, hit_polygon, inside_crossings, newell_normal, winding_number};
pub use slabs::{hit_box, hit_slabs};
pub use triangle::{
    TriangleHit, edge_function, hit_triangle, hit_triangle_cramer, hit_triangle_moller_trumbore,
    hit_triangle_watertight, interpolate_normal,
};
