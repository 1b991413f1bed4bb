//! The checks of `refract.rs`: interface, refract, the critical angle and the tiny glass sphere.

use super::common::*;
use raylab_testing::refraction::{ExactlyOne, sin2_t_exactly_one};

pub(super) fn interface_cases(interface: InterfaceFn) -> CheckResult {
    let show = |s: &Interface| {
        format!(
            "normal {}, η_i = {}, η_t = {}, entering {}",
            vec3(s.normal),
            num(s.eta_i),
            num(s.eta_t),
            s.entering
        )
    };
    for ior in [1.5, 2.4] {
        // From (0, 0, 5) down −z onto the sphere's top (0, 0, 1), outward normal +z: entering.
        let ray = Ray::new(v(0.0, 0.0, 5.0), -Vec3::Z);
        let hit = Hit::new(&ray, 4.0, Vec3::Z);
        let expected = Interface { normal: Vec3::Z, eta_i: 1.0, eta_t: ior, entering: true };
        let case = format!("ray from (0, 0, 5) along −z, outside a sphere of ior {ior}, front face");
        let got = interface(&hit, ior);
        check_interface(&case, &got, &expected, show)?;
        // From the centre out along +z: the same point from inside, so the hit's normal is −z.
        let ray = Ray::new(Vec3::ZERO, Vec3::Z);
        let hit = Hit::new(&ray, 1.0, Vec3::Z);
        let expected = Interface { normal: -Vec3::Z, eta_i: ior, eta_t: 1.0, entering: false };
        let case = format!("ray from the centre along +z, inside a sphere of ior {ior}, back face");
        let got = interface(&hit, ior);
        check_interface(&case, &got, &expected, show)?;
    }
    Ok("4 cases".into())
}

pub(super) fn check_interface(
    case: &str,
    got: &Interface,
    expected: &Interface,
    show: impl Fn(&Interface) -> String,
) -> Result<(), crate::check::Failure> {
    let cause = if got.normal != expected.normal {
        if got.normal == -expected.normal {
            "use hit.normal, which already faces the ray: the outward normal points the wrong way for a ray leaving"
        } else {
            "the interface's normal is hit.normal as it is"
        }
    } else if got.eta_i == expected.eta_t && got.eta_t == expected.eta_i {
        "from outside (front face) η_i = 1 (vacuum) and η_t = ior; from inside the two swap"
    } else if got.entering != expected.entering {
        "entering is hit.front_face: a ray arriving at the front face goes into the object"
    } else {
        "η_i is the index on the ray's side, η_t on the other: 1 outside, ior inside"
    };
    ensure(got == expected, case, show(expected), show(got), cause)
}

/// t = η i + (η cos θ_i − cos θ_t) n by hand and Snell's law against f64.
pub(super) fn refract_cases(refract: RefractFn) -> CheckResult {
    // Air to glass at 30°: i = (½, −√3/2, 0), η = 1/1.5: sin θ_t = ½/1.5 = ⅓,
    // cos θ_t = √(1 − 1/9) = 2√2/3, so t = (1/3, −2√2/3, 0). Tolerance 8ε: √3/2 rounded,
    // then about six roundings of values ≤ 1.
    let case = "i = (0.5, −0.8660, 0) onto n = +y (30°), η = 1/1.5 (air to glass)";
    let i = v(0.5, -(3.0 as Float).sqrt() / 2.0, 0.0);
    let expected = v(1.0 / 3.0, -(8.0 as Float).sqrt() / 3.0, 0.0);
    let got = refract(i, Vec3::Y, 1.0 / 1.5);
    let Some(t) = got else {
        return Err(fail(
            case,
            vec3(expected),
            show(&got),
            "into a denser medium (η < 1) there is no total internal reflection: TIR only when sin²θ_t = η²(1 − cos²θ_i) ≥ 1",
        ));
    };
    let cause = if (t.x - 0.75).abs() < 1e-3 {
        "eta_ratio is already η_i/η_t (here 1/1.5): use it as given, do not invert it"
    } else if !t.is_finite() {
        "clamp cos θ_i = −i·n to [0, 1] and take the square root only when sin²θ_t < 1"
    } else if (t.length() - 1.0).abs() > 1e-3 {
        "cos θ_i = −i·n (i points toward the surface, n against it), so that |t| = 1"
    } else if t.y > 0.0 {
        "the transmitted ray goes through the surface: its normal part is −cos θ_t·n"
    } else {
        "t = η·i + (η·cos θ_i − cos θ_t)·n with cos θ_i = −i·n"
    };
    close3(case, t, expected, 8.0 * EPS, cause)?;
    // Normal incidence: cos θ_i = 1, cos θ_t = 1, t = ηi + (η − 1)n = −n for every η.
    // Tolerance 8ε: the tilted normal is rounded, and ηi + (η − 1)n rounds a few times.
    for n in [Vec3::Y, v(1.0, 2.0, -2.0) / 3.0] {
        for eta in [1.0 / 1.5, 1.5, 2.4] {
            let case = format!("i = −n at normal incidence, n = {}, η = {}", vec3(n), num(eta));
            let got = refract(-n, n, eta);
            let t = got.unwrap_or(Vec3::NAN);
            close3(case, t, -n, 8.0 * EPS, "at normal incidence the ray goes straight through: t = −n")?;
        }
    }
    // η = 1: no bending, t = i. Tolerance 8ε + ε/cos θ_i: √(1 − (1 − cos²θ_i)) cancels.
    for degrees in [10.0, 45.0, 80.0] {
        let i = incoming(degrees);
        let case = format!("i at {degrees}° onto n = +y, η = 1 (the same medium on both sides)");
        let t = refract(i, Vec3::Y, 1.0).unwrap_or(Vec3::NAN);
        let tolerance = 8.0 * EPS + EPS / cos_deg(degrees);
        close3(case, t, i, tolerance, "with η = 1, sin θ_t = sin θ_i and t = i")?;
    }
    // Glass to air at 45°: sin²θ_t = 2.25·½ = 1.125 ≥ 1, total internal reflection.
    let case = "i at 45° onto n = +y, η = 1.5 (glass to air), sin²θ_t = 1.125";
    let got = refract(incoming(45.0), Vec3::Y, 1.5);
    ensure(
        got.is_none(),
        case,
        "None (total internal reflection)",
        show(&got),
        "past the critical angle (sin²θ_t = η²(1 − cos²θ_i) ≥ 1) there is no transmitted ray: return None",
    )?;
    // A sweep: |t| = 1 (4ε), t in the plane of i and n, through the surface, and Snell's
    // η sin θ_i = sin θ_t checked in f64 (16ε); None exactly when η² sin²θ_i > 1 in f64
    // (cases within 10⁻⁴ of 1 left to the critical-angle check).
    let mut count = 0;
    for eta in [1.0 / 2.4, 1.0 / 1.5, 1.1, 1.5, 2.4] {
        for degrees in (0..=89).map(f64::from) {
            let i = incoming(degrees);
            let [ix, iy, _] = wide3(i);
            let sin_i = ix.abs() / ix.hypot(iy);
            let sin2_t = (wide(eta) * sin_i).powi(2);
            if (sin2_t - 1.0).abs() < 1e-4 {
                continue;
            }
            count += 1;
            let case = format!("i at {degrees}° onto n = +y, η = {}", num(eta));
            let got = refract(i, Vec3::Y, eta);
            let Some(t) = got else {
                ensure(sin2_t > 1.0, &case, "a transmitted ray", "None", "None only when sin²θ_t ≥ 1")?;
                continue;
            };
            ensure(
                sin2_t < 1.0,
                &case,
                "None (total internal reflection)",
                vec3(t),
                "past the critical angle (sin²θ_t ≥ 1) return None",
            )?;
            let [tx, ty, tz] = wide3(t);
            let unit = (t.length() - 1.0).abs() <= 4.0 * EPS;
            let through = tz == 0.0 && ty < 0.0;
            let snell = (tx.abs() / tx.hypot(ty) - wide(eta) * sin_i).abs() <= 16.0 * wide(EPS);
            ensure(
                unit && through && snell,
                &case,
                format!("unit, through the surface, sin θ_t = {:.6}", wide(eta) * sin_i),
                format!("{}, |t| = {}", vec3(t), num(t.length())),
                "t = η·i + (η·cos θ_i − cos θ_t)·n, cos θ_t = √(1 − η²(1 − cos²θ_i))",
            )?;
        }
    }
    Ok(format!("{} cases", count + 11))
}

/// The extremes of refraction: the critical angle ± 0.001°, sin²θ_t rounding to
/// exactly 1, normal incidence, and i·n rounded past 0 or −1.
pub(super) fn critical_angle(refract: RefractFn) -> CheckResult {
    // Glass to air, η = 1.5: θ_c = arcsin(1/1.5) = 41.8103149°. 0.001° below it the
    // expected cos θ_t = √(1 − η² sin²θ_i) is computed in f64 from the rounded i:
    // about 6.2·10⁻³, a ray leaving nearly along the surface. Tolerance 2 % of it: in
    // f32, 1 − sin²θ_t ≈ 3.9·10⁻⁵ carries an absolute error of a few ε, 1 % of it.
    let critical = (1.0 / 1.5f64).asin().to_degrees();
    let i = incoming(critical - 0.001);
    let case = "glass to air (η = 1.5) at 0.001° below the critical angle 41.8103°";
    let [ix, iy, _] = wide3(i);
    let sin2_t = 2.25 * ix * ix / (ix * ix + iy * iy);
    let expected_cos_t = (1.0 - sin2_t).sqrt();
    let got = refract(i, Vec3::Y, 1.5);
    let Some(t) = got else {
        return Err(fail(
            case,
            format!("a ray with cos θ_t = {expected_cos_t:.4e}"),
            show(&got),
            "just below θ_c, sin²θ_t < 1: only sin²θ_t ≥ 1 is total internal reflection",
        ));
    };
    close(
        format!("{case}: cos θ_t = −t·n"),
        -t.y,
        expected_cos_t as Float,
        0.02 * expected_cos_t as Float,
        "cos θ_t = √(1 − η²(1 − cos²θ_i)), the normal part of t is −cos θ_t·n",
    )?;
    close(
        format!("{case}: the length |t|"),
        t.length(),
        1.0,
        4.0 * EPS,
        "t = η·i + (η·cos θ_i − cos θ_t)·n is unit",
    )?;
    // 0.001° above: sin²θ_t ≈ 1 + 3.9·10⁻⁵, total internal reflection; also at grazing.
    for (case, i) in [
        ("glass to air at 0.001° above the critical angle", incoming(critical + 0.001)),
        ("glass to air at grazing incidence (90°)", incoming(90.0)),
    ] {
        let got = refract(i, Vec3::Y, 1.5);
        ensure(
            got.is_none(),
            case,
            "None (total internal reflection)",
            show(&got),
            "past the critical angle (sin²θ_t ≥ 1) there is no transmitted ray: return None",
        )?;
    }
    // sin²θ_t = (η·η)(1 − cos θ_i·cos θ_i) rounding to exactly 1: cos θ_i = k/64 (so
    // 1 − cos²θ_i is exact) and η among the floats nearest 1/sin θ_i. Exactly 1 is
    // θ_t = 90°: None. The product is evaluated as the contract states it.
    let mut exact_ones = 0;
    for ExactlyOne { k, i, eta, .. } in sin2_t_exactly_one() {
        exact_ones += 1;
        let case = format!("cos θ_i = {k}/64, η = {eta:e}: sin²θ_t = (η·η)(1 − cos²θ_i) is exactly 1");
        let got = refract(i, Vec3::Y, eta);
        ensure(
            got.is_none(),
            case,
            "None (θ_t = 90°)",
            show(&got),
            "sin²θ_t = 1 means θ_t = 90°, no transmitted ray: test sin²θ_t ≥ 1, not > 1",
        )?;
    }
    // Normal incidence for η from 1/2.4 to 2.4: t = −n, finite. Tolerance 8ε as in the unit check.
    for eta in [1.0 / 2.4, 1.0 / 1.5, 1.0, 1.5, 2.4] {
        let n = v(2.0, -3.0, 6.0) / 7.0;
        let case = format!("i = −n at normal incidence, n = (2, −3, 6)/7, η = {}", num(eta));
        let t = refract(-n, n, eta).unwrap_or(Vec3::NAN);
        close3(case, t, -n, 8.0 * EPS, "at normal incidence t = −n, for every η")?;
    }
    // i·n rounded a little above 0 (grazing) or below −1 (normal): finite and unit, or None.
    let grazing = v(1.0, 4.0 * EPS, 0.0).normalize();
    let straight = -Vec3::Y * (1.0 + 2.0 * EPS);
    for (what, i) in [("i·n > 0 by rounding (grazing)", grazing), ("i·n < −1 by rounding (normal)", straight)]
    {
        for eta in [1.0 / 1.5, 1.0, 1.5] {
            let case = format!("i = {} onto n = +y, {what}, η = {}", vec3(i), num(eta));
            if let Some(t) = refract(i, Vec3::Y, eta) {
                ensure(
                    t.is_finite() && (t.length() - 1.0).abs() <= 8.0 * EPS,
                    case,
                    format!("a finite t of length 1 (± 8ε = {:.1e}), or None", 8.0 * EPS),
                    vec3(t),
                    "clamp cos θ_i = −i·n to [0, 1] first: rounding takes it past the ends",
                )?;
            }
        }
    }
    Ok(format!("critical angle ± 0.001°, {exact_ones} cases of sin²θ_t = 1 exactly, normal and grazing"))
}

/// The offset of lecture 06 (`offset_origin`), restated here so that this
/// lecture's check needs no later lecture: p moved along ±n (the side `dir`
/// leaves to) by 8ε(|p|₁ + |from|₁) + the smallest normal float.
pub(super) fn offset(p: Vec3, n: Vec3, dir: Vec3, from: Vec3) -> Vec3 {
    let d = 8.0 * EPS * (p.abs().element_sum() + from.abs().element_sum()) + Float::MIN_POSITIVE;
    if dir.dot(n) < 0.0 { p - d * n } else { p + d * n }
}

/// Through a glass sphere in f64: the entry point, the exit point and the
/// direction out, for the ray (o, d) (d unit) that hits it.
pub(super) fn through_sphere_f64(
    o: [f64; 3],
    d: [f64; 3],
    c: [f64; 3],
    r: f64,
    eta: f64,
) -> ([f64; 3], [f64; 3], [f64; 3]) {
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let at = |o: [f64; 3], d: [f64; 3], t: f64| [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let scale = |a: [f64; 3], s: f64| [a[0] * s, a[1] * s, a[2] * s];
    let add = |a: [f64; 3], b: [f64; 3]| [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
    // Snell in vector form with n facing the ray and η = η_i/η_t.
    let bend = |i: [f64; 3], n: [f64; 3], eta: f64| {
        let cos_i = -dot(i, n);
        let cos_t = (1.0 - eta * eta * (1.0 - cos_i * cos_i)).sqrt();
        add(scale(i, eta), scale(n, eta * cos_i - cos_t))
    };
    // Entry: the near root of |o + t·d − c|² = r², geometrically (f = o − c).
    let f = sub(o, c);
    let tca = -dot(f, d);
    let off = sub(f, scale(d, -tca));
    let half_chord = (r * r - dot(off, off)).sqrt();
    let entry = at(o, d, tca - half_chord);
    let n1 = scale(sub(entry, c), 1.0 / r);
    let inside = bend(d, n1, 1.0 / eta);
    // Exit: the chord from the entry along `inside` has length −2(inside·n1)·r.
    let exit = at(entry, inside, -2.0 * dot(inside, n1) * r);
    let n2 = scale(sub(c, exit), 1.0 / r); // facing the ray from inside
    (entry, exit, bend(inside, n2, eta))
}

/// A glass bead of radius 10⁻⁵ at 0.1 from the eye: for rays over its disc, entry by
/// 02's sphere, `interface` and `refract`, a start just inside (06's offset, restated),
/// the exit by 02's sphere again, `interface` and `refract` out. The exit point and
/// the direction out are compared with the same path traced in f64.
pub(super) fn tiny_glass_sphere(refract: RefractFn, interface: InterfaceFn) -> CheckResult {
    let r: Float = 1e-5;
    let center = v(0.0, 0.0, -0.1);
    let eye = Vec3::ZERO;
    let all = Interval::new(0.0, Float::INFINITY);
    // Error budget in f32: the hit points carry a few ulp of 0.1 (ulp = 7.5·10⁻⁹), i.e.
    // ~0.3 % of r; the normals (p − c)/r inherit that as ~3·10⁻³ rad, and two refractions
    // and a chord of ≤ 2r carry it to the exit: a few 10⁻³ r and 10⁻² rad at worst.
    // Tolerances: the exit within 0.05·r, the direction out within 0.03 (component-wise).
    let point_tolerance = 0.05 * r;
    let direction_tolerance: Float = 0.03;
    let (mut worst_point, mut worst_dir): (Float, Float) = (0.0, 0.0);
    let rays = 48;
    for k in 0..rays {
        // Aim at points of the bead's disc out to 0.9 r, around it.
        let angle = k as Float * 0.7;
        let reach = 0.9 * r * ((k % 8) as Float + 0.5) / 8.0;
        let aim = center + v(angle.cos(), angle.sin(), 0.0) * reach;
        let d = (aim - eye).normalize();
        let ray = Ray::new(eye, d);
        let case = format!(
            "ray from the origin along {} into a glass bead r = 10⁻⁵ at (0, 0, −0.1), ior 1.5",
            vec3(d)
        );
        let Some(entry) = hit_sphere_stable(&ray, center, r, all) else {
            return Err(fail(
                case,
                "a hit",
                "None",
                "02's hit_sphere_stable misses a small sphere: run 02's checks",
            ));
        };
        let into = interface(&entry, 1.5);
        let Some(inside) = refract(d, into.normal, into.eta_ratio()) else {
            return Err(fail(
                case,
                "a refracted ray into the glass",
                "None (total internal reflection)",
                "entering glass from air never reflects totally: η = η_i/η_t = 1/1.5",
            ));
        };
        ensure(
            inside.dot(entry.normal) < 0.0,
            &case,
            "a refracted ray going into the bead (t·n < 0)",
            vec3(inside),
            "the transmitted ray goes through the surface: t = η·i + (η·cos θ_i − cos θ_t)·n",
        )?;
        let start = offset(entry.point, entry.normal, inside, eye);
        let second = Ray::new(start, inside);
        let found = hit_sphere_stable(&second, center, r, all);
        let show_hit = |h: &Option<Hit>| maybe(h, |h| format!("t = {:e}, front_face {}", h.t, h.front_face));
        let Some(exit) = found.filter(|h| !h.front_face && h.t > 0.1 * r) else {
            return Err(fail(
                case,
                "the far side of the bead, from inside",
                show_hit(&found),
                "the refracted ray must go into the bead, away from the entry: refract with the normal facing the ray",
            ));
        };
        let out_of = interface(&exit, 1.5);
        let Some(out) = refract(inside, out_of.normal, out_of.eta_ratio()) else {
            return Err(fail(
                case,
                "a ray out of the bead (the path reversed is no TIR)",
                "None (total internal reflection)",
                "leaving glass, η = ior/1 and the normal is hit.normal, facing the ray from inside",
            ));
        };
        let (_, exit_f64, out_f64) = through_sphere_f64(wide3(eye), wide3(d), wide3(center), wide(r), 1.5);
        let exit_expected = v(exit_f64[0] as Float, exit_f64[1] as Float, exit_f64[2] as Float);
        let out_expected = v(out_f64[0] as Float, out_f64[1] as Float, out_f64[2] as Float);
        worst_point = worst_point.max((exit.point - exit_expected).abs().max_element() / r);
        worst_dir = worst_dir.max((out - out_expected).abs().max_element());
        close3(
            &case,
            exit.point,
            exit_expected,
            point_tolerance,
            "the exit: refract with interface(hit, ior) at the entry (η = 1/1.5) and the far side found from just inside",
        )?;
        close3(
            &case,
            out,
            out_expected,
            direction_tolerance,
            "leaving the bead η = 1.5/1 with hit.normal facing the ray from inside: interface() swaps the indices",
        )?;
    }
    Ok(format!("{rays} rays, exit within {worst_point:.1e} r, direction within {worst_dir:.1e}"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l07_reflection_refraction::{Interface, interface, refract};
    use raylab::{Float, Hit, Vec3};

    #[test]
    fn interface_mistakes_are_caught() {
        // The outward normal from inside.
        caught(
            interface_cases(|h: &Hit, ior| Interface { normal: h.outward_normal(), ..interface(h, ior) }),
            "outward normal",
        );
        // η swapped: ior outside, 1 inside.
        caught(
            interface_cases(|h: &Hit, ior| {
                let s = interface(h, ior);
                Interface { eta_i: s.eta_t, eta_t: s.eta_i, ..s }
            }),
            "the two swap",
        );
        // entering inverted.
        caught(
            interface_cases(|h: &Hit, ior| Interface { entering: !h.front_face, ..interface(h, ior) }),
            "front_face",
        );
    }

    /// The slips planted in the copy of the reference refraction.
    #[derive(Clone, Copy, PartialEq, Eq)]
    enum RefractSlip {
        Faithful,
        /// η inverted: η_t/η_i for η_i/η_t.
        InvertedEta,
        /// cos θ_i = i·n, not −i·n.
        CosSign,
        /// + cos θ_t: the ray goes through the surface the wrong way.
        Plus,
        /// No total internal reflection.
        NoTir,
        /// Total internal reflection only when sin² θ_t > 1, not ≥ 1.
        Strict,
    }

    /// Refraction with a chosen slip.
    fn refract_with(i: Vec3, n: Vec3, eta: Float, slip: RefractSlip) -> Option<Vec3> {
        let eta = if slip == RefractSlip::InvertedEta { 1.0 / eta } else { eta };
        let cos_i =
            if slip == RefractSlip::CosSign { i.dot(n).clamp(0.0, 1.0) } else { (-i.dot(n)).clamp(0.0, 1.0) };
        let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
        let tir = if slip == RefractSlip::Strict { sin2_t > 1.0 } else { sin2_t >= 1.0 };
        if tir && slip != RefractSlip::NoTir {
            return None;
        }
        let cos_t = (1.0 - sin2_t).sqrt();
        if slip == RefractSlip::Plus {
            return Some(eta * i + (eta * cos_i + cos_t) * n);
        }
        Some(eta * i + (eta * cos_i - cos_t) * n)
    }

    #[test]
    fn refract_mistakes_are_caught() {
        caught(refract_cases(|i, n, e| refract_with(i, n, e, RefractSlip::InvertedEta)), "do not invert");
        caught(refract_cases(|i, n, e| refract_with(i, n, e, RefractSlip::CosSign)), "cos θ_i = −i·n");
        caught(refract_cases(|i, n, e| refract_with(i, n, e, RefractSlip::Plus)), "goes through the surface");
        caught(refract_cases(|i, n, e| refract_with(i, n, e, RefractSlip::NoTir)), "return None");
        caught(critical_angle(|i, n, e| refract_with(i, n, e, RefractSlip::Strict)), "not > 1");
        caught(
            tiny_glass_sphere(|i, n, e| refract_with(i, n, e, RefractSlip::Plus), interface),
            "goes through the surface",
        );
        // The reference formula with no slip passes all three.
        let fine = |i, n, e| refract_with(i, n, e, RefractSlip::Faithful);
        assert!(refract_cases(fine).is_ok() && critical_angle(fine).is_ok());
    }

    #[test]
    fn a_tiny_sphere_catches_the_outward_normal_at_the_exit() {
        // With the outward normal at the exit, refract sees i·n > 0 and the ray does not leave
        // the bead where it should.
        let outward = |h: &Hit, ior| Interface { normal: h.outward_normal(), ..interface(h, ior) };
        assert!(tiny_glass_sphere(refract, outward).is_err());
        // With the indices never swapped the ray leaves bent the wrong way.
        let same = |h: &Hit, ior| Interface { eta_i: 1.0, eta_t: ior, ..interface(h, ior) };
        caught(tiny_glass_sphere(refract, same), "swaps the indices");
    }
}
