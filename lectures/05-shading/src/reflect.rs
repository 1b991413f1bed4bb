//! The mirror direction about a normal: the one formula behind Phong's
//! highlight here and the mirror rays of lecture 07.

use raylab::Vec3;

/// Mirror direction of `v` about the unit normal `n`: r = v − 2(v·n)n.
///
/// `v` points **toward** the surface (an incoming ray direction, or −L for the
/// light); the result points away from it on the same side as the normal's
/// mirror image: the tangential part of `v` is kept, the normal part flipped.
/// So |r| = |v| (`v` need not be unit), reflecting twice gives `v` back, and a
/// `v` along the normal comes straight back. `n` must be unit length (an
/// unnormalised `n` scales the normal part by |n|² and bends r). Either side
/// of the surface works: r does not change when `n` is negated.
/// Book: §5.3 The reflection vector (reused in §7.1).
pub fn reflect(v: Vec3, n: Vec3) -> Vec3 {
    debug_assert!(n.is_normalized(), "reflect: n = {n} is not unit length");
    // SOLUTION BEGIN
    // Remove the normal part of v twice: once to reach the tangent plane, once more to mirror it.
    v - 2.0 * v.dot(n) * n
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_abs_diff_eq;
    use raylab::Float;

    /// √½, the components of a unit vector at 45°.
    fn half_sqrt2() -> Float {
        Float::sqrt(0.5)
    }

    #[test]
    fn reflects_at_45_degrees_into_the_mirror_direction() {
        // v = (1, −1, 0)/√2 comes down at 45° onto the floor n = +y; by hand the
        // mirror keeps x and flips y: r = (1, 1, 0)/√2. v·n = −√½ and
        // r_y = −√½ + 2·√½ is a few roundings of √½: 2ε.
        let s = half_sqrt2();
        let r = reflect(Vec3::new(s, -s, 0.0), Vec3::Y);
        assert_abs_diff_eq!(r, Vec3::new(s, s, 0.0), epsilon = 2.0 * Float::EPSILON);
    }

    #[test]
    fn normal_incidence_comes_straight_back() {
        // v = −n: r = −n − 2(−1)n = n, exactly (every product is by 1 or 2).
        assert_eq!(reflect(-Vec3::Y, Vec3::Y), Vec3::Y);
        assert_eq!(reflect(Vec3::new(0.0, 0.0, -3.0), Vec3::Z), Vec3::new(0.0, 0.0, 3.0));
    }

    #[test]
    fn a_vector_along_the_surface_is_unchanged() {
        // v·n = 0: nothing to flip (exact).
        assert_eq!(reflect(Vec3::new(2.0, 0.0, -1.0), Vec3::Y), Vec3::new(2.0, 0.0, -1.0));
    }

    #[test]
    fn reflection_keeps_the_length() {
        // A mirror is an isometry: |r| = |v| for any v. The normal is unit up to one
        // normalisation; |r| then differs from |v| by a few roundings: 8ε relative.
        let n = Vec3::new(1.0, 2.0, -2.0) / 3.0;
        for v in [Vec3::new(0.3, -4.0, 1.0), Vec3::new(-7.0, 0.5, 2.5), Vec3::new(1e-3, 2e-3, -5e-4)] {
            let r = reflect(v, n);
            assert_abs_diff_eq!(r.length(), v.length(), epsilon = 8.0 * Float::EPSILON * v.length());
        }
    }

    #[test]
    fn reflecting_twice_is_the_identity() {
        // The mirror is an involution: reflect(reflect(v, n), n) = v. Two reflections of
        // a vector of length ≈ 4: a few roundings of size 4ε each, so 32ε absolute.
        let n = Vec3::new(2.0, -3.0, 6.0) / 7.0;
        for v in [Vec3::new(0.3, -4.0, 1.0), Vec3::new(-1.0, 0.5, 2.5), Vec3::X] {
            assert_abs_diff_eq!(reflect(reflect(v, n), n), v, epsilon = 32.0 * Float::EPSILON);
        }
    }

    #[test]
    fn the_side_of_the_normal_does_not_matter() {
        // r = v − 2(v·n)n is even in n: both factors of n change sign. Exact.
        let (v, n) = (Vec3::new(0.6, -0.8, 0.0), Vec3::new(0.0, 0.6, 0.8));
        assert_eq!(reflect(v, n), reflect(v, -n));
    }
}
