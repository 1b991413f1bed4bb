//! Shadow rays: is the light seen from a surface point, and how much of it
//! comes through the transparent objects on the way.
//!
//! A shadow ray runs from the (offset) surface point toward the light and
//! asks whether anything lies *between* the two: blockers behind the point
//! or beyond the light do not count. It needs no closest hit, only *a* hit,
//! so it asks the scene's `any_hit`, which may stop at the first blocker.
//!
//! Transparent blockers get one of the slides' two "dirty" treatments,
//! chosen per scene ([`ShadowMode`]): every blocker is opaque, or each one
//! filters the light by its material's transparent colour k_t, the shadow ray
//! going straight through (no refraction: the caustic a glass ball focuses
//! is out of reach of shadow rays). Book: §6.1 Shadow rays, §6.4 Transparent
//! blockers.

use l05_shading::LightSample;
use raylab::scene::Material;
use raylab::stats::{Counter, count};
use raylab::{BLACK, Color, Float, Intersector, Interval, Ray, Vec3, WHITE};

use crate::offset::offset_origin;

/// The shadow ray's range ends this fraction short of the light:
/// (0, distance·(1 − 4ε)).
///
/// The distance to the light is computed with a few roundings (a difference,
/// a length: within about 2ε relative), so a surface the light sits on could
/// otherwise come out a hair nearer than the light and shadow it. Four ε
/// covers that and is far below any gap a scene means to show.
pub const LIGHT_MARGIN: Float = 1.0 - 4.0 * Float::EPSILON;

/// How many blockers [`transmittance`] walks through at most; past that the
/// light counts as blocked (a safeguard against a ray that makes no progress,
/// never reached in a sensible scene: 64 surfaces of k_t ≤ 0.9 pass 0.1 %).
pub const MAX_BLOCKERS: usize = 64;

/// What a transparent object does to the shadows it casts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ShadowMode {
    /// Every blocker blocks: [`occluded`], one any-hit ray per light.
    #[default]
    Opaque,
    /// Each surface crossed multiplies the light by the blocker's `transparent`
    /// colour: [`transmittance`], one closest-hit ray per blocker.
    Transmissive,
}

/// Whether anything blocks the light of `sample` as seen from `from`: the
/// shadow ray from + s·L, L = `sample.direction`, hits something with
/// 0 < s < distance·(1 − 4ε) ([`LIGHT_MARGIN`]).
///
/// `from` is the surface point already moved off the surface
/// ([`offset_origin`]), so the range starts at 0. A blocker behind `from`
/// (s < 0) or beyond the light (s > distance) does not shadow; a directional
/// light (distance ∞) is blocked by anything along the ray. Asks `any_hit`
/// (stops at the first blocker) and counts one [`Counter::ShadowRays`].
/// `sample.direction` must be unit, `sample.distance` ≥ 0.
/// Book: §6.1 Shadow rays.
pub fn occluded(scene: &dyn Intersector, from: Vec3, sample: &LightSample) -> bool {
    debug_assert!(sample.direction.is_normalized(), "occluded: L = {} is not unit", sample.direction);
    debug_assert!(sample.distance >= 0.0, "occluded: distance {} < 0", sample.distance);
    // SOLUTION BEGIN
    // One shadow ray, from the point toward the light, stopping short of it.
    count(Counter::ShadowRays);
    let ray = Ray::new(from, sample.direction);
    scene.any_hit(&ray, Interval::new(0.0, sample.distance * LIGHT_MARGIN))
    // SOLUTION END
}

/// The fraction of the light of `sample` that reaches `from` through the
/// blockers between them, each surface crossing filtering it by the
/// `transparent` colour k_t of its material (`materials[hit.material]`):
/// T = Π k_t over the crossings with 0 < s < distance·(1 − 4ε).
///
/// The walk: from `from`, find the closest blocker; multiply by its k_t; stop
/// with black once the product is black (an opaque blocker); else start again
/// just past that blocker ([`offset_origin`] to the side the ray leaves to,
/// the segment's own origin as the ray that found it), the light now nearer
/// by the t travelled. White when nothing is in the way.
///
/// Counted per surface, as the tracer of lectures 07–08 weights a ray through
/// a transparent object once at each surface: a sphere of k_t = ½ passes
/// ½·½ = ¼ (in and out), a single plane ½, and from inside the sphere ½. A
/// material index with no material counts as opaque. Each ray segment counts
/// one [`Counter::ShadowRays`]; after [`MAX_BLOCKERS`] crossings the light
/// counts as blocked. `from` already offset, `sample.direction` unit.
/// Book: §6.4 Transparent blockers.
pub fn transmittance(
    scene: &dyn Intersector,
    materials: &[Material],
    from: Vec3,
    sample: &LightSample,
) -> Color {
    debug_assert!(sample.direction.is_normalized(), "transmittance: L = {} is not unit", sample.direction);
    debug_assert!(sample.distance >= 0.0, "transmittance: distance {} < 0", sample.distance);
    // SOLUTION BEGIN
    let dir = sample.direction;
    let mut origin = from;
    let mut remaining = sample.distance * LIGHT_MARGIN;
    let mut filtered = WHITE;
    for _ in 0..MAX_BLOCKERS {
        // The next blocker between here and the light; none: the light arrives.
        count(Counter::ShadowRays);
        let Some(hit) = scene.closest_hit(&Ray::new(origin, dir), Interval::new(0.0, remaining)) else {
            return filtered;
        };
        // Filter by its transparent colour; black stops the walk.
        let transparent = materials.get(hit.material).map_or(BLACK, |m| m.transparent);
        filtered *= transparent;
        if filtered == BLACK {
            return BLACK;
        }
        // Start again past the blocker, the light nearer by the distance travelled.
        origin = offset_origin(hit.point, hit.normal, dir, origin);
        remaining -= hit.t;
    }
    BLACK
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{plane, see_through, sphere};
    use l04_quadrics_transforms::BruteForce;
    use raylab::random::Rng;
    use raylab::scene::Object;
    use raylab::stats::measure;
    use raylab::{Hit, Vec3};
    use raylab_testing::v;
    use std::sync::atomic::{AtomicUsize, Ordering};

    /// A point light at `position` seen from `from` (white, undimmed).
    fn point_light(from: Vec3, position: Vec3) -> LightSample {
        let to_light = position - from;
        LightSample { direction: to_light.normalize(), distance: to_light.length(), intensity: WHITE }
    }

    /// A directional light seen along the unit `l`.
    fn directional(l: Vec3) -> LightSample {
        LightSample { direction: l, distance: Float::INFINITY, intensity: WHITE }
    }

    /// Whether a unit sphere at `center` blocks a light 5 above the origin, seen from it.
    fn blocks(center: Vec3) -> bool {
        let objects = [sphere(center, 1.0, 0)];
        occluded(&BruteForce::new(&objects), Vec3::ZERO, &point_light(Vec3::ZERO, v(0.0, 5.0, 0.0)))
    }

    #[test]
    fn point_under_a_sphere_is_occluded_from_a_light_above() {
        // From the origin straight up to (0, 5, 0): the unit sphere at (0, 2, 0) spans
        // 1 < y < 3, inside (0, 5).
        assert!(blocks(v(0.0, 2.0, 0.0)));
        // Moved aside by 1.5 > r the ray passes it.
        assert!(!blocks(v(1.5, 2.0, 0.0)));
    }

    #[test]
    fn blocker_beyond_the_light_does_not_shadow() {
        // The sphere at (0, 8, 0) spans 7 < y < 9: past the light at 5.
        assert!(!blocks(v(0.0, 8.0, 0.0)));
    }

    #[test]
    fn blocker_behind_the_point_does_not_shadow() {
        // The sphere at (0, −3, 0) spans −4 < y < −2: behind the origin (s < 0).
        assert!(!blocks(v(0.0, -3.0, 0.0)));
    }

    #[test]
    fn a_blocker_the_light_sits_on_does_not_shadow() {
        // The sphere at (0, 6, 0) touches the light: its surface is at s = 5 = distance
        // exactly (every value is a small integer); the range ends at 5·(1 − 4ε) < 5.
        assert!(!blocks(v(0.0, 6.0, 0.0)));
        // The same sphere 10ε·5 lower reaches into the range: it shadows.
        assert!(blocks(v(0.0, 6.0 - 50.0 * Float::EPSILON, 0.0)));
    }

    #[test]
    fn directional_light_is_blocked_by_anything_along_the_ray() {
        // Distance ∞: a sphere 1000 away on the ray blocks, one 5 to the side of it does not.
        let l = v(0.0, 1.0, 0.0);
        let far = [sphere(v(0.0, 1000.0, 0.0), 1.0, 0)];
        assert!(occluded(&BruteForce::new(&far), Vec3::ZERO, &directional(l)));
        let aside = [sphere(v(5.0, 1000.0, 0.0), 1.0, 0)];
        assert!(!occluded(&BruteForce::new(&aside), Vec3::ZERO, &directional(l)));
        // A plane y = 10⁶ facing away from the point blocks as well (hit from behind).
        let sky = [plane(Vec3::Y, 1e6, 0)];
        assert!(occluded(&BruteForce::new(&sky), Vec3::ZERO, &directional(l)));
    }

    /// An intersector that records which query it was asked.
    struct Spy<'a> {
        inner: BruteForce<'a>,
        closest: AtomicUsize,
        any: AtomicUsize,
    }

    impl Intersector for Spy<'_> {
        fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
            self.closest.fetch_add(1, Ordering::Relaxed);
            self.inner.closest_hit(ray, range)
        }
        fn any_hit(&self, ray: &Ray, range: Interval) -> bool {
            self.any.fetch_add(1, Ordering::Relaxed);
            self.inner.any_hit(ray, range)
        }
    }

    #[test]
    fn occluded_asks_any_hit_once_and_counts_one_shadow_ray() {
        let objects = [sphere(v(0.0, 2.0, 0.0), 1.0, 0)];
        let spy =
            Spy { inner: BruteForce::new(&objects), closest: AtomicUsize::new(0), any: AtomicUsize::new(0) };
        let (blocked, stats) = measure(|| occluded(&spy, Vec3::ZERO, &directional(Vec3::Y)));
        assert!(blocked);
        assert_eq!((spy.any.into_inner(), spy.closest.into_inner()), (1, 0), "one any_hit, no closest_hit");
        assert_eq!(stats.get(Counter::ShadowRays), 1);
        assert_eq!(stats.total_rays(), 1);
    }

    /// Light from straight above the origin through whatever `objects` hold, with the
    /// materials `materials`.
    fn through(objects: &[Object], materials: &[Material]) -> (Color, u64) {
        let sample = point_light(Vec3::ZERO, v(0.0, 10.0, 0.0));
        let (t, stats) = measure(|| transmittance(&BruteForce::new(objects), materials, Vec3::ZERO, &sample));
        (t, stats.get(Counter::ShadowRays))
    }

    const HALF: Color = Color::splat(0.5);

    #[test]
    fn sphere_of_transparent_half_passes_a_quarter() {
        // Decision: each surface crossing filters by k_t, as the tracer weights a ray at each
        // surface of a transparent object. Entering and leaving the sphere: ½·½ = ¼, exact.
        // Three segments: to the entry, to the exit, and on to the light.
        let objects = [sphere(v(0.0, 4.0, 0.0), 1.0, 0)];
        assert_eq!(through(&objects, &[see_through(HALF)]), (Color::splat(0.25), 3));
    }

    #[test]
    fn one_surface_filters_once() {
        // A plane y = 4 (crossed once): ½. From inside the sphere (only its exit): ½.
        assert_eq!(through(&[plane(Vec3::Y, 4.0, 0)], &[see_through(HALF)]), (HALF, 2));
        assert_eq!(through(&[sphere(v(0.0, 0.5, 0.0), 1.0, 0)], &[see_through(HALF)]), (HALF, 2));
    }

    #[test]
    fn filters_multiply_per_channel_across_blockers() {
        // A sphere of k_t = (1, ½, ¼) and a plane of (½, 1, 1): (1·1·½, ½·½·1, ¼·¼·1) =
        // (½, ¼, 1/16), all products of powers of two: exact.
        let objects = [sphere(v(0.0, 3.0, 0.0), 1.0, 0), plane(Vec3::Y, 6.0, 1)];
        let materials = [see_through(v(1.0, 0.5, 0.25)), see_through(v(0.5, 1.0, 1.0))];
        assert_eq!(through(&objects, &materials), (v(0.5, 0.25, 0.0625), 4));
        // Nothing in the way: white, after one segment. Blockers beyond the light at 10: too.
        assert_eq!(through(&[], &materials), (WHITE, 1));
        assert_eq!(through(&[sphere(v(0.0, 12.0, 0.0), 1.0, 0)], &materials), (WHITE, 1));
    }

    #[test]
    fn an_opaque_blocker_stops_the_walk_at_black() {
        // An opaque sphere (k_t = 0) first: black after one segment; the transparent plane
        // beyond it is never reached. A missing material counts as opaque.
        let objects = [sphere(v(0.0, 3.0, 0.0), 1.0, 0), plane(Vec3::Y, 6.0, 1)];
        let materials = [Material::default(), see_through(HALF)];
        assert_eq!(through(&objects, &materials), (BLACK, 1));
        assert_eq!(through(&[sphere(v(0.0, 3.0, 0.0), 1.0, 7)], &materials), (BLACK, 1));
        // A filter black in one channel only keeps the others going.
        let materials = [see_through(v(1.0, 0.0, 1.0)), see_through(HALF)];
        assert_eq!(through(&objects, &materials), (v(0.5, 0.0, 0.5), 4));
    }

    #[test]
    fn fully_transparent_blockers_walk_through_and_never_loop() {
        // k_t = 1 everywhere: the light arrives whole (white) after 2·20 crossings + 1.
        // A row of 20 spheres along the ray, 2.5 apart, light beyond them at 100.
        let objects: Vec<Object> =
            (0..20).map(|i| sphere(v(0.0, 2.0 + 2.5 * i as Float, 0.0), 1.0, 0)).collect();
        let sample = point_light(Vec3::ZERO, v(0.0, 100.0, 0.0));
        let (t, stats) =
            measure(|| transmittance(&BruteForce::new(&objects), &[see_through(WHITE)], Vec3::ZERO, &sample));
        assert_eq!((t, stats.get(Counter::ShadowRays)), (WHITE, 41));
    }

    #[test]
    fn a_plane_through_the_world_origin_seen_from_afar_filters_once() {
        // Shadow rays from (0, −500, −700) up through the plane y = 0 of k_t = ½ within 0.1 of
        // the world origin, toward a directional light beyond: one crossing, exactly ½, two
        // segments. The crossing point cancels (|p|₁ ≤ 0.2 from |o|₁ = 1200) and carries an
        // error of a few ulp of 700; the next segment starts past it only because the offset
        // scales with the segment's origin. Taken from |p| alone it would stay on the near
        // side about half the time and cross again: ¼, three segments.
        let objects = [plane(Vec3::Y, 0.0, 0)];
        let scene = BruteForce::new(&objects);
        let from = v(0.0, -500.0, -700.0);
        let mut rng = Rng::new(0x0_1a7e);
        for _ in 0..2000 {
            let aim = v(rng.range(-0.1, 0.1), 0.0, rng.range(-0.1, 0.1));
            let (t, stats) = measure(|| {
                transmittance(&scene, &[see_through(HALF)], from, &directional((aim - from).normalize()))
            });
            assert_eq!((t, stats.get(Counter::ShadowRays)), (HALF, 2), "through {aim}");
        }
    }

    /// A broken intersector that always finds a blocker a hair ahead.
    struct Stuck;

    impl Intersector for Stuck {
        fn closest_hit(&self, ray: &Ray, _range: Interval) -> Option<Hit> {
            Some(Hit::new(ray, Float::MIN_POSITIVE, -ray.dir))
        }
    }

    #[test]
    fn a_walk_that_makes_no_progress_ends_black_after_max_blockers() {
        // Every segment "hits" at t ≈ 0 of a fully transparent material: without the cap the
        // walk would never end. It stops after MAX_BLOCKERS segments, light blocked.
        let (t, stats) =
            measure(|| transmittance(&Stuck, &[see_through(WHITE)], Vec3::ZERO, &directional(Vec3::Y)));
        assert_eq!((t, stats.get(Counter::ShadowRays)), (BLACK, MAX_BLOCKERS as u64));
    }
}
