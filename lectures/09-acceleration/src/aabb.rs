//! Axis-aligned bounding boxes: the bounding volume of the hierarchy.
//!
//! A box is cheap to test (three slabs, six multiplications with the ray's
//! precomputed reciprocal direction), cheap to merge (a componentwise min and
//! max) and its surface area prices it for the SAH (`sah.rs`).

use raylab::math::gamma;
use raylab::{Float, Interval, Ray, Vec3};

/// The axis-aligned box of the points p with min ≤ p ≤ max (componentwise).
///
/// [`Aabb::EMPTY`] (min = +∞, max = −∞) holds nothing and is the identity of
/// [`Aabb::union`]; [`Aabb::INFINITE`] holds everything (a plane's bounds).
/// A box with minᵢ = maxᵢ is flat and still holds the points of its plane.
/// Book: §9.1 Axis-aligned bounding boxes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

impl Aabb {
    /// The empty box: min = +∞, max = −∞, so that any union replaces both.
    pub const EMPTY: Aabb = Aabb { min: Vec3::INFINITY, max: Vec3::NEG_INFINITY };

    /// The box of all space: min = −∞, max = +∞.
    pub const INFINITE: Aabb = Aabb { min: Vec3::NEG_INFINITY, max: Vec3::INFINITY };

    /// The box min ≤ p ≤ max (`min ≤ max` componentwise for a non-empty box).
    pub const fn new(min: Vec3, max: Vec3) -> Self {
        Self { min, max }
    }

    /// True when the box holds no point: minᵢ > maxᵢ on some axis (or a NaN end).
    pub fn is_empty(&self) -> bool {
        !self.min.cmple(self.max).all()
    }

    /// True when all six ends are finite numbers (the box is bounded and not empty).
    pub fn is_finite(&self) -> bool {
        self.min.is_finite() && self.max.is_finite()
    }

    /// True when `p` is in the closed box.
    pub fn contains(&self, p: Vec3) -> bool {
        self.min.cmple(p).all() && p.cmple(self.max).all()
    }

    /// The smallest box holding both boxes: the componentwise min of the mins
    /// and max of the maxes. The union with [`Aabb::EMPTY`] changes nothing.
    /// Book: §9.1 Axis-aligned bounding boxes.
    pub fn union(self, other: Aabb) -> Aabb {
        // SOLUTION BEGIN
        Aabb::new(self.min.min(other.min), self.max.max(other.max))
        // SOLUTION END
    }

    /// The smallest box holding the box and the point `p` (for the empty box,
    /// the flat box min = max = p). Book: §9.1 Axis-aligned bounding boxes.
    pub fn union_point(self, p: Vec3) -> Aabb {
        // SOLUTION BEGIN
        Aabb::new(self.min.min(p), self.max.max(p))
        // SOLUTION END
    }

    /// The centre (min + max)/2. Meaningless for an empty or infinite box.
    pub fn centroid(&self) -> Vec3 {
        0.5 * (self.min + self.max)
    }

    /// The extent max − min along each axis.
    pub fn diagonal(&self) -> Vec3 {
        self.max - self.min
    }

    /// The area of the box's six faces, 2(dₓd_y + d_yd_z + d_zdₓ) with
    /// d = max − min: what the SAH charges for a box, since a random ray
    /// meets a convex body with a probability proportional to its surface area.
    /// A flat box has the area of both sides of its rectangle; a point, a
    /// segment and the empty box have area 0; an unbounded box has area ∞.
    /// Book: §9.4 The surface area heuristic.
    pub fn surface_area(&self) -> Float {
        // SOLUTION BEGIN
        if self.is_empty() {
            return 0.0;
        }
        let d = self.diagonal();
        2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
        // SOLUTION END
    }

    /// The axis (0 = x, 1 = y, 2 = z) along which the box is longest; ties go
    /// to the lower axis, so a cube answers x.
    pub fn longest_axis(&self) -> usize {
        let d = self.diagonal();
        if d.x >= d.y && d.x >= d.z {
            0
        } else if d.y >= d.z {
            1
        } else {
            2
        }
    }

    /// The span (t0, t1) of `ray` inside the closed box, clipped to `range`,
    /// by the slab method of §3.1 with the reciprocal direction `inv_dir`
    /// = (1/dₓ, 1/d_y, 1/d_z) computed once per ray, so each slab costs two
    /// subtractions and two multiplications, no division: a traversal makes
    /// dozens of box tests per ray, and a division costs several multiplications.
    ///
    /// Slab i holds t between (minᵢ − oᵢ)/dᵢ and (maxᵢ − oᵢ)/dᵢ, ordered by
    /// the sign of 1/dᵢ; the box holds [t_enter, t_exit], the latest entry and
    /// the earliest exit. Returns `Some((max(t_enter, range.min),
    /// min(t_exit, range.max)))` when t_enter ≤ t_exit, t_enter < range.max
    /// and t_exit > range.min, else `None`: so a box that starts beyond the
    /// closest hit found so far (range.max) is skipped with its whole subtree.
    ///
    /// Axis-parallel rays: 1/dᵢ = ±∞ (a −0 component gives −∞), the slab's
    /// span is all t when the origin is strictly between its planes and empty
    /// when it is outside; an origin exactly on a plane gives 0·∞ = NaN, taken
    /// as the unbounded end (inside the slab), as in 03's `hit_slabs`, so no
    /// NaN reaches the result and a ray along a face of a node still enters it.
    ///
    /// Conservative at both ends: each t carries three roundings (the
    /// difference, the reciprocal, the product), a relative error of at most
    /// γ₃, and a box stands for primitives whose own tests round too, so the
    /// entry is lowered and the exit raised by 2γ₃ (relative): a primitive
    /// hit on its box's boundary, at a t its own test rounds a little below
    /// the box's entry, is not culled (03's `hit_slabs` widens the exit only;
    /// with it, rays through a mesh's vertices find a different triangle than
    /// brute force). The widening is applied once, to t_enter and t_exit,
    /// rather than to each plane's t: multiplying by a constant factor
    /// (chosen by the sign) never reverses an order, so widening the latest
    /// entry gives the latest widened entry, for a third of the work. The
    /// empty box is never hit.
    ///
    /// `inv_dir` must be `ray.dir.recip()`; `dir` must not be zero.
    /// Book: §9.2 Ray–box tests with reciprocals.
    #[inline(always)] // two per inner node in the traversal's hot loop
    pub fn hit(&self, ray: &Ray, inv_dir: Vec3, range: Interval) -> Option<(Float, Float)> {
        debug_assert!(ray.dir != Vec3::ZERO, "the ray direction must not be zero");
        debug_assert!(inv_dir == ray.dir.recip(), "inv_dir must be 1/dir, found {inv_dir} for {}", ray.dir);
        // SOLUTION BEGIN
        let widen_up = 1.0 + 2.0 * gamma(3);
        let widen_down = 1.0 - 2.0 * gamma(3);

        // The parameters of each slab's two planes (±∞ for a parallel ray).
        let t_min_planes = (self.min - ray.origin) * inv_dir;
        let t_max_planes = (self.max - ray.origin) * inv_dir;

        // Order each pair along the ray by the sign of 1/d.
        let negative = inv_dir.cmplt(Vec3::ZERO);
        let t_near = Vec3::select(negative, t_max_planes, t_min_planes);
        let t_far = Vec3::select(negative, t_min_planes, t_max_planes);

        // The latest entry and the earliest exit. `max` and `min` pass over a NaN
        // (an origin on a plane of a parallel slab), which so counts as inside.
        let t_enter = Float::NEG_INFINITY.max(t_near.x).max(t_near.y).max(t_near.z);
        let t_exit = Float::INFINITY.min(t_far.x).min(t_far.y).min(t_far.z);

        // Widen both ends by the rounding error of the t's.
        let t_enter = t_enter * if t_enter >= 0.0 { widen_down } else { widen_up };
        let t_exit = t_exit * if t_exit >= 0.0 { widen_up } else { widen_down };

        // Clip the box's span to the range.
        if t_enter <= t_exit && t_enter < range.max && t_exit > range.min {
            Some((t_enter.max(range.min), t_exit.min(range.max)))
        } else {
            None
        }
        // SOLUTION END
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::Rng;
    use l03_polygons_triangles::hit_slabs;
    use raylab_testing::boxes::FACE_PLANE_RAYS;
    use raylab_testing::ray;

    const EPS: Float = Float::EPSILON;

    fn cube() -> Aabb {
        Aabb::new(Vec3::splat(-1.0), Vec3::ONE)
    }

    fn hit(b: &Aabb, r: &Ray, range: Interval) -> Option<(Float, Float)> {
        b.hit(r, r.dir.recip(), range)
    }

    /// The widened ends stay within 2γ₃ (< 4ε) plus one rounding of the exact
    /// t: `t` lies in [exact(1 − 5ε), exact] for an entry and
    /// [exact, exact(1 + 5ε)] for an exit (exact > 0).
    fn assert_entry(t: Float, exact: Float) {
        assert!(t <= exact && t >= exact * (1.0 - 5.0 * EPS), "entry {t}, exact {exact}");
    }
    fn assert_exit(t: Float, exact: Float) {
        assert!(t >= exact && t <= exact * (1.0 + 5.0 * EPS), "exit {t}, exact {exact}");
    }

    #[test]
    fn union_and_union_point_by_hand() {
        let a = Aabb::new(Vec3::new(0.0, 1.0, 2.0), Vec3::new(1.0, 2.0, 3.0));
        let b = Aabb::new(Vec3::new(-1.0, 1.5, 2.5), Vec3::new(0.5, 4.0, 2.75));
        assert_eq!(a.union(b), Aabb::new(Vec3::new(-1.0, 1.0, 2.0), Vec3::new(1.0, 4.0, 3.0)));
        assert_eq!(a.union(b), b.union(a));
        let p = Vec3::new(5.0, 0.0, 2.5);
        assert_eq!(a.union_point(p), Aabb::new(Vec3::new(0.0, 0.0, 2.0), Vec3::new(5.0, 2.0, 3.0)));
        // A point inside changes nothing.
        assert_eq!(a.union_point(Vec3::new(0.5, 1.5, 2.5)), a);
    }

    #[test]
    fn empty_box_is_the_identity_of_union_and_holds_nothing() {
        let a = Aabb::new(Vec3::new(-1.0, 0.0, 2.0), Vec3::new(1.0, 0.0, 3.0));
        assert_eq!(Aabb::EMPTY.union(a), a);
        assert_eq!(a.union(Aabb::EMPTY), a);
        assert_eq!(Aabb::EMPTY.union(Aabb::EMPTY), Aabb::EMPTY);
        let p = Vec3::new(1.0, -2.0, 3.0);
        assert_eq!(Aabb::EMPTY.union_point(p), Aabb::new(p, p));
        assert!(Aabb::EMPTY.is_empty() && !Aabb::EMPTY.is_finite());
        assert!(!Aabb::EMPTY.contains(Vec3::ZERO));
        assert!(!a.is_empty() && a.is_finite(), "a flat box is not empty");
        assert!(Aabb::INFINITE.contains(Vec3::splat(1e30)) && !Aabb::INFINITE.is_finite());
    }

    #[test]
    fn surface_area_by_hand() {
        // 2·(2·3 + 3·4 + 4·2) = 52.
        let b = Aabb::new(Vec3::ZERO, Vec3::new(2.0, 3.0, 4.0));
        assert_eq!(b.surface_area(), 52.0);
        // Flat 2 × 3 rectangle: both sides, 12. A segment and a point: 0.
        assert_eq!(Aabb::new(Vec3::ZERO, Vec3::new(2.0, 3.0, 0.0)).surface_area(), 12.0);
        assert_eq!(Aabb::new(Vec3::ZERO, Vec3::new(2.0, 0.0, 0.0)).surface_area(), 0.0);
        assert_eq!(Aabb::new(Vec3::ONE, Vec3::ONE).surface_area(), 0.0);
        assert_eq!(Aabb::EMPTY.surface_area(), 0.0);
        assert_eq!(Aabb::INFINITE.surface_area(), Float::INFINITY);
    }

    #[test]
    fn centroid_and_longest_axis_by_hand() {
        let b = Aabb::new(Vec3::new(-1.0, 0.0, 2.0), Vec3::new(3.0, 1.0, 8.0));
        assert_eq!(b.centroid(), Vec3::new(1.0, 0.5, 5.0));
        assert_eq!(b.longest_axis(), 2);
        assert_eq!(Aabb::new(Vec3::ZERO, Vec3::new(1.0, 3.0, 2.0)).longest_axis(), 1);
        // Ties go to the lower axis.
        assert_eq!(cube().longest_axis(), 0);
        assert_eq!(Aabb::new(Vec3::ZERO, Vec3::new(1.0, 2.0, 2.0)).longest_axis(), 1);
    }

    #[test]
    fn slab_span_by_hand() {
        // As in 03: x span [1, 2], y [2/3, 2], z [−4, 4]: the box holds [1, 2].
        let r = ray([-3.0, -2.0, 0.0], [2.0, 1.5, 0.25]);
        let (t0, t1) = hit(&cube(), &r, Interval::POSITIVE).unwrap();
        assert_entry(t0, 1.0);
        assert_exit(t1, 2.0);
        // Beside the box (x span [2, 4], y span [−1, 1]), behind it, beyond range.max.
        assert_eq!(hit(&cube(), &ray([-3.0, 0.0, 0.0], [1.0, 1.0, 0.0]), Interval::POSITIVE), None);
        assert_eq!(hit(&cube(), &ray([3.0, 0.0, 0.0], [1.0, 0.0, 0.0]), Interval::POSITIVE), None);
        assert_eq!(hit(&cube(), &ray([-3.0, 0.0, 0.0], [1.0, 0.0, 0.0]), Interval::new(0.0, 1.5)), None);
        // From inside: the span starts at range.min.
        let (t0, t1) = hit(&cube(), &ray([0.0; 3], [0.0, 0.0, -2.0]), Interval::POSITIVE).unwrap();
        assert_eq!(t0, 0.0);
        assert_exit(t1, 0.5);
        // The empty box is never hit, not even from inside "everything".
        assert_eq!(hit(&Aabb::EMPTY, &r, Interval::new(Float::NEG_INFINITY, Float::INFINITY)), None);
        let (t0, t1) = hit(&Aabb::INFINITE, &r, Interval::POSITIVE).unwrap();
        assert_eq!((t0, t1), (0.0, Float::INFINITY));
    }

    #[test]
    fn axis_parallel_rays_starting_on_a_face_plane_are_inside_that_slab() {
        // Origins exactly on the planes y = ±1 (and on an edge line) moving along ±x with
        // ±0 in the other components: 0·∞ = NaN must count as inside; x span [2, 4].
        for (o, d) in FACE_PLANE_RAYS {
            let (t0, t1) = hit(&cube(), &ray(o, d), Interval::POSITIVE).expect("a ray along a face");
            assert_entry(t0, 2.0);
            assert_exit(t1, 4.0);
        }
        // Just outside the face plane: a miss.
        assert_eq!(
            hit(&cube(), &ray([-3.0, 1.0 + 4.0 * EPS, 0.0], [1.0, 0.0, 0.0]), Interval::POSITIVE),
            None
        );
    }

    #[test]
    fn flat_box_is_hit_across_and_along_its_plane() {
        // The square x = 0, −1 ≤ y, z ≤ 1 as a box with min.x = max.x.
        let flat = Aabb::new(Vec3::new(0.0, -1.0, -1.0), Vec3::new(0.0, 1.0, 1.0));
        let (t0, t1) = hit(&flat, &ray([-1.0, 0.5, 0.5], [1.0, 0.0, 0.0]), Interval::POSITIVE).unwrap();
        assert_entry(t0, 1.0);
        assert_exit(t1, 1.0);
        // In its plane: both x ends are 0·∞ = NaN; the y span is [2, 4].
        let (t0, t1) = hit(&flat, &ray([0.0, -3.0, 0.0], [0.0, 1.0, 0.0]), Interval::POSITIVE).unwrap();
        assert_entry(t0, 2.0);
        assert_exit(t1, 4.0);
    }

    #[test]
    fn span_contains_03s_slab_span_and_is_barely_wider() {
        // 03's hit_slabs widens the exit only; this test widens both ends, so on 20 000
        // random rays and boxes (half of them aimed at the box) its span must contain 03's, and differ from it by at most
        // the widening: 2γ₃·|t| plus one rounding, < 5ε·|t| (asserted). Rays that only this
        // test hits are misses by a few ulps; they must be rare.
        let mut rng = Rng::new(9);
        let (mut both, mut only_wide) = (0, 0);
        for _ in 0..20_000 {
            let (a, b) = (rng.in_cube(4.0), rng.in_cube(4.0));
            let mut b = b;
            if rng.below(8) == 0 {
                b.y = a.y; // one box in eight is flat
            }
            let bx = Aabb::new(a.min(b), a.max(b));
            let origin = rng.in_cube(8.0);
            let mut d = if rng.below(2) == 0 {
                rng.in_cube(1.0)
            } else {
                // Aimed at a point of the box, one in two on a face plane.
                let mut target = bx.min.lerp(bx.max, rng.range(0.0, 1.0));
                let axis = rng.below(3) as usize;
                if rng.below(2) == 0 {
                    target[axis] = if rng.below(2) == 0 { bx.min[axis] } else { bx.max[axis] };
                }
                target - origin
            };
            if rng.below(4) == 0 {
                d.x = 0.0; // axis-parallel in one component
            }
            if d == Vec3::ZERO {
                continue;
            }
            let r = Ray::new(origin, d);
            let range = Interval::new(0.0, rng.range(1.0, 30.0));
            match (hit_slabs(&r, bx.min, bx.max, range), hit(&bx, &r, range)) {
                (Some((s0, s1)), Some((t0, t1))) => {
                    both += 1;
                    assert!(t0 <= s0 && s1 <= t1, "{t0} {t1} does not contain {s0} {s1}");
                    assert!(s0 - t0 <= 5.0 * EPS * s0.abs() && t1 - s1 <= 5.0 * EPS * t1.abs());
                }
                (Some(s), None) => panic!("03 finds {s:?} but the node test misses {r:?} {bx:?}"),
                (None, Some(_)) => only_wide += 1,
                (None, None) => {}
            }
        }
        eprintln!("aabb: {both} hits shared with 03's slabs, {only_wide} near misses only widened");
        assert!(both > 5_000, "too few hits ({both}) for the comparison to mean much");
        assert!(only_wide <= 20, "{only_wide} extra hits");
    }
}
