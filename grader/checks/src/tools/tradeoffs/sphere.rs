//! The sphere pair: lecture 02's three solutions on a small sphere far away.

use std::hint::black_box;

use l02_ray_casting::{hit_sphere_algebraic, hit_sphere_geometric, hit_sphere_stable};
use raylab::random::Rng;
use raylab::{Float, Hit, Interval, Ray, Vec3};

use super::reference::sphere_truth;
use super::row::{Pair, Row, own_precision};
use super::timing::{Effort, time_per_item};
use raylab_testing::{roots::ulp_wide, wide};

type HitSphere = fn(&Ray, Vec3, Float, Interval) -> Option<Hit>;

/// The three solutions, the reference method last.
pub const VARIANTS: [(&str, HitSphere); 3] =
    [("algebraic", hit_sphere_algebraic), ("geometric", hit_sphere_geometric), ("stable", hit_sphere_stable)];

/// The distances of the sphere from the world origin.
pub const DISTANCES: [Float; 3] = [1e3, 1e4, 1e5];

/// A ray of the far-sphere case with what the reference says of it.
struct Case {
    ray: Ray,
    center: Vec3,
    /// The reference's verdict (`None`: within 10⁻⁹ of the silhouette, left out).
    hits: Option<bool>,
    /// The line passes farther than ε·D from the silhouette: beyond what rounding the inputs
    /// o − c (an error of half an ulp of D) can move it by.
    clear_of_silhouette: bool,
    /// The near root, for rays passing within half a radius of the centre.
    t_inside: Option<f64>,
}

/// Rays from the unit ball around the world origin toward a unit sphere at
/// `distance` in a random direction, aimed at a random point of the disc of
/// radius 1.5 around its centre (square of the radius uniform: 44 % of them
/// hit).
fn cases(distance: Float, count: usize, seed: u64) -> Vec<Case> {
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|_| {
            let origin = rng.in_ball(1.0);
            let center = rng.unit_vector() * distance;
            let toward = (center - origin).normalize();
            let across = rng.in_ball(1.5);
            let aim = center + (across - across.dot(toward) * toward);
            let dir = (aim - origin).normalize();
            let truth = sphere_truth(origin, dir, center, 1.0);
            let hits = (truth.h2.abs() > 1e-9).then_some(truth.h2 >= 0.0);
            let t_inside = truth.roots.filter(|_| truth.closeness < 0.5).map(|(t0, _)| t0);
            let clear_of_silhouette = (truth.closeness - 1.0).abs() >= wide(Float::EPSILON * distance);
            Case { ray: Ray::new(origin, dir), center, hits, clear_of_silhouette, t_inside }
        })
        .collect()
}

/// Every variant at every distance: wrong hit/miss % (of all rays, and of those clear of the
/// silhouette by ε·D), median and max |Δt| in ulp, ns per test.
pub fn measure(effort: &Effort) -> Vec<Row> {
    let mut rows = Vec::new();
    for (k, &distance) in DISTANCES.iter().enumerate() {
        let cases = cases(distance, effort.samples, 0x5f_e2e0 + k as u64);
        for (name, hit_sphere) in VARIANTS {
            let (mut wrong, mut judged, mut errors) = (0usize, 0usize, Vec::new());
            let (mut wrong_clear, mut judged_clear) = (0usize, 0usize);
            for case in &cases {
                let found = hit_sphere(&case.ray, case.center, 1.0, Interval::POSITIVE);
                if let Some(hits) = case.hits {
                    judged += 1;
                    wrong += usize::from(found.is_some() != hits);
                    if case.clear_of_silhouette {
                        judged_clear += 1;
                        wrong_clear += usize::from(found.is_some() != hits);
                    }
                }
                if let (Some(t0), Some(hit)) = (case.t_inside, found) {
                    errors.push((wide(hit.t) - t0).abs() / ulp_wide(t0));
                }
            }
            let time = time_per_item(effort, cases.len(), || {
                for case in &cases {
                    black_box(hit_sphere(black_box(&case.ray), case.center, 1.0, Interval::POSITIVE));
                }
            });
            let wrong_percent = 100.0 * wrong as f64 / judged.max(1) as f64;
            let wrong_clear_percent = 100.0 * wrong_clear as f64 / judged_clear.max(1) as f64;
            let median = if errors.is_empty() { 0.0 } else { crate::tools::bench::median(&mut errors) };
            let max = errors.iter().copied().fold(0.0, f64::max);
            rows.push(Row {
                pair: Pair::Sphere,
                case: format!("D = {distance:.0e}"),
                variant: name.to_string(),
                precision: own_precision().to_string(),
                time,
                metrics: vec![
                    ("wrong hit/miss %".into(), wrong_percent),
                    ("… clear of silhouette %".into(), wrong_clear_percent),
                    ("median |Δt| ulp".into(), median),
                    ("max |Δt| ulp".into(), max),
                ],
                fails: wrong_clear_percent > 0.2 || max > 4.0,
                pareto: false,
            });
        }
    }
    rows
}
