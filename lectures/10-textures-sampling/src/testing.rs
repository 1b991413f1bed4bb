//! Test support: scenes whose supersampled pixels are known, and the exact
//! coverage of a pixel by a half-plane.

use l01_transforms::Camera;
use l04_quadrics_transforms::BruteForce;
use l08_ray_tree::{TraceSettings, World};
use raylab::scene::{self, Light, LightKind, Material, Object, Shape};
use raylab::stats::RayStats;
use raylab::{Color, Float, Image, Scene, Vec3};

use crate::{Filter, Pattern, render_supersampled};

fn scene_of(camera: scene::Camera, size: (u32, u32), objects: Vec<Object>, lights: Vec<Light>) -> Scene {
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
    let camera = scene::Camera::Orthographic {
        eye: Vec3::new(0.0, 0.0, 5.0),
        at: Vec3::ZERO,
        up: Vec3::Y,
        height: 2.0,
    };
    scene_of(camera, (size, size), vec![Object { shape: triangle, material: 0, transform: None }], vec![])
}

/// Two lit spheres over a floor, 24 × 16, seen in perspective: a scene with
/// edges, shading and shadows for the comparisons with lecture 08.
pub fn spheres() -> Scene {
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
        scene::Camera::Perspective { eye: Vec3::new(0.0, 1.0, 6.0), at: Vec3::ZERO, up: Vec3::Y, fovy: 0.7 };
    let mut s = scene_of(camera, (24, 16), vec![sphere(-1.0, 0.9), sphere(1.2, 0.6), floor], vec![light]);
    s.ambient = Color::splat(0.1);
    s.background = Color::new(0.2, 0.3, 0.5);
    s
}

/// `render_supersampled` of a scene at its own size, through its own camera,
/// with brute-force intersection and the default trace settings.
pub fn render(s: &Scene, spp: u32, pattern: Pattern, filter: Filter, seed: u64) -> (Image, RayStats) {
    let camera = Camera::from_scene(&s.camera, s.width, s.height).expect("a valid camera");
    let objects = BruteForce::new(&s.objects);
    let world = World::new(s, &objects);
    render_supersampled(
        &world,
        &camera,
        s.width,
        s.height,
        &TraceSettings::default(),
        spp,
        pattern,
        filter,
        seed,
    )
}

/// The fraction of the rectangle [x0, x1] × [y0, y1] below the line
/// y = slope·x + intercept, exactly (in f64): the height of the covered part
/// of each vertical line, g(x) = clamp(slope·x + intercept − y0, 0, y1 − y0),
/// is linear between the x where the line crosses y0 and y1, so the trapezoid
/// rule between those points integrates it exactly.
pub fn covered_fraction(slope: f64, intercept: f64, x0: f64, x1: f64, y0: f64, y1: f64) -> f64 {
    let g = |x: f64| (slope * x + intercept - y0).clamp(0.0, y1 - y0);
    let mut xs = vec![x0, x1];
    if slope != 0.0 {
        xs.extend(
            [(y0 - intercept) / slope, (y1 - intercept) / slope].into_iter().filter(|&x| x0 < x && x < x1),
        );
    }
    xs.sort_by(f64::total_cmp);
    let area: f64 = xs.windows(2).map(|s| 0.5 * (g(s[0]) + g(s[1])) * (s[1] - s[0])).sum();
    area / ((x1 - x0) * (y1 - y0))
}

/// The exact fraction of pixel (px, py) of [`half_plane`]'s `size × size` image
/// that the half-plane covers.
pub fn pixel_coverage(slope: f64, intercept: f64, size: u32, px: u32, py: u32) -> f64 {
    let side = 2.0 / f64::from(size);
    let (x0, y1) = (-1.0 + side * f64::from(px), 1.0 - side * f64::from(py));
    covered_fraction(slope, intercept, x0, x0 + side, y1 - side, y1)
}
