//! The checks of `polygon.rs`: inside_crossings, winding_number, newell_normal, hit_polygon.

use super::common::*;
use raylab_testing::polygons::{on_plane, pentagram, square, square_in_plane, u_shape};

// ---- polygons --------------------------------------------------------------

pub(super) fn v2(points: &[[Float; 2]]) -> Vec<Vec2> {
    points.iter().map(|&p| Vec2::from_array(p)).collect()
}

pub(super) fn show2(p: Vec2) -> String {
    format!("({}, {})", num(p.x), num(p.y))
}

pub(super) fn show_polygon(poly: &[Vec2]) -> String {
    let points: Vec<String> = poly.iter().map(|&p| show2(p)).collect();
    format!("[{}]", points.join(", "))
}

pub(super) const VERTEX: &str = "a vertex at the height of p counts as above (v.y ≥ p.y) for both its edges, so a \
    test ray through a vertex crosses once or not at all, and an edge lying on the test ray never counts";

/// Polygon cases shared by the two rules: (polygon, point, winding number, cause).
pub(super) fn polygon_table() -> Vec<(Vec<Vec2>, Vec2, i32, &'static str)> {
    let p = Vec2::new;
    let cw: Vec<Vec2> = square().iter().rev().copied().collect();
    let closing = v2(&[[0.0, 2.0], [0.0, 0.0], [2.0, 0.0]]);
    let diamond = v2(&[[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]]);
    let kite = v2(&[[-1.0, 1.0], [1.0, 0.0], [3.0, 1.0], [1.0, 2.0]]);
    let star = pentagram();
    let reversed_star: Vec<Vec2> = star.iter().rev().copied().collect();
    let gap = 0.8 * Vec2::from_angle(PI / 2.0 + PI / 5.0);
    const BASIC: &str = "cast the test ray from p toward +x and count the edges it crosses";
    vec![
        (square(), p(1.0, 1.0), 1, BASIC),
        (square(), p(3.0, 1.0), 0, BASIC),
        (
            closing,
            p(0.5, 0.5),
            1,
            "the polygon is closed: include the edge from the last vertex back to the first",
        ),
        (
            square(),
            p(-1.0, 1.0),
            0,
            "only crossings to the right of p count (p strictly left of the upward edge)",
        ),
        (square(), p(1.0, 3.0), 0, BASIC),
        (
            cw,
            p(1.0, 1.0),
            -1,
            "clockwise winds negatively: a crossing downward counts −1 (even–odd ignores the \
                orientation)",
        ),
        (u_shape(), p(1.5, 2.0), 0, "in the notch the test ray crosses two edges: even, outside"),
        (u_shape(), p(0.5, 2.0), 1, "in the left arm the test ray crosses three edges: odd, inside"),
        (u_shape(), p(1.5, 0.5), 1, BASIC),
        (star.clone(), p(0.0, 0.8), 1, "a tip of the pentagram is covered once"),
        (star.clone(), gap, 0, "between two tips of the pentagram is outside"),
        (
            star.clone(),
            p(0.0, 0.0),
            2,
            "the pentagram's centre is crossed twice, both upward: winding 2, even–odd outside",
        ),
        (reversed_star, p(0.0, 0.0), -2, "the reversed pentagram winds −2 around its centre"),
        (diamond.clone(), p(0.0, 0.0), 1, VERTEX),
        (diamond.clone(), p(-0.5, 0.0), 1, VERTEX),
        (diamond.clone(), p(-2.0, 0.0), 0, VERTEX),
        (diamond, p(2.0, 0.0), 0, VERTEX),
        (kite, p(0.0, 0.0), 0, VERTEX),
        (square(), p(-1.0, 0.0), 0, VERTEX),
        (square(), p(-1.0, 2.0), 0, VERTEX),
        (square(), p(3.0, 0.0), 0, VERTEX),
        (square(), p(3.0, 2.0), 0, VERTEX),
        (vec![], p(0.0, 0.0), 0, "no vertices contain nothing"),
        (v2(&[[0.0, 0.0], [1.0, 1.0]]), p(0.5, 0.2), 0, "fewer than three vertices contain nothing"),
    ]
}

/// Points on an edge shared by two squares (lower and upper, lower and right).
pub(super) fn shared_edges() -> Vec<(Vec<Vec2>, Vec<Vec2>, Vec2)> {
    let lower = square();
    let upper: Vec<Vec2> = lower.iter().map(|&v| v + Vec2::new(0.0, 2.0)).collect();
    let right: Vec<Vec2> = lower.iter().map(|&v| v + Vec2::new(2.0, 0.0)).collect();
    vec![(lower.clone(), upper, Vec2::new(1.0, 2.0)), (lower, right, Vec2::new(2.0, 1.0))]
}

pub(super) const SHARED: &str = "a point of a shared edge belongs to exactly one of the two polygons: a vertex at \
    p's height counts as above, and the crossing must be strictly right of p";

pub(super) fn crossings_cases(inside: InsideFn) -> CheckResult {
    let table = polygon_table();
    for (poly, p, winding, cause) in &table {
        let expected = winding % 2 != 0;
        let got = inside(poly, *p);
        let case = format!("inside_crossings(polygon {}, p = {})", show_polygon(poly), show2(*p));
        let cause = if *winding == 2 {
            "even–odd: the pentagram's centre is crossed twice, so it is outside (a hole)"
        } else {
            cause
        };
        ensure(got == expected, case, expected, got, cause)?;
    }
    for (a, b, p) in shared_edges() {
        let (in_a, in_b) = (inside(&a, p), inside(&b, p));
        let case =
            format!("p = {} on the edge shared by {} and {}", show2(p), show_polygon(&a), show_polygon(&b));
        ensure(in_a != in_b, case, "inside exactly one", format!("{in_a} and {in_b}"), SHARED)?;
    }
    // Which side a boundary point goes to: the test ray runs toward +x and a crossing counts when
    // p is strictly left of the upward edge, so a point of the square's left edge is inside (it
    // crosses the right edge only) and one of its right edge is outside (it crosses nothing).
    for (p, expected) in [(Vec2::new(0.0, 1.0), true), (Vec2::new(2.0, 1.0), false)] {
        let got = inside(&square(), p);
        let case =
            format!("inside_crossings(polygon {}, p = {}): on an edge", show_polygon(&square()), show2(p));
        ensure(
            got == expected,
            case,
            expected,
            got,
            "cast the test ray toward +x and count an edge only when p is strictly left of it, directed \
                upward: (hi − lo) × (p − lo) > 0",
        )?;
    }
    Ok(format!("{} points, 2 shared edges, 2 points on edges", table.len()))
}

pub(super) fn winding_cases(winding_number: WindingFn) -> CheckResult {
    let table = polygon_table();
    for (poly, p, expected, cause) in &table {
        let got = winding_number(poly, *p);
        let case = format!("winding_number(polygon {}, p = {})", show_polygon(poly), show2(*p));
        let cause = if got == -expected && *expected != 0 {
            "counter-clockwise is positive: an upward crossing right of p counts +1, a downward one −1"
        } else if *expected == 2 || *expected == -2 {
            "count signed crossings, +1 upward and −1 downward (not a parity): the pentagram's centre \
                winds twice"
        } else {
            cause
        };
        ensure(got == *expected, case, expected, got, cause)?;
    }
    for (a, b, p) in shared_edges() {
        let sum = winding_number(&a, p) + winding_number(&b, p);
        let case =
            format!("p = {} on the edge shared by {} and {}", show2(p), show_polygon(&a), show_polygon(&b));
        ensure(sum == 1, case, "windings summing to 1", sum, SHARED)?;
    }
    Ok(format!("{} points and 2 shared edges", table.len()))
}

pub(super) fn newell_cases(newell: NewellFn) -> CheckResult {
    let at_z5: Vec<Vec3> = square().iter().map(|v| v.extend(5.0)).collect();
    let cw: Vec<Vec3> = at_z5.iter().rev().copied().collect();
    let cases = [
        // Area 4, counter-clockwise from +z: (0, 0, 8).
        (at_z5, Vec3::new(0.0, 0.0, 8.0)),
        (cw, Vec3::new(0.0, 0.0, -8.0)),
        // The same square in the plane x = 1: (8, 0, 0).
        (square_in_plane(0), Vec3::new(8.0, 0.0, 0.0)),
        // (b − a) × (c − a) = (−1, 1, 0) × (−1, 0, 1) = (1, 1, 1): twice the area along the normal.
        (vec![Vec3::X, Vec3::Y, Vec3::Z], Vec3::ONE),
        // Collinear: no plane.
        (vec![Vec3::ZERO, Vec3::X, 2.0 * Vec3::X], Vec3::ZERO),
    ];
    for (poly, expected) in cases {
        let got = newell(&poly);
        let points: Vec<String> = poly.iter().map(|&p| vec3(p)).collect();
        let case = format!("newell_normal([{}])", points.join(", "));
        let cause = if expected != Vec3::ZERO && near3(got, -expected, TOL) {
            "the sign: nₓ = Σ (yᵢ − yⱼ)(zᵢ + zⱼ) with j = i + 1, so n points to the side from which the \
                vertices run counter-clockwise"
        } else if expected != Vec3::ZERO && near3(got, expected.normalize(), TOL) {
            "do not normalise: |n| is twice the area (hit_polygon normalises)"
        } else {
            "sum over every edge i → j = i + 1, the last vertex joining the first: nₓ = Σ (yᵢ − yⱼ)(zᵢ \
                + zⱼ), n_y = Σ (zᵢ − zⱼ)(xᵢ + xⱼ), n_z = Σ (xᵢ − xⱼ)(yᵢ + yⱼ)"
        };
        close3(&case, got, expected, TOL * 8.0, cause)?;
    }
    Ok("5 polygons".into())
}

pub(super) fn polygon_cases(hit_polygon: PolygonFn) -> CheckResult {
    for axis in 0..3 {
        let quad = square_in_plane(axis);
        let normal = Vec3::AXES[axis];
        let at = |u: Float, v: Float| on_plane(axis, u, v);
        let plane = ["x", "y", "z"][axis];
        // From 4 units in front, oblique, toward (0.5, 1.5) of the square: t = 1.
        let target = at(0.5, 1.5);
        let slant = 0.5 * at(0.3, -0.2);
        let r = Ray::new(target + 4.0 * normal + slant, -4.0 * normal - slant);
        let case = format!("the square [0, 2]² in the plane {plane} = 1, {}", show_ray(&r));
        let got = hit_polygon(&r, &quad, ALL);
        let Some(h) = got else {
            let cause = if axis < 2 {
                "project by dropping the coordinate of the normal's dominant axis: dropping z always \
                    flattens a polygon in a vertical plane to a segment"
            } else {
                "hit the plane n·p = n·v₀ (n = Newell's normal, normalised), then test the point inside \
                    the projected polygon"
            };
            return Err(fail(case, "t = 1", show_hit(&got), cause));
        };
        close(&case, h.t, 1.0, TOL, "t = (n·v₀ − n·o)/(n·d)")?;
        close3(
            &case,
            h.normal,
            normal,
            TOL,
            "the outward normal is Newell's n normalised (the side from which the vertices run \
                counter-clockwise), faced by Hit::new",
        )?;
        ensure(
            h.front_face,
            &case,
            "front_face true",
            "false",
            "the ray comes from the counter-clockwise side: the front",
        )?;
        // From behind: t = 2, the normal turned toward the ray.
        let r = Ray::new(at(1.0, 1.0) - 2.0 * normal, normal);
        let case = format!("the square [0, 2]² in the plane {plane} = 1, {} (from behind)", show_ray(&r));
        let got = hit_polygon(&r, &quad, ALL);
        let Some(h) = got else {
            return Err(fail(
                case,
                "t = 2",
                show_hit(&got),
                "a polygon is two-sided: it is hit from behind too",
            ));
        };
        close(&case, h.t, 2.0, TOL, "t = (n·v₀ − n·o)/(n·d)")?;
        close3(
            &case,
            h.normal,
            -normal,
            TOL,
            "from behind the normal faces the ray: build the hit with Hit::new(ray, t, n)",
        )?;
        // Beside the square: the projected point (2.5, 1) is outside.
        let r = Ray::new(at(2.5, 1.0) + normal, -normal);
        let got = hit_polygon(&r, &quad, ALL);
        let case = format!("the square [0, 2]² in the plane {plane} = 1, {} (beside it)", show_ray(&r));
        ensure(
            got.is_none(),
            case,
            "None",
            show_hit(&got),
            "the plane's hit point must be inside the polygon (inside_crossings of the projection)",
        )?;
    }
    // A tilted quad (normal (1, 1, 0)/√2, x and y tie): the ray (t, t, 0.5) meets x + y = 1 at t = ½.
    let tilted = [
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.0, 1.0, 0.0),
        Vec3::new(0.0, 1.0, 1.0),
        Vec3::new(1.0, 0.0, 1.0),
    ];
    let r = ray([0.0, 0.0, 0.5], [1.0, 1.0, 0.0]);
    let got = hit_polygon(&r, &tilted, ALL);
    let case = format!("the tilted quad x + y = 1, 0 ≤ z ≤ 1, {}", show_ray(&r));
    close(
        &case,
        got.map_or(Float::NAN, |h| h.t),
        0.5,
        TOL,
        "any dominant axis of the normal works; t = (n·v₀ − n·o)/(n·d)",
    )?;
    // The pentagram at z = −2 seen from above: the centre is a hole (even–odd), a tip is hit.
    let star: Vec<Vec3> = pentagram().iter().map(|v| v.extend(-2.0)).collect();
    let centre = ray([0.0, 0.0, 0.0], [0.0, 0.0, -1.0]);
    let got = hit_polygon(&centre, &star, ALL);
    ensure(
        got.is_none(),
        "the pentagram at z = −2, ray from the origin along −z (through its centre)",
        "None (a hole)",
        show_hit(&got),
        "hit_polygon follows the even–odd rule (inside_crossings): the pentagram's centre is a hole",
    )?;
    let tip = ray([0.0, 0.8, 0.0], [0.0, 0.0, -1.0]);
    let got = hit_polygon(&tip, &star, ALL);
    close(
        "the pentagram at z = −2, ray from (0, 0.8, 0) along −z (a tip)",
        got.map_or(Float::NAN, |h| h.t),
        2.0,
        TOL,
        "a tip of the pentagram is inside",
    )?;
    // Degenerate polygons and a parallel ray: None, never a panic.
    let down = ray([0.5, 0.5, 1.0], [0.0, 0.0, -1.0]);
    for (poly, why) in [
        (vec![], "no vertices: return None"),
        (vec![Vec3::ZERO, Vec3::X], "fewer than three vertices: return None"),
        (
            vec![Vec3::ZERO, Vec3::X, 2.0 * Vec3::X],
            "collinear vertices have a zero Newell normal: return None (do not normalise zero)",
        ),
    ] {
        let got = hit_polygon(&down, &poly, ALL);
        let case = format!("a degenerate polygon with {} vertices, {}", poly.len(), show_ray(&down));
        ensure(got.is_none(), case, "None", show_hit(&got), why)?;
    }
    // Three vertices are a polygon too: the triangle (0, 0, −1), (2, 0, −1), (0, 2, −1), hit from
    // above at (0.5, 0.5): t = 2.
    let triangle = [Vec3::new(0.0, 0.0, -1.0), Vec3::new(2.0, 0.0, -1.0), Vec3::new(0.0, 2.0, -1.0)];
    let r = ray([0.5, 0.5, 1.0], [0.0, 0.0, -1.0]);
    let got = hit_polygon(&r, &triangle, ALL);
    let case = format!("the triangle (0, 0, −1), (2, 0, −1), (0, 2, −1) as a polygon, {}", show_ray(&r));
    close(
        case,
        got.map_or(Float::NAN, |h| h.t),
        2.0,
        TOL,
        "three vertices make a polygon: only fewer are None",
    )?;
    let along = ray([-1.0, 1.0, 1.0], [1.0, 0.0, 0.0]);
    let got = hit_polygon(&along, &square_in_plane(2), ALL);
    ensure(
        got.is_none(),
        "the square in the plane z = 1, ray within that plane",
        "None",
        show_hit(&got),
        "n·d = 0: a ray parallel to the plane has no hit",
    )?;
    Ok("3 axis planes × 3 rays, a tilted quad, the pentagram, a triangle, 4 degenerate cases".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l03_polygons_triangles::dominant_axis;

    /// Even–odd with `above` deciding which vertices count as above p, and
    /// optionally without the closing edge.
    fn crossings(polygon: &[Vec2], p: Vec2, lax: bool, open: bool) -> bool {
        let n = polygon.len();
        let mut inside = false;
        for i in 0..n {
            if open && i + 1 == n {
                break;
            }
            let (a, b) = (polygon[i], polygon[(i + 1) % n]);
            let a_above = if lax { a.y > p.y } else { a.y >= p.y };
            if a_above != (b.y >= p.y) {
                let (lo, hi) = if a.y < b.y { (a, b) } else { (b, a) };
                if (hi - lo).perp_dot(p - lo) > 0.0 {
                    inside = !inside;
                }
            }
        }
        inside
    }

    #[test]
    fn crossings_mistakes() {
        assert!(crossings_cases(|poly, p| crossings(poly, p, false, false)).is_ok());
        caught(crossings_cases(|poly, p| crossings(poly, p, true, false)), "counts as above");
        caught(crossings_cases(|poly, p| crossings(poly, p, false, true)), "closed");
    }

    #[test]
    fn winding_mistakes() {
        caught(winding_cases(|poly, p| -winding_number(poly, p)), "counter-clockwise is positive");
        caught(
            winding_cases(|poly, p| inside_crossings(poly, p) as i32 * winding_number(poly, p).signum()),
            "signed crossings",
        );
    }

    fn newell_open(vertices: &[Vec3]) -> Vec3 {
        vertices.windows(2).fold(Vec3::ZERO, |n, w| {
            let (a, b) = (w[0], w[1]);
            n + Vec3::new((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y))
        })
    }

    #[test]
    fn newell_mistakes() {
        caught(newell_cases(|v| -newell_normal(v)), "the sign");
        caught(newell_cases(|v| newell_normal(v).normalize_or_zero()), "do not normalise");
        caught(newell_cases(newell_open), "sum over every edge");
    }

    /// hit_polygon as written, or with one planted mistake.
    #[derive(Clone, Copy, PartialEq, Eq)]
    enum PolygonMistake {
        Faithful,
        /// Projects onto xy whatever the normal.
        AlwaysDropZ,
        /// Inside by the winding rule, not even–odd.
        WindingRule,
        /// The plane's normal, not faced against the ray.
        UnfacedNormal,
    }

    fn planted_polygon(
        ray: &Ray,
        vertices: &[Vec3],
        range: Interval,
        mistake: PolygonMistake,
    ) -> Option<Hit> {
        if vertices.len() < 3 {
            return None;
        }
        let n = newell_normal(vertices).try_normalize()?;
        let hit = l02_ray_casting::hit_plane(ray, n, n.dot(vertices[0]), range)?;
        let drop = if mistake == PolygonMistake::AlwaysDropZ { 2 } else { dominant_axis(n) };
        let (i, j) = ((drop + 1) % 3, (drop + 2) % 3);
        let flat = |v: Vec3| Vec2::new(v[i], v[j]);
        let polygon: Vec<Vec2> = vertices.iter().map(|&v| flat(v)).collect();
        let inside = if mistake == PolygonMistake::WindingRule {
            winding_number(&polygon, flat(hit.point)) != 0
        } else {
            inside_crossings(&polygon, flat(hit.point))
        };
        let hit = if mistake == PolygonMistake::UnfacedNormal { Hit { normal: n, ..hit } } else { hit };
        inside.then_some(hit)
    }

    #[test]
    fn polygon_mistakes() {
        assert!(polygon_cases(|r, v, i| planted_polygon(r, v, i, PolygonMistake::Faithful)).is_ok());
        caught(polygon_cases(|r, v, i| planted_polygon(r, v, i, PolygonMistake::AlwaysDropZ)), "dropping z");
        caught(polygon_cases(|r, v, i| planted_polygon(r, v, i, PolygonMistake::WindingRule)), "even–odd");
        caught(polygon_cases(|r, v, i| planted_polygon(r, v, i, PolygonMistake::UnfacedNormal)), "Hit::new");
    }
}
