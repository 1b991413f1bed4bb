//! Test support: scenes whose supersampled pixels are known, and the exact
//! coverage of a pixel by a half-plane.

use l01_transforms::Camera;
use l04_quadrics_transforms::BruteForce;
use l08_ray_tree::{TraceSettings, World};
use raylab::stats::RayStats;
use raylab::{Image, Scene};

use crate::{Filter, Pattern, render_supersampled};

pub use raylab_testing::scenes::half_plane;

/// Two lit spheres over a floor, 24 × 16, seen in perspective: a scene with
/// edges, shading and shadows for the comparisons with lecture 08.
pub fn spheres() -> Scene {
    raylab_testing::scenes::two_spheres(24, 16)
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
