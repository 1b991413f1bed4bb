//! Small scenes built in code, as lecture 08's tests and checks (and the
//! later lectures') build them: objects and materials by a word each, and the
//! handful of scenes whose colours are worked out by hand in both.

use raylab::scene::{Camera, Light, LightKind, Material, Object, Shape};
use raylab::{Color, Float, Ray, Scene, Vec3};

use crate::v;

/// The grey-blue background of the hand-worked scenes.
pub const BACKGROUND: Color = Color::new(0.2, 0.3, 0.4);

/// A scene of these objects, materials and lights, background and ambient as
/// given, seen by a 16 × 12 camera at (0, 0, 5) looking at the origin (only a
/// render uses the camera; a test that wants another size sets `width` and
/// `height`).
pub fn scene(
    objects: Vec<Object>,
    materials: Vec<Material>,
    lights: Vec<Light>,
    background: Color,
    ambient: Color,
) -> Scene {
    Scene {
        camera: Camera::Perspective { eye: v(0.0, 0.0, 5.0), at: Vec3::ZERO, up: Vec3::Y, fovy: 0.8 },
        width: 16,
        height: 12,
        background,
        ambient,
        lights,
        materials,
        objects,
        render: Default::default(),
    }
}

/// A world-space object (no transform) of material `material`.
pub fn object(shape: Shape, material: usize) -> Object {
    Object { shape, material, transform: None }
}

pub fn sphere(center: Vec3, radius: Float, material: usize) -> Object {
    object(Shape::Sphere { center, radius }, material)
}

pub fn plane(normal: Vec3, offset: Float, material: usize) -> Object {
    object(Shape::Plane { normal, offset }, material)
}

pub fn cuboid(min: Vec3, max: Vec3, material: usize) -> Object {
    object(Shape::Box { min, max }, material)
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

/// A directional light that casts shadows, seen along the unit `toward_light`.
pub fn directional(toward_light: Vec3, color: Color) -> Light {
    Light { color, shadows: true, kind: LightKind::Directional { direction: -toward_light } }
}

/// A mirror square (a thin box, front face z = −2, material 0 of k_r = `kr`) in front of
/// an eye at the origin, and behind the eye the wall z = 3 (material 1, k_d = (0.8, 0.4,
/// 0.2)), lit from L = (0, 1, −1)/√2 by white light, ambient 0.1, [`BACKGROUND`].
pub fn mirror_and_wall(kr: Float) -> Scene {
    scene(
        vec![cuboid(v(-1.0, -1.0, -2.1), v(1.0, 1.0, -2.0), 0), plane(Vec3::Z, 3.0, 1)],
        vec![mirror(kr), matte(v(0.8, 0.4, 0.2))],
        vec![directional(v(0.0, 1.0, -1.0).normalize(), Color::ONE)],
        BACKGROUND,
        Color::splat(0.1),
    )
}

/// Two parallel mirrors x = ±1 (k_d = 0.1, k_r = `kr`), no lights, white ambient light,
/// and the ray from the origin along +x, bouncing between them at normal incidence.
pub fn facing_mirrors(kr: Float) -> (Scene, Ray) {
    let material = Material { diffuse: Color::splat(0.1), ..mirror(kr) };
    let s = scene(
        vec![plane(Vec3::X, 1.0, 0), plane(Vec3::X, -1.0, 0)],
        vec![material],
        vec![],
        BACKGROUND,
        Color::ONE,
    );
    (s, Ray::new(Vec3::ZERO, Vec3::X))
}

/// A glass block (y from −1 to 0, η = 1.5, k_t = 1, no mirror of its own) holding a
/// green matte tile (y from −1 to −0.8, x from 1.5 to 3), no lights, ambient ½, magenta
/// sky, and a ray from (0, −0.5, 0) inside the glass going up at `degrees` from the
/// vertical.
pub fn block_with_tile(degrees: Float) -> (Scene, Ray) {
    let s = scene(
        vec![
            cuboid(v(-5.0, -1.0, -5.0), v(5.0, 0.0, 5.0), 0),
            cuboid(v(1.5, -1.0, -1.0), v(3.0, -0.8, 1.0), 1),
        ],
        vec![glass(1.5), matte(v(0.2, 0.6, 0.4))],
        vec![],
        v(1.0, 0.0, 1.0),
        Color::splat(0.5),
    );
    let a = raylab::radians(degrees);
    (s, Ray::new(v(0.0, -0.5, 0.0), v(a.sin(), a.cos(), 0.0)))
}

/// Head-on into a glass block (z from −10 to −1, η = 1.5, k_t = 1, no mirror of its own)
/// holding a green matte tile (z from −6 to −5, x and y from −1 to 1), no lights, ambient
/// ½, magenta sky, and the ray from the origin along −z: Fresnel's R at normal incidence.
pub fn tile_in_glass() -> (Scene, Ray) {
    let s = scene(
        vec![
            cuboid(v(-5.0, -5.0, -10.0), v(5.0, 5.0, -1.0), 0),
            cuboid(v(-1.0, -1.0, -6.0), v(1.0, 1.0, -5.0), 1),
        ],
        vec![glass(1.5), matte(v(0.2, 0.6, 0.4))],
        vec![],
        v(1.0, 0.0, 1.0),
        Color::splat(0.5),
    );
    (s, Ray::new(Vec3::ZERO, -Vec3::Z))
}

/// A mirror ball, a glass ball and a matte one over a floor, lit, seen from (0, 0, 5): a
/// scene with every kind of ray (lecture 08's render).
pub fn three_balls() -> Scene {
    scene(
        vec![
            plane(Vec3::Y, -1.0, 0),
            sphere(v(-1.2, 0.0, 0.0), 0.8, 1),
            sphere(v(0.0, 0.0, 0.5), 0.6, 2),
            sphere(v(1.2, 0.0, 0.0), 0.8, 3),
        ],
        vec![matte(v(0.8, 0.8, 0.6)), mirror(0.8), glass(1.5), matte(v(0.2, 0.4, 0.9))],
        vec![directional(v(-1.0, 2.0, 1.0).normalize(), Color::ONE)],
        v(0.3, 0.4, 0.6),
        Color::splat(0.1),
    )
}

fn scene_of(camera: Camera, size: (u32, u32), objects: Vec<Object>, lights: Vec<Light>) -> Scene {
    Scene {
        camera,
        width: size.0,
        height: size.1,
        background: Color::ZERO,
        ambient: Color::ONE,
        lights,
        materials: vec![Material { diffuse: Color::ONE, ..Material::default() }],
        objects,
        render: Default::default(),
    }
}

/// The white half-plane y < slope·x + intercept (z = 0) on black, seen by an
/// orthographic camera from +z with a view 2 units high, in a `size × size`
/// image: the image is the square [−1, 1]², pixel (px, py) the square
/// x ∈ [−1 + 2px/size, −1 + 2(px + 1)/size], y ∈ [1 − 2(py + 1)/size, 1 − 2py/size].
/// No lights and white ambient light: a sample is exactly 1 on the half-plane
/// and 0 off it, so a box-filtered pixel is the fraction of its samples that
/// hit. The half-plane is a triangle reaching 100 units either way along the
/// edge and 1000 below it, which holds everything below the edge within
/// [−2, 2]² (the tent filter's reach from the pixels of a 1 × 1 image).
pub fn half_plane(slope: Float, intercept: Float, size: u32) -> Scene {
    let edge = |x: Float| Vec3::new(x, slope * x + intercept, 0.0);
    let triangle = Shape::Triangle {
        vertices: [edge(-100.0), edge(100.0), Vec3::new(0.0, -1000.0, 0.0)],
        normals: None,
    };
    let camera =
        Camera::Orthographic { eye: Vec3::new(0.0, 0.0, 5.0), at: Vec3::ZERO, up: Vec3::Y, height: 2.0 };
    scene_of(camera, (size, size), vec![Object { shape: triangle, material: 0, transform: None }], vec![])
}

/// Two lit spheres over a floor, `width × height`, seen in perspective: a scene
/// with edges, shading and shadows (lecture 10's supersampling against lecture 08).
pub fn two_spheres(width: u32, height: u32) -> Scene {
    let sphere = |x: Float, r: Float| Object {
        shape: Shape::Sphere { center: Vec3::new(x, 0.0, 0.0), radius: r },
        material: 0,
        transform: None,
    };
    let floor =
        Object { shape: Shape::Plane { normal: Vec3::Y, offset: -1.0 }, material: 0, transform: None };
    let light = Light {
        color: Color::splat(0.8),
        shadows: true,
        kind: LightKind::Directional { direction: Vec3::new(-1.0, -2.0, -1.0).normalize() },
    };
    let camera =
        Camera::Perspective { eye: Vec3::new(0.0, 1.0, 6.0), at: Vec3::ZERO, up: Vec3::Y, fovy: 0.7 };
    let mut s =
        scene_of(camera, (width, height), vec![sphere(-1.0, 0.9), sphere(1.2, 0.6), floor], vec![light]);
    s.ambient = Color::splat(0.1);
    s.background = Color::new(0.2, 0.3, 0.5);
    s
}
