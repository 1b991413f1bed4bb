//! Model only what the scene requires: a hierarchy where it pays, brute
//! force for a handful of objects. Glue, not an exercise.

use l04_quadrics_transforms::BruteForce;
use raylab::Intersector;
use raylab::scene::{Object, Shape};

use crate::bounds::object_bounds;
use crate::bvh::Bvh;

/// Above this many bounded primitives a scene gets a BVH. Brute force costs
/// one test per primitive; a BVH a few box tests per level and a leaf or
/// two, which wins from a few dozen primitives on.
pub const BVH_THRESHOLD: usize = 32;

/// How many bounded primitives brute force tests on each ray: one per
/// triangle of a mesh, one per other object with a finite box. A transformed
/// mesh counts its triangles too: brute force tests them all (04's
/// `hit_object`), and a BVH, where the mesh is one primitive tested whole,
/// tests them only for the rays that meet its box. Unbounded objects
/// (planes) are not counted: every ray tests them either way.
pub fn bounded_primitives(objects: &[Object]) -> usize {
    objects
        .iter()
        .map(|object| match &object.shape {
            Shape::Mesh(mesh) => mesh.triangles.len(),
            _ => usize::from(object_bounds(object).is_finite()),
        })
        .sum()
}

/// True when the scene is worth a BVH: more than [`BVH_THRESHOLD`] bounded
/// primitives, counting mesh triangles ([`bounded_primitives`]). Five
/// spheres on a plane: false, brute force. Book: §9.9 When a hierarchy pays.
pub fn needs_bvh(objects: &[Object]) -> bool {
    bounded_primitives(objects) > BVH_THRESHOLD
}

/// The intersector the scene requires: a [`Bvh`] when [`needs_bvh`], else
/// 04's [`BruteForce`]. Both give the same hits.
pub fn intersector_for(objects: &[Object]) -> Box<dyn Intersector + '_> {
    if needs_bvh(objects) { Box::new(Bvh::build(objects)) } else { Box::new(BruteForce::new(objects)) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{object, sphere};
    use raylab::scene::Mesh;
    use raylab::{Interval, Mat4, Ray, Vec3};
    use std::sync::Arc;

    fn floor() -> Object {
        object(Shape::Plane { normal: Vec3::Y, offset: -1.0 }, 0, None)
    }

    #[test]
    fn five_spheres_stay_brute_force_and_a_mesh_gets_a_bvh() {
        let mut objects: Vec<Object> =
            (0..5).map(|i| sphere(Vec3::new(i as raylab::Float, 0.0, 0.0), 0.4, 0)).collect();
        objects.push(floor());
        assert_eq!(bounded_primitives(&objects), 5);
        assert!(!needs_bvh(&objects));
        // 32 bounded primitives is still brute force, 33 is not; planes never count.
        let spheres = |n: usize| -> Vec<Object> { (0..n).map(|_| sphere(Vec3::ZERO, 1.0, 0)).collect() };
        assert!(!needs_bvh(&spheres(32)));
        assert!(needs_bvh(&spheres(33)));
        assert!(!needs_bvh(&vec![floor(); 100]));
        // The icosphere(1) has 80 triangles: a BVH, placed by a transform or not (brute force
        // tests its 80 triangles on every ray either way; the BVH, where a transformed mesh is
        // one primitive, only on the rays that meet its box). The icosahedron, icosphere(0),
        // has 20: brute force.
        let (ico, icosahedron) = (Arc::new(Mesh::icosphere(1)), Arc::new(Mesh::icosphere(0)));
        let scaled = Some(Mat4::from_scale(Vec3::splat(2.0)));
        assert!(needs_bvh(&[object(Shape::Mesh(ico.clone()), 0, None)]));
        assert!(needs_bvh(&[object(Shape::Mesh(ico), 0, scaled)]));
        assert_eq!(bounded_primitives(&[object(Shape::Mesh(icosahedron.clone()), 0, scaled)]), 20);
        assert!(!needs_bvh(&[object(Shape::Mesh(icosahedron), 0, scaled)]));
    }

    #[test]
    fn either_choice_answers_the_same() {
        let few = [sphere(Vec3::ZERO, 1.0, 0)];
        let many: Vec<Object> =
            (0..40).map(|i| sphere(Vec3::new(0.0, 0.0, -3.0 * i as raylab::Float), 1.0, 0)).collect();
        let ray = Ray::new(Vec3::new(0.0, 0.0, 5.0), -Vec3::Z);
        // The sphere at the origin: from z = 5 to its top z = 1, t = 4.
        for objects in [&few[..], &many[..]] {
            assert_eq!(
                intersector_for(objects).closest_hit(&ray, Interval::POSITIVE).map(|h| h.t),
                Some(4.0)
            );
        }
    }
}
