//! The checks of `axis_angle.rs`: rotate_axis.

use super::common::*;

/// Rodrigues' rotation of vector `v` about the unit `k`, in f64:
/// v cos θ + (k × v) sin θ + k (k·v)(1 − cos θ) — the vector form, not the matrix.
pub(super) fn rodrigues_f64(k: [f64; 3], angle: f64, v: [f64; 3]) -> [f64; 3] {
    let (s, c) = angle.sin_cos();
    let kxv = [k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]];
    let kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
    [0, 1, 2].map(|i| v[i] * c + kxv[i] * s + k[i] * kv * (1.0 - c))
}

/// The rotation matrix whose columns are the f64 Rodrigues images of x, y, z.
pub(super) fn rodrigues_matrix(axis: Vec3, angle: Float) -> Mat4 {
    let a = [axis.x as f64, axis.y as f64, axis.z as f64];
    let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    let k = a.map(|x| x / l);
    let col = |e: [f64; 3]| {
        let r = rodrigues_f64(k, angle as f64, e);
        Vec4::new(r[0] as Float, r[1] as Float, r[2] as Float, 0.0)
    };
    Mat4::from_cols(col([1.0, 0.0, 0.0]), col([0.0, 1.0, 0.0]), col([0.0, 0.0, 1.0]), Vec4::W)
}

pub(super) fn rotate_axis_cases(rotate_axis: AxisAngleFn) -> CheckResult {
    // 1. A generic unit axis is fixed: R·a = a (the slides' sign typo moves it).
    let a = Vec3::new(1.0, 2.0, 3.0).normalize();
    let r = rotate_axis(a, 0.7);
    close3(
        "rotate_axis((1, 2, 3)/√14, 0.7) applied to its own axis",
        apply(&r, a, 0.0),
        a,
        TOL,
        "R must fix its axis: the sin terms form the skew-symmetric s·[a]× (entry (i, j) is minus entry \
            (j, i)); the slides print some of those signs wrong",
    )?;
    // 2. Orthonormal: RᵀR = I.
    same_matrix(
        "RᵀR for rotate_axis((1, 2, 3)/√14, 0.7)",
        &(r.transpose() * r),
        &Mat4::IDENTITY,
        2.0 * TOL,
        "R = c·I + (1 − c)·a aᵀ + s·[a]× is orthonormal: check the cos and (1 − c) terms",
        "R = c·I + (1 − c)·a aᵀ + s·[a]× is orthonormal: check the cos and (1 − c) terms",
    )?;
    // 3. Right-handed: a quarter turn about +z takes +x to +y.
    let got = apply(&rotate_axis(Vec3::Z, FRAC_PI_2), Vec3::X, 0.0);
    let cause = diagnose(got, &[(-Vec3::Y, WRONG_WAY)], 1e-3, "rotate_axis(z, θ) must be rotate_z(θ)");
    close3("rotate_axis(+z, π/2) applied to +x", got, Vec3::Y, TOL, cause)?;
    // 4. Every entry against Rodrigues' vector formula in f64: the coordinate axes,
    //    the diagonal (a third of a turn cycles x → y → z), generic axes.
    let axes = [Vec3::X, Vec3::Y, Vec3::Z, Vec3::ONE.normalize(), a, Vec3::new(-0.3, 0.9, 0.1).normalize()];
    for axis in axes {
        for angle in [0.4, -1.1, TAU / 3.0, 2.9] {
            let case = format!("rotate_axis({}, {})", vec3(axis), num(angle));
            same_matrix(
                &case,
                &rotate_axis(axis, angle),
                &rodrigues_matrix(axis, angle),
                TOL,
                "R = c·I + (1 − c)·a aᵀ + s·[a]×: column x is (c + (1−c)aₓ², (1−c)aₓa_y + s a_z, \
                    (1−c)aₓa_z − s a_y)",
                WRONG_WAY,
            )?;
        }
    }
    // 5. Any length names the same rotation.
    for axis in [7.0 * Vec3::Z, Vec3::new(1e-3, 4e-3, -2e-3), Vec3::new(5.0, -5.0, 2.0)] {
        let case = format!("rotate_axis({}, 0.4): an axis that is not unit length", vec3(axis));
        same_matrix(
            &case,
            &rotate_axis(axis, 0.4),
            &rodrigues_matrix(axis, 0.4),
            TOL,
            "normalise the axis first: any length of axis names the same rotation",
            WRONG_WAY,
        )?;
    }
    Ok("axis fixed, orthonormal, right-handed, 27 matrices against Rodrigues in f64".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l01_transforms::rotate_axis;
    use raylab::{Float, Mat4, Vec3, Vec4};

    /// Rodrigues with the slides' sign typo: the sin terms of the upper triangle
    /// take the sign of the lower one, so s·[a]× becomes symmetric.
    fn slide_typo(axis: Vec3, angle: Float) -> Mat4 {
        let a = axis.normalize();
        let (s, c) = angle.sin_cos();
        let t = 1.0 - c;
        Mat4::from_cols(
            Vec4::new(c + t * a.x * a.x, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y, 0.0),
            Vec4::new(t * a.x * a.y + s * a.z, c + t * a.y * a.y, t * a.y * a.z + s * a.x, 0.0),
            Vec4::new(t * a.x * a.z - s * a.y, t * a.y * a.z + s * a.x, c + t * a.z * a.z, 0.0),
            Vec4::W,
        )
    }

    /// Rodrigues without normalising the axis.
    fn unnormalised(a: Vec3, angle: Float) -> Mat4 {
        let (s, c) = angle.sin_cos();
        let t = 1.0 - c;
        Mat4::from_cols(
            Vec4::new(c + t * a.x * a.x, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y, 0.0),
            Vec4::new(t * a.x * a.y - s * a.z, c + t * a.y * a.y, t * a.y * a.z + s * a.x, 0.0),
            Vec4::new(t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, c + t * a.z * a.z, 0.0),
            Vec4::W,
        )
    }

    #[test]
    fn rotate_axis_mistakes() {
        caught(rotate_axis_cases(slide_typo), "skew-symmetric");
        caught(rotate_axis_cases(|a, t| rotate_axis(a, t).transpose()), "wrong way");
        caught(rotate_axis_cases(unnormalised), "normalise the axis");
    }
}
