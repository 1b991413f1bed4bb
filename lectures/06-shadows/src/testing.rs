//! Test support: scene objects to feed lecture 04's brute-force
//! [`BruteForce`](l04_quadrics_transforms::BruteForce) intersector, the
//! scene without one object, and the ulp of a coordinate. The seeded
//! generator is the kit's `raylab::random::Rng`.

use raylab::scene::{Material, Object, Shape};
use raylab::{Color, Float, Vec3};

/// A world-space object of material `material`.
pub fn object(shape: Shape, material: usize) -> Object {
    Object { shape, material, transform: None }
}

pub fn sphere(center: Vec3, radius: Float, material: usize) -> Object {
    object(Shape::Sphere { center, radius }, material)
}

pub fn plane(normal: Vec3, offset: Float, material: usize) -> Object {
    object(Shape::Plane { normal, offset }, material)
}

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

/// The unit in the last place of `x`: the gap from |x| to the next float up.
pub fn ulp(x: Float) -> Float {
    let x = x.abs();
    x.next_up() - x
}
