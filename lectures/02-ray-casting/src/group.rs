//! A group of objects and the closest hit along a ray: test every object,
//! keep the nearest. The brute-force [`Group`] is what lectures 02–04 hand
//! the tracer; lecture 09 replaces it with a BVH behind the same
//! [`Intersector`] trait.

use raylab::scene::{Object, Shape};
use raylab::stats::{Counter, count};
use raylab::{Hit, Intersector, Interval, Ray};

use crate::plane::hit_plane;
use crate::sphere::hit_sphere_stable;

/// The closest hit of `ray` with any of `objects` inside `range`, found by
/// asking `hit_object` about each object in turn.
///
/// After each hit the range's `max` shrinks to its t, so later objects only
/// count if they are nearer (and a shape routine can stop early); the order
/// of the objects never changes the answer. The hit records the index of its
/// object in `objects` (`hit.object`) and the object's material
/// (`hit.material`). Book: §2.6 Groups and the closest hit.
pub fn closest_hit(
    objects: &[Object],
    ray: &Ray,
    range: Interval,
    hit_object: impl Fn(&Object, &Ray, Interval) -> Option<Hit>,
) -> Option<Hit> {
    // SOLUTION BEGIN
    let mut closest = None;
    let mut range = range;
    for (index, object) in objects.iter().enumerate() {
        // A nearer hit shrinks the range for every object after it.
        if let Some(mut hit) = hit_object(object, ray, range) {
            range = range.with_max(hit.t);
            hit.object = index;
            hit.material = object.material;
            closest = Some(hit);
        }
    }
    closest
    // SOLUTION END
}

/// The intersection routine of this lecture for one scene object: spheres by
/// [`hit_sphere_stable`], planes by [`hit_plane`]. Any other shape, and any
/// object with a transform, is not handled here (lectures 03 and 04) and
/// gives `None` without being counted; each handled call counts one
/// [`Counter::IntersectionTests`].
pub fn hit_sphere_or_plane(object: &Object, ray: &Ray, range: Interval) -> Option<Hit> {
    if object.transform.is_some() {
        return None;
    }
    hit_shape(&object.shape, ray, range)
}

/// The shapes of this lecture behind one door, in the shape's own
/// coordinates: a sphere by [`hit_sphere_stable`], a plane by [`hit_plane`],
/// each counting one [`Counter::IntersectionTests`]; `None`, uncounted, for
/// every later shape. Lectures 03 and 04 widen the door with their own
/// `hit_shape`, handing these two shapes back to this one.
pub fn hit_shape(shape: &Shape, ray: &Ray, range: Interval) -> Option<Hit> {
    match *shape {
        Shape::Sphere { center, radius } => {
            count(Counter::IntersectionTests);
            hit_sphere_stable(ray, center, radius, range)
        }
        Shape::Plane { normal, offset } => {
            count(Counter::IntersectionTests);
            hit_plane(ray, normal, offset, range)
        }
        _ => None,
    }
}

/// The scene's objects as one brute-force [`Intersector`]: every ray tests
/// every sphere and plane ([`hit_sphere_or_plane`]).
#[derive(Clone, Copy, Debug)]
pub struct Group<'a> {
    pub objects: &'a [Object],
}

impl<'a> Group<'a> {
    pub fn new(objects: &'a [Object]) -> Self {
        Self { objects }
    }
}

impl Intersector for Group<'_> {
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        closest_hit(self.objects, ray, range, hit_sphere_or_plane)
    }

    /// Stops at the first object hit in `range`: a shadow ray needs no more.
    fn any_hit(&self, ray: &Ray, range: Interval) -> bool {
        self.objects.iter().any(|object| hit_sphere_or_plane(object, ray, range).is_some())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::scene::Transform;
    use raylab::stats::measure;
    use raylab::{Float, Mat4, Vec3};

    fn sphere(z: Float, radius: Float, material: usize) -> Object {
        Object { shape: Shape::Sphere { center: Vec3::new(0.0, 0.0, z), radius }, material, transform: None }
    }

    fn plane(normal: Vec3, offset: Float, material: usize) -> Object {
        Object { shape: Shape::Plane { normal, offset }, material, transform: None }
    }

    /// Every ordering of 0..n (Heap's algorithm).
    fn permutations(n: usize) -> Vec<Vec<usize>> {
        fn heap(k: usize, items: &mut Vec<usize>, out: &mut Vec<Vec<usize>>) {
            if k <= 1 {
                out.push(items.clone());
                return;
            }
            for i in 0..k {
                heap(k - 1, items, out);
                let j = if k.is_multiple_of(2) { i } else { 0 };
                items.swap(j, k - 1);
            }
        }
        let mut out = Vec::new();
        heap(n, &mut (0..n).collect(), &mut out);
        out
    }

    #[test]
    fn closest_hit_picks_the_nearest_in_every_order() {
        // Seen from (0, 0, 10) along −z: three overlapping spheres and a floor-like plane
        // z = −5 facing +z. First surfaces: sphere at z = 2, r = 1.5 → t = 10 − 3.5 = 6.5;
        // z = 1, r = 2 → t = 7; z = 0, r = 3 → t = 7; plane → t = 15. The nearest is
        // the first sphere (t = 6.5, material 7), whatever the order.
        let objects =
            [sphere(2.0, 1.5, 7), sphere(1.0, 2.0, 3), sphere(0.0, 3.0, 5), plane(Vec3::Z, -5.0, 1)];
        let ray = Ray::new(Vec3::new(0.0, 0.0, 10.0), -Vec3::Z);
        let perms = permutations(objects.len());
        assert_eq!(perms.len(), 24);
        for order in perms {
            let shuffled: Vec<Object> = order.iter().map(|&i| objects[i].clone()).collect();
            let hit = closest_hit(&shuffled, &ray, Interval::POSITIVE, hit_sphere_or_plane).expect("hits");
            let at = order.iter().position(|&i| i == 0).unwrap();
            assert_eq!((hit.t, hit.object, hit.material), (6.5, at, 7), "order {order:?}");
            assert_eq!(hit.point, Vec3::new(0.0, 0.0, 3.5));
        }
    }

    #[test]
    fn closest_hit_respects_the_range() {
        // The same spheres: with max = 6.5 the t = 6.5 hit is excluded (open interval) and the
        // others are beyond; with min = 6.5 the next surfaces are at t = 7 (two of them: the
        // first in order is kept, the second is not nearer); with min = 9 the only hits left are the far sides
        // z = 2 − 1.5, 1 − 2, 0 − 3 at t = 9.5, 11, 13: the nearest is 9.5, from inside.
        let objects = [sphere(2.0, 1.5, 7), sphere(1.0, 2.0, 3), sphere(0.0, 3.0, 5)];
        let ray = Ray::new(Vec3::new(0.0, 0.0, 10.0), -Vec3::Z);
        let hit = closest_hit(&objects, &ray, Interval::new(0.0, 6.5), hit_sphere_or_plane);
        assert_eq!(hit.map(|h| h.t), None, "6.5 is max itself, the others are beyond");
        let hit = closest_hit(&objects, &ray, Interval::new(6.5, 100.0), hit_sphere_or_plane).expect("t = 7");
        assert_eq!((hit.t, hit.object, hit.material), (7.0, 1, 3), "the first of two hits at t = 7");
        let hit = closest_hit(&objects, &ray, Interval::new(9.0, 100.0), hit_sphere_or_plane).expect("far");
        assert_eq!((hit.t, hit.object, hit.front_face), (9.5, 0, false));
    }

    #[test]
    fn closest_hit_of_nothing_is_none() {
        let ray = Ray::new(Vec3::ZERO, -Vec3::Z);
        assert_eq!(closest_hit(&[], &ray, Interval::POSITIVE, hit_sphere_or_plane), None);
        let behind = [sphere(5.0, 1.0, 0)];
        assert_eq!(closest_hit(&behind, &ray, Interval::POSITIVE, hit_sphere_or_plane), None);
    }

    #[test]
    fn closest_hit_shrinks_the_range_it_passes_on() {
        // Each object is asked with max = the nearest t so far: with spheres first met at
        // t = 9, 7, 8 (in that order), the third is asked with max = 7.
        let objects = [sphere(0.0, 1.0, 0), sphere(2.0, 1.0, 0), sphere(1.0, 1.0, 0)];
        let ray = Ray::new(Vec3::new(0.0, 0.0, 10.0), -Vec3::Z);
        let asked = std::sync::Mutex::new(Vec::new());
        let hit = closest_hit(&objects, &ray, Interval::POSITIVE, |object, ray, range| {
            asked.lock().unwrap().push(range.max);
            hit_sphere_or_plane(object, ray, range)
        });
        assert_eq!(hit.map(|h| (h.t, h.object)), Some((7.0, 1)));
        assert_eq!(asked.into_inner().unwrap(), vec![Float::INFINITY, 9.0, 7.0]);
    }

    #[test]
    fn transformed_and_other_shapes_are_not_handled_nor_counted() {
        let ray = Ray::new(Vec3::new(0.0, 0.0, 10.0), -Vec3::Z);
        let mut moved = sphere(0.0, 1.0, 0);
        moved.transform = Transform::new(Mat4::IDENTITY);
        let cube = Object {
            shape: Shape::Box { min: Vec3::splat(-1.0), max: Vec3::ONE },
            material: 0,
            transform: None,
        };
        let (hits, stats) = measure(|| {
            [moved, cube, sphere(0.0, 1.0, 0)]
                .map(|o| hit_sphere_or_plane(&o, &ray, Interval::POSITIVE).is_some())
        });
        assert_eq!(hits, [false, false, true]);
        assert_eq!(stats.get(Counter::IntersectionTests), 1, "only the plain sphere is tested");
    }

    #[test]
    fn any_hit_stops_at_the_first_blocker() {
        // All three spheres are on the ray: any_hit tests one, closest_hit tests all three.
        let objects = [sphere(0.0, 1.0, 0), sphere(2.0, 1.0, 0), sphere(-2.0, 1.0, 0)];
        let group = Group::new(&objects);
        let ray = Ray::new(Vec3::new(0.0, 0.0, 10.0), -Vec3::Z);
        let (blocked, stats) = measure(|| group.any_hit(&ray, Interval::POSITIVE));
        assert!(blocked);
        assert_eq!(stats.get(Counter::IntersectionTests), 1);
        let (hit, stats) = measure(|| group.closest_hit(&ray, Interval::POSITIVE));
        assert_eq!(hit.map(|h| (h.t, h.object)), Some((7.0, 1)));
        assert_eq!(stats.get(Counter::IntersectionTests), 3);
        // Nothing before t = 5 (the nearest surface is at 7): no blocker, every object tested.
        let (blocked, stats) = measure(|| group.any_hit(&ray, Interval::new(0.0, 5.0)));
        assert!(!blocked);
        assert_eq!(stats.get(Counter::IntersectionTests), 3);
    }
}
