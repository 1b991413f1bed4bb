//! The checks of `shade.rs`: visibility and shade_with_shadows.

use super::common::*;

/// Materials: 0 the grey floor (k_d = ½, opaque), 1 an opaque ball, 2 a ball of k_t = ½.
pub(super) fn materials() -> Vec<Material> {
    let grey = Material { diffuse: Color::splat(0.5), ..Material::default() };
    vec![grey.clone(), grey, see_through(Color::splat(0.5))]
}

/// The floor point (x, 0, z) seen from 5 away, up and in front: the hit and its eye.
pub(super) fn floor_hit(x: Float, z: Float) -> (Hit, Vec3) {
    let ray = Ray::new(v(x, 3.0, z + 4.0), v(0.0, -3.0, -4.0) / 5.0);
    (Hit::new(&ray, 5.0, Vec3::Y), ray.origin)
}

pub(super) fn surface<'a>(material: &'a Material, hit: Hit, eye: Vec3) -> Surface<'a> {
    Surface { material, diffuse: material.diffuse, hit, v: (eye - hit.point).normalize(), origin: eye }
}

pub(super) fn visibility_cases(visibility: VisibilityFn) -> CheckResult {
    let materials = materials();
    // The floor y = 0 seen from (0, 500, 700), points within 0.1 of the world origin, a light
    // straight above: nothing blocks it. Each point carries an error of a few ulp of the eye
    // (o + t·d cancels): only a shadow ray offset by the eye's scale leaves the floor.
    let scene = Scene::new(&[floor(0.0, 0)]);
    let eye = v(0.0, 500.0, 700.0);
    let mut rng = Rng::new(0xe_7e);
    for _ in 0..500 {
        let aim = v(rng.range(-0.1, 0.1), 0.0, rng.range(-0.1, 0.1));
        let ray = Ray::new(eye, (aim - eye).normalize());
        let Some(hit) = scene.closest_hit(&ray, Interval::POSITIVE) else { continue };
        let s = surface(&materials[0], hit, eye);
        let case = format!(
            "floor y = 0 seen from (0, 500, 700) at {}, light straight up, nothing above",
            vec3(hit.point)
        );
        for mode in [ShadowMode::Opaque, ShadowMode::Transmissive] {
            let got = visibility(&scene, &materials, &s, &toward(Vec3::Y), mode);
            ensure(
                got == WHITE,
                &case,
                "(1, 1, 1)",
                vec3(got),
                "start the shadow ray just off the surface: offset_origin(p, N, L, surface.origin), the eye as from",
            )?;
        }
    }
    // A ball above the floor's origin: opaque blocks; transparent (k_t = ½) blocks in Opaque
    // mode and passes ½·½ in Transmissive mode.
    let (hit, eye) = floor_hit(0.0, 0.0);
    let s = surface(&materials[0], hit, eye);
    for (ball, mode, expected, cause) in [
        (1, ShadowMode::Opaque, BLACK, "a blocker between the point and the light: black"),
        (1, ShadowMode::Transmissive, BLACK, "an opaque blocker passes nothing, in either mode"),
        (2, ShadowMode::Opaque, BLACK, "in Opaque mode every blocker blocks: occluded → black"),
        (
            2,
            ShadowMode::Transmissive,
            Color::splat(0.25),
            "in Transmissive mode the visibility is transmittance(…)",
        ),
    ] {
        let scene = Scene::new(&[floor(0.0, 0), sphere(0.0, 2.0, 0.0, 1.0, ball)]);
        let case = format!(
            "floor point (0, 0, 0) under a {} ball at (0, 2, 0), light straight up, {mode:?}",
            if ball == 1 { "opaque" } else { "k_t = ½" }
        );
        let got = visibility(&scene, &materials, &s, &toward(Vec3::Y), mode);
        ensure(got == expected, case, vec3(expected), vec3(got), cause)?;
    }
    Ok("1004 cases".into())
}

pub(super) fn directional(toward_light: Vec3, shadows: bool) -> Light {
    Light { color: WHITE, shadows, kind: LightKind::Directional { direction: -toward_light } }
}

pub(super) const AMBIENT: Color = Color::splat(0.1);

pub(super) fn shade_cases(shade: ShadeFn) -> CheckResult {
    let materials = materials();
    let show = |(c, n): (Color, u64)| format!("{} with {n} shadow rays", vec3(c));
    let run = |shapes: &[(Shape, usize)], lights: &[Light], x: Float, mode: ShadowMode| {
        let (hit, eye) = floor_hit(x, 0.0);
        let s = surface(&materials[0], hit, eye);
        let scene = Scene::new(shapes);
        let settings = ShadowSettings { mode, area_samples: 16 };
        let (c, stats) = measured(|| shade(&scene, &materials, &s, lights, AMBIENT, settings));
        (c, stats.get(Counter::ShadowRays))
    };
    let floor_and = |ball: usize| [floor(0.0, 0), sphere(0.0, 2.0, 0.0, 1.0, ball)];
    let up = [directional(Vec3::Y, true)];
    // k_a ⊙ I_a = ½·0.1 = 0.05 (exact) under the ball; beside it + k_d·(N·L)·I = 0.55 (2ε).
    let shadowed = Color::splat(0.05);
    let lit = Color::splat(0.55);
    let cases = [
        (
            "floor (0, 0, 0) under an opaque ball, light straight up, Opaque",
            floor_and(1).to_vec(),
            up.to_vec(),
            0.0,
            ShadowMode::Opaque,
            shadowed,
            1,
        ),
        (
            "floor (3, 0, 0) beside an opaque ball, light straight up",
            floor_and(1).to_vec(),
            up.to_vec(),
            3.0,
            ShadowMode::Opaque,
            lit,
            1,
        ),
        (
            "floor (0, 0, 0) under a ball of k_t = ½, light straight up, Transmissive",
            floor_and(2).to_vec(),
            up.to_vec(),
            0.0,
            ShadowMode::Transmissive,
            Color::splat(0.175),
            3,
        ),
        (
            "floor (0, 0, 0) under an opaque ball, a light with shadows = false",
            floor_and(1).to_vec(),
            vec![directional(Vec3::Y, false)],
            0.0,
            ShadowMode::Opaque,
            lit,
            0,
        ),
        (
            "floor (3, 0, 0), a light below the floor",
            floor_and(1).to_vec(),
            vec![directional(-Vec3::Y, true)],
            3.0,
            ShadowMode::Opaque,
            shadowed,
            0,
        ),
    ];
    for (case, shapes, lights, x, mode, expected, rays) in cases {
        let got = run(&shapes, &lights, x, mode);
        let near = |a: Color| (got.0 - a).abs().max_element() <= 1e-4;
        let cause = if near(BLACK) {
            "the ambient term k_a ⊙ I_a is never shadowed"
        } else if near(lit) && expected == shadowed && rays > 0 {
            "trace a shadow ray toward each light that casts shadows: visible = visibility(…)"
        } else if near(shadowed) && expected != shadowed && mode == ShadowMode::Transmissive {
            "pass settings.mode to visibility: in Transmissive mode a blocker filters by its k_t"
        } else if near(shadowed) && !lights[0].shadows {
            "a light with shadows = false is never blocked: cast no shadow ray for it"
        } else if near(expected) && !lights[0].shadows {
            "a light with shadows = false casts no shadow ray"
        } else if near(expected) {
            "no shadow ray for a light behind the surface (N·L ≤ 0): it adds nothing anyway"
        } else {
            "I = k_a ⊙ I_a + Σ visibility ⊙ shade_light(…, illuminate(light, p))"
        };
        let ok = crate::check::near3(got.0, expected, 2.0 * EPS) && got.1 == rays;
        ensure(ok, case, show((expected, rays)), show(got), cause)?;
    }
    // A spot aimed away (the point 63° off its 10° cone): nothing to add, no shadow ray.
    let spot = Light {
        color: WHITE,
        shadows: true,
        kind: LightKind::Spot {
            position: v(10.0, 5.0, 0.0),
            direction: -Vec3::Y,
            inner: radians(5.0),
            outer: radians(10.0),
            attenuation: Attenuation::default(),
        },
    };
    let case = "floor (0, 0, 0), a spot at (10, 5, 0) aimed down with a 10° cone (the point is outside it)";
    let got = run(&floor_and(1), &[spot], 0.0, ShadowMode::Opaque);
    ensure(
        got == (shadowed, 0),
        case,
        show((shadowed, 0)),
        show(got),
        "no shadow ray for a light that sends nothing here (shade_light is black)",
    )?;
    // An area light with shadows under an opaque roof: sampled with 16 shadow rays, all blocked.
    let panel = Light {
        color: WHITE,
        shadows: true,
        kind: LightKind::Rect {
            corner: v(-0.5, 20.0, -0.5),
            edge_u: Vec3::X,
            edge_v: Vec3::Z,
            attenuation: Attenuation::default(),
        },
    };
    let case = "floor (0, 0, 0) under an opaque roof y = 10, a 1 × 1 rect light at height 20, 16 samples";
    let got = run(&[floor(0.0, 0), floor(10.0, 1)], &[panel], 0.0, ShadowMode::Opaque);
    ensure(
        got == (shadowed, 16),
        case,
        show((shadowed, 16)),
        show(got),
        "an area light that casts shadows is sampled: shade_area_light, settings.area_samples shadow rays",
    )?;
    Ok("7 cases".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l05_shading::{illuminate, shade_light};
    use l06_shadows::{
        ShadowMode, ShadowSettings, Surface, occluded, shade_area_light, transmittance, visibility,
    };

    use raylab::scene::{Light, LightKind, Material};

    use raylab::{BLACK, Color, Intersector, WHITE};

    #[test]
    fn visibility_mistakes_are_caught() {
        // The shadow ray from the hit point itself.
        caught(
            visibility_cases(|scene, materials, surface, sample, mode| match mode {
                ShadowMode::Opaque if occluded(scene, surface.hit.point, sample) => BLACK,
                ShadowMode::Opaque => WHITE,
                ShadowMode::Transmissive => transmittance(scene, materials, surface.hit.point, sample),
            }),
            "just off the surface",
        );
        // The offset from the hit point alone (from = p): fails where the eye is far.
        caught(
            visibility_cases(|scene, materials, surface, sample, mode| {
                let p = surface.hit.point;
                let s = Surface { origin: p, ..*surface };
                visibility(scene, materials, &s, sample, mode)
            }),
            "the eye as from",
        );
        // Every blocker opaque, whatever the mode.
        caught(
            visibility_cases(|scene, materials, surface, sample, _| {
                visibility(scene, materials, surface, sample, ShadowMode::Opaque)
            }),
            "Transmissive mode",
        );
    }

    /// Shading with shadows with a chosen slip (point and directional lights only; area
    /// lights through the reference).
    fn shade_with(
        scene: &dyn Intersector,
        materials: &[Material],
        s: &Surface,
        lights: &[Light],
        ambient: Color,
        settings: ShadowSettings,
        slip: &str,
    ) -> Color {
        let mut color = s.diffuse * ambient;
        let mut lit = BLACK;
        for light in lights {
            let area = matches!(light.kind, LightKind::Rect { .. } | LightKind::Sphere { .. });
            if area && light.shadows && slip != "area as point" {
                lit += shade_area_light(scene, materials, s, light, settings);
                continue;
            }
            let sample = illuminate(light, s.hit.point);
            if s.hit.normal.dot(sample.direction) <= 0.0 && slip != "rays behind" {
                continue;
            }
            let direct = shade_light(s.material, s.diffuse, s.hit.normal, s.v, &sample);
            if direct == BLACK && slip != "rays for black" && slip != "rays behind" {
                continue;
            }
            let visible = if light.shadows || slip == "ignore flag" {
                visibility(scene, materials, s, &sample, settings.mode)
            } else {
                WHITE
            };
            lit += visible * direct;
            if slip == "shadowed ambient" && visible == BLACK {
                color = BLACK;
            }
        }
        color + lit
    }

    #[test]
    fn shade_with_shadows_mistakes_are_caught() {
        caught(
            shade_cases(|a, b, c, d, e, f| shade_with(a, b, c, d, e, f, "shadowed ambient")),
            "never shadowed",
        );
        caught(
            shade_cases(|a, b, c, d, e, f| shade_with(a, b, c, d, e, f, "ignore flag")),
            "shadows = false",
        );
        caught(
            shade_cases(|a, b, c, d, e, f| shade_with(a, b, c, d, e, f, "rays behind")),
            "behind the surface",
        );
        caught(shade_cases(|a, b, c, d, e, f| shade_with(a, b, c, d, e, f, "area as point")), "is sampled");
        caught(
            shade_cases(|a, b, c, d, e, f| shade_with(a, b, c, d, e, f, "rays for black")),
            "sends nothing here",
        );
        assert!(shade_cases(|a, b, c, d, e, f| shade_with(a, b, c, d, e, f, "")).is_ok());
    }
}
