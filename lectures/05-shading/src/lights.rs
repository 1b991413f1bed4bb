//! Light sources seen from a surface point: which way the light is, how far,
//! and how much of it arrives.
//!
//! In a scene file (`crates/raylab/SCENES.md`):
//! ```toml
//! [[lights]]
//! type = "spot"              # or "directional", "point", "rect", "sphere"
//! position = [0, 3, 0]
//! direction = [0, -1, 0]     # the way the light travels
//! inner = 10                 # degrees: full intensity inside
//! outer = 30                 # degrees: dark outside
//! attenuation = [1, 0, 0.5]  # 1 / (c + l·d + q·d²)
//! color = [1, 1, 1]
//! ```

use raylab::scene::{Attenuation, Light, LightKind};
use raylab::{BLACK, Color, Float, Vec3};

/// One light as seen from one surface point: what the shading needs.
/// Book: §5.6 Light sources.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample {
    /// Unit vector from the point toward the light (L).
    pub direction: Vec3,
    /// Distance from the point to the light; `Float::INFINITY` for a
    /// directional light (lecture 06's shadow rays stop there).
    pub distance: Float,
    /// The light's colour after distance attenuation and spot falloff: what
    /// arrives at the point, before the surface's cosine.
    pub intensity: Color,
}

/// Distance attenuation of point and spot lights: 1 / (c + l·d + q·d²) at
/// distance `distance` ≥ 0.
///
/// c alone keeps the light constant; l·d gives the falloff of a light along
/// a line, q·d² the physical inverse square law of a point source (with c
/// keeping it finite up close). The loaders guarantee c, l, q ≥ 0, not all 0;
/// where the denominator is not positive or the quotient not finite (d = 0
/// with c = 0, or q·d² underflowing to 0) the factor is 0: a point on the
/// light itself gets no light from it. Book: §5.7 Attenuation.
pub fn distance_falloff(attenuation: Attenuation, distance: Float) -> Float {
    debug_assert!(distance >= 0.0, "distance {distance} < 0");
    // SOLUTION BEGIN
    let Attenuation { constant, linear, quadratic } = attenuation;
    // The polynomial in d, then its reciprocal where it is a number.
    let denominator = constant + linear * distance + quadratic * distance * distance;
    let factor = 1.0 / denominator;
    if denominator > 0.0 && factor.is_finite() { factor } else { 0.0 }
    // SOLUTION END
}

/// The spot cone's falloff for a point at angle α from the spot's axis,
/// given `cos_angle` = cos α: 1 inside the `inner` half-angle, 0 outside the
/// `outer` one, and between them smoothstep on the cosines:
///
///   t = (cos α − cos outer) / (cos inner − cos outer),  s = t²(3 − 2t),
///
/// which rises from 0 at the outer edge to 1 at the inner edge with zero
/// slope at both ends, so the rim of the pool has no visible crease. Angles
/// in radians, 0 ≤ inner ≤ outer < π/2 (the loaders check it); inner =
/// outer is a hard edge (no division: every α is then inside or outside).
/// Points behind the spot (cos α ≤ 0) are outside. Book: §5.8 Spot lights.
pub fn spot_falloff(cos_angle: Float, inner: Float, outer: Float) -> Float {
    debug_assert!(0.0 <= inner && inner <= outer, "spot angles: inner {inner}, outer {outer}");
    // SOLUTION BEGIN
    let (cos_inner, cos_outer) = (inner.cos(), outer.cos());
    // Inside the inner cone, outside the outer one, then the smooth band between.
    if cos_angle >= cos_inner {
        1.0
    } else if cos_angle <= cos_outer {
        0.0
    } else {
        let t = (cos_angle - cos_outer) / (cos_inner - cos_outer);
        t * t * (3.0 - 2.0 * t)
    }
    // SOLUTION END
}

/// How `light` reaches `point`: the unit direction toward it, its distance
/// and the intensity that arrives.
///
/// - Directional: direction = −(the direction the light travels), distance
///   ∞, intensity = the light's colour (never dimmed).
/// - Point: direction = (position − point)/d, d = |position − point|,
///   intensity = colour · [`distance_falloff`]`(attenuation, d)`.
/// - Spot: as a point light, times [`spot_falloff`] of the angle between the
///   spot's axis and the ray from the light to the point (cos α = −L·axis).
/// - Rect and sphere (area lights): as a point light at the light's centre
///   (corner + ½(edge_u + edge_v) for a rect): the approximation used when no
///   shadow rays are traced. [`crate::sample_light`] picks other points.
///
/// A point exactly at the light's position has no direction to it: the
/// sample then has direction +y (any unit vector would do), distance 0 and
/// zero intensity, never NaN. Book: §5.6 Light sources.
pub fn illuminate(light: &Light, point: Vec3) -> LightSample {
    if let LightKind::Directional { direction } | LightKind::Spot { direction, .. } = light.kind {
        debug_assert!(direction.is_normalized(), "light direction {direction} is not unit length");
    }
    // SOLUTION BEGIN
    // Directional light: the same direction everywhere, never dimmed.
    let (position, attenuation, cone) = match light.kind {
        LightKind::Directional { direction } => {
            return LightSample { direction: -direction, distance: Float::INFINITY, intensity: light.color };
        }
        LightKind::Point { position, attenuation } => (position, attenuation, None),
        LightKind::Spot { position, direction, inner, outer, attenuation } => {
            (position, attenuation, Some((direction, inner, outer)))
        }
        // An area light stands at its centre.
        LightKind::Rect { corner, edge_u, edge_v, attenuation } => {
            (corner + 0.5 * (edge_u + edge_v), attenuation, None)
        }
        LightKind::Sphere { center, attenuation, .. } => (center, attenuation, None),
    };
    // Direction and distance to a light at a position; none from the light itself.
    let to_light = position - point;
    let Some(direction) = to_light.try_normalize() else {
        return LightSample { direction: Vec3::Y, distance: 0.0, intensity: BLACK };
    };
    let distance = to_light.length();
    // Dimmed with distance, then cut to the spot's cone.
    let mut factor = distance_falloff(attenuation, distance);
    if let Some((axis, inner, outer)) = cone {
        factor *= spot_falloff(-direction.dot(axis), inner, outer);
    }
    LightSample { direction, distance, intensity: light.color * factor }
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_abs_diff_eq;
    use raylab::radians;
    use raylab_testing::lights::{FALLOFF_AT_2, floor_at, spot_down};

    fn light(kind: LightKind) -> Light {
        Light { color: Color::new(1.0, 0.5, 0.25), shadows: true, kind }
    }

    fn point_light(position: Vec3, c: Float, l: Float, q: Float) -> Light {
        light(LightKind::Point {
            position,
            attenuation: Attenuation { constant: c, linear: l, quadratic: q },
        })
    }

    /// A spot at (0, 1, 0) shining straight down, no attenuation.
    fn spot(inner_degrees: Float, outer_degrees: Float) -> Light {
        light(spot_down(inner_degrees, outer_degrees))
    }

    #[test]
    fn directional_light_points_back_along_its_travel_everywhere() {
        // By the definition: L = −direction, d = ∞, intensity = colour, wherever the point is.
        let travel = Vec3::new(1.0, -2.0, 2.0) / 3.0;
        let l = light(LightKind::Directional { direction: travel });
        for p in [Vec3::ZERO, Vec3::new(1e6, -3.0, 2.0)] {
            let s = illuminate(&l, p);
            assert_eq!(s, LightSample { direction: -travel, distance: Float::INFINITY, intensity: l.color });
        }
    }

    #[test]
    fn point_light_attenuation_at_distance_2_by_hand() {
        // The light is 2 straight above the point (exact in floats): L = +y, d = 2, and
        // 1/(c + 2l + 4q) by hand (FALLOFF_AT_2). One division: 2ε relative.
        for ((c, l, q), expected) in FALLOFF_AT_2 {
            let light = point_light(Vec3::new(1.0, 2.0, 3.0), c, l, q);
            let s = illuminate(&light, Vec3::new(1.0, 0.0, 3.0));
            assert_eq!((s.direction, s.distance), (Vec3::Y, 2.0), "({c}, {l}, {q})");
            assert_abs_diff_eq!(s.intensity, light.color * expected, epsilon = 2.0 * Float::EPSILON);
        }
    }

    #[test]
    fn point_light_direction_is_unit_toward_the_light() {
        // Light at (1, 2, 2) from the origin: d = 3, L = (1, 2, 2)/3 (a 1-2-2-3
        // triple). Within the rounding of one normalisation: 2ε.
        let s = illuminate(&point_light(Vec3::new(1.0, 2.0, 2.0), 1.0, 0.0, 0.0), Vec3::ZERO);
        assert_abs_diff_eq!(s.direction, Vec3::new(1.0, 2.0, 2.0) / 3.0, epsilon = 2.0 * Float::EPSILON);
        assert_eq!(s.distance, 3.0);
    }

    #[test]
    fn spot_is_full_inside_the_inner_cone() {
        // Inner 30°, outer 60°, the light 1 above the floor (d = 1/cos α, no attenuation):
        // on the axis and 20° or 29° off it, intensity = colour · 1/(1 + 0 + 0), exactly.
        let l = spot(30.0, 60.0);
        for degrees in [0.0, 20.0, -29.0] {
            assert_eq!(illuminate(&l, floor_at(degrees)).intensity, l.color, "{degrees}°");
        }
    }

    #[test]
    fn spot_is_dark_outside_the_outer_cone_and_behind() {
        // 61° and 80° off the axis, and a point above the light (cos α < 0): exactly 0.
        let l = spot(30.0, 60.0);
        for p in [floor_at(61.0), floor_at(-80.0), Vec3::new(0.3, 2.0, 0.0)] {
            assert_eq!(illuminate(&l, p).intensity, BLACK, "{p}");
        }
    }

    #[test]
    fn spot_falls_off_by_smoothstep_of_the_cosines_between() {
        // Inner 30°, outer 60°: cos = 0.8660 and 0.5. At the angle whose cosine is the
        // midpoint 0.6830, t = ½ and s = ¼·(3 − 1) = ½; where cos α = 0.5 + ¼·0.3660,
        // t = ¼ and s = (1/16)·2.5 = 0.15625. The point goes through acos, tan and a
        // normalisation (a few ε in cos α), divided by the band 0.366 and times the
        // slope ≤ 1.5: 64ε covers it.
        let l = spot(30.0, 60.0);
        let (ci, co) = (radians(30.0).cos(), radians(60.0).cos());
        for (t, expected) in [(0.5, 0.5), (0.25, 0.15625), (0.75, 0.84375)] {
            let alpha = (co + t * (ci - co)).acos();
            let s = illuminate(&l, Vec3::new(alpha.tan(), 0.0, 0.0));
            assert_abs_diff_eq!(s.intensity, l.color * expected, epsilon = 64.0 * Float::EPSILON);
        }
    }

    #[test]
    fn spot_with_equal_angles_has_a_hard_edge() {
        // inner = outer = 30°: 1 inside, 0 outside, no 0/0 in between.
        let l = spot(30.0, 30.0);
        assert_eq!(illuminate(&l, floor_at(29.0)).intensity, l.color);
        assert_eq!(illuminate(&l, floor_at(31.0)).intensity, BLACK);
        for c in [0.0, 0.5, radians(30.0).cos(), 1.0] {
            let f = spot_falloff(c, radians(30.0), radians(30.0));
            assert!(f == 0.0 || f == 1.0, "cos {c}: {f}");
        }
    }

    #[test]
    fn spot_is_attenuated_like_a_point_light() {
        // On the axis at d = 2 with quadratic attenuation: ¼ (as for the point light).
        let l = light(LightKind::Spot {
            position: Vec3::new(0.0, 2.0, 0.0),
            direction: -Vec3::Y,
            inner: radians(10.0),
            outer: radians(20.0),
            attenuation: Attenuation { constant: 0.0, linear: 0.0, quadratic: 1.0 },
        });
        assert_abs_diff_eq!(
            illuminate(&l, Vec3::ZERO).intensity,
            l.color * 0.25,
            epsilon = 2.0 * Float::EPSILON
        );
    }

    #[test]
    fn a_point_at_the_light_gets_a_unit_direction_and_no_light() {
        // d = 0: no direction to the light. Unit direction, zero intensity, no NaN, for
        // point and spot lights and every attenuation (1/(0 + 0 + 0) would be ∞).
        let p = Vec3::new(0.5, -1.0, 2.0);
        let lights = [
            point_light(p, 1.0, 0.0, 0.0),
            point_light(p, 0.0, 0.0, 1.0),
            light(LightKind::Spot {
                position: p,
                direction: Vec3::X,
                inner: 0.1,
                outer: 0.2,
                attenuation: Attenuation::default(),
            }),
        ];
        for l in &lights {
            let s = illuminate(l, p);
            assert!(s.direction.is_normalized() && s.distance == 0.0 && s.intensity == BLACK, "{s:?}");
        }
    }

    #[test]
    fn a_point_almost_at_the_light_stays_finite() {
        // d = 10⁻²⁰: q·d² underflows to 0 in f32 (10⁻⁴⁰ is below the smallest float),
        // so 1/(q·d²) would be ∞ and ∞·0 a NaN later. The factor is finite (or 0).
        let p = Vec3::ZERO;
        for (c, l, q) in [(0.0, 0.0, 1.0), (0.0, 1.0, 0.0), (1.0, 0.0, 0.0)] {
            let s = illuminate(&point_light(Vec3::new(0.0, 1e-20, 0.0), c, l, q), p);
            assert!(s.direction.is_normalized() && s.intensity.is_finite(), "({c}, {l}, {q}): {s:?}");
        }
        assert_eq!(distance_falloff(Attenuation { constant: 0.0, linear: 0.0, quadratic: 1.0 }, 0.0), 0.0);
    }
}
