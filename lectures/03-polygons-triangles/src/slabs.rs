//! Axis-aligned boxes by the slab method.
//!
//! In a scene file: `{ type = "box", min = [-1, -1, -1], max = [1, 1, 1] }`
//! (min ≤ max; a flat box, min.x == max.x, is allowed).

use raylab::math::gamma;
use raylab::{Float, Hit, Interval, Ray, Vec3};

/// The span of parameters t for which `ray` is inside the closed box
/// min ≤ p ≤ max, clipped to `range`.
///
/// The box is the intersection of three slabs minᵢ ≤ pᵢ ≤ maxᵢ. Along the ray,
/// slab i holds t between (minᵢ − oᵢ)/dᵢ and (maxᵢ − oᵢ)/dᵢ (the near plane is
/// the min plane when dᵢ > 0, the max plane when dᵢ < 0); the box holds the
/// intersection of the three spans, [t_enter, t_exit], with t_enter the latest
/// entry and t_exit the earliest exit. The ray meets the box iff
/// t_enter ≤ t_exit.
///
/// Returns `Some((t0, t1))` with t0 = max(t_enter, range.min) and
/// t1 = min(t_exit, range.max) when the closed span [t_enter, t_exit] meets
/// the open `range` (t_enter ≤ t_exit, t_enter < range.max,
/// t_exit > range.min). Then t0 ≤ t1; t0 == range.min means the ray starts
/// inside the box (the ends of the result are those of the range there, and
/// are not themselves in the open range); t0 == t1 when the ray only touches
/// an edge or a corner, or crosses a flat box.
///
/// Axis-parallel rays use IEEE arithmetic: 1/dᵢ = ±∞, so the slab's span is
/// (−∞, ∞) when the origin is strictly between its planes and (∞, ∞) or
/// (−∞, −∞), i.e. empty, when it is outside. An origin exactly on a slab plane
/// gives (minᵢ − oᵢ)·∞ = 0·∞ = NaN; that end is taken as the unbounded one,
/// so a ray moving within a face plane counts as inside that slab, and no NaN
/// ever reaches the result.
///
/// Conservative: each t carries three roundings (the difference, the
/// reciprocal, the product), a relative error of at most γ₃, so each slab's
/// exit is widened by 2γ₃ (pbrt's t_far·(1 + 2γ₃); a negative t_far is
/// multiplied by 1 − 2γ₃, which also moves it up): rounding never turns a hit
/// into a miss. It can turn a miss by a few ulps into a hit, and t1 can be a
/// few ulps beyond the exact exit.
///
/// `dir` need not be unit length (t is in the ray's units) but must not be
/// zero. Book: §3.1 Boxes as three slabs.
pub fn hit_slabs(ray: &Ray, min: Vec3, max: Vec3, range: Interval) -> Option<(Float, Float)> {
    debug_assert!(min.cmple(max).all(), "the box needs min ≤ max, got {min} and {max}");
    debug_assert!(ray.dir != Vec3::ZERO, "the ray direction must not be zero");
    // SOLUTION BEGIN
    let widen_up = 1.0 + 2.0 * gamma(3);
    let widen_down = 1.0 - 2.0 * gamma(3);
    let mut t_enter = Float::NEG_INFINITY;
    let mut t_exit = Float::INFINITY;
    for axis in 0..3 {
        // The parameters of the slab's two planes (±∞ for a parallel ray).
        let inv_dir = 1.0 / ray.dir[axis];
        let t_min_plane = (min[axis] - ray.origin[axis]) * inv_dir;
        let t_max_plane = (max[axis] - ray.origin[axis]) * inv_dir;

        // Order them along the ray by the sign of 1/d (never NaN, unlike the t's).
        let (mut t_near, mut t_far) =
            if inv_dir >= 0.0 { (t_min_plane, t_max_plane) } else { (t_max_plane, t_min_plane) };

        // An origin on a plane of a parallel slab: 0·∞ = NaN, inside that slab.
        if t_near.is_nan() {
            t_near = Float::NEG_INFINITY;
        }
        if t_far.is_nan() {
            t_far = Float::INFINITY;
        }

        // Widen the exit by the rounding error of the t's.
        t_far *= if t_far >= 0.0 { widen_up } else { widen_down };

        // Intersect with the spans of the other slabs.
        t_enter = t_enter.max(t_near);
        t_exit = t_exit.min(t_far);
    }

    // Clip the box's span to the range.
    if t_enter <= t_exit && t_enter < range.max && t_exit > range.min {
        Some((t_enter.max(range.min), t_exit.min(range.max)))
    } else {
        None
    }
    // SOLUTION END
}

/// The first crossing of `ray` with the surface of the box min ≤ p ≤ max
/// inside `range`: where the ray enters, or where it leaves when it starts
/// inside (t_enter ≤ range.min).
///
/// Found with [`hit_slabs`]. The face is the slab whose plane gave the hit:
/// entering, the slab with the latest entry t; leaving, the one with the
/// earliest exit t (ties at an edge or corner pick either face). Its outward
/// normal is −eᵢ on the min face and +eᵢ on the max face; the ray enters
/// through the min face of axis i when dᵢ > 0 and leaves through it when
/// dᵢ < 0. The face is never found by comparing the hit point with the
/// planes with `==`, which rounding defeats. [`Hit::new`] turns the normal
/// against the ray (`front_face` is false from inside).
///
/// The returned t is the face's own t (not widened). `dir` need not be unit
/// length but must not be zero. Book: §3.2 Which face was hit.
pub fn hit_box(ray: &Ray, min: Vec3, max: Vec3, range: Interval) -> Option<Hit> {
    // SOLUTION BEGIN
    let (t0, _) = hit_slabs(ray, min, max, range)?;
    // Entering when the span starts after the range does; else leaving.
    let entering = t0 > range.min;

    // The face: the latest entry or the earliest exit among the slabs the ray crosses.
    let mut face: Option<(Float, usize)> = None;
    for axis in 0..3 {
        let d = ray.dir[axis];
        if d == 0.0 {
            continue; // a parallel slab has no plane on the ray
        }
        let on_min_face = (d > 0.0) == entering;
        let plane = if on_min_face { min[axis] } else { max[axis] };
        let t = (plane - ray.origin[axis]) * (1.0 / d);
        let better = match face {
            None => true,
            Some((t_best, _)) => (entering && t > t_best) || (!entering && t < t_best),
        };
        if better {
            face = Some((t, axis));
        }
    }
    let (t, axis) = face?;
    if !range.contains(t) {
        return None;
    }

    // The outward normal of that face.
    let on_min_face = (ray.dir[axis] > 0.0) == entering;
    let mut outward = Vec3::ZERO;
    outward[axis] = if on_min_face { -1.0 } else { 1.0 };
    Some(Hit::new(ray, t, outward))
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use raylab::random::Rng;
    use raylab_testing::boxes::{FACE_PLANE_RAYS, GridRay, grid_ray, sixteenths};
    use raylab_testing::exact::exact_hits;
    use raylab_testing::ray;

    /// The cube [−1, 1]³.
    const LO: Vec3 = Vec3::splat(-1.0);
    const HI: Vec3 = Vec3::splat(1.0);

    /// The widened exit t·(1 ± 2γ₃) may exceed the exact exit by 2γ₃ relative,
    /// plus one rounding of the product: 4ε covers both. Never below it.
    fn assert_exit(t1: Float, exact: Float) {
        assert!(t1 >= exact && t1 <= exact + 4.0 * Float::EPSILON * exact.abs(), "exit {t1}, exact {exact}");
    }

    #[test]
    fn generic_ray_enters_and_leaves() {
        // x: [(−1+3)/2, (1+3)/2] = [1, 2]; y: [(−1+2)/1.5, (1+2)/1.5] = [2/3, 2];
        // z: [−1/0.25, 1/0.25] = [−4, 4]. Span [1, 2]; t_enter = 2·0.5 = 1 exactly.
        let r = ray([-3.0, -2.0, 0.0], [2.0, 1.5, 0.25]);
        let (t0, t1) = hit_slabs(&r, LO, HI, Interval::POSITIVE).unwrap();
        assert_eq!(t0, 1.0);
        assert_exit(t1, 2.0);
        let hit = hit_box(&r, LO, HI, Interval::POSITIVE).unwrap();
        assert_eq!((hit.t, hit.normal, hit.front_face), (1.0, -Vec3::X, true));
    }

    #[test]
    fn misses_beside_and_behind() {
        // x span [2, 4], y span [−1, 1]: the slabs' spans do not overlap.
        assert_eq!(hit_slabs(&ray([-3.0, 0.0, 0.0], [1.0, 1.0, 0.0]), LO, HI, Interval::POSITIVE), None);
        // The box lies behind the origin: the span [−4, −2] is outside (0, ∞).
        let away = ray([3.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        assert_eq!(hit_slabs(&away, LO, HI, Interval::POSITIVE), None);
        // ... but is found with a range that reaches back: the span [−4, −2], its negative
        // exit widened toward +∞ (by 1 − 2γ₃), never toward 0 or −∞.
        let (t0, t1) = hit_slabs(&away, LO, HI, Interval::new(-10.0, 10.0)).unwrap();
        assert_eq!(t0, -4.0);
        assert_exit(t1, -2.0);
        // The box is beyond range.max = 1.5 (it starts at t = 2).
        assert_eq!(hit_slabs(&ray([-3.0, 0.0, 0.0], [1.0, 0.0, 0.0]), LO, HI, Interval::new(0.0, 1.5)), None);
    }

    #[test]
    fn origin_inside_hits_the_exit_face() {
        // From the centre along +x: span [−1, 1], clipped to (0, ∞) → t0 = 0.
        let r = ray([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        let (t0, t1) = hit_slabs(&r, LO, HI, Interval::POSITIVE).unwrap();
        assert_eq!(t0, 0.0);
        assert_exit(t1, 1.0);
        let hit = hit_box(&r, LO, HI, Interval::POSITIVE).unwrap();
        assert_eq!(
            (hit.t, hit.outward_normal(), hit.normal, hit.front_face),
            (1.0, Vec3::X, -Vec3::X, false)
        );
        // The exit beyond range.max = 0.5 is no hit.
        assert!(hit_box(&r, LO, HI, Interval::new(0.0, 0.5)).is_none());
    }

    #[test]
    fn axis_parallel_rays_inside_outside_and_on_a_face_plane() {
        let inside = ray([-3.0, 0.5, -0.5], [1.0, 0.0, 0.0]);
        let (t0, t1) = hit_slabs(&inside, LO, HI, Interval::POSITIVE).unwrap();
        assert_eq!(t0, 2.0);
        assert_exit(t1, 4.0);
        assert_eq!(hit_slabs(&ray([-3.0, 1.5, 0.0], [1.0, 0.0, 0.0]), LO, HI, Interval::POSITIVE), None);
        assert_eq!(hit_slabs(&ray([-3.0, 0.0, -1.5], [1.0, 0.0, -0.0]), LO, HI, Interval::POSITIVE), None);
        // Origins exactly on a face plane (y = 1, y = −1) or on an edge line (y = z = 1),
        // with +0 and −0 direction components: 0·∞ = NaN must count as inside.
        for (o, d) in FACE_PLANE_RAYS {
            let (t0, t1) = hit_slabs(&ray(o, d), LO, HI, Interval::POSITIVE).expect("ray along a face");
            assert_eq!(t0, 2.0, "{o:?} {d:?}");
            assert_exit(t1, 4.0);
            let hit = hit_box(&ray(o, d), LO, HI, Interval::POSITIVE).unwrap();
            assert_eq!(hit.t, 2.0);
            assert_eq!(hit.normal, Vec3::new(-d[0].signum(), 0.0, 0.0), "{o:?} {d:?}");
        }
    }

    #[test]
    fn flat_box_is_hit_once_and_along_its_plane() {
        // The square x = 0, −1 ≤ y, z ≤ 1 as a box with min.x == max.x.
        let (lo, hi) = (Vec3::new(0.0, -1.0, -1.0), Vec3::new(0.0, 1.0, 1.0));
        let across = ray([-1.0, 0.5, 0.5], [1.0, 0.0, 0.0]);
        let (t0, t1) = hit_slabs(&across, lo, hi, Interval::POSITIVE).unwrap();
        assert_eq!(t0, 1.0);
        assert_exit(t1, 1.0);
        let hit = hit_box(&across, lo, hi, Interval::POSITIVE).unwrap();
        assert_eq!((hit.t, hit.normal), (1.0, -Vec3::X));
        // A ray in the plane x = 0: both x ends are 0·∞ = NaN; y span [2, 4].
        let along = ray([0.0, -3.0, 0.0], [0.0, 1.0, 0.0]);
        let (t0, t1) = hit_slabs(&along, lo, hi, Interval::POSITIVE).unwrap();
        assert_eq!(t0, 2.0);
        assert_exit(t1, 4.0);
        // An oblique ray through the flat box: x span [1/3·3, …] = [1, 1] exactly.
        let oblique = ray([-3.0, -1.0, 0.5], [3.0, 1.0, -0.25]);
        assert!(hit_slabs(&oblique, lo, hi, Interval::POSITIVE).is_some_and(|(t0, _)| t0 == 1.0));
    }

    #[test]
    fn rays_exactly_through_edges_and_corners_hit() {
        // Through the edge x = y = −1 into the box: x and y spans [2, 4].
        let (t0, _) =
            hit_slabs(&ray([-3.0, -3.0, 0.0], [1.0, 1.0, 0.0]), LO, HI, Interval::POSITIVE).unwrap();
        assert_eq!(t0, 2.0);
        // Through the corner (−1, −1, −1): all three spans [2, 4].
        let (t0, _) = hit_slabs(&ray([-3.0; 3], [1.0; 3]), LO, HI, Interval::POSITIVE).unwrap();
        assert_eq!(t0, 2.0);
        // Touching only the edge x = y = 1 at t = 1: x [−1, 1], y [1, 3] → [1, 1].
        let (t0, t1) =
            hit_slabs(&ray([0.0, 2.0, 0.0], [1.0, -1.0, 0.0]), LO, HI, Interval::POSITIVE).unwrap();
        assert_eq!(t0, 1.0);
        assert_exit(t1, 1.0);
        // Touching only the corner (1, 1, 1) at t = 1: x [−1, 1], y and z [1, 3].
        let r = ray([0.0, 2.0, 2.0], [1.0, -1.0, -1.0]);
        assert!(hit_slabs(&r, LO, HI, Interval::POSITIVE).is_some_and(|(t0, _)| t0 == 1.0));
        assert!(hit_box(&r, LO, HI, Interval::POSITIVE).is_some_and(|h| h.t == 1.0));
    }

    #[test]
    fn box_normals_on_each_of_the_six_faces() {
        for axis in 0..3 {
            for sign in [-1.0, 1.0] {
                let mut outward = Vec3::ZERO;
                outward[axis] = sign;
                // From outside toward the face centre, slightly oblique: enters at t = 2.
                let oblique = Vec3::new(0.1, -0.05, 0.07) - Vec3::new(0.1, -0.05, 0.07) * outward.abs();
                let from_out = Ray::new(3.0 * outward + oblique, -outward);
                let hit = hit_box(&from_out, LO, HI, Interval::POSITIVE).unwrap();
                assert_eq!((hit.t, hit.normal, hit.front_face), (2.0, outward, true), "face {outward}");
                // From inside toward the face: leaves at t = 1 with the normal facing the ray.
                let from_in = Ray::new(oblique, outward + 0.25 * oblique);
                let hit = hit_box(&from_in, LO, HI, Interval::POSITIVE).unwrap();
                assert_eq!((hit.outward_normal(), hit.front_face), (outward, false), "face {outward}");
                assert_relative_eq!(hit.t, 1.0, max_relative = 2.0 * Float::EPSILON);
            }
        }
    }

    #[test]
    fn no_false_misses_against_an_exact_reference() {
        // Coordinates are integers/16, exact in f32 and f64, so the reference sees
        // the very numbers the routine sees; 1/d and the products still round.
        let mut rng = Rng::new(3);
        let (mut hits, mut false_hits, mut boundary) = (0, 0, 0);
        for n in 0..20_000 {
            // Half of them aimed exactly at the box's boundary: a face, an edge or a corner.
            let aimed = n % 2 == 1;
            boundary += aimed as u32;
            let GridRay { lo, hi, o, d } = grid_ray(&mut rng, aimed);
            if d == [0; 3] {
                continue;
            }
            let r = Ray::new(sixteenths(o), sixteenths(d));
            let found = hit_slabs(&r, sixteenths(lo), sixteenths(hi), Interval::POSITIVE);
            if let Some((t0, t1)) = found {
                assert!(!t0.is_nan() && !t1.is_nan() && t0 <= t1, "{t0} {t1} for {o:?} {d:?}");
            }
            let exact = exact_hits(o, d, lo, hi);
            assert!(
                !exact || found.is_some(),
                "false miss: origin {o:?}, dir {d:?}, box {lo:?}..{hi:?} (units of 1/16)"
            );
            hits += exact as u32;
            false_hits += (!exact && found.is_some()) as u32;
        }
        eprintln!(
            "slabs: {hits} exact hits of 20000 rays ({boundary} aimed at the boundary), {false_hits} false hits"
        );
        // The widening admits misses by a few ulps only; on this grid that is rare.
        assert!(false_hits <= 20, "{false_hits} false hits");
    }
}
