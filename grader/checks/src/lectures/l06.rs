//! Lecture 06, shadows: shadow rays and where they start, transparent
//! blockers, shading with shadows, and soft shadows from area lights.
//!
//! The checks intersect their scenes with a small intersector of their own
//! (spheres, planes and a half plane, below), so that a shadow check is not
//! blocked by lectures 02–04; the offset checks decide "self-hit or not" in
//! f64, on which side of the surface the new origin lies.

use crate::check::Meta;

declare_checks! {
    "l06";
    Meta::unit(
        "offset_origin",
        "along ±n to the side dir leaves to, by a few ulp of p and of the ray's origin, never zero",
    ) => offset_cases(offset_origin),
    Meta::extreme(
        "offset_origin",
        "large-coordinates",
        "spheres at 10⁴ and 10⁵ and a floor seen from 860 away: no shadow ray starts inside, moves ≤ 97 ulp",
    ) => large_coordinates(offset_origin),
    Meta::unit("offset_origin_fixed_t", "the naive method: p + 10⁻⁴·dir")
        => fixed_t_cases(offset_origin_fixed_t),
    Meta::unit("offset_origin_fixed_normal", "the naive method: p + 10⁻⁴·n, whatever dir")
        => fixed_normal_cases(offset_origin_fixed_normal),
    Meta::unit(
        "occluded",
        "a blocker between, beside, beyond the light and behind the point; one any-hit shadow ray",
    ) => occluded_cases(occluded),
    Meta::unit(
        "transmittance",
        "Π k_t over the surfaces crossed: a sphere ¼, a plane ½, by channel, opaque stops, the light nearer",
    )
    .needs(&["06/offset_origin"]) => transmittance_cases(transmittance),
    Meta::unit("visibility", "opaque or filtered by mode, from just off a floor seen from far away")
        .needs(&["06/offset_origin", "06/occluded", "06/transmittance"]) => visibility_cases(visibility),
    Meta::unit(
        "shade_with_shadows",
        "under and beside a ball, a transparent ball, lights without shadows or behind: values and ray counts",
    )
    .needs(&["05/illuminate", "05/shade_light", "06/visibility", "06/shade_area_light"])
        => shade_cases(shade_with_shadows),
    Meta::unit("stratified", "n samples, one per cell of the √n × √n grid or the n strips, row by row, in [0, 1)²")
        => stratified_cases(stratified),
    Meta::unit(
        "shade_area_light",
        "the average over n samples of V·(N·L) against the same points in f64: umbra, penumbra, half below",
    )
    .needs(&["05/sample_light", "05/shade_light", "06/visibility", "06/stratified"])
        => area_cases(shade_area_light),
}

#[cfg(feature = "l06")]
// `Failure` is large (its optional images); see check.rs.
#[allow(clippy::result_large_err)]
mod code {
    pub(super) use l05_shading::LightSample;
    pub(super) use l06_shadows::{
        ShadowMode, ShadowSettings, Surface, occluded, offset_origin, offset_origin_fixed_normal,
        offset_origin_fixed_t, point_seed, shade_area_light, shade_with_shadows, stratified, transmittance,
        visibility,
    };
    use raylab::random::Rng;
    use raylab::scene::{Attenuation, Light, LightKind, Material};
    use raylab::stats::{Counter, measure};
    use raylab::{BLACK, Color, Float, Hit, Intersector, Interval, Ray, Vec2, Vec3, WHITE, radians};
    use std::sync::atomic::{AtomicUsize, Ordering};

    use crate::check::{CheckResult, Failure, close3, ensure, num, vec3, wide, wide3};

    pub(super) type OffsetFn = fn(Vec3, Vec3, Vec3, Vec3) -> Vec3;
    pub(super) type OccludedFn = fn(&dyn Intersector, Vec3, &LightSample) -> bool;
    pub(super) type TransmittanceFn = fn(&dyn Intersector, &[Material], Vec3, &LightSample) -> Color;
    pub(super) type VisibilityFn =
        fn(&dyn Intersector, &[Material], &Surface, &LightSample, ShadowMode) -> Color;
    pub(super) type ShadeFn =
        fn(&dyn Intersector, &[Material], &Surface, &[Light], Color, ShadowSettings) -> Color;
    pub(super) type StratifiedFn = fn(u32, &mut Rng) -> Vec<Vec2>;
    pub(super) type AreaFn = fn(&dyn Intersector, &[Material], &Surface, &Light, ShadowSettings) -> Color;

    const EPS: Float = Float::EPSILON;

    fn v(x: Float, y: Float, z: Float) -> Vec3 {
        Vec3::new(x, y, z)
    }

    /// The gap from |x| to the next float up.
    fn ulp(x: Float) -> Float {
        let x = x.abs();
        x.next_up() - x
    }

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
            Self {
                shapes: shapes.to_vec(),
                closest_calls: AtomicUsize::new(0),
                any_calls: AtomicUsize::new(0),
            }
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

    fn sphere(x: Float, y: Float, z: Float, radius: Float, material: usize) -> (Shape, usize) {
        (Shape::Sphere { center: v(x, y, z), radius }, material)
    }

    fn floor(height: Float, material: usize) -> (Shape, usize) {
        (Shape::Floor { height }, material)
    }

    /// A white diffuse material letting `transparent` through.
    fn see_through(transparent: Color) -> Material {
        Material { transparent, ..Material::default() }
    }

    /// A point light at `position` seen from `from` (white, undimmed).
    fn toward_point(from: Vec3, position: Vec3) -> LightSample {
        let to = position - from;
        LightSample { direction: to.normalize(), distance: to.length(), intensity: WHITE }
    }

    /// A directional light seen along the unit `l`.
    fn toward(l: Vec3) -> LightSample {
        LightSample { direction: l, distance: Float::INFINITY, intensity: WHITE }
    }

    // ----------------------------------------------------------------- offsets

    /// Checks one offset: moved along ±n only, to `side` (+1 or −1) of the surface, by
    /// 4 to 97 ulp of the largest coordinate of p and from (the lecture's bound:
    /// 8ε·(|p|₁ + |from|₁) ≤ 48ε·M ≤ 96 ulp(M), plus half an ulp storing it; and at
    /// least 8ε·M ≥ 8 ulp(M) of which a unit n's largest component carries 1/√3).
    fn check_offset(
        case: &str,
        p: Vec3,
        n: Vec3,
        from: Vec3,
        moved: Vec3,
        side: Float,
    ) -> Result<(), Failure> {
        let step = moved - p;
        let along = step.dot(n);
        let sideways = (step - along * n).abs().max_element();
        let m = p.abs().max_element().max(from.abs().max_element());
        let in_ulp = step.abs().max_element() / ulp(m);
        let expected = format!(
            "p moved along {}·n by 4 to 97 ulp of {}, at most 2 ulp sideways",
            if side > 0.0 { "+" } else { "−" },
            num(m)
        );
        let got = format!("{} ({} ulp, {} along n)", vec3(moved), num(in_ulp), num(along));
        ensure(
            moved != p,
            case,
            &expected,
            &got,
            "the point did not move: the step is below half an ulp of p — scale it to the coordinates, \
             8ε·(|p|₁ + |from|₁); a fixed 10⁻⁴ rounds away far from the origin",
        )?;
        ensure(
            sideways <= 2.0 * ulp(m) + Float::MIN_POSITIVE,
            case,
            &expected,
            &got,
            "move along the normal n, not along dir: the error of p that matters is across the surface",
        )?;
        ensure(
            along * side > 0.0,
            case,
            &expected,
            &got,
            "move to the side the new ray leaves to: p + d·n when dir·n ≥ 0, p − d·n when dir·n < 0, whichever way n faces",
        )?;
        ensure(
            in_ulp <= 97.0,
            case,
            &expected,
            &got,
            "at most a few dozen ulp: scale the offset to the coordinates, 8ε·(|p|₁ + |from|₁), not a fixed epsilon",
        )?;
        ensure(
            in_ulp >= 4.0 || (m == 0.0 && along * side > 0.0),
            case,
            &expected,
            &got,
            "scale by |p|₁ + |from|₁: where from + t·dir cancels, p carries the rounding error of from",
        )
    }

    pub(super) fn offset_cases(offset: OffsetFn) -> CheckResult {
        let p = v(2.0, 0.0, 0.0);
        let cases = [
            (
                "p = (2, 0, 0), n = +x, dir = (1, 1, 0), from the origin",
                Vec3::X,
                v(1.0, 1.0, 0.0),
                Vec3::ZERO,
                1.0,
            ),
            (
                "p = (2, 0, 0), n = +x, dir = (−1, 1, 0) (through the surface)",
                Vec3::X,
                v(-1.0, 1.0, 0.0),
                Vec3::ZERO,
                -1.0,
            ),
            (
                "p = (2, 0, 0), n = −x, dir = (1, 1, 0) (the normal faces away)",
                -Vec3::X,
                v(1.0, 1.0, 0.0),
                Vec3::ZERO,
                -1.0,
            ),
            (
                "p = (2, 0, 0), n = +x, dir = +y (tangent: the normal's side)",
                Vec3::X,
                Vec3::Y,
                Vec3::ZERO,
                1.0,
            ),
            (
                "p = (2, 0, 0), n = +x, dir = +x, found from (0, −2, 0)",
                Vec3::X,
                Vec3::X,
                v(0.0, -2.0, 0.0),
                1.0,
            ),
        ];
        for (case, n, dir, from, side) in cases {
            check_offset(case, p, n, from, offset(p, n, dir, from), side)?;
        }
        // The world origin seen from the eye (0, 5, 7): p = 0, so only |from| can scale the
        // offset above the error p carries (a few ulp of 7).
        let case = "p = (0, 0, 0), n = +y, dir = +y, found from the eye (0, 5, 7)";
        let from = v(0.0, 5.0, 7.0);
        check_offset(case, Vec3::ZERO, Vec3::Y, from, offset(Vec3::ZERO, Vec3::Y, Vec3::Y, from), 1.0)?;
        // The world origin from the world origin: nothing to scale by, yet p must move.
        let case = "p = (0, 0, 0), n = +y, dir = +y, found from (0, 0, 0)";
        let moved = offset(Vec3::ZERO, Vec3::Y, Vec3::Y, Vec3::ZERO);
        ensure(
            moved.y > 0.0 && moved.y <= 1e-30 && moved.x == 0.0 && moved.z == 0.0,
            case,
            "(0, y, 0) with 0 < y ≤ 1e-30",
            vec3(moved),
            "add a floor (the smallest normal float) so the point moves even when p = from = 0",
        )?;
        // Random points, origins and normals at scales 10⁻³⁰ to 10²⁰: within the bound.
        let mut rng = Rng::new(0x0ff5e7);
        let mut largest: Float = 0.0;
        for scale in [1e-30, 1e-4, 1.0, 7.0, 1e4, 1e5, 1e20] {
            for from_scale in [0.0, 1.0, 100.0] {
                for _ in 0..100 {
                    let p = rng.in_ball(scale);
                    let from = rng.in_ball(scale * from_scale);
                    let (n, dir) = (rng.unit_vector(), rng.unit_vector());
                    let side = if dir.dot(n) < 0.0 { -1.0 } else { 1.0 };
                    let case =
                        format!("p = {}, n = {}, dir = {}, from {}", vec3(p), vec3(n), vec3(dir), vec3(from));
                    let moved = offset(p, n, dir, from);
                    check_offset(&case, p, n, from, moved, side)?;
                    let m = p.abs().max_element().max(from.abs().max_element());
                    largest = largest.max((moved - p).abs().max_element() / ulp(m));
                }
            }
        }
        Ok(format!("7 cases and 2100 random ones, at most {largest:.0} ulp"))
    }

    /// Shadow rays from hits on spheres of radius 1 at (10⁴, 10⁴, 10⁴) and 10⁵ and on a
    /// floor through the world origin seen from (0, 5, 7) and (0, 500, 700), toward
    /// lights on the lit side. Hit points are computed as the tracer does, p = o + t·d in
    /// `Float`, with t the exact root rounded once (f64); whether the offset origin is
    /// still inside (a self-hit) is decided in f64.
    pub(super) fn large_coordinates(offset: OffsetFn) -> CheckResult {
        let mut rng = Rng::new(0xac_4e);
        let mut largest: Float = 0.0;
        for d in [1e4, 1e5] {
            let center = Vec3::splat(d);
            let c = wide3(center);
            for _ in 0..2000 {
                let origin = center + rng.unit_vector() * rng.range(2.0, 10.0);
                let aim = center + rng.in_ball(0.95);
                let dir = (aim - origin).normalize();
                // The near root in f64: t = f·d̂ term minus the half chord.
                let (o, dd) = (wide3(origin), wide3(dir));
                let f = [o[0] - c[0], o[1] - c[1], o[2] - c[2]];
                let a = dd.iter().map(|x| x * x).sum::<f64>();
                let b = (0..3).map(|k| f[k] * dd[k]).sum::<f64>() / a;
                let off2 = (0..3).map(|k| (f[k] - b * dd[k]).powi(2)).sum::<f64>();
                let t = (-b - ((1.0 - off2) / a).sqrt()) as Float;
                let p = origin + t * dir;
                let n = (p - center).normalize();
                let l = rng.unit_vector();
                let l = if l.dot(n) < 0.0 { -l } else { l };
                let moved = offset(p, n, l, origin);
                let case = format!(
                    "unit sphere at ({d:e}, {d:e}, {d:e}), hit p = {} from {}, light along {}",
                    vec3(p),
                    vec3(origin),
                    vec3(l)
                );
                let m = wide3(moved);
                let outside = (0..3).map(|k| (m[k] - c[k]).powi(2)).sum::<f64>() > 1.0;
                ensure(
                    outside,
                    &case,
                    "a shadow ray starting outside the sphere",
                    format!("{} is inside: the sphere shadows itself", vec3(moved)),
                    "the offset must exceed the rounding error of p: 8ε·(|p|₁ + |from|₁) along n; a fixed 10⁻⁴ \
                     rounds away at 10⁴ (one ulp is 10⁻³ in f32)",
                )?;
                check_offset(&case, p, n, origin, moved, 1.0)?;
                largest = largest.max((moved - p).abs().max_element() / ulp(p.abs().max_element()));
            }
        }
        for eye in [v(0.0, 5.0, 7.0), v(0.0, 500.0, 700.0)] {
            for _ in 0..2000 {
                let aim = v(rng.range(-0.1, 0.1), 0.0, rng.range(-0.1, 0.1));
                let dir = (aim - eye).normalize();
                let t = (-wide(eye.y) / wide(dir.y)) as Float;
                let p = eye + t * dir;
                let l = rng.unit_vector();
                let l = if l.y < 0.0 { -l } else { l };
                let moved = offset(p, Vec3::Y, l, eye);
                let case = format!(
                    "floor y = 0 seen from {}, hit p = {}, light along {}",
                    vec3(eye),
                    vec3(p),
                    vec3(l)
                );
                ensure(
                    moved.y > 0.0,
                    &case,
                    "a shadow ray starting above the floor",
                    format!("{} is below it: the floor shadows itself", vec3(moved)),
                    "scale by |p|₁ + |from|₁: here p ≈ 0 but carries the rounding error of the eye's coordinates",
                )?;
                check_offset(&case, p, Vec3::Y, eye, moved, 1.0)?;
            }
        }
        Ok(format!("8000 shadow rays, none starting inside; at most {largest:.0} ulp of p on the spheres"))
    }

    pub(super) fn fixed_t_cases(offset: OffsetFn) -> CheckResult {
        // p + 10⁻⁴·dir, the normal and the ray's origin unused. One product and a sum: half
        // an ulp of each coordinate (ulp(3) = 2.4·10⁻⁷ in f32).
        let p = v(1.0, 2.0, 3.0);
        for (case, n, dir) in [
            ("p = (1, 2, 3), n = +y, dir = (0, 0, 1)", Vec3::Y, Vec3::Z),
            ("p = (1, 2, 3), n = +y, dir = (0.6, 0, 0.8)", Vec3::Y, v(0.6, 0.0, 0.8)),
            ("p = (1, 2, 3), n = +y, dir = (0, −1, 0) (through the surface)", Vec3::Y, -Vec3::Y),
        ] {
            let moved = offset(p, n, dir, v(9.0, 9.0, 9.0));
            let expected = p + 1e-4 * dir;
            let cause = if (moved - (p + 1e-4 * n)).abs().max_element() <= ulp(3.0) {
                "the fixed-t method steps 10⁻⁴ along dir (the ray's own direction), not along n"
            } else {
                "p + NAIVE_EPSILON·dir: the ray from p with range.min = 10⁻⁴"
            };
            close3(case, moved, expected, ulp(3.0), cause)?;
        }
        Ok("3 cases".into())
    }

    pub(super) fn fixed_normal_cases(offset: OffsetFn) -> CheckResult {
        // p + 10⁻⁴·n, whatever dir (the naive method's flaw, kept on purpose).
        let p = v(1.0, 2.0, 3.0);
        for (case, n, dir) in [
            ("p = (1, 2, 3), n = +y, dir = (0.6, 0.8, 0)", Vec3::Y, v(0.6, 0.8, 0.0)),
            ("p = (1, 2, 3), n = +y, dir = (0, −1, 0) (through the surface)", Vec3::Y, -Vec3::Y),
            ("p = (1, 2, 3), n = (0.6, 0, 0.8), dir = +x", v(0.6, 0.0, 0.8), Vec3::X),
        ] {
            let moved = offset(p, n, dir, v(9.0, 9.0, 9.0));
            let expected = p + 1e-4 * n;
            let cause = if (moved - (p - 1e-4 * n)).abs().max_element() <= ulp(3.0) {
                "the fixed-normal method always steps along +n, whatever dir (its flaw, kept to compare)"
            } else if (moved - (p + 1e-4 * dir)).abs().max_element() <= ulp(3.0) {
                "step along the normal n, not along dir"
            } else {
                "p + NAIVE_EPSILON·n"
            };
            close3(case, moved, expected, ulp(3.0), cause)?;
        }
        Ok("3 cases".into())
    }

    // --------------------------------------------------------------- occlusion

    pub(super) fn occluded_cases(occluded: OccludedFn) -> CheckResult {
        let light = toward_point(Vec3::ZERO, v(0.0, 5.0, 0.0));
        let cases = [
            (
                "unit sphere at (0, 2, 0) between the origin and a light at (0, 5, 0)",
                v(0.0, 2.0, 0.0),
                true,
                "a blocker between the point and the light shadows it: any hit with 0 < s < distance",
            ),
            (
                "unit sphere at (1.5, 2, 0), beside the ray to a light at (0, 5, 0)",
                v(1.5, 2.0, 0.0),
                false,
                "the shadow ray runs from the point along L = sample.direction",
            ),
            (
                "unit sphere at (0, 8, 0), beyond a light at (0, 5, 0)",
                v(0.0, 8.0, 0.0),
                false,
                "blockers beyond the light do not count: the range ends at sample.distance",
            ),
            (
                "unit sphere at (0, −3, 0), behind the point, light at (0, 5, 0)",
                v(0.0, -3.0, 0.0),
                false,
                "blockers behind the point do not count: the range starts at 0 (from is already offset)",
            ),
            (
                "unit sphere at (0, 6, 0) whose surface touches the light at (0, 5, 0)",
                v(0.0, 6.0, 0.0),
                false,
                "the range ends short of the light: distance·(1 − 4ε) (LIGHT_MARGIN)",
            ),
        ];
        for (case, center, expected, cause) in cases {
            let scene = Scene::new(&[(Shape::Sphere { center, radius: 1.0 }, 0)]);
            let got = occluded(&scene, Vec3::ZERO, &light);
            ensure(got == expected, case, expected, got, cause)?;
        }
        // A directional light (distance ∞): blocked by a sphere 1000 away on the ray.
        let case = "unit sphere at (0, 1000, 0), directional light straight up";
        let scene = Scene::new(&[sphere(0.0, 1000.0, 0.0, 1.0, 0)]);
        let got = occluded(&scene, Vec3::ZERO, &toward(Vec3::Y));
        ensure(
            got,
            case,
            true,
            got,
            "a directional light (distance ∞) is blocked by anything along the ray",
        )?;
        // One any-hit query, no closest hit, one shadow ray counted.
        let case = "unit sphere at (0, 2, 0), directional light straight up: the queries asked";
        let scene = Scene::new(&[sphere(0.0, 2.0, 0.0, 1.0, 0)]);
        let (_, stats) = measure(|| occluded(&scene, Vec3::ZERO, &toward(Vec3::Y)));
        let (any, closest) =
            (scene.any_calls.load(Ordering::Relaxed), scene.closest_calls.load(Ordering::Relaxed));
        ensure(
            any == 1 && closest == 0,
            case,
            "1 any_hit, 0 closest_hit",
            format!("{any} any_hit, {closest} closest_hit"),
            "a shadow ray needs any hit, not the closest: ask scene.any_hit once (it may stop at the first blocker)",
        )?;
        let rays = stats.get(Counter::ShadowRays);
        ensure(
            rays == 1,
            case,
            "1 shadow ray counted",
            rays,
            "count one Counter::ShadowRays per shadow ray (the statistics show what the scene required)",
        )?;
        Ok("8 cases".into())
    }

    /// Light from (0, 10, 0) to the origin through `shapes`: the filter and the segments.
    fn through(
        transmittance: TransmittanceFn,
        shapes: &[(Shape, usize)],
        materials: &[Material],
    ) -> (Color, u64) {
        let scene = Scene::new(shapes);
        let sample = toward_point(Vec3::ZERO, v(0.0, 10.0, 0.0));
        let (t, stats) = measure(|| transmittance(&scene, materials, Vec3::ZERO, &sample));
        (t, stats.get(Counter::ShadowRays))
    }

    /// A case of the walk: what, the shapes, their materials, the filter and the segments.
    type TransmittanceCase = (&'static str, Vec<(Shape, usize)>, Vec<Material>, Color, u64);

    pub(super) fn transmittance_cases(transmittance: TransmittanceFn) -> CheckResult {
        let half = see_through(Color::splat(0.5));
        let show = |(c, n): (Color, u64)| format!("{} after {n} segments", vec3(c));
        // Each surface crossing filters by k_t: products of powers of two, exact.
        let cases: [TransmittanceCase; 6] = [
            (
                "a sphere of k_t = ½ at (0, 4, 0), light at (0, 10, 0)",
                vec![sphere(0.0, 4.0, 0.0, 1.0, 0)],
                vec![half.clone()],
                Color::splat(0.25),
                3,
            ),
            (
                "a plane y = 4 of k_t = ½, light at (0, 10, 0)",
                vec![floor(4.0, 0)],
                vec![half.clone()],
                Color::splat(0.5),
                2,
            ),
            (
                "a sphere of k_t = (1, ½, ¼) at (0, 3, 0) and a plane y = 6 of k_t = (½, 1, 1)",
                vec![sphere(0.0, 3.0, 0.0, 1.0, 0), floor(6.0, 1)],
                vec![see_through(v(1.0, 0.5, 0.25)), see_through(v(0.5, 1.0, 1.0))],
                v(0.5, 0.25, 0.0625),
                4,
            ),
            ("nothing in the way", vec![], vec![half.clone()], WHITE, 1),
            (
                "an opaque sphere at (0, 3, 0), a transparent plane y = 6 beyond",
                vec![sphere(0.0, 3.0, 0.0, 1.0, 0), floor(6.0, 1)],
                vec![Material::default(), half.clone()],
                BLACK,
                1,
            ),
            (
                "a plane y = 4 of k_t = ½, an opaque sphere at (0, 12, 0) beyond the light at 10",
                vec![floor(4.0, 0), sphere(0.0, 12.0, 0.0, 1.0, 1)],
                vec![half.clone(), Material::default()],
                Color::splat(0.5),
                2,
            ),
        ];
        for (case, shapes, materials, expected, segments) in cases {
            let got = through(transmittance, &shapes, &materials);
            let cause = if expected == BLACK && got.0 == BLACK && got.1 > segments {
                "an opaque blocker (k_t = 0) ends the walk: stop at black, no more segments"
            } else if got.0 == 2.0 * expected && expected != BLACK {
                "each surface crossing filters by k_t: a sphere is crossed twice, in and out"
            } else if got.0 == BLACK && got.1 >= 60 {
                "start the next segment past the blocker: offset_origin(hit.point, hit.normal, dir, origin)"
            } else if got.0 == BLACK && expected != BLACK && shapes.len() == 2 {
                "after each blocker the light is nearer by the t travelled: shrink the range (remaining −= hit.t)"
            } else if got.0 == expected {
                "count one Counter::ShadowRays per segment: to each blocker, and on to the light"
            } else if expected == BLACK {
                "an opaque blocker (k_t = 0) blocks: stop the walk at black"
            } else {
                "T = Π k_t over the surfaces crossed between the point and the light, by channel"
            };
            ensure(got == (expected, segments), case, show((expected, segments)), show(got), cause)?;
        }
        // A material index with no material is opaque.
        let case = "a sphere at (0, 3, 0) whose material index 7 has no material";
        let got = through(transmittance, &[sphere(0.0, 3.0, 0.0, 1.0, 7)], std::slice::from_ref(&half));
        ensure(
            got.0 == BLACK,
            case,
            "(0, 0, 0)",
            show(got),
            "a material index with no material counts as opaque",
        )?;
        // Twenty fully transparent spheres along the ray, the light beyond at 100: white after
        // 2·20 + 1 segments, and the walk ends.
        let case = "20 spheres of k_t = 1 along the ray, light at (0, 100, 0)";
        let shapes: Vec<(Shape, usize)> =
            (0..20).map(|i| sphere(0.0, 2.0 + 2.5 * i as Float, 0.0, 1.0, 0)).collect();
        let scene = Scene::new(&shapes);
        let sample = toward_point(Vec3::ZERO, v(0.0, 100.0, 0.0));
        let (t, stats) = measure(|| transmittance(&scene, &[see_through(WHITE)], Vec3::ZERO, &sample));
        let got = (t, stats.get(Counter::ShadowRays));
        ensure(
            got == (WHITE, 41),
            case,
            show((WHITE, 41)),
            show(got),
            "walk through every surface up to the light",
        )?;
        Ok("8 cases".into())
    }

    // ----------------------------------------------------------------- shading

    /// Materials: 0 the grey floor (k_d = ½, opaque), 1 an opaque ball, 2 a ball of k_t = ½.
    fn materials() -> Vec<Material> {
        let grey = Material { diffuse: Color::splat(0.5), ..Material::default() };
        vec![grey.clone(), grey, see_through(Color::splat(0.5))]
    }

    /// The floor point (x, 0, z) seen from 5 away, up and in front: the hit and its eye.
    fn floor_hit(x: Float, z: Float) -> (Hit, Vec3) {
        let ray = Ray::new(v(x, 3.0, z + 4.0), v(0.0, -3.0, -4.0) / 5.0);
        (Hit::new(&ray, 5.0, Vec3::Y), ray.origin)
    }

    fn surface<'a>(material: &'a Material, hit: Hit, eye: Vec3) -> Surface<'a> {
        Surface { material, diffuse: material.diffuse, hit, v: (eye - hit.point).normalize(), origin: eye }
    }

    pub(super) fn visibility_cases(visibility: VisibilityFn) -> CheckResult {
        let materials = materials();
        // The floor y = 0 seen from (0, 500, 700), points within 0.1 of the world origin, a light
        // straight above: nothing blocks it. Each point carries an error of a few ulp of the eye
        // (o + t·d cancels): only a shadow ray offset by the eye's scale leaves the floor.
        let scene = Scene::new(&[floor(0.0, 0)]);
        let eye = v(0.0, 500.0, 700.0);
        let mut rng = Rng::new(0xe_7e);
        for _ in 0..500 {
            let aim = v(rng.range(-0.1, 0.1), 0.0, rng.range(-0.1, 0.1));
            let ray = Ray::new(eye, (aim - eye).normalize());
            let Some(hit) = scene.closest_hit(&ray, Interval::POSITIVE) else { continue };
            let s = surface(&materials[0], hit, eye);
            let case = format!(
                "floor y = 0 seen from (0, 500, 700) at {}, light straight up, nothing above",
                vec3(hit.point)
            );
            for mode in [ShadowMode::Opaque, ShadowMode::Transmissive] {
                let got = visibility(&scene, &materials, &s, &toward(Vec3::Y), mode);
                ensure(
                    got == WHITE,
                    &case,
                    "(1, 1, 1)",
                    vec3(got),
                    "start the shadow ray just off the surface: offset_origin(p, N, L, surface.origin), the eye as from",
                )?;
            }
        }
        // A ball above the floor's origin: opaque blocks; transparent (k_t = ½) blocks in Opaque
        // mode and passes ½·½ in Transmissive mode.
        let (hit, eye) = floor_hit(0.0, 0.0);
        let s = surface(&materials[0], hit, eye);
        for (ball, mode, expected, cause) in [
            (1, ShadowMode::Opaque, BLACK, "a blocker between the point and the light: black"),
            (1, ShadowMode::Transmissive, BLACK, "an opaque blocker passes nothing, in either mode"),
            (2, ShadowMode::Opaque, BLACK, "in Opaque mode every blocker blocks: occluded → black"),
            (
                2,
                ShadowMode::Transmissive,
                Color::splat(0.25),
                "in Transmissive mode the visibility is transmittance(…)",
            ),
        ] {
            let scene = Scene::new(&[floor(0.0, 0), sphere(0.0, 2.0, 0.0, 1.0, ball)]);
            let case = format!(
                "floor point (0, 0, 0) under a {} ball at (0, 2, 0), light straight up, {mode:?}",
                if ball == 1 { "opaque" } else { "k_t = ½" }
            );
            let got = visibility(&scene, &materials, &s, &toward(Vec3::Y), mode);
            ensure(got == expected, case, vec3(expected), vec3(got), cause)?;
        }
        Ok("1004 cases".into())
    }

    fn directional(toward_light: Vec3, shadows: bool) -> Light {
        Light { color: WHITE, shadows, kind: LightKind::Directional { direction: -toward_light } }
    }

    const AMBIENT: Color = Color::splat(0.1);

    pub(super) fn shade_cases(shade: ShadeFn) -> CheckResult {
        let materials = materials();
        let show = |(c, n): (Color, u64)| format!("{} with {n} shadow rays", vec3(c));
        let run = |shapes: &[(Shape, usize)], lights: &[Light], x: Float, mode: ShadowMode| {
            let (hit, eye) = floor_hit(x, 0.0);
            let s = surface(&materials[0], hit, eye);
            let scene = Scene::new(shapes);
            let settings = ShadowSettings { mode, area_samples: 16 };
            let (c, stats) = measure(|| shade(&scene, &materials, &s, lights, AMBIENT, settings));
            (c, stats.get(Counter::ShadowRays))
        };
        let floor_and = |ball: usize| [floor(0.0, 0), sphere(0.0, 2.0, 0.0, 1.0, ball)];
        let up = [directional(Vec3::Y, true)];
        // k_a ⊙ I_a = ½·0.1 = 0.05 (exact) under the ball; beside it + k_d·(N·L)·I = 0.55 (2ε).
        let shadowed = Color::splat(0.05);
        let lit = Color::splat(0.55);
        let cases = [
            (
                "floor (0, 0, 0) under an opaque ball, light straight up, Opaque",
                floor_and(1).to_vec(),
                up.to_vec(),
                0.0,
                ShadowMode::Opaque,
                shadowed,
                1,
            ),
            (
                "floor (3, 0, 0) beside an opaque ball, light straight up",
                floor_and(1).to_vec(),
                up.to_vec(),
                3.0,
                ShadowMode::Opaque,
                lit,
                1,
            ),
            (
                "floor (0, 0, 0) under a ball of k_t = ½, light straight up, Transmissive",
                floor_and(2).to_vec(),
                up.to_vec(),
                0.0,
                ShadowMode::Transmissive,
                Color::splat(0.175),
                3,
            ),
            (
                "floor (0, 0, 0) under an opaque ball, a light with shadows = false",
                floor_and(1).to_vec(),
                vec![directional(Vec3::Y, false)],
                0.0,
                ShadowMode::Opaque,
                lit,
                0,
            ),
            (
                "floor (3, 0, 0), a light below the floor",
                floor_and(1).to_vec(),
                vec![directional(-Vec3::Y, true)],
                3.0,
                ShadowMode::Opaque,
                shadowed,
                0,
            ),
        ];
        for (case, shapes, lights, x, mode, expected, rays) in cases {
            let got = run(&shapes, &lights, x, mode);
            let near = |a: Color| (got.0 - a).abs().max_element() <= 1e-4;
            let cause = if near(BLACK) {
                "the ambient term k_a ⊙ I_a is never shadowed"
            } else if near(lit) && expected == shadowed && rays > 0 {
                "trace a shadow ray toward each light that casts shadows: visible = visibility(…)"
            } else if near(shadowed) && expected != shadowed && mode == ShadowMode::Transmissive {
                "pass settings.mode to visibility: in Transmissive mode a blocker filters by its k_t"
            } else if near(shadowed) && !lights[0].shadows {
                "a light with shadows = false is never blocked: cast no shadow ray for it"
            } else if near(expected) && !lights[0].shadows {
                "a light with shadows = false casts no shadow ray"
            } else if near(expected) {
                "no shadow ray for a light behind the surface (N·L ≤ 0): it adds nothing anyway"
            } else {
                "I = k_a ⊙ I_a + Σ visibility ⊙ shade_light(…, illuminate(light, p))"
            };
            let ok = (got.0 - expected).abs().max_element() <= 2.0 * EPS && got.1 == rays;
            ensure(ok, case, show((expected, rays)), show(got), cause)?;
        }
        // A spot aimed away (the point 63° off its 10° cone): nothing to add, no shadow ray.
        let spot = Light {
            color: WHITE,
            shadows: true,
            kind: LightKind::Spot {
                position: v(10.0, 5.0, 0.0),
                direction: -Vec3::Y,
                inner: radians(5.0),
                outer: radians(10.0),
                attenuation: Attenuation::default(),
            },
        };
        let case =
            "floor (0, 0, 0), a spot at (10, 5, 0) aimed down with a 10° cone (the point is outside it)";
        let got = run(&floor_and(1), &[spot], 0.0, ShadowMode::Opaque);
        ensure(
            got == (shadowed, 0),
            case,
            show((shadowed, 0)),
            show(got),
            "no shadow ray for a light that sends nothing here (shade_light is black)",
        )?;
        // An area light with shadows under an opaque roof: sampled with 16 shadow rays, all blocked.
        let panel = Light {
            color: WHITE,
            shadows: true,
            kind: LightKind::Rect {
                corner: v(-0.5, 20.0, -0.5),
                edge_u: Vec3::X,
                edge_v: Vec3::Z,
                attenuation: Attenuation::default(),
            },
        };
        let case = "floor (0, 0, 0) under an opaque roof y = 10, a 1 × 1 rect light at height 20, 16 samples";
        let got = run(&[floor(0.0, 0), floor(10.0, 1)], &[panel], 0.0, ShadowMode::Opaque);
        ensure(
            got == (shadowed, 16),
            case,
            show((shadowed, 16)),
            show(got),
            "an area light that casts shadows is sampled: shade_area_light, settings.area_samples shadow rays",
        )?;
        Ok("7 cases".into())
    }

    // ------------------------------------------------------------ soft shadows

    pub(super) fn stratified_cases(stratified: StratifiedFn) -> CheckResult {
        let mut rng = Rng::new(0x57_7a7a);
        for (n, nx, ny) in [
            (1u32, 1u32, 1u32),
            (2, 2, 1),
            (3, 3, 1),
            (4, 2, 2),
            (5, 5, 1),
            (16, 4, 4),
            (64, 8, 8),
            (4096, 64, 64),
        ] {
            let samples = stratified(n, &mut rng);
            let grid = if nx == ny { format!("the {nx} × {ny} grid") } else { format!("{n} strips") };
            let case = format!("n = {n}: {grid}");
            ensure(
                samples.len() == n as usize,
                &case,
                format!("{n} samples"),
                samples.len(),
                "return exactly n samples: a √n × √n grid when n is a square, else n strips",
            )?;
            let mut seen = vec![false; n as usize];
            for &u in &samples {
                ensure(
                    u.cmpge(Vec2::ZERO).all() && u.cmplt(Vec2::ONE).all(),
                    &case,
                    "every sample in [0, 1)²",
                    format!("({}, {})", num(u.x), num(u.y)),
                    "u = ((i + ξ₁)/nₓ, (j + ξ₂)/n_y) with ξ in [0, 1), each coordinate at most ONE_MINUS_EPSILON",
                )?;
                // The cell, in f64 (exact for these n).
                let (i, j) = ((wide(u.x) * f64::from(nx)) as usize, (wide(u.y) * f64::from(ny)) as usize);
                let k = j * nx as usize + i;
                ensure(
                    !seen[k],
                    &case,
                    "one sample in each cell",
                    format!("two in cell ({i}, {j})"),
                    "one uniform sample per cell: u = ((i + ξ₁)/nₓ, (j + ξ₂)/n_y); n strips [i/n, (i+1)/n) × [0, 1) when n is not a square",
                )?;
                seen[k] = true;
            }
        }
        // The order: n = 4 from Rng::new(9), cells (0,0), (1,0), (0,1), (1,1), each from two
        // draws ξ₁ (x) then ξ₂ (y): the first is (ξ₁/2, ξ₂/2), the second ((1 + ξ₃)/2, ξ₄/2).
        // Tolerance 2ε: (i + ξ)/2 and i/2 + ξ/2 may round differently.
        let draws: Vec<Float> = {
            let mut rng = Rng::new(9);
            (0..8).map(|_| rng.next_float()).collect()
        };
        let samples = stratified(4, &mut Rng::new(9));
        let expected = [
            Vec2::new(draws[0] / 2.0, draws[1] / 2.0),
            Vec2::new((1.0 + draws[2]) / 2.0, draws[3] / 2.0),
            Vec2::new(draws[4] / 2.0, (1.0 + draws[5]) / 2.0),
            Vec2::new((1.0 + draws[6]) / 2.0, (1.0 + draws[7]) / 2.0),
        ];
        let show = |s: &[Vec2]| {
            s.iter().map(|u| format!("({}, {})", num(u.x), num(u.y))).collect::<Vec<_>>().join(", ")
        };
        ensure(
            samples.len() == 4
                && samples.iter().zip(&expected).all(|(a, b)| (*a - *b).abs().max_element() <= 2.0 * EPS),
            "n = 4 from Rng::new(9): the order of the samples and of the draws",
            format!("{} (± 2ε each)", show(&expected)),
            show(&samples),
            "row by row (j outer, i inner), each cell drawing ξ₁ for x then ξ₂ for y, from the generator given",
        )?;
        Ok("8 grids and the order".into())
    }

    /// The expected soft-shadowed light at the floor point `hit` from the white rect
    /// light (corner, edge_u, edge_v) with no attenuation, on a white matte surface:
    /// (1/n) Σ V(qᵢ)·(N·Lᵢ)⁺, over the points qᵢ of the samples uᵢ, in f64. V is given
    /// by `visible(p, q)`.
    fn area_expected(
        hit: &Hit,
        samples: &[Vec2],
        (corner, edge_u, edge_v): (Vec3, Vec3, Vec3),
        visible: impl Fn([f64; 3], [f64; 3]) -> bool,
    ) -> f64 {
        let p = wide3(hit.point);
        let n = wide3(hit.normal);
        let sum: f64 = samples
            .iter()
            .map(|u| {
                let q = wide3(corner + u.x * edge_u + u.y * edge_v);
                let to = [q[0] - p[0], q[1] - p[1], q[2] - p[2]];
                let d = (to[0] * to[0] + to[1] * to[1] + to[2] * to[2]).sqrt();
                let cos = (to[0] * n[0] + to[1] * n[1] + to[2] * n[2]) / d;
                if cos > 0.0 && visible(p, q) { cos } else { 0.0 }
            })
            .sum();
        sum / samples.len() as f64
    }

    pub(super) fn area_cases(area: AreaFn) -> CheckResult {
        let white = Material::default();
        let materials = [Material::default()];
        let rect = |corner, edge_u, edge_v| Light {
            color: WHITE,
            shadows: true,
            kind: LightKind::Rect { corner, edge_u, edge_v, attenuation: Attenuation::default() },
        };
        let panel_geometry = (v(-0.5, 20.0, -0.5), Vec3::X, Vec3::Z);
        let panel = rect(panel_geometry.0, panel_geometry.1, panel_geometry.2);
        let run = |shapes: &[(Shape, usize)], light: &Light, x: Float, n: u32| {
            let (hit, eye) = floor_hit(x, 0.1);
            let s = surface(&white, hit, eye);
            let scene = Scene::new(shapes);
            let settings = ShadowSettings { mode: ShadowMode::Opaque, area_samples: n };
            let (c, stats) = measure(|| area(&scene, &materials, &s, light, settings));
            (c, stats.get(Counter::ShadowRays), hit)
        };
        let samples_at = |hit: &Hit, n: u32| stratified(n, &mut Rng::new(point_seed(hit.point)));
        // A 2 × 2 wall light through the floor at x = 1 (y, z in [−1, 1]): of a 4 × 4 grid the
        // rows below the floor (N·L < 0) add nothing and cast no ray, but count in n.
        let wall = (v(1.0, -1.0, -1.0), 2.0 * Vec3::Z, 2.0 * Vec3::Y);
        let case =
            "white floor (0, 0, 0.1), a 2 × 2 rect light standing through the floor at x = 1, 16 samples";
        let (c, rays, hit) = run(&[], &rect(wall.0, wall.1, wall.2), 0.0, 16);
        let expected = area_expected(&hit, &samples_at(&hit, 16), wall, |_, _| true) as Float;
        // Sixteen terms below 1, each a few roundings: 16·4ε.
        let tolerance = 64.0 * EPS;
        let cause = if (c.x - 2.0 * expected).abs() <= 1e-4 {
            "divide by n: samples behind the surface count in the average"
        } else if (c.x - 16.0 * expected).abs() <= 1e-3 {
            "average: divide the sum over the samples by n"
        } else if rays < 8 {
            "weight each sample by the visibility of its own shadow ray (one per sample facing the surface)"
        } else if rays > 8 {
            "no shadow ray for a sample behind the surface (N·L ≤ 0)"
        } else {
            "the samples are stratified(n, Rng::new(point_seed(hit.point))), each through sample_light and shade_light"
        };
        ensure(
            (c - Color::splat(expected)).abs().max_element() <= tolerance && rays == 8,
            case,
            format!("{} (± {tolerance:.1e}) with 8 shadow rays", num(expected)),
            format!("{} with {rays} shadow rays", vec3(c)),
            cause,
        )?;
        // Under an opaque roof y = 10: every sample blocked, n shadow rays, black.
        for n in [1, 5, 16] {
            let case = format!(
                "white floor (0, 0, 0.1) under an opaque roof y = 10, 1 × 1 rect light at 20, {n} samples"
            );
            let (c, rays, _) = run(&[floor(10.0, 0)], &panel, 0.0, n);
            let cause = if c != BLACK {
                "weight each sample by the visibility of its own shadow ray"
            } else {
                "one shadow ray per sample that faces the surface"
            };
            ensure(
                c == BLACK && rays == u64::from(n),
                case,
                format!("(0, 0, 0) with {n} shadow rays"),
                format!("{} with {rays} shadow rays", vec3(c)),
                cause,
            )?;
        }
        // Nothing in the way, and the penumbra of a half plane x < 0 at height 10 (edge x = 0):
        // the ray from p to q crosses height 10 at x = (pₓ + qₓ)/2 (halfway up), blocked where
        // that is < 0. Points whose samples come within 10⁻⁴ of the edge are left out (the
        // checks' own f32 intersection may decide either way there).
        let mut count = 0;
        for (shapes, xs) in [
            (vec![], vec![0.0, 0.3]),
            (vec![(Shape::HalfFloor { height: 10.0 }, 0)], vec![-0.3, -0.1, 0.0, 0.2, 0.37]),
        ] {
            for x in xs {
                for n in [16, 64] {
                    let (c, _, hit) = run(&shapes, &panel, x, n);
                    let samples = samples_at(&hit, n);
                    let edge =
                        |p: [f64; 3], q: [f64; 3]| p[0] + (q[0] - p[0]) * (10.0 - p[1]) / (q[1] - p[1]);
                    let p = wide3(hit.point);
                    let near_edge = samples.iter().any(|u| {
                        let q = wide3(panel_geometry.0 + u.x * panel_geometry.1 + u.y * panel_geometry.2);
                        edge(p, q).abs() < 1e-4
                    });
                    if near_edge && !shapes.is_empty() {
                        continue;
                    }
                    let blocker = !shapes.is_empty();
                    let expected =
                        area_expected(&hit, &samples, panel_geometry, |p, q| !blocker || edge(p, q) >= 0.0)
                            as Float;
                    let case = format!(
                        "white floor ({}, 0, 0.1), 1 × 1 rect light at 20, {}, {n} samples",
                        num(x),
                        if blocker { "half plane x < 0 at height 10" } else { "nothing in the way" }
                    );
                    let cause = if (c.x - (n as Float) * expected).abs() <= 1e-3 {
                        "average: divide the sum over the samples by n"
                    } else if blocker {
                        "weight each sample by the visibility of its own shadow ray, from its own point of the light"
                    } else {
                        "the samples are stratified(n, Rng::new(point_seed(hit.point))), each through sample_light and shade_light"
                    };
                    // n terms below 1, each a few roundings: n·4ε.
                    close3(&case, c, Color::splat(expected), (n as Float) * 4.0 * EPS, cause)?;
                    count += 1;
                }
            }
        }
        Ok(format!("{} cases", count + 4))
    }
}

#[cfg(all(test, feature = "l06"))]
#[allow(clippy::result_large_err)]
mod tests {
    use super::code::*;
    use crate::check::testing::caught;
    pub(super) use l05_shading::{LightSample, illuminate, sample_light, shade_light};
    pub(super) use l06_shadows::{
        LIGHT_MARGIN, ShadowMode, ShadowSettings, Surface, occluded, offset_origin, point_seed,
        shade_area_light, stratified, transmittance, visibility,
    };
    use raylab::random::Rng;
    use raylab::scene::{Light, LightKind, Material};
    use raylab::stats::{Counter, count};
    use raylab::{BLACK, Color, Float, Intersector, Interval, Ray, Vec2, Vec3, WHITE};

    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }

    const EPS: Float = Float::EPSILON;

    #[test]
    fn offset_mistakes_are_caught() {
        // Always along +n, whatever dir.
        caught(
            offset_cases(|p, n, _dir, from| {
                p + (8.0 * EPS * (p.abs().element_sum() + from.abs().element_sum()) + Float::MIN_POSITIVE) * n
            }),
            "side the new ray leaves to",
        );
        // Scaled by p alone (the catalogued patch): the world origin seen from the eye moves by
        // the floor only.
        caught(
            offset_cases(|p, n, dir, _from| {
                let d = 8.0 * EPS * p.abs().element_sum() + Float::MIN_POSITIVE;
                if dir.dot(n) < 0.0 { p - d * n } else { p + d * n }
            }),
            "carries the rounding error of from",
        );
        // A fixed 10⁻⁴.
        caught(
            offset_cases(|p, n, dir, _| if dir.dot(n) < 0.0 { p - 1e-4 * n } else { p + 1e-4 * n }),
            "not a fixed epsilon",
        );
        // No floor: p = from = 0 does not move.
        caught(
            offset_cases(|p, n, dir, from| {
                let d = 8.0 * EPS * (p.abs().element_sum() + from.abs().element_sum());
                if dir.dot(n) < 0.0 { p - d * n } else { p + d * n }
            }),
            "add a floor",
        );
        // Along dir instead of n.
        caught(
            offset_cases(|p, _n, dir, from| {
                p + (8.0 * EPS * (p.abs().element_sum() + from.abs().element_sum()) + Float::MIN_POSITIVE)
                    * dir.normalize()
            }),
            "not along dir",
        );
    }

    #[test]
    fn large_coordinates_catch_fixed_and_p_only_offsets() {
        // A fixed 10⁻⁴ along n: rounds away at 10⁴ in f32 (a self-hit), far above 97 ulp in f64.
        caught(large_coordinates(|p, n, _, _| p + 1e-4 * n), "fixed");
        // Scaled by p alone: the floor near the world origin seen from (0, 500, 700) shadows itself.
        caught(
            large_coordinates(|p, n, dir, _from| {
                let d = 8.0 * EPS * p.abs().element_sum() + Float::MIN_POSITIVE;
                if dir.dot(n) < 0.0 { p - d * n } else { p + d * n }
            }),
            "rounding error of",
        );
    }

    #[test]
    fn naive_offset_mistakes_are_caught() {
        caught(fixed_t_cases(|p, n, _, _| p + 1e-4 * n), "not along n");
        caught(
            fixed_normal_cases(|p, n, dir, _| if dir.dot(n) < 0.0 { p - 1e-4 * n } else { p + 1e-4 * n }),
            "always steps along +n",
        );
        caught(fixed_normal_cases(|p, _, dir, _| p + 1e-4 * dir), "not along dir");
    }

    #[test]
    fn occluded_mistakes_are_caught() {
        // The closest hit asked, where any hit would do.
        caught(
            occluded_cases(|scene, from, s| {
                count(Counter::ShadowRays);
                scene
                    .closest_hit(&Ray::new(from, s.direction), Interval::new(0.0, s.distance * LIGHT_MARGIN))
                    .is_some()
            }),
            "any hit, not the closest",
        );
        // No end at the light.
        caught(
            occluded_cases(|scene, from, s| {
                count(Counter::ShadowRays);
                scene.any_hit(&Ray::new(from, s.direction), Interval::POSITIVE)
            }),
            "beyond the light",
        );
        // A range open behind the point.
        caught(
            occluded_cases(|scene, from, s| {
                count(Counter::ShadowRays);
                scene.any_hit(&Ray::new(from, s.direction), Interval::new(Float::NEG_INFINITY, s.distance))
            }),
            "behind the point",
        );
        // Not counted.
        caught(
            occluded_cases(|scene, from, s| {
                scene.any_hit(&Ray::new(from, s.direction), Interval::new(0.0, s.distance * LIGHT_MARGIN))
            }),
            "count one",
        );
    }

    /// The reference walk with a chosen slip.
    fn walk(
        scene: &dyn Intersector,
        materials: &[Material],
        from: Vec3,
        s: &LightSample,
        slip: &str,
    ) -> Color {
        let mut origin = from;
        let mut remaining = s.distance * LIGHT_MARGIN;
        let mut filtered = WHITE;
        for _ in 0..64 {
            count(Counter::ShadowRays);
            let Some(hit) = scene.closest_hit(&Ray::new(origin, s.direction), Interval::new(0.0, remaining))
            else {
                return filtered;
            };
            let kt = materials.get(hit.material).map_or(BLACK, |m| m.transparent);
            if slip != "once per object" || hit.front_face {
                filtered *= kt;
            }
            if filtered == BLACK && slip != "no stop" {
                return BLACK;
            }
            origin = if slip == "no offset" {
                hit.point
            } else {
                offset_origin(hit.point, hit.normal, s.direction, origin)
            };
            if slip != "light not nearer" {
                remaining -= hit.t;
            }
        }
        BLACK
    }

    #[test]
    fn transmittance_mistakes_are_caught() {
        caught(transmittance_cases(|sc, m, f, s| walk(sc, m, f, s, "once per object")), "crossed twice");
        caught(transmittance_cases(|sc, m, f, s| walk(sc, m, f, s, "light not nearer")), "light is nearer");
        caught(transmittance_cases(|sc, m, f, s| walk(sc, m, f, s, "no stop")), "ends the walk");
        assert!(transmittance_cases(|sc, m, f, s| walk(sc, m, f, s, "")).is_ok());
    }

    #[test]
    fn visibility_mistakes_are_caught() {
        // The shadow ray from the hit point itself.
        caught(
            visibility_cases(|scene, materials, surface, sample, mode| match mode {
                ShadowMode::Opaque if occluded(scene, surface.hit.point, sample) => BLACK,
                ShadowMode::Opaque => WHITE,
                ShadowMode::Transmissive => transmittance(scene, materials, surface.hit.point, sample),
            }),
            "just off the surface",
        );
        // The offset from the hit point alone (from = p): fails where the eye is far.
        caught(
            visibility_cases(|scene, materials, surface, sample, mode| {
                let p = surface.hit.point;
                let s = Surface { origin: p, ..*surface };
                visibility(scene, materials, &s, sample, mode)
            }),
            "the eye as from",
        );
        // Every blocker opaque, whatever the mode.
        caught(
            visibility_cases(|scene, materials, surface, sample, _| {
                visibility(scene, materials, surface, sample, ShadowMode::Opaque)
            }),
            "Transmissive mode",
        );
    }

    /// Shading with shadows with a chosen slip (point and directional lights only; area
    /// lights through the reference).
    fn shade_with(
        scene: &dyn Intersector,
        materials: &[Material],
        s: &Surface,
        lights: &[Light],
        ambient: Color,
        settings: ShadowSettings,
        slip: &str,
    ) -> Color {
        let mut color = s.diffuse * ambient;
        let mut lit = BLACK;
        for light in lights {
            let area = matches!(light.kind, LightKind::Rect { .. } | LightKind::Sphere { .. });
            if area && light.shadows && slip != "area as point" {
                lit += shade_area_light(scene, materials, s, light, settings);
                continue;
            }
            let sample = illuminate(light, s.hit.point);
            if s.hit.normal.dot(sample.direction) <= 0.0 && slip != "rays behind" {
                continue;
            }
            let direct = shade_light(s.material, s.diffuse, s.hit.normal, s.v, &sample);
            if direct == BLACK && slip != "rays for black" && slip != "rays behind" {
                continue;
            }
            let visible = if light.shadows || slip == "ignore flag" {
                visibility(scene, materials, s, &sample, settings.mode)
            } else {
                WHITE
            };
            lit += visible * direct;
            if slip == "shadowed ambient" && visible == BLACK {
                color = BLACK;
            }
        }
        color + lit
    }

    #[test]
    fn shade_with_shadows_mistakes_are_caught() {
        caught(
            shade_cases(|a, b, c, d, e, f| shade_with(a, b, c, d, e, f, "shadowed ambient")),
            "never shadowed",
        );
        caught(
            shade_cases(|a, b, c, d, e, f| shade_with(a, b, c, d, e, f, "ignore flag")),
            "shadows = false",
        );
        caught(
            shade_cases(|a, b, c, d, e, f| shade_with(a, b, c, d, e, f, "rays behind")),
            "behind the surface",
        );
        caught(shade_cases(|a, b, c, d, e, f| shade_with(a, b, c, d, e, f, "area as point")), "is sampled");
        caught(
            shade_cases(|a, b, c, d, e, f| shade_with(a, b, c, d, e, f, "rays for black")),
            "sends nothing here",
        );
        assert!(shade_cases(|a, b, c, d, e, f| shade_with(a, b, c, d, e, f, "")).is_ok());
    }

    #[test]
    fn stratified_mistakes_are_caught() {
        // Independent samples.
        caught(
            stratified_cases(|n, rng| {
                (0..n).map(|_| Vec2::new(rng.next_float(), rng.next_float())).collect()
            }),
            "one uniform sample per cell",
        );
        // Column by column.
        caught(
            stratified_cases(|n, rng| {
                let mut s = stratified(n, rng);
                let root = n.isqrt() as usize;
                if root * root == n as usize {
                    let copy = s.clone();
                    for (k, u) in s.iter_mut().enumerate() {
                        *u = copy[(k % root) * root + k / root];
                    }
                }
                s
            }),
            "row by row",
        );
        // The largest square grid for every n.
        caught(
            stratified_cases(|n, rng| {
                let root = n.isqrt();
                let mut s = Vec::new();
                for j in 0..root {
                    for i in 0..root {
                        let x = (i as Float + rng.next_float()) / root as Float;
                        let y = (j as Float + rng.next_float()) / root as Float;
                        s.push(Vec2::new(x, y));
                    }
                }
                s
            }),
            "exactly n samples",
        );
    }

    /// The soft-shadowed light with a chosen slip.
    fn area_with(
        scene: &dyn Intersector,
        materials: &[Material],
        s: &Surface,
        light: &Light,
        settings: ShadowSettings,
        slip: &str,
    ) -> Color {
        let samples = stratified(settings.area_samples, &mut Rng::new(point_seed(s.hit.point)));
        let (mut sum, mut used) = (BLACK, 0);
        for &u in &samples {
            let sample = sample_light(light, s.hit.point, u);
            if s.hit.normal.dot(sample.direction) <= 0.0 && slip != "rays behind" {
                continue;
            }
            used += 1;
            let direct = shade_light(s.material, s.diffuse, s.hit.normal, s.v, &sample);
            let visible = if slip == "no shadows" {
                WHITE
            } else {
                visibility(scene, materials, s, &sample, settings.mode)
            };
            sum += visible * direct;
        }
        match slip {
            "divide by used" => sum / used.max(1) as Float,
            "sum" => sum,
            _ => sum / samples.len() as Float,
        }
    }

    #[test]
    fn shade_area_light_mistakes_are_caught() {
        caught(area_cases(|a, b, c, d, e| area_with(a, b, c, d, e, "divide by used")), "divide by n");
        caught(area_cases(|a, b, c, d, e| area_with(a, b, c, d, e, "sum")), "average");
        caught(
            area_cases(|a, b, c, d, e| area_with(a, b, c, d, e, "no shadows")),
            "visibility of its own shadow ray",
        );
        caught(
            area_cases(|a, b, c, d, e| area_with(a, b, c, d, e, "rays behind")),
            "no shadow ray for a sample behind",
        );
        assert!(area_cases(|a, b, c, d, e| area_with(a, b, c, d, e, "")).is_ok());
        // The same for the reference.
        assert!(area_cases(shade_area_light).is_ok());
    }
}
