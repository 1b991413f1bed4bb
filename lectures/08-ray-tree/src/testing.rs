//! Test support: small scenes built in code, and tracing one ray through
//! them with lecture 04's brute-force intersector.

use l04_quadrics_transforms::BruteForce;
use raylab::scene::{Camera, Light, LightKind, Material, Object, Shape};
use raylab::stats::{RayStats, measure};
use raylab::{Color, Float, Ray, Scene, Vec3};

use crate::{RayTree, TraceSettings, World, trace, trace_recorded};

pub const EPS: Float = Float::EPSILON;

pub fn v(x: Float, y: Float, z: Float) -> Vec3 {
    Vec3::new(x, y, z)
}

/// A scene of these objects, materials and lights; background and ambient as given,
/// the camera at (0, 0, 5) looking at the origin (only `render` uses it).
pub fn scene(
    objects: Vec<Object>,
    materials: Vec<Material>,
    lights: Vec<Light>,
    background: Color,
    ambient: Color,
) -> Scene {
    Scene {
        camera: Camera::Perspective { eye: v(0.0, 0.0, 5.0), at: Vec3::ZERO, up: Vec3::Y, fovy: 0.8 },
        width: 40,
        height: 30,
        background,
        ambient,
        lights,
        materials,
        objects,
        render: Default::default(),
    }
}

pub fn sphere(center: Vec3, radius: Float, material: usize) -> Object {
    Object { shape: Shape::Sphere { center, radius }, material, transform: None }
}

pub fn plane(normal: Vec3, offset: Float, material: usize) -> Object {
    Object { shape: Shape::Plane { normal, offset }, material, transform: None }
}

pub fn cuboid(min: Vec3, max: Vec3, material: usize) -> Object {
    Object { shape: Shape::Box { min, max }, material, transform: None }
}

/// A diffuse material of colour `kd`.
pub fn matte(kd: Color) -> Material {
    Material { diffuse: kd, ..Material::default() }
}

/// A mirror: black, k_r = `kr` everywhere.
pub fn mirror(kr: Float) -> Material {
    Material { diffuse: Color::ZERO, reflective: Color::splat(kr), ..Material::default() }
}

/// Clear glass: black, k_t = 1, index `ior`, no mirror of its own.
pub fn glass(ior: Float) -> Material {
    Material { diffuse: Color::ZERO, transparent: Color::ONE, ior, ..Material::default() }
}

/// A directional light seen along the unit `toward_light`.
pub fn directional(toward_light: Vec3, color: Color) -> Light {
    Light { color, shadows: true, kind: LightKind::Directional { direction: -toward_light } }
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

/// A mirror square (a thin box, front face z = −2, material 0 of k_r = `kr`) in front of
/// an eye at the origin, and behind the eye the wall z = 3 (material 1, k_d = (0.8, 0.4,
/// 0.2)), lit from L = (0, 1, −1)/√2 by white light, ambient 0.1, a grey-blue background.
pub fn mirror_and_wall(kr: Float) -> Scene {
    scene(
        vec![cuboid(v(-1.0, -1.0, -2.1), v(1.0, 1.0, -2.0), 0), plane(Vec3::Z, 3.0, 1)],
        vec![mirror(kr), matte(v(0.8, 0.4, 0.2))],
        vec![directional(v(0.0, 1.0, -1.0).normalize(), Color::ONE)],
        Color::new(0.2, 0.3, 0.4),
        Color::splat(0.1),
    )
}
