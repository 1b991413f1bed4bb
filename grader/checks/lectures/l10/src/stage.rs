//! What lecture 10 lends the stages (`stages::Lent`): the complete tracer (`tracer`: textures,
//! the hierarchy, supersampling), which draws lecture 10's scenes and every earlier lecture's
//! final pictures, and the samples' and textures' calls on a picture's path.

use std::borrow::Cow;

use l10_textures_sampling as l10;
use raylab::scene::{Material, Shape, SolidPattern, Texture};
use raylab::{Hit, Scene, Vec3};

use super::tracer::{SAMPLING_SEED, pixel_trees, render_scene, scene_sampling};
use crate::path::{SAMPLES_SHOWN, Trail};
use crate::stages::{Drawer, Draws, Lent};
use raylab_checks_l05::stage::{AtHit, Lights, Walk, walk};
use raylab_checks_l06::stage::Shadowed;
use raylab_checks_l07::stage::directions;
use raylab_checks_l08::stage::{scene_settings, trace, tree_node};

/// Lends stage 10's drawing.
pub fn lend(lent: &mut Lent) {
    let render = |scene: &Scene| {
        render_scene(scene, None, &scene_settings(scene), scene_sampling(scene)).map(|(image, _)| image)
    };
    let traced = |scene: &Scene, pixels: &[(u32, u32)]| {
        let trees = pixel_trees(scene, pixels, &scene_settings(scene)).ok()?;
        Some(trees.iter().map(|(color, tree)| (*color, tree_node(tree))).collect())
    };
    let calls =
        |stage: &str, scene: &Scene, pixel, trail: &mut Trail| walk(&Complete, stage, scene, pixel, trail);
    let pixel_loop =
        |scene: &Scene| if scene_sampling(scene).spp > 1 { "10/render_supersampled" } else { "08/render" };
    lent.drawers.push((Draws::Complete, Drawer::Traces { render, traced, calls, pixel_loop }));
}

/// Stage 10's calls: the pixel's samples, then stage 08's with the hit's textures.
struct Complete;

impl Walk for Complete {
    /// The pixel's samples, where the scene asks for more than one: their offsets in order (the
    /// pixel's own generator) and their filter weights.
    fn sampling(&self, trail: &mut Trail, scene: &Scene, (x, y): (u32, u32)) {
        let sampling = scene_sampling(scene);
        if sampling.spp <= 1 {
            return;
        }
        let mut rng = l10::pixel_rng(SAMPLING_SEED, x, y);
        let offsets = l10::sample_offsets(sampling.pattern, sampling.spp, &mut rng);
        let shown = &offsets[..offsets.len().min(SAMPLES_SHOWN)];
        trail.push("10/sample_offsets", "the pixel's first samples, in order", shown);
        let radius = sampling.filter.radius();
        let weights: Vec<raylab::Float> = shown
            .iter()
            .map(|u| l10::filter_weight(sampling.filter, (2.0 * *u - raylab::Vec2::ONE) * radius))
            .collect();
        trail.push("10/filter_weight", "the first samples' weights", &weights[..]);
    }

    fn material<'m>(
        &self,
        trail: &mut Trail,
        scene: &Scene,
        hit: &Hit,
        material: &'m Material,
    ) -> Cow<'m, Material> {
        textures(trail, scene, hit, material);
        l10::surface_material(scene, hit, material)
    }

    fn lights(&self) -> &dyn Lights {
        &Shadowed
    }

    fn after(&self, trail: &mut Trail, at: &AtHit) {
        let scene = at.scene;
        directions(trail, at, scene_settings(scene).fresnel);
        trace(trail, at, Some(&|hit, material| l10::surface_material(scene, hit, material)));
    }
}

/// The hit's texture: the surface's uv where an exercise maps it, then the texture's value,
/// through the blend of a solid pattern's two materials.
fn textures(trail: &mut Trail, scene: &Scene, hit: &Hit, material: &Material) {
    let uv = || {
        let uv = l10::surface_uv(scene, hit);
        let exercise = scene.objects.get(hit.object).and_then(|o| match o.shape {
            Shape::Sphere { .. } => Some("10/sphere_uv"),
            Shape::Plane { .. } => Some("10/plane_uv"),
            _ => None,
        });
        (uv, exercise)
    };
    match &material.texture {
        None => {}
        Some(Texture::Checker { scale, other }) => {
            let (uv, exercise) = uv();
            if let Some(exercise) = exercise {
                trail.push(exercise, "the hit's uv", &uv);
            }
            trail.push(
                "10/checker",
                "the checker's colour",
                &l10::checker(uv, *scale, material.diffuse, *other),
            );
        }
        Some(Texture::Image { image, .. }) => {
            let (uv, exercise) = uv();
            if let Some(exercise) = exercise {
                trail.push(exercise, "the hit's uv", &uv);
            }
            trail.push("10/bilinear", "the image's colour", &l10::bilinear(image, uv));
        }
        Some(Texture::Solid { pattern_from_world, pattern, a, b }) => {
            let q = l01_transforms::transform_point(pattern_from_world, hit.point);
            let octaves = match *pattern {
                SolidPattern::Noise { octaves }
                | SolidPattern::Marble { octaves, .. }
                | SolidPattern::Wood { octaves, .. } => Some(octaves),
                SolidPattern::Checker => None,
            };
            if let Some(octaves) = octaves {
                trail.push("10/noise", "noise at the pattern's point", &l10::noise(q));
                trail.push("10/fractal_noise", format!("{octaves} octaves"), &l10::fractal_noise(q, octaves));
            }
            let (exercise, value) = match *pattern {
                SolidPattern::Checker => ("10/checker_3d", l10::checker_3d(q, 1.0, Vec3::ZERO, Vec3::ONE).x),
                SolidPattern::Noise { .. } => ("10/fractal_noise", l10::solid_value(pattern, q)),
                SolidPattern::Marble { octaves, frequency, amplitude } => {
                    ("10/marble", l10::marble(q, octaves, frequency, amplitude))
                }
                SolidPattern::Wood { octaves, frequency, amplitude } => {
                    ("10/wood", l10::wood(q, octaves, frequency, amplitude))
                }
            };
            trail.push(exercise, "the pattern's blend of its two materials", &value);
            // The two materials' own textures, as the blend takes them.
            for inner in [a, b] {
                textures(trail, scene, hit, inner);
            }
        }
    }
}
