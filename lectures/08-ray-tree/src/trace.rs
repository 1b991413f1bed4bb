//! Whitted's recursive ray tracer: local shading plus the light the mirror
//! and the transmitted ray bring back, each traced the same way.
//!
//! ```text
//! trace(ray, depth, weight):
//!     hit = closest hit of ray            none: the background
//!     I   = local shading of hit          (with shadow rays, 06)
//!     if depth < max_depth:
//!         I += k_r ⊙ trace(mirror ray,      depth + 1, weight·max(k_r))
//!         I += k_t ⊙ trace(transmitted ray, depth + 1, weight·max(k_t))
//!     return I
//! ```

use l05_shading::shade_local;
use l06_shadows::{ShadowSettings, Surface, offset_origin, shade_with_shadows};
use l07_reflection_refraction::{fresnel_dielectric, interface, mirror_direction, refract};
use raylab::stats::{Counter, count};
use raylab::{BLACK, Color, Float, Interval, Ray, Vec3};

use crate::ray_tree::{RayKind, Recorder};
use crate::settings::TraceSettings;
use crate::world::World;

/// The colour seen along `ray`: its closest hit's local shading plus what
/// its mirror and transmitted rays see, weighted by k_r and k_t, recursively
/// (Whitted 1980):
///
///   I = I_local + k_r ⊙ trace(R, depth + 1) + k_t ⊙ trace(T, depth + 1),
///
/// or the scene's background when nothing is hit. I_local is lecture 06's
/// shading with shadow rays, or lecture 05's without them when
/// `settings.shadows` is off. Every property (k_d, k_s, k_r, k_t, η) is the
/// surface's material at the hit, [`World::material_at`]: the scene's, or
/// its texture's there when the world has a surface material (lecture 10).
/// Every ray looks in (0, ∞); `ray.dir` need not
/// be unit (it is normalised for the shading and the children, whose
/// directions are unit).
///
/// The ray tree stops by two rules: a ray of depth `settings.max_depth`
/// spawns nothing (the eye ray has depth 0), and a child is spawned only when
/// its weight w·max(k) is at least `settings.min_weight` (and above 0), w
/// being `weight`, the product of the maxima of the k's above this ray
/// (1 for an eye ray). The counters [`Counter::ReflectionRays`] and
/// [`Counter::RefractionRays`] count each child; the eye ray is counted by
/// the caller ([`Counter::PrimaryRays`]). Never NaN.
///
/// Which children, and their k (k_r = `reflective`, k_t = `transparent`):
/// - a mirror ray in 07's [`mirror_direction`] when k_r ≠ 0;
/// - when k_t ≠ 0, a transmitted ray in 07's [`refract`] direction, with the
///   indices from [`interface`] (entering or leaving). Its reflectance R
///   moves R·k_t into the mirror ray: k_r' = k_r + R·k_t, k_t' = (1 − R)·k_t.
///   R = 1 under total internal reflection (no transmitted ray: all of k_t
///   goes to the mirror ray); otherwise, with `settings.fresnel`, R is the
///   exact [`fresnel_dielectric`] reflectance at cos θ_i = −d·N (not
///   Schlick's: it costs a square root more, and Schlick is off by up to
///   0.02 on glass), and without it R = 0.
///
/// Both start at 06's [`offset_origin`] toward the side they leave to (the
/// mirror ray on the incoming side, the transmitted ray past the surface),
/// scaled to the hit point and this ray's origin.
/// Book: §8.2 The recursive tracer, §8.3 Stopping the recursion.
pub fn trace(world: &World, ray: &Ray, depth: u32, weight: Float, settings: &TraceSettings) -> Color {
    debug_assert!(ray.dir.is_finite() && ray.dir != Vec3::ZERO, "trace: the ray direction is {}", ray.dir);
    trace_node(world, ray, RayKind::Eye, depth, weight, settings, None)
}

/// One node of the ray tree: counts the ray by its kind (a reflected or a
/// transmitted ray; the eye ray is the caller's), records it when a
/// [`Recorder`] is given (see `ray_tree.rs`), and traces it with
/// [`trace_ray`]. The tracer's one door for new rays. Book: §8.5 Seeing the
/// ray tree.
pub(crate) fn trace_node(
    world: &World,
    ray: &Ray,
    kind: RayKind,
    depth: u32,
    weight: Float,
    settings: &TraceSettings,
    recorder: Option<&Recorder>,
) -> Color {
    debug_assert!(kind != RayKind::Shadow, "shadow rays are cast by the shading, not traced");
    match kind {
        RayKind::Reflected => count(Counter::ReflectionRays),
        RayKind::Transmitted => count(Counter::RefractionRays),
        RayKind::Eye | RayKind::Shadow => {}
    }
    let Some(recorder) = recorder else {
        return trace_ray(world, ray, depth, weight, settings, None);
    };
    recorder.open(kind, ray, weight);
    let color = trace_ray(world, ray, depth, weight, settings, Some(recorder));
    recorder.close();
    color
}

/// The body of [`trace`] (see there for the formula and the rules): the
/// closest hit, the local shading, then the children, each through
/// [`trace_node`] with its kind (`RayKind::Reflected`, `RayKind::Transmitted`)
/// and the `recorder` handed on unchanged. The ray's own hit must be the
/// first question asked of `world.objects` (the recorder takes it for the
/// node's hit). Book: §8.2 The recursive tracer.
fn trace_ray(
    world: &World,
    ray: &Ray,
    depth: u32,
    weight: Float,
    settings: &TraceSettings,
    recorder: Option<&Recorder>,
) -> Color {
    // SOLUTION BEGIN
    // The closest hit; a ray that hits nothing sees the background.
    let Some(hit) = world.objects.closest_hit(ray, Interval::POSITIVE) else {
        return world.scene.background;
    };
    let scene = world.scene;
    // The surface's material there (a texture's, lecture 10), borrowed when nothing varies.
    let material = world.material_at(&hit, &scene.materials[hit.material]);
    let material = material.as_ref();
    let dir = ray.dir.normalize();

    // Local shading: with shadow rays (06), or every light unblocked (05).
    let diffuse = material.diffuse;
    let mut color = if settings.shadows {
        let surface = Surface { material, diffuse, hit, v: -dir, origin: ray.origin };
        shade_with_shadows(
            world.objects,
            &scene.materials,
            &surface,
            &scene.lights,
            scene.ambient,
            ShadowSettings { mode: settings.shadow_mode, area_samples: settings.area_samples },
        )
    } else {
        shade_local(material, diffuse, &hit, -dir, &scene.lights, scene.ambient)
    };

    // The depth limit: the deepest rays spawn nothing.
    if depth >= settings.max_depth {
        return color;
    }

    // A transparent surface: the refracted direction and the reflectance R that moves
    // R·k_t into the mirror ray (R = 1 under total internal reflection).
    let (mut k_r, mut k_t) = (material.reflective, material.transparent);
    let mut refracted = None;
    if k_t != BLACK {
        let crossing = interface(&hit, material.ior);
        refracted = refract(dir, crossing.normal, crossing.eta_ratio());
        let reflectance = match refracted {
            None => 1.0,
            Some(_) if settings.fresnel => {
                fresnel_dielectric(-dir.dot(crossing.normal), crossing.eta_i, crossing.eta_t)
            }
            Some(_) => 0.0,
        };
        k_r += reflectance * k_t;
        k_t *= 1.0 - reflectance;
    }

    // The mirror ray, from the incoming side, if it weighs enough.
    let mirror_weight = weight * k_r.max_element();
    if mirror_weight > 0.0 && mirror_weight >= settings.min_weight {
        let r = mirror_direction(dir, hit.normal);
        let mirror = Ray::new(offset_origin(hit.point, hit.normal, r, ray.origin), r);
        let seen =
            trace_node(world, &mirror, RayKind::Reflected, depth + 1, mirror_weight, settings, recorder);
        color += k_r * seen;
    }

    // The transmitted ray, from just past the surface, if it weighs enough.
    let through_weight = weight * k_t.max_element();
    if let Some(t) = refracted
        && through_weight > 0.0
        && through_weight >= settings.min_weight
    {
        let through = Ray::new(offset_origin(hit.point, hit.normal, t, ray.origin), t);
        let kind = RayKind::Transmitted;
        let seen = trace_node(world, &through, kind, depth + 1, through_weight, settings, recorder);
        color += k_t * seen;
    }
    color
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{
        EPS, cuboid, directional, glass, matte, mirror, mirror_and_wall, plane, recorded, scene, sphere,
        trace_counted, v,
    };
    use approx::assert_abs_diff_eq;
    use l04_quadrics_transforms::BruteForce;
    use l06_shadows::ShadowMode;
    use raylab::scene::{Attenuation, Light, LightKind, Material, Specular};
    use raylab::stats::RayStats;
    use raylab::{Intersector, WHITE};
    use raylab_testing::scenes::{block_with_tile, facing_mirrors, tile_in_glass};

    const BACKGROUND: Color = Color::new(0.2, 0.3, 0.4);
    const AMBIENT: Color = Color::new(0.1, 0.2, 0.3);

    /// (reflection, refraction, shadow) rays counted.
    fn secondary(stats: &RayStats) -> (u64, u64, u64) {
        (
            stats.get(Counter::ReflectionRays),
            stats.get(Counter::RefractionRays),
            stats.get(Counter::ShadowRays),
        )
    }

    #[test]
    fn a_miss_sees_the_background_and_casts_nothing() {
        // A ray away from the only sphere, and any ray in an empty scene: the background,
        // exactly, and no secondary ray.
        let one = scene(
            vec![sphere(v(0.0, 0.0, -5.0), 1.0, 0)],
            vec![mirror(1.0)],
            vec![directional(Vec3::Z, WHITE)],
            BACKGROUND,
            AMBIENT,
        );
        let empty = scene(vec![], vec![], vec![directional(Vec3::Z, WHITE)], BACKGROUND, AMBIENT);
        for (s, dir) in [(&one, Vec3::Y), (&one, Vec3::Z), (&empty, -Vec3::Z)] {
            let (color, stats) = trace_counted(s, &Ray::new(Vec3::ZERO, dir), &TraceSettings::default());
            assert_eq!((color, stats.total_rays()), (BACKGROUND, 0), "{dir}");
        }
    }

    /// A shiny diffuse sphere of radius 1 at (0, 0, −5), lit by one directional light.
    fn diffuse_sphere(toward_light: Vec3) -> raylab::Scene {
        let shiny = Material {
            diffuse: v(0.6, 0.4, 0.2),
            specular: Color::splat(0.25),
            exponent: 8.0,
            model: Specular::Blinn,
            ..Material::default()
        };
        scene(
            vec![sphere(v(0.0, 0.0, -5.0), 1.0, 0)],
            vec![shiny],
            vec![directional(toward_light, v(1.0, 0.5, 0.25))],
            BACKGROUND,
            AMBIENT,
        )
    }

    #[test]
    fn a_diffuse_sphere_head_on_gives_ambient_diffuse_and_highlight_by_hand() {
        // The ray down −z meets the sphere at (0, 0, −4) with N = +z = V = L, so N·L = 1 and
        // Blinn's H = N, N·H = 1: I = k_d⊙I_a + (k_d + k_s)⊙I_L
        // = (0.06, 0.08, 0.06) + (0.85, 0.65, 0.45)⊙(1, 0.5, 0.25) = (0.91, 0.405, 0.1725).
        // A handful of roundings of values below 1: 4ε. One shadow ray, nothing else.
        let s = diffuse_sphere(Vec3::Z);
        let (color, stats) = trace_counted(&s, &Ray::new(Vec3::ZERO, -Vec3::Z), &TraceSettings::default());
        assert_abs_diff_eq!(color, v(0.91, 0.405, 0.1725), epsilon = 4.0 * EPS);
        assert_eq!(secondary(&stats), (0, 0, 1));
    }

    #[test]
    fn a_diffuse_sphere_is_exactly_the_local_shading_of_05_and_06() {
        // Without k_r and k_t, trace is the local shading and nothing more: bit for bit
        // 06's shade_with_shadows (05's shade_local with shadows off), for rays over the
        // whole sphere, lit from the side so that some points face away from the light.
        let s = diffuse_sphere(v(1.0, 1.0, 1.0).normalize());
        let objects = BruteForce::new(&s.objects);
        let material = &s.materials[0];
        let mut hits = 0;
        for i in -10..=10 {
            for j in -10..=10 {
                let ray = Ray::new(Vec3::ZERO, v(i as Float * 0.02, j as Float * 0.02, -1.0).normalize());
                let Some(hit) = objects.closest_hit(&ray, Interval::POSITIVE) else { continue };
                hits += 1;
                let eye = -ray.dir.normalize();
                let surface =
                    Surface { material, diffuse: material.diffuse, hit, v: eye, origin: ray.origin };
                let shadows = ShadowSettings::default();
                let with =
                    shade_with_shadows(&objects, &s.materials, &surface, &s.lights, s.ambient, shadows);
                let without = shade_local(material, material.diffuse, &hit, eye, &s.lights, s.ambient);
                let settings = TraceSettings::default();
                let (color, stats) = trace_counted(&s, &ray, &settings);
                assert_eq!(color, with, "{ray:?}");
                assert_eq!(secondary(&stats).0 + secondary(&stats).1, 0);
                let (color, stats) = trace_counted(&s, &ray, &TraceSettings { shadows: false, ..settings });
                assert_eq!(color, without, "{ray:?}");
                assert_eq!(stats.total_rays(), 0);
            }
        }
        // The cone of rays, 0.2 wide at distance 1, covers the sphere's middle (radius ≈ 0.2).
        assert!(hits > 300, "{hits} rays hit the sphere");
    }

    #[test]
    fn a_mirror_shows_the_wall_behind_the_eye_times_k_r() {
        // The eye ray hits the mirror head-on at (0, 0, −2): black, no highlight, and the
        // light is behind it (N·L = −1/√2), so its own shading is 0 and casts no shadow ray.
        // The mirror ray goes straight back to the wall at (0, 0, 3), whose normal faces it
        // (−z): N·L = 1/√2, and its shadow ray rises to y = 5 by the time it is back at
        // z = −2, far above the mirror: I = k_r·k_d⊙(0.1 + 1/√2). A few roundings of values
        // below 1: 8ε.
        for kr in [1.0, 0.5] {
            let s = mirror_and_wall(kr);
            let (color, stats) =
                trace_counted(&s, &Ray::new(Vec3::ZERO, -Vec3::Z), &TraceSettings::default());
            let wall = v(0.8, 0.4, 0.2) * (0.1 + Float::sqrt(0.5));
            assert_abs_diff_eq!(color, kr * wall, epsilon = 8.0 * EPS);
            assert_eq!(secondary(&stats), (1, 0, 1), "k_r = {kr}");
        }
    }

    #[test]
    fn the_mirror_ray_leaves_from_the_incoming_side_in_the_mirror_direction() {
        // At 45° onto the mirror (ray (1, 0, −1)/√2 from (−2, 0, 0)): the mirror ray starts
        // within the offset (a few dozen ulp) of (0, 0, −2), on the +z side, and leaves along
        // (1, 0, 1)/√2.
        let s = mirror_and_wall(1.0);
        let ray = Ray::new(v(-2.0, 0.0, 0.0), v(1.0, 0.0, -1.0).normalize());
        let (_, tree) = recorded(&s, &ray, &TraceSettings::default());
        let reflected = &tree.children[0];
        assert_eq!(reflected.kind, RayKind::Reflected);
        assert!(reflected.origin.z > -2.0, "origin {} is not in front of the mirror", reflected.origin);
        assert_abs_diff_eq!(reflected.origin, v(0.0, 0.0, -2.0), epsilon = 64.0 * 4.0 * EPS);
        assert_abs_diff_eq!(reflected.dir, v(1.0, 0.0, 1.0).normalize(), epsilon = 4.0 * EPS);
    }

    #[test]
    fn glass_of_index_one_is_invisible() {
        // A slab of η = 1 (k_t = 1, black, no highlight) between the eye and a wall lit by a
        // point light in front of the slab: every ray goes straight through (Snell with
        // η = 1 bends nothing) and the wall looks as it does without the slab. Shadows are
        // Transmissive, where the slab's k_t = 1 lets all the light through (Opaque would
        // shadow the wall behind it). What differs: each crossing starts the ray at most
        // d = 8ε·(|p|₁ + |o|₁) ≤ 8ε·16 off along the normal (|p|₁, |o|₁ ≤ 8 here), which
        // moves the wall point by d·tan θ ≤ d at these angles (θ < 45°), and each refraction
        // turns the ray by at most 9ε (07's test: 8ε + ε/cos θ), about 5ε over the 4 units
        // left to the wall, twice: at most 2·128ε + 2·36ε ≈ 330ε of wall. The light is ≥ 5
        // away, so N·L changes by at most 1/5 per unit of wall: 66ε of colour, plus the
        // roundings of the shading (a few ε). Asserted: 128ε (measured: 6.5ε in f32, 6ε in f64).
        let wall = plane(Vec3::Z, -6.0, 0);
        let slab = cuboid(v(-3.0, -3.0, -3.0), v(3.0, 3.0, -2.0), 1);
        let light = Light {
            color: WHITE,
            shadows: true,
            kind: LightKind::Point { position: v(1.0, 2.0, 0.0), attenuation: Attenuation::default() },
        };
        let materials = vec![matte(v(0.7, 0.5, 0.3)), glass(1.0)];
        let with = scene(vec![wall.clone(), slab], materials.clone(), vec![light], BACKGROUND, AMBIENT);
        let without = scene(vec![wall], materials, vec![light], BACKGROUND, AMBIENT);
        let settings = TraceSettings { shadow_mode: ShadowMode::Transmissive, ..TraceSettings::default() };
        let mut largest: Float = 0.0;
        for i in -5..=5 {
            for j in -5..=5 {
                let ray = Ray::new(Vec3::ZERO, v(i as Float * 0.15, j as Float * 0.15, -1.0).normalize());
                let (through, stats) = trace_counted(&with, &ray, &settings);
                let (direct, _) = trace_counted(&without, &ray, &settings);
                // Two refracted rays (into the slab, out of it), no mirror ray.
                assert_eq!(secondary(&stats).0, 0);
                assert_eq!(secondary(&stats).1, 2, "{ray:?}");
                largest = largest.max((through - direct).abs().max_element());
                assert_abs_diff_eq!(through, direct, epsilon = 128.0 * EPS);
            }
        }
        println!("glass of η = 1: largest difference {:.1}ε", largest / EPS);
    }

    #[test]
    fn the_area_samples_reach_the_shading() {
        // A matte sphere (k_d = ½) at (0, 0, −5) and a white 2 × 2 rect light in the plane
        // z = 5, x, y ∈ [−1, 1]. The eye ray down −z hits (0, 0, −4), N = +z; every point of
        // the light is in front of it (N·L ≥ 9/√83 = 0.988) with nothing in the way: exactly
        // `area_samples` shadow rays and no other ray, and the colour is at least
        // ½·0.1 + ½·0.988 = 0.544 in red (no attenuation).
        let attenuation = Attenuation::default();
        let panel = Light {
            color: WHITE,
            shadows: true,
            kind: LightKind::Rect {
                corner: v(-1.0, -1.0, 5.0),
                edge_u: 2.0 * Vec3::X,
                edge_v: 2.0 * Vec3::Y,
                attenuation,
            },
        };
        let s = scene(
            vec![sphere(v(0.0, 0.0, -5.0), 1.0, 0)],
            vec![matte(v(0.5, 0.5, 0.5))],
            vec![panel],
            BACKGROUND,
            AMBIENT,
        );
        for n in [1, 9, 10] {
            let settings = TraceSettings { area_samples: n, ..TraceSettings::default() };
            let (color, stats) = trace_counted(&s, &Ray::new(Vec3::ZERO, -Vec3::Z), &settings);
            assert_eq!(secondary(&stats), (0, 0, u64::from(n)), "{n} samples");
            assert!(color.is_finite() && color.x >= 0.544, "{color}");
        }
    }

    #[test]
    fn total_internal_reflection_sends_the_transmitted_weight_to_the_mirror_ray() {
        // At 60° from the top face's normal, above θ_c = arcsin(1/1.5) = 41.8°: no
        // transmitted ray, and the whole k_t = 1 goes to the mirror ray (weight 1, though the
        // glass has no k_r). That ray goes down at 60° from (0.866, 0, 0) and meets the tile's
        // top y = −0.8 at x = 0.866 + 0.8·tan 60° = 2.25, inside the tile, whose colour is
        // k_d⊙I_a = (0.1, 0.3, 0.2). The glass itself is black and unlit (no lights): the
        // pixel is the tile's colour, exactly (1·x is x). The same with Fresnel on (R = 1).
        let (s, ray) = block_with_tile(60.0);
        for fresnel in [false, true] {
            let settings = TraceSettings { fresnel, ..TraceSettings::default() };
            let (color, stats) = trace_counted(&s, &ray, &settings);
            assert_eq!(color, v(0.2, 0.6, 0.4) * 0.5, "fresnel {fresnel}");
            assert_eq!(secondary(&stats), (1, 0, 0), "fresnel {fresnel}");
        }
        // Below the critical angle (30°: sin²θ_t = 2.25·¼ < 1) the ray leaves the glass into
        // the empty sky above: the background, through one refracted ray and no mirror ray.
        let (s, ray) = block_with_tile(30.0);
        let (color, stats) = trace_counted(&s, &ray, &TraceSettings::default());
        assert_eq!(color, v(1.0, 0.0, 1.0));
        assert_eq!(secondary(&stats), (0, 1, 0));
    }

    #[test]
    fn fresnel_sends_four_percent_back_at_normal_incidence_on_glass() {
        // Head-on into a glass block (η = 1.5, k_t = 1, k_r = 0) holding a green tile, one
        // bounce allowed. R = ((1 − 1.5)/(1 + 1.5))² = 0.04 at normal incidence: the mirror
        // ray (weight 0.04) sees the background B behind the eye, the transmitted one (0.96)
        // the tile, k_d⊙I_a. Without Fresnel: only the transmitted ray, weight 1.
        // Tolerance: R from 07 within a few ε, times values ≤ 1: 8ε.
        let (s, ray) = tile_in_glass();
        let background = s.background;
        let tile = v(0.2, 0.6, 0.4) * 0.5;
        let settings = TraceSettings { max_depth: 1, ..TraceSettings::default() };
        let (plain, stats) = trace_counted(&s, &ray, &settings);
        assert_eq!((plain, secondary(&stats)), (tile, (0, 1, 0)));
        let (fresnel, stats) = trace_counted(&s, &ray, &TraceSettings { fresnel: true, ..settings });
        assert_abs_diff_eq!(fresnel, 0.04 * background + 0.96 * tile, epsilon = 8.0 * EPS);
        assert_eq!(secondary(&stats), (1, 1, 0));
    }

    #[test]
    fn facing_mirrors_stop_after_exactly_max_depth_reflections() {
        // The eye ray (depth 0) hits a mirror; a ray of depth d < D spawns the mirror ray of
        // depth d + 1, which hits the other mirror (normal incidence: it comes straight
        // back). So the rays of depths 1, …, D are spawned and the one of depth D spawns
        // nothing: exactly D reflected rays. With k_r = 1 every ray weighs 1 (never below
        // the cut-off) and each of the D + 1 hits adds k_d⊙I_a = 0.1: I = 0.1·(D + 1).
        // Tolerance: D + 1 sums of values up to 0.1·(D + 1), ε each.
        let (s, ray) = facing_mirrors(1.0);
        for depth in [0, 1, 2, 5, 64] {
            let settings = TraceSettings { max_depth: depth, ..TraceSettings::default() };
            let (color, stats) = trace_counted(&s, &ray, &settings);
            let n = (depth + 1) as Float;
            assert_abs_diff_eq!(color, Color::splat(0.1 * n), epsilon = n * n * 0.1 * EPS);
            assert_eq!(secondary(&stats), (depth as u64, 0, 0), "max_depth {depth}");
            let (_, tree) = recorded(&s, &ray, &settings);
            assert_eq!((tree.depth(), tree.count(RayKind::Reflected)), (depth, depth as usize));
        }
    }

    #[test]
    fn facing_mirrors_stop_where_the_weight_falls_below_the_cut_off() {
        // k_r = 0.9, min_weight 0.01, depth limit out of reach (1000): the k-th mirror ray
        // weighs 0.9ᵏ and is spawned while 0.9ᵏ ≥ 0.01, i.e. k ≤ ln 0.01 / ln 0.9 = 43.7: 43
        // reflected rays (0.9⁴³ = 0.0108, 0.9⁴⁴ = 0.0097, far from the cut-off in both
        // precisions). The hits add 0.1·Σ_{k=0}^{43} 0.9ᵏ = 1 − 0.9⁴⁴ = 0.990302. Tolerance
        // 64ε: 44 products and sums of values below 1.
        let (s, ray) = facing_mirrors(0.9);
        let settings = TraceSettings { max_depth: 1000, ..TraceSettings::default() };
        let (color, stats) = trace_counted(&s, &ray, &settings);
        assert_eq!(secondary(&stats), (43, 0, 0));
        let expected = (1.0 - 0.9f64.powi(44)) as Float;
        assert_abs_diff_eq!(color, Color::splat(expected), epsilon = 64.0 * EPS);
        // Without the weight rule (min_weight 0) the depth limit stops it instead.
        let settings = TraceSettings { max_depth: 100, min_weight: 0.0, ..settings };
        assert_eq!(secondary(&trace_counted(&s, &ray, &settings).1), (100, 0, 0));
    }

    #[test]
    fn a_black_mirror_and_a_black_glass_spawn_nothing() {
        // k_r = 0 and k_t = 0: the weight rule's w·max(k) = 0 never spawns, even with the
        // cut-off at 0 (a ray of weight 0 can add nothing).
        let (s, ray) = facing_mirrors(0.0);
        let settings = TraceSettings { min_weight: 0.0, ..TraceSettings::default() };
        let (color, stats) = trace_counted(&s, &ray, &settings);
        assert_eq!((color, stats.total_rays()), (Color::splat(0.1), 0));
    }
}
