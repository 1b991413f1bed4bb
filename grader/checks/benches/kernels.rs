//! The intersection kernels of the lectures, timed by divan:
//! `cargo bench -p raylab-checks --bench kernels` (add `-- sphere` to run
//! only the benches whose name contains "sphere").
//!
//! Every bench answers a batch of [`RAYS`] precomputed queries (rays, or
//! points and directions) drawn from a seeded [`Rng`], so runs compare like
//! with like; one iteration is the whole batch, and divan's `item/s` column
//! is queries per second. Inputs and each answer go through
//! [`divan::black_box`] so the compiler can neither hoist nor drop the work.
//! The scene a group is run on is its argument, visible in the bench name
//! (`sphere::stable/far`, `bvh::closest_hit/65536`). Setup (the rays, the
//! mesh, the hierarchy of `closest_hit`) is outside the clock.
//!
//! The kernels are the lectures' reference bodies as built (lecture 02's
//! spheres, 03's triangles, slabs and meshes, 06's ray offsets, 07's
//! refraction and Fresnel terms, 09's boxes and BVH), so a change to one of
//! them is measured here, not guessed. Book: §9.10 Measuring a hierarchy.

use std::sync::Arc;

use divan::counter::ItemsCount;
use divan::{Bencher, black_box};
use raylab::random::Rng;
use raylab::scene::{Mesh, Object, Shape};
use raylab::{Float, Interval, Ray, Vec3};

fn main() {
    divan::main();
}

/// Queries in one batch: enough that the loop overhead and one cold cache
/// line are noise, few enough that the inputs stay in the L1/L2 cache.
const RAYS: usize = 256;

/// The seed of every group's inputs (any fixed value: the same inputs on every run).
const SEED: u64 = 0x5EED_0009;

/// Times `kernel` over every input of `inputs`, [`RAYS`] queries per iteration.
fn run<I: Sync, O>(bencher: Bencher, inputs: &[I], kernel: impl Fn(&I) -> O + Sync) {
    bencher.counter(ItemsCount::new(inputs.len())).bench(|| {
        for input in black_box(inputs) {
            black_box(kernel(input));
        }
    });
}

/// [`RAYS`] rays from points of the cube of half-side `spread` around
/// `origin`, each toward a point given by `target` (unit directions).
fn rays_toward(origin: Vec3, spread: Float, mut target: impl FnMut(&mut Rng) -> Vec3) -> Vec<Ray> {
    let mut rng = Rng::new(SEED);
    (0..RAYS)
        .map(|_| {
            let from = origin + rng.in_cube(spread);
            Ray::new(from, (target(&mut rng) - from).normalize())
        })
        .collect()
}

/// Lecture 02: one sphere of radius 1, near (centre 3 away) or far (1000
/// away, where the textbook discriminant cancels); rays from around the
/// origin toward the ball of radius 1.5 around the centre, so about half hit.
mod sphere {
    use super::*;
    use l02_ray_casting::{hit_sphere_algebraic, hit_sphere_geometric, hit_sphere_stable};

    const CASES: [&str; 2] = ["near", "far"];

    /// The sphere (centre, radius) of `case` and the rays shot at it.
    fn scene(case: &str) -> (Vec3, Float, Vec<Ray>) {
        let distance = if case == "far" { 1000.0 } else { 3.0 };
        let center = Vec3::new(0.0, 0.0, -distance);
        (center, 1.0, rays_toward(Vec3::ZERO, 0.5, |rng| center + rng.in_ball(1.5)))
    }

    #[divan::bench(args = CASES)]
    fn algebraic(bencher: Bencher, case: &str) {
        let (center, radius, rays) = scene(case);
        run(bencher, &rays, |ray| hit_sphere_algebraic(ray, center, radius, Interval::POSITIVE));
    }

    #[divan::bench(args = CASES)]
    fn geometric(bencher: Bencher, case: &str) {
        let (center, radius, rays) = scene(case);
        run(bencher, &rays, |ray| hit_sphere_geometric(ray, center, radius, Interval::POSITIVE));
    }

    #[divan::bench(args = CASES)]
    fn stable(bencher: Bencher, case: &str) {
        let (center, radius, rays) = scene(case);
        run(bencher, &rays, |ray| hit_sphere_stable(ray, center, radius, Interval::POSITIVE));
    }
}

/// Lecture 03: one triangle 3 in front of the rays, which aim at a square
/// around it (a bit under half of them hit).
mod triangle {
    use super::*;
    use l03_polygons_triangles::{
        hit_triangle_cramer, hit_triangle_moller_trumbore, hit_triangle_watertight,
    };

    const A: Vec3 = Vec3::new(-1.0, -1.0, -3.0);
    const B: Vec3 = Vec3::new(1.0, -1.0, -3.0);
    const C: Vec3 = Vec3::new(0.0, 1.0, -3.0);

    fn rays() -> Vec<Ray> {
        rays_toward(Vec3::ZERO, 0.5, |rng| Vec3::new(rng.range(-1.2, 1.2), rng.range(-1.2, 1.2), -3.0))
    }

    #[divan::bench]
    fn cramer(bencher: Bencher) {
        run(bencher, &rays(), |ray| hit_triangle_cramer(ray, A, B, C, Interval::POSITIVE));
    }

    #[divan::bench]
    fn moller_trumbore(bencher: Bencher) {
        run(bencher, &rays(), |ray| hit_triangle_moller_trumbore(ray, A, B, C, Interval::POSITIVE));
    }

    #[divan::bench]
    fn watertight(bencher: Bencher) {
        run(bencher, &rays(), |ray| hit_triangle_watertight(ray, A, B, C, Interval::POSITIVE));
    }
}

/// Lectures 03 and 09: the box [−1, 1]² × [−4, −2], rays from around the
/// origin toward the cube of half-side 1.5 around its centre (about half
/// hit). 09's `Aabb::hit` takes the reciprocal direction, precomputed per
/// ray as the traversal does.
mod slabs {
    use super::*;
    use l09_acceleration::Aabb;

    const MIN: Vec3 = Vec3::new(-1.0, -1.0, -4.0);
    const MAX: Vec3 = Vec3::new(1.0, 1.0, -2.0);

    fn rays() -> Vec<Ray> {
        rays_toward(Vec3::ZERO, 0.5, |rng| Vec3::new(0.0, 0.0, -3.0) + rng.in_cube(1.5))
    }

    #[divan::bench]
    fn hit_slabs(bencher: Bencher) {
        run(bencher, &rays(), |ray| l03_polygons_triangles::hit_slabs(ray, MIN, MAX, Interval::POSITIVE));
    }

    #[divan::bench]
    fn hit_box(bencher: Bencher) {
        run(bencher, &rays(), |ray| l03_polygons_triangles::hit_box(ray, MIN, MAX, Interval::POSITIVE));
    }

    #[divan::bench]
    fn aabb_hit(bencher: Bencher) {
        let aabb = Aabb::new(MIN, MAX);
        let inputs: Vec<(Ray, Vec3)> = rays().into_iter().map(|ray| (ray, ray.dir.recip())).collect();
        run(bencher, &inputs, |(ray, inv_dir)| aabb.hit(ray, *inv_dir, Interval::POSITIVE));
    }
}

/// Lecture 03's brute-force mesh test on the kit's icosphere (argument: its
/// subdivisions; 2 gives 320 triangles), rays from a sphere of radius 3
/// toward the ball of radius 1.2 (most hit).
mod mesh {
    use super::*;
    use l03_polygons_triangles::hit_mesh;

    #[divan::bench(args = [2])]
    fn hit_mesh_icosphere(bencher: Bencher, subdivisions: u32) {
        let mesh = Mesh::icosphere(subdivisions);
        let mut rng = Rng::new(SEED);
        let rays: Vec<Ray> = (0..RAYS)
            .map(|_| {
                let from = 3.0 * rng.unit_vector();
                Ray::new(from, (rng.in_ball(1.2) - from).normalize())
            })
            .collect();
        run(bencher, &rays, |ray| hit_mesh(ray, &mesh, Interval::POSITIVE));
    }
}

/// Lecture 06: the shadow-ray origin, robust and the two fixed-size
/// variants, on hit points in the cube of half-side 10 with random unit
/// normals and directions.
mod offset {
    use super::*;
    use l06_shadows::{offset_origin, offset_origin_fixed_normal, offset_origin_fixed_t};

    /// (p, n, dir, from) for each query.
    fn inputs() -> Vec<[Vec3; 4]> {
        let mut rng = Rng::new(SEED);
        (0..RAYS)
            .map(|_| [rng.in_cube(10.0), rng.unit_vector(), rng.unit_vector(), rng.in_cube(10.0)])
            .collect()
    }

    #[divan::bench]
    fn robust(bencher: Bencher) {
        run(bencher, &inputs(), |&[p, n, dir, from]| offset_origin(p, n, dir, from));
    }

    #[divan::bench]
    fn fixed_t(bencher: Bencher) {
        run(bencher, &inputs(), |&[p, n, dir, from]| offset_origin_fixed_t(p, n, dir, from));
    }

    #[divan::bench]
    fn fixed_normal(bencher: Bencher) {
        run(bencher, &inputs(), |&[p, n, dir, from]| offset_origin_fixed_normal(p, n, dir, from));
    }
}

/// Lecture 07: refraction and the two Fresnel terms on random unit
/// directions and normals facing them, entering glass (η 1 → 1.5) or
/// leaving it (1.5 → 1, where rays past the critical angle reflect totally).
mod fresnel {
    use super::*;
    use l07_reflection_refraction as l07;

    const CASES: [&str; 2] = ["air_to_glass", "glass_to_air"];

    /// (η_i, η_t) of `case`.
    fn indices(case: &str) -> (Float, Float) {
        if case == "glass_to_air" { (1.5, 1.0) } else { (1.0, 1.5) }
    }

    /// (incoming direction, normal facing it) for each query.
    fn inputs() -> Vec<(Vec3, Vec3)> {
        let mut rng = Rng::new(SEED);
        (0..RAYS)
            .map(|_| {
                let (i, n) = (rng.unit_vector(), rng.unit_vector());
                (i, if i.dot(n) > 0.0 { -n } else { n })
            })
            .collect()
    }

    #[divan::bench(args = CASES)]
    fn refract(bencher: Bencher, case: &str) {
        let (eta_i, eta_t) = indices(case);
        run(bencher, &inputs(), |&(i, n)| l07::refract(i, n, eta_i / eta_t));
    }

    #[divan::bench(args = CASES)]
    fn schlick(bencher: Bencher, case: &str) {
        let (eta_i, eta_t) = indices(case);
        let cosines: Vec<Float> = inputs().iter().map(|(i, n)| -i.dot(*n)).collect();
        run(bencher, &cosines, |&cos_i| l07::schlick(cos_i, eta_i, eta_t));
    }

    #[divan::bench(args = CASES)]
    fn fresnel_dielectric(bencher: Bencher, case: &str) {
        let (eta_i, eta_t) = indices(case);
        let cosines: Vec<Float> = inputs().iter().map(|(i, n)| -i.dot(*n)).collect();
        run(bencher, &cosines, |&cos_i| l07::fresnel_dielectric(cos_i, eta_i, eta_t));
    }
}

/// Lecture 09: building the hierarchy of, and shooting closest-hit rays at,
/// the kit's torus (major radius 1, minor 0.4, around z) with about the
/// argument's number of triangles, as `grader bench-rays --generated N`
/// makes it (65,536: 256 × 128 segments, exactly 65,536 triangles). The
/// rays start on the sphere of radius 3 and aim into the torus's bounding
/// box [−1.4, 1.4]² × [−0.4, 0.4] (about half hit).
mod bvh {
    use super::*;
    use l09_acceleration::Bvh;

    const TRIANGLES: [u32; 1] = [65_536];

    /// The torus of about `triangles` triangles as the one object of a scene:
    /// N = √(triangles/4) minor segments, M = triangles/2N major ones (2·M·N
    /// triangles), the segment counts of `grader bench-rays`' `torus_segments`.
    fn torus(triangles: u32) -> [Object; 1] {
        let minor = ((triangles as f64 / 4.0).sqrt().round() as u32).max(3);
        let major = ((triangles as f64 / (2.0 * minor as f64)).round() as u32).max(3);
        let mesh = Mesh::torus(1.0, 0.4, major, minor);
        [Object { shape: Shape::Mesh(Arc::new(mesh)), material: 0, transform: None }]
    }

    /// 20 samples: one build takes tens of milliseconds.
    #[divan::bench(args = TRIANGLES, sample_count = 20)]
    fn build(bencher: Bencher, triangles: u32) {
        let objects = torus(triangles);
        bencher.bench(|| Bvh::build(black_box(&objects)));
    }

    #[divan::bench(args = TRIANGLES)]
    fn closest_hit(bencher: Bencher, triangles: u32) {
        let objects = torus(triangles);
        let bvh = Bvh::build(&objects);
        let mut rng = Rng::new(SEED);
        let rays: Vec<Ray> = (0..RAYS)
            .map(|_| {
                let from = 3.0 * rng.unit_vector();
                let to = Vec3::new(rng.range(-1.4, 1.4), rng.range(-1.4, 1.4), rng.range(-0.4, 0.4));
                Ray::new(from, (to - from).normalize())
            })
            .collect();
        run(bencher, &rays, |ray| bvh.closest_hit(ray, Interval::POSITIVE));
    }
}
