//! Checks shared by this lecture's tests.

use raylab::{Float, Mat4, Vec3, Vec4};

/// How far from orthonormal a rotation built from unit vectors may be: each
/// entry of RᵀR is a 3-term dot product of numbers ≤ 1 that were rounded a
/// few times on the way, so a few ε. 8ε is 9.5e-7 in f32 (below the course's
/// 1e-6) and 1.8e-15 in f64.
pub const ORTHO_TOL: Float = 8.0 * Float::EPSILON;

/// `x` rounded to `Float`.
pub fn from_f64(x: f64) -> Float {
    x as Float
}

/// Asserts that the three vectors are unit length, pairwise orthogonal and
/// right-handed (u × v = w), each within [`ORTHO_TOL`].
pub fn assert_orthonormal(u: Vec3, v: Vec3, w: Vec3) {
    for (name, a) in [("u", u), ("v", v), ("w", w)] {
        assert!((a.length() - 1.0).abs() <= ORTHO_TOL, "|{name}| = {} is not 1", a.length());
    }
    for (name, d) in [("u·v", u.dot(v)), ("v·w", v.dot(w)), ("w·u", w.dot(u))] {
        assert!(d.abs() <= ORTHO_TOL, "{name} = {d:e} is not 0");
    }
    let handed = u.cross(v) - w;
    assert!(handed.abs().max_element() <= 2.0 * ORTHO_TOL, "u × v − w = {handed:?}: not right-handed");
}

/// Asserts that `m` is a rotation: linear (no translation, last row 0 0 0 1)
/// with orthonormal right-handed columns.
pub fn assert_rotation(m: &Mat4) {
    assert_eq!(m.w_axis, Vec4::W, "a rotation has no translation");
    assert_eq!(m.row(3), Vec4::W, "a rotation is affine");
    assert_orthonormal(m.x_axis.truncate(), m.y_axis.truncate(), m.z_axis.truncate());
}
