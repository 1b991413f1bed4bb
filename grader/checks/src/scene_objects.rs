//! Intersectors over a scene's objects for the lectures that have no
//! intersector type of their own.

use raylab::scene::Object;
use raylab::{Hit, Intersector, Interval, Ray};

/// Lecture 03's shapes (boxes, polygons, triangles, meshes, and lecture 02's
/// spheres and planes behind its `hit_shape`), tested brute force through
/// lecture 02's `closest_hit`.
pub struct Lecture03<'a>(pub &'a [Object]);

impl Intersector for Lecture03<'_> {
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        l02_ray_casting::closest_hit(self.0, ray, range, |object, ray, range| {
            l03_polygons_triangles::hit_shape(&object.shape, ray, range)
        })
    }
}
