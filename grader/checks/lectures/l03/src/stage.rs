//! What lecture 03 lends the stages (`stages::Lent`): its shapes, tested brute force through
//! lecture 02's `closest_hit` (lecture 03 has no intersector type of its own): stage 03's
//! intersections.

use raylab::scene::Object;
use raylab::{Hit, Intersector, Interval, Ray};

use crate::stages::{Finds, Lent};

/// Lends lecture 03's shapes.
pub fn lend(lent: &mut Lent) {
    lent.finders.push((Finds::Shapes, |scene| Box::new(Shapes(&scene.objects))));
}

/// Lecture 03's shapes (boxes, polygons, triangles, meshes, and lecture 02's spheres and planes
/// behind its `hit_shape`), tested brute force through lecture 02's `closest_hit`.
struct Shapes<'a>(&'a [Object]);

impl Intersector for Shapes<'_> {
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        l02_ray_casting::closest_hit(self.0, ray, range, |object, ray, range| {
            l03_polygons_triangles::hit_shape(&object.shape, ray, range)
        })
    }
}
