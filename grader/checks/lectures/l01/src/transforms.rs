//! The checks of `transforms.rs`: translate, scale, the axis rotations, transform_point and transform_vector.

use super::common::*;

pub(super) fn translate_cases(translate: VecToMat) -> CheckResult {
    // Columns x, y, z unchanged; the last column (1, −2, 3, 1): where the origin goes.
    let t = Vec3::new(1.0, -2.0, 3.0);
    let expected = Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::Z, Vec4::new(1.0, -2.0, 3.0, 1.0));
    let got = translate(t);
    let case = "translate((1, −2, 3))";
    let cause = if near(&got, &Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::Z, t.extend(0.0)), 0.0) {
        "the last column is (t, 1): with w = 0 there a point would lose its w = 1"
    } else if near(&got, &Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::Z, (-t).extend(1.0)), 0.0) {
        "translate(t) moves points by +t: the last column is (t, 1), not (−t, 1)"
    } else {
        "the columns are the images of x, y, z (unchanged) and of the origin (t, 1)"
    };
    // Small integers: exact.
    same_matrix(
        case,
        &got,
        &expected,
        0.0,
        cause,
        "the translation belongs in the last column (Mat4::from_cols(X, Y, Z, (t, 1))), not the last row",
    )?;
    Ok("translate((1, −2, 3)) exact".into())
}

pub(super) fn scale_cases(scale: VecToMat) -> CheckResult {
    // diag(2, 3, −1, 1): (1, 1, 1) ↦ (2, 3, −1), the origin stays.
    let expected = Mat4::from_diagonal(Vec4::new(2.0, 3.0, -1.0, 1.0));
    let got = scale(Vec3::new(2.0, 3.0, -1.0));
    let cause = if got.w_axis != Vec4::W {
        "the last column stays (0, 0, 0, 1): scaling keeps the origin and w = 1"
    } else {
        "scale(s) = diag(sₓ, s_y, s_z, 1): each axis column is multiplied by its factor"
    };
    same_matrix("scale((2, 3, −1))", &got, &expected, 0.0, cause, cause)?;
    Ok("scale((2, 3, −1)) exact".into())
}

/// The right-handed rotation by θ about coordinate axis `axis`, from the
/// images of the other two axes i → j (cyclic order x → y → z → x):
/// i ↦ c·i + s·j and j ↦ −s·i + c·j. About z: x ↦ (c, s, 0), y ↦ (−s, c, 0).
pub(super) fn axis_rotation(axis: usize, angle: Float) -> Mat4 {
    let (s, c) = angle.sin_cos();
    let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
    let mut cols = [Vec4::X, Vec4::Y, Vec4::Z, Vec4::W];
    cols[i][i] = c;
    cols[i][j] = s;
    cols[j][i] = -s;
    cols[j][j] = c;
    Mat4::from_cols(cols[0], cols[1], cols[2], cols[3])
}

pub(super) fn rotation_cases(axis: usize, rotate: AngleToMat) -> CheckResult {
    let name = axis_name(axis);
    let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
    // A quarter turn takes the next axis to the one after it.
    let case = format!("rotate_{name}(π/2) applied to +{} (a vector)", axis_name(i));
    let got = apply(&rotate(FRAC_PI_2), unit(i), 0.0);
    let cause = diagnose(
        got,
        &[
            (-unit(j), WRONG_WAY),
            (
                apply(&axis_rotation(axis, radians(FRAC_PI_2)), unit(i), 0.0),
                "angles are in radians: π/2 is a quarter turn (do not convert from degrees)",
            ),
        ],
        1e-3,
        "a quarter turn about an axis takes the next axis to the one after it (cyclic x → y → z → x)",
    );
    close3(&case, got, unit(j), TOL, cause)?;
    // The axis itself stays, for generic angles; every entry by hand.
    for angle in [0.5, -2.0, 3.0] {
        let case = format!("rotate_{name}({angle})");
        let got = rotate(angle);
        let expected = axis_rotation(axis, angle);
        let cause = if near(&got, &axis_rotation(axis, radians(angle)), TOL) {
            "angles are in radians already: do not convert from degrees"
        } else if got.col(axis) != unit(axis).extend(0.0) {
            "the rotation axis is fixed: its column stays the unit axis"
        } else {
            "about z: x ↦ (cos θ, sin θ, 0), y ↦ (−sin θ, cos θ, 0), and cyclically for x and y"
        };
        same_matrix(&case, &got, &expected, TOL, cause, WRONG_WAY)?;
    }
    Ok("a quarter turn and 3 angles".into())
}

/// Scale by (2, 3, −1), then move by (1, −2, 3): columns by hand.
pub(super) fn scale_then_move() -> Mat4 {
    Mat4::from_cols(
        Vec4::new(2.0, 0.0, 0.0, 0.0),
        Vec4::new(0.0, 3.0, 0.0, 0.0),
        Vec4::new(0.0, 0.0, -1.0, 0.0),
        Vec4::new(1.0, -2.0, 3.0, 1.0),
    )
}

pub(super) fn transform_point_cases(transform_point: ApplyFn) -> CheckResult {
    // (1, 1, 1) ↦ (2, 3, −1) + (1, −2, 3) = (3, 1, 2): small integers, exact.
    let got = transform_point(&scale_then_move(), Vec3::ONE);
    let cause = diagnose(
        got,
        &[(
            Vec3::new(2.0, 3.0, -1.0),
            "a point has w = 1: extend it with 1.0 so the translation column applies",
        )],
        0.0,
        "m·(p, 1) = pₓ·col₀ + p_y·col₁ + p_z·col₂ + col₃",
    );
    close3(
        "scale (2, 3, −1) then translate (1, −2, 3), applied to the point (1, 1, 1)",
        got,
        Vec3::new(3.0, 1.0, 2.0),
        0.0,
        cause,
    )?;
    // A general affine matrix: the sum of its columns weighted by (p, 1).
    let m = Mat4::from_cols(
        Vec4::new(0.5, -1.25, 2.0, 0.0),
        Vec4::new(0.75, 0.5, -0.25, 0.0),
        Vec4::new(-1.5, 0.25, 1.0, 0.0),
        Vec4::new(4.0, 5.0, -6.0, 1.0),
    );
    let p = Vec3::new(2.0, -4.0, 0.5);
    // Dyadic entries, exact: x = 0.5·2 + 0.75·(−4) − 1.5·0.5 + 4 = 1.25,
    // y = −2.5 − 2 + 0.125 + 5 = 0.625, z = 4 + 1 + 0.5 − 6 = −0.5.
    close3(
        "an affine matrix with dyadic entries, applied to (2, −4, 0.5)",
        transform_point(&m, p),
        Vec3::new(1.25, 0.625, -0.5),
        0.0,
        "m·(p, 1) = pₓ·col₀ + p_y·col₁ + p_z·col₂ + col₃",
    )?;
    // A projective matrix (last row 0 0 0 2): w' = 2 divides, (2, 4, 6) ↦ (1, 2, 3).
    let mut half = Mat4::IDENTITY;
    half.w_axis.w = 2.0;
    let got = transform_point(&half, Vec3::new(2.0, 4.0, 6.0));
    let cause = diagnose(
        got,
        &[(Vec3::new(2.0, 4.0, 6.0), "divide by w' when it is not 1: a projective matrix gives w' ≠ 1")],
        0.0,
        "(x', y', z', w') = m·(p, 1), then (x', y', z')/w'",
    );
    close3(
        "the identity with w_axis.w = 2, applied to (2, 4, 6)",
        got,
        Vec3::new(1.0, 2.0, 3.0),
        0.0,
        cause,
    )?;
    // The perspective divide: w' = −z maps (2, 4, −2) to (1, 2, −1).
    let mut perspective = Mat4::IDENTITY;
    perspective.z_axis.w = -1.0;
    perspective.w_axis.w = 0.0;
    let got = transform_point(&perspective, Vec3::new(2.0, 4.0, -2.0));
    close3(
        "a perspective matrix (w' = −z), applied to (2, 4, −2)",
        got,
        Vec3::new(1.0, 2.0, -1.0),
        0.0,
        "divide by w' = −z = 2",
    )?;
    Ok("4 points, exact".into())
}

pub(super) fn transform_vector_cases(transform_vector: ApplyFn) -> CheckResult {
    // (1, 1, 1) ↦ (2, 3, −1): the translation (1, −2, 3) does not apply.
    let got = transform_vector(&scale_then_move(), Vec3::ONE);
    let cause = diagnose(
        got,
        &[(Vec3::new(3.0, 1.0, 2.0), "a vector has w = 0: the translation column must not move it")],
        0.0,
        "m·(v, 0) = vₓ·col₀ + v_y·col₁ + v_z·col₂",
    );
    close3(
        "scale (2, 3, −1) then translate (1, −2, 3), applied to the vector (1, 1, 1)",
        got,
        Vec3::new(2.0, 3.0, -1.0),
        0.0,
        cause,
    )?;
    // (1, −2, 4) ↦ (2, −6, −4).
    let got = transform_vector(&scale_then_move(), Vec3::new(1.0, -2.0, 4.0));
    close3(
        "the same matrix, applied to the vector (1, −2, 4)",
        got,
        Vec3::new(2.0, -6.0, -4.0),
        0.0,
        "m·(v, 0) = vₓ·col₀ + v_y·col₁ + v_z·col₂",
    )?;
    Ok("2 vectors, exact".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    use raylab::{Float, Mat4, Vec4, radians};

    #[test]
    fn translate_and_scale_mistakes() {
        caught(
            translate_cases(|t| Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::Z, t.extend(1.0)).transpose()),
            "not the last row",
        );
        caught(translate_cases(|t| Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::Z, (-t).extend(1.0))), "+t");
        caught(scale_cases(|s| Mat4::from_diagonal(s.extend(0.0))), "w = 1");
    }

    /// The reference rotate_z with the signs of the sin terms swapped (left-handed).
    fn rotate_z_left_handed(angle: Float) -> Mat4 {
        let (s, c) = angle.sin_cos();
        Mat4::from_cols(Vec4::new(c, -s, 0.0, 0.0), Vec4::new(s, c, 0.0, 0.0), Vec4::Z, Vec4::W)
    }

    #[test]
    fn rotation_mistakes() {
        caught(rotation_cases(2, rotate_z_left_handed), "wrong way");
        caught(rotation_cases(0, |a| l01_transforms::rotate_x(-a)), "wrong way");
        caught(rotation_cases(1, |a| l01_transforms::rotate_y(radians(a))), "radians");
    }

    #[test]
    fn point_and_vector_mistakes() {
        caught(transform_point_cases(|m, p| (*m * p.extend(0.0)).truncate()), "w = 1");
        caught(transform_point_cases(|m, p| (*m * p.extend(1.0)).truncate()), "divide by w'");
        caught(transform_vector_cases(|m, v| (*m * v.extend(1.0)).truncate()), "w = 0");
    }
}
