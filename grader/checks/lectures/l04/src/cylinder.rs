//! The checks of `cylinder.rs`: hit_cylinder, and what the cone's checks share with it (the rim rays, the far-origin case).

use super::common::*;

/// Expects a hit at `t` (relative TOL) with `normal` (absolute TOL) and `front`.
pub(super) fn expect_hit(
    case: &str,
    got: Option<Hit>,
    t: Float,
    normal: Vec3,
    front: bool,
    causes: &[(Vec3, &str)],
    miss: &str,
) -> Result<(), Failure> {
    let Some(h) = got else {
        return Err(fail(case, format!("t = {}, normal {}", num(t), vec3(normal)), "None (no hit)", miss));
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

pub(super) const FROM_INSIDE: &str =
    "from inside the normal faces the ray: build the hit with Hit::new(ray, t, outward normal)";
pub(super) const DIR_UNITS: &str = "t is in units of dir: do not normalise the direction";

/// Rays aimed at rim points from outside, entering exactly there at t = 1;
/// returns (origin, rim point, the two admissible outward normals).
pub(super) fn rim_rays(cone: bool) -> Vec<(Vec3, Vec3, Vec3, Vec3)> {
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
pub(super) fn no_rim_leaks(hit: ShapeFn, cone: bool) -> Result<(), Failure> {
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
    // Parallel to the axis in the side itself (a = 0, c = 0): from (1, 0, −1) up, the solid is
    // where the slab cuts the line, entered at the base's rim at t = 1 (a rim: −z or +x).
    let r = ray([1.0, 0.0, -1.0], [0.0, 0.0, 1.0]);
    let got = hit(&r, ALL);
    let Some(h) = got else {
        return Err(fail(case(&r), "t = 1 at the rim (1, 0, 0)", "None (no hit)", axis_parallel));
    };
    close(case(&r), h.t, 1.0, TOL, axis_parallel)?;
    let rim = near3(h.normal, -Vec3::Z, TOL) || near3(h.normal, Vec3::X, TOL);
    ensure(
        rim,
        case(&r),
        "the normal −z or +x (a rim)",
        vec3(h.normal),
        "a ray on the side is inside the closed cylinder",
    )?;
    // From just inside the side (x = −0.9999) out along +x: the far root t = 1 − x (in f64) is
    // free of cancellation, c ≈ −2·10⁻⁴ notwithstanding.
    let x0: Float = -0.9999;
    let r = ray([x0, 0.0, 0.5], [1.0, 0.0, 0.0]);
    expect_hit(
        &case(&r),
        hit(&r, ALL),
        (1.0 - x0 as f64) as Float,
        -Vec3::X,
        false,
        &[],
        "the far root loses nothing to cancellation: q = −(b + sign(b)·√(b² − ac)) adds two numbers of one \
            sign, then t = q/a and c/q",
    )?;
    no_rim_leaks(hit, false)?;
    Ok("14 hand cases and 1,000 rim rays".into())
}

#[derive(Clone, Copy)]
pub(super) enum Quadric {
    Cylinder,
    Cone,
}

/// The side's entry t of the infinite cylinder or the cone's lower nappe, in
/// f64, for a ray from far away along +x-ish: stable roots, and the
/// discriminant from the moment (Lagrange), so f64 keeps ~16 digits.
pub(super) fn side_entry_f64(q: Quadric, o: Vec3, d: Vec3) -> f64 {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l04_quadrics_transforms::{first_crossing, slab_z_span};

    use raylab::{Float, Hit, Interval, Ray, Vec3};

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
}
