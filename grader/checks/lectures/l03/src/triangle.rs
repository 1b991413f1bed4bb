//! The checks of `triangle.rs`: the three ray–triangle tests, edge_function, interpolate_normal,
//! hit_triangle, and the leak test of the watertight one.

use super::common::*;
use raylab_testing::meshes::{edge_and_vertex_rays, wobbly_octahedron};

// ---- triangles -------------------------------------------------------------

/// The right triangle a = 0, b = x̂, c = ŷ in the plane z = 0 (front +z).
pub(super) const A: Vec3 = Vec3::ZERO;
pub(super) const B: Vec3 = Vec3::X;
pub(super) const C: Vec3 = Vec3::Y;

pub(super) fn show_tri(h: &Option<TriangleHit>) -> String {
    maybe(h, |h| format!("t = {}, β = {}, γ = {}", num(h.t), num(h.beta), num(h.gamma)))
}

/// Expects a hit (t, β, γ) within `tol`, naming swapped barycentrics.
pub(super) fn expect_tri(
    case: &str,
    got: Option<TriangleHit>,
    t: Float,
    beta: Float,
    gamma: Float,
    tol: Float,
    cause: &str,
) -> Result<(), Failure> {
    let expected = format!("t = {}, β = {}, γ = {} (± {tol:.1e})", num(t), num(beta), num(gamma));
    let Some(h) = got else { return Err(fail(case, expected, "None (no hit)", cause)) };
    let ok = (h.t - t).abs() <= tol && (h.beta - beta).abs() <= tol && (h.gamma - gamma).abs() <= tol;
    let cause = if (h.beta - gamma).abs() <= tol && (h.gamma - beta).abs() <= tol && beta != gamma {
        "β weights b and γ weights c: p = (1 − β − γ)a + βb + γc"
    } else if (h.t - t).abs() > tol {
        "t solves o + t·d = (1 − β − γ)a + βb + γc, in units of dir"
    } else {
        cause
    };
    ensure(ok, case, expected, show_tri(&got), cause)
}

pub(super) fn triangle_cases(method: TriangleFn) -> CheckResult {
    let down = |x: Float, y: Float| ray([x, y, 2.0], [0.0, 0.0, -1.0]);
    // Vertical rays onto z = 0 are exact: t = 2 and (β, γ) = (x, y), as p = β·x̂ + γ·ŷ.
    for (x, y, cause) in [
        (0.25, 0.5, "solve o + t·d = (1 − β − γ)a + βb + γc for (t, β, γ)"),
        (0.0, 0.0, "the vertices belong to the triangle: accept β ≥ 0, γ ≥ 0 (not > 0)"),
        (1.0, 0.0, "the edges belong to the triangle: accept β + γ ≤ 1 (not < 1)"),
        (0.0, 1.0, "the edges belong to the triangle: accept β + γ ≤ 1 (not < 1)"),
        (0.5, 0.0, "the edges belong to the triangle: accept γ = 0"),
    ] {
        let r = down(x, y);
        let case = format!("triangle (0, 0, 0), (1, 0, 0), (0, 1, 0), {}", show_ray(&r));
        expect_tri(&case, method(&r, A, B, C, ALL), 2.0, x, y, TOL, cause)?;
    }
    // A general triangle, a ray from an oblique origin through its centroid: β = γ = ⅓, t = 1.
    let (a, b, c) = (Vec3::new(1.0, -2.0, 0.5), Vec3::new(3.0, 1.0, -1.0), Vec3::new(-1.0, 2.0, 2.0));
    let origin = Vec3::new(-3.0, 4.0, 5.0);
    let r = Ray::new(origin, (a + b + c) / 3.0 - origin);
    let case =
        format!("triangle {}, {}, {}, {} (through the centroid)", vec3(a), vec3(b), vec3(c), show_ray(&r));
    expect_tri(
        &case,
        method(&r, a, b, c, ALL),
        1.0,
        1.0 / 3.0,
        1.0 / 3.0,
        TOL,
        "solve the 3×3 system for (t, β, γ)",
    )?;
    // From behind: the same t and barycentrics (two-sided).
    let up = ray([0.25, 0.25, -2.0], [0.0, 0.0, 1.0]);
    let case = format!("triangle (0, 0, 0), (1, 0, 0), (0, 1, 0), {} (from behind)", show_ray(&up));
    expect_tri(
        &case,
        method(&up, A, B, C, ALL),
        2.0,
        0.25,
        0.25,
        TOL,
        "the test is two-sided: a ray from behind (a negative determinant) hits too",
    )?;
    // Non-unit direction: t in units of dir, 2/4.
    let fast = ray([0.25, 0.25, 2.0], [0.0, 0.0, -4.0]);
    let case = format!("triangle (0, 0, 0), (1, 0, 0), (0, 1, 0), {}", show_ray(&fast));
    expect_tri(
        &case,
        method(&fast, A, B, C, ALL),
        0.5,
        0.25,
        0.25,
        TOL,
        "t is in units of dir: do not normalise it",
    )?;
    // Two triangles off the origin, in z = 0, hit straight down at points with exact barycentrics:
    // (0, 1), (1, 1), (½, −1) at (½, 0), β = ¼, γ = ½; (0, 1), (1, −1), (−1, 1) at (0, ½),
    // β = γ = ¼. In the first c + a is parallel to b − a, in the second c − a to b + a: a
    // degeneracy test on a wrong pair of edges refuses them.
    for (a, b, c, x, y, beta, gamma) in [
        (Vec3::Y, Vec3::new(1.0, 1.0, 0.0), Vec3::new(0.5, -1.0, 0.0), 0.5, 0.0, 0.25, 0.5),
        (Vec3::Y, Vec3::new(1.0, -1.0, 0.0), Vec3::new(-1.0, 1.0, 0.0), 0.0, 0.5, 0.25, 0.25),
    ] {
        let r = down(x, y);
        let case = format!("triangle {}, {}, {}, {}", vec3(a), vec3(b), vec3(c), show_ray(&r));
        let cause = "a triangle is degenerate when (b − a) × (c − a) = 0, its two edges from a parallel";
        expect_tri(&case, method(&r, a, b, c, ALL), 2.0, beta, gamma, TOL, cause)?;
    }
    // Misses: outside each edge, beyond the range, behind the origin.
    for (r, range, why) in [
        (down(0.6, 0.6), ALL, "β + γ = 1.2 > 1: outside"),
        (down(-0.1, 0.5), ALL, "β = −0.1 < 0: outside"),
        (down(0.5, -0.1), ALL, "γ = −0.1 < 0: outside"),
        (down(0.2, 0.2), Interval::new(0.0, 1.5), "t = 2 is beyond range.max = 1.5"),
        (ray([0.2, 0.2, -2.0], [0.0, 0.0, -1.0]), ALL, "t = −2 is behind the origin: outside the range"),
    ] {
        let got = method(&r, A, B, C, range);
        let case = format!(
            "triangle (0, 0, 0), (1, 0, 0), (0, 1, 0), {}, range ({}, {})",
            show_ray(&r),
            num(range.min),
            num(range.max)
        );
        ensure(got.is_none(), case, "None", show_tri(&got), why)?;
    }
    // Parallel rays (in the plane and above it) and a degenerate triangle: None.
    for z in [0.0, 1.0] {
        for d in [[1.0, 0.5, 0.0], [0.0, -1.0, 0.0], [-0.3, 0.7, 0.0]] {
            let r = ray([-1.0, 0.25, z], d);
            let got = method(&r, A, B, C, ALL);
            let case =
                format!("triangle (0, 0, 0), (1, 0, 0), (0, 1, 0), {} (parallel to its plane)", show_ray(&r));
            ensure(
                got.is_none(),
                case,
                "None",
                show_tri(&got),
                "a ray parallel to the plane (determinant 0) has no hit: return None, never divide by \
                    zero",
            )?;
        }
    }
    let r = down(0.5, 0.0);
    let got = method(&r, A, B, 2.0 * B, ALL);
    ensure(
        got.is_none(),
        format!("degenerate triangle (0, 0, 0), (1, 0, 0), (2, 0, 0), {}", show_ray(&r)),
        "None",
        show_tri(&got),
        "a degenerate triangle has no plane: return None",
    )?;
    Ok("9 hits, 5 misses, 6 parallel rays, a degenerate triangle".into())
}

pub(super) fn edge_cases(edge: EdgeFn) -> CheckResult {
    // e = p.x·q.y − p.y·q.x: (1, 2)·(3, 4) → 1·4 − 2·3 = −2; z plays no part.
    let (p, q) = (Vec3::new(1.0, 2.0, 5.0), Vec3::new(3.0, 4.0, -1.0));
    let got = edge(p, q);
    let cause = if got == 2.0 {
        "e = p.x·q.y − p.y·q.x (positive when the ray passes left of p→q), not the other way round"
    } else {
        "e = p.x·q.y − p.y·q.x: the z components play no part"
    };
    close("edge_function((1, 2, 5), (3, 4, −1))", got, -2.0, 0.0, cause)?;
    // Exactly antisymmetric on arbitrary values.
    let mut rng = Rng::new(17);
    for _ in 0..200 {
        let (p, q) = (rng.in_cube(3.0), rng.in_cube(3.0));
        let (pq, qp) = (edge(p, q), edge(q, p));
        let case = format!("edge_function({}, {}) and with p, q swapped", vec3(p), vec3(q));
        ensure(
            pq == -qp,
            case,
            "e(q, p) = −e(p, q) exactly",
            format!("{} and {}", num(pq), num(qp)),
            "e must be exactly antisymmetric: compute e(q, p) from the same two products, subtracted \
                the other way",
        )?;
    }
    // p.x·q.y = (1 + 2⁻¹²)² = 1 + 2⁻¹¹ + 2⁻²⁴ and p.y·q.x = 1 + 2⁻¹¹: exactly 2⁻²⁴. In f32 both
    // products round to 1 + 2⁻¹¹ (ties to even), so the plain difference is 0.
    let s: Float = 1.0 + (2.0 as Float).powi(-12);
    let (p, q) = (Vec3::new(s, 1.0 + (2.0 as Float).powi(-11), 0.0), Vec3::new(1.0, s, 0.0));
    let tiny = (2.0 as Float).powi(-24);
    let case = "edge_function((1 + 2⁻¹², 1 + 2⁻¹¹, 0), (1, 1 + 2⁻¹², 0)): exactly 2⁻²⁴";
    close(
        case,
        edge(p, q),
        tiny,
        0.0,
        "when the f32 difference rounds to exactly 0, recompute it in f64 (where both products are \
            exact) so the sign of a zero is decided exactly",
    )?;
    close(
        case,
        edge(q, p),
        -tiny,
        0.0,
        "when the f32 difference rounds to exactly 0, recompute it in f64 (where both products are \
            exact) so the sign of a zero is decided exactly",
    )?;
    Ok("a hand value, 200 antisymmetric pairs, a rounding tie".into())
}

/// Closed meshes with an origin inside, and the rays from it aimed exactly
/// at every vertex and at three points of every edge.
pub(super) fn leak_tests() -> Vec<(Mesh, Vec<Ray>)> {
    let mut rng = Rng::new(5);
    let mut meshes: Vec<(Mesh, Vec3)> =
        (0..60).map(|_| (wobbly_octahedron(&mut rng), rng.in_cube(0.05))).collect();
    meshes.push((Mesh::icosphere(2), Vec3::ZERO));
    meshes.push((Mesh::icosphere(2), Vec3::new(0.1, -0.2, 0.05)));
    meshes
        .into_iter()
        .map(|(mesh, origin)| {
            let rays = edge_and_vertex_rays(&mesh, origin);
            (mesh, rays)
        })
        .collect()
}

pub(super) const LEAK: &str = "a ray aimed exactly at a shared edge or vertex slipped between the triangles: \
    accept zero edge functions (all ≥ 0 or all ≤ 0), computed by edge_function from the translated, \
    permuted and sheared vertices, so neighbours see the ray on opposite sides of their edge";

pub(super) fn triangle_no_leaks(method: TriangleFn) -> CheckResult {
    let mut total = 0;
    for (mesh, rays) in leak_tests() {
        // Each vertex's triangles.
        let mut around: Vec<Vec<usize>> = vec![Vec::new(); mesh.positions.len()];
        for (t, corners) in mesh.triangles.iter().enumerate() {
            for &v in corners {
                around[v as usize].push(t);
            }
        }
        for r in &rays {
            total += 1;
            // First the triangles around the vertex nearest the aimed point (that vertex itself,
            // or for a point of an edge usually one of its ends, whose triangles hold the edge),
            // then the others: a watertight test hits one of the first at once, where asking all
            // 320 of an icosphere in turn took 0.77 s of a judged grade (each answer crosses to
            // the judge). A leak still asks every triangle: what is proved is the same, that some
            // triangle is hit.
            let target = r.origin + r.dir;
            let nearest = (0..mesh.positions.len())
                .min_by(|&i, &j| {
                    let d = |v: usize| mesh.positions[v].distance_squared(target);
                    d(i).total_cmp(&d(j))
                })
                .unwrap_or(0);
            let first = around.get(nearest).map(Vec::as_slice).unwrap_or_default();
            let mut order =
                first.iter().copied().chain((0..mesh.triangles.len()).filter(|t| !first.contains(t)));
            let hit = order.any(|i| {
                let [a, b, c] = mesh.triangle(i);
                method(r, a, b, c, ALL).is_some()
            });
            if !hit {
                let case = format!(
                    "a closed mesh of {} triangles around the origin, {} (aimed at a vertex or an edge)",
                    mesh.triangles.len(),
                    show_ray(r)
                );
                return Err(fail(case, "a hit on some triangle", "no triangle hit", LEAK));
            }
        }
    }
    Ok(format!("{total} edge and vertex rays, no leak"))
}

// ---- normals, hit records, meshes ---------------------------------------------

pub(super) fn interpolate_cases(interpolate: InterpolateFn) -> CheckResult {
    let normals = [Vec3::new(1.0, 0.0, 1.0), Vec3::new(0.0, 2.0, 2.0), Vec3::Z];
    let show_normals = "normals (1, 0, 1), (0, 2, 2), (0, 0, 1)";
    // At a vertex the blend is that vertex's normal, normalised.
    for (k, (beta, gamma)) in [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)].into_iter().enumerate() {
        let got = interpolate(&normals, beta, gamma);
        let case = format!("interpolate_normal({show_normals}, β = {beta}, γ = {gamma})");
        let others: Vec<Vec3> = (0..3).filter(|&j| j != k).map(|j| normals[j].normalize()).collect();
        let cause = if others.iter().any(|&n| near3(got, n, TOL)) {
            "n₀ takes the weight 1 − β − γ, n₁ takes β and n₂ takes γ"
        } else if near3(got, normals[k], TOL) && normals[k].length() != 1.0 {
            "normalise the blend"
        } else {
            "(1 − β − γ)n₀ + βn₁ + γn₂, normalised"
        };
        close3(&case, got, normals[k].normalize(), TOL, cause)?;
    }
    // Midpoint of the first edge: (1, 0, 1)/2 + (0, 2, 2)/2 = (0.5, 1, 1.5), over √3.5.
    let got = interpolate(&normals, 0.5, 0.0);
    let expected = Vec3::new(0.5, 1.0, 1.5) / (3.5 as Float).sqrt();
    let cause = if near3(got, Vec3::new(0.5, 1.0, 1.5), TOL) {
        "normalise the blend"
    } else {
        "(1 − β − γ)n₀ + βn₁ + γn₂, normalised"
    };
    close3(format!("interpolate_normal({show_normals}, β = 0.5, γ = 0)"), got, expected, TOL, cause)?;
    // Opposite normals cancel: zero, not NaN.
    let got = interpolate(&[Vec3::Z, -Vec3::Z, Vec3::Z], 0.5, 0.0);
    close3(
        "interpolate_normal(normals +z, −z, +z, β = 0.5, γ = 0): the blend cancels",
        got,
        Vec3::ZERO,
        0.0,
        "where the blend is zero return the zero vector (normalize_or_zero), never NaN",
    )?;
    Ok("3 vertices, a midpoint, a cancelling blend".into())
}

pub(super) fn hit_triangle_cases(hit_triangle: HitTriangleFn) -> CheckResult {
    let tri = [A, B, C];
    let name = "triangle (0, 0, 0), (1, 0, 0), (0, 1, 0)";
    // From above at (0.25, 0.25): t = 2, normal +z (front), uv = (β, γ) = (0.25, 0.25).
    let down = ray([0.25, 0.25, 2.0], [0.0, 0.0, -1.0]);
    let case = format!("{name}, {}", show_ray(&down));
    let got = hit_triangle(&down, &tri, None, ALL);
    let Some(h) = got else {
        return Err(fail(case, "t = 2", show_hit(&got), "the watertight test finds this hit"));
    };
    close(&case, h.t, 2.0, TOL, "t of the watertight test")?;
    close3(&case, h.point, Vec3::new(0.25, 0.25, 0.0), TOL, "the point is ray.at(t)")?;
    let cause = if !h.front_face {
        "the outward normal is (b − a) × (c − a): the front is the side from which a, b, c run \
            counter-clockwise"
    } else {
        "the geometric normal (b − a) × (c − a), normalised and faced by Hit::new"
    };
    close3(&case, h.normal, Vec3::Z, TOL, cause)?;
    ensure(h.front_face, &case, "front_face true", "false", cause)?;
    let uv = Vec3::new(h.uv.x, h.uv.y, 0.0);
    close3(&case, uv, Vec3::new(0.25, 0.25, 0.0), TOL, "uv = (β, γ) of the triangle hit (Hit::with_uv)")?;
    // From below: the normal turned toward the ray, front_face false.
    let up = ray([0.25, 0.25, -2.0], [0.0, 0.0, 1.0]);
    let case = format!("{name}, {} (from behind)", show_ray(&up));
    let got = hit_triangle(&up, &tri, None, ALL);
    let Some(h) = got else { return Err(fail(case, "t = 2", show_hit(&got), "the test is two-sided")) };
    close3(
        &case,
        h.normal,
        -Vec3::Z,
        TOL,
        "from behind the normal faces the ray: build the hit with Hit::new(ray, t, (b − a) × (c − a))",
    )?;
    ensure(!h.front_face, &case, "front_face false", "true", "from behind the ray meets the back face")?;
    // Vertex normals tilted from +z: the blend 0.5n₀ + 0.25n₁ + 0.25n₂ = (0.25, 0.25, 1), normalised.
    let normals = [Vec3::Z, Vec3::new(1.0, 0.0, 1.0), Vec3::new(0.0, 1.0, 1.0)];
    let blended = Vec3::new(0.25, 0.25, 1.0).normalize();
    let case = format!("{name} with vertex normals (0, 0, 1), (1, 0, 1), (0, 1, 1), {}", show_ray(&down));
    let got = hit_triangle(&down, &tri, Some(&normals), ALL);
    close3(
        &case,
        got.map_or(Vec3::NAN, |h| h.normal),
        blended,
        TOL,
        "with vertex normals the hit's normal is interpolate_normal at (β, γ)",
    )?;
    let case = format!(
        "{name} with vertex normals (0, 0, 1), (1, 0, 1), (0, 1, 1), {} (from behind)",
        show_ray(&up)
    );
    let got = hit_triangle(&up, &tri, Some(&normals), ALL);
    let n = got.map_or(Vec3::NAN, |h| h.normal);
    let cause = if near3(n, blended, TOL) {
        "turn the interpolated normal to the side of the geometric normal that faces the ray"
    } else {
        "the interpolated normal, turned toward the ray"
    };
    close3(&case, n, -blended, TOL, cause)?;
    // Cancelling vertex normals: the geometric normal stays.
    let cancel = [Vec3::Z, -Vec3::Z, Vec3::Z];
    let r = ray([0.5, 0.0, 2.0], [0.0, 0.0, -1.0]);
    let case =
        format!("{name} with vertex normals +z, −z, +z, {} (the blend cancels at β = 0.5)", show_ray(&r));
    let got = hit_triangle(&r, &tri, Some(&cancel), ALL);
    close3(
        &case,
        got.map_or(Vec3::NAN, |h| h.normal),
        Vec3::Z,
        TOL,
        "where the blend vanishes keep the geometric normal (never a zero or NaN normal)",
    )?;
    // A miss.
    let r = ray([0.6, 0.6, 2.0], [0.0, 0.0, -1.0]);
    let got = hit_triangle(&r, &tri, None, ALL);
    ensure(
        got.is_none(),
        format!("{name}, {}", show_ray(&r)),
        "None",
        show_hit(&got),
        "β + γ = 1.2 > 1: no hit",
    )?;
    Ok("front, back, shading normals both ways, a cancelling blend, a miss".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l03_polygons_triangles::dominant_axis;

    #[test]
    fn triangle_mistakes() {
        // One-sided Möller–Trumbore (back faces culled).
        caught(
            triangle_cases(|r, a, b, c, i| {
                let det = (b - a).dot(r.dir.cross(c - a));
                if det < 0.0 { None } else { hit_triangle_moller_trumbore(r, a, b, c, i) }
            }),
            "two-sided",
        );
        // β and γ swapped.
        caught(
            triangle_cases(|r, a, b, c, i| {
                hit_triangle_watertight(r, a, b, c, i).map(|h| TriangleHit {
                    beta: h.gamma,
                    gamma: h.beta,
                    ..h
                })
            }),
            "β weights b",
        );
        // Strict inequalities: edges and vertices excluded.
        caught(
            triangle_cases(|r, a, b, c, i| {
                hit_triangle_watertight(r, a, b, c, i)
                    .filter(|h| h.beta > 0.0 && h.gamma > 0.0 && h.beta + h.gamma < 1.0)
            }),
            "belong to the triangle",
        );
        // The watertight test with zero edge functions rejected (the catalogue's patch).
        caught(triangle_cases(|r, a, b, c, i| watertight(r, a, b, c, i, true)), "belong to the triangle");
        caught(triangle_no_leaks(|r, a, b, c, i| watertight(r, a, b, c, i, true)), "slipped between");
        // Möller–Trumbore is not watertight.
        caught(triangle_no_leaks(hit_triangle_moller_trumbore), "slipped between");
    }

    /// The reference watertight test; `strict` rejects zero edge functions.
    fn watertight(
        ray: &Ray,
        a: Vec3,
        b: Vec3,
        c: Vec3,
        range: Interval,
        strict: bool,
    ) -> Option<TriangleHit> {
        if (c - a).cross(b - a).length_squared() == 0.0 {
            return None;
        }
        let kz = dominant_axis(ray.dir);
        let (kx, ky) = ((kz + 1) % 3, (kz + 2) % 3);
        let permute = |v: Vec3| Vec3::new(v[kx], v[ky], v[kz]);
        let d = permute(ray.dir);
        let (sx, sy, sz) = (-d.x / d.z, -d.y / d.z, 1.0 / d.z);
        let shear = |p: Vec3| {
            let p = permute(p - ray.origin);
            Vec3::new(p.x + sx * p.z, p.y + sy * p.z, p.z * sz)
        };
        let (p0, p1, p2) = (shear(a), shear(b), shear(c));
        let (e0, e1, e2) = (edge_function(p1, p2), edge_function(p2, p0), edge_function(p0, p1));
        let outside = if strict {
            !((e0 > 0.0 && e1 > 0.0 && e2 > 0.0) || (e0 < 0.0 && e1 < 0.0 && e2 < 0.0))
        } else {
            (e0 < 0.0 || e1 < 0.0 || e2 < 0.0) && (e0 > 0.0 || e1 > 0.0 || e2 > 0.0)
        };
        let det = e0 + e1 + e2;
        if outside || det == 0.0 {
            return None;
        }
        let t = (e0 * p0.z + e1 * p1.z + e2 * p2.z) / det;
        range.contains(t).then_some(TriangleHit { t, beta: e1 / det, gamma: e2 / det })
    }

    #[test]
    fn planted_watertight_copy_is_faithful() {
        assert!(triangle_cases(|r, a, b, c, i| watertight(r, a, b, c, i, false)).is_ok());
        assert!(triangle_no_leaks(|r, a, b, c, i| watertight(r, a, b, c, i, false)).is_ok());
    }

    #[test]
    fn edge_function_mistakes() {
        caught(edge_cases(|p, q| p.y * q.x - p.x * q.y), "not the other way round");
        caught(edge_cases(|p, q| p.x.mul_add(q.y, -(p.y * q.x))), "antisymmetric");
        // Without the f64 fallback a tie rounds to 0 in f32 (f64 needs none: the products are exact).
        if Float::EPSILON > 1e-10 {
            caught(edge_cases(|p, q| p.x * q.y - p.y * q.x), "recompute it in f64");
        }
    }

    #[test]
    fn interpolate_mistakes() {
        caught(
            interpolate_cases(|n, b, g| ((1.0 - b - g) * n[1] + b * n[2] + g * n[0]).normalize_or_zero()),
            "n₀ takes",
        );
        caught(
            interpolate_cases(|n, b, g| (1.0 - b - g) * n[0] + b * n[1] + g * n[2]),
            "normalise the blend",
        );
        caught(
            interpolate_cases(|n, b, g| ((1.0 - b - g) * n[0] + b * n[1] + g * n[2]).normalize()),
            "never NaN",
        );
    }

    /// hit_triangle with one planted mistake.
    #[derive(Clone, Copy, PartialEq, Eq)]
    enum HitTriangleMistake {
        /// The interpolated shading normal is not turned to the geometric normal's side.
        ShadingNotTurned,
        /// The geometric normal from a clockwise cross product.
        Clockwise,
        /// No uv in the hit record.
        NoUv,
        /// The outward normal, not faced against the ray.
        Unfaced,
    }

    fn planted_hit_triangle(
        ray: &Ray,
        v: &[Vec3; 3],
        normals: Option<&[Vec3; 3]>,
        range: Interval,
        mistake: HitTriangleMistake,
    ) -> Option<Hit> {
        let [a, b, c] = *v;
        let found = hit_triangle_watertight(ray, a, b, c, range)?;
        let geometric = if mistake == HitTriangleMistake::Clockwise {
            (c - a).cross(b - a)
        } else {
            (b - a).cross(c - a)
        }
        .try_normalize()?;
        let mut hit = Hit::new(ray, found.t, geometric);
        if mistake != HitTriangleMistake::NoUv {
            hit = hit.with_uv(Vec2::new(found.beta, found.gamma));
        }
        if mistake == HitTriangleMistake::Unfaced {
            hit.normal = geometric;
        }
        let Some(normals) = normals else { return Some(hit) };
        let shading = interpolate_normal(normals, found.beta, found.gamma);
        if shading == Vec3::ZERO {
            return Some(hit);
        }
        let normal = if mistake != HitTriangleMistake::ShadingNotTurned && shading.dot(hit.normal) < 0.0 {
            -shading
        } else {
            shading
        };
        Some(Hit { normal, ..hit })
    }

    #[test]
    fn hit_triangle_mistakes() {
        caught(
            hit_triangle_cases(|r, v, n, i| {
                planted_hit_triangle(r, v, n, i, HitTriangleMistake::ShadingNotTurned)
            }),
            "turn the interpolated normal",
        );
        caught(
            hit_triangle_cases(|r, v, n, i| planted_hit_triangle(r, v, n, i, HitTriangleMistake::Clockwise)),
            "counter-clockwise",
        );
        caught(
            hit_triangle_cases(|r, v, n, i| planted_hit_triangle(r, v, n, i, HitTriangleMistake::NoUv)),
            "uv = (β, γ)",
        );
        caught(
            hit_triangle_cases(|r, v, n, i| planted_hit_triangle(r, v, n, i, HitTriangleMistake::Unfaced)),
            "Hit::new",
        );
    }
}
