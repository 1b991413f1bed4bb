//! Planar polygons: the point-in-polygon tests (crossing number and winding
//! number) and the ray–polygon intersection.
//!
//! In a scene file:
//! `{ type = "polygon", vertices = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]] }`
//! (at least three vertices, planar, not all on a line; counter-clockwise seen
//! from the front).

use raylab::{Hit, Interval, Ray, Vec2, Vec3};

/// Whether `p` is inside `polygon` by the even–odd rule (crossing number):
/// cast a test ray from `p` toward +x and count the edges it crosses; odd is
/// inside.
///
/// An edge a→b crosses the test ray's line when one end is above and the
/// other is not, where a vertex exactly at the height of `p` counts as above
/// (v.y ≥ p.y). So a test ray through a vertex counts it once (the two edges
/// go to opposite sides) or not at all (both go the same way), never twice,
/// and an edge lying on the test ray is never counted. The crossing is right
/// of `p` when `p` is strictly left of the edge directed upward
/// (lo→hi: (hi − lo) × (p − lo) > 0), which needs no division.
///
/// Points on the boundary go to one side consistently (half-open rule): of
/// two polygons sharing an edge, exactly one contains a point of it
/// (vertices aside). A self-intersecting polygon's doubly covered parts are
/// outside (the pentagram's centre). The polygon is implicitly closed (the
/// last vertex joins the first); fewer than three vertices contain nothing.
/// Book: §3.3 Inside a polygon: counting crossings.
pub fn inside_crossings(polygon: &[Vec2], p: Vec2) -> bool {
    // SOLUTION BEGIN
    let mut inside = false;
    for (i, &a) in polygon.iter().enumerate() {
        let b = polygon[(i + 1) % polygon.len()];
        // Does the edge cross the line of the test ray? (a vertex on it counts as above)
        if (a.y >= p.y) != (b.y >= p.y) {
            // Is the crossing right of p? (p strictly left of the upward edge)
            let (lo, hi) = if a.y < b.y { (a, b) } else { (b, a) };
            if (hi - lo).perp_dot(p - lo) > 0.0 {
                inside = !inside;
            }
        }
    }
    inside
    // SOLUTION END
}

/// The winding number of `polygon` around `p`: how many times the boundary
/// turns counter-clockwise around `p` (negative for clockwise); non-zero is
/// inside by the non-zero rule.
///
/// The test ray toward +x counts +1 for an edge crossing it upward right of
/// `p` and −1 for one crossing it downward, with the same "a vertex at the
/// height of `p` counts as above" rule and the same crossing test as
/// [`inside_crossings`], so the two always agree on parity:
/// `inside_crossings(poly, p) == (winding_number(poly, p) % 2 != 0)`.
/// A counter-clockwise convex polygon has winding 1 inside; the
/// counter-clockwise pentagram has 2 at its centre (even–odd says outside).
/// Book: §3.4 The winding number.
pub fn winding_number(polygon: &[Vec2], p: Vec2) -> i32 {
    // SOLUTION BEGIN
    let mut winding = 0;
    for (i, &a) in polygon.iter().enumerate() {
        let b = polygon[(i + 1) % polygon.len()];
        let (a_above, b_above) = (a.y >= p.y, b.y >= p.y);
        // An upward crossing right of p winds counter-clockwise.
        if !a_above && b_above && (b - a).perp_dot(p - a) > 0.0 {
            winding += 1;
        }
        // A downward crossing right of p winds clockwise (tested on the upward edge b→a).
        if a_above && !b_above && (a - b).perp_dot(p - b) > 0.0 {
            winding -= 1;
        }
    }
    winding
    // SOLUTION END
}

/// Newell's normal of a polygon: nₓ = Σ (yᵢ − yⱼ)(zᵢ + zⱼ),
/// n_y = Σ (zᵢ − zⱼ)(xᵢ + xⱼ), n_z = Σ (xᵢ − xⱼ)(yᵢ + yⱼ) over the edges
/// i → j = i + 1. Its length is twice the area and it points to the side from
/// which the vertices turn counter-clockwise; it averages out small
/// non-planarity and never depends on a choice of three vertices (which could
/// be collinear). Zero for a degenerate polygon. Book: §3.5 Ray–polygon intersection.
pub fn newell_normal(vertices: &[Vec3]) -> Vec3 {
    // SOLUTION BEGIN
    let mut n = Vec3::ZERO;
    for (i, &a) in vertices.iter().enumerate() {
        let b = vertices[(i + 1) % vertices.len()];
        n += Vec3::new((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    n
    // SOLUTION END
}

/// The index (0, 1, 2 for x, y, z) of the component of `v` with the largest
/// magnitude; ties go to the later axis.
pub fn dominant_axis(v: Vec3) -> usize {
    let a = v.abs();
    if a.x > a.y && a.x > a.z {
        0
    } else if a.y > a.z {
        1
    } else {
        2
    }
}

/// The hit of `ray` with the planar polygon `vertices` inside `range`.
///
/// The plane is n·p = n·v₀ with n Newell's normal ([`newell_normal`],
/// normalised); the ray meets it at t = (n·v₀ − n·o)/(n·d) (none when
/// n·d = 0, a ray parallel to the plane), found by lecture 02's
/// [`l02_ray_casting::hit_plane`]. The hit point and the vertices are
/// projected to 2D by dropping the coordinate of the normal's dominant axis
/// (the projection that shrinks the polygon least, never to a segment) and
/// tested with [`inside_crossings`]; so a self-intersecting polygon follows the
/// even–odd rule. The outward normal is n: the front is the side from which
/// the vertices run counter-clockwise.
///
/// `None` for fewer than three vertices or a degenerate polygon (zero normal),
/// never a panic. `dir` need not be unit length. Book: §3.5 Ray–polygon
/// intersection.
pub fn hit_polygon(ray: &Ray, vertices: &[Vec3], range: Interval) -> Option<Hit> {
    // SOLUTION BEGIN
    if vertices.len() < 3 {
        return None;
    }
    // The plane from Newell's normal.
    let n = newell_normal(vertices).try_normalize()?;
    let offset = n.dot(vertices[0]);

    // Hit the plane.
    let hit = l02_ray_casting::hit_plane(ray, n, offset, range)?;

    // Project to 2D by dropping the dominant axis of the normal, then count crossings.
    let drop = dominant_axis(n);
    let (i, j) = ((drop + 1) % 3, (drop + 2) % 3);
    let flat = |v: Vec3| Vec2::new(v[i], v[j]);
    let polygon: Vec<Vec2> = vertices.iter().map(|&v| flat(v)).collect();
    inside_crossings(&polygon, flat(hit.point)).then_some(hit)
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use raylab::Float;
    use raylab::math::consts::PI;
    use raylab::random::Rng;
    use raylab_testing::polygons::{on_plane, pentagram, square, square_in_plane, u_shape};

    fn v2(points: &[[Float; 2]]) -> Vec<Vec2> {
        points.iter().map(|&p| Vec2::from_array(p)).collect()
    }

    #[test]
    fn convex_square_inside_and_outside() {
        let sq = square();
        for (p, inside) in
            [([1.0, 1.0], true), ([3.0, 1.0], false), ([-1.0, 1.0], false), ([1.0, 3.0], false)]
        {
            let p = Vec2::from_array(p);
            assert_eq!(inside_crossings(&sq, p), inside, "{p}");
            assert_eq!(winding_number(&sq, p), inside as i32, "{p}");
        }
        // Clockwise, the winding number turns negative; even–odd does not care.
        let cw: Vec<Vec2> = sq.iter().rev().copied().collect();
        assert_eq!(winding_number(&cw, Vec2::ONE), -1);
        assert!(inside_crossings(&cw, Vec2::ONE));
    }

    #[test]
    fn concave_notch_is_outside() {
        let u = u_shape();
        // In the notch: the test ray crosses x = 2 and x = 3, two crossings.
        assert!(!inside_crossings(&u, Vec2::new(1.5, 2.0)));
        assert_eq!(winding_number(&u, Vec2::new(1.5, 2.0)), 0);
        // In the left arm: it crosses x = 1, 2 and 3, three crossings (winding +1 −1 +1).
        assert!(inside_crossings(&u, Vec2::new(0.5, 2.0)));
        assert_eq!(winding_number(&u, Vec2::new(0.5, 2.0)), 1);
        // In the base below the notch.
        assert!(inside_crossings(&u, Vec2::new(1.5, 0.5)));
        assert_eq!(winding_number(&u, Vec2::new(1.5, 0.5)), 1);
    }

    #[test]
    fn pentagram_centre_winds_twice_and_is_outside_by_even_odd() {
        let star = pentagram();
        // No vertex is at height 0 (sin of 90°+72°k is ±1, ±0.309, ±0.809), so the
        // test ray from the centre crosses two edges, both upward: winding 2.
        assert_eq!(winding_number(&star, Vec2::ZERO), 2);
        assert!(!inside_crossings(&star, Vec2::ZERO));
        let reversed: Vec<Vec2> = star.iter().rev().copied().collect();
        assert_eq!(winding_number(&reversed, Vec2::ZERO), -2);
        // A tip (toward the top vertex (0, 1), at (0, 0.8)) is covered once.
        assert_eq!(winding_number(&star, Vec2::new(0.0, 0.8)), 1);
        assert!(inside_crossings(&star, Vec2::new(0.0, 0.8)));
        // Between two tips (at angle 90° + 36°, radius 0.8) and far away: outside.
        let gap = 0.8 * Vec2::from_angle(PI / 2.0 + PI / 5.0);
        for p in [gap, Vec2::new(2.0, 0.0)] {
            assert_eq!(winding_number(&star, p), 0, "{p}");
            assert!(!inside_crossings(&star, p), "{p}");
        }
    }

    #[test]
    fn test_ray_through_a_vertex_is_counted_once_or_not_at_all() {
        // The diamond |x| + |y| ≤ 1: the test ray from a point at height 0 runs
        // through the vertices (1, 0) and (−1, 0). Each counts as above, so each
        // is crossed once (its edges go to opposite sides).
        let diamond = v2(&[[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]]);
        for (x, inside) in [(0.0, true), (-0.5, true), (-2.0, false), (2.0, false)] {
            let p = Vec2::new(x, 0.0);
            assert_eq!(inside_crossings(&diamond, p), inside, "{p}");
            assert_eq!(winding_number(&diamond, p), inside as i32, "{p}");
        }
        // A vertex that only touches the test ray is not counted at all: the kite
        // whose lowest vertex (1, 0) has both neighbours above.
        let v = v2(&[[-1.0, 1.0], [1.0, 0.0], [3.0, 1.0], [1.0, 2.0]]);
        assert!(!inside_crossings(&v, Vec2::new(0.0, 0.0)));
        assert_eq!(winding_number(&v, Vec2::new(0.0, 0.0)), 0);
        // The square's test rays along its bottom and top edges (vertices at p.y):
        // from (−1, 0) nothing is crossed; from (−1, 2) both sides are: outside.
        for p in [Vec2::new(-1.0, 0.0), Vec2::new(-1.0, 2.0), Vec2::new(3.0, 0.0), Vec2::new(3.0, 2.0)] {
            assert!(!inside_crossings(&square(), p), "{p}");
            assert_eq!(winding_number(&square(), p), 0, "{p}");
        }
    }

    #[test]
    fn shared_edge_points_belong_to_exactly_one_polygon() {
        let lower = square();
        let upper: Vec<Vec2> = lower.iter().map(|&v| v + Vec2::new(0.0, 2.0)).collect();
        let right: Vec<Vec2> = lower.iter().map(|&v| v + Vec2::new(2.0, 0.0)).collect();
        // On the horizontal edge y = 2 and the vertical edge x = 2.
        for (a, b, p) in [(&lower, &upper, Vec2::new(1.0, 2.0)), (&lower, &right, Vec2::new(2.0, 1.0))] {
            assert!(inside_crossings(a, p) != inside_crossings(b, p), "{p}");
            assert_eq!(winding_number(a, p) + winding_number(b, p), 1, "{p}");
        }
    }

    #[test]
    fn crossings_and_winding_agree_on_parity() {
        // An independent check of both on random points: the two rules count the
        // same crossings, one with signs.
        let mut rng = Rng::new(7);
        for polygon in [square(), u_shape(), pentagram()] {
            for _ in 0..2000 {
                // Half the points on the grid of vertex coordinates (ties everywhere).
                let p = if rng.int(0, 1) == 0 {
                    Vec2::new(rng.range(-1.5, 3.5), rng.range(-1.5, 3.5))
                } else {
                    Vec2::new(rng.int(-1, 3) as Float, rng.int(-1, 3) as Float)
                };
                assert_eq!(inside_crossings(&polygon, p), winding_number(&polygon, p) % 2 != 0, "{p}");
            }
        }
        assert!(!inside_crossings(&[], Vec2::ZERO));
        assert_eq!(winding_number(&v2(&[[0.0, 0.0], [1.0, 1.0]]), Vec2::new(0.5, 0.2)), 0);
    }

    #[test]
    fn newell_normal_is_twice_the_area_along_the_ccw_normal() {
        // The square [0, 2]² at z = 5: area 4, counter-clockwise from +z.
        let sq: Vec<Vec3> = square().iter().map(|v| v.extend(5.0)).collect();
        assert_eq!(newell_normal(&sq), Vec3::new(0.0, 0.0, 8.0));
        // Collinear points: no plane.
        assert_eq!(newell_normal(&[Vec3::ZERO, Vec3::X, 2.0 * Vec3::X]), Vec3::ZERO);
    }

    #[test]
    fn polygon_in_3d_for_each_dominant_axis() {
        for axis in 0..3 {
            let quad = square_in_plane(axis);
            let normal = Vec3::AXES[axis];
            let at = |u: Float, v: Float| on_plane(axis, u, v);
            // From 4 units in front, slightly oblique, toward (0.5, 1.5) of the square: t = 1.
            let target = at(0.5, 1.5);
            let r =
                Ray::new(target + 4.0 * normal + 0.5 * at(0.3, -0.2), -4.0 * normal - 0.5 * at(0.3, -0.2));
            let hit = hit_polygon(&r, &quad, Interval::POSITIVE).expect("inside the square");
            assert_relative_eq!(hit.t, 1.0, max_relative = 4.0 * Float::EPSILON);
            assert_eq!((hit.normal, hit.front_face), (normal, true));
            // From behind: the back face, normal turned toward the ray.
            let back = Ray::new(at(1.0, 1.0) - 2.0 * normal, normal);
            let hit = hit_polygon(&back, &quad, Interval::POSITIVE).unwrap();
            assert_eq!((hit.t, hit.normal, hit.front_face), (2.0, -normal, false));
            // Beside the square (projected point (2.5, 1) is outside).
            assert!(
                hit_polygon(&Ray::new(at(2.5, 1.0) + normal, -normal), &quad, Interval::POSITIVE).is_none()
            );
        }
        // A tilted quad whose normal (1, 1, 0)/√2 ties x and y: either drop works.
        let tilted = [
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(0.0, 1.0, 1.0),
            Vec3::new(1.0, 0.0, 1.0),
        ];
        let hit = hit_polygon(
            &Ray::new(Vec3::new(0.0, 0.0, 0.5), Vec3::ONE - Vec3::Z),
            &tilted,
            Interval::POSITIVE,
        );
        // The ray (t, t, 0.5) meets x + y = 1 at t = 1/2.
        assert_relative_eq!(hit.expect("tilted quad").t, 0.5, max_relative = 4.0 * Float::EPSILON);
    }

    #[test]
    fn pentagram_polygon_has_a_hole_by_even_odd() {
        let star: Vec<Vec3> = pentagram().iter().map(|v| v.extend(-2.0)).collect();
        let down = |x: Float, y: Float| Ray::new(Vec3::new(x, y, 0.0), -Vec3::Z);
        assert!(hit_polygon(&down(0.0, 0.0), &star, Interval::POSITIVE).is_none(), "the centre is a hole");
        let tip = hit_polygon(&down(0.0, 0.8), &star, Interval::POSITIVE).expect("a tip");
        assert_relative_eq!(tip.t, 2.0, max_relative = 4.0 * Float::EPSILON);
    }

    #[test]
    fn degenerate_polygons_and_parallel_rays_give_none() {
        let down = Ray::new(Vec3::new(0.5, 0.5, 1.0), -Vec3::Z);
        assert!(hit_polygon(&down, &[], Interval::POSITIVE).is_none());
        assert!(hit_polygon(&down, &[Vec3::ZERO, Vec3::X], Interval::POSITIVE).is_none());
        assert!(hit_polygon(&down, &[Vec3::ZERO, Vec3::X, 2.0 * Vec3::X], Interval::POSITIVE).is_none());
        let quad = square_in_plane(2);
        let along = Ray::new(Vec3::new(-1.0, 1.0, 1.0), Vec3::X);
        assert!(hit_polygon(&along, &quad, Interval::POSITIVE).is_none());
    }
}
