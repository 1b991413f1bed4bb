//! Helpers shared by the unit tests: a seeded generator (the kit's SplitMix64)
//! with the draws the tests need, f64 views of `Float` values for independent
//! references, and the scenes the BVH is compared with brute force on.

use std::sync::Arc;

use raylab::scene::{Mesh, Object, Shape, Transform};
use raylab::{Float, Mat4, Vec3};

/// Seeded draws: the same rays and scenes on every run and machine.
pub struct Rng(raylab::random::Rng);

impl Rng {
    pub fn new(seed: u64) -> Self {
        Self(raylab::random::Rng::new(seed))
    }

    /// Uniform in [0, 1) with 53 random bits.
    pub fn f64(&mut self) -> f64 {
        (self.0.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi), rounded to `Float`.
    pub fn range(&mut self, lo: f64, hi: f64) -> Float {
        (lo + (hi - lo) * self.f64()) as Float
    }

    /// A uniform integer in 0..n (n > 0).
    pub fn below(&mut self, n: u64) -> u64 {
        self.0.next_u64() % n
    }

    /// A point uniform in the cube [−h, h]³.
    pub fn in_cube(&mut self, h: f64) -> Vec3 {
        Vec3::new(self.range(-h, h), self.range(-h, h), self.range(-h, h))
    }

    /// A uniformly distributed unit vector, in f64 (rejection from the cube).
    pub fn unit_f64(&mut self) -> [f64; 3] {
        loop {
            let v = [2.0 * self.f64() - 1.0, 2.0 * self.f64() - 1.0, 2.0 * self.f64() - 1.0];
            let l2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
            if l2 > 1e-6 && l2 <= 1.0 {
                let l = l2.sqrt();
                return [v[0] / l, v[1] / l, v[2] / l];
            }
        }
    }

    /// A random direction (unit up to rounding to `Float`).
    pub fn direction(&mut self) -> Vec3 {
        let [x, y, z] = self.unit_f64();
        Vec3::new(x as Float, y as Float, z as Float)
    }

    /// Barycentric coordinates (β, γ) uniform over a triangle.
    pub fn barycentric(&mut self) -> (f64, f64) {
        let (u, v) = (self.f64(), self.f64());
        if u + v > 1.0 { (1.0 - u, 1.0 - v) } else { (u, v) }
    }
}

pub use raylab_testing::wide3 as d3;

/// The first three rows of an affine matrix as f64 numbers (exact).
pub fn mat_f64(m: &Mat4) -> [[f64; 4]; 3] {
    std::array::from_fn(|i| {
        let row = m.row(i);
        [row.x as f64, row.y as f64, row.z as f64, row.w as f64]
    })
}

pub fn object(shape: Shape, material: usize, world_from_object: Option<Mat4>) -> Object {
    Object { shape, material, transform: world_from_object.map(|m| Transform::new(m).unwrap()) }
}

pub use raylab_testing::scenes::sphere;

/// A random scene of every kind of shape the brief names: 60 spheres, 20
/// boxes (one in four flat), 30 triangles (some with vertex normals), a
/// transformed sphere, a transformed box, a polygon, a cylinder and a cone
/// (placed), a floor plane and a torus mesh (1,024 triangles with normals and
/// uvs), all in [−6, 6]³. Materials are the object's index mod 7.
pub fn mixed_scene(rng: &mut Rng) -> Vec<Object> {
    let mut objects = Vec::new();
    let material = |objects: &Vec<Object>| objects.len() % 7;
    objects.push(object(Shape::Plane { normal: Vec3::Y, offset: -6.0 }, 0, None));
    objects.push(object(Shape::Mesh(Arc::new(Mesh::torus(2.0, 0.5, 32, 16))), 1, None));
    for _ in 0..60 {
        let m = material(&objects);
        objects.push(sphere(rng.in_cube(5.0), rng.range(0.05, 0.6), m));
    }
    for k in 0..20 {
        let (c, half) =
            (rng.in_cube(5.0), Vec3::new(rng.range(0.05, 0.5), rng.range(0.05, 0.5), rng.range(0.05, 0.5)));
        let mut half = half;
        if k % 4 == 0 {
            half[k % 3] = 0.0; // a flat box
        }
        let m = material(&objects);
        objects.push(object(Shape::Box { min: c - half, max: c + half }, m, None));
    }
    for k in 0..30 {
        let c = rng.in_cube(5.0);
        let vertices = [c + rng.in_cube(0.7), c + rng.in_cube(0.7), c + rng.in_cube(0.7)];
        let normals = (k % 3 == 0).then(|| [rng.direction(), rng.direction(), rng.direction()]);
        let m = material(&objects);
        objects.push(object(Shape::Triangle { vertices, normals }, m, None));
    }
    let placement = |t: Vec3, s: Vec3, angle: Float| {
        Mat4::from_translation(t)
            * Mat4::from_axis_angle(Vec3::new(1.0, -2.0, 0.5).normalize(), angle)
            * Mat4::from_scale(s)
    };
    let m = material(&objects);
    objects.push(object(
        Shape::Sphere { center: Vec3::ZERO, radius: 1.0 },
        m,
        Some(placement(Vec3::new(3.0, 1.0, -2.0), Vec3::new(0.3, 1.5, 0.8), 0.7)),
    ));
    let m = material(&objects);
    objects.push(object(
        Shape::Box { min: -Vec3::ONE, max: Vec3::ONE },
        m,
        Some(placement(Vec3::new(-3.0, -1.0, 2.0), Vec3::new(0.5, 0.2, 1.0), -1.1)),
    ));
    let m = material(&objects);
    objects.push(object(
        Shape::Cylinder,
        m,
        Some(placement(Vec3::new(0.0, 3.0, 3.0), Vec3::new(0.4, 0.4, 2.0), 0.3)),
    ));
    let m = material(&objects);
    objects.push(object(Shape::Cone, m, Some(placement(Vec3::new(-2.0, 2.0, -3.0), Vec3::splat(0.8), 2.0))));
    let m = material(&objects);
    objects.push(object(
        Shape::Polygon {
            vertices: vec![
                Vec3::new(4.0, -2.0, 0.0),
                Vec3::new(5.0, -2.0, 0.0),
                Vec3::new(5.0, -1.0, 0.5),
                Vec3::new(4.0, -1.0, 0.5),
            ],
        },
        m,
        None,
    ));
    objects
}
