//! The checks of `trace.rs`: trace_ray.

use super::common::*;

/// Unit cases with answers by hand.
pub(super) fn trace_cases(trace: TraceFn) -> CheckResult {
    let settings = TraceSettings::default();

    // A miss: the background, exactly, and nothing spawned.
    let s = mirror_and_wall(1.0);
    let case = "eye ray from the origin along +y, past a mirror and a wall (background (0.2, 0.3, 0.4))";
    let (color, counted) = traced(trace, &s, &Ray::new(Vec3::ZERO, Vec3::Y), &settings);
    ensure(
        color == BACKGROUND && counted == rays(0, 0, 0),
        case,
        format!("{} exactly, {}", vec3(BACKGROUND), rays(0, 0, 0)),
        format!("{}, {counted}", vec3(color)),
        "a ray that hits nothing sees scene.background and spawns nothing",
    )?;

    // The mirror head-on at (0, 0, −2): black, lit from behind, so its own shading is 0 and
    // it casts no shadow ray. Its mirror ray goes straight back to the wall z = 3, normal −z:
    // N·L = 1/√2, its shadow ray unblocked: I = k_r·k_d⊙(0.1 + 1/√2). One mirror ray, one
    // shadow ray.
    let wall = v(0.8, 0.4, 0.2) * (0.1 + Float::sqrt(0.5));
    for kr in [1.0, 0.5] {
        let s = mirror_and_wall(kr);
        let case = format!("mirror (k_r = {kr}) head-on at z = −2, lit wall z = 3 behind the eye");
        let (color, counted) = traced(trace, &s, &Ray::new(Vec3::ZERO, -Vec3::Z), &settings);
        if counted.reflected == 0 {
            return Err(fail(
                case,
                format!("{} (± {COLOR_TOL:.1e} each), {}", vec3(kr * wall), rays(1, 0, 1)),
                format!("{}, {counted}", vec3(color)),
                "spawn a mirror ray when k_r ≠ 0 and its weight w·max(k_r) ≥ settings.min_weight",
            ));
        }
        if kr != 1.0 && near(color, wall, COLOR_TOL) {
            return Err(fail(
                case,
                format!("{} (± {COLOR_TOL:.1e} each)", vec3(kr * wall)),
                vec3(color),
                "weight what the mirror ray sees by k_r: I += k_r ⊙ trace(mirror ray)",
            ));
        }
        same_color(
            &case,
            color,
            kr * wall,
            COLOR_TOL,
            "the mirror ray leaves from offset_origin(p, N, r, ray.origin) in mirror_direction(d, N) and \
             adds k_r ⊙ what it sees",
        )?;
    }

    // Facing mirrors at normal incidence, k_r = 1: the rays of depths 1..=D are spawned and
    // the one of depth D spawns nothing: exactly D mirror rays; each of the D + 1 hits adds
    // k_d⊙I_a = 0.1, so I = 0.1·(D + 1).
    let (s, ray) = facing_mirrors(1.0);
    for depth in [0u32, 1, 2, 5] {
        let settings = TraceSettings { max_depth: depth, ..TraceSettings::default() };
        let case = format!("facing mirrors x = ±1 (k_r = 1), ray along +x, max_depth {depth}");
        let (color, counted) = traced(trace, &s, &ray, &settings);
        let n = u64::from(depth);
        if counted.reflected != n {
            let cause = if counted.reflected == n + 1 || counted.reflected + 1 == n {
                "off by one: the eye ray has depth 0 and a ray of depth max_depth spawns nothing (stop when \
                 depth ≥ max_depth)"
            } else {
                "children are traced at depth + 1, and a ray of depth ≥ max_depth spawns none"
            };
            return Err(fail(
                case,
                format!("{n} mirror rays"),
                format!("{} mirror rays", counted.reflected),
                cause,
            ));
        }
        let expected = Color::splat(0.1 * (depth + 1) as Float);
        same_color(
            &case,
            color,
            expected,
            COLOR_TOL,
            "every hit adds its local shading k_d⊙I_a to what its mirror ray sees",
        )?;
    }

    // The weight rule: k_r = 0.9, min_weight 0.01, depth out of reach: the k-th mirror ray
    // weighs 0.9ᵏ and is spawned while 0.9ᵏ ≥ 0.01, k ≤ ln 0.01/ln 0.9 = 43.7: 43 rays
    // (0.9⁴³ = 0.0108, 0.9⁴⁴ = 0.0097, far from the cut-off in either precision). The hits
    // add 0.1·Σ_{k=0}^{43} 0.9ᵏ = 1 − 0.9⁴⁴. Tolerance: 44 products and sums below 1, ≤ 88ε,
    // in any order: 256ε.
    let (s, ray) = facing_mirrors(0.9);
    let settings = TraceSettings { max_depth: 1000, ..TraceSettings::default() };
    let case = "facing mirrors (k_r = 0.9), min_weight 0.01, max_depth 1000";
    let (color, counted) = traced(trace, &s, &ray, &settings);
    if counted.reflected != 43 {
        let cause = match counted.reflected {
            44 => "compare the child's weight w·max(k_r) with min_weight, not the parent's weight",
            n if n >= 1000 => "spawn a child only when its weight w·max(k_r) ≥ settings.min_weight",
            _ => "pass the child its weight, weight·max(k_r), and spawn it only when that is ≥ min_weight",
        };
        return Err(fail(case, "43 mirror rays", format!("{} mirror rays", counted.reflected), cause));
    }
    let expected = (1.0 - 0.9f64.powi(44)) as Float;
    close(case, color.x, expected, 256.0 * EPS, "every hit adds k_d⊙I_a, each mirror ray weighted by k_r")?;
    // Without the weight rule the depth limit stops it.
    let settings = TraceSettings { max_depth: 100, min_weight: 0.0, ..settings };
    let (_, counted) = traced(trace, &s, &ray, &settings);
    ensure(
        counted.reflected == 100,
        "facing mirrors (k_r = 0.9), min_weight 0, max_depth 100",
        "100 mirror rays",
        format!("{} mirror rays", counted.reflected),
        "with min_weight 0 only the depth limit stops the tree",
    )?;
    // A black mirror spawns nothing, even with the cut-off at 0.
    let (s, ray) = facing_mirrors(0.0);
    let settings = TraceSettings { min_weight: 0.0, ..TraceSettings::default() };
    let (color, counted) = traced(trace, &s, &ray, &settings);
    same_tree(
        "facing mirrors with k_r = 0 (black), min_weight 0",
        (color, counted),
        Color::splat(0.1),
        rays(0, 0, 0),
        "a child of weight 0 adds nothing: spawn it only when w·max(k) > 0",
    )?;

    // Total internal reflection at 60° from the normal of the glass's top face (above
    // θ_c = arcsin(1/1.5) = 41.8°): no transmitted ray, the whole k_t = 1 goes to the mirror
    // ray, which goes down at 60° from (0.866, 0, 0) to the tile's top y = −0.8 at
    // x = 0.866 + 0.8·tan 60° = 2.25: the tile's k_d⊙I_a = (0.1, 0.3, 0.2), exactly.
    let tile = v(0.2, 0.6, 0.4) * 0.5;
    let (s, ray) = block_with_tile(60.0);
    for fresnel in [false, true] {
        let settings = TraceSettings { fresnel, ..TraceSettings::default() };
        let case = format!("inside glass (η = 1.5), ray up at 60° to the top face (TIR), fresnel {fresnel}");
        let (color, counted) = traced(trace, &s, &ray, &settings);
        if counted.refracted > 0 {
            return Err(fail(
                case,
                format!("{} (± {COLOR_TOL:.1e} each), {}", vec3(tile), rays(1, 0, 0)),
                format!("{}, {counted}", vec3(color)),
                "leaving the glass η = η_i/η_t = 1.5/1, from 07's interface(hit, ior) (back face): at 60° \
                 that is total internal reflection",
            ));
        }
        if counted.reflected == 0 {
            return Err(fail(
                case,
                format!("{} (± {COLOR_TOL:.1e} each), {}", vec3(tile), rays(1, 0, 0)),
                format!("{}, {counted}", vec3(color)),
                "under total internal reflection refract gives None: all of k_t goes to the mirror ray \
                 (k_r' = k_r + k_t)",
            ));
        }
        same_color(
            &case,
            color,
            tile,
            COLOR_TOL,
            "the totally reflected ray carries k_r + k_t and sees the tile",
        )?;
    }
    // Below the critical angle (30°: sin²θ_t = 2.25·¼ < 1) the ray leaves into the sky.
    let (s, ray) = block_with_tile(30.0);
    let case = "inside glass (η = 1.5), ray up at 30° to the top face (leaves into the sky)";
    let (color, counted) = traced(trace, &s, &ray, &TraceSettings::default());
    same_tree(
        case,
        (color, counted),
        v(1.0, 0.0, 1.0),
        rays(0, 1, 0),
        "below the critical angle the transmitted ray (07's refract with interface's η) leaves the glass",
    )?;

    // Head-on into a glass block (η = 1.5, k_t = 1, k_r = 0) holding a tile, one bounce:
    // R = ((1 − 1.5)/(1 + 1.5))² = 0.04. Without Fresnel only the transmitted ray, weight 1,
    // sees the tile; with it, the mirror ray (0.04) sees the sky B behind the eye and the
    // transmitted one (0.96) the tile.
    let (s, ray) = tile_in_glass();
    let sky = s.background;
    let settings = TraceSettings { max_depth: 1, ..TraceSettings::default() };
    let case = "head-on into glass (η = 1.5) holding a tile, max_depth 1, fresnel off";
    let (color, counted) = traced(trace, &s, &ray, &settings);
    same_tree(
        case,
        (color, counted),
        tile,
        rays(0, 1, 0),
        "without settings.fresnel, R = 0: clear glass spawns one transmitted ray of weight k_t",
    )?;
    let case = "head-on into glass (η = 1.5) holding a tile, max_depth 1, fresnel on";
    let (color, counted) = traced(trace, &s, &ray, &TraceSettings { fresnel: true, ..settings });
    let expected = 0.04 * sky + 0.96 * tile;
    same_tree(
        case,
        (color, counted),
        expected,
        rays(1, 1, 0),
        "with settings.fresnel, R = fresnel_dielectric(−d·N, η_i, η_t): k_r' = k_r + R·k_t, k_t' = (1 − R)·k_t",
    )?;
    // Through the glass block without its tile, max_depth 1 (found by mutation testing: the
    // transmitted child at depth instead of depth + 1 passed): the transmitted ray (depth 1)
    // reaches the back face z = −10 and spawns nothing. Black glass under ambient light adds
    // 0 at both faces: black, one refracted ray; one more depth would add the sky.
    let mut clear = s.clone();
    clear.objects.truncate(1);
    let case = "head-on through a glass block (η = 1.5), nothing inside, max_depth 1, fresnel off";
    let (color, counted) = traced(trace, &clear, &ray, &settings);
    same_tree(
        case,
        (color, counted),
        Color::ZERO,
        rays(0, 1, 0),
        "every child, transmitted ones too, is traced at depth + 1: the ray of depth max_depth spawns nothing",
    )?;

    // The same with tinted glass, k_t = ½ (found by mutation testing: k_r + R/k_t passed where
    // k_t = 1): k_r' = 0.04·½ = 0.02 on the sky, k_t' = 0.96·½ = 0.48 on the tile.
    let mut tinted = s.clone();
    tinted.materials[0].transparent = Color::splat(0.5);
    let case = "head-on into tinted glass (η = 1.5, k_t = ½) holding a tile, max_depth 1, fresnel on";
    let (color, counted) = traced(trace, &tinted, &ray, &TraceSettings { fresnel: true, ..settings });
    let expected = 0.02 * sky + 0.48 * tile;
    same_tree(
        case,
        (color, counted),
        expected,
        rays(1, 1, 0),
        "R moves R·k_t into the mirror ray: k_r' = k_r + R·k_t, k_t' = (1 − R)·k_t",
    )?;

    // A shiny sphere head-on, lit along the view, with and without shadow rays (found by
    // mutation testing: V = d instead of −d passed without them): N = L = V = +z at the hit,
    // so H = N and the highlight is k_s·1⁸; I = k_d⊙(0.1 + 1) + k_s.
    let shiny = raylab::scene::Material {
        diffuse: v(0.6, 0.4, 0.2),
        specular: Color::splat(0.5),
        exponent: 8.0,
        ..matte(Color::ONE)
    };
    let s = scene(
        vec![sphere(v(0.0, 0.0, -5.0), 1.0, 0)],
        vec![shiny],
        vec![directional(Vec3::Z, Color::ONE)],
        Color::ZERO,
        Color::splat(0.1),
    );
    let expected = v(0.6, 0.4, 0.2) * 1.1 + Color::splat(0.5);
    for shadows in [false, true] {
        let case = format!("a shiny sphere (k_s = ½, n = 8) head-on, lit along the view, shadows {shadows}");
        let settings = TraceSettings { shadows, ..TraceSettings::default() };
        let (color, _) = traced(trace, &s, &Ray::new(Vec3::ZERO, -Vec3::Z), &settings);
        ensure(
            near(color, expected, COLOR_TOL),
            &case,
            format!("{} (± {COLOR_TOL:.1e} each)", vec3(expected)),
            vec3(color),
            "the local shading's view vector V points back toward the eye: −d, with shadows or without",
        )?;
    }
    Ok("12 scenes".into())
}

/// A clear glass ball (η = 1.5) of radius 10⁻⁵ one unit in front of the eye, a matte wall
/// z = −3 behind it, no lights, ambient ½, black sky. Rays aimed at the ball at impact
/// parameters 0 to 0.9 of its radius, in four directions around it: each must enter and find
/// its exit (two refracted rays: a ray into a ball leaves at the angle it entered, so there
/// is no total internal reflection and no mirror ray without Fresnel) and then meet the
/// wall (bent by at most 2(arcsin 0.9 − arcsin 0.6) = 54°, still toward −z): k_d⊙I_a
/// exactly, whatever the bend.
pub(super) fn tiny_glass_sphere(trace: TraceFn) -> CheckResult {
    let radius: Float = 1.0e-5;
    let center = v(0.0, 0.0, -1.0);
    let wall = v(0.8, 0.4, 0.2);
    let s = scene(
        vec![sphere(center, radius, 0), plane(Vec3::Z, -3.0, 1)],
        vec![glass(1.5), matte(wall)],
        vec![],
        Color::ZERO,
        Color::splat(0.5),
    );
    let expected = wall * 0.5;
    let settings = TraceSettings::default();
    let mut rays_traced = 0;
    for b in [0.0, 0.3, 0.6, 0.9] {
        for side in [Vec3::X, Vec3::Y, -Vec3::X, v(0.6, -0.8, 0.0)] {
            let target = center + b * radius * side;
            let ray = Ray::new(Vec3::ZERO, target.normalize());
            let case = format!(
                "glass ball r = 1e-5 at (0, 0, −1), eye ray from the origin at {} of the radius off its \
                 centre toward {}",
                b,
                vec3(side)
            );
            let (color, counted) = traced(trace, &s, &ray, &settings);
            rays_traced += 1;
            if counted.refracted < 2 {
                return Err(fail(
                    case,
                    format!("{} (± {COLOR_TOL:.1e} each), {}", vec3(expected), rays(0, 2, 0)),
                    format!("{}, {counted}", vec3(color)),
                    "the ray inside missed the exit: start refracted rays at 06's offset_origin(p, N, t, \
                     ray.origin) and search (0, ∞), no fixed epsilon (10⁻⁴ jumps across a ball of radius \
                     10⁻⁵)",
                ));
            }
            same_tree(
                &case,
                (color, counted),
                expected,
                rays(0, 2, 0),
                "after the exit the ray meets the wall: the ray inside must leave the ball where it \
                 exits, not bounce inside it",
            )?;
        }
    }
    Ok(format!("{rays_traced} rays through the tiny ball, each in and out"))
}

#[cfg(test)]
mod tests {
    use super::*;

    use l05_shading::shade_local;
    use l06_shadows::{ShadowSettings, Surface, offset_origin, shade_with_shadows};
    use l07_reflection_refraction::{fresnel_dielectric, interface, mirror_direction, refract};
    use l08_ray_tree::{TraceSettings, World};

    use raylab::stats::{Counter, count};
    use raylab::{BLACK, Color, Float, Interval, Ray};

    /// The mistakes planted in a copy of the reference tracer.
    #[derive(Clone, Copy, PartialEq)]
    enum Slip {
        None,
        /// `depth > max_depth` instead of `≥`.
        DepthOffByOne,
        /// No weight cut-off.
        NoWeightRule,
        /// The mirror ray's colour not weighted by k_r.
        UnweightedMirror,
        /// k_t dropped under total internal reflection.
        TirDropped,
        /// η = 1/ior whether entering or leaving.
        AlwaysEntering,
        /// The refracted ray started at p − 10⁻⁴·N.
        FixedEpsilon,
        /// Fresnel's R ignored.
        NoFresnel,
    }

    /// The reference tracer, written again with `slip` planted.
    fn planted(
        slip: Slip,
        world: &World,
        ray: &Ray,
        depth: u32,
        weight: Float,
        settings: &TraceSettings,
    ) -> Color {
        let Some(hit) = world.objects.closest_hit(ray, Interval::POSITIVE) else {
            return world.scene.background;
        };
        let scene = world.scene;
        let material = world.material_at(&hit, &scene.materials[hit.material]);
        let material = material.as_ref();
        let dir = ray.dir.normalize();
        let diffuse = material.diffuse;
        let mut color = if settings.shadows {
            let surface = Surface { material, diffuse, hit, v: -dir, origin: ray.origin };
            let shadows = ShadowSettings { mode: settings.shadow_mode, area_samples: settings.area_samples };
            shade_with_shadows(
                world.objects,
                &scene.materials,
                &surface,
                &scene.lights,
                scene.ambient,
                shadows,
            )
        } else {
            shade_local(material, diffuse, &hit, -dir, &scene.lights, scene.ambient)
        };
        let stop = if slip == Slip::DepthOffByOne {
            depth > settings.max_depth
        } else {
            depth >= settings.max_depth
        };
        if stop {
            return color;
        }
        let (mut k_r, mut k_t) = (material.reflective, material.transparent);
        let mut refracted = None;
        if k_t != BLACK {
            let crossing = interface(&hit, material.ior);
            let eta = if slip == Slip::AlwaysEntering { 1.0 / material.ior } else { crossing.eta_ratio() };
            refracted = refract(dir, crossing.normal, eta);
            let reflectance = match refracted {
                None if slip == Slip::TirDropped => 0.0,
                None => 1.0,
                Some(_) if settings.fresnel && slip != Slip::NoFresnel => {
                    fresnel_dielectric(-dir.dot(crossing.normal), crossing.eta_i, crossing.eta_t)
                }
                Some(_) => 0.0,
            };
            k_r += reflectance * k_t;
            k_t *= 1.0 - reflectance;
        }
        let min_weight = if slip == Slip::NoWeightRule { 0.0 } else { settings.min_weight };
        let mirror_weight = weight * k_r.max_element();
        if mirror_weight > 0.0 && mirror_weight >= min_weight {
            count(Counter::ReflectionRays);
            let r = mirror_direction(dir, hit.normal);
            let mirror = Ray::new(offset_origin(hit.point, hit.normal, r, ray.origin), r);
            let seen = planted(slip, world, &mirror, depth + 1, mirror_weight, settings);
            color += if slip == Slip::UnweightedMirror { seen } else { k_r * seen };
        }
        let through_weight = weight * k_t.max_element();
        if let Some(t) = refracted
            && through_weight > 0.0
            && through_weight >= min_weight
        {
            count(Counter::RefractionRays);
            let origin = if slip == Slip::FixedEpsilon {
                hit.point - 1e-4 * hit.normal
            } else {
                offset_origin(hit.point, hit.normal, t, ray.origin)
            };
            let seen = planted(slip, world, &Ray::new(origin, t), depth + 1, through_weight, settings);
            color += k_t * seen;
        }
        color
    }

    macro_rules! slipped {
        ($($name:ident => $slip:expr),* $(,)?) => {
            $(fn $name(w: &World, r: &Ray, d: u32, wt: Float, s: &TraceSettings) -> Color {
                planted($slip, w, r, d, wt, s)
            })*
        };
    }

    slipped! {
        no_slip => Slip::None,
        depth_off_by_one => Slip::DepthOffByOne,
        no_weight_rule => Slip::NoWeightRule,
        unweighted_mirror => Slip::UnweightedMirror,
        tir_dropped => Slip::TirDropped,
        always_entering => Slip::AlwaysEntering,
        fixed_epsilon => Slip::FixedEpsilon,
        no_fresnel => Slip::NoFresnel,
    }

    fn cause_of(result: crate::check::CheckResult) -> String {
        match result {
            Ok(detail) => panic!("the planted mistake passed: {detail}"),
            Err(failure) => {
                println!(
                    "caught: {} | expected {} | got {} | {}",
                    failure.case, failure.expected, failure.got, failure.cause
                );
                failure.cause
            }
        }
    }

    #[test]
    fn the_planted_copy_without_a_slip_passes() {
        assert!(trace_cases(no_slip).is_ok(), "{:?}", trace_cases(no_slip));
        assert!(tiny_glass_sphere(no_slip).is_ok());
    }

    #[test]
    fn planted_tracer_mistakes_are_caught_with_their_cause() {
        // The planted tracers recurse in this (unoptimised) crate, to depth 100 and more without
        // the weight rule: a test thread's 2 MB stack is too small for that in an f64 debug build.
        std::thread::Builder::new()
            .stack_size(256 << 20)
            .spawn(planted_tracers)
            .expect("a thread")
            .join()
            .expect("the planted tracers are caught");
    }

    fn planted_tracers() {
        for (tracer, cause) in [
            (depth_off_by_one as TraceFn, "off by one"),
            (no_weight_rule, "spawn a child only when its weight"),
            (unweighted_mirror, "weight what the mirror ray sees by k_r"),
            (tir_dropped, "all of k_t goes to the mirror ray"),
            (always_entering, "leaving the glass η = η_i/η_t = 1.5/1"),
            (no_fresnel, "with settings.fresnel, R = fresnel_dielectric"),
        ] {
            let got = cause_of(trace_cases(tracer));
            assert!(got.contains(cause), "expected a cause with {cause:?}, got {got:?}");
        }
        let got = cause_of(tiny_glass_sphere(fixed_epsilon));
        assert!(got.contains("missed the exit"), "{got}");
    }
}
