//! The checks of `uv.rs`: sphere_uv, plane_uv, triangle_uv.

use super::common::*;
use raylab_testing::uv::sphere_grid;

pub(super) const SPHERE_UV: &str = "u = ½ + atan2(−z, x)/2π, v = ½ + atan2(y, √(x² + z²))/π";

pub(super) fn sphere_cases(sphere_uv: SphereUvFn) -> CheckResult {
    // Poles: atan2(±1, 0) = ±π/2, v = ½ ± ½ exactly; any u in [0, 1] there.
    for (p, v, name) in
        [(Vec3::Y, 1.0, "north pole (0, 1, 0)"), (v3(0.0, -1.0, 0.0), 0.0, "south pole (0, −1, 0)")]
    {
        let got = sphere_uv(p);
        let cause = if (got.y - (1.0 - v)).abs() <= 2.0 * EPS {
            "v grows upward: 0 at the south pole (−y), 1 at the north pole"
        } else {
            SPHERE_UV
        };
        ensure(
            (got.y - v).abs() <= 2.0 * EPS && (0.0..=1.0).contains(&got.x),
            format!("the {name}"),
            format!("v = {v} (± 2ε = {:.1e}), u in [0, 1]", 2.0 * EPS),
            show2(got),
            cause,
        )?;
    }
    // The equator (v = ½): longitude atan2(−z, x): +x → u = ½, +z → ¼, −z → ¾, −x → 0 (z = +0).
    // Two roundings (atan2, the sum): 2ε; allowed 4ε.
    for (p, u, name) in [
        (Vec3::X, 0.5, "+x"),
        (Vec3::Z, 0.25, "+z"),
        (-Vec3::Z, 0.75, "−z"),
        (v3(-1.0, 0.0, 0.0), 0.0, "−x (z = +0)"),
    ] {
        let got = sphere_uv(p);
        let case = format!("the equator's point {name}, {}", vec3(p));
        let cause = if (got.x - (1.0 - u)).abs() <= 4.0 * EPS && u != 0.5 {
            "seen from outside u grows to the right: atan2(−z, x), so +z (facing the viewer) is u = ¼"
        } else if (got.x - (u + 0.5).rem_euclid(1.0)).abs() <= 4.0 * EPS {
            "the seam is at −x: u = ½ + atan2(−z, x)/2π puts +x at u = ½"
        } else {
            SPHERE_UV
        };
        same_uv(&case, got, uv(u, 0.5), 4.0 * EPS, cause)?;
    }
    // A pole one ulp outside the sphere (a rounded hit point): acos(−y) is NaN there.
    let outside = v3(0.0, -(1.0 as Float).next_up(), 0.0);
    let got = sphere_uv(outside);
    ensure(
        got.is_finite() && got.y.abs() <= 2.0 * EPS,
        "the south pole one ulp outside the sphere, (0, −1 − ε, 0)",
        format!("v = 0 (± 2ε = {:.1e}), finite", 2.0 * EPS),
        show2(got),
        "use atan2(y, √(x² + z²)) for the latitude, not acos(y): a point a rounding off the sphere makes \
         acos (or asin) NaN",
    )?;
    // The inverse map, written from the definition: φ = 2π(u − ½), λ = π(v − ½),
    // p = (cos λ cos φ, sin λ, −cos λ sin φ); every (u, v) of a 9 × 9 grid comes back, at
    // radius 1, 3 and 1/7 (only the direction counts). sin, cos, atan2 and the products, a
    // few ulp each: 8ε; allowed 16ε.
    for (expected, p) in sphere_grid() {
        for s in [1.0, 3.0, 1.0 / 7.0] {
            let case = format!("the point {} (radius {})", vec3(s * p), num(s));
            let got = sphere_uv(s * p);
            let cause = if s != 1.0 && near2(sphere_uv(p), expected, 16.0 * EPS) {
                "only the direction of p matters: a point at radius 3 has the uv of p/3 (atan2 of ratios, \
                 or normalise p first)"
            } else {
                SPHERE_UV
            };
            same_uv(&case, got, expected, 16.0 * EPS, cause)?;
        }
    }
    Ok("6 axis points, 243 grid points, a point off the sphere".into())
}

pub(super) fn plane_cases(plane_uv: PlaneUvFn) -> CheckResult {
    // Origin (1, 2, 3), perpendicular axes a = (2, 0, 0), b = (0, 0, −3): p = o + u·a + v·b by
    // construction, exact in floats.
    let (o, a, b) = (v3(1.0, 2.0, 3.0), v3(2.0, 0.0, 0.0), v3(0.0, 0.0, -3.0));
    let cause = "(u, v) with p = origin + u·a + v·b: for perpendicular axes u = d·a/|a|², v = d·b/|b|²";
    for (p, expected, name) in [
        (o, uv(0.0, 0.0), "the origin"),
        (o + a, uv(1.0, 0.0), "origin + a"),
        (o + b, uv(0.0, 1.0), "origin + b"),
        (o - 0.5 * a + 2.0 * b, uv(-0.5, 2.0), "origin − ½a + 2b"),
    ] {
        let got = plane_uv(p, o, a, b);
        let case = format!("plane through (1, 2, 3), axes a = (2, 0, 0), b = (0, 0, −3): {name}");
        let cause = if near2(got, expected * uv(2.0, 3.0), 4.0 * EPS) {
            "divide by the axis's squared length: the axes' lengths set the tile's size"
        } else {
            cause
        };
        same_uv(&case, got, expected, 4.0 * EPS, cause)?;
    }
    // 5 units off the plane along its normal: projected back.
    let got = plane_uv(o + a + 5.0 * Vec3::Y, o, a, b);
    same_uv(
        "plane through (1, 2, 3), axes (2, 0, 0), (0, 0, −3): 5 above origin + a",
        got,
        uv(1.0, 0.0),
        4.0 * EPS,
        "a point off the plane is projected along the normal: use dot products with the axes",
    )?;
    // Skew axes a = (1, 0, 0), b = (1, 1, 0): p = o + 2a + 3b = o + (5, 3, 0). Each axis
    // alone would give u = 5; the 2 × 2 solve gives (2, 3). Gram matrix [1 1; 1 2], det 1.
    let (o, a, b) = (v3(-1.0, 0.5, 2.0), Vec3::X, v3(1.0, 1.0, 0.0));
    let got = plane_uv(o + 2.0 * a + 3.0 * b, o, a, b);
    same_uv(
        "skew axes a = (1, 0, 0), b = (1, 1, 0), the point origin + 2a + 3b",
        got,
        uv(2.0, 3.0),
        8.0 * EPS,
        "for axes that are not perpendicular solve the 2 × 2 normal equations (Cramer): projecting on each \
         axis alone is wrong",
    )?;
    Ok("6 points".into())
}

pub(super) fn triangle_cases(triangle_uv: TriangleUvFn) -> CheckResult {
    let uvs = [uv(0.0, 0.0), uv(1.0, 0.25), uv(0.5, 1.0)];
    let cause = "uv = (1 − β − γ)·uv₀ + β·uv₁ + γ·uv₂: β weighs vertex 1 and γ vertex 2";
    // The vertices: weights 1 and 0, exact. The centroid: the mean (0.5, 5/12), 4ε. The edge
    // b–c midpoint (β = γ = ½): the mean of uv₁ and uv₂, exact.
    let third = 1.0 / 3.0;
    for (beta, gamma, expected, tolerance, name) in [
        (0.0, 0.0, uvs[0], 0.0, "vertex a (β = γ = 0)"),
        (1.0, 0.0, uvs[1], 0.0, "vertex b (β = 1)"),
        (0.0, 1.0, uvs[2], 0.0, "vertex c (γ = 1)"),
        (third, third, uv(0.5, 5.0 / 12.0), 4.0 * EPS, "the centroid (β = γ = ⅓)"),
        (0.5, 0.5, uv(0.75, 0.625), 0.0, "the midpoint of b–c (β = γ = ½)"),
    ] {
        let case = format!("vertex uvs (0, 0), (1, 0.25), (0.5, 1): {name}");
        same_uv(&case, triangle_uv(&uvs, beta, gamma), expected, tolerance, cause)?;
    }
    // Vertex a's uv away from (0, 0), so that its weight shows: at β = γ = ¼ the weights are
    // ½, ¼, ¼, and ½(0.25, 0.5) + ¼(1, 0.25) + ¼(0.5, 1) = (0.5, 0.5625), exact.
    let moved = [uv(0.25, 0.5), uvs[1], uvs[2]];
    same_uv(
        "vertex uvs (0.25, 0.5), (1, 0.25), (0.5, 1): β = γ = ¼",
        triangle_uv(&moved, 0.25, 0.25),
        uv(0.5, 0.5625),
        0.0,
        cause,
    )?;
    Ok("6 points".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    use raylab::math::consts::{PI, TAU};

    use raylab::Vec2;

    #[test]
    fn planted_uv_mistakes_are_caught() {
        // Mirrored longitude, v from the north pole, acos for the latitude, not scale-free.
        caught(
            sphere_cases(|p| {
                Vec2::new(0.5 + p.z.atan2(p.x) / TAU, 0.5 + p.y.atan2((p.x * p.x + p.z * p.z).sqrt()) / PI)
            }),
            "seen from outside",
        );
        caught(
            sphere_cases(|p| {
                Vec2::new(0.5 + (-p.z).atan2(p.x) / TAU, 0.5 - p.y.atan2((p.x * p.x + p.z * p.z).sqrt()) / PI)
            }),
            "v grows upward",
        );
        caught(sphere_cases(|p| Vec2::new(0.5 + (-p.z).atan2(p.x) / TAU, 1.0 - p.y.acos() / PI)), "not acos");
        caught(
            sphere_cases(|p| {
                Vec2::new(0.5 + (-p.z).atan2(p.x) / TAU, 0.5 + p.y.clamp(-1.0, 1.0).asin() / PI)
            }),
            "only the direction",
        );
        // Each axis alone; no division by the squared length.
        caught(
            plane_cases(|p, o, a, b| Vec2::new((p - o).dot(a) / a.dot(a), (p - o).dot(b) / b.dot(b))),
            "normal equations",
        );
        caught(
            plane_cases(|p, o, a, b| Vec2::new((p - o).dot(a.normalize()), (p - o).dot(b.normalize()))),
            "squared length",
        );
        // Weights rotated.
        caught(
            triangle_cases(|uvs, b, g| b * uvs[0] + g * uvs[1] + (1.0 - b - g) * uvs[2]),
            "β weighs vertex 1",
        );
    }
}
