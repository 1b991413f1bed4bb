//! The tracer assembled from every lecture available: cameras (01),
//! intersections (02–04) and, until the shading lectures land, a plain
//! diffuse shade: k_d·(Iₐ + I_L·max(N·L, 0)) from the first light, or the
//! flat diffuse colour when the scene has no light (6.837 assignment 1).

use l01_transforms::Camera;
use l04_quadrics_transforms::BruteForce;
use raylab::scene::{LightKind, Scene};
use raylab::stats::{Counter, RayStats, count};
use raylab::{Color, Hit, Image, Intersector, render};

use crate::Aov;

/// Renders `scene` at its size: the shaded image, or the AOV asked for.
pub fn render_scene(scene: &Scene, aov: Option<Aov>) -> Result<(Image, RayStats), String> {
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).map_err(|e| e.to_string())?;
    let world = BruteForce { objects: &scene.objects };
    let (w, h) = (scene.width, scene.height);
    Ok(match aov {
        Some(Aov::Id) => raylab::stats::measure(|| l02_ray_casting::object_id_image(&camera, &world, w, h)),
        Some(Aov::Depth) => raylab::stats::measure(|| l02_ray_casting::depth_image(&camera, &world, w, h)),
        Some(Aov::Normal) => raylab::stats::measure(|| l02_ray_casting::normal_image(&camera, &world, w, h)),
        None => render::render_image(w, h, |x, y| {
            count(Counter::PrimaryRays);
            let ray = camera.pixel_ray(x, y, w, h);
            match world.closest_hit(&ray, camera.t_range()) {
                Some(hit) => diffuse(scene, &hit),
                None => scene.background,
            }
        }),
    })
}

/// k_d·(Iₐ + I_L·max(N·L, 0)) for the first light; k_d alone without lights.
fn diffuse(scene: &Scene, hit: &Hit) -> Color {
    let kd = scene.materials[hit.material].diffuse;
    let Some(light) = scene.lights.first() else {
        return kd;
    };
    let to_light = match light.kind {
        LightKind::Directional { direction } => -direction,
        LightKind::Point { position, .. } | LightKind::Spot { position, .. } => {
            (position - hit.point).normalize_or_zero()
        }
    };
    kd * (scene.ambient + light.color * hit.normal.dot(to_light).max(0.0))
}
