//! A closed mesh with no edge on nice coordinates, and the rays that find a
//! leak in a closed mesh: lecture 03's watertightness tests and checks,
//! lecture 09's shared-edge tests and checks, and the triangle trade-offs.

use raylab::random::Rng;
use raylab::scene::Mesh;
use raylab::{Ray, Vec3};

/// The octahedron |x| + |y| + |z| = 1 with each vertex scaled by 0.8–1.2 and
/// moved by up to 0.1 (so no edge lies on nice coordinates): 6 vertices, 8
/// faces wound counter-clockwise seen from outside, every edge shared by two
/// faces that share its vertices, so the mesh is closed.
pub fn wobbly_octahedron(rng: &mut Rng) -> Mesh {
    let axes = [Vec3::X, -Vec3::X, Vec3::Y, -Vec3::Y, Vec3::Z, -Vec3::Z];
    let positions = axes.iter().map(|&v| v * rng.range(0.8, 1.2) + rng.in_cube(0.1)).collect();
    let mut triangles = Vec::new();
    for (x, y, z) in [(0, 2, 4), (1, 2, 4), (0, 3, 4), (1, 3, 4), (0, 2, 5), (1, 2, 5), (0, 3, 5), (1, 3, 5)]
    {
        // (x̂, ŷ, ẑ) is counter-clockwise seen from (1, 1, 1); each negated axis reverses it.
        let flips = (x % 2) + (y % 2) + (z % 2);
        triangles.push(if flips % 2 == 0 { [x, y, z] } else { [x, z, y] });
    }
    Mesh { positions, triangles, ..Mesh::default() }
}

/// The points a leak would show at: every vertex, then three points of every
/// edge (fractions 0.5, 0.1 and 0.7 of the way), each edge once.
pub fn edge_and_vertex_targets(mesh: &Mesh) -> Vec<Vec3> {
    let mut targets = mesh.positions.clone();
    for triangle in &mesh.triangles {
        for k in 0..3 {
            let (i, j) = (triangle[k], triangle[(k + 1) % 3]);
            // Each edge once: it appears as i→j in one face and j→i in the other.
            if i < j {
                let (p, q) = (mesh.positions[i as usize], mesh.positions[j as usize]);
                targets.extend([0.5, 0.1, 0.7].map(|s| p.lerp(q, s)));
            }
        }
    }
    targets
}

/// Rays from `origin` (inside the mesh) toward every vertex and toward three
/// points of every edge ([`edge_and_vertex_targets`]).
pub fn edge_and_vertex_rays(mesh: &Mesh, origin: Vec3) -> Vec<Ray> {
    edge_and_vertex_targets(mesh).into_iter().map(|p| Ray::new(origin, p - origin)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_octahedron_is_closed_and_its_rays_cover_every_edge() {
        let mesh = wobbly_octahedron(&mut Rng::new(1));
        assert_eq!((mesh.positions.len(), mesh.triangles.len()), (6, 8));
        // Closed: each of the 12 edges in one face as i→j and in another as j→i.
        let mut directed: Vec<(u32, u32)> =
            mesh.triangles.iter().flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3]))).collect();
        directed.sort();
        for &(i, j) in &directed {
            assert!(directed.binary_search(&(j, i)).is_ok(), "edge {i}→{j} has no twin");
        }
        // 6 vertices and 3 points on each of 12 edges.
        assert_eq!(edge_and_vertex_rays(&mesh, Vec3::ZERO).len(), 6 + 3 * 12);
    }
}
