//! The checks of `mesh.rs`: hit_mesh.

use super::common::*;
use super::triangle::{LEAK, leak_tests};

pub(super) fn mesh_no_leaks(hit_mesh: MeshFn) -> CheckResult {
    let mut total = 0;
    for (mesh, rays) in leak_tests() {
        for r in &rays {
            total += 1;
            let got = hit_mesh(r, &mesh, ALL);
            let case = lazy(|f| {
                let n = mesh.triangles.len();
                write!(
                    f,
                    "a closed mesh of {n} triangles around the origin, {} (aimed at a vertex or an edge)",
                    show_ray(r)
                )
            });
            let Some(h) = got else { return Err(fail(case, "a hit", "None (no hit)", LEAK)) };
            ensure(
                h.t.is_finite() && h.t > 0.0 && h.normal.is_finite(),
                case,
                "a finite hit",
                lazy(|f| f.write_str(&show_hit(&got))),
                "no NaN may escape a hit",
            )?;
        }
    }
    Ok(format!("{total} edge and vertex rays, no leak"))
}

/// How far a mesh hit's uv may be from the exact one, each component. The hit's β and γ are
/// within TOL of exact (as the triangle checks hold them); the blend moves by their errors
/// times corner differences ≤ 2 (uv = 2·(x, y) + (1, 3) over the unit square), 4·TOL at most,
/// and rounds a few products and sums of numbers ≤ 6, under 2·TOL more (the reference's worst
/// over 20,000 points: 5ε in f32, 4ε in f64). A wrong weight, 1 − β + γ or two corners'
/// weights swapped, moves the uv by 0.2 or more at one of the points tested at least.
const UV_TOL: Float = 6.0 * TOL;

/// The unit square in z = 0 as triangles (0, 1, 2) and (0, 2, 3), counter-clockwise from +z.
pub(super) fn quad() -> Mesh {
    Mesh {
        positions: vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y],
        triangles: vec![[0, 1, 2], [0, 2, 3]],
        ..Mesh::default()
    }
}

pub(super) fn mesh_cases(hit_mesh: MeshFn) -> CheckResult {
    let down = |x: Float, y: Float| ray([x, y, 2.0], [0.0, 0.0, -1.0]);
    let mesh = quad();
    let name = "the unit square as triangles (0, 1, 2), (0, 2, 3)";
    // (0.75, 0.25) is in (0, x̂, x̂ + ŷ): p = (β + γ, γ), so β = 0.5, γ = 0.25.
    for (x, y, uv) in [(0.75, 0.25, Vec2::new(0.5, 0.25)), (0.25, 0.75, Vec2::new(0.25, 0.5))] {
        let r = down(x, y);
        let case = format!("{name}, {}", show_ray(&r));
        let got = hit_mesh(&r, &mesh, ALL);
        let Some(h) = got else {
            return Err(fail(case, "t = 2", show_hit(&got), "test every triangle with hit_triangle"));
        };
        close(&case, h.t, 2.0, TOL, "the triangle's t")?;
        close3(
            &case,
            h.normal,
            Vec3::Z,
            TOL,
            "a mesh without normals keeps the triangle's geometric normal",
        )?;
        close3(
            &case,
            Vec3::new(h.uv.x, h.uv.y, 0.0),
            uv.extend(0.0),
            TOL,
            "without mesh uvs the hit's uv is the triangle's (β, γ)",
        )?;
    }
    for (r, m, why) in [
        (down(1.5, 0.5), quad(), "beside the square: no hit"),
        (down(0.5, 0.5), Mesh::default(), "an empty mesh is never hit"),
    ] {
        let got = hit_mesh(&r, &m, ALL);
        ensure(got.is_none(), format!("{name}, {}", show_ray(&r)), "None", show_hit(&got), why)?;
    }
    // Two layers, z = 0 and z = −1, in both orders: the nearer one (t = 2 from above) wins.
    let near_layer = quad();
    for far_first in [true, false] {
        let far: Vec<Vec3> = near_layer.positions.iter().map(|p| *p - Vec3::Z).collect();
        let (first, second) =
            if far_first { (far, near_layer.positions.clone()) } else { (near_layer.positions.clone(), far) };
        let layers = Mesh {
            positions: first.into_iter().chain(second).collect(),
            triangles: vec![[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7]],
            ..Mesh::default()
        };
        let r = down(0.3, 0.6);
        let order = if far_first { "the far layer listed first" } else { "the near layer listed first" };
        let case = format!("squares at z = 0 and z = −1 ({order}), {}", show_ray(&r));
        let got = hit_mesh(&r, &layers, ALL);
        close(
            &case,
            got.map_or(Float::NAN, |h| h.t),
            2.0,
            TOL,
            "keep the closest hit: shrink range.max to each hit's t and test every triangle",
        )?;
    }
    // Mesh uvs 2·(x, y) + (1, 3): an affine function of the position, which the blend
    // (1 − β − γ)uv_a + β·uv_b + γ·uv_c reproduces, so the hit at (x, y) has uv 2·(x, y) + (1, 3)
    // whichever triangle it is in (computed in f64 from the ray's origin). No corner's uv is
    // zero and, but at (0.75, 0.25), the three weights differ, so a wrong weight, or one paired
    // with the wrong corner, shows. By hand: (0.875, 0.25) is in (0, x̂, x̂ + ŷ) with weights
    // (1 − x, x − y, y) = (0.125, 0.625, 0.25) of (1, 3), (3, 3), (3, 5): uv (2.75, 3.5);
    // (0.125, 0.75) is in (0, x̂ + ŷ, ŷ) with weights (1 − y, x, y − x) = (0.25, 0.125, 0.625)
    // of (1, 3), (3, 5), (1, 5): uv (1.25, 4.5). Normals (x, 0, 1)/|…| per vertex.
    let mut textured = quad();
    textured.uvs = textured.positions.iter().map(|p| 2.0 * p.truncate() + Vec2::new(1.0, 3.0)).collect();
    textured.normals = textured.positions.iter().map(|p| Vec3::new(p.x, 0.0, 1.0).normalize()).collect();
    let points = [(0.75, 0.25), (0.875, 0.25), (0.125, 0.75), (0.7, 0.2), (0.3, 0.9)];
    for (k, (x, y)) in points.into_iter().enumerate() {
        let r = down(x, y);
        let case =
            format!("{name} with uvs 2·(x, y) + (1, 3) and normals (x, 0, 1) normalised, {}", show_ray(&r));
        let got = hit_mesh(&r, &textured, ALL);
        let Some(h) = got else { return Err(fail(case, "a hit", show_hit(&got), "test every triangle")) };
        let (x, y) = (r.origin.x as f64, r.origin.y as f64);
        let uv = [2.0 * x + 1.0, 2.0 * y + 3.0];
        let ok =
            (h.uv.x as f64 - uv[0]).abs() <= UV_TOL as f64 && (h.uv.y as f64 - uv[1]).abs() <= UV_TOL as f64;
        // The triangle's own (β, γ) at (x, y), to tell mesh uvs ignored from mesh uvs mixed wrongly.
        let (beta, gamma) = if x >= y { (x - y, y) } else { (x, y - x) };
        let ignored =
            (h.uv.x as f64 - beta).abs() <= UV_TOL as f64 && (h.uv.y as f64 - gamma).abs() <= UV_TOL as f64;
        ensure(
            ok,
            format!("{case}: the hit's uv"),
            format!("({}, {}) (± {UV_TOL:.1e} each)", num(uv[0] as Float), num(uv[1] as Float)),
            format!("({}, {})", num(h.uv.x), num(h.uv.y)),
            if ignored {
                "with mesh uvs, uv = (1 − β − γ)uv_a + β·uv_b + γ·uv_c, not the triangle's (β, γ)"
            } else {
                "with mesh uvs, uv = (1 − β − γ)uv_a + β·uv_b + γ·uv_c: weights that sum to 1, each with \
                    its own corner of the triangle hit"
            },
        )?;
        if k == 0 {
            // Normal at (0.75, 0.25): 0.25·ẑ + 0.75·(1, 0, 1)/√2, normalised.
            let expected = (0.25 * Vec3::Z + 0.75 * Vec3::new(1.0, 0.0, 1.0).normalize()).normalize();
            close3(
                &case,
                h.normal,
                expected,
                TOL,
                "with mesh normals, pass the triangle's three vertex normals to hit_triangle",
            )?;
        }
    }
    Ok("2 hits, 2 misses, layers in both orders, mesh uvs at 5 points on both triangles, mesh normals".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    /// hit_mesh as written, or with one planted mistake.
    #[derive(Clone, Copy, PartialEq, Eq)]
    enum MeshMistake {
        Faithful,
        /// The range never shrinks: the last hit in the list wins, not the closest.
        RangeNeverShrinks,
        /// The mesh's uvs ignored: the triangle's (β, γ) stays.
        MeshUvsIgnored,
        /// The mesh's vertex normals ignored.
        MeshNormalsIgnored,
        /// The first corner's uv weighted by 1 − β + γ (the weights no longer sum to 1).
        UvFirstWeightPlusGamma,
        /// The weights of the first and third corners' uvs swapped: γ·uv_a + β·uv_b + (1 − β − γ)·uv_c.
        UvWeightsOfAAndCSwapped,
    }

    fn planted_mesh(ray: &Ray, mesh: &Mesh, range: Interval, mistake: MeshMistake) -> Option<Hit> {
        let mut closest: Option<(Hit, [usize; 3])> = None;
        let mut range = range;
        for triangle in &mesh.triangles {
            let corners = triangle.map(|i| i as usize);
            let vertices = corners.map(|i| mesh.positions[i]);
            let normals = (mistake != MeshMistake::MeshNormalsIgnored && !mesh.normals.is_empty())
                .then(|| corners.map(|i| mesh.normals[i]));
            if let Some(hit) = hit_triangle(ray, &vertices, normals.as_ref(), range) {
                if mistake != MeshMistake::RangeNeverShrinks {
                    range = range.with_max(hit.t);
                }
                closest = Some((hit, corners));
            }
        }
        let (hit, [a, b, c]) = closest?;
        if mistake == MeshMistake::MeshUvsIgnored || mesh.uvs.is_empty() {
            return Some(hit);
        }
        let (beta, gamma) = (hit.uv.x, hit.uv.y);
        let (uv_a, uv_b, uv_c) = (mesh.uvs[a], mesh.uvs[b], mesh.uvs[c]);
        Some(hit.with_uv(match mistake {
            MeshMistake::UvFirstWeightPlusGamma => (1.0 - beta + gamma) * uv_a + beta * uv_b + gamma * uv_c,
            MeshMistake::UvWeightsOfAAndCSwapped => gamma * uv_a + beta * uv_b + (1.0 - beta - gamma) * uv_c,
            _ => (1.0 - beta - gamma) * uv_a + beta * uv_b + gamma * uv_c,
        }))
    }

    #[test]
    fn mesh_mistakes() {
        assert!(mesh_cases(|r, m, i| planted_mesh(r, m, i, MeshMistake::Faithful)).is_ok());
        caught(
            mesh_cases(|r, m, i| planted_mesh(r, m, i, MeshMistake::RangeNeverShrinks)),
            "keep the closest hit",
        );
        caught(mesh_cases(|r, m, i| planted_mesh(r, m, i, MeshMistake::MeshUvsIgnored)), "with mesh uvs");
        caught(
            mesh_cases(|r, m, i| planted_mesh(r, m, i, MeshMistake::MeshNormalsIgnored)),
            "with mesh normals",
        );
        // A mesh of Möller–Trumbore triangles leaks.
        caught(
            mesh_no_leaks(|r, m, i| {
                (0..m.triangles.len())
                    .filter_map(|k| {
                        let [a, b, c] = m.triangle(k);
                        hit_triangle_moller_trumbore(r, a, b, c, i)
                            .map(|h| Hit::new(r, h.t, (b - a).cross(c - a)))
                    })
                    .min_by(|x, y| x.t.total_cmp(&y.t))
            }),
            "slipped between",
        );
    }

    #[test]
    fn mesh_uv_with_a_wrong_corner_weight_is_caught() {
        let formula = "uv = (1 − β − γ)uv_a + β·uv_b + γ·uv_c";
        caught(mesh_cases(|r, m, i| planted_mesh(r, m, i, MeshMistake::UvFirstWeightPlusGamma)), formula);
        caught(mesh_cases(|r, m, i| planted_mesh(r, m, i, MeshMistake::UvWeightsOfAAndCSwapped)), formula);
    }
}
