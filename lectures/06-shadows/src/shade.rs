//! Local shading with shadows: lecture 05's model, each light weighted by
//! how much of it the shadow rays let through.

use l05_shading::{LightSample, illuminate, shade_light};
use raylab::scene::{Light, LightKind, Material};
use raylab::{BLACK, Color, Hit, Intersector, Vec3, WHITE};

use crate::occlusion::{ShadowMode, occluded, transmittance};
use crate::offset::offset_origin;
use crate::soft::shade_area_light;

/// What the shading with shadows spends on its shadow rays: what transparent
/// blockers do, and how many samples an area light gets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShadowSettings {
    /// Transparent blockers block ([`ShadowMode::Opaque`]) or filter by their k_t.
    pub mode: ShadowMode,
    /// Shadow rays per area light and shaded point (≥ 1; a scene file's
    /// `area_samples`): more rays, less noise in the penumbra.
    pub area_samples: u32,
}

impl Default for ShadowSettings {
    /// Opaque blockers, 16 samples (a 4 × 4 grid) per area light.
    fn default() -> Self {
        Self { mode: ShadowMode::Opaque, area_samples: 16 }
    }
}

/// The surface point being shaded: the hit, its material, the surface colour
/// there, the direction to the eye and the origin of the ray that found it.
#[derive(Clone, Copy, Debug)]
pub struct Surface<'a> {
    /// The material of the hit (k_s, the exponent, the highlight model).
    pub material: &'a Material,
    /// The surface colour at the hit, k_d (and k_a): the material's, or a
    /// texture's value (lecture 10).
    pub diffuse: Color,
    /// The hit: point, and unit normal facing the eye.
    pub hit: Hit,
    /// Unit direction from the point toward the eye, −ray.dir/|ray.dir|.
    pub v: Vec3,
    /// The origin of the ray that found the hit: the eye for a primary ray.
    /// The shadow ray's offset scales with it ([`offset_origin`]): where
    /// origin + t·dir cancels, the hit point carries its rounding error.
    pub origin: Vec3,
}

/// How much of the light of `sample` reaches `surface` past the blockers:
/// white or black by [`occluded`] in [`ShadowMode::Opaque`], the filter colour
/// [`transmittance`] in [`ShadowMode::Transmissive`], for the shadow ray from
/// [`offset_origin`]`(p, N, L, surface.origin)` (p, N the hit's point and
/// normal, L = `sample.direction`). Book: §6.3 Shading with shadows.
pub fn visibility(
    scene: &dyn Intersector,
    materials: &[Material],
    surface: &Surface,
    sample: &LightSample,
    mode: ShadowMode,
) -> Color {
    // SOLUTION BEGIN
    // The shadow ray starts just off the surface, on the light's side.
    let from = offset_origin(surface.hit.point, surface.hit.normal, sample.direction, surface.origin);
    match mode {
        ShadowMode::Opaque if occluded(scene, from, sample) => BLACK,
        ShadowMode::Opaque => WHITE,
        ShadowMode::Transmissive => transmittance(scene, materials, from, sample),
    }
    // SOLUTION END
}

/// Lecture 05's local shading with shadows:
///
///   I = k_a ⊙ I_a + Σ_lights V_L ⊙ shade_light(…, illuminate(light, p)),
///
/// where the visibility V_L is [`visibility`] (1 or 0 in
/// [`ShadowMode::Opaque`], the filter colour in [`ShadowMode::Transmissive`],
/// as `settings.mode` says); k_a = `surface.diffuse`. An area light (rect or
/// sphere) that casts shadows adds [`shade_area_light`] instead: the average
/// over `settings.area_samples` of its points, each with its own shadow ray
/// (soft shadows). The ambient term is never shadowed.
///
/// Only what the scene requires is traced: no shadow ray for a light with
/// `shadows == false` (it lights everything it faces; an area light then
/// stands at its centre, as in lecture 05's `illuminate`), none for a light
/// (or a light's sample) behind the surface (N·L ≤ 0: it adds nothing anyway)
/// and none for a light that sends nothing here (a spot light outside its
/// cone, a black material). `materials` are the scene's, indexed by
/// `hit.material` of the blockers. With nothing in the way and no area light
/// casting shadows, the result is exactly lecture 05's `shade_local`.
/// Book: §6.3 Shading with shadows, §6.5 Area lights and soft shadows.
pub fn shade_with_shadows(
    scene: &dyn Intersector,
    materials: &[Material],
    surface: &Surface,
    lights: &[Light],
    ambient: Color,
    settings: ShadowSettings,
) -> Color {
    debug_assert!(surface.hit.normal.is_normalized(), "shade_with_shadows: the normal is not unit");
    // SOLUTION BEGIN
    let Surface { material, diffuse, hit, v, .. } = *surface;
    // The ambient term, never shadowed.
    let mut color = diffuse * ambient;
    for light in lights {
        // An area light with shadows: the average of its samples, soft shadows.
        if light.shadows && matches!(light.kind, LightKind::Rect { .. } | LightKind::Sphere { .. }) {
            color += shade_area_light(scene, materials, surface, light, settings);
            continue;
        }
        // A light behind the surface adds nothing: no shadow ray.
        let sample = illuminate(light, hit.point);
        if hit.normal.dot(sample.direction) <= 0.0 {
            continue;
        }
        // What the light would add; nothing added, nothing to shadow.
        let direct = shade_light(material, diffuse, hit.normal, v, &sample);
        if direct == BLACK {
            continue;
        }
        // The visibility of the light, by a shadow ray from just off the surface.
        let visible =
            if light.shadows { visibility(scene, materials, surface, &sample, settings.mode) } else { WHITE };
        color += visible * direct;
    }
    color
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{plane, see_through, sphere};
    use l04_quadrics_transforms::BruteForce;
    use l05_shading::shade_local;
    use raylab::random::Rng;
    use raylab::scene::{Attenuation, LightKind, Object, Specular};
    use raylab::stats::{Counter, measure};
    use raylab::{Float, Ray, radians};
    use raylab_testing::v;

    const EPS: Float = Float::EPSILON;
    const AMBIENT: Color = Color::splat(0.1);

    /// The default settings with blockers treated by `mode`.
    fn settings(mode: ShadowMode) -> ShadowSettings {
        ShadowSettings { mode, ..ShadowSettings::default() }
    }

    /// Materials: 0 the grey floor (k_d = ½, opaque), 1 an opaque ball, 2 a ball of k_t = ½.
    fn materials() -> Vec<Material> {
        let grey = Material { diffuse: Color::splat(0.5), ..Material::default() };
        vec![grey.clone(), grey, see_through(Color::splat(0.5))]
    }

    /// The floor y = 0 and a unit ball at (0, 2, 0) of material `ball`.
    fn floor_and_ball(ball: usize) -> Vec<Object> {
        vec![plane(Vec3::Y, 0.0, 0), sphere(v(0.0, 2.0, 0.0), 1.0, ball)]
    }

    fn directional(toward_light: Vec3, shadows: bool) -> Light {
        Light { color: WHITE, shadows, kind: LightKind::Directional { direction: -toward_light } }
    }

    /// The floor point (x, 0, z) as seen by an eye above and in front of it: the hit, the
    /// direction to the eye and the eye.
    fn floor_hit(x: Float, z: Float) -> (Hit, Vec3, Vec3) {
        let point = v(x, 0.0, z);
        let ray = Ray::new(point + v(0.0, 3.0, 4.0), v(0.0, -3.0, -4.0) / 5.0);
        let hit = Hit { object: 0, material: 0, ..Hit::new(&ray, 5.0, Vec3::Y) };
        (hit, -ray.dir, ray.origin)
    }

    /// The shading of the floor point (x, 0, z) and the shadow rays it cast.
    fn shade_floor(
        objects: &[Object],
        lights: &[Light],
        x: Float,
        z: Float,
        mode: ShadowMode,
    ) -> (Color, u64) {
        let materials = materials();
        let (hit, v, origin) = floor_hit(x, z);
        let surface = Surface { material: &materials[0], diffuse: materials[0].diffuse, hit, v, origin };
        let scene = BruteForce::new(objects);
        let (color, stats) =
            measure(|| shade_with_shadows(&scene, &materials, &surface, lights, AMBIENT, settings(mode)));
        (color, stats.get(Counter::ShadowRays))
    }

    #[test]
    fn under_a_ball_only_the_ambient_term_is_left() {
        // Light straight down, the origin under the opaque ball: k_a·I_a = ½·0.1 only, one
        // shadow ray. Beside the ball (x = 3): + k_d·(N·L)·I = ½·1·1, i.e. 0.55 up to one
        // rounding of the sum.
        let lights = [directional(Vec3::Y, true)];
        let objects = floor_and_ball(1);
        for mode in [ShadowMode::Opaque, ShadowMode::Transmissive] {
            let (shadowed, rays) = shade_floor(&objects, &lights, 0.0, 0.0, mode);
            assert_eq!((shadowed, rays), (Color::splat(0.5) * AMBIENT, 1), "{mode:?}");
            let (lit, _) = shade_floor(&objects, &lights, 3.0, 0.0, mode);
            approx::assert_abs_diff_eq!(lit, Color::splat(0.55), epsilon = 2.0 * EPS);
        }
    }

    #[test]
    fn a_transparent_ball_lets_a_quarter_through_in_transmissive_mode() {
        // Ball of k_t = ½, light straight down onto the origin: Opaque gives 0.05 (one ray);
        // Transmissive 0.05 + ¼·0.5 = 0.175, through three segments (in, out, on).
        let lights = [directional(Vec3::Y, true)];
        let objects = floor_and_ball(2);
        let (opaque, rays) = shade_floor(&objects, &lights, 0.0, 0.0, ShadowMode::Opaque);
        assert_eq!((opaque, rays), (Color::splat(0.5) * AMBIENT, 1));
        let (filtered, rays) = shade_floor(&objects, &lights, 0.0, 0.0, ShadowMode::Transmissive);
        approx::assert_abs_diff_eq!(filtered, Color::splat(0.175), epsilon = 2.0 * EPS);
        assert_eq!(rays, 3);
    }

    #[test]
    fn opaque_and_transmissive_differ_exactly_inside_the_shadow_of_the_transparent_ball() {
        // Light along L = (1, 2, 0)/√5 onto a 41 × 41 grid of floor points in [−3, 3]². The
        // ray from p meets the unit ball at c = (0, 2, 0) iff the line passes within 1 of c
        // ahead of p: |(c − p) − ((c − p)·L)·L| < 1 and (c − p)·L > 0, computed here in f64.
        // Inside: Opaque = k_a·I_a, Transmissive = that + ¼·½·(N·L) with N·L = 2/√5. Outside:
        // the two are equal. Points within 10⁻³ of the shadow's edge are left out.
        let l = v(1.0, 2.0, 0.0).normalize();
        let lights = [directional(l, true)];
        let objects = floor_and_ball(2);
        let (mut inside, mut outside) = (0, 0);
        for i in 0..41 {
            for j in 0..41 {
                // The point in f64 for the geometry, rounded to Float for the shading (they
                // differ by < 10⁻⁶, far inside the 10⁻³ left out at the edge).
                let (px, pz) = (-3.0 + 0.15 * f64::from(i), -3.0 + 0.15 * f64::from(j));
                let (x, z) = (px as Float, pz as Float);
                let (lx, ly) = (1.0 / 5f64.sqrt(), 2.0 / 5f64.sqrt());
                let to_c = [-px, 2.0, -pz];
                let along = to_c[0] * lx + to_c[1] * ly;
                let away = [to_c[0] - along * lx, to_c[1] - along * ly, to_c[2]];
                let distance = (away[0] * away[0] + away[1] * away[1] + away[2] * away[2]).sqrt();
                if (distance - 1.0).abs() < 1e-3 {
                    continue;
                }
                let (opaque, _) = shade_floor(&objects, &lights, x, z, ShadowMode::Opaque);
                let (filtered, _) = shade_floor(&objects, &lights, x, z, ShadowMode::Transmissive);
                if distance < 1.0 && along > 0.0 {
                    inside += 1;
                    let ambient_only = Color::splat(0.5) * AMBIENT;
                    assert_eq!(opaque, ambient_only, "({x}, {z})");
                    let expected = 0.05 + 0.25 * 0.5 * 2.0 / 5f64.sqrt();
                    approx::assert_abs_diff_eq!(
                        filtered,
                        Color::splat(expected as Float),
                        epsilon = 4.0 * EPS
                    );
                } else {
                    outside += 1;
                    assert_eq!(opaque, filtered, "({x}, {z})");
                }
            }
        }
        // The shadow is an ellipse of area π·1·√5/2 ≈ 3.5 of the grid's 36: about 10% inside.
        assert!(inside > 100 && outside > 1000, "{inside} inside, {outside} outside");
    }

    #[test]
    fn a_light_without_shadows_casts_no_shadow_ray() {
        // The same light with `shadows = false`: no shadow ray (stats: 0), and it lights the
        // point under the opaque ball as if nothing were there: 0.55.
        let lights = [directional(Vec3::Y, false)];
        for mode in [ShadowMode::Opaque, ShadowMode::Transmissive] {
            let (color, rays) = shade_floor(&floor_and_ball(1), &lights, 0.0, 0.0, mode);
            assert_eq!(rays, 0, "{mode:?}");
            approx::assert_abs_diff_eq!(color, Color::splat(0.55), epsilon = 2.0 * EPS);
        }
        // Beside one with shadows: exactly one shadow ray, for the other light.
        let both = [directional(Vec3::Y, false), directional(Vec3::Y, true)];
        let (color, rays) = shade_floor(&floor_and_ball(1), &both, 0.0, 0.0, ShadowMode::Opaque);
        assert_eq!(rays, 1);
        approx::assert_abs_diff_eq!(color, Color::splat(0.55), epsilon = 2.0 * EPS);
    }

    #[test]
    fn a_light_behind_the_surface_or_outside_its_cone_casts_no_shadow_ray() {
        // Light from below the floor (N·L = −1): nothing but the ambient term, no ray.
        let below = [directional(-Vec3::Y, true)];
        let (color, rays) = shade_floor(&floor_and_ball(1), &below, 3.0, 0.0, ShadowMode::Opaque);
        assert_eq!((color, rays), (Color::splat(0.5) * AMBIENT, 0));
        // A grazing light (N·L = 0 exactly): the same.
        let grazing = [directional(Vec3::X, true)];
        assert_eq!(shade_floor(&floor_and_ball(1), &grazing, 3.0, 0.0, ShadowMode::Opaque).1, 0);
        // A spot at (10, 5, 0) aimed straight down with a 10° cone: the origin is 63° off
        // its axis, dark, no ray; a point light at the same place (in front) casts one.
        let position = v(10.0, 5.0, 0.0);
        let attenuation = Attenuation::default();
        let spot = Light {
            color: WHITE,
            shadows: true,
            kind: LightKind::Spot {
                position,
                direction: -Vec3::Y,
                inner: radians(5.0),
                outer: radians(10.0),
                attenuation,
            },
        };
        let (color, rays) = shade_floor(&floor_and_ball(1), &[spot], 0.0, 0.0, ShadowMode::Opaque);
        assert_eq!((color, rays), (Color::splat(0.5) * AMBIENT, 0));
        let point = Light { kind: LightKind::Point { position, attenuation }, ..spot };
        assert_eq!(shade_floor(&floor_and_ball(1), &[point], 0.0, 0.0, ShadowMode::Opaque).1, 1);
    }

    #[test]
    fn the_shadow_ray_starts_past_the_error_the_eye_brings() {
        // The floor y = 0 seen from (0, 500, 700), points within 0.1 of the world origin, a
        // light straight above: nothing blocks it, so every point gets 0.55 (see above). Each
        // point carries an error of a few ulp of the eye (o + t·d cancels), covered only
        // because the shadow ray's offset scales with `surface.origin`: a self-shadowed point
        // would get 0.05.
        let materials = materials();
        let objects = [plane(Vec3::Y, 0.0, 0)];
        let scene = BruteForce::new(&objects);
        let lights = [directional(Vec3::Y, true)];
        let eye = v(0.0, 500.0, 700.0);
        let mut rng = Rng::new(0xe_7e);
        for _ in 0..2000 {
            let aim = v(rng.range(-0.1, 0.1), 0.0, rng.range(-0.1, 0.1));
            let ray = Ray::new(eye, (aim - eye).normalize());
            let hit = scene.closest_hit(&ray, raylab::Interval::POSITIVE).expect("aimed");
            let surface = Surface {
                material: &materials[0],
                diffuse: materials[0].diffuse,
                hit,
                v: -ray.dir,
                origin: eye,
            };
            let color =
                shade_with_shadows(&scene, &materials, &surface, &lights, AMBIENT, ShadowSettings::default());
            approx::assert_abs_diff_eq!(color, Color::splat(0.55), epsilon = 2.0 * EPS);
        }
    }

    #[test]
    fn with_nothing_in_the_way_it_is_exactly_shade_local() {
        // Random floor points, a shiny material and every kind of light, some behind the
        // floor; no blockers. Every term is the same sum in the same order, skipped lights
        // would have added exactly 0, and white·x = x: bit-for-bit equal to lecture 05.
        let mut rng = Rng::new(0x5_4ade);
        let attenuation = Attenuation { constant: 1.0, linear: 0.1, quadratic: 0.01 };
        let lights = [
            directional(v(1.0, 2.0, 3.0).normalize(), true),
            directional(v(0.0, -1.0, 0.0), true),
            Light {
                color: v(1.0, 0.5, 0.2),
                shadows: true,
                kind: LightKind::Point { position: v(2.0, 3.0, -1.0), attenuation },
            },
            Light {
                color: v(0.2, 0.5, 1.0),
                shadows: false,
                kind: LightKind::Spot {
                    position: v(-1.0, 4.0, 1.0),
                    direction: -Vec3::Y,
                    inner: 0.3,
                    outer: 0.6,
                    attenuation,
                },
            },
        ];
        let shiny = Material {
            diffuse: v(0.7, 0.6, 0.5),
            specular: Color::splat(0.4),
            exponent: 20.0,
            model: Specular::Phong,
            ..Material::default()
        };
        let objects = [plane(Vec3::Y, 0.0, 0)];
        let scene = BruteForce::new(&objects);
        for _ in 0..500 {
            let (hit, eye, origin) = floor_hit(rng.range(-3.0, 3.0), rng.range(-3.0, 3.0));
            let surface = Surface { material: &shiny, diffuse: shiny.diffuse, hit, v: eye, origin };
            for mode in [ShadowMode::Opaque, ShadowMode::Transmissive] {
                let with = shade_with_shadows(&scene, &[], &surface, &lights, AMBIENT, settings(mode));
                assert_eq!(with, shade_local(&shiny, shiny.diffuse, &hit, eye, &lights, AMBIENT), "{hit:?}");
            }
        }
    }
}
