//! Lecture 09: bounding volumes and a bounding-volume hierarchy.
//!
//! Brute force tests every primitive for every ray; a hierarchy of boxes
//! tests a handful. An axis-aligned box ([`Aabb`]) is met by the slab test
//! with the ray's reciprocal direction computed once ([`Aabb::hit`]), merged
//! by [`Aabb::union`] and priced by its [`Aabb::surface_area`]. Every shape
//! gets a box ([`bounds`], [`object_bounds`]: the 8 corners through the
//! transform). [`Bvh::build`] splits the primitives (whole objects, or single
//! triangles of a mesh) by the surface area heuristic over binned centroids
//! ([`sah_split`]) into a flat array of four-wide nodes; [`Bvh::closest_hit`] walks it
//! near child first and skips what lies beyond the closest hit so far;
//! [`Bvh::any_hit`] stops at the first blocker. The answers are brute
//! force's, bit for bit; the ray statistics show the drop in tests. And a
//! scene gets a BVH only when it pays ([`needs_bvh`]). Book: chapter 9.

mod aabb;
mod bounds;
mod bvh;
mod choose;
// INSTRUCTOR BEGIN
mod fast;
// INSTRUCTOR END
mod primitive;
mod sah;
#[cfg(test)]
mod scenes;
#[cfg(test)]
mod testing;
mod traverse;

pub use aabb::Aabb;
pub use bounds::{bounds, object_bounds, sphere_bounds, transform_bounds, triangle_bounds};
pub use bvh::{Bvh, MAX_DEPTH, MAX_LEAF, Node, SAH_DEPTH, WIDTH};
pub use choose::{BVH_THRESHOLD, bounded_primitives, intersector_for, needs_bvh};
pub use primitive::{Primitive, hit_mesh_triangle};
pub use sah::{BINS, Bin, TRAVERSAL_COST, sah_split};
pub use traverse::{Closest, STACK_SIZE, Waiting};
