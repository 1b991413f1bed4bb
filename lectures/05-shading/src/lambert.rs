//! Lambert's cosine law: how much light a matte surface receives.

use raylab::{Float, Vec3};

/// The diffuse (Lambert) factor (N·L)⁺ = max(n·l, 0).
///
/// `n` is the unit surface normal on the side being shaded (the hit's normal,
/// facing the eye); `l` is the unit direction **from the point toward the
/// light**. A beam of light spread over a tilted surface covers more area, so
/// the light per unit area falls as the cosine of the angle between N and L:
/// 1 head-on, ½ at 60°, 0 at grazing incidence.
///
/// Why max(·, 0): a light behind the surface (n·l < 0) does not light it, and
/// the raw cosine would be negative, subtracting light that the other lights
/// and the ambient term gave. A back-lit point must be dark, not negative.
///
/// Why both vectors must be unit: the cosine is a dot product only of unit
/// vectors. Passing l = light position − point unnormalised multiplies the
/// result by the distance, so a far light looks brighter and a near one
/// dimmer, for the wrong reason (dimming with distance is attenuation's job,
/// §5.7). Book: §5.2 Lambert's cosine law.
pub fn lambert(n: Vec3, l: Vec3) -> Float {
    debug_assert!(n.is_normalized(), "lambert: n = {n} is not unit length");
    debug_assert!(l.is_normalized(), "lambert: l = {l} is not unit length");
    // SOLUTION BEGIN
    // The cosine of the angle of incidence, and no light from behind.
    n.dot(l).max(0.0)
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_abs_diff_eq;
    use raylab::radians;

    /// The unit vector at `degrees` from +y toward +x.
    fn at_angle(degrees: Float) -> Vec3 {
        let a = radians(degrees);
        Vec3::new(a.sin(), a.cos(), 0.0)
    }

    #[test]
    fn head_on_light_gives_one() {
        // cos 0° = 1, exactly.
        assert_eq!(lambert(Vec3::Y, Vec3::Y), 1.0);
    }

    #[test]
    fn light_at_60_degrees_gives_one_half() {
        // cos 60° = ½. The vector comes from sin/cos of a rounded angle: within 4ε.
        assert_abs_diff_eq!(lambert(Vec3::Y, at_angle(60.0)), 0.5, epsilon = 4.0 * Float::EPSILON);
        // Only the angle counts, not its orientation about the normal.
        assert_abs_diff_eq!(lambert(Vec3::Y, at_angle(-60.0)), 0.5, epsilon = 4.0 * Float::EPSILON);
    }

    #[test]
    fn grazing_light_gives_zero() {
        // L ⟂ N: cos 90° = 0, exactly, since L has no y component.
        assert_eq!(lambert(Vec3::Y, Vec3::X), 0.0);
    }

    #[test]
    fn light_from_behind_gives_zero_not_negative() {
        // Angles past 90°: the raw cosine is negative; the factor is exactly 0.
        for degrees in [100.0, 120.0, 150.0, 180.0] {
            let f = lambert(Vec3::Y, at_angle(degrees));
            assert_eq!(f, 0.0, "{degrees}°");
        }
    }

    #[test]
    fn forgetting_the_max_makes_a_back_lit_point_negative() {
        // The catalogued mistake `n.dot(l)`: at 120° it gives cos 120° = −½, which
        // would darken the ambient light; the reference gives 0.
        let forgot_max = |n: Vec3, l: Vec3| n.dot(l);
        let l = at_angle(120.0);
        assert_abs_diff_eq!(forgot_max(Vec3::Y, l), -0.5, epsilon = 4.0 * Float::EPSILON);
        assert_eq!(lambert(Vec3::Y, l), 0.0);
    }

    #[test]
    fn an_unnormalised_l_is_off_by_its_length() {
        // The catalogued mistake: L = light − point without normalising. A light at
        // (√3, 1, 0)·2 seen from the origin is at 60° and distance 4: the reference
        // gives cos 60° = ½, the mistake 4·½ = 2 (a near light looks dim, a far one
        // bright). Tolerance: √3 and the normalisation round, 8ε relative.
        let to_light = Vec3::new(Float::sqrt(3.0), 1.0, 0.0) * 2.0;
        let unnormalised = to_light.dot(Vec3::Y).max(0.0);
        let reference = lambert(Vec3::Y, to_light.normalize());
        assert_abs_diff_eq!(reference, 0.5, epsilon = 8.0 * Float::EPSILON);
        assert_abs_diff_eq!(unnormalised, 2.0, epsilon = 8.0 * Float::EPSILON);
        assert_abs_diff_eq!(unnormalised / reference, to_light.length(), epsilon = 32.0 * Float::EPSILON);
    }
}
