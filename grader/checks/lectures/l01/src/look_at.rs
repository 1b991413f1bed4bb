//! The checks of `look_at.rs`: look_at, its degenerate cases.

use super::common::*;

pub(super) fn f64s(v: Vec3) -> [f64; 3] {
    [v.x as f64, v.y as f64, v.z as f64]
}

pub(super) fn cross64(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// `a` normalised in f64, rescaled first so that tiny and huge vectors neither underflow nor overflow.
pub(super) fn unit64(a: [f64; 3]) -> Vec3 {
    let scale = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let a = a.map(|x| x / scale);
    let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    Vec3::new((a[0] / l) as Float, (a[1] / l) as Float, (a[2] / l) as Float)
}

/// The look-at basis (u, v, w) by its definition, in f64.
pub(super) fn basis_f64(eye: Vec3, at: Vec3, up: Vec3) -> (Vec3, Vec3, Vec3) {
    let w = unit64(f64s(eye - at));
    let u = unit64(cross64(f64s(up), f64s(w)));
    let v = unit64(cross64(f64s(w), f64s(u)));
    (u, v, w)
}

pub(super) fn columns(m: &Mat4) -> (Vec3, Vec3, Vec3, Vec4) {
    (m.x_axis.truncate(), m.y_axis.truncate(), m.z_axis.truncate(), m.w_axis)
}

pub(super) fn show_look_at(r: &Result<Mat4, CameraError>) -> String {
    match r {
        Ok(m) => {
            let (u, v, w, e) = columns(m);
            format!("Ok: u {}, v {}, w {}, last column {}", vec3(u), vec3(v), vec3(w), vec3(e.truncate()))
        }
        Err(e) => format!("Err({e:?})"),
    }
}

/// One look-at camera against its f64 basis, each likely mistake with its cause.
pub(super) fn look_at_case(look_at: LookAtFn, eye: Vec3, at: Vec3, up: Vec3) -> Result<(), Failure> {
    let case = format!("look_at(eye {}, at {}, up {})", vec3(eye), vec3(at), vec3(up));
    let (u, v, w) = basis_f64(eye, at, up);
    let expected = Mat4::from_cols(u.extend(0.0), v.extend(0.0), w.extend(0.0), eye.extend(1.0));
    let result = look_at(eye, at, up);
    let Ok(got) = result else {
        return Err(fail(
            case,
            rows(&expected),
            show_look_at(&result),
            "this camera is well defined: up is across the view",
        ));
    };
    // Positions of size ≤ 5: 8ε relative on them; unit vectors 8ε.
    let tol = TOL * 5.0;
    if near(&got, &expected, tol) {
        return Ok(());
    }
    let (gu, gv, gw, ge) = columns(&got);
    let cause = if near(&got.transpose(), &expected, tol) {
        "u, v, w and the eye are the columns of world_from_camera (Mat4::from_cols), not its rows"
    } else if near3(gw, -w, TOL) {
        "w points backwards, from at to the eye: w = (eye − at)/|eye − at| (the camera looks down −w)"
    } else if !near3(gw, w, TOL) {
        "w = (eye − at)/|eye − at|: the unit vector from at to the eye"
    } else if near3(gu, -u, TOL) {
        "u = up × w, in this order (w × up points left, not right)"
    } else if (gu.length() - 1.0).abs() > TOL {
        "normalise u = (up × w)/|up × w|: up need not be unit length or perpendicular to the view"
    } else if !near3(gu, u, TOL) {
        "u = (up × w)/|up × w|"
    } else if near3(gv, up.normalize(), TOL) && !near3(gv, v, TOL) {
        "the true up is v = w × u, not the up vector you were given"
    } else if !near3(gv, v, TOL) {
        "v = w × u (the true up, unit and perpendicular to both)"
    } else if ge.w != 1.0 {
        "the last column is (eye, 1): a point"
    } else {
        "the last column is the eye: camera space has the eye at its origin"
    };
    Err(fail(case, format!("{} (± {tol:.1e} each)", rows(&expected)), rows(&got), cause))
}

pub(super) fn look_at_cases(look_at: LookAtFn) -> CheckResult {
    let v = Vec3::new;
    // Eye on +z looking at the origin, up +y: u = x, v = y, w = z, so a translation by (0, 0, 5).
    look_at_case(look_at, v(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y)?;
    // Along +x with up y: w = −x, u = y × −x = z, v = −x × z = y.
    look_at_case(look_at, Vec3::ZERO, Vec3::X, Vec3::Y)?;
    // Straight down with up −z: w = y, u = −z × y = x, v = y × x = −z.
    look_at_case(look_at, v(0.0, 5.0, 0.0), Vec3::ZERO, -Vec3::Z)?;
    // Generic: up neither unit nor perpendicular to the view.
    look_at_case(look_at, v(1.0, 2.0, 3.0), v(-2.0, 0.0, -1.0), v(0.0, 3.0, 0.5))?;
    look_at_case(look_at, v(-3.0, 1.0, 2.0), v(0.5, -1.0, 0.25), v(0.2, -1.0, 0.1))?;
    // eye = at: no view direction.
    let p = v(1.0, 2.0, 3.0);
    let got = look_at(p, p, Vec3::Y);
    ensure(
        got == Err(CameraError::EyeAtTarget),
        "look_at(eye = at = (1, 2, 3), up +y)",
        "Err(EyeAtTarget)",
        show_look_at(&got),
        "eye = at has no view direction: return CameraError::EyeAtTarget before normalising eye − at",
    )?;
    Ok("5 cameras and eye = at".into())
}

/// Fails unless `got` is an error or a right-handed orthonormal basis with
/// the right w, each within [`BASIS_TOL`], and a finite matrix.
pub(super) fn error_or_basis(
    case: &str,
    got: &Result<Mat4, CameraError>,
    eye: Vec3,
    at: Vec3,
    cause: &str,
) -> Result<(), Failure> {
    let Ok(m) = got else { return Ok(()) };
    let (u, v, w, e) = columns(m);
    let w_exact = unit64(f64s(eye - at));
    let worst = [
        (u.length() - 1.0).abs(),
        (v.length() - 1.0).abs(),
        (w.length() - 1.0).abs(),
        u.dot(v).abs(),
        v.dot(w).abs(),
        w.dot(u).abs(),
        (u.cross(v) - w).abs().max_element(),
        (w - w_exact).abs().max_element(),
    ]
    .into_iter()
    // A NaN anywhere stays (f32::max would drop it at the next number).
    .fold(0.0, |m: Float, x| if m.is_nan() || x.is_nan() { Float::NAN } else { m.max(x) });
    let ok = m.is_finite() && worst <= BASIS_TOL && e == eye.extend(1.0);
    ensure(
        ok,
        case,
        format!("an error, or u, v, w orthonormal with w = {} within {BASIS_TOL:.0e}", vec3(w_exact)),
        format!("{} (off by {worst:.1e})", show_look_at(got)),
        cause,
    )
}

pub(super) fn look_at_degenerate(look_at: LookAtFn) -> CheckResult {
    const PARALLEL: &str = "up × w is zero when up is parallel to the view: return \
        CameraError::UpParallelToView instead of normalising a zero vector (NaN)";
    const CANCEL: &str = "with up nearly parallel to the view, up × w cancels and loses digits: make u \
        perpendicular to w again (u − (u·w)w, normalised) or reject |up × w| ≤ 1e-6·|up|";
    let v = Vec3::new;
    // 1. Up exactly parallel to the view, either way, or zero: an error, never NaN.
    let (eye, at) = (v(1.0, 2.0, 3.0), v(4.0, -2.0, 3.0));
    let view = at - eye;
    for (eye, at, up) in [
        (eye, at, view),
        (eye, at, -2.5 * view),
        (eye, at, Vec3::ZERO),
        (v(0.0, 5.0, 0.0), Vec3::ZERO, Vec3::Y),
        (v(0.0, -5.0, 0.0), Vec3::ZERO, Vec3::Y),
    ] {
        let got = look_at(eye, at, up);
        ensure(
            got == Err(CameraError::UpParallelToView),
            format!("look_at(eye {}, at {}, up {}): up parallel to the view", vec3(eye), vec3(at), vec3(up)),
            "Err(UpParallelToView)",
            show_look_at(&got),
            PARALLEL,
        )?;
    }
    // 2. Up at an angle δ to the view, generic view directions, both senses. From
    //    1e-3 rad on it is a camera; closer, an error is allowed.
    let mut checked = 0;
    for dir in [v(1.0, 2.0, 3.0), v(-0.3, 0.7, -0.2), -Vec3::Y, Vec3::Z, v(0.6, -0.8, 0.05)] {
        let dir = dir.normalize();
        let across = dir.any_orthonormal_vector();
        for delta in [1e-2 as Float, 1e-3, 1e-4, 1e-5, 3e-6] {
            let up = delta.cos() * dir + delta.sin() * across;
            for sign in [1.0, -1.0] {
                let eye = v(0.5, -1.0, 2.0);
                let at = eye + sign * dir;
                let case = format!(
                    "look_at(eye {}, at {}, up {}): up {delta:.0e} rad from the view",
                    vec3(eye),
                    vec3(at),
                    vec3(sign * up)
                );
                let got = look_at(eye, at, sign * up);
                if delta >= 1e-3 && got.is_err() {
                    return Err(fail(
                        case,
                        "a camera",
                        show_look_at(&got),
                        "1e-3 rad is far from parallel: only |up × w| ≤ 1e-6·|up| is an error",
                    ));
                }
                error_or_basis(&case, &got, eye, at, CANCEL)?;
                checked += 1;
            }
        }
    }
    // 3. Views near −z (eye just off the z axis), up +y: bases near the identity.
    for off in [1e-2, 1e-4, 1e-6, 1e-8] {
        for eye in [v(off, 0.0, 5.0), v(-off, off, 5.0), v(0.0, off, 5.0)] {
            let case = format!("look_at(eye {}, at the origin, up +y): a view near −z", vec3(eye));
            let got = look_at(eye, Vec3::ZERO, Vec3::Y);
            if got.is_err() {
                return Err(fail(
                    case,
                    "a camera",
                    show_look_at(&got),
                    "a view near −z with up +y is an ordinary camera",
                ));
            }
            error_or_basis(
                &case,
                &got,
                eye,
                Vec3::ZERO,
                "u = (up × w)/|up × w|, v = w × u: an orthonormal basis",
            )?;
            checked += 1;
        }
    }
    // 4. Tiny and huge distances: |eye − at|² underflows or overflows.
    let (tiny, huge) = (Float::MIN_POSITIVE.sqrt() * 1e-10, Float::MAX.sqrt() * 1e3);
    for d in [tiny, huge] {
        for (eye, up) in [(v(0.0, 0.0, d), Vec3::Y), (v(d, d, 0.0), Vec3::Z)] {
            let case = format!("look_at(eye {}, at the origin, up {})", vec3(eye), vec3(up));
            let got = look_at(eye, Vec3::ZERO, up);
            error_or_basis(
                &case,
                &got,
                eye,
                Vec3::ZERO,
                "|eye − at|² underflows or overflows at this distance: rescale eye − at by its largest \
                    component before normalising",
            )?;
            checked += 1;
        }
    }
    // 5. The threshold is relative to |up|: eye − at along (1, 1, 0) and up = (1, 1, 10⁻⁶), so
    //    |up × w| = 10⁻⁶ (to a few ε) against 1e-6·|up| = 1.41·10⁻⁶: an error, by a margin of
    //    40 %. (1e-6/|up| = 0.71·10⁻⁶ would make it a camera.)
    let (eye, at, up) = (v(1.0, 1.0, 0.0), Vec3::ZERO, v(1.0, 1.0, 1e-6));
    let got = look_at(eye, at, up);
    ensure(
        got == Err(CameraError::UpParallelToView),
        format!("look_at(eye {}, at the origin, up {}): |up × w| = 1e-6, |up| = √2", vec3(eye), vec3(up)),
        "Err(UpParallelToView)",
        show_look_at(&got),
        "the threshold is relative: an error when |up × w| ≤ 1e-6·|up|, and here |up| = √2",
    )?;
    // 6. A huge up is still up: (0, MAX/4, 0) from +z, the identity's axes (up × w overflows
    //    unless up is rescaled first).
    look_at_case(look_at, v(0.0, 0.0, 5.0), Vec3::ZERO, v(0.0, Float::MAX / 4.0, 0.0))?;
    // 7. A NaN or infinite input, the up vector's included: an error, never a NaN matrix.
    let (nan, inf) = (Float::NAN, Float::INFINITY);
    for (eye, at, up) in [
        (v(nan, 0.0, 5.0), Vec3::ZERO, Vec3::Y),
        (v(0.0, 0.0, 5.0), v(0.0, inf, 0.0), Vec3::Y),
        (v(0.0, 0.0, 5.0), Vec3::ZERO, v(nan, 1.0, 0.0)),
        (v(0.0, 0.0, 5.0), Vec3::ZERO, v(inf, 1.0, 0.0)),
    ] {
        let got = look_at(eye, at, up);
        ensure(
            got == Err(CameraError::NotFinite),
            format!("look_at(eye {}, at {}, up {})", vec3(eye), vec3(at), vec3(up)),
            "Err(NotFinite)",
            show_look_at(&got),
            "a NaN or infinite eye, at or up is CameraError::NotFinite: test all three with is_finite first",
        )?;
    }
    Ok(format!(
        "5 parallel ups are errors, {checked} near-degenerate cameras are orthonormal within \
            {BASIS_TOL:.0e}; the threshold relative to |up|, a huge up, 4 non-finite inputs"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l01_transforms::CameraError;
    use raylab::{Float, Mat4, Vec3};

    /// look_at built step by step, with switches for the classic mistakes.
    #[derive(Clone, Copy, Default)]
    struct LookAt {
        backwards: bool,
        w_cross_up: bool,
        v_is_up: bool,
        u_unnormalised: bool,
        no_parallel_check: bool,
        no_gram_schmidt: bool,
    }

    impl LookAt {
        fn build(self, eye: Vec3, at: Vec3, up: Vec3) -> Result<Mat4, CameraError> {
            if eye == at {
                return Err(CameraError::EyeAtTarget);
            }
            let w = if self.backwards { at - eye } else { eye - at }.normalize();
            let right = if self.w_cross_up { w.cross(up) } else { up.cross(w) };
            if !self.no_parallel_check && right.length() <= 1e-6 * up.length() {
                return Err(CameraError::UpParallelToView);
            }
            let mut u = if self.u_unnormalised { right } else { right.normalize() };
            if !self.no_gram_schmidt && !self.u_unnormalised {
                u = (u - u.dot(w) * w).normalize();
            }
            let v = if self.v_is_up { up } else { w.cross(u) };
            Ok(Mat4::from_cols(u.extend(0.0), v.extend(0.0), w.extend(0.0), eye.extend(1.0)))
        }
    }

    thread_local! {
        static PLANTED: std::cell::Cell<LookAt> = std::cell::Cell::new(LookAt::default());
    }

    fn planted(eye: Vec3, at: Vec3, up: Vec3) -> Result<Mat4, CameraError> {
        PLANTED.with(|p| p.get()).build(eye, at, up)
    }

    fn with(mistake: LookAt) -> LookAtFn {
        PLANTED.with(|p| p.set(mistake));
        planted
    }

    #[test]
    fn look_at_mistakes() {
        // The step-by-step build without mistakes passes the unit check (it does not rescale).
        assert!(look_at_cases(with(LookAt::default())).is_ok());
        caught(look_at_cases(with(LookAt { backwards: true, ..LookAt::default() })), "backwards");
        caught(look_at_cases(with(LookAt { w_cross_up: true, ..LookAt::default() })), "in this order");
        caught(look_at_cases(with(LookAt { v_is_up: true, ..LookAt::default() })), "the true up");
        caught(look_at_cases(with(LookAt { u_unnormalised: true, ..LookAt::default() })), "normalise u");
        caught(
            look_at_cases(|e, a, u| l01_transforms::look_at(e, a, u).map(|m| m.transpose())),
            "not its rows",
        );
        caught(
            look_at_cases(|e, a, u| {
                l01_transforms::look_at(e, a, u).map(|mut m| {
                    m.w_axis.w = 0.0;
                    m
                })
            }),
            "(eye, 1)",
        );
        let no_check = LookAt { no_parallel_check: true, ..LookAt::default() };
        caught(look_at_degenerate(with(no_check)), "UpParallelToView");
        // Without rescaling, |eye − at|² underflows for tiny distances.
        caught(look_at_degenerate(with(LookAt::default())), "rescale");
        // Without the Gram–Schmidt step, u drifts off ⟂ w by ~ε/δ: 1e-2 at δ = 1e-5 in f32
        // (in f64 the drift, 2e-11, is within the bound: the mistake costs nothing there).
        if Float::EPSILON > 1e-10 {
            caught(
                look_at_degenerate(with(LookAt { no_gram_schmidt: true, ..LookAt::default() })),
                "cancels",
            );
        }
    }
}
