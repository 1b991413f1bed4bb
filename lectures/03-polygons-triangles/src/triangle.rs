//! Ray–triangle intersection, three ways: the slides' barycentric system by
//! Cramer's rule, Möller–Trumbore, and the watertight test the tracer uses;
//! then the hit record with interpolated vertex normals.
//!
//! All three solve o + t·d = (1 − β − γ)a + βb + γc for (t, β, γ) and report a
//! hit when β ≥ 0, γ ≥ 0, β + γ ≤ 1 and t is inside the open `range`. They
//! are two-sided (a ray from behind hits too). `dir` need not be unit length
//! but must not be zero. In a scene file:
//! `{ type = "triangle", vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]], normals = [[0, 0, 1], …] }`
//! (normals optional).

use raylab::{Float, Hit, Interval, Mat3, Ray, Vec2, Vec3};

use crate::polygon::dominant_axis;

/// A hit on a triangle (a, b, c): the ray parameter `t` and the barycentric
/// coordinates of the point p = (1 − β − γ)a + βb + γc.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleHit {
    pub t: Float,
    pub beta: Float,
    pub gamma: Float,
}

/// The slides' barycentric system solved by Cramer's rule.
///
/// o + t·d = a + β(b − a) + γ(c − a) rearranges to the 3×3 linear system
/// β(a − b) + γ(a − c) + t·d = a − o, i.e. A·(β, γ, t)ᵀ = a − o with the
/// columns A = [a − b | a − c | d]. Cramer's rule: β = |A_β|/|A|,
/// γ = |A_γ|/|A|, t = |A_t|/|A|, where A_x is A with the column of x replaced
/// by a − o. |A| = 0 means the ray is parallel to the triangle's plane (or the
/// triangle is degenerate): `None`. Four determinants of 9 products each: the
/// clearest, and the slowest of the three. Book: §3.7 Barycentric coordinates
/// and Cramer's rule.
pub fn hit_triangle_cramer(ray: &Ray, a: Vec3, b: Vec3, c: Vec3, range: Interval) -> Option<TriangleHit> {
    debug_assert!(ray.dir != Vec3::ZERO, "the ray direction must not be zero");
    // SOLUTION BEGIN
    // The system's columns and right-hand side.
    let (col_beta, col_gamma, col_t) = (a - b, a - c, ray.dir);
    let rhs = a - ray.origin;

    // |A| = 0: parallel or degenerate.
    let det_a = Mat3::from_cols(col_beta, col_gamma, col_t).determinant();
    if det_a == 0.0 {
        return None;
    }

    // Cramer's rule.
    let beta = Mat3::from_cols(rhs, col_gamma, col_t).determinant() / det_a;
    let gamma = Mat3::from_cols(col_beta, rhs, col_t).determinant() / det_a;
    let t = Mat3::from_cols(col_beta, col_gamma, rhs).determinant() / det_a;

    // Inside the triangle and the range (written so that NaN fails).
    let inside = beta >= 0.0 && gamma >= 0.0 && beta + gamma <= 1.0;
    (inside && range.contains(t)).then_some(TriangleHit { t, beta, gamma })
    // SOLUTION END
}

/// Möller–Trumbore (1997): the same system, with the edges e₁ = b − a,
/// e₂ = c − a and s = o − a, solved by triple products:
/// P = d × e₂, det = e₁·P, β = (s·P)/det, Q = s × e₁, γ = (d·Q)/det,
/// t = (e₂·Q)/det. Leaves early when β or γ falls outside; det = 0 means the
/// ray is parallel to the plane: `None`. Fast, but shared edges can leak: the
/// β, γ of two neighbours are computed from different edges and round
/// differently. Book: §3.8 Möller–Trumbore.
pub fn hit_triangle_moller_trumbore(
    ray: &Ray,
    a: Vec3,
    b: Vec3,
    c: Vec3,
    range: Interval,
) -> Option<TriangleHit> {
    debug_assert!(ray.dir != Vec3::ZERO, "the ray direction must not be zero");
    // SOLUTION BEGIN
    // The edges and the determinant.
    let (e1, e2) = (b - a, c - a);
    let p = ray.dir.cross(e2);
    let det = e1.dot(p);
    if det == 0.0 {
        return None;
    }
    let inv_det = 1.0 / det;

    // β, leaving early outside.
    let s = ray.origin - a;
    let beta = s.dot(p) * inv_det;
    if !(0.0..=1.0).contains(&beta) {
        return None;
    }

    // γ, leaving early outside.
    let q = s.cross(e1);
    let gamma = ray.dir.dot(q) * inv_det;
    if !(gamma >= 0.0 && beta + gamma <= 1.0) {
        return None;
    }

    // t.
    let t = e2.dot(q) * inv_det;
    range.contains(t).then_some(TriangleHit { t, beta, gamma })
    // SOLUTION END
}

/// The edge function of the directed edge p→q in the ray's sheared space
/// (the ray at the origin along +z): e = p.x·q.y − p.y·q.x, twice the signed
/// area of (0, p, q) in the xy plane, positive when the ray passes left of
/// p→q.
///
/// It is exactly antisymmetric, e(q, p) = −e(p, q), whatever the rounding
/// (the same two products, subtracted the other way), so two triangles that
/// share an edge see the ray on opposite sides of it: that is what makes the
/// test watertight. In f32, when e rounds to exactly 0 it is recomputed in
/// f64, where the two products are exact, so the sign of a zero is decided
/// exactly (pbrt-v4's fallback). pbrt-v4 also forms the f32 difference with
/// a fused multiply–add (DifferenceOfProducts) for accuracy; the plain
/// difference is kept here because its exact antisymmetry is all that
/// watertightness needs, and it costs no libm call on machines built
/// without FMA.
pub fn edge_function(p: Vec3, q: Vec3) -> Float {
    // SOLUTION BEGIN
    let e = p.x * q.y - p.y * q.x;
    // Zero in f32: recompute in f64 (exact products, one rounding).
    if e == 0.0 && Float::MANTISSA_DIGITS < f64::MANTISSA_DIGITS {
        let wide = |x: Float| x as f64;
        return (wide(p.x) * wide(q.y) - wide(p.y) * wide(q.x)) as Float;
    }
    e
    // SOLUTION END
}

/// The watertight test of Woop, Benthin and Wald (2013), as in pbrt-v4.
///
/// Move to the ray's space: translate the vertices by −o; permute the axes so
/// that the dominant axis of d becomes z (kz = argmax |dᵢ|, kx = kz + 1,
/// ky = kx + 1, mod 3; the permutation keeps the handedness); shear
/// x' = x + Sₓz, y' = y + S_y z with Sₓ = −dₓ/d_z, S_y = −d_y/d_z, which
/// takes d to (0, 0, d_z): the ray is now the z axis through the origin, at
/// z = t·d_z.
/// The edge functions e₀ = e(p₁, p₂), e₁ = e(p₂, p₀), e₂ = e(p₀, p₁) (see
/// [`edge_function`]) are, up to one factor, the barycentric weights of the
/// origin in the projected triangle: the ray is inside iff all three have the
/// same sign, zeros allowed (so a ray exactly through an edge or a vertex hits
/// every triangle there); all three zero is a triangle seen edge-on or
/// degenerate: `None`. With det = e₀ + e₁ + e₂: β = e₁/det, γ = e₂/det, and
/// t = (e₀z₀ + e₁z₁ + e₂z₂)/det with the scaled zᵢ = zᵢ/d_z.
///
/// Every vertex is transformed the same way in every triangle that holds it
/// and the edge functions are exactly antisymmetric, so a ray through a
/// shared edge or vertex of a closed mesh always hits at least one triangle:
/// no leaks. Book: §3.9 Watertight ray–triangle intersection.
pub fn hit_triangle_watertight(ray: &Ray, a: Vec3, b: Vec3, c: Vec3, range: Interval) -> Option<TriangleHit> {
    debug_assert!(ray.dir != Vec3::ZERO, "the ray direction must not be zero");
    // SOLUTION BEGIN
    // A degenerate triangle has no plane.
    if (c - a).cross(b - a).length_squared() == 0.0 {
        return None;
    }

    // Translate the vertices to the ray's origin.
    let (p0, p1, p2) = (a - ray.origin, b - ray.origin, c - ray.origin);

    // Permute the axes so that the direction's dominant axis is z.
    let kz = dominant_axis(ray.dir);
    let (kx, ky) = ((kz + 1) % 3, (kz + 2) % 3);
    let permute = |v: Vec3| Vec3::new(v[kx], v[ky], v[kz]);
    let (d, p0, p1, p2) = (permute(ray.dir), permute(p0), permute(p1), permute(p2));

    // Shear the ray onto the +z axis.
    let (shear_x, shear_y, scale_z) = (-d.x / d.z, -d.y / d.z, 1.0 / d.z);
    let shear = |p: Vec3| Vec3::new(p.x + shear_x * p.z, p.y + shear_y * p.z, p.z * scale_z);
    let (p0, p1, p2) = (shear(p0), shear(p1), shear(p2));

    // The edge functions.
    let e0 = edge_function(p1, p2);
    let e1 = edge_function(p2, p0);
    let e2 = edge_function(p0, p1);

    // Inside iff all have the same sign (zeros allowed); all zero is edge-on.
    if (e0 < 0.0 || e1 < 0.0 || e2 < 0.0) && (e0 > 0.0 || e1 > 0.0 || e2 > 0.0) {
        return None;
    }
    let det = e0 + e1 + e2;
    if det == 0.0 {
        return None;
    }

    // The hit distance from the scaled z, and the barycentrics.
    let inv_det = 1.0 / det;
    let t = (e0 * p0.z + e1 * p1.z + e2 * p2.z) * inv_det;
    range.contains(t).then_some(TriangleHit { t, beta: e1 * inv_det, gamma: e2 * inv_det })
    // SOLUTION END
}

/// The shading normal at barycentrics (β, γ): the vertex normals blended
/// (1 − β − γ)n₀ + βn₁ + γn₂ (Phong shading's normal), normalised. The
/// normals need not be unit length; where the blend is zero (opposite
/// normals cancelling) the result is the zero vector, never NaN.
/// Book: §3.10 Interpolated normals.
pub fn interpolate_normal(normals: &[Vec3; 3], beta: Float, gamma: Float) -> Vec3 {
    // SOLUTION BEGIN
    ((1.0 - beta - gamma) * normals[0] + beta * normals[1] + gamma * normals[2]).normalize_or_zero()
    // SOLUTION END
}

/// The hit of `ray` with the triangle `vertices` = (a, b, c), by the
/// watertight test.
///
/// The outward (geometric) normal is (b − a)×(c − a): the front is the side
/// from which a, b, c run counter-clockwise; [`Hit::new`] turns it against
/// the ray and sets `front_face`. With vertex `normals`, the hit's normal is
/// the [`interpolate_normal`] one, turned to the side of the geometric
/// normal that faces the ray (so shading never sees a normal facing away
/// from the viewer); where the blend vanishes the geometric normal stays.
/// uv = (β, γ). Book: §3.10 Interpolated normals.
pub fn hit_triangle(
    ray: &Ray,
    vertices: &[Vec3; 3],
    normals: Option<&[Vec3; 3]>,
    range: Interval,
) -> Option<Hit> {
    // SOLUTION BEGIN
    let [a, b, c] = *vertices;
    let found = hit_triangle_watertight(ray, a, b, c, range)?;

    // The geometric normal (None if it overflows: no NaN normal).
    let outward = (b - a).cross(c - a).try_normalize()?;
    let hit = Hit::new(ray, found.t, outward).with_uv(Vec2::new(found.beta, found.gamma));

    // The interpolated normal, on the side of the geometric one that faces the ray.
    let Some(normals) = normals else {
        return Some(hit);
    };
    let shading = interpolate_normal(normals, found.beta, found.gamma);
    if shading == Vec3::ZERO {
        return Some(hit);
    }
    let normal = if shading.dot(hit.normal) < 0.0 { -shading } else { shading };
    Some(Hit { normal, ..hit })
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::{assert_abs_diff_eq, assert_relative_eq};
    use raylab::random::Rng;
    use raylab::scene::Mesh;
    use raylab_testing::meshes::{edge_and_vertex_rays, wobbly_octahedron};
    use raylab_testing::{wide, wide3};

    type Method = fn(&Ray, Vec3, Vec3, Vec3, Interval) -> Option<TriangleHit>;

    const METHODS: [(&str, Method); 3] = [
        ("cramer", hit_triangle_cramer),
        ("moller_trumbore", hit_triangle_moller_trumbore),
        ("watertight", hit_triangle_watertight),
    ];

    /// The right triangle a = 0, b = x̂, c = ŷ in the plane z = 0 (front +z).
    const A: Vec3 = Vec3::ZERO;
    const B: Vec3 = Vec3::X;
    const C: Vec3 = Vec3::Y;

    fn down_at(x: Float, y: Float) -> Ray {
        Ray::new(Vec3::new(x, y, 2.0), Vec3::new(0.0, 0.0, -1.0))
    }

    #[test]
    fn barycentrics_at_the_vertices_and_the_centroid() {
        // Vertical rays onto z = 0 are exact: t = 2, and (β, γ) = (x, y) because
        // p = (1 − β − γ)·0 + β·x̂ + γ·ŷ.
        for (name, method) in METHODS {
            for (x, y) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.25, 0.5)] {
                let hit =
                    method(&down_at(x, y), A, B, C, Interval::POSITIVE).unwrap_or_else(|| panic!("{name}"));
                assert_eq!(hit, TriangleHit { t: 2.0, beta: x, gamma: y }, "{name} at ({x}, {y})");
            }
        }
        // A general triangle, a ray from an oblique origin through its centroid:
        // β = γ = 1/3, t = 1 (the ray's dir is centroid − origin). Cramer and
        // Möller–Trumbore round a few operations on values of size ~4: 16ε.
        let (a, b, c) = (Vec3::new(1.0, -2.0, 0.5), Vec3::new(3.0, 1.0, -1.0), Vec3::new(-1.0, 2.0, 2.0));
        let centroid = (a + b + c) / 3.0;
        let origin = Vec3::new(-3.0, 4.0, 5.0);
        let r = Ray::new(origin, centroid - origin);
        for (name, method) in METHODS {
            let hit = method(&r, a, b, c, Interval::POSITIVE).unwrap_or_else(|| panic!("{name}"));
            let tol = 16.0 * Float::EPSILON;
            assert_abs_diff_eq!(hit.beta, 1.0 / 3.0, epsilon = tol);
            assert_abs_diff_eq!(hit.gamma, 1.0 / 3.0, epsilon = tol);
            assert_abs_diff_eq!(hit.t, 1.0, epsilon = tol);
        }
    }

    #[test]
    fn back_face_hits_and_misses() {
        // From below (z = −2, going up): the same t and barycentrics.
        let up = Ray::new(Vec3::new(0.25, 0.25, -2.0), Vec3::Z);
        for (name, method) in METHODS {
            assert_eq!(
                method(&up, A, B, C, Interval::POSITIVE),
                Some(TriangleHit { t: 2.0, beta: 0.25, gamma: 0.25 }),
                "{name}"
            );
            // Outside: β + γ = 1.2 > 1, β < 0, γ < 0; and outside the range.
            for (x, y) in [(0.6, 0.6), (-0.1, 0.5), (0.5, -0.1)] {
                assert_eq!(method(&down_at(x, y), A, B, C, Interval::POSITIVE), None, "{name} at ({x}, {y})");
            }
            assert_eq!(method(&down_at(0.2, 0.2), A, B, C, Interval::new(0.0, 1.5)), None, "{name}");
        }
        let hit = hit_triangle(&up, &[A, B, C], None, Interval::POSITIVE).unwrap();
        assert_eq!((hit.normal, hit.front_face, hit.outward_normal()), (-Vec3::Z, false, Vec3::Z));
        let hit = hit_triangle(&down_at(0.25, 0.25), &[A, B, C], None, Interval::POSITIVE).unwrap();
        assert_eq!((hit.normal, hit.front_face, hit.uv), (Vec3::Z, true, Vec2::new(0.25, 0.25)));
        assert_eq!(hit.point, Vec3::new(0.25, 0.25, 0.0));
    }

    #[test]
    fn ray_parallel_to_the_triangle_gives_none() {
        // In the plane z = 0 (through the triangle) and above it (z = 1): every
        // determinant is exactly 0 (all z components vanish) or the edge
        // functions have mixed signs.
        for z in [0.0, 1.0] {
            for dir in [Vec3::new(1.0, 0.5, 0.0), Vec3::new(0.0, -1.0, 0.0), Vec3::new(-0.3, 0.7, 0.0)] {
                let r = Ray::new(Vec3::new(-1.0, 0.25, z), dir);
                for (name, method) in METHODS {
                    assert_eq!(method(&r, A, B, C, Interval::POSITIVE), None, "{name} z = {z} dir {dir}");
                }
            }
        }
        // A degenerate (collinear) triangle is never hit.
        for (name, method) in METHODS {
            assert_eq!(method(&down_at(0.5, 0.0), A, B, 2.0 * B, Interval::POSITIVE), None, "{name}");
        }
    }

    #[test]
    fn edge_function_zero_is_decided_exactly() {
        // p.x·q.y = (1 + 2⁻¹²)² = 1 + 2⁻¹¹ + 2⁻²⁴ and p.y·q.x = 1 + 2⁻¹¹: the exact
        // edge function is 2⁻²⁴ > 0. In f32 both products round to 1 + 2⁻¹¹ (the
        // 2⁻²⁴ is half an ulp, ties to even), so e = 0 and the f64 fallback
        // must find the sign; in f64 the plain difference is already exact.
        let s: Float = 1.0 + (2.0 as Float).powi(-12);
        let p = Vec3::new(s, 1.0 + (2.0 as Float).powi(-11), 0.0);
        let q = Vec3::new(1.0, s, 0.0);
        assert_eq!(edge_function(p, q), (2.0 as Float).powi(-24));
        assert_eq!(edge_function(q, p), -(2.0 as Float).powi(-24));
    }

    /// The triangle hit in f64 by an independent method: the plane through
    /// (a, b, c) by its normal, then barycentrics as ratios of sub-triangle
    /// areas. Returns (t, β, γ) and the smallest of the three barycentrics
    /// (the distance from the nearest edge, in barycentric units).
    fn reference(r: &Ray, a: Vec3, b: Vec3, c: Vec3) -> Option<(f64, f64, f64, f64)> {
        let (o, d, a, b, c) = (wide3(r.origin), wide3(r.dir), wide3(a), wide3(b), wide3(c));
        let sub = |u: [f64; 3], v: [f64; 3]| [u[0] - v[0], u[1] - v[1], u[2] - v[2]];
        let dot = |u: [f64; 3], v: [f64; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
        let cross = |u: [f64; 3], v: [f64; 3]| {
            [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        };
        let n = cross(sub(b, a), sub(c, a));
        let denom = dot(n, d);
        if denom == 0.0 {
            return None;
        }
        let t = dot(n, sub(a, o)) / denom;
        let p = [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]];
        let nn = dot(n, n);
        let beta = dot(n, cross(sub(p, a), sub(c, a))) / nn;
        let gamma = dot(n, cross(sub(b, a), sub(p, a))) / nn;
        let alpha = 1.0 - beta - gamma;
        Some((t, beta, gamma, alpha.min(beta).min(gamma)))
    }

    #[test]
    fn all_three_agree_with_an_f64_reference_on_random_rays() {
        // Random triangles in [−1, 1]³, rays from a sphere of radius 4 aimed at a
        // random point near the triangle. Tolerances: the three routines' errors
        // in β, γ and t grow like ε × (the condition of the system), which stays
        // below ~100 when the ray is not grazing (|cos| ≥ 0.1, checked) and the
        // triangle is not a sliver (area ≥ 0.05): 10⁴ε. Classification may
        // differ only within that distance of an edge.
        let tol = 1e4 * wide(Float::EPSILON);
        let mut rng = Rng::new(11);
        let (mut tested, mut hits) = (0, 0);
        while tested < 5000 {
            let (a, b, c) = (rng.in_cube(1.0), rng.in_cube(1.0), rng.in_cube(1.0));
            let n = (b - a).cross(c - a);
            let origin = rng.in_cube(1.0).normalize() * 4.0;
            let target = (a + b + c) / 3.0 + rng.in_cube(0.4);
            let dir = target - origin;
            if n.length() < 0.1 || (n.normalize().dot(dir.normalize())).abs() < 0.1 {
                continue;
            }
            tested += 1;
            let r = Ray::new(origin, dir);
            let Some((t, beta, gamma, margin)) = reference(&r, a, b, c) else { continue };
            let exact_hit = margin >= 0.0 && t > 0.0;
            hits += exact_hit as u32;
            for (name, method) in METHODS {
                let found = method(&r, a, b, c, Interval::POSITIVE);
                if margin.abs() > tol {
                    assert_eq!(found.is_some(), exact_hit, "{name}: margin {margin}, {r:?} {a} {b} {c}");
                }
                if let Some(h) = found {
                    let close = |x: Float, y: f64| (wide(x) - y).abs() <= tol * (1.0 + y.abs());
                    assert!(
                        close(h.t, t) && close(h.beta, beta) && close(h.gamma, gamma),
                        "{name}: {h:?} vs {t} {beta} {gamma}"
                    );
                }
            }
        }
        assert!(hits > 1000, "only {hits} hits: the test would prove little");
    }

    /// How many `rays` find no triangle of `mesh` with `method`.
    fn leaks(mesh: &Mesh, rays: &[Ray], method: Method) -> usize {
        let hits_any = |r: &Ray| {
            (0..mesh.triangles.len()).any(|i| {
                let [a, b, c] = mesh.triangle(i);
                method(r, a, b, c, Interval::POSITIVE).is_some()
            })
        };
        rays.iter().filter(|r| !hits_any(r)).count()
    }

    #[test]
    fn shared_edge_never_leaks_on_closed_meshes() {
        // Rays from inside a closed mesh aimed exactly at its edges and vertices
        // must all hit it. Measured on these 11 604 rays: Cramer leaks 638 (f32) /
        // 729 (f64), Möller–Trumbore 815 / 871, the watertight test none. A ray
        // aimed at an edge passes it by rounding's width on one side, and the two
        // neighbours' non-watertight tests can both round it outside. The counts
        // are printed (run with --nocapture).
        let mut rng = Rng::new(5);
        let mut meshes: Vec<(Mesh, Vec3)> =
            (0..200).map(|_| (wobbly_octahedron(&mut rng), rng.in_cube(0.05))).collect();
        meshes.push((Mesh::icosphere(2), Vec3::ZERO));
        meshes.push((Mesh::icosphere(2), Vec3::new(0.1, -0.2, 0.05)));
        let mut counts = [0; 3];
        let mut total = 0;
        for (mesh, origin) in &meshes {
            let rays = edge_and_vertex_rays(mesh, *origin);
            total += rays.len();
            for (k, (_, method)) in METHODS.iter().enumerate() {
                counts[k] += leaks(mesh, &rays, *method);
            }
        }
        eprintln!(
            "leaks over {total} edge and vertex rays: cramer {}, moller_trumbore {}, watertight {}",
            counts[0], counts[1], counts[2]
        );
        assert_eq!(counts[2], 0, "the watertight test leaked");
    }

    #[test]
    fn coplanar_neighbours_share_their_edge() {
        // The quad (0,0,0), (1,0,0), (1,1,0), (0,1,0) split along the diagonal
        // a–c into (a, b, c) and (a, c, d). Rays from random origins above and
        // below, aimed at points of the diagonal, must hit one or both (watertight).
        // Measured on these 5000 rays: Cramer misses both on 68 (f32) / 64 (f64),
        // Möller–Trumbore on 406 / 420; the counts are printed.
        let (a, b, c, d) = (Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y);
        let mut rng = Rng::new(9);
        let (mut both, mut counts) = (0, [0; 3]);
        for _ in 0..5000 {
            let target = a.lerp(c, rng.range(0.01, 0.99));
            let origin = Vec3::new(rng.range(-2.0, 3.0), rng.range(-2.0, 3.0), rng.range(-3.0, 3.0));
            let r = Ray::new(origin, target - origin);
            for (k, (_, method)) in METHODS.iter().enumerate() {
                let first = method(&r, a, b, c, Interval::POSITIVE).is_some();
                let second = method(&r, a, c, d, Interval::POSITIVE).is_some();
                counts[k] += (!first && !second) as u32;
                if k == 2 {
                    both += (first && second) as u32;
                }
            }
        }
        eprintln!(
            "diagonal rays hitting neither: cramer {}, moller_trumbore {}, watertight {} ({both} hit both)",
            counts[0], counts[1], counts[2]
        );
        assert_eq!(counts[2], 0, "a ray slipped through the shared edge");
    }

    #[test]
    fn interpolated_normal_at_the_vertices_is_the_vertex_normal() {
        let normals = [Vec3::new(1.0, 0.0, 1.0), Vec3::new(0.0, 2.0, 2.0), Vec3::Z];
        // At a vertex the blend is 1·nᵢ + 0·(others) exactly, so the result is nᵢ
        // normalised; 2ε covers normalize's rounding.
        for (k, (beta, gamma)) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)].into_iter().enumerate() {
            assert_relative_eq!(
                interpolate_normal(&normals, beta, gamma),
                normals[k].normalize(),
                max_relative = 2.0 * Float::EPSILON
            );
        }
        // At the midpoint of the first edge: (1, 0, 1)/2 + (0, 2, 2)/2 = (0.5, 1, 1.5), /√3.5.
        let mid = interpolate_normal(&normals, 0.5, 0.0);
        assert_relative_eq!(
            mid,
            Vec3::new(0.5, 1.0, 1.5) / (3.5 as Float).sqrt(),
            max_relative = 4.0 * Float::EPSILON
        );
        // Opposite normals cancel: zero, not NaN.
        assert_eq!(interpolate_normal(&[Vec3::Z, -Vec3::Z, Vec3::Z], 0.5, 0.0), Vec3::ZERO);
    }

    #[test]
    fn vertex_normals_are_turned_to_the_side_facing_the_ray() {
        // Vertex normals tilted from +z; the hit at (β, γ) = (0.25, 0.25) blends
        // them 0.5 n₀ + 0.25 n₁ + 0.25 n₂.
        let normals = [Vec3::new(0.0, 0.0, 1.0), Vec3::new(1.0, 0.0, 1.0), Vec3::new(0.0, 1.0, 1.0)];
        let blended = Vec3::new(0.25, 0.25, 1.0).normalize();
        let from_above =
            hit_triangle(&down_at(0.25, 0.25), &[A, B, C], Some(&normals), Interval::POSITIVE).unwrap();
        assert_relative_eq!(from_above.normal, blended, max_relative = 4.0 * Float::EPSILON);
        assert!(from_above.front_face);
        // From below the shading normal is flipped with the geometric one.
        let up = Ray::new(Vec3::new(0.25, 0.25, -2.0), Vec3::Z);
        let from_below = hit_triangle(&up, &[A, B, C], Some(&normals), Interval::POSITIVE).unwrap();
        assert_relative_eq!(from_below.normal, -blended, max_relative = 4.0 * Float::EPSILON);
        assert!(!from_below.front_face);
        // Cancelling normals fall back to the geometric normal.
        let cancel = [Vec3::Z, -Vec3::Z, Vec3::Z];
        let hit = hit_triangle(&down_at(0.5, 0.0), &[A, B, C], Some(&cancel), Interval::POSITIVE).unwrap();
        assert_eq!(hit.normal, Vec3::Z);
    }
}
