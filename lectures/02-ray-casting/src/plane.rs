//! Ray–plane intersection.
//!
//! In a scene file: `{ type = "plane", normal = [0, 1, 0], offset = -1 }`
//! (the plane y = −1, facing up).

use raylab::{Float, Hit, Interval, Ray, Vec3};

/// The plane n·p = offset, for the unit normal n: substituting p = o + t·d
/// gives n·o + t·(n·d) = offset, so t = (offset − n·o) / (n·d).
///
/// The plane's outward side is the one n points to: a ray arriving from that
/// side gets `front_face` true and the normal n, a ray from behind gets the
/// normal −n (it always faces the ray). A ray parallel to the plane (n·d = 0,
/// including a ray lying in the plane) never hits: no NaN, no infinite t.
/// `dir` need not be unit. Book: §2.5 Planes.
pub fn hit_plane(ray: &Ray, normal: Vec3, offset: Float, range: Interval) -> Option<Hit> {
    debug_assert!(normal.is_normalized(), "the plane's normal must be unit length");
    // SOLUTION BEGIN
    // A ray parallel to the plane never meets it.
    let denominator = normal.dot(ray.dir);
    if denominator == 0.0 {
        return None;
    }
    // Where the ray meets the plane; a nearly parallel ray may overflow to ±∞, which no
    // interval contains.
    let t = (offset - normal.dot(ray.origin)) / denominator;
    if !range.contains(t) {
        return None;
    }
    Some(Hit::new(ray, t, normal))
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab_testing::v;

    const EPS: Float = Float::EPSILON;

    #[test]
    fn hit_from_the_front_keeps_the_normal() {
        // The plane y = 0 seen from (1, 2, 3) straight down: t = (0 − 2)/(−1) = 2 at (1, 0, 3).
        let ray = Ray::new(v(1.0, 2.0, 3.0), -Vec3::Y);
        let hit = hit_plane(&ray, Vec3::Y, 0.0, Interval::POSITIVE).expect("straight down");
        assert_eq!((hit.t, hit.point, hit.normal, hit.front_face), (2.0, v(1.0, 0.0, 3.0), Vec3::Y, true));
    }

    #[test]
    fn hit_from_behind_flips_the_normal() {
        // From (1, −2, 3) straight up: t = (0 + 2)/1 = 2, from the back side, normal −y.
        let ray = Ray::new(v(1.0, -2.0, 3.0), Vec3::Y);
        let hit = hit_plane(&ray, Vec3::Y, 0.0, Interval::POSITIVE).expect("straight up");
        assert_eq!((hit.t, hit.point, hit.normal, hit.front_face), (2.0, v(1.0, 0.0, 3.0), -Vec3::Y, false));
        assert_eq!(hit.outward_normal(), Vec3::Y);
    }

    #[test]
    fn offset_plane_with_a_slanted_normal() {
        // n = (0.6, 0.8, 0) (a 3-4-5 triangle), offset 5: the plane 0.6x + 0.8y = 5, at distance
        // 5 from the origin. From the origin along d = 2n: n·d = 2, t = 5/2 = 2.5, p = 5n.
        // Tolerance: 0.6 and 0.8 are rounded in binary, so n·n = 1 and n·d = 2 only up to a few
        // ε: allow 4ε relative on t and 8ε·|p| on the point.
        let n = v(0.6, 0.8, 0.0);
        let ray = Ray::new(Vec3::ZERO, 2.0 * n);
        let hit = hit_plane(&ray, n, 5.0, Interval::POSITIVE).expect("toward the plane");
        assert!((hit.t - 2.5).abs() <= 4.0 * EPS * 2.5, "t = {}", hit.t);
        assert!((hit.point - 5.0 * n).length() <= 8.0 * EPS * 5.0, "p = {}", hit.point);
        // Seen from the origin the plane's normal points away: the origin is behind it.
        assert!(!hit.front_face);
        // The negative offset: the same normal, the plane on the other side of the origin.
        let ray = Ray::new(Vec3::ZERO, -n);
        let hit = hit_plane(&ray, n, -5.0, Interval::POSITIVE).expect("toward the plane");
        assert!((hit.t - 5.0).abs() <= 4.0 * EPS * 5.0, "t = {}", hit.t);
        assert!(hit.front_face, "the origin is on the side n points to");
    }

    #[test]
    fn parallel_ray_never_hits() {
        // n·d = 0 exactly: 0.6·0.8 − 0.8·0.6 rounds both products identically.
        let n = v(0.6, 0.0, 0.8);
        let d = v(0.8, 0.0, -0.6);
        assert_eq!(n.dot(d), 0.0);
        for offset in [0.0, 1.0, -3.0] {
            let ray = Ray::new(v(1.0, 2.0, 3.0), d);
            assert_eq!(hit_plane(&ray, n, offset, Interval::POSITIVE), None, "offset {offset}");
            assert_eq!(hit_plane(&ray, n, offset, Interval::new(Float::MIN, Float::MAX)), None);
        }
    }

    #[test]
    fn ray_in_the_plane_never_hits() {
        // Origin on y = 0 and direction along it: 0/0 if computed blindly.
        let ray = Ray::new(v(1.0, 0.0, 3.0), v(1.0, 0.0, -1.0));
        assert_eq!(hit_plane(&ray, Vec3::Y, 0.0, Interval::POSITIVE), None);
        assert_eq!(hit_plane(&ray, Vec3::Y, 0.0, Interval::new(-Float::INFINITY, Float::INFINITY)), None);
    }

    #[test]
    fn nearly_parallel_ray_gives_finite_t_or_nothing() {
        // n·d = 10⁻³⁰ (a normal number in f32 and f64): t = 1/10⁻³⁰ = 10³⁰, finite, far away.
        let ray = Ray::new(v(0.0, 1.0, 0.0), v(1.0, -1e-30, 0.0));
        let hit = hit_plane(&ray, Vec3::Y, 0.0, Interval::POSITIVE).expect("grazing hit far away");
        assert!(hit.t.is_finite() && hit.point.is_finite(), "{hit:?}");
        assert!((hit.t - 1e30).abs() <= 2.0 * EPS * 1e30, "t = {}", hit.t);
        // With n·d the smallest positive subnormal and a far origin, t overflows to ∞:
        // no interval contains it, so no hit rather than an infinite t.
        let tiny = Float::from_bits(1);
        let ray = Ray::new(v(0.0, 1e10, 0.0), v(1.0, -tiny, 0.0));
        assert_eq!(hit_plane(&ray, Vec3::Y, 0.0, Interval::POSITIVE), None);
    }

    #[test]
    fn range_excludes_hits_behind_at_min_and_at_max() {
        // From (0, 2, 0) down onto y = 0: t = 2 (exact).
        let ray = Ray::new(v(0.0, 2.0, 0.0), -Vec3::Y);
        let t_in = |min, max| hit_plane(&ray, Vec3::Y, 0.0, Interval::new(min, max)).map(|h| h.t);
        assert_eq!(t_in(0.0, Float::INFINITY), Some(2.0));
        assert_eq!(t_in(2.0, 10.0), None, "t = min is excluded");
        assert_eq!(t_in(0.0, 2.0), None, "t = max is excluded");
        let up = Ray::new(v(0.0, 2.0, 0.0), Vec3::Y);
        assert_eq!(hit_plane(&up, Vec3::Y, 0.0, Interval::POSITIVE), None, "the plane is behind");
    }

    #[test]
    fn longer_direction_gives_proportionally_smaller_t() {
        // From (0, 2, 0) along d = (1, −2, 1)·k the plane y = 0 is met at (1, 0, 1), t = 1/k
        // (exact: k is a power of two).
        for (k, t) in [(1.0, 1.0), (2.0, 0.5), (0.25, 4.0)] {
            let ray = Ray::new(v(0.0, 2.0, 0.0), v(1.0, -2.0, 1.0) * k);
            let hit = hit_plane(&ray, Vec3::Y, 0.0, Interval::POSITIVE).expect("toward the plane");
            assert_eq!((hit.t, hit.point), (t, v(1.0, 0.0, 1.0)), "k = {k}");
        }
    }
}
