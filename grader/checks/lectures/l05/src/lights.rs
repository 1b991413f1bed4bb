//! The checks of `lights.rs`: distance_falloff, spot_falloff, illuminate.

use super::area_lights::rect;
use super::common::*;
use raylab_testing::lights::{FALLOFF_AT_2, floor_at, spot_down};

pub(super) fn falloff_cases(falloff: FalloffFn) -> CheckResult {
    // At d = 2 by hand 1/(c + 2l + 4q) (FALLOFF_AT_2). One division: 2ε relative.
    for ((c, l, q), expected) in FALLOFF_AT_2 {
        let case = format!("attenuation (c, l, q) = ({c}, {l}, {q}) at distance 2");
        let f = falloff(attenuation(c, l, q), 2.0);
        let cause = if (f - (c + 2.0 * l + 4.0 * q)).abs() < 1e-4 && expected != 1.0 {
            "the factor is the reciprocal 1/(c + l·d + q·d²), not the polynomial"
        } else if (f - 1.0 / (c + 2.0 * l + 2.0 * q)).abs() < 1e-4 {
            "the quadratic term is q·d², the square of the distance"
        } else {
            "1/(c + l·d + q·d²)"
        };
        close(&case, f, expected, 2.0 * EPS * expected, cause)?;
    }
    // At the light itself with c = 0: the polynomial is 0, the factor 0 (not ∞).
    for (c, l, q) in [(0.0, 0.0, 1.0), (0.0, 1.0, 0.0)] {
        let case = format!("attenuation ({c}, {l}, {q}) at distance 0 (a point on the light)");
        let f = falloff(attenuation(c, l, q), 0.0);
        close(
            &case,
            f,
            0.0,
            0.0,
            "where c + l·d + q·d² is 0 (a point on the light) the factor is 0, never ∞",
        )?;
    }
    // d = 10⁻²⁰, quadratic only: d² = 10⁻⁴⁰ is subnormal in f32 and 1/d² overflows to ∞;
    // in f64 it is 10⁴⁰. Finite either way (0 where it would overflow).
    let case = "attenuation (0, 0, 1) at distance 10⁻²⁰";
    let f = falloff(attenuation(0.0, 0.0, 1.0), 1e-20);
    ensure(
        f.is_finite() && f >= 0.0,
        case,
        "a finite factor (0 where 1/(q·d²) overflows)",
        num(f),
        "1/(q·d²) overflows for tiny d in f32: return 0 where the quotient is not finite",
    )?;
    Ok("8 cases".into())
}

pub(super) fn spot_cases(spot: SpotFn) -> CheckResult {
    let (inner, outer) = (radians(30.0), radians(60.0));
    let (ci, co) = (inner.cos(), outer.cos());
    // Inside the inner cone (α = 0°, 20°, 29°): exactly 1.
    for degrees in [0.0, 20.0, 29.0] {
        let case = format!("inner 30°, outer 60°, α = {degrees}° (inside the inner cone)");
        let f = spot(radians(degrees).cos(), inner, outer);
        let cause = if f == 0.0 {
            "a larger cosine is a smaller angle: inside the inner cone when cos α ≥ cos inner"
        } else {
            "inside the inner cone (cos α ≥ cos inner) the falloff is 1"
        };
        close(&case, f, 1.0, 0.0, cause)?;
    }
    // Outside the outer cone (61°, 80°) and behind the spot (cos α < 0): exactly 0.
    for cos_angle in [radians(61.0).cos(), radians(80.0).cos(), -0.5] {
        let case = format!("inner 30°, outer 60°, cos α = {} (outside the outer cone)", num(cos_angle));
        let f = spot(cos_angle, inner, outer);
        close(&case, f, 0.0, 0.0, "outside the outer cone (cos α ≤ cos outer) the falloff is 0")?;
    }
    // Between: t = (cos α − cos outer)/(cos inner − cos outer), s = t²(3 − 2t):
    // t = ¼ → 1/16·2.5 = 0.15625, ½ → ½, ¾ → 9/16·1.5 = 0.84375. cos α carries a rounding
    // or two, divided by the band 0.366, times the slope ≤ 1.5: 16ε.
    for (t, expected) in [(0.25, 0.15625), (0.5, 0.5), (0.75, 0.84375)] {
        let cos_angle = co + t * (ci - co);
        let case = format!("inner 30°, outer 60°, cos α = {} (t = {t} of the band)", num(cos_angle));
        let f = spot(cos_angle, inner, outer);
        let alpha = cos_angle.acos();
        let t_angle = (outer - alpha) / (outer - inner);
        let cause = if (f - t).abs() < 1e-4 {
            "between the cones use smoothstep s = t²(3 − 2t), not t itself: the rim of the pool has no crease"
        } else if (f - t_angle * t_angle * (3.0 - 2.0 * t_angle)).abs() < 1e-4 {
            "t is measured on the cosines: t = (cos α − cos outer)/(cos inner − cos outer), not on the angles"
        } else {
            "s = t²(3 − 2t) with t = (cos α − cos outer)/(cos inner − cos outer)"
        };
        close(&case, f, expected, 16.0 * EPS, cause)?;
    }
    // inner = outer = 30°: a hard edge, 0 or 1 everywhere, including exactly at the edge.
    for cos_angle in [0.0, 0.5, radians(30.0).cos(), 1.0] {
        let case = format!("inner = outer = 30°, cos α = {}", num(cos_angle));
        let f = spot(cos_angle, radians(30.0), radians(30.0));
        ensure(
            f == 0.0 || f == 1.0,
            case,
            "0 or 1 (a hard edge)",
            num(f),
            "inner = outer is a hard edge: test both cones before dividing by cos inner − cos outer",
        )?;
    }
    Ok("13 cases".into())
}

pub(super) fn illuminate_cases(illuminate: IlluminateFn) -> CheckResult {
    // Directional: L = −travel, d = ∞, intensity = colour, wherever the point.
    let travel = v(1.0, -2.0, 2.0) / 3.0;
    let sun = light(LightKind::Directional { direction: travel });
    for p in [Vec3::ZERO, v(1e6, -3.0, 2.0)] {
        let case = format!("directional light travelling along (1, −2, 2)/3, point {}", vec3(p));
        let s = illuminate(&sun, p);
        let expected = LightSample { direction: -travel, distance: Float::INFINITY, intensity: COLOR };
        let cause = if s.direction == travel {
            "L points toward the light: the negative of the direction the light travels"
        } else if s.distance.is_finite() {
            "a directional light is infinitely far: distance = Float::INFINITY (06's shadow rays stop there)"
        } else {
            "a directional light is never dimmed: the intensity is its colour"
        };
        ensure(s == expected, case, show(&expected), show(&s), cause)?;
    }
    // Point light at (1, 2, 2) seen from the origin: d = 3, L = (1, 2, 2)/3 (2ε).
    let point = |position, c, l, q| light(LightKind::Point { position, attenuation: attenuation(c, l, q) });
    let case = "point light at (1, 2, 2), attenuation (1, 0, 0), seen from the origin";
    let s = illuminate(&point(v(1.0, 2.0, 2.0), 1.0, 0.0, 0.0), Vec3::ZERO);
    let expected = v(1.0, 2.0, 2.0) / 3.0;
    let cause = if (s.direction + expected).length() < 1e-3 {
        "L = (position − point)/|position − point|: from the point toward the light"
    } else if (s.direction - 3.0 * expected).length() < 1e-3 {
        "normalise: L = (position − point)/|position − point| is a unit vector"
    } else {
        "L = (position − point)/|position − point|"
    };
    close3(case, s.direction, expected, 2.0 * EPS, cause)?;
    close(case, s.distance, 3.0, 2.0 * EPS, "the distance is |position − point|")?;
    // 2 above with q = 1: colour/4 (2ε).
    let case = "point light 2 above the point, attenuation (0, 0, 1)";
    let s = illuminate(&point(v(1.0, 2.0, 3.0), 0.0, 0.0, 1.0), v(1.0, 0.0, 3.0));
    close3(
        case,
        s.intensity,
        COLOR / 4.0,
        2.0 * EPS,
        "the intensity is colour · distance_falloff(attenuation, d)",
    )?;
    // Spot at (0, 1, 0) down, inner 30°, outer 60°: the floor point at α from the axis is
    // (tan α, 0, 0). On the axis and at 20°: colour; at 61° and above the light: black.
    let spot = light(spot_down(30.0, 60.0));
    for degrees in [0.0, 20.0] {
        let case =
            format!("spot at (0, 1, 0) along −y (inner 30°, outer 60°), floor point {degrees}° off its axis");
        let s = illuminate(&spot, floor_at(degrees));
        let cause = if s.intensity == BLACK {
            "cos α = −L·axis: the axis points away from the light, L toward it"
        } else {
            "inside the inner cone a spot is a point light: colour · distance_falloff"
        };
        // Every factor is exactly 1 inside the inner cone; 4ε leaves room for another order of products.
        close3(&case, s.intensity, COLOR, 4.0 * EPS, cause)?;
    }
    for p in [floor_at(61.0), v(0.3, 2.0, 0.0)] {
        let case = format!("the same spot, point {} (outside its cone)", vec3(p));
        let s = illuminate(&spot, p);
        close3(
            &case,
            s.intensity,
            BLACK,
            0.0,
            "outside the outer cone a spot sends nothing: times spot_falloff",
        )?;
    }
    // In the band at t = ¼: cos α = cos 60° + ¼(cos 30° − cos 60°), s = 0.15625. The point
    // goes through acos, tan and a normalisation: 64ε.
    let cos_alpha = radians(60.0).cos() + 0.25 * (radians(30.0).cos() - radians(60.0).cos());
    let case = "the same spot, a floor point in its band (t = ¼): smoothstep 0.15625";
    let s = illuminate(&spot, v(cos_alpha.acos().tan(), 0.0, 0.0));
    close3(case, s.intensity, COLOR * 0.15625, 64.0 * EPS, "times spot_falloff(−L·axis, inner, outer)")?;
    // Area lights stand at their centre: the rect's corner + ½(edge_u + edge_v) = (1, 2, 2),
    // the ball's centre; q = 1 so colour/9 at distance 3.
    let case = "rect light, corner (0, 2, 0), edges (2, 0, 0), (0, 0, 4), seen from the origin";
    let s = illuminate(&rect(), Vec3::ZERO);
    close(
        case,
        s.distance,
        3.0,
        2.0 * EPS,
        "without samples an area light stands at its centre corner + ½(edge_u + edge_v)",
    )?;
    // The direction too: corner − ½(edge_u + edge_v) and corner + ½(edge_u − edge_v) are 3 away as
    // well. One normalisation of (1, 2, 2): 2ε.
    close3(
        case,
        s.direction,
        v(1.0, 2.0, 2.0) / 3.0,
        2.0 * EPS,
        "the rect's centre is corner + ½(edge_u + edge_v) = (1, 2, 2): L points to it",
    )?;
    let case = "ball light r = 2 at (0, 3, 0) seen from the origin";
    let ball = light(LightKind::Sphere {
        center: v(0.0, 3.0, 0.0),
        radius: 2.0,
        attenuation: Attenuation::default(),
    });
    let s = illuminate(&ball, Vec3::ZERO);
    close(case, s.distance, 3.0, 0.0, "without samples a ball light stands at its centre")?;
    // At the light itself: a unit direction, distance 0, no light, never NaN.
    let p = v(0.5, -1.0, 2.0);
    for l in [point(p, 0.0, 0.0, 1.0), point(p, 1.0, 0.0, 0.0)] {
        let case = format!("the point {} is the point light's position", vec3(p));
        let s = illuminate(&l, p);
        ensure(
            s.direction.is_normalized() && s.distance == 0.0 && s.intensity == BLACK,
            case,
            "a unit L (any), distance 0, intensity (0, 0, 0)",
            show(&s),
            "a point at the light has no direction to it: return a unit L, distance 0 and no light, never NaN",
        )?;
    }
    Ok("14 cases".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l05_shading::{LightSample, distance_falloff, illuminate};
    use raylab::Float;
    use raylab::scene::{Attenuation, Light, LightKind};

    #[test]
    fn falloff_mistakes_are_caught() {
        fn poly(a: Attenuation, d: Float) -> Float {
            a.constant + a.linear * d + a.quadratic * d * d
        }
        caught(falloff_cases(poly), "reciprocal");
        caught(
            falloff_cases(|a, d| 1.0 / (a.constant + a.linear * d + a.quadratic * d)),
            "square of the distance",
        );
        caught(falloff_cases(|a, d| 1.0 / poly(a, d)), "never ∞");
        // 1/(q·d²) overflows at d = 10⁻²⁰ only in f32 (10⁴⁰ is a finite f64).
        let no_finite_test = falloff_cases(|a, d| {
            let p = poly(a, d);
            if p > 0.0 { 1.0 / p } else { 0.0 }
        });
        if size_of::<Float>() == 4 {
            caught(no_finite_test, "not finite");
        } else {
            assert!(no_finite_test.is_ok());
        }
    }

    #[test]
    fn spot_mistakes_are_caught() {
        fn smooth(t: Float) -> Float {
            t * t * (3.0 - 2.0 * t)
        }
        // Linear between the cones.
        caught(
            spot_cases(|c, i, o| {
                let (ci, co) = (i.cos(), o.cos());
                if c >= ci {
                    1.0
                } else if c <= co {
                    0.0
                } else {
                    (c - co) / (ci - co)
                }
            }),
            "smoothstep",
        );
        // Angles compared as if they were cosines.
        caught(
            spot_cases(|c, i, o| {
                let (ci, co) = (i.cos(), o.cos());
                if c <= ci {
                    1.0
                } else if c >= co {
                    0.0
                } else {
                    smooth((c - co) / (ci - co))
                }
            }),
            "a larger cosine is a smaller angle",
        );
        // t on the angles.
        caught(
            spot_cases(|c, i, o| {
                let a = c.acos();
                if a <= i {
                    1.0
                } else if a >= o {
                    0.0
                } else {
                    smooth((o - a) / (o - i))
                }
            }),
            "measured on the cosines",
        );
        // Dividing before testing the cones: 0/0 at inner = outer.
        caught(
            spot_cases(|c, i, o| smooth(((c - o.cos()) / (i.cos() - o.cos())).clamp(0.0, 1.0))),
            "hard edge",
        );
    }

    #[test]
    fn illuminate_mistakes_are_caught() {
        // Directional L = the travel direction.
        caught(
            illuminate_cases(|l, p| match l.kind {
                LightKind::Directional { direction } => {
                    LightSample { direction, distance: Float::INFINITY, intensity: l.color }
                }
                _ => illuminate(l, p),
            }),
            "negative of the direction",
        );
        // Point L = point − position.
        caught(
            illuminate_cases(|l, p| match l.kind {
                LightKind::Point { position, .. } => {
                    let s = illuminate(l, p);
                    LightSample { direction: (p - position).normalize(), ..s }
                }
                _ => illuminate(l, p),
            }),
            "from the point toward the light",
        );
        // Spot with cos α = L·axis.
        caught(
            illuminate_cases(|l, p| match l.kind {
                LightKind::Spot { position, direction, inner, outer, attenuation } => {
                    let to = position - p;
                    let (dir, d) = (to.normalize(), to.length());
                    let f = distance_falloff(attenuation, d)
                        * l05_shading::spot_falloff(dir.dot(direction), inner, outer);
                    LightSample { direction: dir, distance: d, intensity: l.color * f }
                }
                _ => illuminate(l, p),
            }),
            "−L·axis",
        );
        // No attenuation.
        caught(
            illuminate_cases(|l, p| {
                let s = illuminate(l, p);
                match l.kind {
                    LightKind::Point { .. } if s.distance > 0.0 => LightSample { intensity: l.color, ..s },
                    _ => s,
                }
            }),
            "distance_falloff",
        );
        // A rect standing at its corner.
        caught(
            illuminate_cases(|l, p| match l.kind {
                LightKind::Rect { corner, attenuation, .. } => {
                    illuminate(&Light { kind: LightKind::Point { position: corner, attenuation }, ..*l }, p)
                }
                _ => illuminate(l, p),
            }),
            "its centre corner",
        );
    }
}
