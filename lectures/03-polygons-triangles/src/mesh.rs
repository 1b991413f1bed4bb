//! Triangle meshes, by brute force (lecture 09 replaces the loop by a BVH).
//!
//! In a scene file: `{ type = "mesh", file = "bunny.obj" }`, or the kit's
//! generated `{ type = "icosphere", subdivisions = 2 }` and
//! `{ type = "torus", major = 1, minor = 0.25 }`.

use raylab::scene::Mesh;
use raylab::stats::{Counter, count_n};
use raylab::{Hit, Interval, Ray, Vec2};

use crate::triangle::{hit_triangle, hit_triangle_watertight};

/// The closest hit of `ray` with any triangle of `mesh` inside `range`.
///
/// Tests every triangle by the watertight test ([`hit_triangle_watertight`],
/// so the closed meshes never leak), shrinking the range to the closest hit
/// so far, and makes the hit record of the closest triangle alone, with
/// [`hit_triangle`]: a ray crosses several triangles on its way, and the
/// normals of those a closer one hides are never needed (calling
/// [`hit_triangle`] on every triangle gives the same hits, about twice as
/// slowly on the lecture's meshes). Normals are interpolated from
/// `mesh.normals` when the mesh has them (else the triangle's geometric
/// normal); uv is interpolated from `mesh.uvs`,
/// (1 − β − γ)uv_a + β·uv_b + γ·uv_c, when present, else it is (β, γ) of the
/// triangle hit. Counts one intersection test per triangle.
///
/// `mesh` must be well formed, as the kit's loaders and generators make it:
/// indices inside `positions`, `normals` and `uvs` empty or one per position.
/// Book: §3.11 Meshes by brute force.
pub fn hit_mesh(ray: &Ray, mesh: &Mesh, range: Interval) -> Option<Hit> {
    count_n(Counter::IntersectionTests, mesh.triangles.len() as u64);
    // SOLUTION BEGIN
    // The closest triangle by the watertight test alone, the range shrinking to it; its hit
    // record (normals, uv) is made once, for the closest, not for every triangle hit on the
    // way. A triangle whose normal overflows is skipped, as `hit_triangle` skips it.
    let mut closest: Option<[usize; 3]> = None;
    let mut shrinking = range;
    for triangle in &mesh.triangles {
        let [a, b, c] = [triangle[0] as usize, triangle[1] as usize, triangle[2] as usize];
        let (pa, pb, pc) = (mesh.positions[a], mesh.positions[b], mesh.positions[c]);
        if let Some(found) = hit_triangle_watertight(ray, pa, pb, pc, shrinking)
            && (pb - pa).cross(pc - pa).try_normalize().is_some()
        {
            shrinking = shrinking.with_max(found.t);
            closest = Some([a, b, c]);
        }
    }
    let [a, b, c] = closest?;
    let vertices = [mesh.positions[a], mesh.positions[b], mesh.positions[c]];
    let normals = (!mesh.normals.is_empty()).then(|| [mesh.normals[a], mesh.normals[b], mesh.normals[c]]);
    // The same test again, in the caller's range (which holds its t): the same hit.
    let hit = hit_triangle(ray, &vertices, normals.as_ref(), range)?;

    // The texture coordinates from the mesh's, when it has them (else the triangle's (β, γ)).
    if !mesh.uvs.is_empty() {
        let (beta, gamma) = (hit.uv.x, hit.uv.y);
        let uv: Vec2 = (1.0 - beta - gamma) * mesh.uvs[a] + beta * mesh.uvs[b] + gamma * mesh.uvs[c];
        return Some(hit.with_uv(uv));
    }
    Some(hit)
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use raylab::stats::measure;
    use raylab::{Float, Vec3};

    /// The unit square in z = 0 as two triangles (0, 1, 2) and (0, 2, 3),
    /// counter-clockwise from +z.
    fn quad() -> Mesh {
        Mesh {
            positions: vec![Vec3::ZERO, Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Y],
            triangles: vec![[0, 1, 2], [0, 2, 3]],
            ..Mesh::default()
        }
    }

    fn down_at(x: Float, y: Float) -> Ray {
        Ray::new(Vec3::new(x, y, 2.0), -Vec3::Z)
    }

    #[test]
    fn quad_of_two_triangles_is_hit_on_both_halves() {
        let mesh = quad();
        // (0.75, 0.25) is in (a, b, c) = (0, x̂, x̂ + ŷ): p = (β + γ, γ), so γ = 0.25, β = 0.5.
        let (hit, stats) = measure(|| hit_mesh(&down_at(0.75, 0.25), &mesh, Interval::POSITIVE));
        let hit = hit.unwrap();
        assert_eq!((hit.t, hit.normal, hit.uv), (2.0, Vec3::Z, Vec2::new(0.5, 0.25)));
        assert_eq!(stats.get(Counter::IntersectionTests), 2);
        // (0.25, 0.75) is in (0, x̂ + ŷ, ŷ): p = (β, β + γ), so β = 0.25, γ = 0.5.
        let hit = hit_mesh(&down_at(0.25, 0.75), &mesh, Interval::POSITIVE).unwrap();
        assert_eq!(hit.uv, Vec2::new(0.25, 0.5));
        // On the diagonal, and beside the quad.
        assert!(hit_mesh(&down_at(0.5, 0.5), &mesh, Interval::POSITIVE).is_some());
        assert!(hit_mesh(&down_at(1.5, 0.5), &mesh, Interval::POSITIVE).is_none());
        assert!(hit_mesh(&down_at(0.5, 0.5), &Mesh::default(), Interval::POSITIVE).is_none());
    }

    #[test]
    fn mesh_uvs_and_normals_are_interpolated() {
        // uv = 2·(x, y) + (1, 3) at each vertex, an affine function of the position, so the
        // interpolated uv at (x, y) is 2·(x, y) + (1, 3) on either triangle (exact for these
        // dyadic values). The points' weights (1 − β − γ, β, γ) differ, and no corner's uv is
        // zero, so each weight must go with its own corner.
        let mut mesh = quad();
        mesh.uvs = mesh.positions.iter().map(|p| 2.0 * p.truncate() + Vec2::new(1.0, 3.0)).collect();
        // (0.875, 0.25) in (0, x̂, x̂ + ŷ): weights (0.125, 0.625, 0.25) of (1, 3), (3, 3), (3, 5).
        let hit = hit_mesh(&down_at(0.875, 0.25), &mesh, Interval::POSITIVE).unwrap();
        assert_eq!(hit.uv, Vec2::new(2.75, 3.5));
        // (0.125, 0.75) in (0, x̂ + ŷ, ŷ): weights (0.25, 0.125, 0.625) of (1, 3), (3, 5), (1, 5).
        let hit = hit_mesh(&down_at(0.125, 0.75), &mesh, Interval::POSITIVE).unwrap();
        assert_eq!(hit.uv, Vec2::new(1.25, 4.5));
        // Normals tilting toward +x on the right side: n = (x, 0, 1) normalised per vertex.
        mesh.normals = mesh.positions.iter().map(|p| Vec3::new(p.x, 0.0, 1.0).normalize()).collect();
        let hit = hit_mesh(&down_at(0.75, 0.25), &mesh, Interval::POSITIVE).unwrap();
        assert_eq!(hit.uv, Vec2::new(2.5, 3.5));
        // Blend with weights (1 − β − γ, β, γ) = (0.25, 0.5, 0.25) of n₀ = ẑ and
        // n₁ = n₂ = (1, 0, 1)/√2, normalised.
        let (n0, n1) = (Vec3::Z, Vec3::new(1.0, 0.0, 1.0).normalize());
        let expected = (0.25 * n0 + 0.75 * n1).normalize();
        assert_relative_eq!(hit.normal, expected, max_relative = 4.0 * Float::EPSILON);
    }

    #[test]
    fn closest_of_stacked_layers_wins() {
        // Two copies of the quad, at z = 0 and z = −1, listed far one first.
        let near = quad();
        let mut mesh = near.clone();
        mesh.positions =
            near.positions.iter().map(|p| *p - Vec3::Z).chain(near.positions.iter().copied()).collect();
        mesh.triangles = vec![[0, 1, 2], [0, 2, 3], [4, 5, 6], [4, 6, 7]];
        let hit = hit_mesh(&down_at(0.3, 0.6), &mesh, Interval::POSITIVE).unwrap();
        assert_eq!(hit.t, 2.0);
        // Below both, looking up: the z = −1 layer is first (t = 1), seen from its back.
        let up = Ray::new(Vec3::new(0.3, 0.6, -2.0), Vec3::Z);
        let hit = hit_mesh(&up, &mesh, Interval::POSITIVE).unwrap();
        assert_eq!((hit.t, hit.front_face), (1.0, false));
    }

    #[test]
    fn icosphere_is_hit_near_the_unit_sphere() {
        // Rays through the centre of the unit icosphere hit it where the sphere is,
        // within the chord error of its flat faces: subdivision 2 has edges of
        // about 0.3, so the faces lie within 1 − cos(0.15) ≈ 0.012 of the sphere.
        let sphere = Mesh::icosphere(2);
        for dir in [Vec3::X, -Vec3::Y, Vec3::new(0.3, -0.5, 0.8).normalize()] {
            let hit = hit_mesh(&Ray::new(-3.0 * dir, dir), &sphere, Interval::POSITIVE).unwrap();
            assert!((hit.t - 2.0).abs() < 0.02, "t = {}", hit.t);
            assert!(hit.front_face && hit.normal.dot(dir) < 0.0);
        }
    }
}
