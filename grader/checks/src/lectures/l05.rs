//! Lecture 05, shading: Lambert, Phong and Blinn–Phong, the reflection vector,
//! light sources with attenuation and spot cones, area-light samples, and the
//! local shading equation that puts them together.

use crate::check::Meta;

declare_checks! {
    "l05";
    Meta::unit(
        "concentric_disk",
        "square rings go to circles of the same half side, the centre and the sides by hand, both branches",
    ) => disk_cases(concentric_disk),
    Meta::unit(
        "sample_light",
        "rect samples at corner + u·edges, ball samples on the silhouette disc, point lights",
    )
    .needs(&["05/illuminate", "05/concentric_disk"]) => sample_light_cases(sample_light),
    Meta::unit("lambert", "(N·L)⁺ head-on, at 60°, grazing and from behind") => lambert_cases(lambert),
    Meta::unit("distance_falloff", "1/(c + l·d + q·d²) at d = 2 by hand; 0, never ∞, at and near d = 0")
        => falloff_cases(distance_falloff),
    Meta::unit(
        "spot_falloff",
        "1 inside, 0 outside, smoothstep of the cosines between, a hard edge when inner = outer",
    ) => spot_cases(spot_falloff),
    Meta::unit(
        "illuminate",
        "directional, point, spot and area lights: L toward the light, d, attenuated intensity",
    )
    .needs(&["05/distance_falloff", "05/spot_falloff"]) => illuminate_cases(illuminate),
    Meta::unit(
        "phong_specular",
        "(R·V)ⁿ: the peak in the mirror direction, (√½)ⁿ seen along N, nothing from behind",
    )
    .needs(&["05/reflect"]) => phong_cases(phong_specular),
    Meta::unit(
        "blinn_specular",
        "(N·H)ⁿ: the peak at H = N, cos(22.5°)ⁿ seen along N, l = −v gives 0, not NaN",
    ) => blinn_cases(blinn_specular),
    Meta::unit("reflect", "r = v − 2(v·n)n at 45°, normal incidence, along the surface, non-unit v")
        => reflect_cases(reflect),
    Meta::unit(
        "shade_light",
        "(k_d(N·L)⁺ + k_s·spec) ⊙ I_L: colours by channel, Phong or Blinn as the material says",
    )
    .needs(&["05/lambert", "05/phong_specular", "05/blinn_specular"]) => shade_light_cases(shade_light),
    Meta::unit(
        "shade_local",
        "ambient plus every light: one light at 60°, two lights, none, from behind, a point light",
    )
    .needs(&["05/illuminate", "05/shade_light", "05/lambert"]) => shade_local_cases(shade_local),
}

#[cfg(feature = "l05")]
// `Failure` is large (its optional images); see check.rs.
#[allow(clippy::result_large_err)]
mod code {
    pub(super) use l05_shading::{
        LightSample, blinn_specular, concentric_disk, distance_falloff, illuminate, lambert, phong_specular,
        reflect, sample_light, shade_light, shade_local, spot_falloff,
    };
    use raylab::scene::{Attenuation, Light, LightKind, Material, Specular};
    use raylab::{BLACK, Color, Float, Hit, Ray, Vec2, Vec3, WHITE, radians};

    use crate::check::{CheckResult, close, close3, ensure, num, vec3};

    pub(super) type DiskFn = fn(Vec2) -> Vec2;
    pub(super) type SampleFn = fn(&Light, Vec3, Vec2) -> LightSample;
    pub(super) type LambertFn = fn(Vec3, Vec3) -> Float;
    pub(super) type FalloffFn = fn(Attenuation, Float) -> Float;
    pub(super) type SpotFn = fn(Float, Float, Float) -> Float;
    pub(super) type IlluminateFn = fn(&Light, Vec3) -> LightSample;
    pub(super) type SpecularFn = fn(Vec3, Vec3, Vec3, Float) -> Float;
    pub(super) type ReflectFn = fn(Vec3, Vec3) -> Vec3;
    pub(super) type ShadeLightFn = fn(&Material, Color, Vec3, Vec3, &LightSample) -> Color;
    pub(super) type ShadeLocalFn = fn(&Material, Color, &Hit, Vec3, &[Light], Color) -> Color;

    const EPS: Float = Float::EPSILON;
    const COLOR: Color = Color::new(1.0, 0.5, 0.25);

    fn v(x: Float, y: Float, z: Float) -> Vec3 {
        Vec3::new(x, y, z)
    }

    /// The unit vector in the xy plane at `degrees` from +y (the normal) toward +x.
    fn at_angle(degrees: Float) -> Vec3 {
        let a = radians(degrees);
        v(a.sin(), a.cos(), 0.0)
    }

    fn v2(u: Vec2) -> String {
        format!("({}, {})", num(u.x), num(u.y))
    }

    fn show(s: &LightSample) -> String {
        format!("L = {}, distance {}, intensity {}", vec3(s.direction), num(s.distance), vec3(s.intensity))
    }

    fn attenuation(c: Float, l: Float, q: Float) -> Attenuation {
        Attenuation { constant: c, linear: l, quadratic: q }
    }

    fn light(kind: LightKind) -> Light {
        Light { color: COLOR, shadows: true, kind }
    }

    // ------------------------------------------------------------ area lights

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
            (
                Vec2::new(0.75, 0.625),
                polar(0.5, pi / 8.0),
                "the first branch, |aₓ| > |a_y|: φ = (π/4)·a_y/aₓ",
            ),
            (Vec2::new(0.625, 0.75), polar(0.5, 3.0 * pi / 8.0), "the second branch: φ = π/2 − (π/4)·aₓ/a_y"),
        ];
        for (u, expected, cause) in cases {
            let d = disk(u);
            let case = format!("u = {}", v2(u));
            let shown = format!("{} (± 4ε = {:.1e} each)", v2(expected), 4.0 * EPS);
            ensure((d - expected).abs().max_element() <= 4.0 * EPS, case, shown, v2(d), cause)?;
        }
        Ok(format!("{} cases", 1 + 17 * 17 + cases.len()))
    }

    /// The rect light 2 above the origin, 2 wide in x and 4 deep in z, from x = z = 0;
    /// quadratic attenuation.
    fn rect() -> Light {
        light(LightKind::Rect {
            corner: v(0.0, 2.0, 0.0),
            edge_u: v(2.0, 0.0, 0.0),
            edge_v: v(0.0, 0.0, 4.0),
            attenuation: attenuation(0.0, 0.0, 1.0),
        })
    }

    /// A ball light of radius 2 at the origin, no attenuation.
    fn ball() -> Light {
        light(LightKind::Sphere { center: Vec3::ZERO, radius: 2.0, attenuation: Attenuation::default() })
    }

    pub(super) fn sample_light_cases(sample: SampleFn) -> CheckResult {
        // Rect, u = (0, 0): the corner (0, 2, 0), straight up at distance 2, colour/2²
        // (every value a power of two: exact). A student standing at the centre gets distance 3.
        let case =
            "rect corner (0, 2, 0), edges (2, 0, 0), (0, 0, 4), q = 1, seen from the origin, u = (0, 0)";
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
        // From the oblique (3, −4, 12) (|p| = 13): the disc turns to face it, (q − c)·p/13 = 0.
        // q from values up to 15: 64ε.
        let p = v(3.0, -4.0, 12.0);
        for u in [Vec2::new(1.0, 0.5), Vec2::new(0.1, 0.8)] {
            let case = format!("ball r = 2 at the origin seen from (3, −4, 12), u = {}", v2(u));
            let s = sample(&ball(), p, u);
            let q = p + s.distance * s.direction;
            close(
                &case,
                q.dot(p / 13.0),
                0.0,
                64.0 * EPS,
                "the disc is perpendicular to w = (point − center)/|point − center|, whatever the point",
            )?;
        }
        // A point light at (0, 2, 0) (no attenuation) and a directional light straight down:
        // one point each, whatever u. Exact.
        let point =
            light(LightKind::Point { position: v(0.0, 2.0, 0.0), attenuation: Attenuation::default() });
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

    // ---------------------------------------------------------------- lambert

    pub(super) fn lambert_cases(lambert: LambertFn) -> CheckResult {
        // cos 0° = 1 exactly; a sign slip (n·(−l)) gives 0 here.
        let case = "n = +y, l = +y (the light straight above)";
        let f = lambert(Vec3::Y, Vec3::Y);
        let cause = if f == 0.0 {
            "l points from the point toward the light: the factor is n·l itself, 1 head-on"
        } else {
            "the factor is the cosine n·l of unit vectors"
        };
        close(case, f, 1.0, 0.0, cause)?;
        // cos 60° = ½ on either side of the normal. Vectors from sin/cos of a rounded angle: 4ε.
        for degrees in [60.0, -60.0] {
            let case = format!("n = +y, l at {degrees}° from it");
            close(
                &case,
                lambert(Vec3::Y, at_angle(degrees)),
                0.5,
                4.0 * EPS,
                "the factor is the cosine n·l",
            )?;
        }
        // Grazing (l ⟂ n, exact 0) and from behind: exactly 0, never negative.
        for degrees in [90.0, 120.0, 180.0] {
            let l = if degrees == 90.0 { Vec3::X } else { at_angle(degrees) };
            let case = format!("n = +y, l at {degrees}° from it (behind the surface or grazing)");
            let f = lambert(Vec3::Y, l);
            let cause = if f < 0.0 {
                "clamp: max(n·l, 0) — a light behind the surface gives 0, not negative light"
            } else {
                "a light behind the surface gives 0: max(n·l, 0)"
            };
            close(&case, f, 0.0, 0.0, cause)?;
        }
        Ok("6 cases".into())
    }

    // ----------------------------------------------------------------- lights

    pub(super) fn falloff_cases(falloff: FalloffFn) -> CheckResult {
        // At d = 2 by hand 1/(c + 2l + 4q): (1,0,0) → 1, (0,1,0) → ½, (0,0,1) → ¼,
        // (1,1,1) → 1/7, (½,¼,⅛) → 1/(½ + ½ + ½) = ⅔. One division: 2ε relative.
        let cases = [
            ((1.0, 0.0, 0.0), 1.0),
            ((0.0, 1.0, 0.0), 0.5),
            ((0.0, 0.0, 1.0), 0.25),
            ((1.0, 1.0, 1.0), 1.0 / 7.0),
            ((0.5, 0.25, 0.125), 2.0 / 3.0),
        ];
        for ((c, l, q), expected) in cases {
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

    /// A spot at (0, 1, 0) shining straight down, no attenuation.
    fn spot_light(inner_degrees: Float, outer_degrees: Float) -> Light {
        light(LightKind::Spot {
            position: Vec3::Y,
            direction: -Vec3::Y,
            inner: radians(inner_degrees),
            outer: radians(outer_degrees),
            attenuation: Attenuation::default(),
        })
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
        let point =
            |position, c, l, q| light(LightKind::Point { position, attenuation: attenuation(c, l, q) });
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
        let spot = spot_light(30.0, 60.0);
        for degrees in [0.0, 20.0] {
            let case = format!(
                "spot at (0, 1, 0) along −y (inner 30°, outer 60°), floor point {degrees}° off its axis"
            );
            let s = illuminate(&spot, v(radians(degrees).tan(), 0.0, 0.0));
            let cause = if s.intensity == BLACK {
                "cos α = −L·axis: the axis points away from the light, L toward it"
            } else {
                "inside the inner cone a spot is a point light: colour · distance_falloff"
            };
            // Every factor is exactly 1 inside the inner cone; 4ε leaves room for another order of products.
            close3(&case, s.intensity, COLOR, 4.0 * EPS, cause)?;
        }
        for p in [v(radians(61.0).tan(), 0.0, 0.0), v(0.3, 2.0, 0.0)] {
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

    // -------------------------------------------------------------- specular

    /// A cosine near 1 carries a few ε of rounding; raised to n, n times as much.
    fn tol(exponent: Float) -> Float {
        8.0 * EPS * exponent.max(1.0)
    }

    pub(super) fn phong_cases(phong: SpecularFn) -> CheckResult {
        // The mirror direction: N = y, L at 45° toward +x, V at 45° toward −x: V = R, 1.
        let (l, mirror) = (at_angle(45.0), at_angle(-45.0));
        for e in [1.0, 10.0, 200.0] {
            let case = format!("n = +y, l at +45°, v at −45° (the mirror direction), exponent {e}");
            let f = phong(Vec3::Y, l, mirror, e);
            let cause = if f < 0.5 {
                "R = reflect(−l, n): reflect takes the direction the light travels, −l"
            } else {
                "at V = R the highlight is 1 for every exponent"
            };
            close(&case, f, 1.0, tol(e), cause)?;
        }
        // Seen along N: R·V = cos 45°, so (√½)ⁿ: 0.7071, ½, 1/32.
        let half_angle = radians(22.5).cos();
        for (e, expected) in [(1.0, (0.5 as Float).sqrt()), (2.0, 0.5), (10.0, 1.0 / 32.0)] {
            let case = format!("n = +y, l at +45°, v = n, exponent {e}");
            let f = phong(Vec3::Y, l, Vec3::Y, e);
            let cause = if (f - half_angle.powf(e)).abs() < 1e-4 {
                "Phong's cosine is R·V with R the mirror of the light, not N·H with the half vector (that is Blinn)"
            } else if (f - (0.5 as Float).sqrt()).abs() < 1e-4 {
                "raise the cosine to the exponent: (R·V)ⁿ"
            } else {
                "(max(R·V, 0))ⁿ with R = reflect(−l, n)"
            };
            close(&case, f, expected, tol(e), cause)?;
        }
        // The light behind the surface (l at 100°), the eye near its below-surface mirror image
        // (v at −80°, above the surface): R·V = 0.94, yet no highlight: 0.
        let case = "n = +y, l at 100° (behind the surface), v at −80°, exponent 1";
        let f = phong(Vec3::Y, at_angle(100.0), at_angle(-80.0), 1.0);
        close(case, f, 0.0, 0.0, "no highlight when n·l ≤ 0: the light is behind the surface")?;
        // The eye away from the lobe: R at −45°, V at +80°, R·V = cos 125° < 0: 0 (exponent 1),
        // and 0, not NaN, for a fractional exponent.
        for e in [1.0, 2.5] {
            let case = format!("n = +y, l at +45°, v at +80° (R·V < 0), exponent {e}");
            let f = phong(Vec3::Y, l, at_angle(80.0), e);
            close(
                &case,
                f,
                0.0,
                0.0,
                "clamp R·V at 0 before the power: an eye away from the lobe sees no highlight",
            )?;
        }
        // Exponent 0 with the light in front: 1 everywhere (0⁰ = 1), here where R·V < 0.
        let case = "n = +y, l at +45°, v at +80°, exponent 0";
        close(
            case,
            phong(Vec3::Y, l, at_angle(80.0), 0.0),
            1.0,
            0.0,
            "x⁰ = 1 for every x ≥ 0 (0⁰ = 1): clamp, then powf",
        )?;
        // A huge exponent at the peak: within 10⁴·8ε of 1, finite.
        let case = "n = +y, l at +45°, v at −45°, exponent 10⁴";
        close(
            case,
            phong(Vec3::Y, l, mirror, 1e4),
            1.0,
            tol(1e4),
            "clamp the cosine to [0, 1] before the power",
        )?;
        Ok("11 cases".into())
    }

    pub(super) fn blinn_cases(blinn: SpecularFn) -> CheckResult {
        // L and V at ±45°: H = N, the peak 1; L = V = N: 1.
        for (what, l, v) in
            [("l at +45°, v at −45°", at_angle(45.0), at_angle(-45.0)), ("l = v = n", Vec3::Y, Vec3::Y)]
        {
            for e in [1.0, 80.0] {
                let case = format!("n = +y, {what}, exponent {e}");
                close(
                    &case,
                    blinn(Vec3::Y, l, v, e),
                    1.0,
                    tol(e),
                    "H = (l + v)/|l + v|: both point away from the surface",
                )?;
            }
        }
        // Seen along N with L at 45°: H is at 22.5°, N·H = cos 22.5° = 0.92388; to the n.
        let l = at_angle(45.0);
        let c = radians(22.5).cos();
        for e in [1.0, 2.0, 10.0] {
            let case = format!("n = +y, l at +45°, v = n, exponent {e}");
            let f = blinn(Vec3::Y, l, Vec3::Y, e);
            let cause = if (f - radians(45.0).cos().powf(e)).abs() < 1e-4 {
                "Blinn's cosine is N·H with the half vector H = (l + v)/|l + v|, not R·V (that is Phong)"
            } else if f >= 1.0 - 1e-4 {
                "normalise the half vector: H = (l + v)/|l + v|"
            } else {
                "(max(N·H, 0))ⁿ with H = (l + v)/|l + v|"
            };
            close(&case, f, c.powf(e), tol(e), cause)?;
        }
        // l = −v: no half vector; the light in front (n·l = cos 30°), the eye below: 0, not NaN.
        for e in [0.0, 1.0] {
            let case = format!("n = +y, l at 30°, v = −l (l + v = 0), exponent {e}");
            let f = blinn(Vec3::Y, at_angle(30.0), -at_angle(30.0), e);
            close(
                &case,
                f,
                0.0,
                0.0,
                "l + v = 0 has no direction: no highlight (0), never NaN (try_normalize)",
            )?;
        }
        // The light behind the surface: 0, even with H near N (l at 100°, v at −100°... v above:
        // v at −80°: H = (l + v)/|l + v| points along ±y, N·H = ±1).
        let case = "n = +y, l at 100° (behind the surface), v at −80°, exponent 1";
        let f = blinn(Vec3::Y, at_angle(100.0), at_angle(-80.0), 1.0);
        close(case, f, 0.0, 0.0, "no highlight when n·l ≤ 0: the light is behind the surface")?;
        Ok("10 cases".into())
    }

    pub(super) fn reflect_cases(reflect: ReflectFn) -> CheckResult {
        let s = (0.5 as Float).sqrt();
        // v = (1, −1, 0)/√2 onto the floor: r = (1, 1, 0)/√2. A few roundings of √½: 2ε.
        let case = "v = (1, −1, 0)/√2 onto n = +y (45°)";
        let vin = v(s, -s, 0.0);
        let r = reflect(vin, Vec3::Y);
        let expected = v(s, s, 0.0);
        let near = |a: Vec3| (r - a).abs().max_element() <= 1e-4;
        let cause = if near(vin + 2.0 * vin.dot(Vec3::Y) * Vec3::Y) {
            "r = v − 2(v·n)n: subtract twice the normal part, do not add it"
        } else if near(vin - vin.dot(Vec3::Y) * Vec3::Y) {
            "twice the normal part: once reaches the tangent plane, once more mirrors it"
        } else if near(-expected) {
            "v points toward the surface and r away from it: r = v − 2(v·n)n, not its negative"
        } else {
            "r = v − 2(v·n)n"
        };
        close3(case, r, expected, 2.0 * EPS, cause)?;
        // Exact cases: normal incidence, a vector along the surface, a non-unit v.
        for (case, vin, n, expected) in [
            ("v = −n at normal incidence, n = +y", -Vec3::Y, Vec3::Y, Vec3::Y),
            ("v = (2, 0, −1) along the floor n = +y", v(2.0, 0.0, -1.0), Vec3::Y, v(2.0, 0.0, -1.0)),
            ("v = (0, 0, −3) (not unit) onto n = +z", v(0.0, 0.0, -3.0), Vec3::Z, v(0.0, 0.0, 3.0)),
        ] {
            let r = reflect(vin, n);
            let cause = if (r.length() - 1.0).abs() < 1e-4 && vin.length() != 1.0 {
                "keep |r| = |v|: do not normalise"
            } else {
                "r = v − 2(v·n)n: the tangential part kept, the normal part flipped"
            };
            close3(case, r, expected, 0.0, cause)?;
        }
        // Either side of the normal: r is even in n (exact).
        let (vin, n) = (v(0.6, -0.8, 0.0), v(0.0, 0.6, 0.8));
        let case = "v = (0.6, −0.8, 0) about n = (0, 0.6, 0.8) and about −n";
        let (a, b) = (reflect(vin, n), reflect(vin, -n));
        ensure(a == b, case, vec3(a), vec3(b), "r = v − 2(v·n)n does not change when n is negated")?;
        Ok("5 cases".into())
    }

    // ----------------------------------------------------------------- shading

    pub(super) fn shade_light_cases(shade: ShadeLightFn) -> CheckResult {
        // k_d = (1, ½, 0), k_s = 0.2, I_L = (½, 1, 1), L = V = N (Blinn: H = N, spec = 1):
        // (k_d·1 + 0.2·1) ⊙ I_L = (0.6, 0.7, 0.2). A few roundings of values ≤ 1.2: 4ε.
        let m = Material { specular: Color::splat(0.2), exponent: 30.0, ..Material::default() };
        let kd = Color::new(1.0, 0.5, 0.0);
        let sample = LightSample { direction: Vec3::Y, distance: 1.0, intensity: Color::new(0.5, 1.0, 1.0) };
        let case = "k_d = (1, 0.5, 0), k_s = 0.2, Blinn n = 30, I_L = (0.5, 1, 1), L = V = N = +y";
        let c = shade(&m, kd, Vec3::Y, Vec3::Y, &sample);
        let expected = Color::new(0.6, 0.7, 0.2);
        let near = |a: Color| (c - a).abs().max_element() <= 1e-4;
        let cause = if near(Color::new(0.7, 0.7, 0.2)) {
            "both terms reflect the light that arrives: (k_d·(N·L)⁺ + k_s·spec) ⊙ I_L"
        } else if near(Color::new(0.6, 1.2, 1.2)) {
            "the surface colour is the diffuse argument (a texture's value), not material.diffuse"
        } else {
            "(k_d·(N·L)⁺ + k_s·spec) ⊙ I_L, colours multiplied channel by channel"
        };
        close3(case, c, expected, 4.0 * EPS, cause)?;
        // No diffuse colour, k_s = 1, N = V = y, L at 45°: Phong cos 45°, Blinn cos 22.5°
        // (exponent 1), times I_L; exponent 10: (cos 45°)¹⁰ = 1/32. Unit vectors from sin/cos,
        // a reflection or a normalisation: 8ε.
        let sample = LightSample { direction: at_angle(45.0), distance: 1.0, intensity: COLOR };
        for (model, exponent, expected) in [
            (Specular::Phong, 1.0, radians(45.0).cos()),
            (Specular::Blinn, 1.0, radians(22.5).cos()),
            (Specular::Phong, 10.0, 1.0 / 32.0),
        ] {
            let m = Material { specular: WHITE, model, exponent, ..Material::default() };
            let case = format!("k_d = 0, k_s = 1, {model:?} n = {exponent}, N = V = +y, L at 45°");
            let c = shade(&m, BLACK, Vec3::Y, Vec3::Y, &sample);
            let cause = if model == Specular::Phong && (c.x - radians(22.5).cos()).abs() < 1e-4
                || model == Specular::Blinn && (c.x - radians(45.0).cos()).abs() < 1e-4
            {
                "use material.model: Specular::Phong → phong_specular, Specular::Blinn → blinn_specular"
            } else if exponent != 1.0 && (c.x - radians(45.0).cos()).abs() < 1e-4 {
                "the highlight's exponent is material.exponent"
            } else {
                "k_s·spec ⊙ I_L with the material's highlight model and exponent"
            };
            close3(&case, c, COLOR * expected, 8.0 * EPS, cause)?;
        }
        // A light behind the surface, a shiny material: nothing at all.
        let m = Material { specular: WHITE, exponent: 10.0, ..Material::default() };
        let sample = LightSample { direction: at_angle(120.0), distance: 1.0, intensity: WHITE };
        let case = "white k_d, k_s = 1, L at 120° (behind the surface)";
        let c = shade(&m, WHITE, Vec3::Y, Vec3::Y, &sample);
        close3(case, c, BLACK, 0.0, "a light behind the surface adds nothing: (N·L)⁺ = 0 and no highlight")?;
        Ok("5 cases".into())
    }

    const AMBIENT: Color = Color::new(0.1, 0.2, 0.3);
    const LIGHT: Color = Color::new(1.0, 0.8, 0.6);

    /// The hit of a ray straight down onto the floor y = 0 at the origin: normal +y.
    fn floor_hit() -> Hit {
        Hit::new(&Ray::new(Vec3::Y, -Vec3::Y), 1.0, Vec3::Y)
    }

    fn directional(color: Color, toward_light: Vec3) -> Light {
        Light { color, shadows: true, kind: LightKind::Directional { direction: -toward_light } }
    }

    /// L at 60° from +y with y exactly ½ (N·L = ½ exactly).
    fn sixty() -> Vec3 {
        v((3.0 as Float).sqrt() / 2.0, 0.5, 0.0)
    }

    pub(super) fn shade_local_cases(shade: ShadeLocalFn) -> CheckResult {
        let white = Material::default();
        let check = |case: &str, got: Color, expected: Color, tolerance: Float, cause: &str| {
            close3(case, got, expected, tolerance, cause)
        };
        // No lights: k_a ⊙ I_a with k_a = the diffuse argument (exact).
        let kd = Color::new(0.5, 1.0, 0.25);
        let case = "no lights, diffuse (0.5, 1, 0.25), ambient (0.1, 0.2, 0.3)";
        let c = shade(&white, kd, &floor_hit(), Vec3::Y, &[], AMBIENT);
        let cause = if c == AMBIENT {
            "the ambient term is k_a ⊙ I_a with k_a = the diffuse argument"
        } else {
            "with no lights only the ambient term k_d ⊙ I_a is left"
        };
        check(case, c, kd * AMBIENT, 0.0, cause)?;
        // One directional light at 60°, white matte: I_a + ½I_L, exact (products by 1 and ½).
        let case = "white matte floor n = +y, one directional light at 60° of (1, 0.8, 0.6)";
        let c = shade(&white, WHITE, &floor_hit(), Vec3::Y, &[directional(LIGHT, sixty())], AMBIENT);
        check(
            case,
            c,
            AMBIENT + 0.5 * LIGHT,
            2.0 * EPS,
            "I = k_a ⊙ I_a + Σ shade_light(…, illuminate(light, p))",
        )?;
        // Two lights add: I_a + ½I_A + I_B (4ε: three additions of values below 2).
        let (a, b) = (Color::new(0.2, 0.4, 0.6), Color::new(0.5, 0.25, 1.0));
        let lights = [directional(a, sixty()), directional(b, Vec3::Y)];
        let case = "the same floor, lights (0.2, 0.4, 0.6) at 60° and (0.5, 0.25, 1) head-on";
        let c = shade(&white, WHITE, &floor_hit(), Vec3::Y, &lights, AMBIENT);
        let cause = if (c - (AMBIENT + b)).abs().max_element() < 1e-4 {
            "add every light's term: the sum over all the lights"
        } else if (c - (2.0 * AMBIENT + 0.5 * a + b)).abs().max_element() < 1e-4 {
            "add the ambient term once, then each light's term"
        } else {
            "the lights' terms add: I_a + Σ shade_light(…)"
        };
        check(case, c, AMBIENT + 0.5 * a + b, 4.0 * EPS, cause)?;
        // A point light 2 above, quadratic attenuation: I_a + ¼I_L (exact).
        let point = Light {
            color: LIGHT,
            shadows: true,
            kind: LightKind::Point { position: v(0.0, 2.0, 0.0), attenuation: attenuation(0.0, 0.0, 1.0) },
        };
        let case = "the same floor, a point light 2 above it, attenuation (0, 0, 1)";
        let c = shade(&white, WHITE, &floor_hit(), Vec3::Y, &[point], AMBIENT);
        check(
            case,
            c,
            AMBIENT + 0.25 * LIGHT,
            2.0 * EPS,
            "each light reaches the point through illuminate(light, hit.point): its direction, distance and attenuation",
        )?;
        // A light below the floor: ambient only, even on a shiny material.
        let shiny =
            Material { specular: WHITE, exponent: 10.0, model: Specular::Phong, ..Material::default() };
        let case = "shiny floor n = +y, a directional light from below it";
        let c = shade(&shiny, WHITE, &floor_hit(), Vec3::Y, &[directional(LIGHT, -sixty())], AMBIENT);
        check(case, c, AMBIENT, 0.0, "a light behind the surface adds nothing")?;
        // Seen from below: the hit's normal is −y (facing the eye), a light below lights it.
        let hit = Hit::new(&Ray::new(-Vec3::Y, Vec3::Y), 1.0, Vec3::Y);
        let case = "the floor seen from below (normal −y), a directional light from below, head-on";
        let c = shade(&white, WHITE, &hit, -Vec3::Y, &[directional(LIGHT, -Vec3::Y)], AMBIENT);
        check(case, c, AMBIENT + LIGHT, 2.0 * EPS, "shade with hit.normal, which faces the eye")?;
        Ok("6 cases".into())
    }
}

#[cfg(all(test, feature = "l05"))]
#[allow(clippy::result_large_err)]
mod tests {
    use super::code::*;
    use crate::check::testing::caught;
    pub(super) use l05_shading::{
        LightSample, blinn_specular, distance_falloff, illuminate, lambert, phong_specular, reflect,
        shade_light,
    };
    use raylab::scene::{Attenuation, Light, LightKind, Material};
    use raylab::{Color, Float, Hit, Vec2, Vec3};

    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }

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

    #[test]
    fn lambert_mistakes_are_caught() {
        caught(lambert_cases(|n, l| n.dot(l)), "not negative light");
        caught(lambert_cases(|n, l| n.dot(-l).max(0.0)), "toward the light");
    }

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

    #[test]
    fn specular_mistakes_are_caught() {
        // Phong with R = reflect(l, n).
        caught(
            phong_cases(
                |n, l, v, e| if n.dot(l) <= 0.0 { 0.0 } else { reflect(l, n).dot(v).clamp(0.0, 1.0).powf(e) },
            ),
            "reflect(−l, n)",
        );
        // Phong without the n·l test.
        caught(phong_cases(|n, l, v, e| reflect(-l, n).dot(v).clamp(0.0, 1.0).powf(e)), "behind the surface");
        // Phong without the clamp.
        caught(
            phong_cases(|n, l, v, e| if n.dot(l) <= 0.0 { 0.0 } else { reflect(-l, n).dot(v).powf(e) }),
            "clamp R·V",
        );
        // Phong computed with the half vector.
        caught(phong_cases(blinn_specular), "not N·H");
        // Blinn with H unnormalised.
        caught(
            blinn_cases(
                |n, l, v, e| if n.dot(l) <= 0.0 { 0.0 } else { n.dot(l + v).clamp(0.0, 1.0).powf(e) },
            ),
            "normalise the half vector",
        );
        // Blinn with a plain normalize: NaN at l = −v.
        caught(
            blinn_cases(|n, l, v, e| {
                if n.dot(l) <= 0.0 { 0.0 } else { n.dot((l + v).normalize()).clamp(0.0, 1.0).powf(e) }
            }),
            "never NaN",
        );
        // Blinn computed as Phong.
        caught(blinn_cases(phong_specular), "not R·V");
    }

    #[test]
    fn reflect_mistakes_are_caught() {
        caught(reflect_cases(|v, n| v + 2.0 * v.dot(n) * n), "do not add it");
        caught(reflect_cases(|v, n| v - v.dot(n) * n), "twice the normal part");
        caught(reflect_cases(|v, n| 2.0 * v.dot(n) * n - v), "not its negative");
        caught(reflect_cases(|v, n| (v - 2.0 * v.dot(n) * n).normalize()), "do not normalise");
    }

    #[test]
    fn shade_light_mistakes_are_caught() {
        // The specular term not times the light.
        caught(
            shade_light_cases(|m, kd, n, v, s| {
                kd * lambert(n, s.direction) * s.intensity
                    + m.specular * blinn_specular(n, s.direction, v, m.exponent)
            }),
            "both terms reflect",
        );
        // material.diffuse instead of the argument.
        caught(
            shade_light_cases(|m, _kd, n, v, s| shade_light(m, m.diffuse, n, v, s)),
            "not material.diffuse",
        );
        // Always Blinn.
        caught(
            shade_light_cases(|m, kd, n, v, s| {
                let spec = blinn_specular(n, s.direction, v, m.exponent);
                (kd * lambert(n, s.direction) + m.specular * spec) * s.intensity
            }),
            "use material.model",
        );
    }

    #[test]
    fn shade_local_mistakes_are_caught() {
        fn sum(
            m: &Material,
            kd: Color,
            hit: &Hit,
            v: Vec3,
            lights: &[Light],
            ambient: Color,
            per_light: bool,
        ) -> Color {
            let mut c = if per_light { Color::ZERO } else { kd * ambient };
            for l in lights {
                if per_light {
                    c += kd * ambient;
                }
                c += shade_light(m, kd, hit.normal, v, &illuminate(l, hit.point));
            }
            c
        }
        // Ambient added once per light.
        caught(shade_local_cases(|m, kd, h, v, l, a| sum(m, kd, h, v, l, a, true)), "no lights");
        // Ambient not times the diffuse colour.
        caught(
            shade_local_cases(|m, kd, h, v, l, a| sum(m, kd, h, v, l, a, false) - kd * a + a),
            "k_a = the diffuse argument",
        );
        // Only the last light kept.
        caught(
            shade_local_cases(|m, kd, h, v, l, a| {
                sum(m, kd, h, v, &l[l.len().saturating_sub(1)..], a, false)
            }),
            "sum over all the lights",
        );
    }
}
