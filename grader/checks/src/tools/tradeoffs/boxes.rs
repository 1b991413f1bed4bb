//! The box pair: lecture 03's slab test against the six-plane test that
//! students write first, judged by exact rational arithmetic.

use std::hint::black_box;

use l03_polygons_triangles::hit_slabs;
use raylab::random::Rng;
use raylab::{Float, Interval, Ray, Vec3};

use super::row::{Pair, Row, own_precision};
use super::timing::{Effort, time_per_item};
pub use raylab_testing::exact::exact_hits;

/// The catalogued naive box test: each of the six face planes in turn, the
/// plane's t = (plane − oᵢ)/dᵢ, the point o + t·d, and whether that point lies
/// within the face's rectangle (the other two coordinates within the box,
/// closed); the nearest such t inside `range` is the hit.
///
/// Correct in exact arithmetic; in floating point the point o + t·d of a ray
/// aimed exactly at an edge or a corner rounds outside both faces that meet
/// there about half the time (a false miss), and a ray parallel to a face
/// divides by zero (t = ±∞, or 0/0 = NaN when the origin is on the plane),
/// which only the comparisons happen to reject. Returns the t of the entry
/// face (or of the exit face from inside). Book: §3.1 Boxes as three slabs
/// (the version before the slabs).
pub fn hit_box_six_planes(ray: &Ray, min: Vec3, max: Vec3, range: Interval) -> Option<Float> {
    let mut best: Option<Float> = None;
    for axis in 0..3 {
        let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
        for plane in [min[axis], max[axis]] {
            // Where the ray meets the face's plane.
            let t = (plane - ray.origin[axis]) / ray.dir[axis];
            if !range.contains(t) || best.is_some_and(|b| t >= b) {
                continue;
            }
            // Whether that point is on the face.
            let p = ray.at(t);
            if p[u] >= min[u] && p[u] <= max[u] && p[v] >= min[v] && p[v] <= max[v] {
                best = Some(t);
            }
        }
    }
    best
}

/// The textbook slab test (Kay–Kajiya, as most tutorials write it): per axis
/// t_near = (minᵢ − oᵢ)/dᵢ and t_far = (maxᵢ − oᵢ)/dᵢ, swapped when
/// t_near > t_far, the span narrowed by comparisons (so a NaN end leaves it
/// as it is), a miss as soon as it is empty; the entry t (or `range.min` from
/// inside).
///
/// Two catalogued omissions against lecture 03's `hit_slabs`: no 1 + 2γ₃
/// widening of t_far, so a ray aimed exactly at an edge, where two slabs'
/// t's meet, is lost when rounding puts t_near an ulp above t_far; and
/// division by a −0 component: (min − o)/−0 = +∞ for an origin beside the
/// min plane, and (max − o)/−0 = NaN on the max plane, so the swap (which
/// never happens against a NaN) leaves t_near = +∞ and the ray along a face
/// is lost. Book: §3.1 Boxes as three slabs.
pub fn hit_slabs_textbook(ray: &Ray, min: Vec3, max: Vec3, range: Interval) -> Option<Float> {
    let (mut t0, mut t1) = (range.min, range.max);
    for axis in 0..3 {
        let mut t_near = (min[axis] - ray.origin[axis]) / ray.dir[axis];
        let mut t_far = (max[axis] - ray.origin[axis]) / ray.dir[axis];
        if t_near > t_far {
            std::mem::swap(&mut t_near, &mut t_far);
        }
        t0 = if t_near > t0 { t_near } else { t0 };
        t1 = if t_far < t1 { t_far } else { t1 };
        if t0 > t1 {
            return None;
        }
    }
    Some(t0)
}

/// The slab test as a hit/miss with a t, NaN-checked: lecture 03's `hit_slabs`.
fn slabs(ray: &Ray, min: Vec3, max: Vec3, range: Interval) -> Option<Float> {
    hit_slabs(ray, min, max, range).map(|(t0, t1)| if t0.is_nan() || t1.is_nan() { Float::NAN } else { t0 })
}

type HitBox = fn(&Ray, Vec3, Vec3, Interval) -> Option<Float>;

/// The naive tests first, the reference method last.
pub const VARIANTS: [(&str, HitBox); 3] =
    [("six_planes", hit_box_six_planes), ("slabs_textbook", hit_slabs_textbook), ("slabs", slabs)];

/// One ray and box on the integer grid.
#[derive(Clone, Copy, Debug)]
pub struct BoxCase {
    pub o: [i64; 3],
    pub d: [i64; 3],
    pub lo: [i64; 3],
    pub hi: [i64; 3],
    /// The zero components of `d` are −0 (the same ray; IEEE division tells them apart).
    pub negative_zero: bool,
}

impl BoxCase {
    /// Coordinates are integers/16: exact in f32 and f64 alike.
    pub fn ray(&self) -> Ray {
        let mut dir = grid(self.d);
        if self.negative_zero {
            dir = Vec3::select(dir.cmpeq(Vec3::ZERO), Vec3::splat(-0.0), dir);
        }
        Ray::new(grid(self.o), dir)
    }

    pub fn bounds(&self) -> (Vec3, Vec3) {
        (grid(self.lo), grid(self.hi))
    }
}

fn grid(v: [i64; 3]) -> Vec3 {
    Vec3::new(v[0] as Float, v[1] as Float, v[2] as Float) / 16.0
}

/// A random box (one axis in eight flat) and an origin on the grid.
fn random_box(rng: &mut Rng) -> ([i64; 3], [i64; 3], [i64; 3]) {
    let mut lo = [0i64; 3];
    let mut hi = [0i64; 3];
    for i in 0..3 {
        lo[i] = rng.int(-40, 40);
        hi[i] = if rng.int(0, 7) == 0 { lo[i] } else { lo[i] + rng.int(1, 40) };
    }
    (lo, hi, std::array::from_fn(|_| rng.int(-100, 100)))
}

/// The three cases: axis-parallel rays with origins on slab planes, rays aimed
/// exactly at the boundary (a face, an edge or a corner), and generic rays.
fn cases(count: usize) -> Vec<(&'static str, Vec<BoxCase>)> {
    let mut rng = Rng::new(3);
    let mut parallel = Vec::new();
    while parallel.len() < count {
        let (lo, hi, mut o) = random_box(&mut rng);
        // One or two direction components exactly zero, the origin on a plane of such a slab.
        let zeros = rng.int(1, 2) as usize;
        let first = rng.int(0, 2) as usize;
        let mut d: [i64; 3] = std::array::from_fn(|_| rng.int(-60, 60));
        for k in 0..zeros {
            let i = (first + k) % 3;
            d[i] = 0;
            o[i] = if rng.int(0, 1) == 0 { lo[i] } else { hi[i] };
        }
        if d != [0; 3] {
            parallel.push(BoxCase { o, d, lo, hi, negative_zero: rng.int(0, 1) == 1 });
        }
    }
    let mut boundary = Vec::new();
    while boundary.len() < count {
        let (lo, hi, o) = random_box(&mut rng);
        // Each coordinate of the target at lo, at hi or between: a face, an edge or a corner.
        let mut target: [i64; 3] = std::array::from_fn(|i| match rng.int(0, 2) {
            0 => lo[i],
            1 => hi[i],
            _ => rng.int(lo[i], hi[i]),
        });
        if !(0..3).any(|i| target[i] == lo[i] || target[i] == hi[i]) {
            target[0] = hi[0];
        }
        // Scaled by an odd factor k in 3..=999, so that t = 1/k at the target is inexact and the
        // rounding of o + t·d is exercised (with k = 1 the target would be met at t = 1 exactly).
        let k = 2 * rng.int(1, 499) + 1;
        let d = [k * (target[0] - o[0]), k * (target[1] - o[1]), k * (target[2] - o[2])];
        if d != [0; 3] {
            boundary.push(BoxCase { o, d, lo, hi, negative_zero: false });
        }
    }
    let mut generic = Vec::new();
    while generic.len() < count {
        let (lo, hi, o) = random_box(&mut rng);
        let d: [i64; 3] = std::array::from_fn(|_| rng.int(-60, 60));
        if d != [0; 3] {
            generic.push(BoxCase { o, d, lo, hi, negative_zero: rng.int(0, 1) == 1 });
        }
    }
    vec![
        ("axis-parallel, origin on a plane", parallel),
        ("aimed at faces, edges, corners", boundary),
        ("generic", generic),
    ]
}

/// What a variant got wrong on a set of cases: false misses, false hits, NaN results.
pub fn judge(hit_box: HitBox, cases: &[BoxCase]) -> (usize, usize, usize) {
    let (mut false_misses, mut false_hits, mut nans) = (0, 0, 0);
    for case in cases {
        let (lo, hi) = case.bounds();
        let found = hit_box(&case.ray(), lo, hi, Interval::POSITIVE);
        nans += usize::from(found.is_some_and(Float::is_nan));
        let exact = exact_hits(case.o, case.d, case.lo, case.hi);
        false_misses += usize::from(exact && found.is_none());
        false_hits += usize::from(!exact && found.is_some());
    }
    (false_misses, false_hits, nans)
}

/// Every variant on every case: false misses, false hits, NaNs, ns per test.
pub fn measure(effort: &Effort) -> Vec<Row> {
    let mut rows = Vec::new();
    for (case, boxes) in cases(effort.samples) {
        let prepared: Vec<(Ray, Vec3, Vec3)> = boxes
            .iter()
            .map(|b| {
                let (lo, hi) = b.bounds();
                (b.ray(), lo, hi)
            })
            .collect();
        for (name, hit_box) in VARIANTS {
            let (false_misses, false_hits, nans) = judge(hit_box, &boxes);
            let time = time_per_item(effort, prepared.len(), || {
                for (ray, lo, hi) in &prepared {
                    black_box(hit_box(black_box(ray), *lo, *hi, Interval::POSITIVE));
                }
            });
            rows.push(Row {
                pair: Pair::Box,
                case: format!("{case} ({} rays)", boxes.len()),
                variant: name.to_string(),
                precision: own_precision().to_string(),
                time,
                metrics: vec![
                    ("false misses".into(), false_misses as f64),
                    ("false hits".into(), false_hits as f64),
                    ("NaN".into(), nans as f64),
                ],
                fails: false_misses > 0 || nans > 0,
                pareto: false,
            });
        }
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_reference_on_hand_cases() {
        let unit = ([0, 0, 0], [16, 16, 16]);
        let hits = |o, d| exact_hits(o, d, unit.0, unit.1);
        // Straight through the middle: x span [16/16, 32/16] = [1, 2].
        assert!(hits([-16, 8, 8], [16, 0, 0]));
        // Parallel to x at y = 16, on the max-y face plane: the slab is kept whole, a hit.
        assert!(hits([-16, 16, 8], [16, 0, 0]));
        // Parallel, just above the face plane: y = 17 > 16, a miss.
        assert!(!hits([-16, 17, 8], [16, 0, 0]));
        // Aimed at the edge x = y = 16 from (32, 32, 8): enters at t = 1 on both slabs, a hit.
        assert!(hits([32, 32, 8], [-16, -16, 0]));
        // Touching the corner (16, 16, 16) only: x holds t ∈ [0, 1], y and z t ∈ [1, 2]: t = 1, a hit.
        assert!(hits([0, 32, 32], [16, -16, -16]));
        // The box behind the origin: exit t = −1 ≤ 0, a miss.
        assert!(!hits([32, 8, 8], [16, 0, 0]));
        // Origin on the face x = 16 going out: exit t = 0 is not > 0, a miss; going in, a hit.
        assert!(!hits([16, 8, 8], [16, 0, 0]));
        assert!(hits([16, 8, 8], [-16, 0, 0]));
        // From (−2, 0) along (1, 1): x holds t ∈ [2, 3], y holds t ∈ [0, 1]; no overlap, a miss.
        assert!(!hits([-32, 0, 8], [16, 16, 0]));
    }

    #[test]
    fn a_flat_box_is_hit_across_and_along() {
        // The square x = 0, 0 ≤ y, z ≤ 16 (min.x == max.x).
        let (lo, hi) = ([0, 0, 0], [0, 16, 16]);
        assert!(exact_hits([-16, 8, 8], [16, 0, 0], lo, hi), "across at t = 1");
        assert!(exact_hits([0, -16, 8], [0, 16, 0], lo, hi), "along its own plane");
        assert!(!exact_hits([1, -16, 8], [0, 16, 0], lo, hi), "beside its plane");
    }

    #[test]
    fn six_planes_agree_on_a_simple_case_and_never_leak_a_nan() {
        // The unit cube (in grid units /16) from x = −1 along +x: the face x = 0 at t = 1.
        let case =
            BoxCase { o: [-16, 8, 8], d: [16, 0, 0], lo: [0, 0, 0], hi: [16, 16, 16], negative_zero: false };
        let (lo, hi) = case.bounds();
        assert_eq!(hit_box_six_planes(&case.ray(), lo, hi, Interval::POSITIVE), Some(1.0));
        assert_eq!(slabs(&case.ray(), lo, hi, Interval::POSITIVE), Some(1.0));
        // An origin on the face plane y = 1 moving along it: 0/0 = NaN for that face, rejected.
        let along = BoxCase { o: [-16, 16, 8], ..case };
        assert_eq!(hit_box_six_planes(&along.ray(), lo, hi, Interval::POSITIVE), Some(1.0));
    }

    #[test]
    fn textbook_slabs_lose_a_ray_along_a_face_with_a_negative_zero() {
        // Along the face plane y = 1 (the max plane) with d.y = −0: (1 − 1)/−0 = NaN for t_far,
        // (0 − 1)/−0 = +∞ for t_near; the swap never fires against the NaN, t0 becomes +∞ and
        // the x slab's t1 = 2 < +∞ empties the span: a false miss. With +0 it is found at t = 1
        // (t_near = −∞, t_far = NaN leave the span alone). Lecture 03's slabs find both.
        let plus =
            BoxCase { o: [-16, 16, 8], d: [16, 0, 0], lo: [0, 0, 0], hi: [16, 16, 16], negative_zero: false };
        let minus = BoxCase { negative_zero: true, ..plus };
        let (lo, hi) = plus.bounds();
        assert!(exact_hits(plus.o, plus.d, plus.lo, plus.hi));
        assert_eq!(hit_slabs_textbook(&plus.ray(), lo, hi, Interval::POSITIVE), Some(1.0));
        assert_eq!(hit_slabs_textbook(&minus.ray(), lo, hi, Interval::POSITIVE), None);
        assert_eq!(slabs(&minus.ray(), lo, hi, Interval::POSITIVE), Some(1.0));
        assert_eq!(judge(hit_slabs_textbook, &[plus, minus]), (1, 0, 0));
    }
}
