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
#[derive(Clone, Copy, Debug, PartialEq)]
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
    /// A zero or non-finite normal is a bug in the caller (debug builds
    /// stop on it); release builds substitute +z rather than spread a NaN.
    pub fn new(ray: &Ray, t: Float, outward_normal: Vec3) -> Self {
        debug_assert!(
            outward_normal.is_finite() && outward_normal != Vec3::ZERO,
            "Hit::new needs a non-zero finite normal, found {outward_normal}"
        );
        Self::facing(ray, t, outward_normal.try_normalize().unwrap_or(Vec3::Z))
    }

    /// [`Hit::new`] for an outward normal `n` already normalised (its
    /// `try_normalize` done by the caller, once, and reused): the same record.
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
