//! What lecture 07 lends the stages (`stages::Lent`): stage 07's local shading plus the sky in
//! 07's mirror and refracted directions (one bounce, no Fresnel split: that is lecture 08's),
//! and the directions' calls on a picture's path, which stages 08 and 10 make too.

use l07_reflection_refraction::{fresnel_dielectric, interface, mirror_direction, refract};
use raylab::{Color, Hit, Intersector, Ray, Scene, Vec3};

use crate::path::Trail;
use crate::stages::{Drawer, Draws, Lent, direction_color};
use raylab_checks_l05::stage::{AtHit, Walk, local, walk};

/// Lends stage 07's drawing.
pub fn lend(lent: &mut Lent) {
    let calls =
        |stage: &str, scene: &Scene, pixel, trail: &mut Trail| walk(&Mirrored, stage, scene, pixel, trail);
    lent.drawers.push((Draws::Mirrored, Drawer::Shades { shade: mirrored, sky_rays: Some(sky_rays), calls }));
}

/// Stage 07's colour of a hit: local shading, plus k_r times the sky ([`direction_color`]) in
/// 07's mirror direction, plus k_t times the sky in 07's refracted direction (with 07's
/// `interface`), or in the mirror direction where `refract` finds total internal reflection. One
/// bounce, to the sky: the rays are not traced into the scene (lecture 08), and there is no
/// Fresnel split.
fn mirrored(scene: &Scene, _: &dyn Intersector, ray: &Ray, hit: &Hit) -> Color {
    let mut color = local(scene, ray, hit);
    for (k, direction, _) in sky_rays(scene, ray, hit) {
        color += k * direction_color(direction);
    }
    color
}

/// Stage 07's rays to the sky from `hit`: (k_r, 07's mirror direction) on a reflective material,
/// (k_t, 07's refracted direction, or the mirror direction where `refract` finds total internal
/// reflection) on a transparent one, each with whether it is the transmitted one.
fn sky_rays(scene: &Scene, ray: &Ray, hit: &Hit) -> Vec<(Color, Vec3, bool)> {
    let Some(material) = scene.materials.get(hit.material) else { return Vec::new() };
    let d = ray.dir.normalize();
    let mirror = || mirror_direction(d, hit.normal);
    let mut rays = Vec::new();
    if material.reflective != raylab::BLACK {
        rays.push((material.reflective, mirror(), false));
    }
    if material.transparent != raylab::BLACK {
        let crossing = interface(hit, material.ior);
        let through = refract(d, crossing.normal, crossing.eta_ratio()).unwrap_or_else(mirror);
        rays.push((material.transparent, through, true));
    }
    rays
}

/// Stage 07's calls: stage 05's, then the directions.
struct Mirrored;

impl Walk for Mirrored {
    fn after(&self, trail: &mut Trail, at: &AtHit) {
        directions(trail, at, false);
    }
}

/// The mirror and refracted directions at the hit (stages 07, 08, 10), and the Fresnel
/// reflectance where `fresnel` (the tracer's settings ask for it: 08 and 10).
pub fn directions(trail: &mut Trail, at: &AtHit, fresnel: bool) {
    let AtHit { ray, hit, material, .. } = *at;
    let d = ray.dir.normalize();
    if material.reflective != raylab::BLACK {
        trail.push("07/mirror_direction", "the mirror ray", &mirror_direction(d, hit.normal));
    }
    if material.transparent != raylab::BLACK {
        let crossing = interface(hit, material.ior);
        let values =
            [crossing.normal.x, crossing.normal.y, crossing.normal.z, crossing.eta_i, crossing.eta_t];
        trail.push("07/interface", "the surface crossed: normal, η_i, η_t", &values[..]);
        trail.push(
            "07/refract",
            "the refracted ray (no numbers: total internal reflection)",
            &refract(d, crossing.normal, crossing.eta_ratio()),
        );
        if fresnel {
            let cos_i = -d.dot(crossing.normal);
            let r = fresnel_dielectric(cos_i, crossing.eta_i, crossing.eta_t);
            trail.push("07/fresnel_dielectric", "the reflected share", &r);
        }
    }
}
