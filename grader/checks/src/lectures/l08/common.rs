//! What the checks of lecture 08's files share.

pub(super) use l01_transforms::Camera;
pub(super) use l04_quadrics_transforms::BruteForce;
pub(super) use l08_ray_tree::{TraceSettings, World, render, trace};
pub(super) use raylab::scene::{self, Light, LightKind, Material, Object, Shape};
pub(super) use raylab::stats::{Counter, RayStats, measure};
pub(super) use raylab::{Color, Float, Image, Ray, Scene, Vec3};

pub(super) use crate::check::{CheckResult, close, ensure, fail, v, vec3};

pub(super) type TraceFn = fn(&World, &Ray, u32, Float, &TraceSettings) -> Color;
pub(super) type RenderFn = fn(&World, &Camera, u32, u32, &TraceSettings) -> (Image, RayStats);

pub(super) const EPS: Float = Float::EPSILON;

/// Colours by hand are sums of a few products of values at most 1: a handful of roundings,
/// taken in whatever order the student's code takes them. 64ε is far above that (a few ε)
/// and far below any mistake (the smallest one here changes a colour by 0.001).
pub(super) const COLOR_TOL: Float = 64.0 * EPS;

/// A scene of these objects, materials and lights, seen from (0, 0, 5) toward the origin.
pub(super) fn scene(
    objects: Vec<Object>,
    materials: Vec<Material>,
    lights: Vec<Light>,
    background: Color,
    ambient: Color,
) -> Scene {
    Scene {
        camera: scene::Camera::Perspective { eye: v(0.0, 0.0, 5.0), at: Vec3::ZERO, up: Vec3::Y, fovy: 0.8 },
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

pub(super) fn sphere(center: Vec3, radius: Float, material: usize) -> Object {
    Object { shape: Shape::Sphere { center, radius }, material, transform: None }
}

pub(super) fn plane(normal: Vec3, offset: Float, material: usize) -> Object {
    Object { shape: Shape::Plane { normal, offset }, material, transform: None }
}

pub(super) fn cuboid(min: Vec3, max: Vec3, material: usize) -> Object {
    Object { shape: Shape::Box { min, max }, material, transform: None }
}

pub(super) fn matte(kd: Color) -> Material {
    Material { diffuse: kd, ..Material::default() }
}

pub(super) fn mirror(kr: Float) -> Material {
    Material { diffuse: Color::ZERO, reflective: Color::splat(kr), ..Material::default() }
}

pub(super) fn glass(ior: Float) -> Material {
    Material { diffuse: Color::ZERO, transparent: Color::ONE, ior, ..Material::default() }
}

/// A directional light seen along the unit `toward_light`.
pub(super) fn directional(toward_light: Vec3, color: Color) -> Light {
    Light { color, shadows: true, kind: LightKind::Directional { direction: -toward_light } }
}

/// Reflected, refracted and shadow rays counted while tracing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Rays {
    pub(super) reflected: u64,
    pub(super) refracted: u64,
    pub(super) shadow: u64,
}

impl std::fmt::Display for Rays {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} mirror, {} refracted, {} shadow rays", self.reflected, self.refracted, self.shadow)
    }
}

pub(super) const fn rays(reflected: u64, refracted: u64, shadow: u64) -> Rays {
    Rays { reflected, refracted, shadow }
}

/// `trace` of one eye ray (depth 0, weight 1) through `s` with brute-force intersection,
/// and the rays it counted.
pub(super) fn traced(trace: TraceFn, s: &Scene, ray: &Ray, settings: &TraceSettings) -> (Color, Rays) {
    let objects = BruteForce::new(&s.objects);
    let world = World::new(s, &objects);
    let (color, stats) = measure(|| trace(&world, ray, 0, 1.0, settings));
    let counted = rays(
        stats.get(Counter::ReflectionRays),
        stats.get(Counter::RefractionRays),
        stats.get(Counter::ShadowRays),
    );
    (color, counted)
}

pub(super) fn near(a: Color, b: Color, tolerance: Float) -> bool {
    (a - b).abs().max_element() <= tolerance
}

pub(super) fn same_color(
    case: &str,
    got: Color,
    expected: Color,
    tolerance: Float,
    cause: &str,
) -> Result<(), crate::check::Failure> {
    ensure(
        near(got, expected, tolerance),
        case,
        format!("{} (± {tolerance:.1e})", vec3(expected)),
        vec3(got),
        cause,
    )
}

pub(super) const BACKGROUND: Color = Color::new(0.2, 0.3, 0.4);

/// A mirror square (a thin box, front face z = −2, k_r = `kr`) in front of an eye at the
/// origin, and behind the eye the wall z = 3 (k_d = (0.8, 0.4, 0.2)), lit from
/// L = (0, 1, −1)/√2, ambient 0.1.
pub(super) fn mirror_and_wall(kr: Float) -> Scene {
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
pub(super) fn facing_mirrors(kr: Float) -> (Scene, Ray) {
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

/// A glass block (y from −1 to 0, η = 1.5, k_t = 1) holding a green matte tile (y from −1
/// to −0.8, x from 1.5 to 3), no lights, ambient ½, magenta sky, and a ray from
/// (0, −0.5, 0) inside the glass going up at `degrees` from the vertical.
pub(super) fn block_with_tile(degrees: Float) -> (Scene, Ray) {
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
