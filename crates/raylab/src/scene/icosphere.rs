//! The icosphere: a unit sphere made of triangles by subdividing an icosahedron.

use std::collections::HashMap;

use super::Mesh;
use crate::math::{Float, Vec3};

impl Mesh {
    /// A unit sphere around the origin: the regular icosahedron (12 vertices,
    /// 20 faces), each triangle split into four `subdivisions` times with the
    /// edge midpoints pushed out onto the sphere. V = 10·4ˢ + 2 vertices,
    /// F = 20·4ˢ triangles, every edge shared by exactly two of them
    /// (closed, watertight: neighbours share vertices). Triangles wind
    /// counter-clockwise seen from outside; the normal of a vertex is its
    /// position. No texture coordinates (a seam would break the sharing).
    ///
    /// `subdivisions` ≤ 10 (4·10⁷ triangles); scene files allow 0..=6.
    /// Book: §3.6 Triangle meshes.
    pub fn icosphere(subdivisions: u32) -> Mesh {
        debug_assert!(subdivisions <= 10, "icosphere subdivisions {subdivisions} > 10");
        // The icosahedron's vertices are the cyclic permutations of (0, ±1, ±φ).
        let phi = (1.0 + (5.0 as Float).sqrt()) / 2.0;
        let mut positions: Vec<Vec3> = [
            (-1.0, phi, 0.0),
            (1.0, phi, 0.0),
            (-1.0, -phi, 0.0),
            (1.0, -phi, 0.0),
            (0.0, -1.0, phi),
            (0.0, 1.0, phi),
            (0.0, -1.0, -phi),
            (0.0, 1.0, -phi),
            (phi, 0.0, -1.0),
            (phi, 0.0, 1.0),
            (-phi, 0.0, -1.0),
            (-phi, 0.0, 1.0),
        ]
        .into_iter()
        .map(|(x, y, z)| Vec3::new(x, y, z).normalize())
        .collect();
        let mut triangles: Vec<[u32; 3]> = vec![
            [0, 11, 5],
            [0, 5, 1],
            [0, 1, 7],
            [0, 7, 10],
            [0, 10, 11],
            [1, 5, 9],
            [5, 11, 4],
            [11, 10, 2],
            [10, 7, 6],
            [7, 1, 8],
            [3, 9, 4],
            [3, 4, 2],
            [3, 2, 6],
            [3, 6, 8],
            [3, 8, 9],
            [4, 9, 5],
            [2, 4, 11],
            [6, 2, 10],
            [8, 6, 7],
            [9, 8, 1],
        ];
        for _ in 0..subdivisions {
            // One new vertex per edge, shared by the edge's two triangles.
            let mut midpoints: HashMap<(u32, u32), u32> = HashMap::new();
            let mut midpoint = |a: u32, b: u32| {
                *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                    let m = (positions[a as usize] + positions[b as usize]).normalize();
                    positions.push(m);
                    positions.len() as u32 - 1
                })
            };
            // Split each triangle into its three corners and the middle one, same winding.
            triangles = triangles
                .iter()
                .flat_map(|&[a, b, c]| {
                    let (ab, bc, ca) = (midpoint(a, b), midpoint(b, c), midpoint(c, a));
                    [[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]
                })
                .collect();
        }
        let normals = positions.clone();
        Mesh { positions, normals, uvs: Vec::new(), triangles }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::topology::{assert_closed, assert_outward, distinct_positions};

    #[test]
    fn counts_follow_four_way_splits() {
        // Each split turns a face into 4 and adds one vertex per edge:
        // F = 20·4ˢ, E = 3F/2, and Euler's V − E + F = 2 gives V = 10·4ˢ + 2.
        for s in 0..=3 {
            let mesh = Mesh::icosphere(s);
            let four = 4usize.pow(s);
            assert_eq!(mesh.triangles.len(), 20 * four, "F at s = {s}");
            assert_eq!(mesh.positions.len(), 10 * four + 2, "V at s = {s}");
            assert_eq!(distinct_positions(&mesh), mesh.positions.len(), "no duplicate positions");
        }
    }

    #[test]
    fn icosphere_is_closed_outward_and_on_the_unit_sphere() {
        for s in 0..=3 {
            let mesh = Mesh::icosphere(s);
            assert_closed(&mesh);
            // Outward on a sphere around the origin is the position itself.
            assert_outward(&mesh, |p| p);
            for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
                // Unit length up to a few roundings of a normalisation.
                approx::assert_abs_diff_eq!(p.length(), 1.0, epsilon = 8.0 * Float::EPSILON);
                assert_eq!(p, n, "the normal of a unit sphere is the position");
            }
        }
    }
}
