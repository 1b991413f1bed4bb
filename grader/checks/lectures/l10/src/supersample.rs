//! The checks of `supersample.rs`: render_supersampled.

use super::common::*;

/// The white half-plane y < slope·x + intercept in a 1 × 1 image: one pixel of 2 × 2 units.
pub(super) fn half_plane(slope: Float, intercept: Float) -> Scene {
    raylab_testing::scenes::half_plane(slope, intercept, 1)
}

/// Two lit spheres over a floor, 12 × 8, seen in perspective.
pub(super) fn spheres() -> Scene {
    raylab_testing::scenes::two_spheres(12, 8)
}

/// `render` of `s` at its own size through its own camera, brute force, default settings.
pub(super) fn rendered(
    render: SupersampleFn,
    s: &Scene,
    spp: u32,
    pattern: Pattern,
    filter: Filter,
    seed: u64,
) -> (Image, RayStats) {
    // The camera (01's look_at) and the render: the student's code, one value.
    crate::judge::student(|| {
        let camera =
            Camera::from_scene(&s.camera, s.width, s.height).expect("the check scenes have valid cameras");
        let objects = BruteForce::new(&s.objects);
        let world = World::new(s, &objects);
        render(&world, &camera, s.width, s.height, &TraceSettings::default(), spp, pattern, filter, seed)
    })
}

/// The value a pixel of [`half_plane`] takes with the k × k regular samples and `filter`,
/// computed here: offset d = (2u − 1)·r in pixels (r = ½ for the box, 1 for the tent), the sample at world (2dₓ, −2d_y) (the
/// pixel is 2 units wide, y up in the world and down in pixels), covered when
/// y < slope·x + intercept, weighted by the filter written out again (in f64).
pub(super) fn expected_coverage(k: u32, filter: Filter, r: f64, slope: f64, intercept: f64) -> (f64, f64) {
    let (mut covered, mut total, mut largest) = (0.0, 0.0, 0.0f64);
    for j in 0..k {
        for i in 0..k {
            let u = ((f64::from(i) + 0.5) / f64::from(k), (f64::from(j) + 0.5) / f64::from(k));
            let d = ((2.0 * u.0 - 1.0) * r, (2.0 * u.1 - 1.0) * r);
            let w = match filter {
                Filter::Box => f64::from(u8::from((-0.5..0.5).contains(&d.0) && (-0.5..0.5).contains(&d.1))),
                Filter::Tent => (1.0 - d.0.abs()).max(0.0) * (1.0 - d.1.abs()).max(0.0),
            };
            let (x, y) = (2.0 * d.0, -2.0 * d.1);
            if y < slope * x + intercept {
                covered += w;
            }
            total += w;
            largest = largest.max(w);
        }
    }
    (covered / total, largest / total)
}

pub(super) fn supersampling_cases(render: SupersampleFn) -> CheckResult {
    // One regular sample: the pixel centre (d = 0), weight 1: 08's render bit for bit.
    let s = spheres();
    // Lecture 08's picture, the student's too.
    let expected = crate::judge::student(|| {
        let camera = Camera::from_scene(&s.camera, s.width, s.height).expect("a valid camera");
        let objects = BruteForce::new(&s.objects);
        let world = World::new(&s, &objects);
        l08_ray_tree::render(&world, &camera, s.width, s.height, &TraceSettings::default()).0
    });
    for filter in [Filter::Box, Filter::Tent] {
        let (image, stats) = rendered(render, &s, 1, Pattern::Regular, filter, 5);
        let case = format!("two spheres over a floor, 12 × 8, 1 regular sample per pixel, {filter:?} filter");
        if let Some(k) =
            (0..expected.pixels.len()).find(|&k| image.pixels.get(k) != Some(&expected.pixels[k]))
        {
            let (x, y) = (k as u32 % s.width, k as u32 / s.width);
            let got = image.pixels.get(k).map_or("no such pixel".to_owned(), |c| vec3(*c));
            return Err(fail(
                format!("{case}: pixel ({x}, {y})"),
                vec3(expected.pixels[k]),
                got,
                "one regular sample is at the pixel centre, d = (2u − 1)·r = 0, through the screen point \
                 sx = (2(x + ½ + dₓ) − w)/w, sy = (h − 2(y + ½ + d_y))/h, traced at depth 0, weight 1: 08's \
                 render exactly",
            ));
        }
        let primary = stats.get(Counter::PrimaryRays);
        ensure(
            primary == u64::from(s.width * s.height),
            &case,
            format!("{} primary rays", s.width * s.height),
            primary,
            "count one Counter::PrimaryRays per sample",
        )?;
    }
    // Rays: 12 × 8 pixels × 9 samples; spp = 0 is taken as 1.
    for (spp, rays) in [(9u32, 96 * 9), (0, 96)] {
        let (image, stats) = rendered(render, &s, spp, Pattern::Jittered, Filter::Box, 1);
        let primary = stats.get(Counter::PrimaryRays);
        let cause = if spp == 0 {
            "spp = 0 is taken as 1: one sample per pixel"
        } else {
            "count one Counter::PrimaryRays per sample: spp eye rays per pixel"
        };
        ensure(
            primary == rays && image.non_finite().is_none(),
            format!("two spheres over a floor, 12 × 8, {spp} jittered samples per pixel"),
            format!("{rays} primary rays, finite pixels"),
            format!(
                "{primary} primary rays{}",
                if image.non_finite().is_some() { ", NaN pixels" } else { "" }
            ),
            cause,
        )?;
    }
    // The same seed gives the same image.
    let a = rendered(render, &s, 4, Pattern::Stratified, Filter::Tent, 42);
    let b = rendered(render, &s, 4, Pattern::Stratified, Filter::Tent, 42);
    ensure(
        a.0 == b.0,
        "two spheres over a floor, 4 multi-jittered samples, seed 42, rendered twice",
        "the same image",
        "different images",
        "each pixel draws from its own pixel_rng(seed, x, y), never from a shared stream",
    )?;
    // One pixel under the edge y = 0.3x + 0.2 (world units, the pixel is [−1, 1]²), 32 × 32
    // regular samples: the box and the tent weighted coverage, computed here sample by
    // sample. A sample within rounding of the edge may fall either way: one sample's weight
    // over the total, plus a margin of 10⁻⁴ for the sums.
    for filter in [Filter::Box, Filter::Tent] {
        let radius = if filter == Filter::Box { 0.5 } else { 1.0 };
        let (expected, one) = expected_coverage(32, filter, radius, 0.3, 0.2);
        let tolerance = one + 1e-4;
        let (image, _) = rendered(render, &half_plane(0.3, 0.2), 1024, Pattern::Regular, filter, 7);
        let got = image.get(0, 0).x as f64;
        let case = format!(
            "one pixel (the square [−1, 1]²) under the edge y = 0.3x + 0.2, 32 × 32 regular samples, {filter:?} filter"
        );
        let cause = if filter == Filter::Tent && (got - expected / 4.0).abs() <= 0.05 {
            "divide by the sum of the weights Σ w(dₖ), not by the number of samples"
        } else if filter == Filter::Tent
            && (got - expected_coverage(32, filter, 0.5, 0.3, 0.2).0).abs() <= tolerance
        {
            "weight each sample by filter_weight(filter, d) and spread the samples over the filter's support, \
             d = (2u − 1)·filter.radius()"
        } else {
            "the samples cover [−r, r)² around the centre, d = (2u − 1)·r, r = filter.radius(); the pixel is \
             Σ w(dₖ)·cₖ / Σ w(dₖ)"
        };
        ensure(
            (got - expected).abs() <= tolerance,
            case,
            format!("{expected:.5} (± {tolerance:.1e})"),
            format!("{got:.5}"),
            cause,
        )?;
    }
    Ok("1-sample renders as 08's, ray counts, a repeatable seed, box and tent coverage".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l01_transforms::Camera;
    use l08_ray_tree::{TraceSettings, World, trace};
    use l10_textures_sampling::{Filter, Pattern, pixel_rng, sample_offsets};

    use raylab::render::render_image;
    use raylab::stats::{Counter, RayStats, count};
    use raylab::{BLACK, Float, Image, Vec2};

    /// The slips planted in the reference supersampler.
    #[derive(Clone, Copy, PartialEq, Eq)]
    enum SupersampleSlip {
        /// Divided by the number of samples, not the sum of the weights.
        ByCount,
        /// The offsets not spread over the filter's radius (d = u − ½ for every filter).
        Unspread,
        /// Primary rays not counted.
        Uncounted,
    }

    /// The reference supersampler with a slip.
    #[allow(clippy::too_many_arguments)]
    fn supersample(
        slip: SupersampleSlip,
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
        let (w, h) = (width as Float, height as Float);
        render_image(width, height, |x, y| {
            let offsets = sample_offsets(pattern, spp.max(1), &mut pixel_rng(seed, x, y));
            let (mut weighted, mut total) = (BLACK, 0.0);
            for u in &offsets {
                let radius = if slip == SupersampleSlip::Unspread { 0.5 } else { filter.radius() };
                let d = (2.0 * *u - Vec2::ONE) * radius;
                let sx = (2.0 * (x as Float + 0.5 + d.x) - w) / w;
                let sy = (h - 2.0 * (y as Float + 0.5 + d.y)) / h;
                if slip != SupersampleSlip::Uncounted {
                    count(Counter::PrimaryRays);
                }
                let c = trace(world, &camera.generate_ray(sx, sy), 0, 1.0, settings);
                let weight = l10_textures_sampling::filter_weight(filter, d);
                weighted += weight * c;
                total += weight;
            }
            if slip == SupersampleSlip::ByCount {
                weighted / offsets.len() as Float
            } else {
                weighted / total
            }
        })
    }

    macro_rules! supersample_slips {
        ($($name:ident => $slip:expr),* $(,)?) => {
            $(#[allow(clippy::too_many_arguments)]
            fn $name(
                world: &World, camera: &Camera, w: u32, h: u32, s: &TraceSettings,
                spp: u32, pattern: Pattern, filter: Filter, seed: u64,
            ) -> (Image, RayStats) {
                supersample($slip, world, camera, w, h, s, spp, pattern, filter, seed)
            })*
        };
    }

    supersample_slips! {
        by_count => SupersampleSlip::ByCount,
        unspread => SupersampleSlip::Unspread,
        uncounted => SupersampleSlip::Uncounted,
    }

    #[test]
    fn planted_supersampling_mistakes_are_caught() {
        caught(supersampling_cases(by_count), "sum of the weights");
        caught(supersampling_cases(unspread), "filter's support");
        caught(supersampling_cases(uncounted), "per sample");
    }
}
