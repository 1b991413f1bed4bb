//! Checks on this lecture's scene files (`scenes/*.toml`) rendered by the
//! whole tracer: they are small and hold what they are for, every render is
//! finite, the ray statistics show that only what a scene requires is
//! traced and that both stopping rules work, the recorded ray trees agree
//! with the tracer, and two pixels' trees are snapshots. Last, every MIT
//! 6.837 assignment-4 scene renders to finite pixels.

use std::path::{Path, PathBuf};

use l01_transforms::Camera;
use l04_quadrics_transforms::BruteForce;
use raylab::render::render_map;
use raylab::scene::{self, Shape};
use raylab::stats::{Counter, RayStats, measure};
use raylab::{Color, Float, Image, Scene, Vec3};

use crate::{RayKind, TraceSettings, World, render, render_scene, trace, trace_recorded};

const SCENES: [&str; 3] = ["whitted.toml", "whitted-no-shadows.toml", "facing-mirrors.toml"];

fn load(name: &str) -> Scene {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes")).join(name);
    scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

fn rendered(scene: &Scene, settings: &TraceSettings) -> (Image, RayStats) {
    render_scene(scene, settings).unwrap_or_else(|e| panic!("{e}"))
}

/// (reflection, refraction, shadow) rays of a render.
fn secondary(stats: &RayStats) -> [u64; 3] {
    [Counter::ReflectionRays, Counter::RefractionRays, Counter::ShadowRays].map(|c| stats.get(c))
}

/// The settings the tests vary: the default and one change of each knob.
fn variants() -> Vec<(&'static str, TraceSettings)> {
    let d = TraceSettings::default();
    vec![
        ("default", d),
        ("fresnel", TraceSettings { fresnel: true, ..d }),
        ("transmissive", TraceSettings { shadow_mode: l06_shadows::ShadowMode::Transmissive, ..d }),
        ("no shadows", TraceSettings { shadows: false, ..d }),
        ("depth 0", TraceSettings { max_depth: 0, ..d }),
        ("depth 12, no cut-off", TraceSettings { max_depth: 12, min_weight: 0.0, ..d }),
    ]
}

#[test]
fn every_scene_is_small_and_holds_what_it_is_for() {
    for name in SCENES {
        let s = load(name);
        assert!(s.width <= 200 && s.height <= 150, "{name}: {}×{}", s.width, s.height);
    }
    // Whitted: a mirror ball, a glass ball, and a checker of boxes of a second colour.
    let s = load("whitted.toml");
    let spheres: Vec<_> = s
        .objects
        .iter()
        .filter(|o| matches!(o.shape, Shape::Sphere { .. }))
        .map(|o| &s.materials[o.material])
        .collect();
    assert!(spheres.iter().any(|m| m.reflective.min_element() > 0.5 && m.transparent == Color::ZERO));
    assert!(spheres.iter().any(|m| m.transparent.min_element() > 0.5 && m.ior > 1.0));
    let tiles = s.objects.iter().filter(|o| matches!(o.shape, Shape::Box { .. })).count();
    assert!(tiles >= 16, "{tiles} tiles");
    assert!(s.lights.iter().all(|l| l.shadows));
    // The variant: the same scene but for the light's shadows.
    let mut shadowless = load("whitted-no-shadows.toml");
    assert!(shadowless.lights.iter().all(|l| !l.shadows));
    shadowless.lights.iter_mut().for_each(|l| l.shadows = true);
    assert_eq!(format!("{shadowless:?}"), format!("{s:?}"));
    // The deep one: two mirror walls whose inner faces x = ±2 face each other.
    let s = load("facing-mirrors.toml");
    let walls: Vec<(Vec3, Vec3)> = s
        .objects
        .iter()
        .filter(|o| s.materials[o.material].reflective.min_element() > 0.5)
        .map(|o| match o.shape {
            Shape::Box { min, max } => (min, max),
            ref other => panic!("a mirror {}", other.kind()),
        })
        .collect();
    assert_eq!(walls.len(), 2);
    assert_eq!((walls[0].1.x, walls[1].0.x), (-2.0, 2.0), "{walls:?}");
}

#[test]
fn every_render_is_finite_with_every_setting() {
    for name in SCENES {
        let s = load(name);
        for (what, settings) in variants() {
            let (image, stats) = rendered(&s, &settings);
            assert_eq!(image.non_finite(), None, "{name}, {what}");
            assert!(image.pixels.iter().all(|c| c.min_element() >= 0.0), "{name}, {what}: negative light");
            assert_eq!(stats.get(Counter::PrimaryRays), (s.width * s.height) as u64, "{name}, {what}");
        }
    }
}

#[test]
fn only_the_rays_a_scene_requires_are_traced() {
    let d = TraceSettings::default();
    let whitted = load("whitted.toml");
    let [reflection, refraction, shadow] = secondary(&rendered(&whitted, &d).1);
    assert!(reflection > 0 && refraction > 0 && shadow > 0);
    // A light without shadows, or shadows off: not one shadow ray, and the same tree.
    let [r, t, s] = secondary(&rendered(&load("whitted-no-shadows.toml"), &d).1);
    assert_eq!([r, t, s], [reflection, refraction, 0]);
    let off = TraceSettings { shadows: false, ..d };
    assert_eq!(secondary(&rendered(&whitted, &off).1), [reflection, refraction, 0]);
    // Without transparent materials: no refracted ray (and, as nothing sends weight
    // to the mirror by total internal reflection any more, fewer reflected ones).
    let mut opaque = whitted.clone();
    opaque.materials.iter_mut().for_each(|m| m.transparent = Color::ZERO);
    let [r, t, _] = secondary(&rendered(&opaque, &d).1);
    assert!(r > 0 && t == 0, "{r} reflected, {t} refracted");
    // Without reflective ones either: the eye rays and their shadow rays only.
    opaque.materials.iter_mut().for_each(|m| m.reflective = Color::ZERO);
    let [r, t, s] = secondary(&rendered(&opaque, &d).1);
    assert_eq!([r, t], [0, 0]);
    assert!(s > 0);
    // The mirrors of the deep scene: no glass, no refracted ray.
    assert_eq!(secondary(&rendered(&load("facing-mirrors.toml"), &d).1)[1], 0);
    // Depth 0: the eye rays alone spawn nothing.
    let flat = TraceSettings { max_depth: 0, ..d };
    assert_eq!(secondary(&rendered(&whitted, &flat).1)[..2], [0, 0]);
}

#[test]
fn raising_the_weight_cut_off_prunes_the_tree() {
    // A ray's weight is the product of the k maxima above it, whatever the cut-off: a
    // higher cut-off only removes subtrees. So every count falls weakly as it rises from
    // 10⁻⁴ to 0.1, and the total strictly somewhere (at 0.1 the glass ball's inner mirror
    // rays, 0.9·0.1 = 0.09, are gone; the corridor's k-th mirror ray, 0.9ᵏ, stops at k = 21
    // instead of 87). Depth 40, so that the weight is the rule that binds.
    for name in ["whitted.toml", "facing-mirrors.toml"] {
        let s = load(name);
        let counts: Vec<[u64; 3]> = [1e-4, 1e-3, 1e-2, 1e-1]
            .iter()
            .map(|&min_weight| {
                let settings = TraceSettings { max_depth: 40, min_weight, ..TraceSettings::default() };
                secondary(&rendered(&s, &settings).1)
            })
            .collect();
        println!("{name}: (reflected, refracted, shadow) rays at cut-offs 1e-4 … 1e-1: {counts:?}");
        for pair in counts.windows(2) {
            assert!((0..3).all(|k| pair[1][k] <= pair[0][k]), "{name}: {counts:?}");
        }
        let total = |c: &[u64; 3]| c.iter().sum::<u64>();
        assert!(total(&counts[3]) < total(&counts[0]), "{name}: {counts:?}");
    }
}

#[test]
fn no_pixel_of_the_corridor_bounces_more_than_max_depth_times() {
    // Only mirrors reflect in the deep scene and nothing refracts, so each pixel's tree
    // is a chain: at most max_depth reflected rays per pixel, and with no cut-off some
    // pixel (looking down the corridor) reaches the limit exactly.
    let s = load("facing-mirrors.toml");
    let camera = Camera::from_scene(&s.camera, s.width, s.height).unwrap();
    let objects = BruteForce::new(&s.objects);
    let world = World::new(&s, &objects);
    let mut previous = 0;
    for max_depth in [1, 3, 5, 8, 20] {
        let settings = TraceSettings { max_depth, min_weight: 0.0, ..TraceSettings::default() };
        let (per_pixel, _) = render_map(s.width, s.height, |x, y| {
            let ray = camera.pixel_ray(x, y, s.width, s.height);
            measure(|| trace(&world, &ray, 0, 1.0, &settings)).1.get(Counter::ReflectionRays)
        });
        let deepest = per_pixel.iter().copied().max().unwrap();
        let total: u64 = per_pixel.iter().sum();
        println!("max_depth {max_depth:2}: deepest chain {deepest}, {total} reflected rays");
        assert_eq!(deepest, max_depth as u64);
        assert!(total > previous, "max_depth {max_depth}: {total} ≤ {previous}");
        previous = total;
    }
}

#[test]
fn recorded_trees_agree_with_the_tracer() {
    // trace_recorded runs the tracer's own code: the same colour bit for bit, and its
    // tree holds exactly the rays that trace counts, no deeper than the depth limit.
    for name in ["whitted.toml", "facing-mirrors.toml"] {
        let s = load(name);
        let camera = Camera::from_scene(&s.camera, s.width, s.height).unwrap();
        let objects = BruteForce::new(&s.objects);
        let world = World::new(&s, &objects);
        for (what, settings) in variants() {
            for y in (0..s.height).step_by(7) {
                for x in (0..s.width).step_by(7) {
                    let ray = camera.pixel_ray(x, y, s.width, s.height);
                    let (color, stats) = measure(|| trace(&world, &ray, 0, 1.0, &settings));
                    let (recorded_color, tree) = trace_recorded(&world, &ray, &settings);
                    let at = format!("{name}, {what}, pixel ({x}, {y})");
                    assert_eq!(recorded_color, color, "{at}");
                    let kinds = [RayKind::Reflected, RayKind::Transmitted, RayKind::Shadow];
                    assert_eq!(kinds.map(|k| tree.count(k) as u64), secondary(&stats), "{at}");
                    assert_eq!((tree.kind, tree.count(RayKind::Eye)), (RayKind::Eye, 1), "{at}");
                    assert!(tree.depth() <= settings.max_depth, "{at}");
                }
            }
        }
    }
}

/// The recorded tree of pixel (x, y) of a scene, with its colour.
fn pixel_tree(scene: &Scene, x: u32, y: u32) -> (Color, String) {
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).unwrap();
    let objects = BruteForce::new(&scene.objects);
    let ray = camera.pixel_ray(x, y, scene.width, scene.height);
    let (color, tree) = trace_recorded(&World::new(scene, &objects), &ray, &TraceSettings::default());
    (color, tree.to_string())
}

#[test]
fn ray_tree_of_a_pixel_on_the_glass_ball() {
    // Objects: #0 the floor, #1 the chrome ball, #2 the glass ball, #3… the tiles. Read:
    // the eye ray hits the glass (its highlight casts a shadow ray, which sees the
    // light); k_r = 0.1 sends a mirror ray of weight 0.1 to the floor, k_t = 0.9 a
    // refracted ray into the ball. Inside, the far wall's shadow ray is blocked by the
    // ball itself (Opaque shadows), its mirror ray (0.9·0.1 = 0.09) crosses a chord as
    // long as the first (t = 1.399: reflection inside a sphere keeps the angle) and
    // leaves with 0.09·0.9 = 0.081 to the sky; its own mirror ray would weigh 0.009 <
    // 0.01 and is not spawned. The way out (0.81) lands on the floor beyond the
    // checker (z = −5.07 < −4), which sees the light.
    let (_, tree) = pixel_tree(&load("whitted.toml"), 150, 80);
    insta::assert_snapshot!(tree, @r"
    eye from (0.000, 2.200, 6.500) dir (0.238, -0.244, -0.940) weight 1.000: hits #2 at t = 5.554
      shadow from (1.321, 0.847, 1.278) dir (-0.596, 0.710, 0.375) weight 1.000: reaches the light
      reflected from (1.321, 0.847, 1.278) dir (0.961, -0.162, 0.224) weight 0.100: hits #0 at t = 5.339
        shadow from (6.453, -0.020, 2.472) dir (-0.836, 0.532, 0.135) weight 0.100: reaches the light
      transmitted from (1.321, 0.847, 1.278) dir (-0.061, -0.187, -0.980) weight 0.900: hits #2 at t = 1.399
        shadow from (1.236, 0.586, -0.094) dir (-0.529, 0.677, 0.512) weight 0.900: blocked by #2 at t = 1.356
        reflected from (1.236, 0.586, -0.094) dir (-0.796, 0.282, 0.536) weight 0.090: hits #2 at t = 1.399
          transmitted from (0.123, 0.980, 0.657) dir (-0.586, 0.282, 0.760) weight 0.081: misses
        transmitted from (1.236, 0.586, -0.094) dir (-0.354, -0.113, -0.928) weight 0.810: hits #0 at t = 5.365
          shadow from (-0.665, -0.020, -5.074) dir (-0.210, 0.541, 0.815) weight 0.810: reaches the light
    ");
}

#[test]
fn ray_tree_of_a_pixel_on_the_chrome_ball() {
    // The chrome ball (#1) at a point turned away from the light (no shadow ray) mirrors
    // a red tile (#12) that lies in the ball's own shadow: its shadow ray is blocked by
    // #1. Both are lit by the ambient light alone, so by hand
    // I = 0.05·0.1 + 0.8·(0.8, 0.1, 0.08)·0.1 = (0.069, 0.013, 0.0114). Tolerance 4ε:
    // three roundings of values below 0.1.
    let (color, tree) = pixel_tree(&load("whitted.toml"), 99, 70);
    approx::assert_abs_diff_eq!(color, Color::new(0.069, 0.013, 0.0114), epsilon = 4.0 * Float::EPSILON);
    insta::assert_snapshot!(tree, @r"
    eye from (0.000, 2.200, 6.500) dir (-0.002, -0.204, -0.979) weight 1.000: hits #1 at t = 7.521
      reflected from (-0.018, 0.669, -0.864) dir (0.463, -0.378, -0.801) weight 0.800: hits #12 at t = 1.769
        shadow from (0.801, 0.000, -2.282) dir (-0.401, 0.633, 0.662) weight 0.800: blocked by #1 at t = 1.782
    ");
}

/// The MIT 6.837 assignment-4 scenes in the shared data, or none (after a SKIPPED line).
fn mit_scenes() -> Vec<PathBuf> {
    let Some(dir) = raylab::data::shared_data("mit6837", "the MIT 6.837 assignment-4 scenes") else {
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("a readable folder")
        .map(|e| e.expect("a folder entry").path())
        .filter(|p| p.file_name().and_then(|n| n.to_str()).is_some_and(|n| n.starts_with("scene4_")))
        .collect();
    files.sort();
    files
}

fn file_name(path: &Path) -> String {
    path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default()
}

#[test]
fn every_6837_assignment_4_scene_renders_finite_at_100_by_100() {
    // 6.837's own tests of its ray tracer: shadows, coloured shadows, a mirrored floor, a
    // reflective sphere, transparent bars and spheres of η 1.0, 1.1 and 2.0, point lights
    // and a faceted gem (a mesh of index 2.4). Default settings, 100 × 100 pixels.
    let files = mit_scenes();
    for path in &files {
        let name = file_name(path);
        let s = scene::load(path).unwrap_or_else(|e| panic!("{e}"));
        let camera = Camera::from_scene(&s.camera, 100, 100).unwrap_or_else(|e| panic!("{name}: {e}"));
        let objects = BruteForce::new(&s.objects);
        let (image, stats) = render(&World::new(&s, &objects), &camera, 100, 100, &TraceSettings::default());
        assert_eq!(image.non_finite(), None, "{name}");
        println!("{name:45} {:?}", secondary(&stats));
    }
    if !files.is_empty() {
        assert_eq!(files.len(), 14, "the 14 scenes of assignment 4");
    }
}
