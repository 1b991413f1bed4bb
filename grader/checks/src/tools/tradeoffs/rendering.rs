//! The render sweeps: error (mean FLIP against a converged reference) against
//! time for samples per pixel, ray-tree depth and weight cut-off, and BVH
//! against brute force.

use l01_transforms::Camera;
use l04_quadrics_transforms::BruteForce;
use l08_ray_tree::{SurfaceMaterial, TraceSettings, World};
use l09_acceleration::Bvh;
use l10_textures_sampling::{Filter, Pattern, surface_material};
use raylab::stats::{Counter, RayStats};
use raylab::{Float, Image, Intersector, Scene};

use super::row::{Pair, Row, own_precision};
use super::timing::{Effort, Timing, time_per_item};
use crate::lectures::l10::tracer::{Sampling, render_scene, scene_settings};

/// The scene of the spp sweep: a checker receding to the horizon, the lecture's aliasing case.
pub const SPP_SCENE: &str = "lectures/10-textures-sampling/scenes/checker-aliasing-1spp.toml";
/// The scene of the depth and weight sweeps: every kind of ray of the ray tree.
pub const TREE_SCENE: &str = "lectures/08-ray-tree/scenes/whitted.toml";
/// The scenes of the BVH pair, each with the divisor of its size (brute force
/// on 65 536 triangles costs 13 ms a pixel, measured in release: the torus is
/// rendered at 10×7).
pub const BVH_SCENES: [(&str, u32); 2] = [
    ("lectures/09-acceleration/scenes/many-spheres.toml", 1),
    ("lectures/09-acceleration/scenes/torus-65k.toml", 20),
];

/// The reference of the tree sweeps: deep enough that no branch a pixel can show is cut.
pub const REFERENCE_DEPTH: u32 = 16;

/// The weight cut-offs of the weight sweep.
pub const WEIGHTS: [Float; 7] = [0.1, 0.03, 0.01, 0.003, 0.001, 3e-4, 1e-4];

/// The name of the error column of the sweeps.
pub const FLIP: &str = "mean FLIP";

/// A lecture scene (path relative to the workspace), at 1/`divisor` of its size.
pub fn load_scene(relative: &str, divisor: u32) -> Result<Scene, String> {
    let path = crate::scenes::workspace_root().join(relative);
    let mut scene = raylab::scene::load(&path).map_err(|e| e.to_string())?;
    scene.width = (scene.width / divisor.max(1)).max(1);
    scene.height = (scene.height / divisor.max(1)).max(1);
    Ok(scene)
}

/// The mean of FLIP's per-pixel error between `reference` and `test` (same size), on their 8-bit
/// sRGB values at nv-flip's default viewing distance (0 identical, 1 opposite). A NaN pixel is
/// shown as magenta, as the grader's image checks do.
pub fn mean_flip(reference: &Image, test: &Image) -> f64 {
    use raylab_checks_core::images::picture::{flip_error, shown};
    let values = flip_error(&shown(reference), &shown(test)).to_vec();
    values.iter().map(|&v| f64::from(v)).sum::<f64>() / values.len().max(1) as f64
}

/// Timed runs of a render: the minimum the report allows (each render lasts long enough alone).
pub const RENDER_RUNS: usize = 5;

/// Renders with `render` [`RENDER_RUNS`] times after one untimed render: the last image, its
/// statistics and the time in ms per render.
fn timed_render(
    effort: &Effort,
    mut render: impl FnMut() -> Result<(Image, RayStats), String>,
) -> Result<(Image, RayStats, Timing), String> {
    let renders = Effort { runs: RENDER_RUNS, min_batch: std::time::Duration::ZERO, ..*effort };
    let mut last = Err(String::from("no render"));
    let time = time_per_item(&renders, 1, || last = render());
    let (image, stats) = last?;
    Ok((image, stats, time.scaled(1e-6)))
}

fn row(pair: Pair, case: &str, variant: String, time: Timing, metrics: Vec<(String, f64)>) -> Row {
    Row {
        pair,
        case: case.to_string(),
        variant,
        precision: own_precision().to_string(),
        time,
        metrics,
        fails: false,
        pareto: false,
    }
}

/// Samples per pixel 1, 2, 4, … `effort.max_spp` (one at the pixel centre, then jittered, box
/// filter) against `effort.reference_spp` jittered samples.
pub fn measure_spp(effort: &Effort) -> Result<Vec<Row>, String> {
    let scene = load_scene(SPP_SCENE, effort.image_divisor)?;
    let settings = scene_settings(&scene);
    let sampling = |spp: u32| Sampling {
        spp,
        pattern: if spp == 1 { Pattern::Regular } else { Pattern::Jittered },
        filter: Filter::Box,
    };
    let (reference, _) = render_scene(&scene, None, &settings, sampling(effort.reference_spp))?;
    let case = format!("checker, {}×{}, reference {} spp", scene.width, scene.height, effort.reference_spp);
    let mut rows = Vec::new();
    let mut spp = 1;
    while spp <= effort.max_spp {
        let (image, _, time) = timed_render(effort, || render_scene(&scene, None, &settings, sampling(spp)))?;
        let label = if spp == 1 { "spp 1 (centre)".to_string() } else { format!("spp {spp}") };
        rows.push(row(Pair::Spp, &case, label, time, vec![(FLIP.into(), mean_flip(&reference, &image))]));
        spp *= 2;
    }
    Ok(rows)
}

/// Ray-tree depth 1–10 (weight cut-off 0) and weight cut-offs 0.1–10⁻⁴ (depth 16) on the
/// Whitted scene, against depth 16 with weight 0.
pub fn measure_tree(effort: &Effort) -> Result<Vec<Row>, String> {
    let scene = load_scene(TREE_SCENE, effort.image_divisor)?;
    let base = scene_settings(&scene);
    let one_ray = Sampling { spp: 1, pattern: Pattern::Regular, filter: Filter::Box };
    let with = |max_depth: u32, min_weight: Float| TraceSettings { max_depth, min_weight, ..base };
    let (reference, _) = render_scene(&scene, None, &with(REFERENCE_DEPTH, 0.0), one_ray)?;
    let case =
        format!("whitted, {}×{}, reference depth {REFERENCE_DEPTH} weight 0", scene.width, scene.height);
    let mut rows = Vec::new();
    let mut sweep = |pair: Pair, variant: String, settings: TraceSettings| -> Result<(), String> {
        let (image, stats, time) = timed_render(effort, || render_scene(&scene, None, &settings, one_ray))?;
        let rays_per_pixel = stats.total_rays() as f64 / (scene.width * scene.height) as f64;
        let metrics =
            vec![(FLIP.into(), mean_flip(&reference, &image)), ("rays/pixel".into(), rays_per_pixel)];
        rows.push(row(pair, &case, variant, time, metrics));
        Ok(())
    };
    for depth in 1..=10 {
        sweep(Pair::Depth, format!("depth {depth}"), with(depth, 0.0))?;
    }
    for weight in WEIGHTS {
        sweep(Pair::Weight, format!("weight {weight}"), with(REFERENCE_DEPTH, weight))?;
    }
    Ok(rows)
}

/// `scene` traced once per pixel centre through `objects`, with its own settings.
fn render_through(scene: &Scene, objects: &dyn Intersector) -> Result<(Image, RayStats), String> {
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).map_err(|e| e.to_string())?;
    let surface: SurfaceMaterial = &|hit, material| surface_material(scene, hit, material);
    let world = World::new(scene, objects).with_surface(surface);
    Ok(l08_ray_tree::render(&world, &camera, scene.width, scene.height, &scene_settings(scene)))
}

/// Lecture 09's BVH (built inside every timed run) against lecture 04's brute force on the
/// lecture's big scenes: time, pixels that differ, and intersection tests per ray.
pub fn measure_bvh(effort: &Effort) -> Result<Vec<Row>, String> {
    let mut rows = Vec::new();
    for (relative, divisor) in BVH_SCENES {
        let scene = load_scene(relative, divisor * effort.image_divisor)?;
        let name = relative.rsplit('/').next().unwrap_or(relative).trim_end_matches(".toml");
        let case = format!("{name}, {}×{}", scene.width, scene.height);
        let (with_bvh, bvh_stats, bvh_time) =
            timed_render(effort, || render_through(&scene, &Bvh::build(&scene.objects)))?;
        let (brute, brute_stats, brute_time) =
            timed_render(effort, || render_through(&scene, &BruteForce::new(&scene.objects)))?;
        for (variant, image, stats, time) in
            [("bvh", &with_bvh, bvh_stats, bvh_time), ("brute_force", &brute, brute_stats, brute_time)]
        {
            let differing = image.pixels.iter().zip(&with_bvh.pixels).filter(|(a, b)| a != b).count();
            let tests = stats.get(Counter::IntersectionTests) as f64 / stats.total_rays().max(1) as f64;
            let metrics = vec![("pixels differing".into(), differing as f64), ("tests/ray".into(), tests)];
            let mut r = row(Pair::Bvh, &case, variant.to_string(), time, metrics);
            r.fails = differing > 0;
            rows.push(r);
        }
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Color;

    #[test]
    fn flip_is_zero_for_equal_images_and_grows_with_the_difference() {
        let grey = Image::filled(16, 16, Color::splat(0.5));
        assert_eq!(mean_flip(&grey, &grey), 0.0);
        let mut one_pixel = grey.clone();
        one_pixel.set(3, 4, Color::ONE);
        let white = Image::filled(16, 16, Color::ONE);
        let (small, large) = (mean_flip(&grey, &one_pixel), mean_flip(&grey, &white));
        assert!(0.0 < small && small < large && large <= 1.0, "{small} {large}");
    }
}
