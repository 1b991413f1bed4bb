//! The torus mesh: a ring around the z axis, made of triangles.

use super::Mesh;
use crate::math::{Float, Vec2, Vec3, consts::TAU};

impl Mesh {
    /// A torus around the z axis: the circle of radius `minor` whose centre
    /// runs around the circle of radius `major` in the xy plane,
    ///
    ///   p(u, v) = ((R + r cos v) cos u, (R + r cos v) sin u, r sin v),
    ///   n(u, v) = (cos v cos u, cos v sin u, sin v),
    ///
    /// sampled at u = 2π·i/`major_segments`, v = 2π·j/`minor_segments`.
    /// Each grid cell is two triangles, counter-clockwise seen from outside
    /// (along ∂p/∂u × ∂p/∂v = outward). The grid wraps around in both
    /// directions onto shared vertices, so the mesh is closed and watertight:
    /// V = M·N vertices, F = 2·M·N triangles, every edge in two of them.
    ///
    /// uv = (i/M, j/N). Because the seam vertices are shared, the last strip
    /// of triangles in each direction interpolates uv from near 1 back to 0;
    /// texture lookups compute (u, v) from the hit point instead.
    ///
    /// Preconditions: 0 < `minor` < `major` (a ring, not a self-touching
    /// spindle), both segment counts ≥ 3. Book: §3.6 Triangle meshes.
    pub fn torus(major: Float, minor: Float, major_segments: u32, minor_segments: u32) -> Mesh {
        debug_assert!(0.0 < minor && minor < major, "torus radii must satisfy 0 < minor < major");
        debug_assert!(major_segments >= 3 && minor_segments >= 3, "torus needs ≥ 3 segments each way");
        let (m, n) = (major_segments, minor_segments);
        let mut mesh = Mesh::default();
        for i in 0..m {
            let u = TAU * i as Float / m as Float;
            for j in 0..n {
                let v = TAU * j as Float / n as Float;
                // The point on the tube and its outward normal.
                let normal = Vec3::new(v.cos() * u.cos(), v.cos() * u.sin(), v.sin());
                let ring = Vec3::new(major * u.cos(), major * u.sin(), 0.0);
                mesh.positions.push(ring + minor * normal);
                mesh.normals.push(normal);
                mesh.uvs.push(Vec2::new(i as Float / m as Float, j as Float / n as Float));
            }
        }
        // Two triangles per cell, wrapping around at the seams.
        let index = |i: u32, j: u32| (i % m) * n + j % n;
        for i in 0..m {
            for j in 0..n {
                let (a, b, c, d) = (index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1));
                mesh.triangles.push([a, b, c]);
                mesh.triangles.push([a, c, d]);
            }
        }
        mesh
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::topology::{assert_closed, assert_outward, distinct_positions};

    #[test]
    fn torus_counts_and_closure() {
        for (m, n) in [(3, 3), (48, 24), (7, 5)] {
            let mesh = Mesh::torus(1.0, 0.25, m, n);
            // M·N grid points, two triangles per grid cell.
            assert_eq!(mesh.positions.len(), (m * n) as usize);
            assert_eq!(mesh.triangles.len(), (2 * m * n) as usize);
            assert_eq!(mesh.normals.len(), mesh.positions.len());
            assert_eq!(mesh.uvs.len(), mesh.positions.len());
            assert_eq!(distinct_positions(&mesh), mesh.positions.len(), "no duplicate positions");
            assert_closed(&mesh);
            // Outward: away from the nearest point of the core circle of radius 1.
            assert_outward(&mesh, |p| p - Vec3::new(p.x, p.y, 0.0).normalize());
        }
    }

    #[test]
    fn torus_points_lie_on_the_tube_with_unit_normals() {
        let (major, minor) = (2.0, 0.5);
        let mesh = Mesh::torus(major, minor, 16, 8);
        for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
            // The distance from the core circle is the tube radius: (√(x²+y²) − R)² + z² = r².
            let core = (p.x.hypot(p.y) - major).hypot(p.z);
            approx::assert_abs_diff_eq!(core, minor, epsilon = 16.0 * Float::EPSILON);
            approx::assert_abs_diff_eq!(n.length(), 1.0, epsilon = 4.0 * Float::EPSILON);
        }
        // The outermost point is at R + r on the x axis (i = 0, j = 0), its normal +x.
        assert_eq!(mesh.positions[0], Vec3::new(major + minor, 0.0, 0.0));
        assert_eq!(mesh.normals[0], Vec3::X);
        let (lo, hi) = mesh.bounds();
        approx::assert_abs_diff_eq!(hi.x, 2.5, epsilon = 0.0);
        approx::assert_abs_diff_eq!(hi.z, minor, epsilon = 4.0 * Float::EPSILON);
        assert!(lo.z >= -minor);
    }
}
