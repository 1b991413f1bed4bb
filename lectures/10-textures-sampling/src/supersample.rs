//! Supersampling: several eye rays per pixel, weighted by a filter.

use l01_transforms::Camera;
use l08_ray_tree::{TraceSettings, World, trace};
use raylab::random::Rng;
use raylab::render::render_image;
use raylab::stats::{Counter, RayStats, count};
use raylab::{BLACK, Float, Image, Vec2};

use crate::filter::{Filter, filter_weight};
use crate::patterns::{Pattern, sample_offsets};

/// The random generator of pixel (x, y) of a render seeded by `seed`: the
/// seed and the pixel hashed by SplitMix64. Each pixel owns its generator, so
/// a render is the same on every run and for any number of threads (no
/// shared stream whose order depends on scheduling). Book: §10.8 Seeds per pixel.
pub fn pixel_rng(seed: u64, x: u32, y: u32) -> Rng {
    let pixel = (u64::from(y) << 32) | u64::from(x);
    Rng::new(Rng::new(Rng::new(seed).next_u64() ^ pixel).next_u64())
}

/// A `width × height` image of `world` seen by `camera`, with `spp` eye rays
/// per pixel placed by `pattern` and averaged with the weights of `filter`:
///
/// ```text
/// dₖ = (2uₖ − 1)·r,   uₖ = sample_offsets(pattern, spp)ₖ,   r = filter.radius(),
/// pixel = Σₖ w(dₖ)·trace(ray through the pixel centre + dₖ) / Σₖ w(dₖ),
/// ```
///
/// so the samples cover the filter's support [−r, r)² around the centre (the
/// pixel itself for the box, the 2 × 2 pixels around it for the tent). A
/// sample at pixel coordinates (px, py) = (x + ½ + dₓ, y + ½ + d_y) goes
/// through screen point sx = (2px − w)/w, sy = (h − 2py)/h (01's formula,
/// which it equals at the centre, bit for bit), then lecture 08's `trace` at
/// depth 0 with weight 1. When every weight is 0 (all samples on the tent's
/// rim), the plain mean.
///
/// Each pixel draws from its own [`pixel_rng`]`(seed, x, y)`: the image is
/// fixed by the seed, whatever the number of threads. `spp` = 0 is taken as 1.
/// With spp = 1 and [`Pattern::Regular`] the one sample is the pixel centre,
/// weight 1: lecture 08's `render`, bit for bit. Counts one
/// [`Counter::PrimaryRays`] per sample. Book: §10.8 Supersampling.
#[allow(clippy::too_many_arguments)] // the lecture's contract: every knob of the trade in view
pub fn render_supersampled(
    world: &World,
    camera: &Camera,
    width: u32,
    height: u32,
    settings: &TraceSettings,
    spp: u32,
    pattern: Pattern,
    filter: Filter,
    seed: u64,
) -> (Image, RayStats) {
    // SOLUTION BEGIN
    let (w, h) = (width as Float, height as Float);
    let radius = filter.radius();
    render_image(width, height, |x, y| {
        // This pixel's own samples, from its own generator.
        let mut rng = pixel_rng(seed, x, y);
        let offsets = sample_offsets(pattern, spp.max(1), &mut rng);
        let (mut weighted, mut total_weight, mut plain) = (BLACK, 0.0, BLACK);
        for u in &offsets {
            // The sample's offset from the pixel centre, over the filter's support.
            let d = (2.0 * *u - Vec2::ONE) * radius;
            // Its eye ray, through the screen point of (x + ½ + dₓ, y + ½ + d_y).
            let sx = (2.0 * (x as Float + 0.5 + d.x) - w) / w;
            let sy = (h - 2.0 * (y as Float + 0.5 + d.y)) / h;
            count(Counter::PrimaryRays);
            let color = trace(world, &camera.generate_ray(sx, sy), 0, 1.0, settings);
            // Its share of the pixel.
            let weight = filter_weight(filter, d);
            weighted += weight * color;
            total_weight += weight;
            plain += color;
        }
        // The weighted average (the plain mean if nothing weighs).
        if total_weight > 0.0 { weighted / total_weight } else { plain / offsets.len() as Float }
    })
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{covered_fraction, half_plane, pixel_coverage, render, spheres};
    use l04_quadrics_transforms::BruteForce;
    use std::time::Instant;

    const PATTERNS: [Pattern; 3] = [Pattern::Regular, Pattern::Jittered, Pattern::Stratified];

    #[test]
    fn one_regular_sample_is_lecture_08s_render() {
        // spp = 1, Regular: the offset (½, ½) is the centre, d = 0, weight 1: the same eye ray
        // as 08's render (the screen formula is 01's at the centre, exactly) and c·1/1 = c.
        // Bit for bit, pixels and statistics, for both filters (the tent weighs 1 at 0 too).
        let s = spheres();
        let camera = Camera::from_scene(&s.camera, s.width, s.height).unwrap();
        let objects = BruteForce::new(&s.objects);
        let world = World::new(&s, &objects);
        let settings = TraceSettings::default();
        let expected = l08_ray_tree::render(&world, &camera, s.width, s.height, &settings);
        for filter in [Filter::Box, Filter::Tent] {
            assert_eq!(render(&s, 1, Pattern::Regular, filter, 5), expected, "{filter:?}");
        }
    }

    #[test]
    fn counts_one_primary_ray_per_sample() {
        // 24 × 16 pixels × 9 samples = 3456 eye rays; spp = 0 is taken as 1: 384.
        let s = spheres();
        let (_, stats) = render(&s, 9, Pattern::Jittered, Filter::Box, 1);
        assert_eq!(stats.get(Counter::PrimaryRays), 24 * 16 * 9);
        let (image, stats) = render(&s, 0, Pattern::Stratified, Filter::Tent, 1);
        assert_eq!(stats.get(Counter::PrimaryRays), 24 * 16);
        assert_eq!(image.non_finite(), None);
    }

    #[test]
    fn renders_repeat_for_a_seed_whatever_the_thread_count() {
        // Every pixel draws from its own generator: the same seed gives the same image, on one
        // thread as on the default pool; another seed gives another image.
        let s = spheres();
        let one_thread = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap();
        for pattern in [Pattern::Jittered, Pattern::Stratified] {
            let a = render(&s, 4, pattern, Filter::Tent, 42);
            assert_eq!(render(&s, 4, pattern, Filter::Tent, 42), a);
            assert_eq!(one_thread.install(|| render(&s, 4, pattern, Filter::Tent, 42)), a);
            assert_ne!(render(&s, 4, pattern, Filter::Tent, 43).0, a.0);
        }
    }

    #[test]
    fn the_exact_coverage_helper_is_right_by_hand() {
        // The check on the checker: y < 0.3x + 0.2 in [−1, 1]² is the area under the line,
        // ∫₋₁¹ (0.3x + 0.2 + 1) dx = 2·1.2 = 2.4 (the 0.3x part is odd), of 4: 0.6. A line
        // through the square's corners (y = x) halves it; one above it covers it all.
        assert!((covered_fraction(0.3, 0.2, -1.0, 1.0, -1.0, 1.0) - 0.6).abs() < 1e-15);
        assert!((covered_fraction(1.0, 0.0, -1.0, 1.0, -1.0, 1.0) - 0.5).abs() < 1e-15);
        assert_eq!(covered_fraction(0.0, 3.0, -1.0, 1.0, -1.0, 1.0), 1.0);
        assert_eq!(covered_fraction(0.0, -3.0, -1.0, 1.0, -1.0, 1.0), 0.0);
    }

    #[test]
    fn a_box_filtered_pixel_converges_to_its_covered_fraction() {
        // One pixel, the square [−1, 1]², under the edge y = 0.3x + 0.2: covered fraction 0.6
        // (by hand, above). 1024 = 32 × 32 samples.
        // Regular: in each of the 32 sample columns the line is straight, so the covered part of
        // the column is its height at the column's centre, which the 32 samples there count to
        // within ½ sample: error ≤ 1/(2·32) = 1/64.
        // Jittered and multi-jittered: only the cells the edge crosses can be wrong, at most 2
        // per column (it rises 0.3 of a cell per column), 64 cells, each a Bernoulli of
        // variance ≤ ¼ in 1/1024 of the pixel: σ ≤ √64·½/1024 = 0.0039; allowed 0.02 (5σ).
        let s = half_plane(0.3, 0.2, 1);
        for (pattern, tolerance) in
            [(Pattern::Regular, 1.0 / 64.0), (Pattern::Jittered, 0.02), (Pattern::Stratified, 0.02)]
        {
            let (image, _) = render(&s, 1024, pattern, Filter::Box, 7);
            let value = image.get(0, 0).x;
            println!("{pattern:?}, 1024 spp: {value:.5} (exact 0.6)");
            assert!((value - 0.6).abs() <= tolerance, "{pattern:?}: {value}");
        }
    }

    #[test]
    fn an_edge_through_the_centre_gives_one_half_with_either_filter() {
        // The edge y = 0.3x through the pixel's centre, a regular k × k grid with k even (a power
        // of two, so every offset is exact): the samples come in pairs d, −d of equal weight
        // (both filters are symmetric) on opposite sides of the edge (none lies on it: 0.3 = 3/10
        // is no ratio of two odd numbers), so exactly half the weight is covered: ½ up to the
        // rounding of the sums, n terms ≤ 1: within n·ε. The tent's samples reach the
        // neighbours' territory, [−2, 2]² in the scene, where the half-plane still holds.
        let s = half_plane(0.3, 0.0, 1);
        for n in [4u32, 16, 64, 256] {
            for filter in [Filter::Box, Filter::Tent] {
                let value = render(&s, n, Pattern::Regular, filter, 0).0.get(0, 0).x;
                assert!((value - 0.5).abs() <= n as Float * Float::EPSILON, "{filter:?}, {n}: {value}");
            }
        }
    }

    #[test]
    fn edge_error_falls_as_samples_grow() {
        // A 32 × 32 image of the half-plane y < 0.3x + 0.2: the pixels the edge crosses have the
        // exact coverage of `pixel_coverage`; a box-filtered pixel should show it. The RMS error
        // over those pixels, and the time, for 1, 4, 16 and 64 samples per pixel: the
        // speed/accuracy trade. The error must fall at every step for every pattern, and at 64
        // samples (8 × 8) be within 1/16: the regular grid's bound 1/(2·8) per pixel (see the
        // one-pixel test), which the jittered patterns' σ ≤ √16·½/64 = 0.031 also meets.
        let size = 32;
        let s = half_plane(0.3, 0.2, size);
        let mut edge_pixels = Vec::new();
        for py in 0..size {
            for px in 0..size {
                let f = pixel_coverage(0.3, 0.2, size, px, py);
                if 0.0 < f && f < 1.0 {
                    edge_pixels.push((px, py, f));
                }
            }
        }
        println!("{} edge pixels of {}", edge_pixels.len(), size * size);
        println!("{:<11} {:>4} {:>10} {:>10} {:>9}", "pattern", "spp", "RMS error", "max error", "time");
        for pattern in PATTERNS {
            let mut previous = f64::INFINITY;
            for spp in [1u32, 4, 16, 64] {
                let start = Instant::now();
                let (image, _) = render(&s, spp, pattern, Filter::Box, 11);
                let time = start.elapsed();
                let errors: Vec<f64> =
                    edge_pixels.iter().map(|&(x, y, f)| (f64::from(image.get(x, y).x) - f).abs()).collect();
                let rms = (errors.iter().map(|e| e * e).sum::<f64>() / errors.len() as f64).sqrt();
                let max = errors.iter().copied().fold(0.0, f64::max);
                println!(
                    "{:<11} {spp:>4} {rms:>10.5} {max:>10.5} {:>7.1}ms",
                    format!("{pattern:?}"),
                    time.as_secs_f64() * 1e3
                );
                assert!(rms < previous, "{pattern:?}: RMS {rms} at {spp} spp, not below {previous}");
                previous = rms;
            }
            assert!(previous <= 1.0 / 16.0, "{pattern:?}: RMS {previous} at 64 spp");
        }
    }
}
