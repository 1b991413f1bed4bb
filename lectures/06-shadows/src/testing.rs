//! Test support: scene objects to feed lecture 04's brute-force
//! [`BruteForce`](l04_quadrics_transforms::BruteForce) intersector, the
//! scene without one object, and the ulp of a coordinate. The seeded
//! generator is the kit's `raylab::random::Rng`.

use raylab::Color;
use raylab::scene::{Material, Object};

pub use raylab_testing::scenes::{object, plane, sphere};
pub use raylab_testing::ulp;

/// The objects without object `index`. For convex objects that is an exact
/// alternative to the offset of a shadow ray's origin (a convex surface
/// cannot shadow its own lit side), which the tests compare against.
pub fn without(objects: &[Object], index: usize) -> Vec<Object> {
    let mut others = objects.to_vec();
    others.remove(index);
    others
}

/// A white diffuse material that lets `transparent` through.
pub fn see_through(transparent: Color) -> Material {
    Material { transparent, ..Material::default() }
}
