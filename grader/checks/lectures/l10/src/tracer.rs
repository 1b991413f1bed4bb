//! The tracer assembled from every lecture: cameras (01), intersections
//! (02–04), the Whitted tracer of lecture 08 with the shading, shadows,
//! reflection and refraction of lectures 05–07, lecture 09's BVH where the
//! scene has enough primitives to need one, and lecture 10's textures.

use l01_transforms::Camera;
use l08_ray_tree::{RayTree, SurfaceMaterial, TraceSettings, World, trace_recorded};
use l10_textures_sampling::{Filter, Pattern, render_supersampled, surface_material};
use raylab::stats::{RayStats, measure};
use raylab::{Color, Image, Scene};

/// Arbitrary output variables.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Aov {
    /// The object-id image (scene signature), a colour PNG.
    Id,
    /// Distance from the eye along the unit primary ray, 0 where nothing is hit (float EXR).
    Depth,
    /// Unit normal facing the camera, 0 where nothing is hit (float EXR).
    Normal,
}

pub use raylab_checks_l08::stage::scene_settings;

/// How many eye rays each pixel gets, where, and how they are weighted
/// (lecture 10). One ray is the pixel centre, as lecture 08 renders.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sampling {
    pub spp: u32,
    pub pattern: Pattern,
    pub filter: Filter,
}

/// The sampling `scene` asks for: its `[render]` `spp` (default 1), jittered
/// and box-filtered when there is more than one ray.
pub fn scene_sampling(scene: &Scene) -> Sampling {
    let spp = scene.render.samples_per_pixel.unwrap_or(1);
    Sampling { spp, pattern: if spp > 1 { Pattern::Jittered } else { Pattern::Regular }, filter: Filter::Box }
}

/// The seed of every supersampled render: the same image on every run.
pub const SAMPLING_SEED: u64 = 0x5eed;

/// Renders `scene` at its size: the traced image, or the AOV asked for.
pub fn render_scene(
    scene: &Scene,
    aov: Option<Aov>,
    settings: &TraceSettings,
    sampling: Sampling,
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
            let surface: SurfaceMaterial = &|hit, material| surface_material(scene, hit, material);
            let world = World::new(scene, objects).with_surface(surface);
            if sampling.spp == 1 && sampling.pattern == Pattern::Regular {
                l08_ray_tree::render(&world, &camera, w, h, settings)
            } else {
                let Sampling { spp, pattern, filter } = sampling;
                render_supersampled(&world, &camera, w, h, settings, spp, pattern, filter, SAMPLING_SEED)
            }
        }
    })
}

/// The ray tree of pixel (x, y) of `scene`, and the pixel's colour.
pub fn pixel_tree(
    scene: &Scene,
    pixel: (u32, u32),
    settings: &TraceSettings,
) -> Result<(Color, RayTree), String> {
    pixel_trees(scene, &[pixel], settings)?.pop().ok_or_else(|| "no pixel".to_owned())
}

/// [`pixel_tree`] of each of `pixels`, the scene's hierarchy built once.
pub fn pixel_trees(
    scene: &Scene,
    pixels: &[(u32, u32)],
    settings: &TraceSettings,
) -> Result<Vec<(Color, RayTree)>, String> {
    if let Some((x, y)) = pixels.iter().find(|(x, y)| *x >= scene.width || *y >= scene.height) {
        return Err(format!("pixel ({x}, {y}) is outside the {}×{} image", scene.width, scene.height));
    }
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).map_err(|e| e.to_string())?;
    let objects = l09_acceleration::intersector_for(&scene.objects);
    let surface: SurfaceMaterial = &|hit, material| surface_material(scene, hit, material);
    let world = World::new(scene, objects.as_ref()).with_surface(surface);
    Ok(pixels
        .iter()
        .map(|&(x, y)| trace_recorded(&world, &camera.pixel_ray(x, y, scene.width, scene.height), settings))
        .collect())
}
