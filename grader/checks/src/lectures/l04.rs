//! Lecture 04, quadrics and transforms: capped cylinders and cones, rays
//! taken to object space, normals taken back with (M⁻¹)ᵀ, instancing.

use crate::check::Meta;

const CAPPED_NEEDS: &[&str] = &["04/slab_z_span", "04/first_crossing"];

declare_checks! {
    "l04";
    Meta::unit("slab_z_span", "the span of t in 0 ≤ z ≤ 1, ordered, and parallel rays inside or outside")
        => span_cases(slab_z_span),
    Meta::unit(
        "first_crossing",
        "the later entry or the earlier exit of two spans, and which surface made \
        it",
    ) => crossing_cases(first_crossing),
    Meta::unit(
        "hit_cylinder",
        "side and caps from outside and inside, axis-parallel, in a cap plane, tangent, 1,000 rays through \
            the rims",
    )
    .needs(CAPPED_NEEDS) => cylinder_cases(hit_cylinder),
    Meta::extreme(
        "hit_cylinder",
        "far-origin",
        "origins 10³ and 10⁷ radii away (what a squashing transform makes): t within 4ε·t of the f64 root",
    )
    .needs(CAPPED_NEEDS) => far_origin(hit_cylinder, Quadric::Cylinder),
    Meta::unit(
        "hit_cone",
        "side, base, apex (a normal, not NaN), steep rays, rays parallel to a side line, 1,000 rays through \
            the rim",
    )
    .needs(CAPPED_NEEDS) => cone_cases(hit_cone),
    Meta::extreme("hit_cone", "far-origin", "origins 10³ and 10⁷ away: t within 4ε·t of the f64 root")
        .needs(CAPPED_NEEDS) => far_origin(hit_cone, Quadric::Cone),
    Meta::unit(
        "parametric_normal",
        "∂s/∂α × ∂s/∂β normalised: sphere and ellipsoid, the order of factors, \
        a pole",
    ) => parametric_cases(parametric_normal),
    Meta::unit("ray_to_object", "origin as a point, direction as a vector, not renormalised: t is shared")
        => to_object_cases(ray_to_object),
    Meta::unit("normal_to_world", "(M⁻¹)ᵀn normalised for a rotated, squashed, moved object, and a mirror")
        => normal_cases(normal_to_world),
    Meta::unit(
        "hit_transformed",
        "a squashed sphere: world t, world point, the inverse-transpose normal faced against the ray, uv \
            and ids kept",
    )
    .needs(&["04/ray_to_object", "04/normal_to_world"]) => transformed_cases(hit_transformed),
    Meta::extreme(
        "hit_transformed",
        "extreme-scale",
        "a sphere scaled 1e-3 : 1 : 1e3: t in world units (4 rays by hand) and normals within 1e-4 rad of \
            the f64 ellipsoid (4,000 head-on rays)",
    )
    .needs(&["04/ray_to_object", "04/normal_to_world"]) => extreme_scale(hit_transformed),
}

#[cfg(feature = "l04")]
#[allow(clippy::result_large_err)] // Failure is check.rs's report, returned by value as in every lecture
#[allow(clippy::unnecessary_cast)] // widening Float to f64 for references is the identity in an f64 build
mod code {
    pub(super) use l04_quadrics_transforms::{
        first_crossing, hit_cone, hit_cylinder, hit_transformed, normal_to_world, parametric_normal,
        ray_to_object, slab_z_span,
    };
    use raylab::math::consts::{FRAC_PI_6, TAU};
    use raylab::random::Rng;
    use raylab::scene::Transform;
    use raylab::{Float, Hit, Interval, Mat4, Ray, Vec2, Vec3};

    use crate::check::{CheckResult, Failure, close, close3, ensure, fail, maybe, num, vec3};

    pub(super) type SpanFn = fn(Float, Float) -> Option<(Float, Float)>;
    pub(super) type CrossingFn = fn((Float, Float), (Float, Float), Interval) -> Option<(Float, bool)>;
    pub(super) type ShapeFn = fn(&Ray, Interval) -> Option<Hit>;
    pub(super) type ParametricFn = fn(Vec3, Vec3) -> Vec3;
    pub(super) type ToObjectFn = fn(&Ray, &Mat4) -> Ray;
    pub(super) type NormalFn = fn(Vec3, &Mat4) -> Vec3;
    pub(super) type TransformedFn = fn(&Ray, &Transform, Interval, ShapeFn) -> Option<Hit>;

    /// t, points and unit normals of unit-sized shapes a few units away: the
    /// inputs are dyadic, the roots, products and normalisations round a few
    /// times on numbers ≤ 4; 16ε holds them (2e-6 in f32).
    const TOL: Float = 16.0 * Float::EPSILON;

    const ALL: Interval = Interval::POSITIVE;

    const SQRT_HALF: Float = std::f64::consts::FRAC_1_SQRT_2 as Float;

    fn ray(o: [Float; 3], d: [Float; 3]) -> Ray {
        Ray::new(Vec3::from_array(o), Vec3::from_array(d))
    }

    fn show_ray(r: &Ray) -> String {
        format!("ray from {} along {}", vec3(r.origin), vec3(r.dir))
    }

    fn show_hit(h: &Option<Hit>) -> String {
        maybe(h, |h| format!("t = {}, normal {}, front_face {}", num(h.t), vec3(h.normal), h.front_face))
    }

    fn near3(a: Vec3, b: Vec3, tol: Float) -> bool {
        (a - b).abs().max_element() <= tol
    }

    fn show_span(s: &Option<(Float, Float)>) -> String {
        maybe(s, |(a, b)| format!("({}, {})", num(*a), num(*b)))
    }

    // ---- the slab and the crossing -------------------------------------------

    pub(super) fn span_cases(span: SpanFn) -> CheckResult {
        let inf = Float::INFINITY;
        // (o_z, d_z, the span, the cause when it differs)
        type Case = (Float, Float, Option<(Float, Float)>, &'static str);
        let cases: [Case; 8] = [
            // z = −1 + 2t: the planes z = 0 and z = 1 at t = ½ and 1.
            (-1.0, 2.0, Some((0.5, 1.0)), "the cap planes give t = −o_z/d_z and t = (1 − o_z)/d_z"),
            // z = 2 − t: z = 1 at t = 1 first, z = 0 at t = 2.
            (
                2.0,
                -1.0,
                Some((1.0, 2.0)),
                "return (entry, exit) with entry ≤ exit: going down, the plane z = 1 comes first",
            ),
            (0.25, 0.5, Some((-0.5, 1.5)), "the cap planes give t = −o_z/d_z and t = (1 − o_z)/d_z"),
            (
                0.5,
                0.0,
                Some((-inf, inf)),
                "d_z = 0 inside the slab: the whole line, (−∞, ∞); never divide by zero",
            ),
            (1.0, 0.0, Some((-inf, inf)), "the slab is closed: o_z = 1 with d_z = 0 is inside, (−∞, ∞)"),
            (0.0, 0.0, Some((-inf, inf)), "the slab is closed: o_z = 0 with d_z = 0 is inside, (−∞, ∞)"),
            (1.5, 0.0, None, "d_z = 0 outside the slab: None"),
            (-0.5, -0.0, None, "d_z = −0 outside the slab: None"),
        ];
        for (o_z, d_z, expected, cause) in cases {
            let got = span(o_z, d_z);
            let case = format!("slab_z_span(o_z = {o_z}, d_z = {d_z})");
            let ok = match (got, expected) {
                (None, None) => true,
                (Some((a, b)), Some((x, y))) => {
                    let same = |p: Float, q: Float| {
                        p == q || (q.is_finite() && (p - q).abs() <= TOL * q.abs().max(1.0))
                    };
                    same(a, x) && same(b, y)
                }
                _ => false,
            };
            ensure(ok, case, show_span(&expected), show_span(&got), cause)?;
        }
        Ok("8 spans".into())
    }

    pub(super) fn crossing_cases(crossing: CrossingFn) -> CheckResult {
        let inf = Float::INFINITY;
        let ahead = ALL;
        // (side span, caps span, range, the crossing, the cause when it differs)
        type Case = ((Float, Float), (Float, Float), Interval, Option<(Float, bool)>, &'static str);
        let cases: [Case; 8] = [
            (
                (1.0, 4.0),
                (2.0, 3.0),
                ahead,
                Some((2.0, true)),
                "the solid starts at the later entry: the caps' 2, so a cap (true)",
            ),
            (
                (2.0, 3.0),
                (1.0, 4.0),
                ahead,
                Some((2.0, false)),
                "the solid starts at the later entry: the side's 2, so the side (false)",
            ),
            (
                (-2.0, 3.0),
                (-1.0, 4.0),
                ahead,
                Some((3.0, false)),
                "starting inside (entry behind), the crossing is the earlier exit: the side's 3",
            ),
            (
                (-2.0, 4.0),
                (-1.0, 3.0),
                ahead,
                Some((3.0, true)),
                "starting inside, the crossing is the earlier exit: the caps' 3, so a cap (true)",
            ),
            (
                (2.0, 2.0),
                (1.0, 4.0),
                ahead,
                Some((2.0, false)),
                "a tangent ray touches once: t_in = t_out is a hit (a miss is t_in > t_out)",
            ),
            (
                (-inf, inf),
                (1.0, 3.0),
                ahead,
                Some((1.0, true)),
                "a ray inside the tube everywhere enters through a cap",
            ),
            ((1.0, 2.0), (3.0, 4.0), ahead, None, "disjoint spans: the ray misses the solid"),
            (
                (1.0, 2.0),
                (0.0, 4.0),
                Interval::new(2.5, 9.0),
                None,
                "both crossings (1 and 2) are outside the range (2.5, 9)",
            ),
        ];
        for (side, caps, range, expected, cause) in cases {
            let got = crossing(side, caps, range);
            let case = format!(
                "first_crossing(side ({}, {}), caps ({}, {}), range ({}, {}))",
                num(side.0),
                num(side.1),
                num(caps.0),
                num(caps.1),
                num(range.min),
                num(range.max)
            );
            let show = |c: &Option<(Float, bool)>| maybe(c, |(t, cap)| format!("t = {}, cap {cap}", num(*t)));
            ensure(got == expected, case, show(&expected), show(&got), cause)?;
        }
        Ok("8 span pairs".into())
    }

    // ---- cylinder and cone --------------------------------------------------------

    /// Expects a hit at `t` (relative TOL) with `normal` (absolute TOL) and `front`.
    fn expect_hit(
        case: &str,
        got: Option<Hit>,
        t: Float,
        normal: Vec3,
        front: bool,
        causes: &[(Vec3, &str)],
        miss: &str,
    ) -> Result<(), Failure> {
        let Some(h) = got else {
            return Err(fail(
                case,
                format!("t = {}, normal {}", num(t), vec3(normal)),
                "None (no hit)",
                miss,
            ));
        };
        close(case, h.t, t, TOL * t.abs().max(1.0), miss)?;
        let cause = causes
            .iter()
            .find(|(n, _)| near3(h.normal, *n, 1e-3))
            .map_or("the outward normal, faced against the ray by Hit::new", |(_, c)| c);
        close3(case, h.normal, normal, TOL, cause)?;
        let cause = if front {
            "a ray from outside meets the front face"
        } else {
            "a ray from inside meets the back face: front_face false"
        };
        ensure(h.front_face == front, case, format!("front_face {front}"), h.front_face, cause)
    }

    const FROM_INSIDE: &str =
        "from inside the normal faces the ray: build the hit with Hit::new(ray, t, outward normal)";
    const DIR_UNITS: &str = "t is in units of dir: do not normalise the direction";

    /// Rays aimed at rim points from outside, entering exactly there at t = 1;
    /// returns (origin, rim point, the two admissible outward normals).
    fn rim_rays(cone: bool) -> Vec<(Vec3, Vec3, Vec3, Vec3)> {
        let mut rng = Rng::new(if cone { 3 } else { 2 });
        (0..1000)
            .map(|_| {
                let phi = rng.range(0.0, TAU);
                let radial = Vec3::new(phi.cos(), phi.sin(), 0.0);
                if cone {
                    // The wedge z ≥ 0, r + z ≤ 1 near the base rim: come in faster than up (s > k).
                    let k = rng.range(0.25, 2.0);
                    let origin = radial * (1.0 + k * rng.range(1.25, 4.0)) - Vec3::Z * k;
                    (origin, radial, (radial + Vec3::Z) * SQRT_HALF, -Vec3::Z)
                } else {
                    let top = rng.next_float() < 0.5;
                    let rim = radial + if top { Vec3::Z } else { Vec3::ZERO };
                    let axial = if top { Vec3::Z } else { -Vec3::Z };
                    let origin = rim + radial * rng.range(0.25, 2.0) + axial * rng.range(0.25, 2.0);
                    (origin, rim, radial, axial)
                }
            })
            .collect()
    }

    /// Every rim ray enters at t = 1 (64ε: O and d carry a few roundings on |O| ≤ 10,
    /// stretched by 1/sin 6° for grazing entries) with the side's or the cap's normal (1e-4).
    fn no_rim_leaks(hit: ShapeFn, cone: bool) -> Result<(), Failure> {
        for (origin, rim, side, cap) in rim_rays(cone) {
            let r = Ray::new(origin, rim - origin);
            let got = hit(&r, ALL);
            let case = format!("{} (aimed at the rim point {})", show_ray(&r), vec3(rim));
            let leak = "a ray through a rim must not slip between the side test and the cap test: intersect \
                the side's span with the caps' span (first_crossing) instead of testing z and the disc \
                separately";
            let Some(h) = got else { return Err(fail(case, "t = 1", "None (no hit)", leak)) };
            close(&case, h.t, 1.0, 64.0 * Float::EPSILON * 10.0, leak)?;
            let n = h.outward_normal();
            ensure(
                near3(n, side, 1e-4) || near3(n, cap, 1e-4),
                &case,
                format!("the side's normal {} or the cap's {}", vec3(side), vec3(cap)),
                vec3(n),
                "at a rim the normal is the side's or the cap's, whichever surface first_crossing names",
            )?;
        }
        Ok(())
    }

    pub(super) fn cylinder_cases(hit: ShapeFn) -> CheckResult {
        let name = "the unit cylinder x² + y² ≤ 1, 0 ≤ z ≤ 1";
        let case = |r: &Ray| format!("{name}, {}", show_ray(r));
        // Side: x² + 0.6² = 1 at x = −0.8, t = 3 − 0.8 = 2.2; normal (−0.8, 0.6, 0).
        let r = ray([-3.0, 0.6, 0.25], [1.0, 0.0, 0.0]);
        let p = Vec3::new(-0.8, 0.6, 0.25);
        expect_hit(
            &case(&r),
            hit(&r, ALL),
            2.2,
            Vec3::new(-0.8, 0.6, 0.0),
            true,
            &[(p.normalize(), "the side's outward normal is (x, y, 0): the z of the point plays no part")],
            "solve (oₓ + t dₓ)² + (o_y + t d_y)² = 1 for the side",
        )?;
        // Direction ×2: half the t.
        let r = ray([-3.0, 0.0, 0.5], [2.0, 0.0, 0.0]);
        expect_hit(&case(&r), hit(&r, ALL), 1.0, -Vec3::X, true, &[], DIR_UNITS)?;
        // Caps from outside: bottom at t = 1 (normal −z), top at t = 2 (normal +z).
        let wrong_cap = "the cap z = 0 has the outward normal −z, the cap z = 1 has +z";
        let r = ray([0.0, 0.0, -1.0], [0.3, 0.0, 1.0]);
        expect_hit(
            &case(&r),
            hit(&r, ALL),
            1.0,
            -Vec3::Z,
            true,
            &[(Vec3::Z, wrong_cap)],
            "the cap z = 0 at t = −o_z/d_z, inside the unit disc",
        )?;
        let r = ray([0.5, 0.0, 3.0], [0.0, 0.0, -1.0]);
        expect_hit(
            &case(&r),
            hit(&r, ALL),
            2.0,
            Vec3::Z,
            true,
            &[(-Vec3::Z, wrong_cap)],
            "the cap z = 1 at t = (1 − o_z)/d_z (a = 0: the ray is parallel to the axis)",
        )?;
        // From inside: the wall at t = 1 and the top cap at t = ½, normals turned in.
        let r = ray([0.0, 0.0, 0.5], [1.0, 0.0, 0.0]);
        expect_hit(
            &case(&r),
            hit(&r, ALL),
            1.0,
            -Vec3::X,
            false,
            &[(Vec3::X, FROM_INSIDE)],
            "starting inside, the hit is where the ray leaves (the earlier exit)",
        )?;
        let r = ray([0.0, 0.0, 0.5], [0.0, 0.0, 1.0]);
        expect_hit(
            &case(&r),
            hit(&r, ALL),
            0.5,
            -Vec3::Z,
            false,
            &[(Vec3::Z, FROM_INSIDE)],
            "starting inside, the hit is where the ray leaves (the earlier exit)",
        )?;
        // Parallel to the axis (a = 0): the caps only; outside the tube, a miss.
        let axis_parallel = "a = dₓ² + d_y² = 0 for a ray parallel to the axis: it is inside the tube \
            everywhere (c ≤ 0) or nowhere; do not divide by a";
        let r = ray([-0.7, 0.7, 5.0], [0.0, 0.0, -0.5]);
        expect_hit(&case(&r), hit(&r, ALL), 8.0, Vec3::Z, true, &[], axis_parallel)?;
        let r = ray([1.5, 0.0, -1.0], [0.0, 0.0, 1.0]);
        let got = hit(&r, ALL);
        ensure(got.is_none(), case(&r), "None", show_hit(&got), axis_parallel)?;
        // In the cap plane z = 1 (d_z = 0): the side decides, x = −1 at t = 1.
        let r = ray([-2.0, 0.0, 1.0], [1.0, 0.0, 0.0]);
        expect_hit(
            &case(&r),
            hit(&r, ALL),
            1.0,
            -Vec3::X,
            true,
            &[],
            "a ray in the plane z = 1 is inside the closed slab: the side decides",
        )?;
        // Tangent to the side: x = 1, the discriminant is exactly 0, one touch at t = 2.
        let r = ray([1.0, -2.0, 0.5], [0.0, 1.0, 0.0]);
        let got = hit(&r, ALL);
        let tangent = "a zero discriminant is one (double) root: reject only a negative discriminant";
        let Some(h) = got else { return Err(fail(case(&r), "t = 2", "None (no hit)", tangent)) };
        close(case(&r), h.t, 2.0, TOL, tangent)?;
        ensure(
            h.normal.is_normalized(),
            case(&r),
            "a unit normal",
            vec3(h.normal),
            "no NaN normal at a tangent",
        )?;
        // Misses: beside, above.
        for (r, why) in [
            (
                ray([-3.0, 1.5, 0.5], [1.0, 0.0, 0.0]),
                "the line y = 1.5 misses the circle: a negative discriminant",
            ),
            (
                ray([-3.0, 0.0, 1.5], [1.0, 0.0, 0.0]),
                "the cylinder ends at z = 1: intersect the side's span with the caps' span",
            ),
            (ray([-3.0, 0.0, 0.5], [-1.0, 0.0, 0.0]), "the cylinder is behind the origin: no t > 0"),
        ] {
            let got = hit(&r, ALL);
            ensure(got.is_none(), case(&r), "None", show_hit(&got), why)?;
        }
        no_rim_leaks(hit, false)?;
        Ok("12 hand cases and 1,000 rim rays".into())
    }

    pub(super) fn cone_cases(hit: ShapeFn) -> CheckResult {
        let name = "the unit cone x² + y² ≤ (1 − z)², 0 ≤ z ≤ 1";
        let case = |r: &Ray| format!("{name}, {}", show_ray(r));
        let gradient = "the side's outward normal is the gradient (x, y, 1 − z), normalised: out and up";
        let side_out = Vec3::new(-SQRT_HALF, 0.0, SQRT_HALF);
        // Side: at z = ½ the radius is ½, x = −½ at t = 2.5; normal (−1, 0, 1)/√2.
        let r = ray([-3.0, 0.0, 0.5], [1.0, 0.0, 0.0]);
        expect_hit(
            &case(&r),
            hit(&r, ALL),
            2.5,
            side_out,
            true,
            &[(Vec3::new(-SQRT_HALF, 0.0, -SQRT_HALF), gradient), (-Vec3::X, gradient)],
            "solve x² + y² = (1 − z)² along the ray",
        )?;
        // Base from below at x = ¼: t = 1, normal −z.
        let r = ray([0.25, 0.0, -1.0], [0.0, 0.0, 1.0]);
        expect_hit(
            &case(&r),
            hit(&r, ALL),
            1.0,
            -Vec3::Z,
            true,
            &[(Vec3::Z, "the base z = 0 has the outward normal −z")],
            "the base z = 0 at t = −o_z/d_z, inside the unit disc; a vertical ray is a steep ray (a < 0): \
                the solid is the part of the line outside the roots, on the lower nappe",
        )?;
        // From above at x = ¼: the side where 1 − z = ¼, t = 3 − 0.75 = 2.25 (the upper nappe, at
        // z = 1.25, is not part of the solid).
        let r = ray([0.25, 0.0, 3.0], [0.0, 0.0, -1.0]);
        let nappe = "keep the lower nappe: the slab 0 ≤ z ≤ 1 cuts the double cone x² + y² = (1 − z)²";
        let got = hit(&r, ALL);
        let cause = if got.is_some_and(|h| (h.t - 1.75).abs() < 1e-3) {
            nappe
        } else {
            "a steep ray (a < 0) is inside the cone outside its roots; the lower nappe is the half-line \
                after the roots when d_z < 0"
        };
        expect_hit(&case(&r), got, 2.25, Vec3::new(SQRT_HALF, 0.0, SQRT_HALF), true, &[], cause)?;
        let r = ray([1.5, 0.0, -1.0], [0.0, 0.0, 1.0]);
        let got = hit(&r, ALL);
        ensure(
            got.is_none(),
            case(&r),
            "None",
            show_hit(&got),
            "x = 1.5 is outside the base disc and the cone",
        )?;
        // From inside at z = ¼ (radius ¾): t = 0.75, outward (1, 0, 1)/√2 faced back.
        let r = ray([0.0, 0.0, 0.25], [1.0, 0.0, 0.0]);
        expect_hit(
            &case(&r),
            hit(&r, ALL),
            0.75,
            Vec3::new(-SQRT_HALF, 0.0, -SQRT_HALF),
            false,
            &[(Vec3::new(SQRT_HALF, 0.0, SQRT_HALF), FROM_INSIDE)],
            "starting inside, the hit is where the ray leaves",
        )?;
        // The apex: down the axis from z = 3, t = 2, normal +z by definition (the gradient vanishes).
        let r = ray([0.0, 0.0, 3.0], [0.0, 0.0, -1.0]);
        let apex = "at the apex the gradient (x, y, 1 − z) is zero: use +z there, never a NaN normal";
        expect_hit(&case(&r), hit(&r, ALL), 2.0, Vec3::Z, true, &[], apex)?;
        // Through the apex, steeper than the sides: in at t = 2.
        let r = ray([-1.0, 0.0, 3.0], [0.5, 0.0, -1.0]);
        let got = hit(&r, ALL);
        let Some(h) = got else { return Err(fail(case(&r), "t = 2", "None (no hit)", apex)) };
        close(case(&r), h.t, 2.0, TOL, apex)?;
        ensure(h.normal.is_normalized(), case(&r), "a unit normal", vec3(h.normal), apex)?;
        // Parallel to a side line (a = 0): the base at t = 1, then out through the side at t = 1.5.
        let linear = "a = 0 for a ray parallel to a side line: f = 2bt + c is linear, one root t = −c/(2b); \
            do not divide by a";
        let r = ray([1.0, 0.0, -1.0], [-1.0, 0.0, 1.0]);
        expect_hit(&case(&r), hit(&r, ALL), 1.0, -Vec3::Z, true, &[], linear)?;
        let case2 = format!("{}, range (1, ∞)", case(&r));
        expect_hit(
            &case2,
            hit(&r, Interval::new(1.0, Float::INFINITY)),
            1.5,
            Vec3::new(SQRT_HALF, 0.0, -SQRT_HALF),
            false,
            &[],
            linear,
        )?;
        // Straight down beside the apex (a = −1): the side at z = ½, t = 1.5.
        let r = ray([0.5, 0.0, 2.0], [0.0, 0.0, -1.0]);
        expect_hit(
            &case(&r),
            hit(&r, ALL),
            1.5,
            Vec3::new(SQRT_HALF, 0.0, SQRT_HALF),
            true,
            &[],
            "a steep ray (a < 0): the lower nappe is the half-line beyond the larger root when d_z < 0",
        )?;
        no_rim_leaks(hit, true)?;
        Ok("10 hand cases and 1,000 rim rays".into())
    }

    #[derive(Clone, Copy)]
    pub(super) enum Quadric {
        Cylinder,
        Cone,
    }

    /// The side's entry t of the infinite cylinder or the cone's lower nappe, in
    /// f64, for a ray from far away along +x-ish: stable roots, and the
    /// discriminant from the moment (Lagrange), so f64 keeps ~16 digits.
    fn side_entry_f64(q: Quadric, o: Vec3, d: Vec3) -> f64 {
        let (o, d) = ([o.x as f64, o.y as f64, o.z as f64], [d.x as f64, d.y as f64, d.z as f64]);
        let (a, b, c, disc) = match q {
            Quadric::Cylinder => {
                let m = o[0] * d[1] - o[1] * d[0];
                let a = d[0] * d[0] + d[1] * d[1];
                (a, o[0] * d[0] + o[1] * d[1], o[0] * o[0] + o[1] * o[1] - 1.0, a - m * m)
            }
            Quadric::Cone => {
                let w = 1.0 - o[2];
                let (u, v) = ([o[0], o[1], w], [d[0], d[1], -d[2]]);
                let m = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
                let a = d[0] * d[0] + d[1] * d[1] - d[2] * d[2];
                (
                    a,
                    o[0] * d[0] + o[1] * d[1] + w * d[2],
                    o[0] * o[0] + o[1] * o[1] - w * w,
                    m[0] * m[0] + m[1] * m[1] - m[2] * m[2],
                )
            }
        };
        let q = -(b + disc.sqrt().copysign(b));
        (q / a).min(c / q)
    }

    pub(super) fn far_origin(hit: ShapeFn, quadric: Quadric) -> CheckResult {
        let (name, o_z, near) = match quadric {
            Quadric::Cylinder => ("the unit cylinder", 0.5, Vec3::new(-0.8, 0.6, 0.0)),
            Quadric::Cone => ("the unit cone", 0.3, Vec3::new(-SQRT_HALF, 0.0, SQRT_HALF)),
        };
        let y = match quadric {
            Quadric::Cylinder => 0.6,
            Quadric::Cone => 0.0,
        };
        let mut worst: f64 = 0.0;
        for distance in [1.0e3 as Float, 1.0e7] {
            // Along +x from x = −D and along a slanted unit-ish direction from as far.
            let slanted = Vec3::new(0.6, 0.8, 0.0);
            for r in [
                Ray::new(Vec3::new(-distance, y, o_z), Vec3::X),
                Ray::new(
                    Vec3::new(-0.6 * distance, -0.8 * distance, o_z) + Vec3::new(-0.8, 0.6, 0.0) * y,
                    slanted,
                ),
            ] {
                let case = format!("{name}, {} ({} away)", show_ray(&r), num(distance));
                let expected = side_entry_f64(quadric, r.origin, r.dir);
                let got = hit(&r, ALL);
                let cancel = "b² − ac cancels for a far origin (both are about |o|²|d|²): compute the \
                    discriminant from the moment m = o × d about the axis (Lagrange's identity), as the doc \
                    comment says";
                let Some(h) = got else {
                    return Err(fail(case, format!("t = {expected:.4}"), "None (no hit)", cancel));
                };
                // 4ε·t: c = |o|² − 1 and q each round once (relative ε/2), t = c/q once more.
                let tol = 4.0 * Float::EPSILON as f64 * expected;
                worst = worst.max((h.t as f64 - expected).abs() / (Float::EPSILON as f64 * expected));
                ensure(
                    (h.t as f64 - expected).abs() <= tol,
                    &case,
                    format!("t = {expected:.4} (± {tol:.1e})"),
                    num(h.t),
                    cancel,
                )?;
                ensure(
                    h.normal.is_normalized(),
                    &case,
                    "a unit normal",
                    vec3(h.normal),
                    "no NaN may escape: even when the point has lost its digits, return a unit normal",
                )?;
                if distance == 1.0e3 && r.dir == Vec3::X {
                    // The point −1000 + t carries ulp(1000) ≈ 6e-5 in f32: the normal within 1e-3.
                    close3(&case, h.normal, near, 1e-3, "the side's outward normal at the hit point")?;
                }
            }
        }
        Ok(format!("4 far rays, worst |Δt| = {worst:.1} ε·t"))
    }

    // ---- parametric normals --------------------------------------------------------

    /// The unit sphere s(θ, φ) = (sin θ cos φ, sin θ sin φ, cos θ) and its partials.
    fn sphere(theta: Float, phi: Float) -> (Vec3, Vec3, Vec3) {
        let (st, ct, sp, cp) = (theta.sin(), theta.cos(), phi.sin(), phi.cos());
        (Vec3::new(st * cp, st * sp, ct), Vec3::new(ct * cp, ct * sp, -st), Vec3::new(-st * sp, st * cp, 0.0))
    }

    pub(super) fn parametric_cases(normal: ParametricFn) -> CheckResult {
        // ∂s/∂θ × ∂s/∂φ = sin θ · s: the outward radial direction. 16ε: |s| = 1 up to rounding.
        for (theta, phi) in [(0.3, 0.0), (1.0, 2.0), (2.5, -1.0), (1.55, 4.0)] {
            let (s, dt, dp) = sphere(theta, phi);
            let got = normal(dt, dp);
            let case =
                format!("unit sphere at θ = {theta}, φ = {phi}: ∂s/∂θ = {}, ∂s/∂φ = {}", vec3(dt), vec3(dp));
            let cause = if near3(got, -s, TOL) {
                "n = ∂s/∂α × ∂s/∂β in this order: swapping the factors flips the side"
            } else if near3(got, dt.cross(dp), TOL) {
                "normalise the cross product"
            } else {
                "n = (∂s/∂α × ∂s/∂β)/|∂s/∂α × ∂s/∂β|"
            };
            close3(&case, got, s, TOL, cause)?;
        }
        // The ellipsoid (2 sin θ cos φ, ½ sin θ sin φ, cos θ): the normal is the gradient (x/4, 4y, z),
        // normalised; 64ε: a few roundings times the axis ratio 4.
        let semi = Vec3::new(2.0, 0.5, 1.0);
        for (theta, phi) in [(0.7, 0.4), (2.0, 3.0)] {
            let (s, dt, dp) = sphere(theta, phi);
            let got = normal(dt * semi, dp * semi);
            let expected = (s / semi).normalize();
            let case = format!("ellipsoid with semi-axes (2, 0.5, 1) at θ = {theta}, φ = {phi}");
            close3(&case, got, expected, 64.0 * Float::EPSILON, "n = (∂s/∂α × ∂s/∂β)/|∂s/∂α × ∂s/∂β|")?;
        }
        // The pole θ = 0: ∂s/∂φ = 0, no normal: the zero vector, not NaN.
        let (_, dt, dp) = sphere(0.0, 1.0);
        close3(
            "unit sphere at the pole θ = 0 (∂s/∂φ = 0)",
            normal(dt, dp),
            Vec3::ZERO,
            0.0,
            "at a singular point (a zero or parallel partial) return the zero vector, never NaN",
        )?;
        Ok("4 sphere points, 2 ellipsoid points, a pole".into())
    }

    // ---- transforms ----------------------------------------------------------------

    /// T(1, 2, 3)·S(2, 0.5, 4) and its inverse written by hand: S(½, 2, ¼)·T(−1, −2, −3).
    fn placed() -> Transform {
        Transform {
            world_from_object: Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0))
                * Mat4::from_scale(Vec3::new(2.0, 0.5, 4.0)),
            object_from_world: Mat4::from_scale(Vec3::new(0.5, 2.0, 0.25))
                * Mat4::from_translation(Vec3::new(-1.0, -2.0, -3.0)),
        }
    }

    pub(super) fn to_object_cases(to_object: ToObjectFn) -> CheckResult {
        let m = placed().object_from_world;
        let world = ray([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]);
        let case = format!("object_from_world = S(½, 2, ¼)·T(−1, −2, −3), world {}", show_ray(&world));
        let got = to_object(&world, &m);
        // By hand: origin ((0 − 1)/2, (0 − 2)·2, (0 − 3)/4), dir (½, 2, ¼), not renormalised.
        let (origin, dir) = (Vec3::new(-0.5, -4.0, -0.75), Vec3::new(0.5, 2.0, 0.25));
        let cause = if near3(got.origin, Vec3::new(0.0, 0.0, 0.0), TOL) {
            "the origin is a point (w = 1): the translation applies to it"
        } else if near3(got.origin, Vec3::new(1.0, 2.0, 3.0), TOL) {
            "the matrix given is object_from_world already: apply it as it is (do not invert it)"
        } else {
            "origin' = M·(origin, 1)"
        };
        close3(&case, got.origin, origin, TOL, cause)?;
        let cause = if near3(got.dir, dir.normalize(), TOL) {
            "do not renormalise dir: the same t must name the same point in both spaces, so t stays in \
                world units"
        } else if near3(got.dir, origin + dir, TOL) {
            "dir is a vector (w = 0): the translation must not move it"
        } else {
            "dir' = M·(dir, 0)"
        };
        close3(&case, got.dir, dir, TOL, cause)?;
        // A rotation by 30° about z after moving by (−1, 0, 0): (1, 1, 0) ↦ R(0, 1, 0) = (−½, √3/2, 0);
        // (0, 2, 0) ↦ (−1, √3, 0).
        let m = Mat4::from_rotation_z(FRAC_PI_6) * Mat4::from_translation(-Vec3::X);
        let world = ray([1.0, 1.0, 0.0], [0.0, 2.0, 0.0]);
        let got = to_object(&world, &m);
        let case = format!("object_from_world = R_z(30°)·T(−1, 0, 0), world {}", show_ray(&world));
        let half_root3 = (3.0 as Float).sqrt() / 2.0;
        close3(&case, got.origin, Vec3::new(-0.5, half_root3, 0.0), TOL, "origin' = M·(origin, 1)")?;
        close3(
            &case,
            got.dir,
            Vec3::new(-1.0, 2.0 * half_root3, 0.0),
            TOL,
            "dir' = M·(dir, 0), not renormalised",
        )?;
        Ok("2 rays".into())
    }

    /// In f64: the unit normal to the plane spanned by A·t₁ and A·t₂, oriented as t₁ × t₂ is.
    fn spanned_normal(a: &Mat4, t1: Vec3, t2: Vec3) -> Vec3 {
        let (u, v) = (a.transform_vector3(t1), a.transform_vector3(t2));
        let w = |x: Vec3| [x.x as f64, x.y as f64, x.z as f64];
        let (u, v) = (w(u), w(v));
        let n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
        let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        Vec3::new((n[0] / l) as Float, (n[1] / l) as Float, (n[2] / l) as Float)
    }

    pub(super) fn normal_cases(to_world: NormalFn) -> CheckResult {
        // world_from_object A = T(7, 7, 7)·R_z(−30°)·S(1, ¼, 1); object_from_world M = A⁻¹ by hand.
        let a = Mat4::from_translation(Vec3::splat(7.0))
            * Mat4::from_rotation_z(-FRAC_PI_6)
            * Mat4::from_scale(Vec3::new(1.0, 0.25, 1.0));
        let m = Mat4::from_scale(Vec3::new(1.0, 4.0, 1.0))
            * Mat4::from_rotation_z(FRAC_PI_6)
            * Mat4::from_translation(Vec3::splat(-7.0));
        // The world normal is perpendicular to the images A·t of the tangents t ⟂ n, on
        // n's side (det A > 0): n_w ∝ A t₁ × A t₂ for t₁ × t₂ = n, an independent route to (A⁻¹)ᵀn.
        for n in [Vec3::new(1.0, 1.0, 0.0), Vec3::Z, Vec3::new(0.3, -0.5, 0.8), Vec3::new(0.0, 2.0, 0.0)] {
            let t1 = n.normalize().any_orthonormal_vector();
            let t2 = n.normalize().cross(t1);
            let expected = spanned_normal(&a, t1, t2);
            let got = to_world(n, &m);
            let case = format!(
                "object_from_world = S(1, 4, 1)·R_z(30°)·T(−7, −7, −7), object-space normal {}",
                vec3(n)
            );
            let m3 = raylab::Mat3::from_mat4(m);
            let cause = if near3(got, a.transform_vector3(n).normalize(), 1e-4) {
                "normals take (M⁻¹)ᵀ: transforming n like a tangent (by world_from_object) is right only \
                    for rotations and uniform scales; n_w = object_from_worldᵀ·n"
            } else if near3(got, (m3 * n).normalize(), 1e-4) {
                "transpose the 3×3 block: n_w = object_from_worldᵀ·n, not object_from_world·n"
            } else if near3(got, m3.transpose() * n, 1e-4) {
                "normalise the result"
            } else {
                "n_w = (A⁻¹)ᵀn normalised, with A⁻¹ = object_from_world (its 3×3 block: no translation)"
            };
            close3(&case, got, expected, 4.0 * TOL, cause)?;
        }
        // A mirror x ↦ −x: the outward normal +x of the local point (1, 0, 0) becomes −x.
        let mirror = Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0));
        close3(
            "object_from_world = S(−1, 1, 1) (a mirror), normal +x",
            to_world(Vec3::X, &mirror),
            -Vec3::X,
            TOL,
            "n_w = (A⁻¹)ᵀn: a mirror maps the outward normal +x to −x",
        )?;
        Ok("4 normals and a mirror".into())
    }

    /// A unit sphere at the origin written for the checks (independent of
    /// lecture 02): stable roots with the discriminant a − |o × d|², which keeps
    /// its digits when a squashing transform puts the local origin far away.
    fn unit_sphere(ray: &Ray, range: Interval) -> Option<Hit> {
        let (o, d) = (ray.origin, ray.dir);
        let (a, b, c) = (d.dot(d), o.dot(d), o.dot(o) - 1.0);
        let disc = a - o.cross(d).length_squared();
        if disc < 0.0 {
            return None;
        }
        let q = -(b + disc.sqrt().copysign(b));
        let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
        let t = [t0.min(t1), t0.max(t1)].into_iter().find(|&t| range.contains(t))?;
        Some(Hit::new(ray, t, ray.at(t)))
    }

    /// The plane z = 0 seen from inside (outward −z), with uv (¼, ¾), object 3, material 2.
    fn tagged_plane(ray: &Ray, range: Interval) -> Option<Hit> {
        let t = -ray.origin.z / ray.dir.z;
        range.contains(t).then(|| Hit {
            object: 3,
            material: 2,
            ..Hit::new(ray, t, -Vec3::Z).with_uv(Vec2::new(0.25, 0.75))
        })
    }

    const WORLD_T: &str = "t must stay in world units: do not renormalise the object-space direction (the \
        same t names the same point in both spaces)";
    const NORMAL_WORLD: &str = "take the local outward normal to the world with normal_to_world ((M⁻¹)ᵀ), \
        then face it by the local front_face";

    pub(super) fn transformed_cases(transformed: TransformedFn) -> CheckResult {
        let tr = placed();
        let name = "the unit sphere placed by T(1, 2, 3)·S(2, 0.5, 4)";
        // The ellipsoid ((x − 1)/2)² + ((y − 2)/0.5)² + ((z − 3)/4)² = 1; hits by hand.
        // (origin, direction, t, normal, front_face)
        type Case = ([Float; 3], [Float; 3], Float, Vec3, bool);
        let cases: [Case; 3] = [
            ([-5.0, 2.0, 3.0], [1.0, 0.0, 0.0], 4.0, -Vec3::X, true), // x = 1 − 2 = −1
            ([1.0, -3.0, 3.0], [0.0, 2.0, 0.0], 2.25, -Vec3::Y, true), // y = 1.5: (1.5 + 3)/2
            ([1.0, 2.0, 3.0], [0.0, 0.0, 1.0], 4.0, -Vec3::Z, false), // from the centre to z = 7
        ];
        for (o, d, t, normal, front) in cases {
            let r = ray(o, d);
            let case = format!("{name}, {}", show_ray(&r));
            let got = transformed(&r, &tr, ALL, unit_sphere);
            let Some(h) = got else {
                return Err(fail(
                    case,
                    format!("t = {t}"),
                    "None (no hit)",
                    "intersect the object-space ray (ray_to_object) with the local shape",
                ));
            };
            close(&case, h.t, t, TOL * t, WORLD_T)?;
            close3(
                &case,
                h.point,
                r.at(t),
                TOL * 8.0,
                "the hit point is on the world ray: ray.at(t), not the object-space point",
            )?;
            let cause = if near3(h.normal, -normal, TOL) {
                "face the world normal by the local front_face: from inside it points back into the object"
            } else {
                NORMAL_WORLD
            };
            close3(&case, h.normal, normal, TOL, cause)?;
            ensure(
                h.front_face == front,
                &case,
                format!("front_face {front}"),
                h.front_face,
                "keep the local hit's front_face",
            )?;
        }
        // Head-on at the point whose local normal is (1, 1, 0)/√2: the local point (1, 1, 0)/√2 is
        // (1 + √2, 2 + 0.5/√2, 3) in the world, where the normal is ∝ (x/a², y/b²) ∝ (1/2, 2) ∝ (1, 4, 0).
        let s = SQRT_HALF;
        let p = Vec3::new(1.0 + 2.0 * s, 2.0 + 0.5 * s, 3.0);
        let n = Vec3::new(1.0, 4.0, 0.0).normalize();
        let r = Ray::new(p + n, -n);
        let case = format!("{name}, {} (head-on where the local normal is (1, 1, 0)/√2)", show_ray(&r));
        let got = transformed(&r, &tr, ALL, unit_sphere);
        let Some(h) = got else {
            return Err(fail(case, "t = 1", "None (no hit)", "intersect in object space"));
        };
        close(&case, h.t, 1.0, 64.0 * Float::EPSILON, WORLD_T)?;
        let by_m = tr.world_from_object.transform_vector3(Vec3::new(s, s, 0.0)).normalize();
        let cause = if near3(h.normal, by_m, 1e-3) {
            "the normal went through world_from_object: normals take (M⁻¹)ᵀ, use normal_to_world"
        } else {
            NORMAL_WORLD
        };
        close3(&case, h.normal, n, 64.0 * Float::EPSILON, cause)?;
        // A stand-in local shape: the local plane z = 0 (world z = 3) seen from inside, with uv and ids.
        let r = ray([1.0, 2.0, 5.0], [0.0, 0.0, -1.0]);
        let case = format!(
            "the plane z = 0 placed by T(1, 2, 3)·S(2, 0.5, 4), seen from its back, {}",
            show_ray(&r)
        );
        let got = transformed(&r, &tr, ALL, tagged_plane);
        let Some(h) = got else {
            return Err(fail(case, "t = 2", "None (no hit)", "intersect in object space"));
        };
        close(&case, h.t, 2.0, TOL, WORLD_T)?;
        close3(
            &case,
            h.point,
            Vec3::new(1.0, 2.0, 3.0),
            TOL,
            "the hit point is on the world ray: ray.at(t), not the object-space point",
        )?;
        ensure(
            (h.front_face, h.uv, h.object, h.material) == (false, Vec2::new(0.25, 0.75), 3, 2),
            &case,
            "front_face false, uv (0.25, 0.75), object 3, material 2",
            format!(
                "front_face {}, uv ({}, {}), object {}, material {}",
                h.front_face,
                num(h.uv.x),
                num(h.uv.y),
                h.object,
                h.material
            ),
            "keep front_face, uv, object and material from the local hit (Hit { point, normal, ..local })",
        )?;
        close3(
            &case,
            h.normal,
            Vec3::Z,
            TOL,
            "the local outward normal −z, taken to the world and faced against the ray (+z)",
        )?;
        // A mirror x ↦ −x maps the unit sphere to itself: from (−3, 0, 0) along +x, t = 2, normal −x.
        let mirror = Transform::new(Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0))).expect("invertible");
        let r = ray([-3.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        let case = format!("the unit sphere mirrored by S(−1, 1, 1), {}", show_ray(&r));
        let got = transformed(&r, &mirror, ALL, unit_sphere);
        let Some(h) = got else {
            return Err(fail(case, "t = 2", "None (no hit)", "intersect in object space"));
        };
        close3(
            &case,
            h.normal,
            -Vec3::X,
            TOL,
            "the outward side stays outward under a mirror: face the world normal by the local front_face, \
                not by recomputing the sign",
        )?;
        Ok("5 ellipsoid rays, a tagged plane, a mirror".into())
    }

    /// The axis-aligned ellipsoid Σ ((pᵢ − cᵢ)/sᵢ)² = 1 hit by a ray, in f64:
    /// the first t > 0 and the unit outward normal (the gradient).
    fn ellipsoid_f64(o: [f64; 3], d: [f64; 3], center: [f64; 3], semi: [f64; 3]) -> Option<(f64, [f64; 3])> {
        let u = [0, 1, 2].map(|i| (o[i] - center[i]) / semi[i]);
        let v = [0, 1, 2].map(|i| d[i] / semi[i]);
        let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let m = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
        let (a, b, c) = (dot(v, v), dot(u, v), dot(u, u) - 1.0);
        let disc = a - dot(m, m);
        if disc < 0.0 {
            return None;
        }
        let q = -(b + disc.sqrt().copysign(b));
        let t = [(q / a).min(c / q), (q / a).max(c / q)].into_iter().find(|&t| t > 0.0)?;
        let g = [0, 1, 2].map(|i| (u[i] + t * v[i]) / semi[i]);
        let l = dot(g, g).sqrt();
        Some((t, g.map(|x| x / l)))
    }

    fn angle(n: Vec3, reference: [f64; 3]) -> f64 {
        let a = [n.x as f64, n.y as f64, n.z as f64];
        let cross = [
            a[1] * reference[2] - a[2] * reference[1],
            a[2] * reference[0] - a[0] * reference[2],
            a[0] * reference[1] - a[1] * reference[0],
        ];
        let c = (cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]).sqrt();
        c.atan2(a[0] * reference[0] + a[1] * reference[1] + a[2] * reference[2])
    }

    pub(super) fn extreme_scale(transformed: TransformedFn) -> CheckResult {
        // 1. t in world units under the scale 1e-3 : 1 : 1e3, centred at (5, 0, 0), by hand (4ε relative).
        let tr = Transform::new(
            Mat4::from_translation(Vec3::new(5.0, 0.0, 0.0)) * Mat4::from_scale(Vec3::new(1e-3, 1.0, 1e3)),
        )
        .expect("invertible");
        let name = "the unit sphere scaled (1e-3, 1, 1e3) and moved to (5, 0, 0)";
        for (o, d, t) in [
            ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], 4.999),      // x = 5 − 1e-3
            ([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], 2.4995),     // the same point, dir ×2
            ([5.0, -3.0, 0.0], [0.0, 0.5, 0.0], 4.0),       // y = −1: (−1 + 3)/0.5
            ([5.0, 0.0, -3000.0], [0.0, 0.0, 2.0], 1000.0), // z = −1000: (−1000 + 3000)/2
        ] {
            let r = ray(o, d);
            let case = format!("{name}, {}", show_ray(&r));
            let got = transformed(&r, &tr, ALL, unit_sphere);
            let Some(h) = got else {
                return Err(fail(
                    case,
                    format!("t = {t}"),
                    "None (no hit)",
                    "intersect the object-space ray with the local shape",
                ));
            };
            close(&case, h.t, t, 4.0 * Float::EPSILON * t, WORLD_T)?;
        }
        // 2. Head-on rays from one unit out along the normal at 4,000 points of the ellipsoid
        //    centred at (5, −2, 300), against the f64 world-space ellipsoid. Rays whose exact
        //    normal turns by more than 1e-5 rad when the origin moves by one rounding are
        //    ill-conditioned for any Float method (the pancake's rim) and skipped; at least
        //    3/4 remain. t within 16ε relative.
        let (center, semi) = ([5.0, -2.0, 300.0], [1e-3, 1.0, 1e3]);
        let v = |a: [f64; 3]| Vec3::new(a[0] as Float, a[1] as Float, a[2] as Float);
        let tr = Transform::new(Mat4::from_translation(v(center)) * Mat4::from_scale(v(semi)))
            .expect("invertible");
        let mut rng = Rng::new(8);
        let (mut compared, mut worst) = (0, 0.0f64);
        for _ in 0..4000 {
            let (theta, phi) = (rng.range(0.05, 3.09) as f64, rng.range(0.0, TAU) as f64);
            let local = [theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos()];
            let p = [0, 1, 2].map(|i| center[i] + semi[i] * local[i]);
            let g = [0, 1, 2].map(|i| local[i] / semi[i]);
            let l = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
            let n = g.map(|x| x / l);
            let world = Ray::new(v([0, 1, 2].map(|i| p[i] + n[i])), v(n.map(|x| -x)));
            let (o, d) = (
                [world.origin.x as f64, world.origin.y as f64, world.origin.z as f64],
                [world.dir.x as f64, world.dir.y as f64, world.dir.z as f64],
            );
            let Some((t, normal)) = ellipsoid_f64(o, d, center, semi) else { continue };
            // How far the exact normal turns when the origin moves by one rounding.
            let delta = Float::EPSILON as f64 * (o.iter().fold(0.0f64, |m, x| m.max(x.abs())) + 300.0);
            let sensitivity = (0..3)
                .map(|k| {
                    let mut moved = o;
                    moved[k] += delta;
                    ellipsoid_f64(moved, d, center, semi).map_or(f64::INFINITY, |(_, m)| angle(v(m), normal))
                })
                .fold(0.0, f64::max);
            if sensitivity > 1e-5 {
                continue;
            }
            compared += 1;
            let case = format!("{name}, {} (head-on)", show_ray(&world))
                .replace("(1e-3, 1, 1e3) and moved to (5, 0, 0)", "(1e-3, 1, 1e3) and moved to (5, −2, 300)");
            let got = transformed(&world, &tr, ALL, unit_sphere);
            let Some(h) = got else {
                return Err(fail(
                    case,
                    format!("t = {t:.6}"),
                    "None (no hit)",
                    "intersect in object space: the head-on ray hits",
                ));
            };
            ensure(
                (h.t as f64 - t).abs() <= 16.0 * Float::EPSILON as f64 * t,
                &case,
                format!("t = {t:.7} (± 16ε·t = {:.1e})", 16.0 * Float::EPSILON as f64 * t),
                num(h.t),
                WORLD_T,
            )?;
            let error = angle(h.outward_normal(), normal);
            worst = worst.max(error);
            ensure(
                error <= 1e-4,
                &case,
                format!("outward normal {} within 1e-4 rad", vec3(v(normal))),
                format!("{} ({error:.1e} rad off)", vec3(h.outward_normal())),
                "normals take (M⁻¹)ᵀ = object_from_worldᵀ (normal_to_world), normalised after the \
                    transform; M itself tilts them by up to 90° at 1e-3 : 1e3",
            )?;
        }
        ensure(
            compared >= 3000,
            name,
            "at least 3,000 well-conditioned rays",
            compared,
            "(the check's own sampling)",
        )?;
        Ok(format!("4 hand t's; {compared} head-on rays, worst normal {worst:.1e} rad"))
    }
}

#[cfg(all(test, feature = "l04"))]
#[allow(clippy::result_large_err)]
mod tests {
    //! The checks pass on the reference, and planted mistakes (the catalogue's
    //! and a few more) fail them with the intended cause.

    use crate::check::testing::caught;

    pub(super) use l04_quadrics_transforms::{first_crossing, normal_to_world, ray_to_object, slab_z_span};
    use raylab::scene::Transform;
    use raylab::{Float, Hit, Interval, Ray, Vec3};

    use super::code::*;

    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }

    #[test]
    fn span_and_crossing_mistakes() {
        caught(span_cases(|o, d| Some((-o / d, (1.0 - o) / d))), "entry ≤ exit");
        caught(
            span_cases(|o, d| {
                let (t0, t1) = (-o / d, (1.0 - o) / d);
                Some((t0.min(t1), t0.max(t1)))
            }),
            "closed",
        );
        caught(
            crossing_cases(|side, caps, range| first_crossing(side, caps, range).map(|(t, cap)| (t, !cap))),
            "so a cap (true)",
        );
        caught(
            crossing_cases(|side, caps, range| {
                let (t_in, t_out) = (side.0.max(caps.0), side.1.min(caps.1));
                if t_in >= t_out {
                    return None;
                }
                first_crossing(side, caps, range)
            }),
            "tangent",
        );
    }

    /// The reference cylinder with switches: `naive` b² − ac, `point_normal` (x, y, z),
    /// `raw` the outward normal unfaced, `classic` z and disc tested separately.
    #[derive(Clone, Copy, Default)]
    struct Cyl {
        naive: bool,
        point_normal: bool,
        raw: bool,
        classic: bool,
    }

    fn cylinder(ray: &Ray, range: Interval, m: Cyl) -> Option<Hit> {
        let (o, d) = (ray.origin, ray.dir);
        let (a, b, c) = (d.x * d.x + d.y * d.y, o.x * d.x + o.y * d.y, o.x * o.x + o.y * o.y - 1.0);
        let (side_in, side_out) = if a == 0.0 {
            if c > 0.0 {
                return None;
            }
            (Float::NEG_INFINITY, Float::INFINITY)
        } else {
            let mm = o.x * d.y - o.y * d.x;
            let disc = if m.naive { b * b - a * c } else { a - mm * mm };
            if disc < 0.0 {
                return None;
            }
            let q = -(b + disc.sqrt().copysign(b));
            let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
            (t0.min(t1), t0.max(t1))
        };
        let (t, on_cap) = if m.classic {
            // The classic way: side roots with 0 ≤ z ≤ 1, cap hits inside the disc, nearest in range.
            let mut best: Option<(Float, bool)> = None;
            let mut consider = |t: Float, cap: bool| {
                if range.contains(t) && best.is_none_or(|(b, _)| t < b) {
                    best = Some((t, cap));
                }
            };
            for t in [side_in, side_out] {
                if t.is_finite() && (0.0..=1.0).contains(&ray.at(t).z) {
                    consider(t, false);
                }
            }
            for z in [0.0, 1.0] {
                let t = (z - o.z) / d.z;
                let p = ray.at(t);
                if t.is_finite() && p.x * p.x + p.y * p.y <= 1.0 {
                    consider(t, true);
                }
            }
            best?
        } else {
            first_crossing((side_in, side_out), slab_z_span(o.z, d.z)?, range)?
        };
        let p = ray.at(t);
        let outward = if on_cap {
            Vec3::new(0.0, 0.0, if p.z > 0.5 { 1.0 } else { -1.0 })
        } else if m.point_normal {
            p
        } else {
            Vec3::new(p.x, p.y, 0.0)
        };
        let outward = outward.try_normalize().unwrap_or(Vec3::Z);
        let hit = Hit::new(ray, t, outward);
        Some(if m.raw { Hit { normal: outward, ..hit } } else { hit })
    }

    thread_local! {
        static CYL: std::cell::Cell<Cyl> = std::cell::Cell::new(Cyl::default());
    }

    fn planted_cylinder(ray: &Ray, range: Interval) -> Option<Hit> {
        cylinder(ray, range, CYL.with(std::cell::Cell::get))
    }

    fn cyl(m: Cyl) -> ShapeFn {
        CYL.with(|c| c.set(m));
        planted_cylinder
    }

    #[test]
    fn cylinder_mistakes() {
        let none = Cyl::default();
        assert!(cylinder_cases(cyl(none)).is_ok() && far_origin(cyl(none), Quadric::Cylinder).is_ok());
        caught(cylinder_cases(cyl(Cyl { point_normal: true, ..none })), "plays no part");
        caught(cylinder_cases(cyl(Cyl { raw: true, ..none })), "Hit::new");
        caught(cylinder_cases(cyl(Cyl { classic: true, ..none })), "slip between");
        // The textbook discriminant passes the ordinary cases and fails far away.
        assert!(cylinder_cases(cyl(Cyl { naive: true, ..none })).is_ok());
        caught(far_origin(cyl(Cyl { naive: true, ..none }), Quadric::Cylinder), "cancels");
    }

    /// The reference cone with switches: `naive` b² − ac, `down_normal` (x, y, z − 1),
    /// `both_nappes` f ≤ 0 taken between the roots whatever the sign of a.
    fn cone(ray: &Ray, range: Interval, naive: bool, down_normal: bool, both_nappes: bool) -> Option<Hit> {
        let (o, d) = (ray.origin, ray.dir);
        let w = 1.0 - o.z;
        let a = d.x * d.x + d.y * d.y - d.z * d.z;
        let b = o.x * d.x + o.y * d.y + w * d.z;
        let c = o.x * o.x + o.y * o.y - w * w;
        let (side_in, side_out) = if a == 0.0 {
            if b == 0.0 {
                if c > 0.0 {
                    return None;
                }
                (Float::NEG_INFINITY, Float::INFINITY)
            } else {
                let t = -c / (2.0 * b);
                if b > 0.0 { (Float::NEG_INFINITY, t) } else { (t, Float::INFINITY) }
            }
        } else {
            let m = Vec3::new(o.x, o.y, w).cross(Vec3::new(d.x, d.y, -d.z));
            let disc = if naive { b * b - a * c } else { m.x * m.x + m.y * m.y - m.z * m.z };
            if disc < 0.0 && a > 0.0 {
                return None;
            }
            let q = -(b + disc.max(0.0).sqrt().copysign(b));
            let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
            let (r0, r1) = (t0.min(t1), t0.max(t1));
            if a > 0.0 || both_nappes {
                (r0, r1)
            } else if d.z > 0.0 {
                (Float::NEG_INFINITY, r0)
            } else {
                (r1, Float::INFINITY)
            }
        };
        let (t, on_cap) = first_crossing((side_in, side_out), slab_z_span(o.z, d.z)?, range)?;
        let p = ray.at(t);
        let outward = if on_cap {
            Vec3::new(0.0, 0.0, if p.z > 0.5 { 1.0 } else { -1.0 })
        } else if down_normal {
            Vec3::new(p.x, p.y, p.z - 1.0)
        } else {
            Vec3::new(p.x, p.y, 1.0 - p.z)
        };
        Some(Hit::new(ray, t, outward.try_normalize().unwrap_or(Vec3::Z)))
    }

    #[test]
    fn cone_mistakes() {
        assert!(cone_cases(|r, i| cone(r, i, false, false, false)).is_ok());
        assert!(far_origin(|r, i| cone(r, i, false, false, false), Quadric::Cone).is_ok());
        caught(cone_cases(|r, i| cone(r, i, false, true, false)), "gradient");
        caught(cone_cases(|r, i| cone(r, i, false, false, true)), "steep ray");
        caught(far_origin(|r, i| cone(r, i, true, false, false), Quadric::Cone), "cancels");
    }

    #[test]
    fn parametric_mistakes() {
        caught(parametric_cases(|a, b| b.cross(a).normalize_or_zero()), "in this order");
        caught(parametric_cases(|a, b| a.cross(b)), "normalise");
        caught(parametric_cases(|a, b| a.cross(b).normalize()), "never NaN");
    }

    #[test]
    fn to_object_mistakes() {
        caught(
            to_object_cases(|r, m| {
                Ray::new(m.transform_point3(r.origin), m.transform_vector3(r.dir).normalize())
            }),
            "do not renormalise",
        );
        caught(
            to_object_cases(|r, m| Ray::new(m.transform_point3(r.origin), m.transform_point3(r.dir))),
            "w = 0",
        );
        caught(to_object_cases(|r, m| ray_to_object(r, &m.inverse())), "as it is");
    }

    #[test]
    fn normal_mistakes() {
        caught(normal_cases(|n, m| m.inverse().transform_vector3(n).normalize()), "(M⁻¹)ᵀ");
        caught(normal_cases(|n, m| m.transform_vector3(n).normalize()), "transpose");
        caught(normal_cases(|n, m| raylab::Mat3::from_mat4(*m).transpose() * n), "normalise the result");
    }

    /// hit_transformed with a planted mistake: 0 the object-space point, 1 uv and ids
    /// dropped, 2 the object-space direction renormalised, 3 the normal by world_from_object.
    fn planted_transformed(
        ray: &Ray,
        tr: &Transform,
        range: Interval,
        local: ShapeFn,
        mistake: u8,
    ) -> Option<Hit> {
        let mut local_ray = ray_to_object(ray, &tr.object_from_world);
        let scale = if mistake == 2 { local_ray.dir.length() } else { 1.0 };
        local_ray.dir /= scale;
        let h = local(&local_ray, Interval::new(range.min * scale, range.max * scale))?;
        let outward = if mistake == 3 {
            tr.world_from_object.transform_vector3(h.outward_normal()).normalize()
        } else {
            normal_to_world(h.outward_normal(), &tr.object_from_world)
        };
        let normal = if h.front_face { outward } else { -outward };
        let point = if mistake == 0 { h.point } else { ray.at(h.t) };
        Some(match mistake {
            1 => Hit { normal, point, ..Hit::new(ray, h.t, outward) },
            _ => Hit { point, normal, ..h },
        })
    }

    #[test]
    fn transformed_mistakes() {
        assert!(transformed_cases(|r, t, i, l| planted_transformed(r, t, i, l, 9)).is_ok());
        assert!(extreme_scale(|r, t, i, l| planted_transformed(r, t, i, l, 9)).is_ok());
        caught(transformed_cases(|r, t, i, l| planted_transformed(r, t, i, l, 0)), "the world ray");
        caught(transformed_cases(|r, t, i, l| planted_transformed(r, t, i, l, 1)), "keep front_face, uv");
        caught(transformed_cases(|r, t, i, l| planted_transformed(r, t, i, l, 2)), "world units");
        caught(transformed_cases(|r, t, i, l| planted_transformed(r, t, i, l, 3)), "world_from_object");
        caught(extreme_scale(|r, t, i, l| planted_transformed(r, t, i, l, 2)), "world units");
        caught(extreme_scale(|r, t, i, l| planted_transformed(r, t, i, l, 3)), "(M⁻¹)ᵀ");
    }
}
