//! Lecture 03, polygons and triangles: boxes by slabs, point in polygon,
//! ray–polygon, three ray–triangle tests, interpolated normals, meshes.

use crate::check::Meta;

declare_checks! {
    "l03";
    Meta::unit(
        "hit_slabs",
        "the span inside a box: generic rays both ways, from inside, misses, an edge touch",
    ) => slabs_cases(hit_slabs),
    Meta::extreme(
        "hit_slabs",
        "axis-parallel-rays",
        "axis-parallel rays, origins on a slab plane (±0 directions), flat boxes, edges and corners, and \
            4,000 rays against exact integer arithmetic: no false misses and never NaN",
    ) => slabs_extreme(hit_slabs),
    Meta::unit("hit_box", "the face hit and its normal on all six faces, from outside and from inside")
        .needs(&["03/hit_slabs"]) => box_cases(hit_box),
    Meta::unit(
        "inside_crossings",
        "even–odd: convex, concave, pentagram, test rays through vertices, shared edges",
    ) => crossings_cases(inside_crossings),
    Meta::unit("winding_number", "signed crossings: orientation, pentagram (2), vertices on the test ray")
        => winding_cases(winding_number),
    Meta::unit("newell_normal", "Newell's normal is twice the area along the counter-clockwise normal")
        => newell_cases(newell_normal),
    Meta::unit(
        "hit_polygon",
        "squares in the three axis planes from front and back, a tilted quad, degenerate ones",
    )
    .needs(&["03/newell_normal", "03/inside_crossings", "02/hit_plane"]) => polygon_cases(hit_polygon),
    Meta::unit("hit_triangle_cramer", "t and (β, γ) at vertices, inside, from behind, misses, parallel rays")
        => triangle_cases(hit_triangle_cramer),
    Meta::unit(
        "hit_triangle_moller_trumbore",
        "t and (β, γ) at vertices, inside, from behind, misses, parallel rays",
    ) => triangle_cases(hit_triangle_moller_trumbore),
    Meta::unit(
        "edge_function",
        "e(p, q) = p.x·q.y − p.y·q.x, exactly antisymmetric, its sign decided when it rounds to 0",
    ) => edge_cases(edge_function),
    Meta::unit(
        "hit_triangle_watertight",
        "t and (β, γ) at vertices, inside, from behind, misses, parallel rays",
    )
    .needs(&["03/edge_function"]) => triangle_cases(hit_triangle_watertight),
    Meta::extreme(
        "hit_triangle_watertight",
        "no-leaks",
        "closed meshes, rays from inside aimed exactly at every vertex and edge: zero leaks",
    )
    .needs(&["03/edge_function"]) => triangle_no_leaks(hit_triangle_watertight),
    Meta::unit(
        "interpolate_normal",
        "the blend (1 − β − γ)n₀ + βn₁ + γn₂, normalised; zero (not NaN) when it cancels",
    ) => interpolate_cases(interpolate_normal),
    Meta::unit(
        "hit_triangle",
        "the hit record: normal against the ray, front_face, uv = (β, γ), shading normals",
    )
    .needs(&["03/hit_triangle_watertight", "03/interpolate_normal"]) => hit_triangle_cases(hit_triangle),
    Meta::unit("hit_mesh", "the closest triangle whatever the order, mesh uvs and normals interpolated")
        .needs(&["03/hit_triangle"]) => mesh_cases(hit_mesh),
    Meta::extreme(
        "hit_mesh",
        "no-leaks",
        "closed meshes, rays from inside aimed at every vertex and edge: all hit",
    )
    .needs(&["03/hit_triangle"]) => mesh_no_leaks(hit_mesh),
}

#[cfg(feature = "l03")]
#[allow(clippy::result_large_err)] // Failure is check.rs's report, returned by value as in every lecture
#[allow(clippy::unnecessary_cast)] // widening Float to f64 for references is the identity in an f64 build
mod code {
    pub(super) use l03_polygons_triangles::{
        TriangleHit, edge_function, hit_box, hit_mesh, hit_polygon, hit_slabs, hit_triangle,
        hit_triangle_cramer, hit_triangle_moller_trumbore, hit_triangle_watertight, inside_crossings,
        interpolate_normal, newell_normal, winding_number,
    };
    use raylab::math::consts::PI;
    use raylab::random::Rng;
    use raylab::scene::Mesh;
    use raylab::{Float, Hit, Interval, Ray, Vec2, Vec3};

    use crate::check::{CheckResult, Failure, close, close3, ensure, fail, maybe, num, vec3};
    use crate::exact::exact_hits;

    pub(super) type SlabsFn = fn(&Ray, Vec3, Vec3, Interval) -> Option<(Float, Float)>;
    pub(super) type BoxFn = fn(&Ray, Vec3, Vec3, Interval) -> Option<Hit>;
    pub(super) type InsideFn = fn(&[Vec2], Vec2) -> bool;
    pub(super) type WindingFn = fn(&[Vec2], Vec2) -> i32;
    pub(super) type NewellFn = fn(&[Vec3]) -> Vec3;
    pub(super) type PolygonFn = fn(&Ray, &[Vec3], Interval) -> Option<Hit>;
    pub(super) type TriangleFn = fn(&Ray, Vec3, Vec3, Vec3, Interval) -> Option<TriangleHit>;
    pub(super) type EdgeFn = fn(Vec3, Vec3) -> Float;
    pub(super) type InterpolateFn = fn(&[Vec3; 3], Float, Float) -> Vec3;
    pub(super) type HitTriangleFn = fn(&Ray, &[Vec3; 3], Option<&[Vec3; 3]>, Interval) -> Option<Hit>;
    pub(super) type MeshFn = fn(&Ray, &Mesh, Interval) -> Option<Hit>;

    /// t, points and unit normals of unit-sized shapes a few units away: each
    /// method rounds a handful of operations on numbers ≤ 4 (most inputs are
    /// dyadic and exact); 16ε holds them (2e-6 in f32).
    const TOL: Float = 16.0 * Float::EPSILON;

    const ALL: Interval = Interval::POSITIVE;

    fn ray(o: [Float; 3], d: [Float; 3]) -> Ray {
        Ray::new(Vec3::from_array(o), Vec3::from_array(d))
    }

    fn show_ray(r: &Ray) -> String {
        format!("ray from {} along {}", vec3(r.origin), vec3(r.dir))
    }

    fn show_hit(h: &Option<Hit>) -> String {
        maybe(h, |h| format!("t = {}, normal {}, front_face {}", num(h.t), vec3(h.normal), h.front_face))
    }

    fn show_span(s: &Option<(Float, Float)>) -> String {
        maybe(s, |(a, b)| format!("({}, {})", num(*a), num(*b)))
    }

    fn near3(a: Vec3, b: Vec3, tol: Float) -> bool {
        (a - b).abs().max_element() <= tol
    }

    // ---- slabs ---------------------------------------------------------------

    const LO: Vec3 = Vec3::splat(-1.0);
    const HI: Vec3 = Vec3::splat(1.0);

    const SWAP: &str = "for dᵢ < 0 the ray meets the max plane first: the near plane is the max plane, so \
        swap the two t's (order them by the sign of 1/dᵢ)";
    const CLIP: &str =
        "clip the box's span to the range: t0 = max(t_enter, range.min), t1 = min(t_exit, range.max)";
    const NAN_PLANE: &str = "an origin on a slab plane of a parallel ray gives (plane − o)·(1/0) = 0·∞ = \
        NaN: order the planes by the sign of 1/d (never NaN), not by comparing the t's, and let a NaN end \
        count as unbounded";

    /// Expects `Some((t0, t1))` with t0 within TOL·t0 of `enter` and t1 in
    /// [exit, exit·(1 + 8ε)] (the exit may be widened by 2γ₃ ≈ 3.6ε).
    fn expect_span(
        case: &str,
        got: Option<(Float, Float)>,
        enter: Float,
        exit: Float,
        cause: &str,
    ) -> Result<(), Failure> {
        let expected = format!("({}, {}) (t1 may be widened by 8ε)", num(enter), num(exit));
        let Some((t0, t1)) = got else { return Err(fail(case, expected, "None (no hit)", cause)) };
        let ok0 = (t0 - enter).abs() <= TOL * enter.abs().max(1.0);
        let ok1 = t1 >= exit - TOL * exit.abs() && t1 <= exit + 8.0 * Float::EPSILON * exit.abs().max(1.0);
        ensure(ok0 && ok1, case, expected, show_span(&got), cause)
    }

    pub(super) fn slabs_cases(hit_slabs: SlabsFn) -> CheckResult {
        // Generic, all components positive: x [(−1+3)/2, (1+3)/2] = [1, 2], y [2/3, 2], z [−4, 4] → [1, 2].
        let r = ray([-3.0, -2.0, 0.0], [2.0, 1.5, 0.25]);
        let case = format!("cube [−1, 1]³, {}", show_ray(&r));
        expect_span(
            &case,
            hit_slabs(&r, LO, HI, ALL),
            1.0,
            2.0,
            "each slab holds t between (minᵢ − oᵢ)/dᵢ and (maxᵢ − oᵢ)/dᵢ: enter at the latest entry, leave \
                at the earliest exit",
        )?;
        // Negative components: x [(1−3)/−2, (−1−3)/−2] = [1, 2], y [1, 7/3], z [−2, 6] → [1, 2].
        let r = ray([3.0, 2.5, -0.5], [-2.0, -1.5, 0.25]);
        let case = format!("cube [−1, 1]³, {}", show_ray(&r));
        expect_span(&case, hit_slabs(&r, LO, HI, ALL), 1.0, 2.0, SWAP)?;
        // From inside: the span [−1, 1] clipped to (0, ∞) is (0, 1).
        let r = ray([0.0, 0.0, 0.0], [1.0, 0.5, 0.25]);
        let case = format!("cube [−1, 1]³, {} (starts inside)", show_ray(&r));
        expect_span(&case, hit_slabs(&r, LO, HI, ALL), 0.0, 1.0, CLIP)?;
        // Touching the edge x = y = 1 only: x [−1, 1], y [1, 3] → [1, 1].
        let r = ray([0.0, 2.0, 0.0], [1.0, -1.0, 0.0]);
        let case = format!("cube [−1, 1]³, {} (touches the edge x = y = 1 at t = 1)", show_ray(&r));
        expect_span(
            &case,
            hit_slabs(&r, LO, HI, ALL),
            1.0,
            1.0,
            "a ray touching an edge has t_enter = t_exit: the box is closed, test t_enter ≤ t_exit",
        )?;
        // Behind the origin, in a range that reaches back: x [(−1−3)/1, (1−3)/1] = [−4, −2],
        // y [−10, 10], z parallel through the slab: the span (−4, −2), its exit widened toward
        // +∞, i.e. by the factor 1 − 2γ₃ for a negative t.
        let r = ray([3.0, 0.0, 0.0], [1.0, 0.1, 0.0]);
        let back = Interval::new(-10.0, 10.0);
        let case =
            format!("cube [−1, 1]³, {}, range (−10, 10) (the box lies behind the origin)", show_ray(&r));
        expect_span(
            &case,
            hit_slabs(&r, LO, HI, back),
            -4.0,
            -2.0,
            "a negative exit t is widened by (1 − 2γ₃), toward +∞, as a positive one is by (1 + 2γ₃): \
             t_far *= if t_far ≥ 0 { 1 + 2γ₃ } else { 1 − 2γ₃ }",
        )?;
        // Misses.
        for (r, range, why) in [
            (ray([-3.0, 0.0, 0.0], [1.0, 1.0, 0.0]), ALL, "x [2, 4] and y [−1, 1] do not overlap: no hit"),
            (
                ray([3.0, 0.0, 0.0], [1.0, 0.1, 0.0]),
                ALL,
                "the span [−4, −2] is behind the origin (t_exit ≤ range.min): no hit",
            ),
            (
                ray([-3.0, 0.0, 0.0], [1.0, 0.1, 0.0]),
                Interval::new(0.0, 1.5),
                "the box starts at t = 2, after range.max = 1.5: no hit",
            ),
        ] {
            let got = hit_slabs(&r, LO, HI, range);
            let case =
                format!("cube [−1, 1]³, {}, range ({}, {})", show_ray(&r), num(range.min), num(range.max));
            ensure(got.is_none(), case, "None", show_span(&got), why)?;
        }
        Ok("5 hits and 3 misses".into())
    }

    pub(super) fn slabs_extreme(hit_slabs: SlabsFn) -> CheckResult {
        let no_nan = |case: &str, got: Option<(Float, Float)>| {
            ensure(
                got.is_none_or(|(a, b)| !a.is_nan() && !b.is_nan() && a <= b),
                case,
                "no NaN, t0 ≤ t1",
                show_span(&got),
                NAN_PLANE,
            )
        };
        // Axis-parallel: inside the other slabs → [2, 4]; outside one of them → None.
        let r = ray([-3.0, 0.5, -0.5], [1.0, 0.0, 0.0]);
        let case = format!("cube [−1, 1]³, {} (axis-parallel, inside the y and z slabs)", show_ray(&r));
        expect_span(
            &case,
            hit_slabs(&r, LO, HI, ALL),
            2.0,
            4.0,
            "a parallel slab holds the whole ray when the origin is between its planes: 1/0 = ±∞ gives the \
                span (−∞, ∞)",
        )?;
        for r in [ray([-3.0, 1.5, 0.0], [1.0, 0.0, 0.0]), ray([-3.0, 0.0, -1.5], [1.0, 0.0, -0.0])] {
            let got = hit_slabs(&r, LO, HI, ALL);
            let case = format!("cube [−1, 1]³, {} (axis-parallel, outside a slab)", show_ray(&r));
            no_nan(&case, got)?;
            ensure(
                got.is_none(),
                case,
                "None",
                show_span(&got),
                "a parallel ray outside a slab never enters it",
            )?;
        }
        // Origins exactly on a face plane or an edge line, with +0 and −0 components: inside.
        for (o, d) in [
            ([-3.0, 1.0, 0.0], [1.0, 0.0, 0.0]),
            ([-3.0, 1.0, 0.0], [1.0, -0.0, 0.0]),
            ([-3.0, -1.0, 0.0], [1.0, -0.0, -0.0]),
            ([-3.0, -1.0, 0.0], [1.0, 0.0, 0.0]),
            ([-3.0, 1.0, 1.0], [1.0, -0.0, 0.0]),
            ([3.0, -1.0, -1.0], [-1.0, 0.0, -0.0]),
        ] {
            let r = ray(o, d);
            let case = format!("cube [−1, 1]³, {} (moves within a face plane)", show_ray(&r));
            let got = hit_slabs(&r, LO, HI, ALL);
            no_nan(&case, got)?;
            expect_span(&case, got, 2.0, 4.0, NAN_PLANE)?;
        }
        // Flat boxes (min.x = max.x): crossed at one t, or run along.
        let (flat_lo, flat_hi) = (Vec3::new(0.0, -1.0, -1.0), Vec3::new(0.0, 1.0, 1.0));
        for (r, enter, exit) in [
            (ray([-1.0, 0.5, 0.5], [1.0, 0.0, 0.0]), 1.0, 1.0),
            (ray([-3.0, -1.0, 0.5], [3.0, 1.0, -0.25]), 1.0, 1.0),
            (ray([0.0, -3.0, 0.0], [0.0, 1.0, 0.0]), 2.0, 4.0),
        ] {
            let case = format!("flat box x = 0, −1 ≤ y, z ≤ 1, {}", show_ray(&r));
            let got = hit_slabs(&r, flat_lo, flat_hi, ALL);
            no_nan(&case, got)?;
            expect_span(
                &case,
                got,
                enter,
                exit,
                "a flat box is a closed slab of zero width: t_enter = t_exit is a hit, and a ray in its \
                    plane has 0·∞ = NaN ends that count as unbounded",
            )?;
        }
        // Through an edge and a corner, and touching a corner.
        for (r, enter, exit) in [
            (ray([-3.0, -3.0, 0.0], [1.0, 1.0, 0.0]), 2.0, 4.0),
            (ray([-3.0, -3.0, -3.0], [1.0, 1.0, 1.0]), 2.0, 4.0),
            (ray([0.0, 2.0, 2.0], [1.0, -1.0, -1.0]), 1.0, 1.0),
        ] {
            let case = format!("cube [−1, 1]³, {} (through an edge or a corner)", show_ray(&r));
            expect_span(
                &case,
                hit_slabs(&r, LO, HI, ALL),
                enter,
                exit,
                "edges and corners belong to the box: test t_enter ≤ t_exit",
            )?;
        }
        // Random rays on a 1/16 grid (exact in any float), half aimed exactly at a face, an
        // edge or a corner, against exact integer arithmetic: no false misses, never NaN.
        const SCALE: Float = 1.0 / 16.0;
        let to_vec = |v: [i64; 3]| Vec3::new(v[0] as Float, v[1] as Float, v[2] as Float) * SCALE;
        let mut rng = Rng::new(3);
        let mut exact_count = 0;
        for n in 0..4000 {
            let mut lo = [0i64; 3];
            let mut hi = [0i64; 3];
            for i in 0..3 {
                lo[i] = rng.int(-40, 40);
                hi[i] = if rng.int(0, 7) == 0 { lo[i] } else { lo[i] + rng.int(1, 40) };
            }
            let o: [i64; 3] = std::array::from_fn(|_| rng.int(-100, 100));
            let d: [i64; 3] = if n % 2 == 0 {
                std::array::from_fn(|_| if rng.int(0, 3) == 0 { 0 } else { rng.int(-60, 60) })
            } else {
                let target: [i64; 3] = std::array::from_fn(|i| match rng.int(0, 2) {
                    0 => lo[i],
                    1 => hi[i],
                    _ => rng.int(lo[i], hi[i]),
                });
                let mut d = [target[0] - o[0], target[1] - o[1], target[2] - o[2]];
                if !(0..3).any(|i| target[i] == lo[i] || target[i] == hi[i]) {
                    d[0] = hi[0] - o[0];
                }
                d
            };
            if d == [0; 3] {
                continue;
            }
            let r = Ray::new(to_vec(o), to_vec(d));
            let got = hit_slabs(&r, to_vec(lo), to_vec(hi), ALL);
            let case = format!("box {}..{}, {}", vec3(to_vec(lo)), vec3(to_vec(hi)), show_ray(&r));
            no_nan(&case, got)?;
            let exact = exact_hits(o, d, lo, hi);
            exact_count += exact as u32;
            if exact && got.is_none() {
                let cause = if (0..3).any(|i| d[i] == 0) {
                    NAN_PLANE
                } else {
                    "a ray aimed exactly at the box's boundary hits it (exact arithmetic says so): rounding \
                        put t_enter an ulp past t_exit; widen each slab's exit by 2γ₃ (t_far·(1 + 2γ₃))"
                };
                return Err(fail(case, "a hit (exact arithmetic)", "None (no hit)", cause));
            }
        }
        Ok(format!(
            "23 hand cases and 4000 random rays ({exact_count} hits by exact arithmetic): no false miss, no \
                NaN"
        ))
    }

    pub(super) fn box_cases(hit_box: BoxFn) -> CheckResult {
        for axis in 0..3 {
            for sign in [-1.0, 1.0] {
                let mut outward = Vec3::ZERO;
                outward[axis] = sign;
                let oblique = Vec3::new(0.1, -0.05, 0.07) * (Vec3::ONE - outward.abs());
                // From outside toward the face: enters at t = 2 (3 − 1 along the axis).
                let r = Ray::new(3.0 * outward + oblique, -outward);
                let case = format!("cube [−1, 1]³, {} toward the face {}", show_ray(&r), vec3(outward));
                let got = hit_box(&r, LO, HI, ALL);
                let Some(h) = got else {
                    return Err(fail(
                        case,
                        "t = 2",
                        show_hit(&got),
                        "the ray enters the box: hit_slabs finds the span",
                    ));
                };
                close(&case, h.t, 2.0, TOL, "entering, the hit is the latest entry among the slabs")?;
                let cause = if near3(h.normal, -outward, TOL) {
                    "the min face's outward normal is −eᵢ and the max face's +eᵢ; the ray enters through \
                        the min face of axis i when dᵢ > 0"
                } else {
                    "the face is the slab whose plane gave the hit: entering, the slab with the latest \
                        entry t"
                };
                close3(&case, h.normal, outward, TOL, cause)?;
                ensure(
                    h.front_face,
                    &case,
                    "front_face true",
                    "false",
                    "a ray from outside meets a front face",
                )?;
                // From inside toward the face (slightly oblique): leaves at t = 1.
                let r = Ray::new(oblique, outward + 0.25 * oblique);
                let case =
                    format!("cube [−1, 1]³, {} from inside toward the face {}", show_ray(&r), vec3(outward));
                let got = hit_box(&r, LO, HI, ALL);
                let Some(h) = got else {
                    return Err(fail(
                        case,
                        "t = 1",
                        show_hit(&got),
                        "starting inside, the hit is where the ray leaves the box",
                    ));
                };
                let cause = if h.t.abs() <= TOL {
                    "starting inside, the hit is where the ray leaves (the earliest exit), not t0 = range.min"
                } else {
                    "leaving, the face is the slab with the earliest exit t"
                };
                close(&case, h.t, 1.0, TOL, cause)?;
                let cause = if near3(h.normal, outward, TOL) {
                    "from inside the normal faces the ray: build the hit with Hit::new(ray, t, outward \
                        normal)"
                } else {
                    "leaving through the face ±eᵢ, the outward normal is ±eᵢ, turned against the ray"
                };
                close3(&case, h.normal, -outward, TOL, cause)?;
                ensure(
                    !h.front_face,
                    &case,
                    "front_face false",
                    "true",
                    "a ray from inside meets a back face",
                )?;
            }
        }
        // Non-unit direction: t in units of dir, 2/4.
        let r = ray([-3.0, 0.2, 0.1], [4.0, 0.0, 0.0]);
        let got = hit_box(&r, LO, HI, ALL);
        let case = format!("cube [−1, 1]³, {}", show_ray(&r));
        close(
            &case,
            got.map_or(Float::NAN, |h| h.t),
            0.5,
            TOL,
            "t is in units of dir: do not normalise the direction",
        )?;
        // The exit beyond range.max is no hit.
        let r = ray([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        let got = hit_box(&r, LO, HI, Interval::new(0.0, 0.5));
        ensure(
            got.is_none(),
            "cube [−1, 1]³, ray from the centre along +x, range (0, 0.5)",
            "None",
            show_hit(&got),
            "the exit at t = 1 is beyond range.max",
        )?;
        Ok("6 faces from outside and inside, and 2 more".into())
    }

    // ---- polygons --------------------------------------------------------------

    fn v2(points: &[[Float; 2]]) -> Vec<Vec2> {
        points.iter().map(|&p| Vec2::from_array(p)).collect()
    }

    fn square() -> Vec<Vec2> {
        v2(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]])
    }

    /// A "U" with the notch x ∈ (1, 2), y ∈ (1, 3) outside.
    fn u_shape() -> Vec<Vec2> {
        v2(&[[0.0, 0.0], [3.0, 0.0], [3.0, 3.0], [2.0, 3.0], [2.0, 1.0], [1.0, 1.0], [1.0, 3.0], [0.0, 3.0]])
    }

    /// The pentagram {5/2}, counter-clockwise: vertices 90° + 72°k taken 0, 2, 4, 1, 3.
    fn pentagram() -> Vec<Vec2> {
        [0, 2, 4, 1, 3]
            .iter()
            .map(|&k| {
                let a = PI / 2.0 + 2.0 * PI * k as Float / 5.0;
                Vec2::new(a.cos(), a.sin())
            })
            .collect()
    }

    fn show2(p: Vec2) -> String {
        format!("({}, {})", num(p.x), num(p.y))
    }

    fn show_polygon(poly: &[Vec2]) -> String {
        let points: Vec<String> = poly.iter().map(|&p| show2(p)).collect();
        format!("[{}]", points.join(", "))
    }

    const VERTEX: &str = "a vertex at the height of p counts as above (v.y ≥ p.y) for both its edges, so a \
        test ray through a vertex crosses once or not at all, and an edge lying on the test ray never counts";

    /// Polygon cases shared by the two rules: (polygon, point, winding number, cause).
    fn polygon_table() -> Vec<(Vec<Vec2>, Vec2, i32, &'static str)> {
        let p = Vec2::new;
        let cw: Vec<Vec2> = square().iter().rev().copied().collect();
        let closing = v2(&[[0.0, 2.0], [0.0, 0.0], [2.0, 0.0]]);
        let diamond = v2(&[[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]]);
        let kite = v2(&[[-1.0, 1.0], [1.0, 0.0], [3.0, 1.0], [1.0, 2.0]]);
        let star = pentagram();
        let reversed_star: Vec<Vec2> = star.iter().rev().copied().collect();
        let gap = 0.8 * Vec2::from_angle(PI / 2.0 + PI / 5.0);
        const BASIC: &str = "cast the test ray from p toward +x and count the edges it crosses";
        vec![
            (square(), p(1.0, 1.0), 1, BASIC),
            (square(), p(3.0, 1.0), 0, BASIC),
            (
                closing,
                p(0.5, 0.5),
                1,
                "the polygon is closed: include the edge from the last vertex back to the first",
            ),
            (
                square(),
                p(-1.0, 1.0),
                0,
                "only crossings to the right of p count (p strictly left of the upward edge)",
            ),
            (square(), p(1.0, 3.0), 0, BASIC),
            (
                cw,
                p(1.0, 1.0),
                -1,
                "clockwise winds negatively: a crossing downward counts −1 (even–odd ignores the \
                    orientation)",
            ),
            (u_shape(), p(1.5, 2.0), 0, "in the notch the test ray crosses two edges: even, outside"),
            (u_shape(), p(0.5, 2.0), 1, "in the left arm the test ray crosses three edges: odd, inside"),
            (u_shape(), p(1.5, 0.5), 1, BASIC),
            (star.clone(), p(0.0, 0.8), 1, "a tip of the pentagram is covered once"),
            (star.clone(), gap, 0, "between two tips of the pentagram is outside"),
            (
                star.clone(),
                p(0.0, 0.0),
                2,
                "the pentagram's centre is crossed twice, both upward: winding 2, even–odd outside",
            ),
            (reversed_star, p(0.0, 0.0), -2, "the reversed pentagram winds −2 around its centre"),
            (diamond.clone(), p(0.0, 0.0), 1, VERTEX),
            (diamond.clone(), p(-0.5, 0.0), 1, VERTEX),
            (diamond.clone(), p(-2.0, 0.0), 0, VERTEX),
            (diamond, p(2.0, 0.0), 0, VERTEX),
            (kite, p(0.0, 0.0), 0, VERTEX),
            (square(), p(-1.0, 0.0), 0, VERTEX),
            (square(), p(-1.0, 2.0), 0, VERTEX),
            (square(), p(3.0, 0.0), 0, VERTEX),
            (square(), p(3.0, 2.0), 0, VERTEX),
            (vec![], p(0.0, 0.0), 0, "no vertices contain nothing"),
            (v2(&[[0.0, 0.0], [1.0, 1.0]]), p(0.5, 0.2), 0, "fewer than three vertices contain nothing"),
        ]
    }

    /// Points on an edge shared by two squares (lower and upper, lower and right).
    fn shared_edges() -> Vec<(Vec<Vec2>, Vec<Vec2>, Vec2)> {
        let lower = square();
        let upper: Vec<Vec2> = lower.iter().map(|&v| v + Vec2::new(0.0, 2.0)).collect();
        let right: Vec<Vec2> = lower.iter().map(|&v| v + Vec2::new(2.0, 0.0)).collect();
        vec![(lower.clone(), upper, Vec2::new(1.0, 2.0)), (lower, right, Vec2::new(2.0, 1.0))]
    }

    const SHARED: &str = "a point of a shared edge belongs to exactly one of the two polygons: a vertex at \
        p's height counts as above, and the crossing must be strictly right of p";

    pub(super) fn crossings_cases(inside: InsideFn) -> CheckResult {
        let table = polygon_table();
        for (poly, p, winding, cause) in &table {
            let expected = winding % 2 != 0;
            let got = inside(poly, *p);
            let case = format!("inside_crossings(polygon {}, p = {})", show_polygon(poly), show2(*p));
            let cause = if *winding == 2 {
                "even–odd: the pentagram's centre is crossed twice, so it is outside (a hole)"
            } else {
                cause
            };
            ensure(got == expected, case, expected, got, cause)?;
        }
        for (a, b, p) in shared_edges() {
            let (in_a, in_b) = (inside(&a, p), inside(&b, p));
            let case = format!(
                "p = {} on the edge shared by {} and {}",
                show2(p),
                show_polygon(&a),
                show_polygon(&b)
            );
            ensure(in_a != in_b, case, "inside exactly one", format!("{in_a} and {in_b}"), SHARED)?;
        }
        Ok(format!("{} points and 2 shared edges", table.len()))
    }

    pub(super) fn winding_cases(winding_number: WindingFn) -> CheckResult {
        let table = polygon_table();
        for (poly, p, expected, cause) in &table {
            let got = winding_number(poly, *p);
            let case = format!("winding_number(polygon {}, p = {})", show_polygon(poly), show2(*p));
            let cause = if got == -expected && *expected != 0 {
                "counter-clockwise is positive: an upward crossing right of p counts +1, a downward one −1"
            } else if *expected == 2 || *expected == -2 {
                "count signed crossings, +1 upward and −1 downward (not a parity): the pentagram's centre \
                    winds twice"
            } else {
                cause
            };
            ensure(got == *expected, case, expected, got, cause)?;
        }
        for (a, b, p) in shared_edges() {
            let sum = winding_number(&a, p) + winding_number(&b, p);
            let case = format!(
                "p = {} on the edge shared by {} and {}",
                show2(p),
                show_polygon(&a),
                show_polygon(&b)
            );
            ensure(sum == 1, case, "windings summing to 1", sum, SHARED)?;
        }
        Ok(format!("{} points and 2 shared edges", table.len()))
    }

    /// The square [0, 2]² placed with `axis` as its normal axis at coordinate 1,
    /// counter-clockwise seen from +axis.
    fn square_in_plane(axis: usize) -> Vec<Vec3> {
        square()
            .iter()
            .map(|v| {
                let mut p = Vec3::ZERO;
                p[axis] = 1.0;
                p[(axis + 1) % 3] = v.x;
                p[(axis + 2) % 3] = v.y;
                p
            })
            .collect()
    }

    pub(super) fn newell_cases(newell: NewellFn) -> CheckResult {
        let at_z5: Vec<Vec3> = square().iter().map(|v| v.extend(5.0)).collect();
        let cw: Vec<Vec3> = at_z5.iter().rev().copied().collect();
        let cases = [
            // Area 4, counter-clockwise from +z: (0, 0, 8).
            (at_z5, Vec3::new(0.0, 0.0, 8.0)),
            (cw, Vec3::new(0.0, 0.0, -8.0)),
            // The same square in the plane x = 1: (8, 0, 0).
            (square_in_plane(0), Vec3::new(8.0, 0.0, 0.0)),
            // (b − a) × (c − a) = (−1, 1, 0) × (−1, 0, 1) = (1, 1, 1): twice the area along the normal.
            (vec![Vec3::X, Vec3::Y, Vec3::Z], Vec3::ONE),
            // Collinear: no plane.
            (vec![Vec3::ZERO, Vec3::X, 2.0 * Vec3::X], Vec3::ZERO),
        ];
        for (poly, expected) in cases {
            let got = newell(&poly);
            let points: Vec<String> = poly.iter().map(|&p| vec3(p)).collect();
            let case = format!("newell_normal([{}])", points.join(", "));
            let cause = if expected != Vec3::ZERO && near3(got, -expected, TOL) {
                "the sign: nₓ = Σ (yᵢ − yⱼ)(zᵢ + zⱼ) with j = i + 1, so n points to the side from which the \
                    vertices run counter-clockwise"
            } else if expected != Vec3::ZERO && near3(got, expected.normalize(), TOL) {
                "do not normalise: |n| is twice the area (hit_polygon normalises)"
            } else {
                "sum over every edge i → j = i + 1, the last vertex joining the first: nₓ = Σ (yᵢ − yⱼ)(zᵢ \
                    + zⱼ), n_y = Σ (zᵢ − zⱼ)(xᵢ + xⱼ), n_z = Σ (xᵢ − xⱼ)(yᵢ + yⱼ)"
            };
            close3(&case, got, expected, TOL * 8.0, cause)?;
        }
        Ok("5 polygons".into())
    }

    pub(super) fn polygon_cases(hit_polygon: PolygonFn) -> CheckResult {
        for axis in 0..3 {
            let quad = square_in_plane(axis);
            let mut normal = Vec3::ZERO;
            normal[axis] = 1.0;
            let at = |u: Float, v: Float| {
                let mut p = normal;
                p[(axis + 1) % 3] = u;
                p[(axis + 2) % 3] = v;
                p
            };
            let plane = ["x", "y", "z"][axis];
            // From 4 units in front, oblique, toward (0.5, 1.5) of the square: t = 1.
            let target = at(0.5, 1.5);
            let slant = 0.5 * at(0.3, -0.2);
            let r = Ray::new(target + 4.0 * normal + slant, -4.0 * normal - slant);
            let case = format!("the square [0, 2]² in the plane {plane} = 1, {}", show_ray(&r));
            let got = hit_polygon(&r, &quad, ALL);
            let Some(h) = got else {
                let cause = if axis < 2 {
                    "project by dropping the coordinate of the normal's dominant axis: dropping z always \
                        flattens a polygon in a vertical plane to a segment"
                } else {
                    "hit the plane n·p = n·v₀ (n = Newell's normal, normalised), then test the point inside \
                        the projected polygon"
                };
                return Err(fail(case, "t = 1", show_hit(&got), cause));
            };
            close(&case, h.t, 1.0, TOL, "t = (n·v₀ − n·o)/(n·d)")?;
            close3(
                &case,
                h.normal,
                normal,
                TOL,
                "the outward normal is Newell's n normalised (the side from which the vertices run \
                    counter-clockwise), faced by Hit::new",
            )?;
            ensure(
                h.front_face,
                &case,
                "front_face true",
                "false",
                "the ray comes from the counter-clockwise side: the front",
            )?;
            // From behind: t = 2, the normal turned toward the ray.
            let r = Ray::new(at(1.0, 1.0) - 2.0 * normal, normal);
            let case = format!("the square [0, 2]² in the plane {plane} = 1, {} (from behind)", show_ray(&r));
            let got = hit_polygon(&r, &quad, ALL);
            let Some(h) = got else {
                return Err(fail(
                    case,
                    "t = 2",
                    show_hit(&got),
                    "a polygon is two-sided: it is hit from behind too",
                ));
            };
            close(&case, h.t, 2.0, TOL, "t = (n·v₀ − n·o)/(n·d)")?;
            close3(
                &case,
                h.normal,
                -normal,
                TOL,
                "from behind the normal faces the ray: build the hit with Hit::new(ray, t, n)",
            )?;
            // Beside the square: the projected point (2.5, 1) is outside.
            let r = Ray::new(at(2.5, 1.0) + normal, -normal);
            let got = hit_polygon(&r, &quad, ALL);
            let case = format!("the square [0, 2]² in the plane {plane} = 1, {} (beside it)", show_ray(&r));
            ensure(
                got.is_none(),
                case,
                "None",
                show_hit(&got),
                "the plane's hit point must be inside the polygon (inside_crossings of the projection)",
            )?;
        }
        // A tilted quad (normal (1, 1, 0)/√2, x and y tie): the ray (t, t, 0.5) meets x + y = 1 at t = ½.
        let tilted = [
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(0.0, 1.0, 1.0),
            Vec3::new(1.0, 0.0, 1.0),
        ];
        let r = ray([0.0, 0.0, 0.5], [1.0, 1.0, 0.0]);
        let got = hit_polygon(&r, &tilted, ALL);
        let case = format!("the tilted quad x + y = 1, 0 ≤ z ≤ 1, {}", show_ray(&r));
        close(
            &case,
            got.map_or(Float::NAN, |h| h.t),
            0.5,
            TOL,
            "any dominant axis of the normal works; t = (n·v₀ − n·o)/(n·d)",
        )?;
        // The pentagram at z = −2 seen from above: the centre is a hole (even–odd), a tip is hit.
        let star: Vec<Vec3> = pentagram().iter().map(|v| v.extend(-2.0)).collect();
        let centre = ray([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
        let got = hit_polygon(&centre, &star, ALL);
        ensure(
            got.is_none(),
            "the pentagram at z = −2, ray from the origin along −z (through its centre)",
            "None (a hole)",
            show_hit(&got),
            "hit_polygon follows the even–odd rule (inside_crossings): the pentagram's centre is a hole",
        )?;
        let tip = ray([0.0, 0.8, 0.0], [0.0, 0.0, -1.0]);
        let got = hit_polygon(&tip, &star, ALL);
        close(
            "the pentagram at z = −2, ray from (0, 0.8, 0) along −z (a tip)",
            got.map_or(Float::NAN, |h| h.t),
            2.0,
            TOL,
            "a tip of the pentagram is inside",
        )?;
        // Degenerate polygons and a parallel ray: None, never a panic.
        let down = ray([0.5, 0.5, 1.0], [0.0, 0.0, -1.0]);
        for (poly, why) in [
            (vec![], "no vertices: return None"),
            (vec![Vec3::ZERO, Vec3::X], "fewer than three vertices: return None"),
            (
                vec![Vec3::ZERO, Vec3::X, 2.0 * Vec3::X],
                "collinear vertices have a zero Newell normal: return None (do not normalise zero)",
            ),
        ] {
            let got = hit_polygon(&down, &poly, ALL);
            let case = format!("a degenerate polygon with {} vertices, {}", poly.len(), show_ray(&down));
            ensure(got.is_none(), case, "None", show_hit(&got), why)?;
        }
        let along = ray([-1.0, 1.0, 1.0], [1.0, 0.0, 0.0]);
        let got = hit_polygon(&along, &square_in_plane(2), ALL);
        ensure(
            got.is_none(),
            "the square in the plane z = 1, ray within that plane",
            "None",
            show_hit(&got),
            "n·d = 0: a ray parallel to the plane has no hit",
        )?;
        Ok("3 axis planes × 3 rays, a tilted quad, the pentagram, 4 degenerate cases".into())
    }

    // ---- triangles -------------------------------------------------------------

    /// The right triangle a = 0, b = x̂, c = ŷ in the plane z = 0 (front +z).
    const A: Vec3 = Vec3::ZERO;
    const B: Vec3 = Vec3::X;
    const C: Vec3 = Vec3::Y;

    fn show_tri(h: &Option<TriangleHit>) -> String {
        maybe(h, |h| format!("t = {}, β = {}, γ = {}", num(h.t), num(h.beta), num(h.gamma)))
    }

    /// Expects a hit (t, β, γ) within `tol`, naming swapped barycentrics.
    fn expect_tri(
        case: &str,
        got: Option<TriangleHit>,
        t: Float,
        beta: Float,
        gamma: Float,
        tol: Float,
        cause: &str,
    ) -> Result<(), Failure> {
        let expected = format!("t = {}, β = {}, γ = {} (± {tol:.1e})", num(t), num(beta), num(gamma));
        let Some(h) = got else { return Err(fail(case, expected, "None (no hit)", cause)) };
        let ok = (h.t - t).abs() <= tol && (h.beta - beta).abs() <= tol && (h.gamma - gamma).abs() <= tol;
        let cause = if (h.beta - gamma).abs() <= tol && (h.gamma - beta).abs() <= tol && beta != gamma {
            "β weights b and γ weights c: p = (1 − β − γ)a + βb + γc"
        } else if (h.t - t).abs() > tol {
            "t solves o + t·d = (1 − β − γ)a + βb + γc, in units of dir"
        } else {
            cause
        };
        ensure(ok, case, expected, show_tri(&got), cause)
    }

    pub(super) fn triangle_cases(method: TriangleFn) -> CheckResult {
        let down = |x: Float, y: Float| ray([x, y, 2.0], [0.0, 0.0, -1.0]);
        // Vertical rays onto z = 0 are exact: t = 2 and (β, γ) = (x, y), as p = β·x̂ + γ·ŷ.
        for (x, y, cause) in [
            (0.25, 0.5, "solve o + t·d = (1 − β − γ)a + βb + γc for (t, β, γ)"),
            (0.0, 0.0, "the vertices belong to the triangle: accept β ≥ 0, γ ≥ 0 (not > 0)"),
            (1.0, 0.0, "the edges belong to the triangle: accept β + γ ≤ 1 (not < 1)"),
            (0.0, 1.0, "the edges belong to the triangle: accept β + γ ≤ 1 (not < 1)"),
            (0.5, 0.0, "the edges belong to the triangle: accept γ = 0"),
        ] {
            let r = down(x, y);
            let case = format!("triangle (0, 0, 0), (1, 0, 0), (0, 1, 0), {}", show_ray(&r));
            expect_tri(&case, method(&r, A, B, C, ALL), 2.0, x, y, TOL, cause)?;
        }
        // A general triangle, a ray from an oblique origin through its centroid: β = γ = ⅓, t = 1.
        let (a, b, c) = (Vec3::new(1.0, -2.0, 0.5), Vec3::new(3.0, 1.0, -1.0), Vec3::new(-1.0, 2.0, 2.0));
        let origin = Vec3::new(-3.0, 4.0, 5.0);
        let r = Ray::new(origin, (a + b + c) / 3.0 - origin);
        let case = format!(
            "triangle {}, {}, {}, {} (through the centroid)",
            vec3(a),
            vec3(b),
            vec3(c),
            show_ray(&r)
        );
        expect_tri(
            &case,
            method(&r, a, b, c, ALL),
            1.0,
            1.0 / 3.0,
            1.0 / 3.0,
            TOL,
            "solve the 3×3 system for (t, β, γ)",
        )?;
        // From behind: the same t and barycentrics (two-sided).
        let up = ray([0.25, 0.25, -2.0], [0.0, 0.0, 1.0]);
        let case = format!("triangle (0, 0, 0), (1, 0, 0), (0, 1, 0), {} (from behind)", show_ray(&up));
        expect_tri(
            &case,
            method(&up, A, B, C, ALL),
            2.0,
            0.25,
            0.25,
            TOL,
            "the test is two-sided: a ray from behind (a negative determinant) hits too",
        )?;
        // Non-unit direction: t in units of dir, 2/4.
        let fast = ray([0.25, 0.25, 2.0], [0.0, 0.0, -4.0]);
        let case = format!("triangle (0, 0, 0), (1, 0, 0), (0, 1, 0), {}", show_ray(&fast));
        expect_tri(
            &case,
            method(&fast, A, B, C, ALL),
            0.5,
            0.25,
            0.25,
            TOL,
            "t is in units of dir: do not normalise it",
        )?;
        // Misses: outside each edge, beyond the range, behind the origin.
        for (r, range, why) in [
            (down(0.6, 0.6), ALL, "β + γ = 1.2 > 1: outside"),
            (down(-0.1, 0.5), ALL, "β = −0.1 < 0: outside"),
            (down(0.5, -0.1), ALL, "γ = −0.1 < 0: outside"),
            (down(0.2, 0.2), Interval::new(0.0, 1.5), "t = 2 is beyond range.max = 1.5"),
            (ray([0.2, 0.2, -2.0], [0.0, 0.0, -1.0]), ALL, "t = −2 is behind the origin: outside the range"),
        ] {
            let got = method(&r, A, B, C, range);
            let case = format!(
                "triangle (0, 0, 0), (1, 0, 0), (0, 1, 0), {}, range ({}, {})",
                show_ray(&r),
                num(range.min),
                num(range.max)
            );
            ensure(got.is_none(), case, "None", show_tri(&got), why)?;
        }
        // Parallel rays (in the plane and above it) and a degenerate triangle: None.
        for z in [0.0, 1.0] {
            for d in [[1.0, 0.5, 0.0], [0.0, -1.0, 0.0], [-0.3, 0.7, 0.0]] {
                let r = ray([-1.0, 0.25, z], d);
                let got = method(&r, A, B, C, ALL);
                let case = format!(
                    "triangle (0, 0, 0), (1, 0, 0), (0, 1, 0), {} (parallel to its plane)",
                    show_ray(&r)
                );
                ensure(
                    got.is_none(),
                    case,
                    "None",
                    show_tri(&got),
                    "a ray parallel to the plane (determinant 0) has no hit: return None, never divide by \
                        zero",
                )?;
            }
        }
        let r = down(0.5, 0.0);
        let got = method(&r, A, B, 2.0 * B, ALL);
        ensure(
            got.is_none(),
            format!("degenerate triangle (0, 0, 0), (1, 0, 0), (2, 0, 0), {}", show_ray(&r)),
            "None",
            show_tri(&got),
            "a degenerate triangle has no plane: return None",
        )?;
        Ok("7 hits, 5 misses, 6 parallel rays, a degenerate triangle".into())
    }

    pub(super) fn edge_cases(edge: EdgeFn) -> CheckResult {
        // e = p.x·q.y − p.y·q.x: (1, 2)·(3, 4) → 1·4 − 2·3 = −2; z plays no part.
        let (p, q) = (Vec3::new(1.0, 2.0, 5.0), Vec3::new(3.0, 4.0, -1.0));
        let got = edge(p, q);
        let cause = if got == 2.0 {
            "e = p.x·q.y − p.y·q.x (positive when the ray passes left of p→q), not the other way round"
        } else {
            "e = p.x·q.y − p.y·q.x: the z components play no part"
        };
        close("edge_function((1, 2, 5), (3, 4, −1))", got, -2.0, 0.0, cause)?;
        // Exactly antisymmetric on arbitrary values.
        let mut rng = Rng::new(17);
        for _ in 0..200 {
            let (p, q) = (rng.in_cube(3.0), rng.in_cube(3.0));
            let (pq, qp) = (edge(p, q), edge(q, p));
            let case = format!("edge_function({}, {}) and with p, q swapped", vec3(p), vec3(q));
            ensure(
                pq == -qp,
                case,
                "e(q, p) = −e(p, q) exactly",
                format!("{} and {}", num(pq), num(qp)),
                "e must be exactly antisymmetric: compute e(q, p) from the same two products, subtracted \
                    the other way",
            )?;
        }
        // p.x·q.y = (1 + 2⁻¹²)² = 1 + 2⁻¹¹ + 2⁻²⁴ and p.y·q.x = 1 + 2⁻¹¹: exactly 2⁻²⁴. In f32 both
        // products round to 1 + 2⁻¹¹ (ties to even), so the plain difference is 0.
        let s: Float = 1.0 + (2.0 as Float).powi(-12);
        let (p, q) = (Vec3::new(s, 1.0 + (2.0 as Float).powi(-11), 0.0), Vec3::new(1.0, s, 0.0));
        let tiny = (2.0 as Float).powi(-24);
        let case = "edge_function((1 + 2⁻¹², 1 + 2⁻¹¹, 0), (1, 1 + 2⁻¹², 0)): exactly 2⁻²⁴";
        close(
            case,
            edge(p, q),
            tiny,
            0.0,
            "when the f32 difference rounds to exactly 0, recompute it in f64 (where both products are \
                exact) so the sign of a zero is decided exactly",
        )?;
        close(
            case,
            edge(q, p),
            -tiny,
            0.0,
            "when the f32 difference rounds to exactly 0, recompute it in f64 (where both products are \
                exact) so the sign of a zero is decided exactly",
        )?;
        Ok("a hand value, 200 antisymmetric pairs, a rounding tie".into())
    }

    /// The octahedron |x| + |y| + |z| = 1 with its vertices moved a little at
    /// random: 8 faces wound counter-clockwise from outside, every edge shared.
    fn wobbly_octahedron(rng: &mut Rng) -> Mesh {
        let axes = [Vec3::X, -Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z];
        let positions = axes.iter().map(|&v| v * rng.range(0.8, 1.2) + rng.in_cube(0.1)).collect();
        let mut triangles = Vec::new();
        for (sx, sy, sz) in
            [(0, 2, 4), (1, 2, 4), (0, 3, 4), (1, 3, 4), (0, 2, 5), (1, 2, 5), (0, 3, 5), (1, 3, 5)]
        {
            let flips = (sx % 2) + (sy % 2) + (sz % 2);
            triangles.push(if flips % 2 == 0 { [sx, sy, sz] } else { [sx, sz, sy] });
        }
        Mesh { positions, triangles, ..Mesh::default() }
    }

    /// Closed meshes with an origin inside, and the rays from it aimed exactly
    /// at every vertex and at three points of every edge.
    fn leak_tests() -> Vec<(Mesh, Vec<Ray>)> {
        let mut rng = Rng::new(5);
        let mut meshes: Vec<(Mesh, Vec3)> =
            (0..60).map(|_| (wobbly_octahedron(&mut rng), rng.in_cube(0.05))).collect();
        meshes.push((Mesh::icosphere(2), Vec3::ZERO));
        meshes.push((Mesh::icosphere(2), Vec3::new(0.1, -0.2, 0.05)));
        meshes
            .into_iter()
            .map(|(mesh, origin)| {
                let mut rays: Vec<Ray> =
                    mesh.positions.iter().map(|&p| Ray::new(origin, p - origin)).collect();
                for tri in &mesh.triangles {
                    for k in 0..3 {
                        let (i, j) = (tri[k], tri[(k + 1) % 3]);
                        if i < j {
                            let (p, q) = (mesh.positions[i as usize], mesh.positions[j as usize]);
                            for s in [0.5, 0.1, 0.7] {
                                rays.push(Ray::new(origin, p.lerp(q, s) - origin));
                            }
                        }
                    }
                }
                (mesh, rays)
            })
            .collect()
    }

    const LEAK: &str = "a ray aimed exactly at a shared edge or vertex slipped between the triangles: \
        accept zero edge functions (all ≥ 0 or all ≤ 0), computed by edge_function from the translated, \
        permuted and sheared vertices, so neighbours see the ray on opposite sides of their edge";

    pub(super) fn triangle_no_leaks(method: TriangleFn) -> CheckResult {
        let mut total = 0;
        for (mesh, rays) in leak_tests() {
            for r in &rays {
                total += 1;
                let hit = (0..mesh.triangles.len()).any(|i| {
                    let [a, b, c] = mesh.triangle(i);
                    method(r, a, b, c, ALL).is_some()
                });
                if !hit {
                    let case = format!(
                        "a closed mesh of {} triangles around the origin, {} (aimed at a vertex or an edge)",
                        mesh.triangles.len(),
                        show_ray(r)
                    );
                    return Err(fail(case, "a hit on some triangle", "no triangle hit", LEAK));
                }
            }
        }
        Ok(format!("{total} edge and vertex rays, no leak"))
    }

    pub(super) fn mesh_no_leaks(hit_mesh: MeshFn) -> CheckResult {
        let mut total = 0;
        for (mesh, rays) in leak_tests() {
            for r in &rays {
                total += 1;
                let got = hit_mesh(r, &mesh, ALL);
                let case = format!(
                    "a closed mesh of {} triangles around the origin, {} (aimed at a vertex or an edge)",
                    mesh.triangles.len(),
                    show_ray(r)
                );
                let Some(h) = got else { return Err(fail(case, "a hit", "None (no hit)", LEAK)) };
                ensure(
                    h.t.is_finite() && h.t > 0.0 && h.normal.is_finite(),
                    case,
                    "a finite hit",
                    show_hit(&got),
                    "no NaN may escape a hit",
                )?;
            }
        }
        Ok(format!("{total} edge and vertex rays, no leak"))
    }

    // ---- normals, hit records, meshes ---------------------------------------------

    pub(super) fn interpolate_cases(interpolate: InterpolateFn) -> CheckResult {
        let normals = [Vec3::new(1.0, 0.0, 1.0), Vec3::new(0.0, 2.0, 2.0), Vec3::Z];
        let show_normals = "normals (1, 0, 1), (0, 2, 2), (0, 0, 1)";
        // At a vertex the blend is that vertex's normal, normalised.
        for (k, (beta, gamma)) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)].into_iter().enumerate() {
            let got = interpolate(&normals, beta, gamma);
            let case = format!("interpolate_normal({show_normals}, β = {beta}, γ = {gamma})");
            let others: Vec<Vec3> = (0..3).filter(|&j| j != k).map(|j| normals[j].normalize()).collect();
            let cause = if others.iter().any(|&n| near3(got, n, TOL)) {
                "n₀ takes the weight 1 − β − γ, n₁ takes β and n₂ takes γ"
            } else if near3(got, normals[k], TOL) && normals[k].length() != 1.0 {
                "normalise the blend"
            } else {
                "(1 − β − γ)n₀ + βn₁ + γn₂, normalised"
            };
            close3(&case, got, normals[k].normalize(), TOL, cause)?;
        }
        // Midpoint of the first edge: (1, 0, 1)/2 + (0, 2, 2)/2 = (0.5, 1, 1.5), over √3.5.
        let got = interpolate(&normals, 0.5, 0.0);
        let expected = Vec3::new(0.5, 1.0, 1.5) / (3.5 as Float).sqrt();
        let cause = if near3(got, Vec3::new(0.5, 1.0, 1.5), TOL) {
            "normalise the blend"
        } else {
            "(1 − β − γ)n₀ + βn₁ + γn₂, normalised"
        };
        close3(format!("interpolate_normal({show_normals}, β = 0.5, γ = 0)"), got, expected, TOL, cause)?;
        // Opposite normals cancel: zero, not NaN.
        let got = interpolate(&[Vec3::Z, -Vec3::Z, Vec3::Z], 0.5, 0.0);
        close3(
            "interpolate_normal(normals +z, −z, +z, β = 0.5, γ = 0): the blend cancels",
            got,
            Vec3::ZERO,
            0.0,
            "where the blend is zero return the zero vector (normalize_or_zero), never NaN",
        )?;
        Ok("3 vertices, a midpoint, a cancelling blend".into())
    }

    pub(super) fn hit_triangle_cases(hit_triangle: HitTriangleFn) -> CheckResult {
        let tri = [A, B, C];
        let name = "triangle (0, 0, 0), (1, 0, 0), (0, 1, 0)";
        // From above at (0.25, 0.25): t = 2, normal +z (front), uv = (β, γ) = (0.25, 0.25).
        let down = ray([0.25, 0.25, 2.0], [0.0, 0.0, -1.0]);
        let case = format!("{name}, {}", show_ray(&down));
        let got = hit_triangle(&down, &tri, None, ALL);
        let Some(h) = got else {
            return Err(fail(case, "t = 2", show_hit(&got), "the watertight test finds this hit"));
        };
        close(&case, h.t, 2.0, TOL, "t of the watertight test")?;
        close3(&case, h.point, Vec3::new(0.25, 0.25, 0.0), TOL, "the point is ray.at(t)")?;
        let cause = if !h.front_face {
            "the outward normal is (b − a) × (c − a): the front is the side from which a, b, c run \
                counter-clockwise"
        } else {
            "the geometric normal (b − a) × (c − a), normalised and faced by Hit::new"
        };
        close3(&case, h.normal, Vec3::Z, TOL, cause)?;
        ensure(h.front_face, &case, "front_face true", "false", cause)?;
        let uv = Vec3::new(h.uv.x, h.uv.y, 0.0);
        close3(&case, uv, Vec3::new(0.25, 0.25, 0.0), TOL, "uv = (β, γ) of the triangle hit (Hit::with_uv)")?;
        // From below: the normal turned toward the ray, front_face false.
        let up = ray([0.25, 0.25, -2.0], [0.0, 0.0, 1.0]);
        let case = format!("{name}, {} (from behind)", show_ray(&up));
        let got = hit_triangle(&up, &tri, None, ALL);
        let Some(h) = got else { return Err(fail(case, "t = 2", show_hit(&got), "the test is two-sided")) };
        close3(
            &case,
            h.normal,
            -Vec3::Z,
            TOL,
            "from behind the normal faces the ray: build the hit with Hit::new(ray, t, (b − a) × (c − a))",
        )?;
        ensure(!h.front_face, &case, "front_face false", "true", "from behind the ray meets the back face")?;
        // Vertex normals tilted from +z: the blend 0.5n₀ + 0.25n₁ + 0.25n₂ = (0.25, 0.25, 1), normalised.
        let normals = [Vec3::Z, Vec3::new(1.0, 0.0, 1.0), Vec3::new(0.0, 1.0, 1.0)];
        let blended = Vec3::new(0.25, 0.25, 1.0).normalize();
        let case = format!("{name} with vertex normals (0, 0, 1), (1, 0, 1), (0, 1, 1), {}", show_ray(&down));
        let got = hit_triangle(&down, &tri, Some(&normals), ALL);
        close3(
            &case,
            got.map_or(Vec3::NAN, |h| h.normal),
            blended,
            TOL,
            "with vertex normals the hit's normal is interpolate_normal at (β, γ)",
        )?;
        let case = format!(
            "{name} with vertex normals (0, 0, 1), (1, 0, 1), (0, 1, 1), {} (from behind)",
            show_ray(&up)
        );
        let got = hit_triangle(&up, &tri, Some(&normals), ALL);
        let n = got.map_or(Vec3::NAN, |h| h.normal);
        let cause = if near3(n, blended, TOL) {
            "turn the interpolated normal to the side of the geometric normal that faces the ray"
        } else {
            "the interpolated normal, turned toward the ray"
        };
        close3(&case, n, -blended, TOL, cause)?;
        // Cancelling vertex normals: the geometric normal stays.
        let cancel = [Vec3::Z, -Vec3::Z, Vec3::Z];
        let r = ray([0.5, 0.0, 2.0], [0.0, 0.0, -1.0]);
        let case =
            format!("{name} with vertex normals +z, −z, +z, {} (the blend cancels at β = 0.5)", show_ray(&r));
        let got = hit_triangle(&r, &tri, Some(&cancel), ALL);
        close3(
            &case,
            got.map_or(Vec3::NAN, |h| h.normal),
            Vec3::Z,
            TOL,
            "where the blend vanishes keep the geometric normal (never a zero or NaN normal)",
        )?;
        // A miss.
        let r = ray([0.6, 0.6, 2.0], [0.0, 0.0, -1.0]);
        let got = hit_triangle(&r, &tri, None, ALL);
        ensure(
            got.is_none(),
            format!("{name}, {}", show_ray(&r)),
            "None",
            show_hit(&got),
            "β + γ = 1.2 > 1: no hit",
        )?;
        Ok("front, back, shading normals both ways, a cancelling blend, a miss".into())
    }

    /// The unit square in z = 0 as triangles (0, 1, 2) and (0, 2, 3), counter-clockwise from +z.
    fn quad() -> Mesh {
        Mesh {
            positions: vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y],
            triangles: vec![[0, 1, 2], [0, 2, 3]],
            ..Mesh::default()
        }
    }

    pub(super) fn mesh_cases(hit_mesh: MeshFn) -> CheckResult {
        let down = |x: Float, y: Float| ray([x, y, 2.0], [0.0, 0.0, -1.0]);
        let mesh = quad();
        let name = "the unit square as triangles (0, 1, 2), (0, 2, 3)";
        // (0.75, 0.25) is in (0, x̂, x̂ + ŷ): p = (β + γ, γ), so β = 0.5, γ = 0.25.
        for (x, y, uv) in [(0.75, 0.25, Vec2::new(0.5, 0.25)), (0.25, 0.75, Vec2::new(0.25, 0.5))] {
            let r = down(x, y);
            let case = format!("{name}, {}", show_ray(&r));
            let got = hit_mesh(&r, &mesh, ALL);
            let Some(h) = got else {
                return Err(fail(case, "t = 2", show_hit(&got), "test every triangle with hit_triangle"));
            };
            close(&case, h.t, 2.0, TOL, "the triangle's t")?;
            close3(
                &case,
                h.normal,
                Vec3::Z,
                TOL,
                "a mesh without normals keeps the triangle's geometric normal",
            )?;
            close3(
                &case,
                Vec3::new(h.uv.x, h.uv.y, 0.0),
                uv.extend(0.0),
                TOL,
                "without mesh uvs the hit's uv is the triangle's (β, γ)",
            )?;
        }
        for (r, m, why) in [
            (down(1.5, 0.5), quad(), "beside the square: no hit"),
            (down(0.5, 0.5), Mesh::default(), "an empty mesh is never hit"),
        ] {
            let got = hit_mesh(&r, &m, ALL);
            ensure(got.is_none(), format!("{name}, {}", show_ray(&r)), "None", show_hit(&got), why)?;
        }
        // Two layers, z = 0 and z = −1, in both orders: the nearer one (t = 2 from above) wins.
        let near_layer = quad();
        for far_first in [true, false] {
            let far: Vec<Vec3> = near_layer.positions.iter().map(|p| *p - Vec3::Z).collect();
            let (first, second) = if far_first {
                (far, near_layer.positions.clone())
            } else {
                (near_layer.positions.clone(), far)
            };
            let layers = Mesh {
                positions: first.into_iter().chain(second).collect(),
                triangles: vec![[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7]],
                ..Mesh::default()
            };
            let r = down(0.3, 0.6);
            let order = if far_first { "the far layer listed first" } else { "the near layer listed first" };
            let case = format!("squares at z = 0 and z = −1 ({order}), {}", show_ray(&r));
            let got = hit_mesh(&r, &layers, ALL);
            close(
                &case,
                got.map_or(Float::NAN, |h| h.t),
                2.0,
                TOL,
                "keep the closest hit: shrink range.max to each hit's t and test every triangle",
            )?;
        }
        // Mesh uvs 2·(x, y) + (1, 3) (no corner's uv is zero, so each corner's weight shows) and
        // normals (x, 0, 1)/|…| per vertex, interpolated at (0.75, 0.25).
        let mut textured = quad();
        textured.uvs = textured.positions.iter().map(|p| 2.0 * p.truncate() + Vec2::new(1.0, 3.0)).collect();
        textured.normals = textured.positions.iter().map(|p| Vec3::new(p.x, 0.0, 1.0).normalize()).collect();
        let r = down(0.75, 0.25);
        let case =
            format!("{name} with uvs 2·(x, y) + (1, 3) and normals (x, 0, 1) normalised, {}", show_ray(&r));
        let got = hit_mesh(&r, &textured, ALL);
        let Some(h) = got else { return Err(fail(case, "a hit", show_hit(&got), "test every triangle")) };
        // Weights (1 − β − γ, β, γ) = (0.25, 0.5, 0.25) of uv_a = (1, 3), uv_b = (3, 3), uv_c = (3, 5):
        // uv = (0.25 + 1.5 + 0.75, 0.75 + 1.5 + 1.25) = (2.5, 3.5).
        close3(
            format!("{case}: the hit's uv"),
            Vec3::new(h.uv.x, h.uv.y, 0.0),
            Vec3::new(2.5, 3.5, 0.0),
            TOL,
            "with mesh uvs, uv = (1 − β − γ)uv_a + β·uv_b + γ·uv_c",
        )?;
        // Normal: 0.25·ẑ + 0.75·(1, 0, 1)/√2, normalised.
        let expected = (0.25 * Vec3::Z + 0.75 * Vec3::new(1.0, 0.0, 1.0).normalize()).normalize();
        close3(
            &case,
            h.normal,
            expected,
            TOL,
            "with mesh normals, pass the triangle's three vertex normals to hit_triangle",
        )?;
        Ok("2 hits, 2 misses, layers in both orders, mesh uvs and normals".into())
    }
}

#[cfg(all(test, feature = "l03"))]
#[allow(clippy::result_large_err)]
mod tests {
    //! The checks pass on the reference, and planted mistakes (the catalogue's
    //! and a few more) fail them with the intended cause.

    use crate::check::testing::caught;

    use std::cell::Cell;

    pub(super) use l03_polygons_triangles::{
        TriangleHit, dominant_axis, edge_function, hit_slabs, hit_triangle, hit_triangle_moller_trumbore,
        hit_triangle_watertight, inside_crossings, interpolate_normal, newell_normal, winding_number,
    };
    use raylab::math::gamma;
    use raylab::scene::Mesh;
    use raylab::{Float, Hit, Interval, Ray, Vec2, Vec3};

    use super::code::*;

    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }

    /// The slab method with switches for the classic mistakes.
    #[derive(Clone, Copy, Default)]
    struct Slabs {
        order_by_t: bool,
        no_swap: bool,
        no_widen: bool,
        strict: bool,
        no_clip: bool,
    }

    thread_local! {
        static SLABS: Cell<Slabs> = Cell::new(Slabs::default());
    }

    fn planted_slabs(ray: &Ray, min: Vec3, max: Vec3, range: Interval) -> Option<(Float, Float)> {
        let m = SLABS.with(Cell::get);
        let widen = if m.no_widen { 0.0 } else { 2.0 * gamma(3) };
        let (mut t_enter, mut t_exit) = (Float::NEG_INFINITY, Float::INFINITY);
        for axis in 0..3 {
            let inv = 1.0 / ray.dir[axis];
            let t0 = (min[axis] - ray.origin[axis]) * inv;
            let t1 = (max[axis] - ray.origin[axis]) * inv;
            let (mut near, mut far) = if m.no_swap {
                (t0, t1)
            } else if m.order_by_t {
                if t0 <= t1 { (t0, t1) } else { (t1, t0) }
            } else if inv >= 0.0 {
                (t0, t1)
            } else {
                (t1, t0)
            };
            if near.is_nan() {
                near = Float::NEG_INFINITY;
            }
            if far.is_nan() {
                far = Float::INFINITY;
            }
            far *= if far >= 0.0 { 1.0 + widen } else { 1.0 - widen };
            t_enter = t_enter.max(near);
            t_exit = t_exit.min(far);
        }
        let ordered = if m.strict { t_enter < t_exit } else { t_enter <= t_exit };
        if !(ordered && t_enter < range.max && t_exit > range.min) {
            return None;
        }
        if m.no_clip {
            Some((t_enter, t_exit))
        } else {
            Some((t_enter.max(range.min), t_exit.min(range.max)))
        }
    }

    fn slabs(m: Slabs) -> SlabsFn {
        SLABS.with(|s| s.set(m));
        planted_slabs
    }

    #[test]
    fn slabs_mistakes() {
        let none = Slabs::default();
        assert!(slabs_cases(slabs(none)).is_ok() && slabs_extreme(slabs(none)).is_ok());
        caught(slabs_cases(slabs(Slabs { no_swap: true, ..none })), "swap");
        caught(slabs_cases(slabs(Slabs { no_clip: true, ..none })), "clip");
        caught(slabs_cases(slabs(Slabs { strict: true, no_widen: true, ..none })), "t_enter ≤ t_exit");
        caught(slabs_extreme(slabs(Slabs { order_by_t: true, ..none })), "0·∞ = NaN");
    }

    #[test]
    fn slabs_without_widening() {
        // Without the 2γ₃ widening, a ray aimed exactly at an edge can miss by an ulp.
        // Measured: caught in both precisions (a ray aimed at an edge on the 1/16 grid).
        caught(slabs_extreme(slabs(Slabs { no_widen: true, ..Slabs::default() })), "widen");
    }

    /// hit_box from hit_slabs with a planted mistake: `inside_t0` reports t0 when
    /// starting inside; `raw_normal` keeps the outward normal unfaced.
    fn planted_box(
        ray: &Ray,
        min: Vec3,
        max: Vec3,
        range: Interval,
        inside_t0: bool,
        raw_normal: bool,
    ) -> Option<Hit> {
        let (t0, _) = hit_slabs(ray, min, max, range)?;
        let entering = t0 > range.min;
        let mut face: Option<(Float, usize)> = None;
        for axis in 0..3 {
            let d = ray.dir[axis];
            if d == 0.0 {
                continue;
            }
            let plane = if (d > 0.0) == entering { min[axis] } else { max[axis] };
            let t = (plane - ray.origin[axis]) / d;
            if face.is_none_or(|(best, _)| (entering && t > best) || (!entering && t < best)) {
                face = Some((t, axis));
            }
        }
        let (t, axis) = face?;
        let t = if inside_t0 && !entering { t0 } else { t };
        if !range.contains(t) && !inside_t0 {
            return None;
        }
        let mut outward = Vec3::ZERO;
        outward[axis] = if (ray.dir[axis] > 0.0) == entering { -1.0 } else { 1.0 };
        let hit = Hit::new(ray, t, outward);
        Some(if raw_normal { Hit { normal: outward, ..hit } } else { hit })
    }

    #[test]
    fn box_mistakes() {
        let faithful = box_cases(|r, a, b, i| planted_box(r, a, b, i, false, false));
        assert!(faithful.is_ok(), "{faithful:?}");
        caught(box_cases(|r, a, b, i| planted_box(r, a, b, i, true, false)), "not t0 = range.min");
        caught(box_cases(|r, a, b, i| planted_box(r, a, b, i, false, true)), "Hit::new");
    }

    /// Even–odd with `above` deciding which vertices count as above p, and
    /// optionally without the closing edge.
    fn crossings(polygon: &[Vec2], p: Vec2, lax: bool, open: bool) -> bool {
        let n = polygon.len();
        let mut inside = false;
        for i in 0..n {
            if open && i + 1 == n {
                break;
            }
            let (a, b) = (polygon[i], polygon[(i + 1) % n]);
            let a_above = if lax { a.y > p.y } else { a.y >= p.y };
            if a_above != (b.y >= p.y) {
                let (lo, hi) = if a.y < b.y { (a, b) } else { (b, a) };
                if (hi - lo).perp_dot(p - lo) > 0.0 {
                    inside = !inside;
                }
            }
        }
        inside
    }

    #[test]
    fn crossings_mistakes() {
        assert!(crossings_cases(|poly, p| crossings(poly, p, false, false)).is_ok());
        caught(crossings_cases(|poly, p| crossings(poly, p, true, false)), "counts as above");
        caught(crossings_cases(|poly, p| crossings(poly, p, false, true)), "closed");
    }

    #[test]
    fn winding_mistakes() {
        caught(winding_cases(|poly, p| -winding_number(poly, p)), "counter-clockwise is positive");
        caught(
            winding_cases(|poly, p| inside_crossings(poly, p) as i32 * winding_number(poly, p).signum()),
            "signed crossings",
        );
    }

    fn newell_open(vertices: &[Vec3]) -> Vec3 {
        vertices.windows(2).fold(Vec3::ZERO, |n, w| {
            let (a, b) = (w[0], w[1]);
            n + Vec3::new((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y))
        })
    }

    #[test]
    fn newell_mistakes() {
        caught(newell_cases(|v| -newell_normal(v)), "the sign");
        caught(newell_cases(|v| newell_normal(v).normalize_or_zero()), "do not normalise");
        caught(newell_cases(newell_open), "sum over every edge");
    }

    /// hit_polygon projecting onto xy always, or by the winding rule, or with an unfaced normal.
    fn planted_polygon(ray: &Ray, vertices: &[Vec3], range: Interval, mistake: u8) -> Option<Hit> {
        if vertices.len() < 3 {
            return None;
        }
        let n = newell_normal(vertices).try_normalize()?;
        let hit = l02_ray_casting::hit_plane(ray, n, n.dot(vertices[0]), range)?;
        let drop = if mistake == 0 { 2 } else { dominant_axis(n) };
        let (i, j) = ((drop + 1) % 3, (drop + 2) % 3);
        let flat = |v: Vec3| Vec2::new(v[i], v[j]);
        let polygon: Vec<Vec2> = vertices.iter().map(|&v| flat(v)).collect();
        let inside = if mistake == 1 {
            winding_number(&polygon, flat(hit.point)) != 0
        } else {
            inside_crossings(&polygon, flat(hit.point))
        };
        let hit = if mistake == 2 { Hit { normal: n, ..hit } } else { hit };
        inside.then_some(hit)
    }

    #[test]
    fn polygon_mistakes() {
        assert!(polygon_cases(|r, v, i| planted_polygon(r, v, i, 9)).is_ok());
        caught(polygon_cases(|r, v, i| planted_polygon(r, v, i, 0)), "dropping z");
        caught(polygon_cases(|r, v, i| planted_polygon(r, v, i, 1)), "even–odd");
        caught(polygon_cases(|r, v, i| planted_polygon(r, v, i, 2)), "Hit::new");
    }

    #[test]
    fn triangle_mistakes() {
        // One-sided Möller–Trumbore (back faces culled).
        caught(
            triangle_cases(|r, a, b, c, i| {
                let det = (b - a).dot(r.dir.cross(c - a));
                if det < 0.0 { None } else { hit_triangle_moller_trumbore(r, a, b, c, i) }
            }),
            "two-sided",
        );
        // β and γ swapped.
        caught(
            triangle_cases(|r, a, b, c, i| {
                hit_triangle_watertight(r, a, b, c, i).map(|h| TriangleHit {
                    beta: h.gamma,
                    gamma: h.beta,
                    ..h
                })
            }),
            "β weights b",
        );
        // Strict inequalities: edges and vertices excluded.
        caught(
            triangle_cases(|r, a, b, c, i| {
                hit_triangle_watertight(r, a, b, c, i)
                    .filter(|h| h.beta > 0.0 && h.gamma > 0.0 && h.beta + h.gamma < 1.0)
            }),
            "belong to the triangle",
        );
        // The watertight test with zero edge functions rejected (the catalogue's patch).
        caught(triangle_cases(|r, a, b, c, i| watertight(r, a, b, c, i, true)), "belong to the triangle");
        caught(triangle_no_leaks(|r, a, b, c, i| watertight(r, a, b, c, i, true)), "slipped between");
        // Möller–Trumbore is not watertight.
        caught(triangle_no_leaks(hit_triangle_moller_trumbore), "slipped between");
    }

    /// The reference watertight test; `strict` rejects zero edge functions.
    fn watertight(
        ray: &Ray,
        a: Vec3,
        b: Vec3,
        c: Vec3,
        range: Interval,
        strict: bool,
    ) -> Option<TriangleHit> {
        if (c - a).cross(b - a).length_squared() == 0.0 {
            return None;
        }
        let kz = dominant_axis(ray.dir);
        let (kx, ky) = ((kz + 1) % 3, (kz + 2) % 3);
        let permute = |v: Vec3| Vec3::new(v[kx], v[ky], v[kz]);
        let d = permute(ray.dir);
        let (sx, sy, sz) = (-d.x / d.z, -d.y / d.z, 1.0 / d.z);
        let shear = |p: Vec3| {
            let p = permute(p - ray.origin);
            Vec3::new(p.x + sx * p.z, p.y + sy * p.z, p.z * sz)
        };
        let (p0, p1, p2) = (shear(a), shear(b), shear(c));
        let (e0, e1, e2) = (edge_function(p1, p2), edge_function(p2, p0), edge_function(p0, p1));
        let outside = if strict {
            !((e0 > 0.0 && e1 > 0.0 && e2 > 0.0) || (e0 < 0.0 && e1 < 0.0 && e2 < 0.0))
        } else {
            (e0 < 0.0 || e1 < 0.0 || e2 < 0.0) && (e0 > 0.0 || e1 > 0.0 || e2 > 0.0)
        };
        let det = e0 + e1 + e2;
        if outside || det == 0.0 {
            return None;
        }
        let t = (e0 * p0.z + e1 * p1.z + e2 * p2.z) / det;
        range.contains(t).then_some(TriangleHit { t, beta: e1 / det, gamma: e2 / det })
    }

    #[test]
    fn planted_watertight_copy_is_faithful() {
        assert!(triangle_cases(|r, a, b, c, i| watertight(r, a, b, c, i, false)).is_ok());
        assert!(triangle_no_leaks(|r, a, b, c, i| watertight(r, a, b, c, i, false)).is_ok());
    }

    #[test]
    fn edge_function_mistakes() {
        caught(edge_cases(|p, q| p.y * q.x - p.x * q.y), "not the other way round");
        caught(edge_cases(|p, q| p.x.mul_add(q.y, -(p.y * q.x))), "antisymmetric");
        // Without the f64 fallback a tie rounds to 0 in f32 (f64 needs none: the products are exact).
        if Float::EPSILON > 1e-10 {
            caught(edge_cases(|p, q| p.x * q.y - p.y * q.x), "recompute it in f64");
        }
    }

    #[test]
    fn interpolate_mistakes() {
        caught(
            interpolate_cases(|n, b, g| ((1.0 - b - g) * n[1] + b * n[2] + g * n[0]).normalize_or_zero()),
            "n₀ takes",
        );
        caught(
            interpolate_cases(|n, b, g| (1.0 - b - g) * n[0] + b * n[1] + g * n[2]),
            "normalise the blend",
        );
        caught(
            interpolate_cases(|n, b, g| ((1.0 - b - g) * n[0] + b * n[1] + g * n[2]).normalize()),
            "never NaN",
        );
    }

    /// hit_triangle with a planted mistake: 0 shading normal not turned, 1 clockwise
    /// geometric normal, 2 no uv, 3 the outward normal not faced.
    fn planted_hit_triangle(
        ray: &Ray,
        v: &[Vec3; 3],
        normals: Option<&[Vec3; 3]>,
        range: Interval,
        mistake: u8,
    ) -> Option<Hit> {
        let [a, b, c] = *v;
        let found = hit_triangle_watertight(ray, a, b, c, range)?;
        let geometric =
            if mistake == 1 { (c - a).cross(b - a) } else { (b - a).cross(c - a) }.try_normalize()?;
        let mut hit = Hit::new(ray, found.t, geometric);
        if mistake != 2 {
            hit = hit.with_uv(Vec2::new(found.beta, found.gamma));
        }
        if mistake == 3 {
            hit.normal = geometric;
        }
        let Some(normals) = normals else { return Some(hit) };
        let shading = interpolate_normal(normals, found.beta, found.gamma);
        if shading == Vec3::ZERO {
            return Some(hit);
        }
        let normal = if mistake != 0 && shading.dot(hit.normal) < 0.0 { -shading } else { shading };
        Some(Hit { normal, ..hit })
    }

    #[test]
    fn hit_triangle_mistakes() {
        caught(
            hit_triangle_cases(|r, v, n, i| planted_hit_triangle(r, v, n, i, 0)),
            "turn the interpolated normal",
        );
        caught(hit_triangle_cases(|r, v, n, i| planted_hit_triangle(r, v, n, i, 1)), "counter-clockwise");
        caught(hit_triangle_cases(|r, v, n, i| planted_hit_triangle(r, v, n, i, 2)), "uv = (β, γ)");
        caught(hit_triangle_cases(|r, v, n, i| planted_hit_triangle(r, v, n, i, 3)), "Hit::new");
    }

    /// hit_mesh with a planted mistake: 0 the range never shrinks, 1 mesh uvs
    /// ignored, 2 mesh normals ignored.
    fn planted_mesh(ray: &Ray, mesh: &Mesh, range: Interval, mistake: u8) -> Option<Hit> {
        let mut closest: Option<(Hit, [usize; 3])> = None;
        let mut range = range;
        for triangle in &mesh.triangles {
            let corners = triangle.map(|i| i as usize);
            let vertices = corners.map(|i| mesh.positions[i]);
            let normals =
                (mistake != 2 && !mesh.normals.is_empty()).then(|| corners.map(|i| mesh.normals[i]));
            if let Some(hit) = hit_triangle(ray, &vertices, normals.as_ref(), range) {
                if mistake != 0 {
                    range = range.with_max(hit.t);
                }
                closest = Some((hit, corners));
            }
        }
        let (hit, [a, b, c]) = closest?;
        if mistake == 1 || mesh.uvs.is_empty() {
            return Some(hit);
        }
        let (beta, gamma) = (hit.uv.x, hit.uv.y);
        Some(hit.with_uv((1.0 - beta - gamma) * mesh.uvs[a] + beta * mesh.uvs[b] + gamma * mesh.uvs[c]))
    }

    #[test]
    fn mesh_mistakes() {
        assert!(mesh_cases(|r, m, i| planted_mesh(r, m, i, 9)).is_ok());
        caught(mesh_cases(|r, m, i| planted_mesh(r, m, i, 0)), "keep the closest hit");
        caught(mesh_cases(|r, m, i| planted_mesh(r, m, i, 1)), "with mesh uvs");
        caught(mesh_cases(|r, m, i| planted_mesh(r, m, i, 2)), "with mesh normals");
        // A mesh of Möller–Trumbore triangles leaks.
        caught(
            mesh_no_leaks(|r, m, i| {
                (0..m.triangles.len())
                    .filter_map(|k| {
                        let [a, b, c] = m.triangle(k);
                        hit_triangle_moller_trumbore(r, a, b, c, i)
                            .map(|h| Hit::new(r, h.t, (b - a).cross(c - a)))
                    })
                    .min_by(|x, y| x.t.total_cmp(&y.t))
            }),
            "slipped between",
        );
    }
}
