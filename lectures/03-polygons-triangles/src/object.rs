//! One door to every shape of lectures 02 and 03, so this lecture's scenes
//! can be rendered before lecture 04 exists (whose `hit_object` supersedes
//! it). Glue, not an exercise.

use raylab::scene::{Object, Shape};
use raylab::stats::{Counter, count};
use raylab::{Hit, Interval, Ray};

use crate::mesh::hit_mesh;
use crate::polygon::hit_polygon;
use crate::slabs::hit_box;
use crate::triangle::hit_triangle;

/// The hit of `ray` with `object` inside `range`, for the shapes of lecture
/// 03 (box, polygon, triangle, mesh, including the kit's icosphere and torus)
/// and, through [`l02_ray_casting::hit_sphere_or_plane`], of lecture 02.
/// `None` for a transformed object and for the cylinder and cone (lecture
/// 04). Counts one intersection test per shape, one per triangle for a mesh.
/// Use it with [`l02_ray_casting::closest_hit`]. Book: §3.12 Rendering the
/// lecture's scenes.
pub fn hit_flat_shape(object: &Object, ray: &Ray, range: Interval) -> Option<Hit> {
    if object.transform.is_some() {
        return None;
    }
    hit_shape(&object.shape, ray, range)
}

/// The shapes of lectures 02 and 03 behind one door, in the shape's own
/// coordinates: boxes, polygons, triangles and meshes here (one
/// [`Counter::IntersectionTests`] per shape, one per triangle for a mesh),
/// spheres and planes through [`l02_ray_casting::hit_shape`]; `None` for the
/// cylinder and cone, which lecture 04's `hit_shape` handles before handing
/// the rest to this one.
pub fn hit_shape(shape: &Shape, ray: &Ray, range: Interval) -> Option<Hit> {
    match shape {
        Shape::Box { min, max } => {
            count(Counter::IntersectionTests);
            hit_box(ray, *min, *max, range)
        }
        Shape::Polygon { vertices } => {
            count(Counter::IntersectionTests);
            hit_polygon(ray, vertices, range)
        }
        Shape::Triangle { vertices, normals } => {
            count(Counter::IntersectionTests);
            hit_triangle(ray, vertices, normals.as_ref(), range)
        }
        Shape::Mesh(mesh) => hit_mesh(ray, mesh, range),
        _ => l02_ray_casting::hit_shape(shape, ray, range),
    }
}
