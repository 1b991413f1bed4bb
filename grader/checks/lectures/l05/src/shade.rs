//! The checks of `shade.rs`: shade_light and shade_local.

use super::common::*;

pub(super) fn shade_light_cases(shade: ShadeLightFn) -> CheckResult {
    // k_d = (1, ½, 0), k_s = 0.2, I_L = (½, 1, 1), L = V = N (Blinn: H = N, spec = 1):
    // (k_d·1 + 0.2·1) ⊙ I_L = (0.6, 0.7, 0.2). A few roundings of values ≤ 1.2: 4ε.
    let m = Material { specular: Color::splat(0.2), exponent: 30.0, ..Material::default() };
    let kd = Color::new(1.0, 0.5, 0.0);
    let sample = LightSample { direction: Vec3::Y, distance: 1.0, intensity: Color::new(0.5, 1.0, 1.0) };
    let case = "k_d = (1, 0.5, 0), k_s = 0.2, Blinn n = 30, I_L = (0.5, 1, 1), L = V = N = +y";
    let c = shade(&m, kd, Vec3::Y, Vec3::Y, &sample);
    let expected = Color::new(0.6, 0.7, 0.2);
    let near = |a: Color| (c - a).abs().max_element() <= 1e-4;
    let cause = if near(Color::new(0.7, 0.7, 0.2)) {
        "both terms reflect the light that arrives: (k_d·(N·L)⁺ + k_s·spec) ⊙ I_L"
    } else if near(Color::new(0.6, 1.2, 1.2)) {
        "the surface colour is the diffuse argument (a texture's value), not material.diffuse"
    } else {
        "(k_d·(N·L)⁺ + k_s·spec) ⊙ I_L, colours multiplied channel by channel"
    };
    close3(case, c, expected, 4.0 * EPS, cause)?;
    // No diffuse colour, k_s = 1, N = V = y, L at 45°: Phong cos 45°, Blinn cos 22.5°
    // (exponent 1), times I_L; exponent 10: (cos 45°)¹⁰ = 1/32. Unit vectors from sin/cos,
    // a reflection or a normalisation: 8ε.
    let sample = LightSample { direction: at_angle(45.0), distance: 1.0, intensity: COLOR };
    for (model, exponent, expected) in [
        (Specular::Phong, 1.0, radians(45.0).cos()),
        (Specular::Blinn, 1.0, radians(22.5).cos()),
        (Specular::Phong, 10.0, 1.0 / 32.0),
    ] {
        let m = Material { specular: WHITE, model, exponent, ..Material::default() };
        let case = format!("k_d = 0, k_s = 1, {model:?} n = {exponent}, N = V = +y, L at 45°");
        let c = shade(&m, BLACK, Vec3::Y, Vec3::Y, &sample);
        let cause = if model == Specular::Phong && (c.x - radians(22.5).cos()).abs() < 1e-4
            || model == Specular::Blinn && (c.x - radians(45.0).cos()).abs() < 1e-4
        {
            "use material.model: Specular::Phong → phong_specular, Specular::Blinn → blinn_specular"
        } else if exponent != 1.0 && (c.x - radians(45.0).cos()).abs() < 1e-4 {
            "the highlight's exponent is material.exponent"
        } else {
            "k_s·spec ⊙ I_L with the material's highlight model and exponent"
        };
        close3(&case, c, COLOR * expected, 8.0 * EPS, cause)?;
    }
    // A light behind the surface, a shiny material: nothing at all.
    let m = Material { specular: WHITE, exponent: 10.0, ..Material::default() };
    let sample = LightSample { direction: at_angle(120.0), distance: 1.0, intensity: WHITE };
    let case = "white k_d, k_s = 1, L at 120° (behind the surface)";
    let c = shade(&m, WHITE, Vec3::Y, Vec3::Y, &sample);
    close3(case, c, BLACK, 0.0, "a light behind the surface adds nothing: (N·L)⁺ = 0 and no highlight")?;
    Ok("5 cases".into())
}

pub(super) const AMBIENT: Color = Color::new(0.1, 0.2, 0.3);
pub(super) const LIGHT: Color = Color::new(1.0, 0.8, 0.6);

/// The hit of a ray straight down onto the floor y = 0 at the origin: normal +y.
pub(super) fn floor_hit() -> Hit {
    Hit::new(&Ray::new(Vec3::Y, -Vec3::Y), 1.0, Vec3::Y)
}

pub(super) fn directional(color: Color, toward_light: Vec3) -> Light {
    Light { color, shadows: true, kind: LightKind::Directional { direction: -toward_light } }
}

/// L at 60° from +y with y exactly ½ (N·L = ½ exactly).
pub(super) fn sixty() -> Vec3 {
    v((3.0 as Float).sqrt() / 2.0, 0.5, 0.0)
}

pub(super) fn shade_local_cases(shade: ShadeLocalFn) -> CheckResult {
    let white = Material::default();
    let check = |case: &str, got: Color, expected: Color, tolerance: Float, cause: &str| {
        close3(case, got, expected, tolerance, cause)
    };
    // No lights: k_a ⊙ I_a with k_a = the diffuse argument (exact).
    let kd = Color::new(0.5, 1.0, 0.25);
    let case = "no lights, diffuse (0.5, 1, 0.25), ambient (0.1, 0.2, 0.3)";
    let c = shade(&white, kd, &floor_hit(), Vec3::Y, &[], AMBIENT);
    let cause = if c == AMBIENT {
        "the ambient term is k_a ⊙ I_a with k_a = the diffuse argument"
    } else {
        "with no lights only the ambient term k_d ⊙ I_a is left"
    };
    check(case, c, kd * AMBIENT, 0.0, cause)?;
    // One directional light at 60°, white matte: I_a + ½I_L, exact (products by 1 and ½).
    let case = "white matte floor n = +y, one directional light at 60° of (1, 0.8, 0.6)";
    let c = shade(&white, WHITE, &floor_hit(), Vec3::Y, &[directional(LIGHT, sixty())], AMBIENT);
    check(
        case,
        c,
        AMBIENT + 0.5 * LIGHT,
        2.0 * EPS,
        "I = k_a ⊙ I_a + Σ shade_light(…, illuminate(light, p))",
    )?;
    // Two lights add: I_a + ½I_A + I_B (4ε: three additions of values below 2).
    let (a, b) = (Color::new(0.2, 0.4, 0.6), Color::new(0.5, 0.25, 1.0));
    let lights = [directional(a, sixty()), directional(b, Vec3::Y)];
    let case = "the same floor, lights (0.2, 0.4, 0.6) at 60° and (0.5, 0.25, 1) head-on";
    let c = shade(&white, WHITE, &floor_hit(), Vec3::Y, &lights, AMBIENT);
    let cause = if (c - (AMBIENT + b)).abs().max_element() < 1e-4 {
        "add every light's term: the sum over all the lights"
    } else if (c - (2.0 * AMBIENT + 0.5 * a + b)).abs().max_element() < 1e-4 {
        "add the ambient term once, then each light's term"
    } else {
        "the lights' terms add: I_a + Σ shade_light(…)"
    };
    check(case, c, AMBIENT + 0.5 * a + b, 4.0 * EPS, cause)?;
    // A point light 2 above, quadratic attenuation: I_a + ¼I_L (exact).
    let point = Light {
        color: LIGHT,
        shadows: true,
        kind: LightKind::Point { position: v(0.0, 2.0, 0.0), attenuation: attenuation(0.0, 0.0, 1.0) },
    };
    let case = "the same floor, a point light 2 above it, attenuation (0, 0, 1)";
    let c = shade(&white, WHITE, &floor_hit(), Vec3::Y, &[point], AMBIENT);
    check(
        case,
        c,
        AMBIENT + 0.25 * LIGHT,
        2.0 * EPS,
        "each light reaches the point through illuminate(light, hit.point): its direction, distance and attenuation",
    )?;
    // A light below the floor: ambient only, even on a shiny material.
    let shiny = Material { specular: WHITE, exponent: 10.0, model: Specular::Phong, ..Material::default() };
    let case = "shiny floor n = +y, a directional light from below it";
    let c = shade(&shiny, WHITE, &floor_hit(), Vec3::Y, &[directional(LIGHT, -sixty())], AMBIENT);
    check(case, c, AMBIENT, 0.0, "a light behind the surface adds nothing")?;
    // Seen from below: the hit's normal is −y (facing the eye), a light below lights it.
    let hit = Hit::new(&Ray::new(-Vec3::Y, Vec3::Y), 1.0, Vec3::Y);
    let case = "the floor seen from below (normal −y), a directional light from below, head-on";
    let c = shade(&white, WHITE, &hit, -Vec3::Y, &[directional(LIGHT, -Vec3::Y)], AMBIENT);
    check(case, c, AMBIENT + LIGHT, 2.0 * EPS, "shade with hit.normal, which faces the eye")?;
    Ok("6 cases".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l05_shading::{blinn_specular, illuminate, lambert, shade_light};
    use raylab::scene::{Light, Material};
    use raylab::{Color, Hit, Vec3};

    #[test]
    fn shade_light_mistakes_are_caught() {
        // The specular term not times the light.
        caught(
            shade_light_cases(|m, kd, n, v, s| {
                kd * lambert(n, s.direction) * s.intensity
                    + m.specular * blinn_specular(n, s.direction, v, m.exponent)
            }),
            "both terms reflect",
        );
        // material.diffuse instead of the argument.
        caught(
            shade_light_cases(|m, _kd, n, v, s| shade_light(m, m.diffuse, n, v, s)),
            "not material.diffuse",
        );
        // Always Blinn.
        caught(
            shade_light_cases(|m, kd, n, v, s| {
                let spec = blinn_specular(n, s.direction, v, m.exponent);
                (kd * lambert(n, s.direction) + m.specular * spec) * s.intensity
            }),
            "use material.model",
        );
    }

    #[test]
    fn shade_local_mistakes_are_caught() {
        fn sum(
            m: &Material,
            kd: Color,
            hit: &Hit,
            v: Vec3,
            lights: &[Light],
            ambient: Color,
            per_light: bool,
        ) -> Color {
            let mut c = if per_light { Color::ZERO } else { kd * ambient };
            for l in lights {
                if per_light {
                    c += kd * ambient;
                }
                c += shade_light(m, kd, hit.normal, v, &illuminate(l, hit.point));
            }
            c
        }
        // Ambient added once per light.
        caught(shade_local_cases(|m, kd, h, v, l, a| sum(m, kd, h, v, l, a, true)), "no lights");
        // Ambient not times the diffuse colour.
        caught(
            shade_local_cases(|m, kd, h, v, l, a| sum(m, kd, h, v, l, a, false) - kd * a + a),
            "k_a = the diffuse argument",
        );
        // Only the last light kept.
        caught(
            shade_local_cases(|m, kd, h, v, l, a| {
                sum(m, kd, h, v, &l[l.len().saturating_sub(1)..], a, false)
            }),
            "sum over all the lights",
        );
    }
}
