//! The look-at transform: the camera's frame from where it is, what it looks
//! at and which way is up.

use std::fmt;

use raylab::{Mat4, Vec3};

/// Why a camera could not be built.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CameraError {
    /// `eye` and `at` are the same point: there is no view direction.
    EyeAtTarget,
    /// `up` is zero or parallel to the view direction: the sideways axis is undefined.
    UpParallelToView,
    /// An input is NaN or infinite (or `eye − at` overflows).
    NotFinite,
}

impl fmt::Display for CameraError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            CameraError::EyeAtTarget => {
                "the camera's eye and the point it looks at are the same point, so it has no view direction"
            }
            CameraError::UpParallelToView => {
                "the camera's up vector is zero or parallel to the view direction (at − eye), \
                 so the image's horizontal axis is undefined; choose an up vector across the view"
            }
            CameraError::NotFinite => "a camera parameter is NaN or infinite (or eye − at overflows)",
        })
    }
}

impl std::error::Error for CameraError {}

/// The camera's frame, `world_from_camera`: the matrix with columns u, v, w
/// and eye, where
///
/// ```text
/// w = (eye − at) / |eye − at|     (backwards: the camera looks down −w, i.e. −z)
/// u = (up × w) / |up × w|          (right, +x)
/// v = w × u                        (the true up, +y)
/// ```
///
/// so camera space has the eye at the origin looking down −z, +x right and
/// +y up, and `at` lands on the negative z axis at distance |eye − at|.
/// `up` need not be unit or perpendicular to the view; only its component
/// across the view counts.
///
/// Errors, never NaN: [`CameraError::NotFinite`] for a NaN or infinite
/// input, [`CameraError::EyeAtTarget`] when eye = at, and
/// [`CameraError::UpParallelToView`] when |up × w| ≤ 1e-6·|up| (up within
/// about 1e-6 rad of the view axis, either way, or zero). Near that limit
/// the cross product loses digits to cancellation; one Gram–Schmidt step
/// makes u exactly perpendicular to w again, so the basis is orthonormal to
/// a few ε. Book: §1.6 The look-at transform.
pub fn look_at(eye: Vec3, at: Vec3, up: Vec3) -> Result<Mat4, CameraError> {
    // SOLUTION BEGIN
    if !(eye.is_finite() && at.is_finite() && up.is_finite()) {
        return Err(CameraError::NotFinite);
    }
    // The backward axis w: rescale eye − at by its largest component before
    // normalising, so tiny and huge distances neither underflow nor overflow.
    let back = eye - at;
    if !back.is_finite() {
        return Err(CameraError::NotFinite);
    }
    let scale = back.abs().max_element();
    if scale == 0.0 {
        return Err(CameraError::EyeAtTarget);
    }
    let w = (back / scale).normalize();
    // The right axis u: up × w, rejected when up is (nearly) parallel to w.
    let up_scale = up.abs().max_element();
    if up_scale == 0.0 {
        return Err(CameraError::UpParallelToView);
    }
    let up = up / up_scale;
    let right = up.cross(w);
    if right.length() <= 1e-6 * up.length() {
        return Err(CameraError::UpParallelToView);
    }
    let u = right.normalize();
    // Re-orthogonalise u against w (Gram–Schmidt), then the true up v.
    let u = (u - u.dot(w) * w).normalize();
    let v = w.cross(u);
    Ok(Mat4::from_cols(u.extend(0.0), v.extend(0.0), w.extend(0.0), eye.extend(1.0)))
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::assert_orthonormal;
    use crate::transforms::transform_point;
    use approx::assert_abs_diff_eq;
    use raylab::Float;

    fn basis(m: &Mat4) -> (Vec3, Vec3, Vec3) {
        (m.x_axis.truncate(), m.y_axis.truncate(), m.z_axis.truncate())
    }

    /// A deterministic spread of cameras: eye, at and up from a small LCG.
    fn cameras() -> Vec<(Vec3, Vec3, Vec3)> {
        let mut state: u32 = 12345;
        let mut next = move || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (state >> 8) as Float / (1u32 << 24) as Float * 2.0 - 1.0
        };
        let mut v = || Vec3::new(next(), next(), next());
        (0..200).map(|_| (10.0 * v(), 10.0 * v(), v())).collect()
    }

    #[test]
    fn default_view_down_minus_z_is_a_translation() {
        // Eye on +z looking at the origin with up +y: u = x, v = y, w = z exactly.
        let m = look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y).unwrap();
        assert_eq!(m, Mat4::from_translation(Vec3::new(0.0, 0.0, 5.0)));
    }

    #[test]
    fn camera_looks_down_minus_z() {
        for (eye, at, up) in cameras() {
            let Ok(world_from_camera) = look_at(eye, at, up) else { continue };
            let camera_from_world = world_from_camera.inverse();
            // `at` is straight ahead: on the −z axis at distance |eye − at|.
            let d = (at - eye).length();
            let seen = transform_point(&camera_from_world, at);
            // Coordinates of size ≤ 40 through a general 4×4 inverse of a
            // rigid map: a few dozen ε relative, so 64ε·40 (3e-4 in f32).
            let tol = 64.0 * Float::EPSILON * 40.0;
            assert_abs_diff_eq!(seen, Vec3::new(0.0, 0.0, -d), epsilon = tol);
            // The eye is the origin of camera space.
            assert_abs_diff_eq!(transform_point(&camera_from_world, eye), Vec3::ZERO, epsilon = tol);
        }
    }

    #[test]
    fn basis_is_orthonormal_and_right_handed() {
        let mut checked = 0;
        for (eye, at, up) in cameras() {
            let Ok(m) = look_at(eye, at, up) else { continue };
            let (u, v, w) = basis(&m);
            assert_orthonormal(u, v, w);
            // up lies in the (v, w) plane on v's side: u ⟂ up, v·up > 0.
            assert!(u.dot(up.normalize()).abs() <= 1e-5 && v.dot(up) > 0.0, "{u} {v} {up}");
            checked += 1;
        }
        assert!(checked > 190, "only {checked} of the random cameras were valid");
    }

    #[test]
    fn up_parallel_to_view_is_an_error_both_ways() {
        let eye = Vec3::new(1.0, 2.0, 3.0);
        let at = Vec3::new(4.0, -2.0, 3.0);
        let view = at - eye;
        assert_eq!(look_at(eye, at, view), Err(CameraError::UpParallelToView));
        assert_eq!(look_at(eye, at, -2.5 * view), Err(CameraError::UpParallelToView));
        assert_eq!(look_at(eye, at, Vec3::ZERO), Err(CameraError::UpParallelToView));
        // Straight down with the default up, and straight up.
        assert_eq!(
            look_at(Vec3::new(0.0, 5.0, 0.0), Vec3::ZERO, Vec3::Y),
            Err(CameraError::UpParallelToView)
        );
        assert_eq!(
            look_at(Vec3::new(0.0, -5.0, 0.0), Vec3::ZERO, Vec3::Y),
            Err(CameraError::UpParallelToView)
        );
    }

    #[test]
    fn eye_at_target_is_an_error() {
        let p = Vec3::new(1.0, 2.0, 3.0);
        assert_eq!(look_at(p, p, Vec3::Y), Err(CameraError::EyeAtTarget));
    }

    #[test]
    fn non_finite_input_is_an_error() {
        let nan = Vec3::new(Float::NAN, 0.0, 0.0);
        let inf = Vec3::new(0.0, Float::INFINITY, 0.0);
        assert_eq!(look_at(nan, Vec3::ZERO, Vec3::Y), Err(CameraError::NotFinite));
        assert_eq!(look_at(Vec3::Z, nan, Vec3::Y), Err(CameraError::NotFinite));
        assert_eq!(look_at(Vec3::Z, Vec3::ZERO, nan), Err(CameraError::NotFinite));
        assert_eq!(look_at(inf, Vec3::ZERO, Vec3::X), Err(CameraError::NotFinite));
        // Finite inputs whose difference overflows.
        let big = Vec3::new(0.0, 0.0, 0.75 * Float::MAX);
        assert_eq!(look_at(big, -big, Vec3::Y), Err(CameraError::NotFinite));
    }

    #[test]
    fn up_nearly_parallel_still_gives_an_orthonormal_basis() {
        // up at 1e-3 rad from the view axis, for several view directions
        // (generic ones, where the cross product really cancels).
        for dir in [Vec3::new(1.0, 2.0, 3.0), Vec3::new(-0.3, 0.7, -0.2), Vec3::NEG_Y, Vec3::Z] {
            let dir = dir.normalize();
            let across = dir.any_orthonormal_vector();
            let angle: Float = 1e-3;
            let up = angle.cos() * dir + angle.sin() * across;
            for sign in [1.0, -1.0] {
                let eye = Vec3::new(0.5, -1.0, 2.0);
                let m = look_at(eye, eye + sign * dir, sign * up).expect("1e-3 rad is far from parallel");
                assert!(m.is_finite());
                let (u, v, w) = basis(&m);
                assert_orthonormal(u, v, w);
                // u is up × w normalised: perpendicular to `across` and dir, so ±(dir × across).
                assert_abs_diff_eq!(u.dot(across).abs(), 0.0, epsilon = 1e-3);
            }
        }
    }

    #[test]
    fn views_along_the_axes() {
        // Straight down (−y) with up = −z: w = +y, u = −z × y = x, v = y × x = −z.
        let m = look_at(Vec3::new(0.0, 5.0, 0.0), Vec3::ZERO, Vec3::NEG_Z).unwrap();
        assert_eq!(basis(&m), (Vec3::X, Vec3::NEG_Z, Vec3::Y));
        // Straight up (+y) with up = +z: w = −y, u = z × −y = x, v = −y × x = z.
        let m = look_at(Vec3::new(0.0, -5.0, 0.0), Vec3::ZERO, Vec3::Z).unwrap();
        assert_eq!(basis(&m), (Vec3::X, Vec3::Z, Vec3::NEG_Y));
        // Along +x with up = y: w = −x, u = y × −x = z, v = −x × z = y.
        let m = look_at(Vec3::ZERO, Vec3::X, Vec3::Y).unwrap();
        assert_eq!(basis(&m), (Vec3::Z, Vec3::Y, Vec3::NEG_X));
        // Nearly straight down −z (eye 1e-4 off the axis): almost the identity.
        let m = look_at(Vec3::new(1e-4, 0.0, 5.0), Vec3::ZERO, Vec3::Y).unwrap();
        let (u, v, w) = basis(&m);
        // w = (1e-4, 0, 5)/5 ≈ (2e-5, 0, 1): off the identity by 2e-5.
        assert_abs_diff_eq!(w, Vec3::new(2e-5, 0.0, 1.0), epsilon = 1e-6);
        assert_abs_diff_eq!(u, Vec3::new(1.0, 0.0, -2e-5), epsilon = 1e-6);
        assert_abs_diff_eq!(v, Vec3::Y, epsilon = 1e-6);
        assert_orthonormal(u, v, w);
    }

    #[test]
    fn tiny_and_huge_distances_work() {
        // eye − at of 1e-30 would underflow |eye − at|² in f32; 1e30 would overflow it.
        for d in [1e-30, 1e30] {
            let m = look_at(Vec3::new(0.0, 0.0, d), Vec3::ZERO, Vec3::Y).unwrap();
            assert_eq!(basis(&m), (Vec3::X, Vec3::Y, Vec3::Z));
            let m = look_at(Vec3::new(d, d, 0.0), Vec3::ZERO, 1e-30 * Vec3::Z).unwrap();
            let (u, v, w) = basis(&m);
            assert_orthonormal(u, v, w);
            assert!(m.is_finite());
        }
    }

    #[test]
    fn up_need_not_be_perpendicular_or_unit() {
        // Only up's component across the view counts.
        let eye = Vec3::new(0.0, 0.0, 5.0);
        let a = look_at(eye, Vec3::ZERO, Vec3::Y).unwrap();
        let b = look_at(eye, Vec3::ZERO, Vec3::new(0.0, 3.0, -7.0)).unwrap();
        assert_abs_diff_eq!(a, b, epsilon = 2.0 * Float::EPSILON);
    }

    #[test]
    fn errors_read_as_sentences() {
        insta::assert_snapshot!(CameraError::EyeAtTarget, @"the camera's eye and the point it looks at are the same point, so it has no view direction");
        insta::assert_snapshot!(CameraError::UpParallelToView, @"the camera's up vector is zero or parallel to the view direction (at − eye), so the image's horizontal axis is undefined; choose an up vector across the view");
        insta::assert_snapshot!(CameraError::NotFinite, @"a camera parameter is NaN or infinite (or eye − at overflows)");
    }
}
