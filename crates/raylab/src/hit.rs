//! The record of a ray–surface intersection.

use crate::math::{Float, Vec2, Vec3};
use crate::ray::{Interval, Ray};

/// Where a ray meets a surface.
///
/// `normal` is unit length and faces against the incoming ray
/// (`normal·dir ≤ 0`); `front_face` tells whether the ray arrived from the
/// outside, i.e. whether the surface's outward normal had to be kept (true)
/// or flipped (false). `object` and `material` are indices into the scene's
/// objects and materials, filled in by the group that found the hit (0 for a
/// bare shape). Book: §0.3 Hits and normals.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Hit {
    pub t: Float,
    pub point: Vec3,
    pub normal: Vec3,
    pub front_face: bool,
    pub uv: Vec2,
    pub object: usize,
    pub material: usize,
}

impl Hit {
    /// A hit at parameter `t` of `ray` on a surface whose outward normal there
    /// is `outward_normal` (any length, not zero): the normal is normalised
    /// and flipped to face against the ray, and `front_face` records which.
    ///
    /// A non-finite normal is a bug in the caller (debug builds stop on it;
    /// release builds substitute one rather than spread a NaN). A zero normal
    /// is not always one: where the coordinates outgrow the precision, the
    /// hit point can round onto the point the normal is measured from (a
    /// sphere of radius ½ hit by a ray from 10¹⁵ away, in f32, whose spacing
    /// there is 6·10⁷; found by the bad-scenes fuzz test of `grader render`).
    /// Such a hit, whose surface orientation is lost, faces the ray head-on:
    /// normal −d̂, or +z for a ray without a direction.
    #[inline]
    pub fn new(ray: &Ray, t: Float, outward_normal: Vec3) -> Self {
        debug_assert!(outward_normal.is_finite(), "Hit::new needs a finite normal, found {outward_normal}");
        let lost = || (-ray.dir).try_normalize().unwrap_or(Vec3::Z);
        Self::facing(ray, t, outward_normal.try_normalize().unwrap_or_else(lost))
    }

    /// [`Hit::new`] for an outward normal `n` already normalised (its
    /// `try_normalize` done by the caller, once, and reused): the same record.
    #[inline]
    pub fn facing(ray: &Ray, t: Float, n: Vec3) -> Self {
        let front_face = ray.dir.dot(n) < 0.0;
        Self {
            t,
            point: ray.at(t),
            normal: if front_face { n } else { -n },
            front_face,
            uv: Vec2::ZERO,
            object: 0,
            material: 0,
        }
    }

    /// The same hit with texture coordinates `uv`.
    pub fn with_uv(self, uv: Vec2) -> Self {
        Self { uv, ..self }
    }

    /// The outward normal of the surface (the normal before it was turned to
    /// face the ray).
    pub fn outward_normal(&self) -> Vec3 {
        if self.front_face { self.normal } else { -self.normal }
    }
}

/// What the lectures implement to find hits in a whole scene: the brute-force
/// group of lectures 02–04 and the BVH of lecture 09 both implement it, so the
/// tracer of lecture 08 works with either.
pub trait Intersector: Sync {
    /// The closest hit with `range.min < t < range.max`, if any.
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit>;

    /// Whether anything is hit in `range`. Implementations stop at the first
    /// blocker; the default asks for the closest hit.
    fn any_hit(&self, ray: &Ray, range: Interval) -> bool {
        self.closest_hit(ray, range).is_some()
    }
}

/// A reference to an intersector is one, so `&dyn Intersector` (a scene's
/// BVH or brute-force group, chosen at run time) goes wherever an
/// `impl Intersector` is asked for.
impl<T: Intersector + ?Sized> Intersector for &T {
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        (**self).closest_hit(ray, range)
    }

    fn any_hit(&self, ray: &Ray, range: Interval) -> bool {
        (**self).any_hit(ray, range)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_lost_normal_faces_the_ray_head_on() {
        // The hit point rounded onto a sphere's centre: p − c = 0.
        let ray = Ray::new(Vec3::new(1e15, 0.0, 0.0), Vec3::new(-2.0, 0.0, 0.0));
        let hit = Hit::new(&ray, 5e14, Vec3::ZERO);
        assert_eq!((hit.normal, hit.front_face), (Vec3::X, true));
        // Any other normal of any length is normalised and turned to face the ray.
        let hit = Hit::new(&ray, 1.0, Vec3::new(-3.0, 0.0, 4.0));
        // Tolerance 2ε: one normalisation's rounding (0.6 is not exact in binary).
        assert!((hit.normal - Vec3::new(0.6, 0.0, -0.8)).abs().max_element() <= 2.0 * Float::EPSILON);
        assert!(!hit.front_face);
    }
}
