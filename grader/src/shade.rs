//! The tracer assembled from every lecture: cameras (01), intersections
//! (02–04), the Whitted tracer of lecture 08 with the shading, shadows,
//! reflection and refraction of lectures 05–07, lecture 09's BVH where the
//! scene has enough primitives to need one, and lecture 10's textures.

use l01_transforms::Camera;
use l06_shadows::ShadowMode;
use l08_ray_tree::{RayTree, TraceSettings, World, trace_recorded};
use l10_textures_sampling::surface_color;
use raylab::scene::Material;
use raylab::stats::{RayStats, measure};
use raylab::{Color, Hit, Image, Scene};

use crate::Aov;

/// The tracer's settings for `scene`: what its `[render]` table says, and
/// [`TraceSettings::default`] for what it does not (6.837 files say nothing).
pub fn scene_settings(scene: &Scene) -> TraceSettings {
    let (own, default) = (scene.render, TraceSettings::default());
    TraceSettings {
        max_depth: own.max_depth.unwrap_or(default.max_depth),
        min_weight: own.min_weight.unwrap_or(default.min_weight),
        shadow_mode: match own.transparent_shadows {
            Some(true) => ShadowMode::Transmissive,
            Some(false) => ShadowMode::Opaque,
            None => default.shadow_mode,
        },
        area_samples: own.area_samples.unwrap_or(default.area_samples),
        ..default
    }
}

/// Renders `scene` at its size: the traced image, or the AOV asked for.
pub fn render_scene(
    scene: &Scene,
    aov: Option<Aov>,
    settings: &TraceSettings,
) -> Result<(Image, RayStats), String> {
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).map_err(|e| e.to_string())?;
    let objects = l09_acceleration::intersector_for(&scene.objects);
    let objects = objects.as_ref();
    let (w, h) = (scene.width, scene.height);
    Ok(match aov {
        Some(Aov::Id) => measure(|| l02_ray_casting::object_id_image(&camera, &objects, w, h)),
        Some(Aov::Depth) => measure(|| l02_ray_casting::depth_image(&camera, &objects, w, h)),
        Some(Aov::Normal) => measure(|| l02_ray_casting::normal_image(&camera, &objects, w, h)),
        None => {
            let surface = |hit: &Hit, material: &Material| surface_color(scene, hit, material);
            l08_ray_tree::render(&World::new(scene, objects).with_surface(&surface), &camera, w, h, settings)
        }
    })
}

/// The ray tree of pixel (x, y) of `scene`, and the pixel's colour.
pub fn pixel_tree(
    scene: &Scene,
    (x, y): (u32, u32),
    settings: &TraceSettings,
) -> Result<(Color, RayTree), String> {
    if x >= scene.width || y >= scene.height {
        return Err(format!("pixel ({x}, {y}) is outside the {}×{} image", scene.width, scene.height));
    }
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).map_err(|e| e.to_string())?;
    let objects = l09_acceleration::intersector_for(&scene.objects);
    let ray = camera.pixel_ray(x, y, scene.width, scene.height);
    let surface = |hit: &Hit, material: &Material| surface_color(scene, hit, material);
    Ok(trace_recorded(&World::new(scene, objects.as_ref()).with_surface(&surface), &ray, settings))
}
