//! Coordinate frames as matrices: the change of basis.

use raylab::{Mat4, Vec3};

/// The matrix `world_from_frame` of the frame with origin `origin` and axes
/// `i`, `j`, `k` (all in world coordinates): its columns are i, j, k and
/// origin, so the frame coordinates (a, b, c) of a point name the world
/// point origin + a·i + b·j + c·k.
///
/// Its inverse, `frame_from_world`, exists exactly when i, j, k are a basis
/// ([`is_basis`]); for an orthonormal frame it is [Rᵀ | −Rᵀ·origin].
/// Book: §1.5 Coordinate frames.
pub fn frame(origin: Vec3, i: Vec3, j: Vec3, k: Vec3) -> Mat4 {
    // SOLUTION BEGIN
    Mat4::from_cols(i.extend(0.0), j.extend(0.0), k.extend(0.0), origin.extend(1.0))
    // SOLUTION END
}

/// Whether `i`, `j`, `k` are linearly independent, i.e. span space and can
/// be the axes of a frame.
///
/// The test is relative, so it does not depend on the units:
/// |det[i j k]| = |i·(j × k)| > 1e-6·|i|·|j|·|k| — the parallelepiped they
/// span must have more than a millionth of the volume of the box of their
/// lengths (the vectors are not nearly coplanar). A zero vector, or a NaN or
/// infinite component, is never part of a basis. Book: §1.5 Coordinate
/// frames.
pub fn is_basis(i: Vec3, j: Vec3, k: Vec3) -> bool {
    // SOLUTION BEGIN
    if !(i.is_finite() && j.is_finite() && k.is_finite()) {
        return false;
    }
    // Rescale each vector by its largest component (the test does not care
    // about lengths), so neither side can overflow or underflow.
    let (si, sj, sk) = (i.abs().max_element(), j.abs().max_element(), k.abs().max_element());
    if si == 0.0 || sj == 0.0 || sk == 0.0 {
        return false;
    }
    let (i, j, k) = (i / si, j / sj, k / sk);
    // Compare the volume with the product of the lengths.
    let det = i.dot(j.cross(k));
    det.abs() > 1e-6 * i.length() * j.length() * k.length()
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::transforms::{transform_point, transform_vector};
    use approx::assert_abs_diff_eq;
    use raylab::Float;
    use raylab_testing::wide;

    #[test]
    fn frame_coordinates_name_origin_plus_combination_of_axes() {
        let (o, i, j, k) =
            (Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.0, 1.0, 0.0), Vec3::new(-1.0, 0.0, 0.0), Vec3::Z);
        let world_from_frame = frame(o, i, j, k);
        // (2, 3, 4) in the frame is o + 2i + 3j + 4k = (1 − 3, 2 + 2, 3 + 4) = (−2, 4, 7).
        assert_eq!(transform_point(&world_from_frame, Vec3::new(2.0, 3.0, 4.0)), Vec3::new(-2.0, 4.0, 7.0));
        // A vector ignores the origin: 2i + 3j + 4k = (−3, 2, 4).
        assert_eq!(transform_vector(&world_from_frame, Vec3::new(2.0, 3.0, 4.0)), Vec3::new(-3.0, 2.0, 4.0));
        // The frame's origin and axes are its columns' images.
        assert_eq!(transform_point(&world_from_frame, Vec3::ZERO), o);
        assert_eq!(transform_vector(&world_from_frame, Vec3::Y), j);
    }

    #[test]
    fn inverse_frame_reads_coordinates_back() {
        // A skewed, non-orthonormal frame: the inverse still exists.
        let world_from_frame =
            frame(Vec3::new(5.0, -1.0, 2.0), Vec3::new(2.0, 0.0, 0.0), Vec3::new(1.0, 1.0, 0.0), Vec3::ONE);
        let frame_from_world = world_from_frame.inverse();
        let p = Vec3::new(0.5, -2.0, 3.0);
        let round_trip = transform_point(&frame_from_world, transform_point(&world_from_frame, p));
        // Entries ≤ 5 and a 4×4 inverse: a few dozen ε of rounding at |p| ≈ 3.
        assert_abs_diff_eq!(round_trip, p, epsilon = 64.0 * Float::EPSILON * 3.0);
    }

    #[test]
    fn independent_triples_are_bases() {
        assert!(is_basis(Vec3::X, Vec3::Y, Vec3::Z));
        // Left-handed is still a basis: det = −1.
        assert!(is_basis(Vec3::Y, Vec3::X, Vec3::Z));
        // Skewed: det[(1,0,0) (1,1,0) (1,1,1)] = 1 (triangular).
        assert!(is_basis(Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::ONE));
        // Units do not matter: the same axes at 1e-15 and 1e15 (past where
        // |i|·|j|·|k| would underflow or overflow in f32).
        assert!(is_basis(1e-15 * Vec3::X, 1e-15 * Vec3::Y, 1e15 * Vec3::Z));
        assert!(is_basis(1e15 * Vec3::X, 1e15 * Vec3::Y, 1e15 * Vec3::Z));
        assert!(is_basis(1e-15 * Vec3::X, 1e-15 * Vec3::Y, 1e-15 * Vec3::Z));
    }

    #[test]
    fn dependent_triples_are_not_bases() {
        // Coplanar: (7, 8, 9) = 2·(4, 5, 6) − (1, 2, 3), det = 0 by hand.
        let (a, b, c) = (Vec3::new(1.0, 2.0, 3.0), Vec3::new(4.0, 5.0, 6.0), Vec3::new(7.0, 8.0, 9.0));
        assert!(!is_basis(a, b, c));
        // All three in the xy plane.
        assert!(!is_basis(Vec3::X, Vec3::Y, Vec3::new(1.0, 1.0, 0.0)));
        // Two equal, or two opposite.
        assert!(!is_basis(Vec3::X, Vec3::Y, Vec3::X));
        assert!(!is_basis(Vec3::X, Vec3::Y, -Vec3::Y));
        // One zero vector, in each place.
        assert!(!is_basis(Vec3::ZERO, Vec3::Y, Vec3::Z));
        assert!(!is_basis(Vec3::X, Vec3::ZERO, Vec3::Z));
        assert!(!is_basis(Vec3::X, Vec3::Y, Vec3::ZERO));
        // Not finite.
        assert!(!is_basis(Vec3::new(Float::NAN, 0.0, 0.0), Vec3::Y, Vec3::Z));
        assert!(!is_basis(Vec3::X, Vec3::new(0.0, Float::INFINITY, 0.0), Vec3::Z));
    }

    #[test]
    fn nearly_coplanar_is_judged_by_the_relative_threshold() {
        // k = (0, 0, δ) + x: det = δ, |i||j||k| ≈ 1, so the verdict flips at δ = 1e-6.
        let k = |d: Float| Vec3::new(1.0, 0.0, d);
        assert!(is_basis(Vec3::X, Vec3::Y, k(1e-5)));
        assert!(!is_basis(Vec3::X, Vec3::Y, k(1e-7)));
        // Scaled by 1e4 the same shapes keep their verdicts.
        assert!(is_basis(1e4 * Vec3::X, Vec3::Y, 1e4 * k(1e-5)));
        assert!(!is_basis(1e4 * Vec3::X, Vec3::Y, 1e4 * k(1e-7)));
    }

    #[test]
    fn coplanar_triples_from_an_f64_brute_force_are_rejected() {
        // Points on the plane x + 2y − z = 0 (exact in any float: small
        // integers), chosen so no two are parallel; the exact det is 0.
        let on_plane = |x: Float, y: Float| Vec3::new(x, y, x + 2.0 * y);
        for (a, b, c) in [((1.0, 0.0), (0.0, 1.0), (3.0, -2.0)), ((5.0, 7.0), (-3.0, 2.0), (11.0, -13.0))] {
            let (i, j, k) = (on_plane(a.0, a.1), on_plane(b.0, b.1), on_plane(c.0, c.1));
            // Independent check in f64: the determinant is exactly 0.
            let f = |v: Vec3| [wide(v.x), wide(v.y), wide(v.z)];
            let (p, q, r) = (f(i), f(j), f(k));
            let det64 = p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0])
                + p[2] * (q[0] * r[1] - q[1] * r[0]);
            assert_eq!(det64, 0.0);
            assert!(!is_basis(i, j, k), "{i} {j} {k}");
        }
    }
}
