//! Test support: small scenes built in code, and tracing one ray through
//! them with lecture 04's brute-force intersector.

use l04_quadrics_transforms::BruteForce;
use raylab::scene::{Light, Material, Object};
use raylab::stats::{RayStats, measure};
use raylab::{Color, Float, Ray, Scene};

use crate::{RayTree, TraceSettings, World, trace, trace_recorded};

pub const EPS: Float = Float::EPSILON;

pub use raylab_testing::scenes::{cuboid, directional, glass, matte, mirror, mirror_and_wall, plane, sphere};
pub use raylab_testing::v;

/// A scene of these objects, materials and lights; background and ambient as given,
/// the camera at (0, 0, 5) looking at the origin, 40 × 30 (only `render` uses it).
pub fn scene(
    objects: Vec<Object>,
    materials: Vec<Material>,
    lights: Vec<Light>,
    background: Color,
    ambient: Color,
) -> Scene {
    let s = raylab_testing::scenes::scene(objects, materials, lights, background, ambient);
    Scene { width: 40, height: 30, ..s }
}

/// `trace` of one eye ray (depth 0, weight 1) through the scene, with what it counted.
pub fn trace_counted(scene: &Scene, ray: &Ray, settings: &TraceSettings) -> (Color, RayStats) {
    let objects = BruteForce::new(&scene.objects);
    measure(|| trace(&World::new(scene, &objects), ray, 0, 1.0, settings))
}

/// The recorded ray tree of one eye ray, with its colour.
pub fn recorded(scene: &Scene, ray: &Ray, settings: &TraceSettings) -> (Color, RayTree) {
    let objects = BruteForce::new(&scene.objects);
    trace_recorded(&World::new(scene, &objects), ray, settings)
}
