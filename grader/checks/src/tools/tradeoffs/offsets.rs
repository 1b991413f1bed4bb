//! The shadow-offset pair: lecture 06's three origins for a ray leaving a
//! surface, judged on a sphere (which cannot shadow its own lit side).

use std::hint::black_box;

use l04_quadrics_transforms::{BruteForce, hit_shape};
use l05_shading::LightSample;
use l06_shadows::{occluded, offset_origin, offset_origin_fixed_normal, offset_origin_fixed_t};
use raylab::random::Rng;
use raylab::scene::{Object, Shape};
use raylab::{Float, Hit, Interval, Ray, Vec3, WHITE};

use super::row::{Pair, Row, own_precision};
use super::timing::{Effort, time_per_item};

type Offset = fn(Vec3, Vec3, Vec3, Vec3) -> Vec3;

/// The two fixed epsilons first, the reference method last.
pub const VARIANTS: [(&str, Offset); 3] = [
    ("fixed_t", offset_origin_fixed_t),
    ("fixed_normal", offset_origin_fixed_normal),
    ("offset_origin", offset_origin),
];

/// A hit, the origin of the ray that found it, and a unit direction toward a light.
struct Sample {
    hit: Hit,
    from: Vec3,
    l: Vec3,
}

/// `count` hits on the sphere (c, r) from cameras 2–10 radii away aimed inside
/// its silhouette (within 0.95 r of the centre), each with a random unit
/// light direction.
fn samples(center: Vec3, radius: Float, count: usize, seed: u64) -> Vec<Sample> {
    let mut rng = Rng::new(seed);
    let sphere = Shape::Sphere { center, radius };
    let mut found = Vec::with_capacity(count);
    while found.len() < count {
        let from = center + rng.unit_vector() * radius * rng.range(2.0, 10.0);
        let aim = center + rng.in_ball(0.95) * radius;
        let ray = Ray::new(from, (aim - from).normalize());
        let l = rng.unit_vector();
        if let Some(hit) = hit_shape(&sphere, &ray, Interval::POSITIVE) {
            found.push(Sample { hit, from, l });
        }
    }
    found
}

/// A directional light seen along the unit `l`.
fn toward(l: Vec3) -> LightSample {
    LightSample { direction: l, distance: Float::INFINITY, intensity: WHITE }
}

/// How a variant fares on one sphere: the fraction of lit-side shadow rays
/// that find the sphere (acne) and of dark-side ones, |N·L| ≥ 0.05, that
/// find nothing (light leaks).
pub fn acne_and_leaks(offset: Offset, center: Vec3, radius: Float, count: usize) -> (f64, f64) {
    let objects = [Object { shape: Shape::Sphere { center, radius }, material: 0, transform: None }];
    let scene = BruteForce::new(&objects);
    let (mut lit, mut acne, mut dark, mut leaks) = (0usize, 0usize, 0usize, 0usize);
    for Sample { hit, from, l } in samples(center, radius, count, 0xac_4e) {
        let cos = hit.normal.dot(l);
        if cos.abs() < 0.05 {
            continue; // the terminator: neither side's verdict is certain there
        }
        let blocked = occluded(&scene, offset(hit.point, hit.normal, l, from), &toward(l));
        if cos > 0.0 {
            lit += 1;
            acne += usize::from(blocked);
        } else {
            dark += 1;
            leaks += usize::from(!blocked);
        }
    }
    (acne as f64 / lit.max(1) as f64, leaks as f64 / dark.max(1) as f64)
}

/// Every variant on spheres of radius 1 at (c, c, c), c = 1 … 10⁵ (acne), and
/// on a sphere of radius 10⁻⁴ at the origin (acne and leaks); ns per offset
/// and shadow ray.
pub fn measure(effort: &Effort) -> Vec<Row> {
    let mut rows = Vec::new();
    let cases: [(String, Vec3, Float, bool); 5] = [
        ("r = 1 at (1, 1, 1)".into(), Vec3::splat(1.0), 1.0, false),
        ("r = 1 at 1e2".into(), Vec3::splat(1e2), 1.0, false),
        ("r = 1 at 1e4".into(), Vec3::splat(1e4), 1.0, false),
        ("r = 1 at 1e5".into(), Vec3::splat(1e5), 1.0, false),
        ("r = 1e-4 at the origin".into(), Vec3::ZERO, 1e-4, true),
    ];
    for (case, center, radius, with_leaks) in cases {
        let objects = [Object { shape: Shape::Sphere { center, radius }, material: 0, transform: None }];
        let scene = BruteForce::new(&objects);
        let timed = samples(center, radius, effort.samples.min(2000), 0x71_3e);
        for (name, offset) in VARIANTS {
            let (acne, leaks) = acne_and_leaks(offset, center, radius, effort.samples);
            let time = time_per_item(effort, timed.len(), || {
                for Sample { hit, from, l } in &timed {
                    let origin = offset(hit.point, hit.normal, *l, *from);
                    black_box(occluded(&scene, black_box(origin), &toward(*l)));
                }
            });
            let mut metrics = vec![("acne %".to_string(), 100.0 * acne)];
            if with_leaks {
                metrics.push(("leaks %".to_string(), 100.0 * leaks));
            }
            rows.push(Row {
                pair: Pair::Offset,
                case: case.clone(),
                variant: name.to_string(),
                precision: own_precision().to_string(),
                time,
                metrics,
                fails: acne > 0.0 || (with_leaks && leaks > 0.01),
                pareto: false,
            });
        }
    }
    rows
}
