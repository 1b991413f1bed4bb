//! The checks of `area_lights.rs`: concentric_disk and sample_light.

use super::common::*;

pub(super) fn disk_cases(disk: DiskFn) -> CheckResult {
    // The centre: a = 2u − 1 = 0, no angle to divide out.
    let case = "u = (0.5, 0.5), the centre of the square";
    let d = disk(Vec2::splat(0.5));
    let cause = "a = 2u − 1 is zero at the centre: return (0, 0) before dividing by aₓ or a_y";
    ensure(!d.is_nan(), case, "(0, 0)", v2(d), cause)?;
    // Every point of a 17 × 17 grid lands on the circle of radius max(|aₓ|, |a_y|), and u,
    // 1 − u on opposite points (the map is odd). Tolerance 4ε: a cosine and a sine times r ≤ 1.
    for i in 0..=16 {
        for j in 0..=16 {
            let u = Vec2::new(i as Float, j as Float) / 16.0;
            let ring = (2.0 * u - Vec2::ONE).abs().max_element();
            let d = disk(u);
            let case = format!("u = {}: on the square ring of half side {}", v2(u), num(ring));
            close(
                &case,
                d.length(),
                ring,
                4.0 * EPS,
                "with a = 2u − 1, r = max(|aₓ|, |a_y|) (with its sign): each square ring goes to the circle of \
                 that radius; this is not the polar map (√u₁, 2πu₂)",
            )?;
            let opposite = disk(Vec2::ONE - u);
            // Two results of 4ε each: 8ε.
            ensure(
                (opposite + d).length() <= 8.0 * EPS,
                &case,
                format!("disk(1 − u) = −disk(u) = {} (± 8ε = {:.1e} in length)", v2(-d), 8.0 * EPS),
                v2(opposite),
                "the map is odd: u and 1 − u go to opposite points (φ = (π/4)·a_y/aₓ keeps the sign of r)",
            )?;
        }
    }
    // By hand: side midpoints, the corner, and one point in each branch:
    // a = (½, ¼): |aₓ| > |a_y|, r = ½, φ = (π/4)·½ = π/8;
    // a = (¼, ½): r = ½, φ = π/2 − (π/4)·½ = 3π/8. Tolerance 4ε as above.
    let pi = raylab::math::consts::PI;
    let s = (0.5 as Float).sqrt();
    let polar = |r: Float, phi: Float| Vec2::new(r * phi.cos(), r * phi.sin());
    let cases = [
        (Vec2::new(1.0, 0.5), Vec2::new(1.0, 0.0), "the first branch, |aₓ| > |a_y|: φ = (π/4)·a_y/aₓ"),
        (Vec2::new(0.0, 0.5), Vec2::new(-1.0, 0.0), "r = aₓ keeps its sign: a = (−1, 0) goes to (−1, 0)"),
        (Vec2::new(0.5, 1.0), Vec2::new(0.0, 1.0), "the second branch: r = a_y, φ = π/2 − (π/4)·aₓ/a_y"),
        (Vec2::new(0.5, 0.0), Vec2::new(0.0, -1.0), "the second branch: r = a_y, φ = π/2 − (π/4)·aₓ/a_y"),
        (Vec2::new(1.0, 1.0), Vec2::new(s, s), "the corner a = (1, 1) is at φ = π/4 on the unit circle"),
        (Vec2::new(0.75, 0.625), polar(0.5, pi / 8.0), "the first branch, |aₓ| > |a_y|: φ = (π/4)·a_y/aₓ"),
        (Vec2::new(0.625, 0.75), polar(0.5, 3.0 * pi / 8.0), "the second branch: φ = π/2 − (π/4)·aₓ/a_y"),
    ];
    for (u, expected, cause) in cases {
        let d = disk(u);
        let case = format!("u = {}", v2(u));
        let shown = format!("{} (± 4ε = {:.1e} each)", v2(expected), 4.0 * EPS);
        ensure(!d.is_nan() && (d - expected).abs().max_element() <= 4.0 * EPS, case, shown, v2(d), cause)?;
    }
    Ok(format!("{} cases", 1 + 17 * 17 + cases.len()))
}

/// The rect light 2 above the origin, 2 wide in x and 4 deep in z, from x = z = 0;
/// quadratic attenuation.
pub(super) fn rect() -> Light {
    light(LightKind::Rect {
        corner: v(0.0, 2.0, 0.0),
        edge_u: v(2.0, 0.0, 0.0),
        edge_v: v(0.0, 0.0, 4.0),
        attenuation: attenuation(0.0, 0.0, 1.0),
    })
}

/// A ball light of radius 2 at the origin, no attenuation.
pub(super) fn ball() -> Light {
    light(LightKind::Sphere { center: Vec3::ZERO, radius: 2.0, attenuation: Attenuation::default() })
}

pub(super) fn sample_light_cases(sample: SampleFn) -> CheckResult {
    // Rect, u = (0, 0): the corner (0, 2, 0), straight up at distance 2, colour/2²
    // (every value a power of two: exact). A student standing at the centre gets distance 3.
    let case = "rect corner (0, 2, 0), edges (2, 0, 0), (0, 0, 4), q = 1, seen from the origin, u = (0, 0)";
    let s = sample(&rect(), Vec3::ZERO, Vec2::ZERO);
    let expected = LightSample { direction: Vec3::Y, distance: 2.0, intensity: COLOR / 4.0 };
    let cause = if (s.distance - 3.0).abs() < 1e-3 {
        "pick the point corner + uₓ·edge_u + u_y·edge_v of the light, not its centre"
    } else if (s.distance - 2.0).abs() < 1e-3 {
        "the picked point shines like a point light of the light's colour, dimmed by its attenuation at its distance"
    } else {
        "the rect's point is corner + uₓ·edge_u + u_y·edge_v"
    };
    ensure(s == expected, case, show(&expected), show(&s), cause)?;
    // u = (¾, ¼): (1.5, 2, 1), distance √7.25. Swapped edges would give (0.5, 2, 3).
    // The point recovered as L·d carries a normalisation and a square root: 8ε of values ≤ 2.
    let case = "the same rect, u = (0.75, 0.25): the point (1.5, 2, 1)";
    let s = sample(&rect(), Vec3::ZERO, Vec2::new(0.75, 0.25));
    let q = s.direction * s.distance;
    let cause = if (q - v(0.5, 2.0, 3.0)).length() < 1e-3 {
        "uₓ goes with edge_u and u_y with edge_v"
    } else {
        "the rect's point is corner + uₓ·edge_u + u_y·edge_v, and L, d are toward it from the point"
    };
    close3(case, q, v(1.5, 2.0, 1.0), 8.0 * EPS, cause)?;
    // u = (½, ½): the centre (1, 2, 2), distance 3 (a 1-2-2-3 triple), colour/9: one
    // division and a normalisation, 2ε.
    let case = "the same rect, u = (0.5, 0.5): the point (1, 2, 2) at distance 3, colour/9";
    let s = sample(&rect(), Vec3::ZERO, Vec2::splat(0.5));
    close3(case, s.direction, v(1.0, 2.0, 2.0) / 3.0, 2.0 * EPS, "L = (q − point)/|q − point|")?;
    close3(
        case,
        s.intensity,
        COLOR / 9.0,
        2.0 * EPS,
        "dimmed by the light's attenuation at distance |q − point|",
    )?;
    // Ball of radius 2 at the origin, seen from (0, 5, 0): the silhouette disc is y = 0, the
    // point lies at 2·|d| from the centre (|d| = the ring's half side). q = p + d·L carries
    // a few roundings of values up to 5.4: 32ε.
    let p = v(0.0, 5.0, 0.0);
    for u in [Vec2::new(1.0, 0.5), Vec2::new(0.25, 0.9), Vec2::new(0.6, 0.55)] {
        let case = format!("ball r = 2 at the origin seen from (0, 5, 0), u = {}", v2(u));
        let s = sample(&ball(), p, u);
        let q = p + s.distance * s.direction;
        let ring = (2.0 * u - Vec2::ONE).abs().max_element();
        close(
            &case,
            q.y,
            0.0,
            32.0 * EPS,
            "the disc goes through the centre perpendicular to w = (point − center)/|point − center|",
        )?;
        close(
            &case,
            q.length(),
            2.0 * ring,
            32.0 * EPS,
            "the ball's point is center + radius·(dₓe₁ + d_y e₂) with d = concentric_disk(u)",
        )?;
    }
    // The ball moved to c = (1, 2, 3) and seen from the oblique c + (3, −4, 12) (13 away): the
    // disc turns to face the point, (q − c)·w = 0 with w = (3, −4, 12)/13, and q stays 2·|d| from
    // c. A w from point + center, (5, 0, 18), tilts the disc. q from values up to 18: 64ε.
    let c = v(1.0, 2.0, 3.0);
    let p = c + v(3.0, -4.0, 12.0);
    let moved = light(LightKind::Sphere { center: c, radius: 2.0, attenuation: Attenuation::default() });
    for u in [Vec2::new(1.0, 0.5), Vec2::new(0.1, 0.8)] {
        let case = format!("ball r = 2 at (1, 2, 3) seen from (4, −2, 15), u = {}", v2(u));
        let s = sample(&moved, p, u);
        let q = p + s.distance * s.direction;
        close(
            &case,
            (q - c).dot(v(3.0, -4.0, 12.0) / 13.0),
            0.0,
            64.0 * EPS,
            "the disc is perpendicular to w = (point − center)/|point − center|, whatever the point",
        )?;
        let ring = (2.0 * u - Vec2::ONE).abs().max_element();
        close(
            &case,
            (q - c).length(),
            2.0 * ring,
            64.0 * EPS,
            "the ball's point is center + radius·(dₓe₁ + d_y e₂) with d = concentric_disk(u)",
        )?;
    }
    // A point light at (0, 2, 0) (no attenuation) and a directional light straight down:
    // one point each, whatever u. Exact.
    let point = light(LightKind::Point { position: v(0.0, 2.0, 0.0), attenuation: Attenuation::default() });
    let sun = light(LightKind::Directional { direction: -Vec3::Y });
    for (what, l, expected) in [
        (
            "point light at (0, 2, 0)",
            point,
            LightSample { direction: Vec3::Y, distance: 2.0, intensity: COLOR },
        ),
        (
            "directional light along −y",
            sun,
            LightSample { direction: Vec3::Y, distance: Float::INFINITY, intensity: COLOR },
        ),
    ] {
        for u in [Vec2::ZERO, Vec2::new(0.9, 0.1)] {
            let case = format!("{what} seen from the origin, u = {}", v2(u));
            let s = sample(&l, Vec3::ZERO, u);
            ensure(
                s == expected,
                case,
                show(&expected),
                show(&s),
                "a point, spot or directional light has one point: ignore u and return illuminate(light, point)",
            )?;
        }
    }
    Ok("12 cases".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l05_shading::{LightSample, illuminate};
    use raylab::scene::{Light, LightKind};
    use raylab::{Vec2, Vec3};

    #[test]
    fn disk_mistakes_are_caught() {
        // The polar map (√u₁, 2πu₂): uniform too, but rings do not go to circles.
        caught(
            disk_cases(|u| {
                let (r, phi) = (u.x.sqrt(), 2.0 * raylab::math::consts::PI * u.y);
                Vec2::new(r * phi.cos(), r * phi.sin())
            }),
            "not the polar map",
        );
        // No guard at the centre: 0/0.
        caught(
            disk_cases(|u| {
                let a = 2.0 * u - Vec2::ONE;
                let q = raylab::math::consts::FRAC_PI_4;
                let (r, phi) =
                    if a.x.abs() > a.y.abs() { (a.x, q * a.y / a.x) } else { (a.y, 2.0 * q - q * a.x / a.y) };
                r * Vec2::new(phi.cos(), phi.sin())
            }),
            "zero at the centre",
        );
        // The second branch with the first branch's angle.
        caught(
            disk_cases(|u| {
                let a = 2.0 * u - Vec2::ONE;
                if a == Vec2::ZERO {
                    return Vec2::ZERO;
                }
                let q = raylab::math::consts::FRAC_PI_4;
                let (r, phi) =
                    if a.x.abs() > a.y.abs() { (a.x, q * a.y / a.x) } else { (a.y, q * a.x / a.y) };
                r * Vec2::new(phi.cos(), phi.sin())
            }),
            "π/2 − (π/4)",
        );
    }

    /// sample_light with the edges swapped, or standing at the centre.
    fn sample_swapped(light: &Light, p: Vec3, u: Vec2) -> LightSample {
        match light.kind {
            LightKind::Rect { corner, edge_u, edge_v, attenuation } => {
                let position = corner + u.y * edge_u + u.x * edge_v;
                illuminate(&Light { kind: LightKind::Point { position, attenuation }, ..*light }, p)
            }
            _ => l05_shading::sample_light(light, p, u),
        }
    }

    #[test]
    fn sample_light_mistakes_are_caught() {
        caught(sample_light_cases(sample_swapped), "uₓ goes with edge_u");
        caught(sample_light_cases(|l, p, _| illuminate(l, p)), "not its centre");
        // The ball's disc not turned to face the point: always the xz plane.
        caught(
            sample_light_cases(|l, p, u| match l.kind {
                LightKind::Sphere { center, radius, attenuation } => {
                    let d = l05_shading::concentric_disk(u);
                    let position = center + radius * Vec3::new(d.x, 0.0, d.y);
                    illuminate(&Light { kind: LightKind::Point { position, attenuation }, ..*l }, p)
                }
                _ => l05_shading::sample_light(l, p, u),
            }),
            "perpendicular to w",
        );
    }
}
