//! Mirror reflection: the direction of the reflected ray.
//!
//! In a scene file: `[materials.mirror]` with `reflective = [0.9, 0.9, 0.9]`
//! (k_r, the weight lecture 08 gives the mirror ray).

use l05_shading::reflect;
use raylab::Vec3;

/// The direction of the ray reflected by a perfect mirror: r = d − 2(d·n)n,
/// the angle of reflection equal to the angle of incidence, in the plane of d
/// and n.
///
/// `dir` is the incoming ray's direction (toward the surface; need not be
/// unit, |r| = |dir|), `n` the unit normal facing the ray (`Hit::normal`,
/// dir·n ≤ 0), so r leaves on the side n faces: r·n = −dir·n ≥ 0. This is 05's
/// [`reflect`], the one formula for every mirror direction in the course (the
/// Phong highlight and the mirror ray); do not write it twice.
/// Book: §7.1 Mirror reflection.
pub fn mirror_direction(dir: Vec3, n: Vec3) -> Vec3 {
    debug_assert!(n.is_normalized(), "the normal must be unit length, got {n}");
    // SOLUTION BEGIN
    reflect(dir, n)
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Float;
    use raylab_testing::v;

    const EPS: Float = Float::EPSILON;

    #[test]
    fn angle_of_reflection_equals_angle_of_incidence() {
        // A 3-4-5 ray onto the floor: d = (0.6, −0.8, 0), n = +y, r = (0.6, 0.8, 0): the tangential
        // part kept, the normal part flipped. d·n = −0.8 exactly, 2·0.8 exact, −0.8 + 1.6 rounds
        // to the float nearest 0.8 (Sterbenz): exact.
        assert_eq!(mirror_direction(v(0.6, -0.8, 0.0), Vec3::Y), v(0.6, 0.8, 0.0));
        // At 45° onto the wall x = 0 seen from +x: (−1, 0, −1)/√2 → (1, 0, −1)/√2. Tolerance 2ε:
        // a few roundings of √½.
        let s = (0.5 as Float).sqrt();
        let r = mirror_direction(v(-s, 0.0, -s), Vec3::X);
        assert!((r - v(s, 0.0, -s)).abs().max_element() <= 2.0 * EPS, "r = {r}");
    }

    #[test]
    fn normal_incidence_comes_straight_back() {
        // d = −n: r = −n − 2(−1)n = n.
        let n = v(2.0, -1.0, 2.0).normalize();
        let r = mirror_direction(-n, n);
        assert!((r - n).abs().max_element() <= 4.0 * EPS, "r = {r}");
        assert_eq!(mirror_direction(-Vec3::Z, Vec3::Z), Vec3::Z);
    }

    #[test]
    fn grazing_ray_goes_on_unchanged() {
        // d ⊥ n: d·n = 0 and r = d, exactly.
        let d = v(1.0, 0.0, -3.0);
        assert_eq!(mirror_direction(d, Vec3::Y), d);
    }

    #[test]
    fn length_is_kept_for_non_unit_directions() {
        // A ray taken into an object's space keeps a non-unit direction; the mirror ray must keep
        // its length so its t stays in the same units. (3, −4, 0)·k → (3, 4, 0)·k, exact for
        // k = 0.25 and 8 (powers of two).
        for k in [0.25, 8.0] {
            assert_eq!(mirror_direction(v(3.0, -4.0, 0.0) * k, Vec3::Y), v(3.0, 4.0, 0.0) * k);
        }
    }

    #[test]
    fn reflected_ray_leaves_on_the_normals_side_and_reflecting_twice_undoes_it() {
        // For many directions coming at a tilted normal: r·n = −d·n (the normal part flips),
        // r − (r·n)n = d − (d·n)n (the tangential part stays), and mirroring r again gives d.
        // Tolerance 8ε: inputs of length ≤ 1, a few roundings per step.
        let n = v(1.0, 3.0, -2.0).normalize();
        for a in 0..24 {
            for b in 1..12 {
                let (phi, theta) = (a as Float * 0.2618, b as Float * 0.1309);
                let d = v(theta.sin() * phi.cos(), -theta.cos(), theta.sin() * phi.sin());
                // Turn d to come at n (d·n ≤ 0), as at a real hit.
                let d = if d.dot(n) > 0.0 { -d } else { d };
                let r = mirror_direction(d, n);
                assert!((r.dot(n) + d.dot(n)).abs() <= 8.0 * EPS, "d = {d}: r·n = {}", r.dot(n));
                assert!(r.dot(n) >= 0.0, "d = {d}: r = {r} goes into the surface");
                let tangential = |x: Vec3| x - x.dot(n) * n;
                assert!((tangential(r) - tangential(d)).abs().max_element() <= 8.0 * EPS);
                let twice = mirror_direction(r, n);
                assert!((twice - d).abs().max_element() <= 8.0 * EPS, "d = {d}: twice {twice}");
            }
        }
    }
}
