//! Rotation about an arbitrary axis through the origin (Rodrigues' formula).

use raylab::{Float, Mat4, Vec3, Vec4};

/// Rotation by `angle` radians about `axis` (through the origin),
/// right-handed: with the thumb along `axis`, the fingers curl the way the
/// points turn.
///
/// With a = axis/|axis|, c = cos θ, s = sin θ, Rodrigues' formula
///
/// ```text
/// R = c·I + (1 − c)·a aᵀ + s·[a]×        [a]× = ⎡  0  −a_z  a_y ⎤
///                                               ⎢ a_z   0  −a_x ⎥
///                                               ⎣−a_y  a_x   0  ⎦
/// ```
///
/// so column x is (c + (1−c)a_x², (1−c)a_x a_y + s a_z, (1−c)a_x a_z − s a_y),
/// and so on. The `s·[a]×` part is *skew-symmetric*: the sin term of entry
/// (i, j) is minus that of (j, i). (The slides print some of those signs
/// wrong; with them R neither fixes the axis nor stays orthonormal.)
///
/// `axis` must be finite and non-zero; any length will do. Book: §1.4
/// Rotation about an arbitrary axis.
pub fn rotate_axis(axis: Vec3, angle: Float) -> Mat4 {
    debug_assert!(
        axis.is_finite() && axis.length_squared() > 0.0,
        "rotate_axis: axis {axis} must be non-zero"
    );
    // SOLUTION BEGIN
    let a = axis.normalize();
    let (s, c) = angle.sin_cos();
    let t = 1.0 - c;
    // The columns of c·I + (1 − c)·a aᵀ + s·[a]×.
    Mat4::from_cols(
        Vec4::new(c + t * a.x * a.x, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y, 0.0),
        Vec4::new(t * a.x * a.y - s * a.z, c + t * a.y * a.y, t * a.y * a.z + s * a.x, 0.0),
        Vec4::new(t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, c + t * a.z * a.z, 0.0),
        Vec4::W,
    )
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frame::frame;
    use crate::testing::{ORTHO_TOL, assert_rotation};
    use crate::transforms::{rotate_x, rotate_y, rotate_z, transform_vector};
    use approx::assert_abs_diff_eq;
    use raylab::math::consts::{FRAC_PI_2, PI, TAU};

    /// Generic axes: none along a coordinate axis, several lengths.
    fn generic_axes() -> [Vec3; 4] {
        [
            Vec3::new(1.0, 2.0, 3.0),
            Vec3::new(-0.3, 0.9, 0.1),
            Vec3::new(5.0, -5.0, 2.0),
            Vec3::new(1e-3, 4e-3, -2e-3),
        ]
    }

    const ANGLES: [Float; 6] = [0.0, 0.4, -1.1, FRAC_PI_2, 2.9, -PI];

    /// Entries are sums of three products of numbers ≤ 1 plus the rounding
    /// of sin and cos and of the normalised axis: a few ε each; 8ε
    /// (≈ 9.5e-7 in f32) holds them.
    const TOL: Float = 8.0 * Float::EPSILON;

    #[test]
    fn on_the_coordinate_axes_it_is_rotate_x_y_z() {
        for angle in ANGLES {
            assert_abs_diff_eq!(rotate_axis(Vec3::X, angle), rotate_x(angle), epsilon = TOL);
            assert_abs_diff_eq!(rotate_axis(Vec3::Y, angle), rotate_y(angle), epsilon = TOL);
            assert_abs_diff_eq!(rotate_axis(Vec3::Z, angle), rotate_z(angle), epsilon = TOL);
            // Any length of axis names the same rotation.
            assert_abs_diff_eq!(rotate_axis(7.0 * Vec3::Z, angle), rotate_z(angle), epsilon = TOL);
        }
    }

    #[test]
    fn quarter_turn_about_z_takes_x_to_y() {
        // Right-handed: the sin terms carry the sign that sends +x to +y.
        let r = rotate_axis(Vec3::Z, FRAC_PI_2);
        assert_abs_diff_eq!(transform_vector(&r, Vec3::X), Vec3::Y, epsilon = TOL);
        // About the diagonal (1, 1, 1) a third of a turn cycles the axes x → y → z.
        let r = rotate_axis(Vec3::ONE, TAU / 3.0);
        assert_abs_diff_eq!(transform_vector(&r, Vec3::X), Vec3::Y, epsilon = TOL);
        assert_abs_diff_eq!(transform_vector(&r, Vec3::Y), Vec3::Z, epsilon = TOL);
        assert_abs_diff_eq!(transform_vector(&r, Vec3::Z), Vec3::X, epsilon = TOL);
    }

    #[test]
    fn fixes_the_axis_and_is_a_rotation() {
        for axis in generic_axes() {
            let a = axis.normalize();
            for angle in ANGLES {
                let r = rotate_axis(axis, angle);
                assert_abs_diff_eq!(transform_vector(&r, a), a, epsilon = TOL);
                assert_rotation(&r);
            }
        }
    }

    #[test]
    fn agrees_with_glam_from_axis_angle() {
        for axis in generic_axes() {
            for angle in ANGLES {
                let expected = Mat4::from_axis_angle(axis.normalize(), angle);
                assert_abs_diff_eq!(rotate_axis(axis, angle), expected, epsilon = TOL);
            }
        }
    }

    #[test]
    fn agrees_with_a_change_of_frame_to_the_z_axis() {
        // An independent construction: in an orthonormal frame (i, j, a) the
        // rotation is rotate_z, so R = F·R_z(θ)·Fᵀ with F = [i j a].
        for axis in generic_axes() {
            let a = axis.normalize();
            let i = a.any_orthonormal_vector();
            let j = a.cross(i);
            let f = frame(Vec3::ZERO, i, j, a);
            for angle in ANGLES {
                let expected = f * rotate_z(angle) * f.transpose();
                // Three matrix products of unit entries: ~12ε of rounding.
                assert_abs_diff_eq!(rotate_axis(axis, angle), expected, epsilon = 2.0 * TOL);
            }
        }
    }

    #[test]
    fn composing_two_turns_adds_the_angles() {
        for axis in generic_axes() {
            for (theta, phi) in [(0.3, 0.5), (-1.2, 2.0), (2.5, 2.5)] {
                let product = rotate_axis(axis, theta) * rotate_axis(axis, phi);
                // A product of two rotations doubles the rounding of one.
                assert_abs_diff_eq!(product, rotate_axis(axis, theta + phi), epsilon = 2.0 * TOL);
            }
        }
    }

    // INSTRUCTOR BEGIN
    // (Out of the handout: the slide's matrix differs from the solution by three signs.)
    /// Rodrigues with the sin terms of the upper triangle given the sign of
    /// the lower one, as the slides print it: s·[a]× becomes symmetric.
    fn slide_matrix(axis: Vec3, angle: Float) -> Mat4 {
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

    #[test]
    fn slide_erratum_sin_signs_break_the_rotation() {
        let axis = Vec3::new(1.0, 2.0, 3.0);
        let a = axis.normalize();
        let angle = 0.7;
        // Ours fixes the axis and is orthonormal (RᵀR = I).
        let ours = rotate_axis(axis, angle);
        assert_abs_diff_eq!(transform_vector(&ours, a), a, epsilon = TOL);
        assert_abs_diff_eq!(ours.transpose() * ours, Mat4::IDENTITY, epsilon = ORTHO_TOL);
        // The slide's signs make the sin part a symmetric S, so M·a = a + s·S·a
        // with, row by row (S as printed: rows (0, a_z, −a_y), (a_z, 0, a_x),
        // (−a_y, a_x, 0)), S·a = (a_z a_y − a_y a_z, a_z a_x + a_x a_z, −a_y a_x + a_x a_y)
        // = (0, 2a_x a_z, 0) = (0, 6/14, 0) for a = (1, 2, 3)/√14: the axis moves.
        let wrong = slide_matrix(axis, angle);
        let moved = transform_vector(&wrong, a) - a;
        let expected = Vec3::new(0.0, (6.0 / 14.0) * (0.7 as Float).sin(), 0.0);
        assert_abs_diff_eq!(moved, expected, epsilon = TOL);
        // And it is far from orthonormal: the columns are no longer unit.
        let gram = wrong.transpose() * wrong;
        assert!((gram - Mat4::IDENTITY).abs().to_cols_array().iter().any(|&e| e > 0.1), "{gram:?}");
    }
    // INSTRUCTOR END

    #[test]
    fn all_sin_signs_flipped_turns_the_wrong_way() {
        // The other misprint: flipping *every* sin term gives R(a, −θ), a
        // rotation about the axis but left-handed, which sends +x to −y for
        // a quarter turn about +z; ours sends it to +y.
        let flipped = slide_like_all_flipped(Vec3::Z, FRAC_PI_2);
        assert_abs_diff_eq!(transform_vector(&flipped, Vec3::X), -Vec3::Y, epsilon = TOL);
        assert_abs_diff_eq!(
            transform_vector(&rotate_axis(Vec3::Z, FRAC_PI_2), Vec3::X),
            Vec3::Y,
            epsilon = TOL
        );
    }

    fn slide_like_all_flipped(axis: Vec3, angle: Float) -> Mat4 {
        // c·I + (1 − c)·a aᵀ − s·[a]× is the transpose of ours.
        rotate_axis(axis, angle).transpose()
    }
}
