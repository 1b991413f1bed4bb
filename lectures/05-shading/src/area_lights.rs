//! Area lights seen from a surface point: one point of the light at a time.
//!
//! An area light is many point lights: every point of a rectangle or of a
//! ball shines like a point light of the whole light's colour, and the
//! shading averages over the points (lecture 06 does it, with a shadow ray
//! for each, and gets soft shadows). Here a uniform sample u ∈ [0, 1)² picks
//! one point; [`illuminate`] without samples stands the light at its centre.
//!
//! In a scene file (`crates/raylab/SCENES.md`):
//! ```toml
//! [[lights]]
//! type = "rect"            # corner + a·edge_u + b·edge_v, a, b ∈ [0, 1]
//! corner = [-0.5, 4, -0.5]
//! edge_u = [1, 0, 0]
//! edge_v = [0, 0, 1]
//!
//! [[lights]]
//! type = "sphere"
//! center = [2, 4, 0]
//! radius = 0.5
//! ```

use raylab::scene::{Light, LightKind};
use raylab::{Vec2, Vec3};

use crate::lights::{LightSample, illuminate};

/// Shirley and Chiu's concentric map of the unit square onto the unit disc:
/// with a = 2u − 1 ∈ [−1, 1]², the square ring max(|aₓ|, |a_y|) = r goes to
/// the circle of radius r,
///
///   |aₓ| > |a_y|:  r = aₓ, φ = (π/4)·a_y/aₓ
///   otherwise:     r = a_y, φ = π/2 − (π/4)·aₓ/a_y   (and 0 for a = 0),
///
/// and the point is (r cos φ, r sin φ). It keeps areas in proportion (the
/// inner square of half the side, ¼ of the area, fills the disc of radius ½,
/// ¼ of its area), so uniform and stratified samples stay so on the disc,
/// and it distorts them less than the polar map (√u₁, 2πu₂) does. It is odd:
/// u and 1 − u go to opposite points. Book: §5.10 Area lights.
pub fn concentric_disk(u: Vec2) -> Vec2 {
    // SOLUTION BEGIN
    // From [0, 1)² to [−1, 1]², the centre to the centre.
    let a = 2.0 * u - Vec2::ONE;
    if a == Vec2::ZERO {
        return Vec2::ZERO;
    }
    // The square ring's half side is the circle's radius; the position along the ring its angle.
    let quarter = raylab::math::consts::FRAC_PI_4;
    let (r, phi) = if a.x.abs() > a.y.abs() {
        (a.x, quarter * (a.y / a.x))
    } else {
        (a.y, 2.0 * quarter - quarter * (a.x / a.y))
    };
    r * Vec2::new(phi.cos(), phi.sin())
    // SOLUTION END
}

/// How the point of `light` picked by the uniform sample `u` ∈ [0, 1]²
/// reaches `point`: the [`LightSample`] of a point light of the light's
/// colour and attenuation standing there.
///
/// - Rect: the point corner + uₓ·edge_u + u_y·edge_v.
/// - Sphere: the point center + radius·(dₓ·e₁ + d_y·e₂), d =
///   [`concentric_disk`]`(u)`, on the disc through the centre perpendicular
///   to w = (point − center)/|point − center|, (e₁, e₂, w) orthonormal: the
///   silhouette of the ball seen from far away. (Seen from nearby the true
///   silhouette is a smaller circle nearer the point; the disc is the
///   course's approximation.) A point at the centre takes w = +y.
/// - Directional, point and spot lights have a single point: exactly
///   [`illuminate`]`(light, point)`, whatever `u`.
///
/// Points of a rect shine to both of its sides, with no cosine at the
/// emitter. Never NaN: a sample on `point` itself gets the zero sample of
/// [`illuminate`]. Book: §5.10 Area lights.
pub fn sample_light(light: &Light, point: Vec3, u: Vec2) -> LightSample {
    debug_assert!(u.cmpge(Vec2::ZERO).all() && u.cmple(Vec2::ONE).all(), "sample {u} outside [0, 1]²");
    // SOLUTION BEGIN
    // The point of the light that the sample picks; a light with one point is that point.
    let (position, attenuation) = match light.kind {
        LightKind::Directional { .. } | LightKind::Point { .. } | LightKind::Spot { .. } => {
            return illuminate(light, point);
        }
        LightKind::Rect { corner, edge_u, edge_v, attenuation } => {
            (corner + u.x * edge_u + u.y * edge_v, attenuation)
        }
        LightKind::Sphere { center, radius, attenuation } => {
            // The silhouette disc, perpendicular to the way from the centre to the point.
            let w = (point - center).try_normalize().unwrap_or(Vec3::Y);
            let (e1, e2) = w.any_orthonormal_pair();
            let d = concentric_disk(u);
            (center + radius * (d.x * e1 + d.y * e2), attenuation)
        }
    };
    // That point shines like a point light of the whole light's colour.
    illuminate(&Light { kind: LightKind::Point { position, attenuation }, ..*light }, point)
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_abs_diff_eq;
    use raylab::scene::Attenuation;
    use raylab::{BLACK, Color, Float};

    const EPS: Float = Float::EPSILON;
    const COLOR: Color = Color::new(1.0, 0.5, 0.25);

    fn light(kind: LightKind) -> Light {
        Light { color: COLOR, shadows: true, kind }
    }

    /// The rect light 2 above the origin, 2 wide in x and 4 deep in z, starting at x = z = 0;
    /// quadratic attenuation.
    fn rect() -> Light {
        let attenuation = Attenuation { constant: 0.0, linear: 0.0, quadratic: 1.0 };
        light(LightKind::Rect {
            corner: Vec3::new(0.0, 2.0, 0.0),
            edge_u: Vec3::new(2.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 0.0, 4.0),
            attenuation,
        })
    }

    /// A ball light of radius 2 at the origin, no attenuation.
    fn ball() -> Light {
        light(LightKind::Sphere { center: Vec3::ZERO, radius: 2.0, attenuation: Attenuation::default() })
    }

    #[test]
    fn the_concentric_map_takes_square_rings_to_circles() {
        // By the formulas: the centre stays; the middles of the square's sides go to the
        // circle's (1, 0), (0, 1), (−1, 0), (0, −1); the corner (1, 1) to angle π/4 at r = 1.
        // A few roundings of a cosine and a sine: 4ε.
        let cases = [
            ((0.5, 0.5), (0.0, 0.0)),
            ((1.0, 0.5), (1.0, 0.0)),
            ((0.5, 1.0), (0.0, 1.0)),
            ((0.0, 0.5), (-1.0, 0.0)),
            ((0.5, 0.0), (0.0, -1.0)),
            ((1.0, 1.0), (0.5f64.sqrt(), 0.5f64.sqrt())),
            ((0.0, 0.0), (-(0.5f64.sqrt()), -(0.5f64.sqrt()))),
        ];
        for ((ux, uy), (x, y)) in cases {
            let d = concentric_disk(Vec2::new(ux, uy));
            assert_abs_diff_eq!(d, Vec2::new(x as Float, y as Float), epsilon = 4.0 * EPS);
        }
        // Every point of a 33 × 33 grid lands on the circle of its ring's half side
        // max(|aₓ|, |a_y|), and u, 1 − u on opposite points (the map is odd).
        for i in 0..=32 {
            for j in 0..=32 {
                let u = Vec2::new(i as Float / 32.0, j as Float / 32.0);
                let a = 2.0 * u - Vec2::ONE;
                let d = concentric_disk(u);
                assert_abs_diff_eq!(d.length(), a.abs().max_element(), epsilon = 4.0 * EPS);
                assert_abs_diff_eq!(concentric_disk(Vec2::ONE - u), -d, epsilon = 4.0 * EPS);
            }
        }
    }

    #[test]
    fn the_concentric_map_keeps_areas_in_proportion() {
        // A 64 × 64 grid of cell centres: the inner square |a|∞ < ½ holds 32² of the 64²
        // cells (¼), and exactly those land inside the disc of radius ½ (area ¼ of the disc).
        let n = 64;
        let inside = (0..n * n)
            .filter(|k| {
                let u = Vec2::new((k % n) as Float + 0.5, (k / n) as Float + 0.5) / n as Float;
                concentric_disk(u).length() < 0.5
            })
            .count();
        assert_eq!(inside, n * n / 4);
    }

    #[test]
    fn a_rect_sample_is_a_point_light_at_corner_plus_u_times_the_edges() {
        // u = (½, ½) picks (0, 2, 0) + (1, 0, 0) + (0, 0, 2) = (1, 2, 2), seen from the origin
        // at distance 3 (a 1-2-2-3 triple) along (1, 2, 2)/3, dimmed by 1/3² (quadratic).
        // One normalisation and a division: 2ε relative.
        let s = sample_light(&rect(), Vec3::ZERO, Vec2::splat(0.5));
        assert_abs_diff_eq!(s.direction, Vec3::new(1.0, 2.0, 2.0) / 3.0, epsilon = 2.0 * EPS);
        assert_eq!(s.distance, 3.0);
        assert_abs_diff_eq!(s.intensity, COLOR / 9.0, epsilon = 2.0 * EPS);
        // u = (0, 0) is the corner (0, 2, 0) itself: straight up, distance 2, ¼.
        let s = sample_light(&rect(), Vec3::ZERO, Vec2::ZERO);
        assert_eq!((s.direction, s.distance, s.intensity), (Vec3::Y, 2.0, COLOR / 4.0));
        // u = (¾, ¼): (1.5, 2, 1), distance √(2.25 + 4 + 1) = √7.25 from the origin.
        let s = sample_light(&rect(), Vec3::ZERO, Vec2::new(0.75, 0.25));
        assert_abs_diff_eq!(s.direction * s.distance, Vec3::new(1.5, 2.0, 1.0), epsilon = 4.0 * EPS);
        assert_abs_diff_eq!(s.distance, Float::sqrt(7.25), epsilon = 4.0 * EPS);
    }

    #[test]
    fn a_rect_shines_to_both_sides_without_a_cosine_at_the_emitter() {
        // The points (1, 0, 2) below and (1, 4, 2) above the light's centre (1, 2, 2): both
        // get colour/2² from the centre sample, the one above looking down.
        let (below, above) = (Vec3::new(1.0, 0.0, 2.0), Vec3::new(1.0, 4.0, 2.0));
        let (b, a) =
            (sample_light(&rect(), below, Vec2::splat(0.5)), sample_light(&rect(), above, Vec2::splat(0.5)));
        assert_eq!((b.direction, a.direction), (Vec3::Y, -Vec3::Y));
        assert_eq!((b.intensity, a.intensity), (COLOR / 4.0, COLOR / 4.0));
        // Grazing: a point in the light's own plane, 1 beyond its edge at x = 2, still gets
        // the full point-light value from the nearest sample (u = (1, ½): (2, 2, 2), distance 1).
        let s = sample_light(&rect(), Vec3::new(3.0, 2.0, 2.0), Vec2::new(1.0, 0.5));
        assert_eq!((s.direction, s.distance, s.intensity), (-Vec3::X, 1.0, COLOR));
    }

    #[test]
    fn a_ball_sample_lies_on_the_silhouette_disc() {
        // Seen from (0, 5, 0), the disc of the ball (radius 2, centre 0) is the plane y = 0:
        // the sample point has y = 0 and lies 2·|d| from the centre, d the concentric point
        // (|d| = the ring's half side, from the test above). The centre sample is straight
        // down at distance 5. The point recovered as p + d·L carries a few roundings of
        // values up to 5.4: 32ε.
        let p = Vec3::new(0.0, 5.0, 0.0);
        let s = sample_light(&ball(), p, Vec2::splat(0.5));
        assert_eq!((s.direction, s.distance, s.intensity), (-Vec3::Y, 5.0, COLOR));
        for u in [Vec2::new(1.0, 0.5), Vec2::new(0.25, 0.9), Vec2::new(0.0, 0.0), Vec2::new(0.6, 0.55)] {
            let s = sample_light(&ball(), p, u);
            let q = p + s.distance * s.direction;
            let ring = (2.0 * u - Vec2::ONE).abs().max_element();
            assert_abs_diff_eq!(q.y, 0.0, epsilon = 32.0 * EPS);
            assert_abs_diff_eq!(q.length(), 2.0 * ring, epsilon = 32.0 * EPS);
        }
        // From an oblique point the disc turns to face it: (q − c)·w = 0 for w = p/|p|
        // (|p| = 13, a 3-4-12-13 quadruple); q recovered from values up to 15: 64ε.
        let p = Vec3::new(3.0, -4.0, 12.0);
        let w = p / 13.0;
        for u in [Vec2::new(1.0, 0.5), Vec2::new(0.1, 0.8), Vec2::new(0.99, 0.99)] {
            let s = sample_light(&ball(), p, u);
            let q = p + s.distance * s.direction;
            assert_abs_diff_eq!(q.dot(w), 0.0, epsilon = 64.0 * EPS);
        }
    }

    #[test]
    fn opposite_samples_of_a_ball_are_symmetric_about_its_centre() {
        // The map is odd, so u and 1 − u pick points symmetric about the centre: their
        // midpoint is the centre, for any viewpoint. Points recovered as p + d·L: 64ε.
        let p = Vec3::new(1.0, 2.0, 7.0);
        for u in [Vec2::new(0.2, 0.7), Vec2::new(0.9, 0.1), Vec2::new(0.5, 0.95)] {
            let (a, b) = (sample_light(&ball(), p, u), sample_light(&ball(), p, Vec2::ONE - u));
            let midpoint = 0.5 * ((p + a.distance * a.direction) + (p + b.distance * b.direction));
            assert_abs_diff_eq!(midpoint, Vec3::ZERO, epsilon = 64.0 * EPS);
        }
    }

    #[test]
    fn point_directional_and_spot_lights_ignore_the_sample() {
        let attenuation = Attenuation { constant: 1.0, linear: 0.5, quadratic: 0.25 };
        let lights = [
            light(LightKind::Directional { direction: -Vec3::Y }),
            light(LightKind::Point { position: Vec3::new(1.0, 3.0, -2.0), attenuation }),
            light(LightKind::Spot {
                position: Vec3::new(0.0, 3.0, 0.0),
                direction: -Vec3::Y,
                inner: 0.2,
                outer: 0.5,
                attenuation,
            }),
        ];
        let p = Vec3::new(0.3, 0.0, -0.2);
        for l in &lights {
            for u in [Vec2::ZERO, Vec2::splat(0.5), Vec2::new(0.99, 0.01)] {
                assert_eq!(sample_light(l, p, u), illuminate(l, p), "{:?}", l.kind);
            }
        }
    }

    #[test]
    fn without_samples_an_area_light_is_a_point_light_at_its_centre() {
        // illuminate stands the rect at (1, 2, 2) (the centre sample) and the ball at its
        // centre; with these exact values both ways give the same bits.
        for p in [Vec3::ZERO, Vec3::new(-3.0, 1.0, 4.0)] {
            assert_eq!(illuminate(&rect(), p), sample_light(&rect(), p, Vec2::splat(0.5)));
            assert_eq!(illuminate(&ball(), p), sample_light(&ball(), p, Vec2::splat(0.5)));
        }
    }

    #[test]
    fn a_point_at_the_sampled_point_gets_no_light_and_no_nan() {
        // The centre of the ball sampled at its own centre (w undefined, then d = 0), and a
        // rect's corner sampled at the corner: distance 0, zero intensity, unit direction.
        let s = sample_light(&ball(), Vec3::ZERO, Vec2::splat(0.5));
        assert!(s.direction.is_normalized() && s.distance == 0.0 && s.intensity == BLACK, "{s:?}");
        let s = sample_light(&rect(), Vec3::new(0.0, 2.0, 0.0), Vec2::ZERO);
        assert!(s.direction.is_normalized() && s.distance == 0.0 && s.intensity == BLACK, "{s:?}");
        // Inside the ball, off centre: finite, and the disc still has radius 2.
        let s = sample_light(&ball(), Vec3::new(0.0, 0.5, 0.0), Vec2::new(1.0, 0.5));
        assert!(s.intensity.is_finite() && s.direction.is_normalized(), "{s:?}");
    }
}
