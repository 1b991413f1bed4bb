//! Checks on this lecture's scene files (`scenes/*.toml`): they load, stay
//! small, ask for a BVH, every object is seen through it, its hits are brute
//! force's, and on the 65k-triangle torus it makes a tiny fraction of brute
//! force's intersection tests.

use std::path::PathBuf;

use l01_transforms::Camera;
use l04_quadrics_transforms::BruteForce;
use raylab::scene::{self, Scene};
use raylab::stats::{Counter, measure};
use raylab::{Float, Hit, Intersector, Ray};

use crate::{Bvh, bounded_primitives, needs_bvh};

const SCENES: [&str; 2] = ["many-spheres.toml", "torus-65k.toml"];

fn load(name: &str) -> Scene {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes")).join(name);
    scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// Every pixel's primary ray at the scene's size, row-major.
fn primary_rays(scene: &Scene) -> (Vec<Ray>, raylab::Interval) {
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).expect("a valid camera");
    let (w, h) = (scene.width, scene.height);
    let rays = (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).map(|(x, y)| camera.pixel_ray(x, y, w, h));
    (rays.collect(), camera.t_range())
}

#[test]
fn scenes_are_small_and_ask_for_a_bvh() {
    for name in SCENES {
        let scene = load(name);
        assert!(scene.width <= 200 && scene.height <= 150, "{name}: {}×{}", scene.width, scene.height);
        assert!(needs_bvh(&scene.objects), "{name}");
    }
    // 100 spheres (the floor is unbounded); 256·128·2 triangles, a sphere, a box and a
    // transformed cylinder.
    assert_eq!(bounded_primitives(&load("many-spheres.toml").objects), 100);
    assert_eq!(bounded_primitives(&load("torus-65k.toml").objects), 65_536 + 3);
}

#[test]
fn every_object_is_seen_through_the_bvh_with_finite_unit_normals() {
    for name in SCENES {
        let scene = load(name);
        let bvh = Bvh::build(&scene.objects);
        let (rays, range) = primary_rays(&scene);
        let hits: Vec<Option<Hit>> = rays.iter().map(|r| bvh.closest_hit(r, range)).collect();
        for i in 0..scene.objects.len() {
            assert!(hits.iter().flatten().any(|h| h.object == i), "{name}: object {i} is never seen");
        }
        for h in hits.iter().flatten() {
            assert!(h.t > 0.0 && h.t.is_finite() && h.point.is_finite(), "{name}: {h:?}");
            // Unit within the rounding of a normalisation (a few ε).
            assert!((h.normal.length() - 1.0).abs() < 8.0 * Float::EPSILON, "{name}: {h:?}");
        }
    }
}

#[test]
fn primary_hits_are_brute_forces() {
    // Every pixel of the spheres; every 37th pixel of the torus (brute force over 65k
    // triangles per ray is slow in a debug build): identical hits, any_hit agreeing.
    for (name, step) in [("many-spheres.toml", 1), ("torus-65k.toml", 37)] {
        let scene = load(name);
        let (bvh, brute) = (Bvh::build(&scene.objects), BruteForce::new(&scene.objects));
        // The tree as built (eight-wide on AVX2 CPUs, in f32) and traversed four-wide.
        let four_wide = bvh.four_wide_twin();
        let (rays, range) = primary_rays(&scene);
        for ray in rays.iter().step_by(step) {
            let expected = brute.closest_hit(ray, range);
            for (bvh, tree) in [(&bvh, "as built"), (&four_wide, "four-wide")] {
                assert_eq!(bvh.closest_hit(ray, range), expected, "{name}, {tree}: {ray:?}");
                assert_eq!(bvh.any_hit(ray, range), expected.is_some(), "{name}, {tree}: {ray:?}");
            }
        }
    }
}

#[test]
fn the_bvh_makes_a_tiny_fraction_of_brute_forces_tests() {
    // Intersection tests per primary ray on the 65k-triangle torus scene. Brute force
    // makes the same number for every ray: one per object, one per triangle (measured on
    // a few rays, and by hand 65 536 + 4). The BVH, averaged over every pixel, must stay
    // under 2% of it, and so must any_hit's.
    let scene = load("torus-65k.toml");
    let (bvh, brute) = (Bvh::build(&scene.objects), BruteForce::new(&scene.objects));
    let (rays, range) = primary_rays(&scene);
    let (_, stats) = measure(|| rays.iter().step_by(997).for_each(|r| _ = brute.closest_hit(r, range)));
    let sampled = rays.iter().step_by(997).count() as u64;
    let brute_per_ray = stats.get(Counter::IntersectionTests) as f64 / sampled as f64;
    assert_eq!(brute_per_ray, 65_536.0 + 4.0);
    let (_, stats) = measure(|| rays.iter().for_each(|r| _ = bvh.closest_hit(r, range)));
    let bvh_per_ray = stats.get(Counter::IntersectionTests) as f64 / rays.len() as f64;
    let (_, shadow_stats) = measure(|| rays.iter().for_each(|r| _ = bvh.any_hit(r, range)));
    let any_per_ray = shadow_stats.get(Counter::IntersectionTests) as f64 / rays.len() as f64;
    eprintln!(
        "torus-65k: intersection tests per primary ray: brute force {brute_per_ray:.0}, \
         BVH closest hit {bvh_per_ray:.1} ({:.3}%), BVH any hit {any_per_ray:.1}; depth {}, {} nodes",
        100.0 * bvh_per_ray / brute_per_ray,
        bvh.depth(),
        bvh.nodes.len()
    );
    assert!(bvh_per_ray < 0.02 * brute_per_ray, "{bvh_per_ray} tests per ray");
    assert!(any_per_ray < 0.02 * brute_per_ray, "{any_per_ray} tests per shadow-like ray");
}
