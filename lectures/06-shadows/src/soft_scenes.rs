//! Checks on this lecture's soft-shadow scenes (`scenes/soft-shadows-*.toml`):
//! the four rect-light files differ only in their sample count, each shows an
//! umbra, a penumbra and full light, renders are the same on every run and
//! for every number of threads, and the noise of the penumbra falls as the
//! samples grow.

use std::ops::Range;

use l01_transforms::Camera;
use l04_quadrics_transforms::BruteForce;
use raylab::render::render_map;
use raylab::scene::{LightKind, Scene, Shape};
use raylab::stats::{Counter, measure};
use raylab::{Color, Image, Intersector};

use crate::scenes::{load, render};
use crate::{ShadowMode, ShadowSettings, Surface, shade_with_shadows};

/// The rect-light scenes and their sample counts.
const RECT: [(&str, u32); 4] = [
    ("soft-shadows-1.toml", 1),
    ("soft-shadows-4.toml", 4),
    ("soft-shadows-16.toml", 16),
    ("soft-shadows-64.toml", 64),
];

const SPHERE: &str = "soft-shadows-sphere.toml";

/// The settings a scene asks for: its `area_samples` (16 if it says none), opaque blockers.
fn own_settings(scene: &Scene) -> ShadowSettings {
    ShadowSettings { mode: ShadowMode::Opaque, area_samples: scene.render.area_samples.unwrap_or(16) }
}

/// The pixels of `rows` shaded with `settings`, each with the index of the object it shows;
/// with `blockers` false the shadow rays see nothing (every light unshadowed, with the very
/// same samples, since they are seeded by the point).
fn shade_rows(
    scene: &Scene,
    settings: ShadowSettings,
    blockers: bool,
    rows: Range<u32>,
) -> Vec<(Color, usize)> {
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).expect("a valid camera");
    let shapes = BruteForce::new(&scene.objects);
    let shadows = if blockers { shapes } else { BruteForce::new(&[]) };
    let (w, h) = (scene.width, scene.height);
    let (pixels, _) = render_map(w, rows.end - rows.start, |x, y| {
        let ray = camera.pixel_ray(x, rows.start + y, w, h);
        let Some(hit) = shapes.closest_hit(&ray, camera.t_range()) else {
            return (scene.background, usize::MAX);
        };
        let material = &scene.materials[hit.material];
        let v = -ray.dir.normalize();
        let surface = Surface { material, diffuse: material.diffuse, hit, v, origin: ray.origin };
        let color =
            shade_with_shadows(&shadows, &scene.materials, &surface, &scene.lights, scene.ambient, settings);
        (color, hit.object)
    });
    pixels
}

/// How much of the light reaches each floor pixel (object 0): (shaded − ambient) over the
/// same without blockers; `None` off the floor.
fn floor_visibility(scene: &Scene, settings: ShadowSettings) -> Vec<Option<f64>> {
    let all = 0..scene.height;
    let shadowed = shade_rows(scene, settings, true, all.clone());
    let open = shade_rows(scene, settings, false, all);
    let floor = scene.materials[scene.objects[0].material].diffuse;
    let ambient = f64::from((floor * scene.ambient).x);
    shadowed
        .iter()
        .zip(&open)
        .map(|(&(s, object), &(o, _))| {
            (object == 0).then(|| (f64::from(s.x) - ambient) / (f64::from(o.x) - ambient))
        })
        .collect()
}

#[test]
fn every_soft_scene_is_small_and_made_of_spheres_planes_and_boxes() {
    // The shapes of this lecture's other scenes (convex, as `scenes.rs` needs for its exact
    // answer), at most 200 × 150 so that a test renders them in well under a second.
    for name in RECT.map(|(name, _)| name).into_iter().chain([SPHERE]) {
        let scene = load(name);
        assert!(scene.width <= 200 && scene.height <= 150, "{name}");
        for object in &scene.objects {
            let simple =
                matches!(object.shape, Shape::Sphere { .. } | Shape::Plane { .. } | Shape::Box { .. });
            assert!(simple && object.transform.is_none(), "{name}: {object:?}");
        }
    }
}

#[test]
fn the_rect_scenes_differ_only_in_their_sample_count() {
    // Each file says its N; with that cleared, all four are the same scene. One rect light
    // casting shadows over a floor (object 0) and a ball.
    let first = load(RECT[0].0);
    assert!(matches!(
        first.lights[..],
        [raylab::scene::Light { shadows: true, kind: LightKind::Rect { .. }, .. }]
    ));
    for (name, n) in RECT {
        let mut scene = load(name);
        assert_eq!(scene.render.area_samples, Some(n), "{name}");
        scene.render.area_samples = first.render.area_samples;
        assert_eq!(format!("{scene:?}"), format!("{first:?}"), "{name}");
    }
    let sphere = load(SPHERE);
    assert!(matches!(sphere.lights[0].kind, LightKind::Sphere { .. }) && sphere.lights[0].shadows);
}

#[test]
fn each_scene_shows_umbra_penumbra_and_full_light() {
    // On the floor, with the scene's own samples: the umbra sees none of the light (every
    // sample blocked: exactly 0), full light all of it (exactly 1: the same samples, all
    // seen), and the penumbra some. Each at least 100 pixels, for every scene but the
    // one-sample one, which has no penumbra at all: a sample is seen or not.
    for name in RECT.map(|(name, _)| name).into_iter().chain([SPHERE]) {
        let scene = load(name);
        let settings = own_settings(&scene);
        let seen = floor_visibility(&scene, settings);
        let count = |keep: fn(f64) -> bool| seen.iter().flatten().filter(|&&f| keep(f)).count();
        let (umbra, full) = (count(|f| f == 0.0), count(|f| f == 1.0));
        let penumbra = count(|f| f > 0.0 && f < 1.0);
        println!("{name:26} umbra {umbra:5}, penumbra {penumbra:5}, full light {full:5} floor pixels");
        assert!(umbra >= 100 && full >= 100, "{name}");
        if settings.area_samples == 1 {
            assert_eq!(penumbra, 0, "{name}");
        } else {
            assert!(penumbra >= 100, "{name}");
        }
        assert!(seen.iter().flatten().all(|f| (0.0..=1.0).contains(f)), "{name}");
    }
}

#[test]
fn renders_are_finite_and_cast_n_shadow_rays_per_floor_pixel() {
    // The floor faces every point of each light (all above it) and is grey, so each floor
    // pixel casts exactly N shadow rays; the other objects' pixels at most N.
    for name in RECT.map(|(name, _)| name).into_iter().chain([SPHERE]) {
        let scene = load(name);
        let settings = own_settings(&scene);
        let (image, rays) = render(&scene, settings);
        assert_eq!(image.non_finite(), None, "{name}");
        let objects = shade_rows(&scene, settings, true, 0..scene.height);
        let floor = objects.iter().filter(|(_, o)| *o == 0).count() as u64;
        let others = objects.iter().filter(|(_, o)| *o != 0 && *o != usize::MAX).count() as u64;
        let n = u64::from(settings.area_samples);
        assert!(rays >= n * floor && rays <= n * (floor + others), "{name}: {rays} rays");
    }
}

#[test]
fn a_render_is_the_same_twice_and_on_any_number_of_threads() {
    // Samples are seeded by the shaded point, never by a shared stream: the same pixels, bit
    // for bit, rendered twice on the default pool and once on a one-thread pool.
    for name in ["soft-shadows-16.toml", SPHERE] {
        let scene = load(name);
        let settings = own_settings(&scene);
        let (first, _) = render(&scene, settings);
        let (second, _) = render(&scene, settings);
        let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("a one-thread pool");
        let (single, _): (Image, u64) = pool.install(|| render(&scene, settings));
        assert!(first == second, "{name}: two renders differ");
        assert!(first == single, "{name}: one thread renders differently");
    }
}

#[test]
fn the_noise_of_the_penumbra_falls_as_the_samples_grow() {
    // The row of soft-shadows-64 with the most penumbra pixels, rendered with 1, 4, 16 and 64
    // samples, against a 1024-sample reference: the RMS error (linear, over the row's
    // pixels and channels) must fall at each step. Expected roughly ∝ n^(−3/4) for an edge
    // (stratified), i.e. ÷2.8 per step; asserted only to fall.
    let scene = load("soft-shadows-64.toml");
    let seen = floor_visibility(&scene, own_settings(&scene));
    let width = scene.width as usize;
    let penumbra_in =
        |y: usize| seen[y * width..(y + 1) * width].iter().flatten().filter(|&&f| f > 0.0 && f < 1.0).count();
    let row = (0..scene.height as usize).max_by_key(|&y| penumbra_in(y)).unwrap() as u32;
    assert!(penumbra_in(row as usize) >= 20, "row {row}: {} penumbra pixels", penumbra_in(row as usize));
    let settings = |n| ShadowSettings { mode: ShadowMode::Opaque, area_samples: n };
    let reference = shade_rows(&scene, settings(1024), true, row..row + 1);
    let mut errors = Vec::new();
    for n in [1, 4, 16, 64] {
        let (pixels, stats) = measure(|| shade_rows(&scene, settings(n), true, row..row + 1));
        let sum_sq: f64 =
            pixels.iter().zip(&reference).map(|((c, _), (r, _))| f64::from((*c - *r).length_squared())).sum();
        let rms = (sum_sq / (3 * pixels.len()) as f64).sqrt();
        println!(
            "row {row}: {n:2} samples, RMS error {rms:.5} against 1024, {} shadow rays",
            stats.get(Counter::ShadowRays)
        );
        errors.push(rms);
    }
    assert!(errors.windows(2).all(|w| w[1] < w[0]), "RMS errors {errors:?}");
}
