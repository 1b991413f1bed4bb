//! The local illumination model: ambient plus, for every light, diffuse and
//! specular reflection of what arrives.

use raylab::scene::{Light, Material, Specular};
use raylab::{Color, Hit, Vec3};

use crate::lambert::lambert;
use crate::lights::{LightSample, illuminate};
use crate::phong::{blinn_specular, phong_specular};

/// One light's contribution at a surface point:
///
///   (k_d·(N·L)⁺ + k_s·spec) ⊙ I_L,
///
/// with k_d = `diffuse`, k_s = `material.specular`, spec = [`phong_specular`]
/// or [`blinn_specular`] as `material.model` says (exponent
/// `material.exponent`), L = `sample.direction` and I_L = `sample.intensity`;
/// ⊙ multiplies colours channel by channel. `diffuse` is the surface colour
/// at the point (the material's k_d, or a texture's value in lecture 10),
/// passed as a value so that this lecture need not know textures. `n` is the
/// unit normal facing the eye and `v` the unit direction from the point to
/// the eye. Book: §5.9 The local shading equation.
pub fn shade_light(material: &Material, diffuse: Color, n: Vec3, v: Vec3, sample: &LightSample) -> Color {
    // SOLUTION BEGIN
    let l = sample.direction;
    // The diffuse term: Lambert's cosine.
    let diffuse_term = diffuse * lambert(n, l);
    // The specular term: the material's highlight. Without a specular colour it is 0 whatever
    // the lobe (a value in [0, 1]), whose power is then not worth computing: the same colour,
    // bit for bit, for most of a scene's surfaces, and the cost of a soft shadow's samples.
    let spec = match material.model {
        _ if material.specular == Color::ZERO => 0.0,
        Specular::Phong => phong_specular(n, l, v, material.exponent),
        Specular::Blinn => blinn_specular(n, l, v, material.exponent),
    };
    // Both reflect the light that arrives.
    (diffuse_term + material.specular * spec) * sample.intensity
    // SOLUTION END
}

/// The local shading of a hit, lit by `lights` and the ambient light I_a:
///
///   I = k_a ⊙ I_a + Σ_lights shade_light(…, illuminate(light, p)),
///
/// with k_a = `diffuse` (the surface colour at the hit, as in 6.837) and p,
/// N the hit's point and normal (unit, facing the eye, so a surface seen
/// from behind is lit by the lights on the eye's side). `v` is the unit
/// direction from the point to the eye, −ray.dir/|ray.dir| for the ray that
/// found the hit. No shadows: every light reaches every point it faces
/// (lecture 06 adds shadow rays). Book: §5.9 The local shading equation.
pub fn shade_local(
    material: &Material,
    diffuse: Color,
    hit: &Hit,
    v: Vec3,
    lights: &[Light],
    ambient: Color,
) -> Color {
    // SOLUTION BEGIN
    // The ambient term, then every light's diffuse and specular terms added up.
    lights.iter().fold(diffuse * ambient, |sum, light| {
        sum + shade_light(material, diffuse, hit.normal, v, &illuminate(light, hit.point))
    })
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_abs_diff_eq;
    use raylab::scene::{Attenuation, LightKind};
    use raylab::{BLACK, Float, Ray, WHITE, radians};

    const AMBIENT: Color = Color::new(0.1, 0.2, 0.3);
    const LIGHT: Color = Color::new(1.0, 0.8, 0.6);

    /// The hit of a ray coming straight down onto the floor y = 0 at the origin:
    /// point 0, normal +y, and v = +y toward the eye.
    fn floor_hit() -> Hit {
        Hit::new(&Ray::new(Vec3::Y, -Vec3::Y), 1.0, Vec3::Y)
    }

    fn directional(color: Color, toward_light: Vec3) -> Light {
        Light { color, shadows: true, kind: LightKind::Directional { direction: -toward_light } }
    }

    fn point(color: Color, position: Vec3, (c, l, q): (Float, Float, Float)) -> Light {
        let attenuation = Attenuation { constant: c, linear: l, quadratic: q };
        Light { color, shadows: true, kind: LightKind::Point { position, attenuation } }
    }

    /// L at 60° from the normal +y whose y component is exactly ½ (so N·L = ½ exactly).
    fn sixty_degrees() -> Vec3 {
        Vec3::new(Float::sqrt(3.0) / 2.0, 0.5, 0.0)
    }

    #[test]
    fn one_light_at_60_degrees_gives_ambient_plus_half_the_light() {
        // White diffuse material (k_d = 1, k_s = 0), N = y, L at 60°: by hand
        // I = 1·I_a + 1·cos 60°·I_L = I_a + ½I_L. Every step is exact here (N·L = 0·x +
        // 1·½ + 0, products by 1 and ½), so the sum rounds as the expected one does.
        let white = Material::default();
        let lights = [directional(LIGHT, sixty_degrees())];
        let i = shade_local(&white, white.diffuse, &floor_hit(), Vec3::Y, &lights, AMBIENT);
        assert_eq!(i, AMBIENT + 0.5 * LIGHT);
    }

    #[test]
    fn a_light_behind_the_surface_gives_ambient_only() {
        // Light from below the floor (directional, and a point light): N·L < 0, so no
        // diffuse and no specular, even on a shiny material; I = k_d·I_a exactly.
        let shiny = Material { specular: WHITE, exponent: 10.0, ..Material::default() };
        for model in [Specular::Phong, Specular::Blinn] {
            let m = Material { model, ..shiny.clone() };
            let lights = [directional(LIGHT, -sixty_degrees()), point(LIGHT, -Vec3::Y, (1.0, 0.0, 0.0))];
            let i = shade_local(&m, m.diffuse, &floor_hit(), Vec3::Y, &lights, AMBIENT);
            assert_eq!(i, AMBIENT, "{model:?}");
        }
    }

    #[test]
    fn two_lights_add() {
        // I = I_a + ½I_A (60°) + 1·I_B (head-on), by hand. Three additions of numbers
        // below 2: 4ε.
        let white = Material::default();
        let (a, b) = (Color::new(0.2, 0.4, 0.6), Color::new(0.5, 0.25, 1.0));
        let lights = [directional(a, sixty_degrees()), directional(b, Vec3::Y)];
        let i = shade_local(&white, white.diffuse, &floor_hit(), Vec3::Y, &lights, AMBIENT);
        assert_abs_diff_eq!(i, AMBIENT + 0.5 * a + b, epsilon = 4.0 * Float::EPSILON);
    }

    #[test]
    fn no_lights_leaves_the_ambient_term() {
        // k_a = diffuse: I = k_d ⊙ I_a, exactly.
        let m = Material::default();
        let kd = Color::new(0.5, 1.0, 0.25);
        assert_eq!(shade_local(&m, kd, &floor_hit(), Vec3::Y, &[], AMBIENT), kd * AMBIENT);
    }

    #[test]
    fn the_diffuse_argument_is_the_surface_colour_not_the_material() {
        // A texture's value replaces k_d (and k_a): the material says white, the
        // argument says (¼, ½, ¾); head-on light gives k_d ⊙ (I_a + I_L).
        let white = Material::default();
        let kd = Color::new(0.25, 0.5, 0.75);
        let lights = [directional(LIGHT, Vec3::Y)];
        let i = shade_local(&white, kd, &floor_hit(), Vec3::Y, &lights, AMBIENT);
        assert_abs_diff_eq!(i, kd * AMBIENT + kd * LIGHT, epsilon = 2.0 * Float::EPSILON);
    }

    #[test]
    fn colours_multiply_channel_by_channel() {
        // k_d = (1, ½, 0), k_s = 0.2, I_L = (½, 1, 1), light and eye head-on (Blinn H = N,
        // spec = 1): (k_d·1 + 0.2·1) ⊙ I_L = (1.2·½, 0.7·1, 0.2·1) = (0.6, 0.7, 0.2).
        let m = Material { specular: Color::splat(0.2), exponent: 30.0, ..Material::default() };
        let kd = Color::new(1.0, 0.5, 0.0);
        let sample = LightSample { direction: Vec3::Y, distance: 1.0, intensity: Color::new(0.5, 1.0, 1.0) };
        let i = shade_light(&m, kd, Vec3::Y, Vec3::Y, &sample);
        assert_abs_diff_eq!(i, Color::new(0.6, 0.7, 0.2), epsilon = 4.0 * Float::EPSILON);
    }

    #[test]
    fn the_material_chooses_phong_or_blinn() {
        // No diffuse colour, k_s = 1, N = y, L at 45°, V = N: by hand Phong gives R·V =
        // cos 45° = 0.70711, Blinn N·H = cos 22.5° = 0.92388 (exponent 1). Unit vectors
        // from sin/cos, a reflection or a normalisation: 8ε.
        let a = radians(45.0);
        let sample =
            LightSample { direction: Vec3::new(a.sin(), a.cos(), 0.0), distance: 1.0, intensity: LIGHT };
        for (model, expected) in [(Specular::Phong, a.cos()), (Specular::Blinn, (a / 2.0).cos())] {
            let m = Material { specular: WHITE, model, ..Material::default() };
            let i = shade_light(&m, BLACK, Vec3::Y, Vec3::Y, &sample);
            assert_abs_diff_eq!(i, expected * LIGHT, epsilon = 8.0 * Float::EPSILON);
        }
    }

    #[test]
    fn a_point_light_is_attenuated_before_it_is_reflected() {
        // Point light 2 above the hit, quadratic attenuation: I_L/4 arrives head-on, so
        // I = I_a + ¼I_L (exact: products by 1 and ¼).
        let white = Material::default();
        let lights = [point(LIGHT, Vec3::new(0.0, 2.0, 0.0), (0.0, 0.0, 1.0))];
        let i = shade_local(&white, white.diffuse, &floor_hit(), Vec3::Y, &lights, AMBIENT);
        assert_eq!(i, AMBIENT + 0.25 * LIGHT);
    }

    #[test]
    fn a_surface_seen_from_behind_is_lit_from_the_eyes_side() {
        // The ray comes up through the floor: the hit normal is −y (facing the eye).
        // A light below, head-on, gives I_a + I_L; a light above gives I_a only.
        let hit = Hit::new(&Ray::new(-Vec3::Y, Vec3::Y), 1.0, Vec3::Y);
        let white = Material::default();
        let below = [directional(LIGHT, -Vec3::Y)];
        let above = [directional(LIGHT, Vec3::Y)];
        assert_eq!(shade_local(&white, WHITE, &hit, -Vec3::Y, &below, AMBIENT), AMBIENT + LIGHT);
        assert_eq!(shade_local(&white, WHITE, &hit, -Vec3::Y, &above, AMBIENT), AMBIENT);
    }

    #[test]
    fn a_light_at_the_hit_point_adds_nothing_and_no_nan() {
        // The point light sits on the surface point itself: no direction, no light.
        let shiny = Material { specular: WHITE, exponent: 0.0, ..Material::default() };
        let lights = [point(LIGHT, Vec3::ZERO, (0.0, 0.0, 1.0))];
        let i = shade_local(&shiny, WHITE, &floor_hit(), Vec3::Y, &lights, AMBIENT);
        assert_eq!(i, AMBIENT);
    }

    #[test]
    fn forgetting_the_max_makes_a_back_lit_point_negative() {
        // The catalogued mistake k_d·(N·L)·I_L without max: a light at 120° gives
        // 0.1 + cos 120°·1 = −0.4 in the red channel, darker than black. The reference
        // keeps the ambient 0.1.
        let white = Material::default();
        let l = Vec3::new(Float::sqrt(3.0) / 2.0, -0.5, 0.0);
        let lights = [directional(WHITE, l)];
        let wrong = AMBIENT + WHITE * Vec3::Y.dot(l);
        let i = shade_local(&white, WHITE, &floor_hit(), Vec3::Y, &lights, AMBIENT);
        assert_eq!(i, AMBIENT);
        assert!(wrong.x < 0.0, "{wrong}");
    }

    #[test]
    fn an_unnormalised_l_makes_a_light_look_brighter_by_its_distance() {
        // The catalogued mistake L = position − point: a light 2 straight above (no
        // attenuation) gives N·L = 2 instead of 1, so I_a + 2·I_L instead of I_a + I_L:
        // a distant light looks brighter for the wrong reason. Exact (products by 1, 2).
        let white = Material::default();
        let position = Vec3::new(0.0, 2.0, 0.0);
        let lights = [point(LIGHT, position, (1.0, 0.0, 0.0))];
        let p = floor_hit().point;
        let wrong = AMBIENT + LIGHT * Vec3::Y.dot(position - p).max(0.0);
        let i = shade_local(&white, WHITE, &floor_hit(), Vec3::Y, &lights, AMBIENT);
        assert_eq!(i, AMBIENT + LIGHT);
        assert_eq!(wrong, AMBIENT + 2.0 * LIGHT);
        assert_ne!(i, wrong);
    }
}
