//! Texture coordinates: where on a texture a point of a surface lies.
//!
//! Each shape has its own parametrisation: longitude and latitude on a
//! sphere, two axes on a plane, barycentric blending on a triangle. All three
//! give (u, v) with v growing upward, as [`crate::bilinear`] reads an image
//! (row 0 at v = 1), so a map appears upright.

use raylab::math::consts::{PI, TAU};
use raylab::{Float, Vec2, Vec3};

/// Texture coordinates of a point `p` of the unit sphere around the origin
/// (object space, +y up), by longitude and latitude:
///
/// ```text
/// u = ½ + atan2(−z, x)/2π        v = ½ + atan2(y, √(x² + z²))/π
/// ```
///
/// v is the polar angle θ measured from the south pole (−y), over π: 0 at the
/// south pole, ½ on the equator, 1 at the north pole. u is the longitude over
/// 2π, measured around +y from −x: u = 0 at (−1, 0, 0), ¼ at (0, 0, 1), ½ at
/// (1, 0, 0), ¾ at (0, 0, −1). Seen from outside (from +z, say) u grows to
/// the right, so a texture is not mirrored. u ∈ [0, 1]: the seam is the half
/// circle through −x, where u is 0 (z = +0) or 1 (z = −0), one and the same
/// column for a wrapping lookup. At the poles the longitude means nothing:
/// u is ½ or, by the signs of zero in x and z, 0 or 1.
///
/// Only the direction of `p` matters: a hit point a few roundings off the
/// sphere needs no normalisation, and the latitude by atan2 (not acos(−y),
/// which is NaN for y = −1.0000001 and ill-conditioned at the poles) is
/// accurate everywhere. The zero vector gives (½, ½); never NaN for finite
/// `p`. Book: §10.1 Spherical coordinates.
pub fn sphere_uv(p: Vec3) -> Vec2 {
    debug_assert!(p.is_finite(), "sphere_uv: p = {p}");
    // SOLUTION BEGIN
    // The longitude φ ∈ [−π, π] from +x toward −z, shifted so the seam is at −x.
    let u = 0.5 + (-p.z).atan2(p.x) / TAU;
    // The latitude ∈ [−π/2, π/2] from the equator, shifted to start at the south pole.
    let v = 0.5 + p.y.atan2((p.x * p.x + p.z * p.z).sqrt()) / PI;
    Vec2::new(u, v)
    // SOLUTION END
}

/// Texture coordinates of a point `p` of the plane through `origin` spanned by
/// `u_axis` = a and `v_axis` = b: the (u, v) with p = origin + u·a + v·b. One
/// texture tile is the parallelogram of the two axes; their lengths set its
/// size. With d = p − origin, (u, v) solve the normal equations
///
/// ```text
/// ⎡a·a  a·b⎤ ⎡u⎤   ⎡d·a⎤
/// ⎣a·b  b·b⎦ ⎣v⎦ = ⎣d·b⎦,    det = (a·a)(b·b) − (a·b)² = |a × b|²,
/// ```
///
/// by Cramer's rule: u = ((d·a)(b·b) − (d·b)(a·b))/det, v = ((d·b)(a·a) −
/// (d·a)(a·b))/det. For perpendicular axes this is u = d·a/|a|², v = d·b/|b|².
/// A point off the plane is projected onto it along the normal a × b (the
/// least-squares solution), so rounding in the hit point does no harm.
///
/// The axes must be non-zero and not parallel (debug builds check it); in
/// release such axes give (0, 0). Book: §10.2 Planar mapping.
pub fn plane_uv(p: Vec3, origin: Vec3, u_axis: Vec3, v_axis: Vec3) -> Vec2 {
    debug_assert!(
        u_axis.cross(v_axis).length_squared() > 0.0,
        "plane_uv: the axes {u_axis} and {v_axis} span no plane"
    );
    // SOLUTION BEGIN
    // The Gram matrix of the axes and its determinant |a × b|².
    let (aa, bb, ab) = (u_axis.dot(u_axis), v_axis.dot(v_axis), u_axis.dot(v_axis));
    let det = u_axis.cross(v_axis).length_squared();
    if !(det > 0.0 && det.is_finite()) {
        return Vec2::ZERO;
    }
    // The right-hand side, and Cramer's rule.
    let d = p - origin;
    let (da, db) = (d.dot(u_axis), d.dot(v_axis));
    Vec2::new((da * bb - db * ab) / det, (db * aa - da * ab) / det)
    // SOLUTION END
}

/// Texture coordinates of the point of a triangle with barycentrics (β, γ)
/// (lecture 03's convention: p = (1 − β − γ)a + βb + γc): the vertices' uvs
/// blended the same way,
///
/// ```text
/// uv = (1 − β − γ)·uv₀ + β·uv₁ + γ·uv₂.
/// ```
///
/// (β, γ) come from the triangle test (a mesh's hit carries them in `Hit::uv`
/// before they are replaced by this). Book: §10.2 Barycentric mapping.
pub fn triangle_uv(uvs: &[Vec2; 3], beta: Float, gamma: Float) -> Vec2 {
    // SOLUTION BEGIN
    (1.0 - beta - gamma) * uvs[0] + beta * uvs[1] + gamma * uvs[2]
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_abs_diff_eq;
    use raylab_testing::uv::sphere_grid;

    const EPS: Float = Float::EPSILON;

    fn v3(x: Float, y: Float, z: Float) -> Vec3 {
        Vec3::new(x, y, z)
    }

    #[test]
    fn sphere_poles_have_v_zero_and_one() {
        // atan2(±1, 0) = ±π/2 → v = ½ ± ½, exactly (π/2 over π is ½ in floats). The longitude
        // of a pole is atan2(∓0, ±0): −0 → u = ½ for (0, 1, 0), but π → u = 1 for −Y = (−0,
        // −1, −0); any u is right there, as long as it is in [0, 1] (Book §10.1; the check
        // asks no more).
        for (pole, v) in [(Vec3::Y, 1.0), (Vec3::new(0.0, -1.0, 0.0), 0.0), (-Vec3::Y, 0.0)] {
            let uv = sphere_uv(pole);
            assert!(
                uv.y == v && (0.0..=1.0).contains(&uv.x),
                "pole {pole}: {uv}; v must be exactly {v}, and u anything in [0, 1]"
            );
        }
    }

    #[test]
    fn sphere_equator_axis_points_by_hand() {
        // Latitude 0 on the equator: v = ½. Longitude atan2(−z, x): +x → 0 → u = ½; +z → −π/2 →
        // u = ¼; −z → π/2 → u = ¾; −x → atan2(−0, −1) = −π → u = 0 (atan2(+0, −1) = π, u = 1, for
        // z = −0). Tolerance 2ε: one rounding of atan2 and one of the sum.
        let cases = [(Vec3::X, 0.5), (Vec3::Z, 0.25), (-Vec3::Z, 0.75), (v3(-1.0, 0.0, 0.0), 0.0)];
        for (p, u) in cases {
            assert_abs_diff_eq!(sphere_uv(p), Vec2::new(u, 0.5), epsilon = 2.0 * EPS);
        }
        assert_abs_diff_eq!(sphere_uv(v3(-1.0, 0.0, -0.0)), Vec2::new(1.0, 0.5), epsilon = 2.0 * EPS);
    }

    #[test]
    fn sphere_uv_inverts_longitude_and_latitude() {
        // The inverse map, written from the definition (independent of the code): φ = 2π(u − ½),
        // λ = π(v − ½), p = (cos λ cos φ, sin λ, −cos λ sin φ). Every (u, v) of a 9 × 9 grid
        // inside the seam and the poles comes back within 8ε (sin, cos, atan2 and the
        // products, a few ulp each); scaling p by 3 or 1/7 changes nothing beyond that.
        for (uv, p) in sphere_grid() {
            for s in [1.0, 3.0, 1.0 / 7.0] {
                assert_abs_diff_eq!(sphere_uv(s * p), uv, epsilon = 8.0 * EPS);
            }
        }
    }

    #[test]
    fn sphere_uv_is_finite_slightly_off_the_sphere_and_at_zero() {
        // A pole 1 ulp outside the sphere (acos(−y) would be NaN there) and the zero vector.
        // At the pole u may be anything in [0, 1] (Book §10.1); v is 0 and nothing is NaN.
        let outside = sphere_uv(v3(0.0, -(1.0 as Float).next_up(), 0.0));
        assert!(outside.y == 0.0 && (0.0..=1.0).contains(&outside.x), "{outside}: v must be 0, u in [0, 1]");
        assert_eq!(sphere_uv(Vec3::ZERO), Vec2::new(0.5, 0.5));
    }

    #[test]
    fn plane_axes_map_to_the_unit_coordinates() {
        // Origin (1, 2, 3), perpendicular axes a = (2, 0, 0), b = (0, 0, −3): p = o + u·a + v·b
        // by construction; these small values are exact in floats, so the answers are exact.
        let (o, a, b) = (v3(1.0, 2.0, 3.0), v3(2.0, 0.0, 0.0), v3(0.0, 0.0, -3.0));
        assert_eq!(plane_uv(o, o, a, b), Vec2::ZERO);
        assert_eq!(plane_uv(o + a, o, a, b), Vec2::new(1.0, 0.0));
        assert_eq!(plane_uv(o + b, o, a, b), Vec2::new(0.0, 1.0));
        assert_eq!(plane_uv(o - 0.5 * a + 2.0 * b, o, a, b), Vec2::new(-0.5, 2.0));
        // 5 units off the plane along its normal a × b: projected back, the same (u, v).
        assert_eq!(plane_uv(o + a + 5.0 * Vec3::Y, o, a, b), Vec2::new(1.0, 0.0));
    }

    #[test]
    fn plane_uv_solves_for_skew_axes() {
        // a = (1, 0, 0), b = (1, 1, 0) (45° apart): p = o + 2a + 3b = o + (5, 3, 0). Projecting
        // on each axis alone would give u = d·a/|a|² = 5, wrong; the solve gives (2, 3). Gram
        // matrix [1 1; 1 2], det 1, all integers: exact.
        let (o, a, b) = (v3(-1.0, 0.5, 2.0), Vec3::X, v3(1.0, 1.0, 0.0));
        assert_eq!(plane_uv(o + 2.0 * a + 3.0 * b, o, a, b), Vec2::new(2.0, 3.0));
    }

    #[test]
    fn triangle_uv_at_vertices_and_centroid() {
        // (β, γ) = (0, 0), (1, 0), (0, 1) are the vertices a, b, c: their uvs exactly (weights
        // 1 and 0). The centroid (⅓, ⅓) blends them equally: the mean of the uvs, here
        // ((0 + 1 + 0.5)/3, (0 + 0.25 + 1)/3) = (0.5, 5/12), within 4ε (three products, a sum).
        let uvs = [Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.25), Vec2::new(0.5, 1.0)];
        assert_eq!(triangle_uv(&uvs, 0.0, 0.0), uvs[0]);
        assert_eq!(triangle_uv(&uvs, 1.0, 0.0), uvs[1]);
        assert_eq!(triangle_uv(&uvs, 0.0, 1.0), uvs[2]);
        let third = 1.0 / 3.0;
        assert_abs_diff_eq!(triangle_uv(&uvs, third, third), Vec2::new(0.5, 5.0 / 12.0), epsilon = 4.0 * EPS);
        // Midway along the edge b–c (β = γ = ½): the mean of uv₁ and uv₂.
        assert_eq!(triangle_uv(&uvs, 0.5, 0.5), Vec2::new(0.75, 0.625));
    }
}
