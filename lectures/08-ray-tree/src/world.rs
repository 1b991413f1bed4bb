//! What a ray is traced through: the scene's description and a way to
//! intersect its objects.

use std::fmt;

use raylab::{Intersector, Scene};

/// The scene (lights, materials, background, ambient light) with the
/// [`Intersector`] that finds hits among its objects: lecture 04's
/// `BruteForce` or lecture 09's BVH, so the tracer works with either.
///
/// `objects` must answer for `scene.objects`: every hit's `material` indexes
/// `scene.materials` (the loaders guarantee it for scenes from files).
/// Book: §8.1 The ray tree.
#[derive(Clone, Copy)]
pub struct World<'a> {
    pub scene: &'a Scene,
    pub objects: &'a dyn Intersector,
}

impl<'a> World<'a> {
    pub fn new(scene: &'a Scene, objects: &'a dyn Intersector) -> Self {
        Self { scene, objects }
    }
}

impl fmt::Debug for World<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("World")
            .field("objects", &self.scene.objects.len())
            .field("materials", &self.scene.materials.len())
            .field("lights", &self.scene.lights.len())
            .finish_non_exhaustive()
    }
}
