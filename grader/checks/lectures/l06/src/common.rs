//! What the checks of lecture 06's files share.

pub(super) use l05_shading::LightSample;
pub(super) use l06_shadows::{ShadowMode, ShadowSettings, Surface, point_seed};
pub(super) use raylab::random::Rng;
pub(super) use raylab::scene::{Attenuation, Light, LightKind, Material};
pub(super) use raylab::stats::Counter;

pub(super) use crate::judge::measured;

// The student's functions, each value taken through `judge::student` (the lecture is `judged`).
crate::rows::student_fns! { l06_shadows:
    fn offset_origin(p: Vec3, n: Vec3, dir: Vec3, from: Vec3) -> Vec3 as OffsetFn;
    fn offset_origin_fixed_t(p: Vec3, n: Vec3, dir: Vec3, from: Vec3) -> Vec3;
    fn offset_origin_fixed_normal(p: Vec3, n: Vec3, dir: Vec3, from: Vec3) -> Vec3;
    fn occluded(scene: &dyn Intersector, from: Vec3, sample: &LightSample) -> bool as OccludedFn;
    fn transmittance(scene: &dyn Intersector, materials: &[Material], from: Vec3, sample: &LightSample) -> Color as TransmittanceFn;
    fn visibility(
        scene: &dyn Intersector,
        materials: &[Material],
        surface: &Surface,
        sample: &LightSample,
        mode: ShadowMode,
    ) -> Color as VisibilityFn;
    fn shade_with_shadows(
        scene: &dyn Intersector,
        materials: &[Material],
        surface: &Surface,
        lights: &[Light],
        ambient: Color,
        settings: ShadowSettings,
    ) -> Color as ShadeFn;
    fn shade_area_light(
        scene: &dyn Intersector,
        materials: &[Material],
        surface: &Surface,
        light: &Light,
        settings: ShadowSettings,
    ) -> Color as AreaFn;
    fn stratified(n: u32, rng: &mut Rng) -> Vec<Vec2> as StratifiedFn
        => crate::judge::drawn(rng, |rng| l06_shadows::stratified(n, rng));
}
pub(super) use raylab::{BLACK, Color, Float, Hit, Intersector, Interval, Ray, Vec2, Vec3, WHITE, radians};
pub(super) use std::sync::atomic::{AtomicUsize, Ordering};

pub(super) use crate::check::{CheckResult, Failure, close3, ensure, lazy, num, v, vec3, wide, wide3};
pub(super) use std::fmt::Display;

pub(super) const EPS: Float = Float::EPSILON;

pub(super) use raylab_testing::ulp;

// ------------------------------------------------------- the check's scene

/// The shapes of the checks' scenes.
#[derive(Clone, Copy, Debug)]
pub(super) enum Shape {
    Sphere {
        center: Vec3,
        radius: Float,
    },
    /// The plane y = height, normal +y.
    Floor {
        height: Float,
    },
    /// The part x < 0 of the plane y = height: a blocker with a straight edge.
    HalfFloor {
        height: Float,
    },
}

/// An intersector over shapes with their material indices, computed in `Float` by
/// the textbook formulas (the robust quadratic for spheres). It counts its queries.
pub(super) struct Scene {
    pub shapes: Vec<(Shape, usize)>,
    pub closest_calls: AtomicUsize,
    pub any_calls: AtomicUsize,
}

impl Scene {
    pub fn new(shapes: &[(Shape, usize)]) -> Self {
        Self { shapes: shapes.to_vec(), closest_calls: AtomicUsize::new(0), any_calls: AtomicUsize::new(0) }
    }

    fn hit_shape(shape: Shape, ray: &Ray, range: Interval) -> Option<Hit> {
        match shape {
            Shape::Sphere { center, radius } => {
                let a = ray.dir.length_squared();
                let f = ray.origin - center;
                let b = f.dot(ray.dir);
                let off = f - (b / a) * ray.dir;
                let disc = a * (radius * radius - off.length_squared());
                if disc < 0.0 {
                    return None;
                }
                let q = -b - disc.sqrt().copysign(b);
                let (t1, t2) = (q / a, (f.length_squared() - radius * radius) / q);
                let (near, far) = if t1 <= t2 { (t1, t2) } else { (t2, t1) };
                let t = if range.contains(near) {
                    near
                } else if range.contains(far) {
                    far
                } else {
                    return None;
                };
                Some(Hit::new(ray, t, ray.at(t) - center))
            }
            Shape::Floor { height } | Shape::HalfFloor { height } => {
                if ray.dir.y == 0.0 {
                    return None;
                }
                let t = (height - ray.origin.y) / ray.dir.y;
                let inside = !matches!(shape, Shape::HalfFloor { .. }) || ray.at(t).x < 0.0;
                (range.contains(t) && inside).then(|| Hit::new(ray, t, Vec3::Y))
            }
        }
    }
}

impl Intersector for Scene {
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        self.closest_calls.fetch_add(1, Ordering::Relaxed);
        let mut best: Option<Hit> = None;
        for (index, &(shape, material)) in self.shapes.iter().enumerate() {
            let range = best.map_or(range, |h| range.with_max(h.t));
            if let Some(hit) = Self::hit_shape(shape, ray, range) {
                best = Some(Hit { object: index, material, ..hit });
            }
        }
        best
    }

    fn any_hit(&self, ray: &Ray, range: Interval) -> bool {
        self.any_calls.fetch_add(1, Ordering::Relaxed);
        self.shapes.iter().any(|&(shape, _)| Self::hit_shape(shape, ray, range).is_some())
    }
}

pub(super) fn sphere(x: Float, y: Float, z: Float, radius: Float, material: usize) -> (Shape, usize) {
    (Shape::Sphere { center: v(x, y, z), radius }, material)
}

pub(super) fn floor(height: Float, material: usize) -> (Shape, usize) {
    (Shape::Floor { height }, material)
}

/// A white diffuse material letting `transparent` through.
pub(super) fn see_through(transparent: Color) -> Material {
    Material { transparent, ..Material::default() }
}

/// A point light at `position` seen from `from` (white, undimmed).
pub(super) fn toward_point(from: Vec3, position: Vec3) -> LightSample {
    let to = position - from;
    LightSample { direction: to.normalize(), distance: to.length(), intensity: WHITE }
}

/// A directional light seen along the unit `l`.
pub(super) fn toward(l: Vec3) -> LightSample {
    LightSample { direction: l, distance: Float::INFINITY, intensity: WHITE }
}
