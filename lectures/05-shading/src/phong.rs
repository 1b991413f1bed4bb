//! The two specular highlights: Phong's (V·R)ⁿ and Blinn's (N·H)ⁿ.
//!
//! Both take unit vectors with the same conventions: `n` the surface normal
//! facing the eye, `l` from the point toward the light, `v` from the point
//! toward the eye. Both are 0 when the light is behind the surface (n·l ≤ 0):
//! a highlight is a reflection of the light, and there is none to reflect.
//! The cosine is clamped to [0, 1] before the power: below 0 the eye is away
//! from the lobe, above 1 only rounding can take it (both vectors are unit),
//! and 1 + ε raised to a huge exponent must not overflow. 0⁰ = 1, so exponent
//! 0 gives 1 wherever the light is in front: a highlight spread everywhere.

use raylab::{Float, Vec3};

use crate::reflect::reflect;

/// Phong's specular factor (max(R·V, 0))ⁿ, with R = reflect(−l, n) the mirror
/// direction of the light.
///
/// `n`, `l`, `v` unit; `l` from the point toward the light and `v` from the
/// point toward the eye (so −l is the direction the light travels, which
/// `reflect` expects). The highlight peaks (value 1) when the eye sits in the
/// mirror direction, V = R, and narrows as `exponent` ≥ 0 grows. 0 when
/// n·l ≤ 0. Book: §5.4 Phong's specular highlight.
pub fn phong_specular(n: Vec3, l: Vec3, v: Vec3, exponent: Float) -> Float {
    debug_assert!(n.is_normalized() && l.is_normalized() && v.is_normalized(), "n {n}, l {l}, v {v}");
    debug_assert!(exponent >= 0.0, "exponent {exponent} < 0");
    // SOLUTION BEGIN
    // No highlight from a light behind the surface.
    if n.dot(l) <= 0.0 {
        return 0.0;
    }
    // The mirror direction of the incoming light, and its cosine to the eye.
    let r = reflect(-l, n);
    let cos_rv = r.dot(v).clamp(0.0, 1.0);
    // The lobe: the cosine raised to the shininess.
    cos_rv.powf(exponent)
    // SOLUTION END
}

/// Blinn's specular factor (max(N·H, 0))ⁿ with the half vector
/// H = (l + v)/|l + v|.
///
/// `n`, `l`, `v` unit, as for [`phong_specular`]. H is halfway between the
/// light and the eye; it equals N exactly when the eye is in the mirror
/// direction, so the peak (value 1) is where Phong's is. In the plane of N
/// and L, the angle between N and H is half the angle θ between R and V, so
/// N·H = cos(θ/2): with the same exponent the Blinn lobe is wider (about
/// four times the exponent gives a similar size). 0 when n·l ≤ 0, and 0
/// when l = −v (the eye looks straight at the light through the surface: H
/// is undefined), never NaN. Book: §5.5 Blinn–Phong: the half vector.
pub fn blinn_specular(n: Vec3, l: Vec3, v: Vec3, exponent: Float) -> Float {
    debug_assert!(n.is_normalized() && l.is_normalized() && v.is_normalized(), "n {n}, l {l}, v {v}");
    debug_assert!(exponent >= 0.0, "exponent {exponent} < 0");
    // SOLUTION BEGIN
    // No highlight from a light behind the surface.
    if n.dot(l) <= 0.0 {
        return 0.0;
    }
    // The half vector; l + v = 0 has no direction, and no highlight.
    let Some(h) = (l + v).try_normalize() else {
        return 0.0;
    };
    // The lobe: the cosine of the normal to the half vector, raised to the shininess.
    n.dot(h).clamp(0.0, 1.0).powf(exponent)
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_abs_diff_eq;
    use raylab::radians;

    /// The unit vector in the xy plane at `degrees` from +y (the normal) toward +x.
    fn at_angle(degrees: Float) -> Vec3 {
        let a = radians(degrees);
        Vec3::new(a.sin(), a.cos(), 0.0)
    }

    /// A cosine near 1 carries a few ε of rounding (unit vectors from sin/cos,
    /// a reflection or a normalisation); raised to n it carries n times as much.
    fn tol(exponent: Float) -> Float {
        8.0 * Float::EPSILON * exponent.max(1.0)
    }

    const EXPONENTS: [Float; 5] = [1.0, 2.0, 10.0, 50.0, 200.0];

    #[test]
    fn phong_peaks_at_one_in_the_mirror_direction() {
        // N = y, L at 45° toward +x, V = L mirrored (45° toward −x): V = R, R·V = 1.
        let (l, v) = (at_angle(45.0), at_angle(-45.0));
        for e in EXPONENTS {
            assert_abs_diff_eq!(phong_specular(Vec3::Y, l, v, e), 1.0, epsilon = tol(e));
        }
    }

    #[test]
    fn phong_seen_along_the_normal_is_cos_45_to_the_n() {
        // N = y, L at 45°, V = N: R is at 45° on the other side, so R·V = cos 45° = √½
        // and the factor is (√½)ⁿ = 2^(−n/2): ½ for n = 2, 1/32 for n = 10.
        let l = at_angle(45.0);
        for (e, expected) in [(1.0, Float::sqrt(0.5)), (2.0, 0.5), (10.0, 1.0 / 32.0)] {
            assert_abs_diff_eq!(phong_specular(Vec3::Y, l, Vec3::Y, e), expected, epsilon = tol(e));
        }
    }

    #[test]
    fn blinn_peaks_at_one_when_the_half_vector_is_the_normal() {
        // L and V at ±45°: L + V = (0, √2, 0), so H = N and N·H = 1.
        let (l, v) = (at_angle(45.0), at_angle(-45.0));
        for e in EXPONENTS {
            assert_abs_diff_eq!(blinn_specular(Vec3::Y, l, v, e), 1.0, epsilon = tol(e));
        }
        // Also with the light straight above and the eye there too: L = V = N.
        assert_eq!(blinn_specular(Vec3::Y, Vec3::Y, Vec3::Y, 80.0), 1.0);
    }

    #[test]
    fn blinn_sees_half_the_angle_that_phong_sees() {
        // N = y, L at α toward +x, V at β toward −x (all in one plane). R is at α
        // toward −x, so the angle between R and V is θ = |α − β| and Phong (n = 1)
        // gives cos θ; H bisects L and V at (α − β)/2 from N, so Blinn gives cos(θ/2).
        // By hand for α = 45°, β = 0: Phong cos 45° = 0.7071, Blinn cos 22.5° = 0.9239.
        for (alpha, beta) in [(45.0, 0.0), (30.0, 70.0), (60.0, 10.0), (20.0, -30.0), (80.0, 80.0)] {
            let (l, v) = (at_angle(alpha), at_angle(-beta));
            let theta = radians(Float::abs(alpha - beta));
            assert_abs_diff_eq!(phong_specular(Vec3::Y, l, v, 1.0), theta.cos(), epsilon = tol(1.0));
            assert_abs_diff_eq!(blinn_specular(Vec3::Y, l, v, 1.0), (theta / 2.0).cos(), epsilon = tol(1.0));
        }
    }

    #[test]
    fn blinn_is_never_below_phong_at_the_same_exponent() {
        // cos(θ/2) ≥ cos θ for θ in [0, π], so in the plane of incidence Blinn's lobe
        // contains Phong's (then raised to the same n ≥ 0). Sweep the eye.
        let l = at_angle(35.0);
        for i in 0..=36 {
            let v = at_angle(-90.0 + 5.0 * i as Float);
            for e in EXPONENTS {
                let (p, b) = (phong_specular(Vec3::Y, l, v, e), blinn_specular(Vec3::Y, l, v, e));
                assert!(b + tol(e) >= p, "eye at {}°, n {e}: Blinn {b} < Phong {p}", -90 + 5 * i);
            }
        }
    }

    #[test]
    fn no_highlight_from_a_light_behind_the_surface() {
        // n·l ≤ 0: both 0, even with the eye in the (below-surface) mirror direction,
        // and even for exponent 0 (an unlit point is not "lit", so 0⁰ = 1 does not
        // apply). Grazing light is exactly X (cos 90° from sin/cos rounds either way).
        for l in [Vec3::X, at_angle(120.0), -Vec3::Y] {
            let mirror = reflect(-l, Vec3::Y);
            for v in [Vec3::Y, mirror.normalize(), at_angle(-45.0)] {
                for e in [0.0, 1.0, 30.0] {
                    assert_eq!(phong_specular(Vec3::Y, l, v, e), 0.0, "l {l} v {v} n {e}");
                    assert_eq!(blinn_specular(Vec3::Y, l, v, e), 0.0, "l {l} v {v} n {e}");
                }
            }
        }
    }

    #[test]
    fn exponent_zero_gives_one_wherever_the_light_is_in_front() {
        // x⁰ = 1 for every x, and 0⁰ = 1 by definition: here V is 90° from R (Phong's
        // cosine is 0), yet the factor is 1.
        let l = at_angle(45.0);
        for v in [at_angle(-45.0), Vec3::Y, at_angle(45.0), at_angle(80.0)] {
            assert_eq!(phong_specular(Vec3::Y, l, v, 0.0), 1.0, "v {v}");
            assert_eq!(blinn_specular(Vec3::Y, l, v, 0.0), 1.0, "v {v}");
        }
    }

    #[test]
    fn a_huge_exponent_stays_finite() {
        // n = 10⁴: at the peak the cosine is 1 − O(ε) (or rounds above 1, clamped), so
        // the result is within 10⁴·8ε of 1 (8·10⁻⁴ in f32); 45° off it, (√½)^10⁴
        // underflows to 0. Never NaN or infinite, never above 1.
        let e = 1e4;
        let (l, mirror) = (at_angle(45.0), at_angle(-45.0));
        for v in [mirror, Vec3::Y, at_angle(-44.9), at_angle(10.0)] {
            for f in [phong_specular(Vec3::Y, l, v, e), blinn_specular(Vec3::Y, l, v, e)] {
                assert!(f.is_finite() && (0.0..=1.0).contains(&f), "v {v}: {f}");
            }
        }
        assert_abs_diff_eq!(phong_specular(Vec3::Y, l, mirror, e), 1.0, epsilon = tol(e));
        assert_abs_diff_eq!(blinn_specular(Vec3::Y, l, mirror, e), 1.0, epsilon = tol(e));
        assert_eq!(phong_specular(Vec3::Y, l, Vec3::Y, e), 0.0);
    }

    #[test]
    fn light_opposite_the_eye_gives_zero_not_nan() {
        // l = −v: l + v = 0 and H has no direction. Here the light is in front
        // (n·l = cos 30° > 0) and the eye below the surface, looking at the light
        // through it. Blinn gives 0 for every exponent, 0 included.
        let l = at_angle(30.0);
        for e in [0.0, 1.0, 1e4] {
            assert_eq!(blinn_specular(Vec3::Y, l, -l, e), 0.0, "n {e}");
            assert!(phong_specular(Vec3::Y, l, -l, e).is_finite());
        }
    }

    #[test]
    fn using_minus_l_in_phong_moves_the_peak() {
        // The catalogued mistake R = reflect(l, n) (l already points to the light)
        // gives −R: its lobe points into the surface. Sweep the eye over the upper half
        // plane, from 89° toward −x to 89° toward +x. By hand, the reference peaks at the
        // mirror direction (−30°, value 1); the mistake gives (−R·V)⁺ = (−cos(30° + β))⁺
        // for an eye at β toward +x, which peaks at the grazing end (β = 89°, value
        // −cos 119° = 0.485) and is 0 at the true mirror direction.
        let l = at_angle(30.0);
        let wrong = |v: Vec3| reflect(l, Vec3::Y).dot(v).max(0.0).powf(20.0);
        let eyes: Vec<Float> = (-89..=89).map(|d| d as Float).collect();
        let argmax = |f: &dyn Fn(Vec3) -> Float| {
            eyes.iter().copied().max_by(|a, b| f(at_angle(*a)).total_cmp(&f(at_angle(*b)))).unwrap()
        };
        assert_eq!(argmax(&|v| phong_specular(Vec3::Y, l, v, 20.0)), -30.0);
        assert_eq!(argmax(&wrong), 89.0);
        assert_abs_diff_eq!(phong_specular(Vec3::Y, l, at_angle(-30.0), 20.0), 1.0, epsilon = tol(20.0));
        assert_eq!(wrong(at_angle(-30.0)), 0.0);
    }
}
