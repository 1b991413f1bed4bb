//! The basic affine transforms as 4×4 homogeneous matrices, and applying a
//! matrix to points (w = 1) and to vectors (w = 0).
//!
//! Every matrix is built from its columns: column j is the image of the j-th
//! basis vector (x, y, z) and the last column is where the origin goes. So
//! `m * (x, y, z, w) = x·col₀ + y·col₁ + z·col₂ + w·col₃`, and a vector
//! (w = 0) never feels the translation in col₃. Book: §1.1 Homogeneous
//! coordinates.

use raylab::{Float, Mat4, Vec3, Vec4};

/// Translation by `t`: p ↦ p + t (vectors are unchanged).
///
/// Columns: x, y, z unchanged; the origin goes to t. Book: §1.2 Translation
/// and scaling.
pub fn translate(t: Vec3) -> Mat4 {
    // SOLUTION BEGIN
    Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::Z, t.extend(1.0))
    // SOLUTION END
}

/// Scaling by `s` along the axes: (x, y, z) ↦ (sₓx, s_yy, s_zz), about the
/// origin.
///
/// A zero factor gives a singular matrix (fine to apply, impossible to
/// invert). Book: §1.2 Translation and scaling.
pub fn scale(s: Vec3) -> Mat4 {
    // SOLUTION BEGIN
    Mat4::from_cols(
        Vec4::new(s.x, 0.0, 0.0, 0.0),
        Vec4::new(0.0, s.y, 0.0, 0.0),
        Vec4::new(0.0, 0.0, s.z, 0.0),
        Vec4::W,
    )
    // SOLUTION END
}

/// Rotation by `angle` radians about the x axis, right-handed (thumb along
/// +x, fingers curl from +y to +z): y ↦ (0, cos θ, sin θ), z ↦ (0, −sin θ, cos θ).
///
/// Book: §1.3 Rotations about the axes.
pub fn rotate_x(angle: Float) -> Mat4 {
    // SOLUTION BEGIN
    let (s, c) = angle.sin_cos();
    Mat4::from_cols(Vec4::X, Vec4::new(0.0, c, s, 0.0), Vec4::new(0.0, -s, c, 0.0), Vec4::W)
    // SOLUTION END
}

/// Rotation by `angle` radians about the y axis, right-handed (from +z to
/// +x): z ↦ (sin θ, 0, cos θ), x ↦ (cos θ, 0, −sin θ).
///
/// Book: §1.3 Rotations about the axes.
pub fn rotate_y(angle: Float) -> Mat4 {
    // SOLUTION BEGIN
    let (s, c) = angle.sin_cos();
    Mat4::from_cols(Vec4::new(c, 0.0, -s, 0.0), Vec4::Y, Vec4::new(s, 0.0, c, 0.0), Vec4::W)
    // SOLUTION END
}

/// Rotation by `angle` radians about the z axis, right-handed (from +x to
/// +y): x ↦ (cos θ, sin θ, 0), y ↦ (−sin θ, cos θ, 0). So rotate_z(π/2)
/// maps +x to +y.
///
/// Book: §1.3 Rotations about the axes.
pub fn rotate_z(angle: Float) -> Mat4 {
    // SOLUTION BEGIN
    let (s, c) = angle.sin_cos();
    Mat4::from_cols(Vec4::new(c, s, 0.0, 0.0), Vec4::new(-s, c, 0.0, 0.0), Vec4::Z, Vec4::W)
    // SOLUTION END
}

/// Applies `m` to the point `p`: (x', y', z', w') = m·(p, 1), then divides by
/// w' when it is not 1.
///
/// An affine matrix (last row 0 0 0 1) gives w' = 1 exactly, so no division
/// happens and no rounding is added; a projective one gives a non-finite
/// point where w' = 0 (a point at infinity). Book: §1.1 Homogeneous
/// coordinates.
pub fn transform_point(m: &Mat4, p: Vec3) -> Vec3 {
    // SOLUTION BEGIN
    let q = *m * p.extend(1.0);
    if q.w == 1.0 { q.truncate() } else { q.truncate() / q.w }
    // SOLUTION END
}

/// Applies `m` to the vector `v`: m·(v, 0), so the translation column is
/// ignored (a direction or a displacement does not move with the origin).
///
/// Not for normals: those take the inverse transpose (lecture 04). Book:
/// §1.1 Homogeneous coordinates.
pub fn transform_vector(m: &Mat4, v: Vec3) -> Vec3 {
    // SOLUTION BEGIN
    (*m * v.extend(0.0)).truncate()
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::assert_rotation;
    use approx::assert_abs_diff_eq;
    use raylab::math::consts::{FRAC_PI_2, PI};
    use raylab_testing::ulp;

    /// sin(π/2) and cos(π/2) of the rounded π/2 are off by ≤ ε/2 (cos(π/2)
    /// in f32 is −4.4e-8); a product and a sum add a few ε more, so 4ε bounds
    /// every entry of a rotated unit vector.
    const ROT_TOL: Float = 4.0 * Float::EPSILON;

    #[test]
    fn translate_moves_points_not_vectors() {
        let m = translate(Vec3::new(1.0, -2.0, 3.0));
        // (4, 5, 6) + (1, −2, 3) = (5, 3, 9): small integers, exact.
        assert_eq!(transform_point(&m, Vec3::new(4.0, 5.0, 6.0)), Vec3::new(5.0, 3.0, 9.0));
        assert_eq!(transform_vector(&m, Vec3::new(4.0, 5.0, 6.0)), Vec3::new(4.0, 5.0, 6.0));
        assert_eq!(m, Mat4::from_translation(Vec3::new(1.0, -2.0, 3.0)));
    }

    #[test]
    fn scale_multiplies_points_and_vectors_per_axis() {
        let m = scale(Vec3::new(2.0, 3.0, -1.0));
        // (1, 1, 1) ↦ (2, 3, −1); the origin stays put.
        assert_eq!(transform_point(&m, Vec3::ONE), Vec3::new(2.0, 3.0, -1.0));
        assert_eq!(transform_vector(&m, Vec3::new(1.0, -2.0, 4.0)), Vec3::new(2.0, -6.0, -4.0));
        assert_eq!(transform_point(&m, Vec3::ZERO), Vec3::ZERO);
        assert_eq!(m, Mat4::from_scale(Vec3::new(2.0, 3.0, -1.0)));
    }

    #[test]
    fn rotations_are_right_handed() {
        let q = FRAC_PI_2;
        // A quarter turn about each axis takes the next axis to the one after
        // it (cyclic x → y → z → x) and that one to minus the next.
        assert_abs_diff_eq!(transform_vector(&rotate_z(q), Vec3::X), Vec3::Y, epsilon = ROT_TOL);
        assert_abs_diff_eq!(transform_vector(&rotate_z(q), Vec3::Y), -Vec3::X, epsilon = ROT_TOL);
        assert_abs_diff_eq!(transform_vector(&rotate_x(q), Vec3::Y), Vec3::Z, epsilon = ROT_TOL);
        assert_abs_diff_eq!(transform_vector(&rotate_x(q), Vec3::Z), -Vec3::Y, epsilon = ROT_TOL);
        assert_abs_diff_eq!(transform_vector(&rotate_y(q), Vec3::Z), Vec3::X, epsilon = ROT_TOL);
        assert_abs_diff_eq!(transform_vector(&rotate_y(q), Vec3::X), -Vec3::Z, epsilon = ROT_TOL);
    }

    #[test]
    fn rotations_fix_their_axis_and_the_origin() {
        for angle in [0.3, -1.7, PI, 5.0] {
            // The axis is the column that holds (1, 0, 0) etc. exactly.
            assert_eq!(transform_vector(&rotate_x(angle), Vec3::X), Vec3::X);
            assert_eq!(transform_vector(&rotate_y(angle), Vec3::Y), Vec3::Y);
            assert_eq!(transform_vector(&rotate_z(angle), Vec3::Z), Vec3::Z);
            assert_eq!(transform_point(&rotate_z(angle), Vec3::ZERO), Vec3::ZERO);
            assert_rotation(&rotate_x(angle));
            assert_rotation(&rotate_y(angle));
            assert_rotation(&rotate_z(angle));
        }
    }

    #[test]
    fn rotations_agree_with_glam() {
        // An independent construction (glam's own code).
        for angle in [0.0, 0.3, -1.7, 2.5, PI] {
            assert_abs_diff_eq!(rotate_x(angle), Mat4::from_rotation_x(angle), epsilon = ROT_TOL);
            assert_abs_diff_eq!(rotate_y(angle), Mat4::from_rotation_y(angle), epsilon = ROT_TOL);
            assert_abs_diff_eq!(rotate_z(angle), Mat4::from_rotation_z(angle), epsilon = ROT_TOL);
        }
    }

    #[test]
    fn rotation_by_30_degrees_by_hand() {
        // cos 30° = √3/2, sin 30° = 1/2: (1, 0, 0) ↦ (√3/2, 1/2, 0) under rotate_z.
        let r = transform_point(&rotate_z(PI / 6.0), Vec3::new(1.0, 0.0, 7.0));
        let half_sqrt3 = (3.0 as Float).sqrt() / 2.0;
        assert_abs_diff_eq!(r, Vec3::new(half_sqrt3, 0.5, 7.0), epsilon = ROT_TOL);
    }

    #[test]
    fn point_divides_by_w_when_projective() {
        // A matrix whose last row is (0, 0, 0, 2) gives w' = 2: (2, 4, 6) ↦ (1, 2, 3).
        let mut m = Mat4::IDENTITY;
        m.w_axis.w = 2.0;
        assert_eq!(transform_point(&m, Vec3::new(2.0, 4.0, 6.0)), Vec3::new(1.0, 2.0, 3.0));
        // The perspective divide: w' = −z maps (2, 4, −2) to (1, 2, −1).
        let mut p = Mat4::IDENTITY;
        p.z_axis.w = -1.0;
        p.w_axis.w = 0.0;
        assert_eq!(transform_point(&p, Vec3::new(2.0, 4.0, -2.0)), Vec3::new(1.0, 2.0, -1.0));
    }

    #[test]
    fn composition_applies_the_right_factor_first() {
        // T·S·p = S·p + t: scale (1, 1, 1) to (2, 2, 2), then move by (1, 0, 0).
        let m = translate(Vec3::X) * scale(Vec3::splat(2.0));
        assert_eq!(transform_point(&m, Vec3::ONE), Vec3::new(3.0, 2.0, 2.0));
        // S·T·p = 2(p + t) = (4, 2, 2).
        let m = scale(Vec3::splat(2.0)) * translate(Vec3::X);
        assert_eq!(transform_point(&m, Vec3::ONE), Vec3::new(4.0, 2.0, 2.0));
    }

    #[test]
    fn far_translation_keeps_points_within_an_ulp() {
        let t = Vec3::new(1e5, -1e5, 1e5);
        let p = Vec3::new(0.1, 0.2, 0.3);
        let moved = transform_point(&translate(t), p);
        // The exact sum correctly rounded: at most ½ ulp(1e5) away from p + t,
        // and the matrix adds only exact zeros, so it rounds the same way.
        assert_eq!(moved, p + t);
        // And back: the round trip loses at most one rounding at 1e5, i.e.
        // ulp(1e5) = 2⁻⁷ in f32 (2⁻³⁶ in f64), never more.
        let back = transform_point(&translate(-t), moved);
        assert_abs_diff_eq!(back, p, epsilon = ulp(1e5));
    }

    #[test]
    fn tiny_and_huge_scales_keep_points_within_a_few_ulp() {
        let p = Vec3::new(1.25, -3.5, 7.0);
        for k in [1e-3, 1e3] {
            let scaled = transform_point(&scale(Vec3::splat(k)), p);
            // One multiplication, correctly rounded, as k·p is.
            assert_eq!(scaled, k * p);
            // Scaling back multiplies by the rounded 1/k: two roundings of
            // relative size ε/2 each, so within 2ε·|p| (f32: 1.7e-6 at |p| = 7).
            let back = transform_point(&scale(Vec3::splat(1.0 / k)), scaled);
            assert_abs_diff_eq!(back, p, epsilon = 2.0 * Float::EPSILON * 7.0);
        }
    }
}
