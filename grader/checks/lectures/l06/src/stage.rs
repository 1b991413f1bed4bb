//! What lecture 06 lends the stages (`stages::Lent`): stage 06's shading with shadow rays, the
//! shadow settings a scene asks for, and the shadow rays' calls on a picture's path, which
//! stages 08 and 10 make too.

use l05_shading::LightSample;
use l06_shadows::{ShadowMode, ShadowSettings, Surface};
use raylab::scene::{LightKind, Material};
use raylab::{Color, Hit, Intersector, Ray, Scene};

use crate::path::{SAMPLES_SHOWN, Trail};
use crate::stages::{Drawer, Draws, Lent};
use raylab_checks_l05::stage::{AtHit, Lights, Walk, light_numbers, walk};

/// Lends stage 06's drawing.
pub fn lend(lent: &mut Lent) {
    let calls =
        |stage: &str, scene: &Scene, pixel, trail: &mut Trail| walk(&Shadows, stage, scene, pixel, trail);
    lent.drawers.push((Draws::Shadowed, Drawer::Shades { shade: shadowed, sky_rays: None, calls }));
}

/// The shadow settings `scene` asks for: its `[render]` table's `transparent_shadows` and
/// `area_samples`, lecture 06's defaults for what it does not say. Stage 06 shades with them;
/// the tracer's settings take them.
pub fn shadow_settings(scene: &Scene) -> ShadowSettings {
    let defaults = ShadowSettings::default();
    ShadowSettings {
        mode: match scene.render.transparent_shadows {
            Some(true) => ShadowMode::Transmissive,
            Some(false) => ShadowMode::Opaque,
            None => defaults.mode,
        },
        area_samples: scene.render.area_samples.unwrap_or(defaults.area_samples),
    }
}

/// Stage 06's colour of a hit: 06's `shade_with_shadows` with the scene's shadow settings.
fn shadowed(scene: &Scene, objects: &dyn Intersector, ray: &Ray, hit: &Hit) -> Color {
    let Some(material) = scene.materials.get(hit.material) else { return scene.background };
    l06_shadows::shade_with_shadows(
        objects,
        &scene.materials,
        &surface(material, hit, ray),
        &scene.lights,
        scene.ambient,
        shadow_settings(scene),
    )
}

/// Lecture 06's view of the surface at the eye ray's hit, with the material there.
fn surface<'a>(material: &'a Material, hit: &Hit, ray: &Ray) -> Surface<'a> {
    let v = -ray.dir.normalize();
    Surface { material, diffuse: material.diffuse, hit: *hit, v, origin: ray.origin }
}

/// Stage 06's calls: stage 05's with shadow rays.
struct Shadows;

impl Walk for Shadows {
    fn lights(&self) -> &dyn Lights {
        &Shadowed
    }
}

/// The lights with shadow rays: stage 06's, and 08's and 10's.
pub struct Shadowed;

impl Lights for Shadowed {
    /// An area light with shadows: its first samples in order, the first sample's light, and its
    /// average.
    fn area_light(&self, trail: &mut Trail, at_hit: &AtHit, index: usize) -> bool {
        use l06_shadows::{point_seed, shade_area_light, stratified};
        let AtHit { scene, objects, ray, hit, material } = *at_hit;
        let light = &scene.lights[index];
        if !(light.shadows && light.kind.is_area()) {
            return false;
        }
        let at = format!("light {index}");
        let settings = shadow_settings(scene);
        let samples =
            stratified(settings.area_samples.max(1), &mut raylab::random::Rng::new(point_seed(hit.point)));
        let shown = &samples[..samples.len().min(SAMPLES_SHOWN)];
        trail.push("06/stratified", format!("{at}: the first samples, in order"), shown);
        if let Some(&u) = samples.first() {
            if let LightKind::Sphere { .. } = light.kind {
                trail.push(
                    "05/concentric_disk",
                    format!("{at}: the first sample"),
                    &l05_shading::concentric_disk(u),
                );
            }
            let sample = l05_shading::sample_light(light, hit.point, u);
            trail.push("05/sample_light", format!("{at}: the first sample"), &light_numbers(&sample)[..]);
        }
        let color =
            shade_area_light(objects, &scene.materials, &surface(material, hit, ray), light, settings);
        trail.push("06/shade_area_light", at, &color);
        true
    }

    /// A lit light's shadow ray: its origin's offset, then what it lets through.
    fn shadow_ray(
        &self,
        trail: &mut Trail,
        at_hit: &AtHit,
        index: usize,
        sample: &LightSample,
        direct: Color,
    ) {
        let AtHit { scene, objects, ray, hit, material } = *at_hit;
        let (p, n) = (hit.point, hit.normal);
        if !(scene.lights[index].shadows && n.dot(sample.direction) > 0.0 && direct != raylab::BLACK) {
            return;
        }
        let at = format!("light {index}");
        // The offset from the surface in units of ε·(|p|₁ + |o|₁), the same in f32 and f64
        // (the book's rule is 8 along the normal, on the light's side).
        let from = l06_shadows::offset_origin(p, n, sample.direction, ray.origin);
        let unit = raylab::Float::EPSILON * (p.abs().element_sum() + ray.origin.abs().element_sum());
        let offset = (from - p) / if unit > 0.0 { unit } else { 1.0 };
        trail.push(
            "06/offset_origin",
            format!("{at}: the shadow ray's origin − p, in units of ε·(|p|₁ + |o|₁)"),
            &offset,
        );
        let mode = shadow_settings(scene).mode;
        let seen =
            l06_shadows::visibility(objects, &scene.materials, &surface(material, hit, ray), sample, mode);
        trail.push("06/visibility", format!("{at}: what its shadow ray lets through"), &seen);
    }

    /// The sum: 06's `shade_with_shadows`.
    fn sum(&self, trail: &mut Trail, at_hit: &AtHit) {
        let AtHit { scene, objects, ray, hit, material } = *at_hit;
        let color = l06_shadows::shade_with_shadows(
            objects,
            &scene.materials,
            &surface(material, hit, ray),
            &scene.lights,
            scene.ambient,
            shadow_settings(scene),
        );
        trail.push("06/shade_with_shadows", "the sum: ambient plus every light's visible share", &color);
    }
}
