//! The scene as triangles for the 3D view: each shape tessellated in world space (spheres by
//! latitude and longitude, quadrics by lathing their profile, boxes as twelve triangles, planes as
//! a square around the scene), meshes simplified to a budget.

use std::f64::consts::PI;

use super::SLICES;
use raylab::scene::Shape;
use raylab::{Float, Mat4, Vec3};

/// An object's triangles in world space. A plane is drawn as a square around the point of it
/// nearest `around`'s centre, three of its radii across; without `around`, none.
pub(super) fn world_triangles(
    object: &raylab::scene::Object,
    around: Option<(Vec3, Float)>,
    slices: usize,
) -> Vec<[Vec3; 3]> {
    let to_world = object.transform.map_or(Mat4::IDENTITY, |t| t.world_from_object);
    let to_object = object.transform.map_or(Mat4::IDENTITY, |t| t.object_from_world);
    let local = match &object.shape {
        Shape::Sphere { center, radius } => sphere(*center, *radius, slices),
        Shape::Plane { normal, offset } => match around {
            Some((center, radius)) => {
                let c = to_object.transform_point3(center);
                let on = c - (normal.dot(c) - offset) * *normal;
                let (u, v) = normal.any_orthonormal_pair();
                let s = 1.5 * radius;
                quad([on - s * u - s * v, on + s * u - s * v, on + s * u + s * v, on - s * u + s * v])
            }
            None => Vec::new(),
        },
        Shape::Box { min, max } => cuboid(*min, *max),
        Shape::Polygon { vertices } => (1..vertices.len().saturating_sub(1))
            .map(|i| [vertices[0], vertices[i], vertices[i + 1]])
            .collect(),
        Shape::Triangle { vertices, .. } => vec![*vertices],
        Shape::Mesh(mesh) => mesh.triangles.iter().map(|t| t.map(|i| mesh.positions[i as usize])).collect(),
        Shape::Cylinder => lathe(|z| (1.0, z), true, true),
        Shape::Cone => lathe(|z| (1.0 - z, z), true, false),
    };
    local.into_iter().map(|t| t.map(|p| to_world.transform_point3(p))).collect()
}

pub(super) fn quad(c: [Vec3; 4]) -> Vec<[Vec3; 3]> {
    vec![[c[0], c[1], c[2]], [c[0], c[2], c[3]]]
}

/// `triangles` in at most `budget` (give or take a few): as they are when they fit, else their
/// vertices merged in the cells of a grid (vertex clustering, Rossignac and Borrel 1993), each
/// cell's at their mean, and the triangles that collapse left out — a coarser grid until they fit.
///
/// The cells are found in a flat array over the grid's box (at most 130³ of them, 8.8 MB) and
/// the repeated triangles by sorting, not hashed: this runs in the checks' core, at opt-level 0,
/// whenever a picture with a large mesh fails. Lecture 09's torus of 65,536 triangles: its failing
/// picture's check took 1.31 s of CPU, 85 % of it here with a `HashMap` of cells (SipHash at
/// opt-level 0), and takes 0.43 s; the simplification alone 0.98 → 0.20 s (six grids), the same
/// triangles byte for byte (compared on that torus, a 256-slice sphere and a larger torus).
pub(super) fn simplified(triangles: Vec<[Vec3; 3]>, budget: usize) -> Vec<[Vec3; 3]> {
    if triangles.len() <= budget {
        return triangles;
    }
    let min = triangles.iter().flatten().fold(Vec3::splat(Float::INFINITY), |m, p| m.min(*p));
    let max = triangles.iter().flatten().fold(Vec3::splat(Float::NEG_INFINITY), |m, p| m.max(*p));
    let size = (max - min).max_element();
    if !(size.is_finite() && size > 0.0) {
        return triangles;
    }
    // Cells across the largest side: a surface of n triangles has ~n/2 vertices, one per cell
    // of a grid fine enough; start where the budget's vertices would fill a square's worth.
    let mut cells = ((budget as f64 / 2.0).sqrt() * 2.0) as Float;
    loop {
        let cell = size / cells;
        // The cells along each axis: one more for a point on the far side, one for rounding.
        let [nx, ny, nz] = (((max - min) / cell).floor() + 2.0).to_array().map(|n| n as usize);
        let cell_of = |p: Vec3| {
            let k = ((p - min) / cell).floor();
            let at = |k: Float, n: usize| (k.max(0.0) as usize).min(n - 1);
            (at(k.x, nx) * ny + at(k.y, ny)) * nz + at(k.z, nz)
        };
        // Each occupied cell's cluster, numbered from 1 in the order first met (0: none yet), and
        // each cluster's sum of vertices and their count.
        let mut cluster_of_cell = vec![0u32; nx * ny * nz];
        let mut clusters: Vec<(Vec3, Float)> = Vec::new();
        let corners: Vec<[u32; 3]> = triangles
            .iter()
            .map(|t| {
                t.map(|p| {
                    let c = &mut cluster_of_cell[cell_of(p)];
                    if *c == 0 {
                        clusters.push((Vec3::ZERO, 0.0));
                        *c = clusters.len() as u32;
                    }
                    let (sum, count) = &mut clusters[*c as usize - 1];
                    *sum += p;
                    *count += 1.0;
                    *c
                })
            })
            .collect();
        // The triangles whose corners stay in three clusters, each three once (the first met):
        // sorted by their three clusters, then by their place.
        let mut sets: Vec<u128> = (corners.iter().enumerate())
            .filter(|(_, c)| c[0] != c[1] && c[1] != c[2] && c[0] != c[2])
            .map(|(i, c)| {
                let mut s = *c;
                s.sort_unstable();
                (u128::from(s[0]) << 96) | (u128::from(s[1]) << 64) | (u128::from(s[2]) << 32) | i as u128
            })
            .collect();
        sets.sort_unstable();
        let mut first = vec![false; triangles.len()];
        for (j, set) in sets.iter().enumerate() {
            if j == 0 || sets[j - 1] >> 32 != set >> 32 {
                first[*set as u32 as usize] = true;
            }
        }
        let kept: Vec<[Vec3; 3]> = (corners.iter().zip(&first))
            .filter(|(_, first)| **first)
            .map(|(c, _)| {
                c.map(|c| {
                    let (sum, count) = clusters[c as usize - 1];
                    sum / count
                })
            })
            .collect();
        if kept.len() <= budget || cells <= 4.0 {
            return kept;
        }
        cells *= 0.8;
    }
}

pub(super) fn sphere(center: Vec3, radius: Float, slices: usize) -> Vec<[Vec3; 3]> {
    let rings = slices / 2;
    let at = |ring: usize, slice: usize| {
        let (theta, phi) = (PI * ring as f64 / rings as f64, 2.0 * PI * slice as f64 / slices as f64);
        center
            + radius
                * Vec3::new(
                    (theta.sin() * phi.cos()) as Float,
                    theta.cos() as Float,
                    (theta.sin() * phi.sin()) as Float,
                )
    };
    let mut triangles = Vec::new();
    for ring in 0..rings {
        for slice in 0..slices {
            let c = [at(ring, slice), at(ring, slice + 1), at(ring + 1, slice + 1), at(ring + 1, slice)];
            // The poles' quads are triangles: leave out the one of zero area.
            if ring > 0 {
                triangles.push([c[0], c[1], c[2]]);
            }
            if ring + 1 < rings {
                triangles.push([c[0], c[2], c[3]]);
            }
        }
    }
    triangles
}

pub(super) fn cuboid(min: Vec3, max: Vec3) -> Vec<[Vec3; 3]> {
    let p = |x: bool, y: bool, z: bool| {
        Vec3::new(if x { max.x } else { min.x }, if y { max.y } else { min.y }, if z { max.z } else { min.z })
    };
    let mut triangles = Vec::new();
    for side in [false, true] {
        triangles.extend(quad([
            p(side, false, false),
            p(side, true, false),
            p(side, true, true),
            p(side, false, true),
        ]));
        triangles.extend(quad([
            p(false, side, false),
            p(true, side, false),
            p(true, side, true),
            p(false, side, true),
        ]));
        triangles.extend(quad([
            p(false, false, side),
            p(true, false, side),
            p(true, true, side),
            p(false, true, side),
        ]));
    }
    triangles
}

/// A solid of revolution about z from z = 0 to 1, its radius and height at `profile(z)`, with a
/// disc at the bottom and (`top`) at the top.
pub(super) fn lathe(profile: impl Fn(Float) -> (Float, Float), bottom: bool, top: bool) -> Vec<[Vec3; 3]> {
    let ring = |k: usize, z: Float| {
        let a = 2.0 * PI * k as f64 / SLICES as f64;
        let (r, h) = profile(z);
        Vec3::new(r * a.cos() as Float, r * a.sin() as Float, h)
    };
    let mut triangles = Vec::new();
    for k in 0..SLICES {
        triangles.extend(quad([ring(k, 0.0), ring(k + 1, 0.0), ring(k + 1, 1.0), ring(k, 1.0)]));
        if bottom {
            triangles.push([Vec3::ZERO, ring(k + 1, 0.0), ring(k, 0.0)]);
        }
        if top {
            triangles.push([Vec3::Z, ring(k, 1.0), ring(k + 1, 1.0)]);
        }
    }
    triangles
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view3d::MESH_TRIANGLES;

    #[test]
    fn a_sphere_is_closed_and_on_its_surface() {
        let triangles = sphere(Vec3::new(1.0, 2.0, 3.0), 2.0, SLICES);
        assert_eq!(triangles.len(), 2 * SLICES * (SLICES / 2 - 1));
        for p in triangles.iter().flatten() {
            assert!(((*p - Vec3::new(1.0, 2.0, 3.0)).length() - 2.0).abs() < 1e-5, "{p}");
        }
    }
    /// A sphere of 64 770 triangles (256 slices) simplified to the mesh budget: at most 8192
    /// triangles, and not far fewer (over a quarter), every vertex still on the sphere within
    /// the grid's cell (the mean of points on the surface, a chord's depth inside it: a cell of
    /// the last grid is at most 2/(2·√4096·0.8⁵) ≈ 0.024 of the diameter 2 — allowed 0.05).
    #[test]
    fn a_fine_mesh_is_simplified_to_the_budget_and_keeps_its_shape() {
        let fine = sphere(Vec3::ZERO, 1.0, 256);
        assert_eq!(fine.len(), 2 * 256 * 127);
        let coarse = simplified(fine, MESH_TRIANGLES);
        assert!(coarse.len() <= MESH_TRIANGLES && coarse.len() > MESH_TRIANGLES / 4, "{}", coarse.len());
        for p in coarse.iter().flatten() {
            assert!((p.length() - 1.0).abs() < 0.05, "{p}");
        }
        // Fewer than the budget: untouched.
        let few = sphere(Vec3::ZERO, 1.0, 8);
        assert_eq!(simplified(few.clone(), MESH_TRIANGLES), few);
    }
    /// A flat mesh (a square of 2 × 100 × 100 triangles in z = 0, no extent along z): simplified
    /// within its plane, every triangle kept with three distinct corners, none twice.
    #[test]
    fn a_flat_mesh_is_simplified_in_its_plane() {
        let at = |i: usize, j: usize| Vec3::new(i as Float / 100.0, j as Float / 100.0, 0.0);
        let fine: Vec<[Vec3; 3]> = (0..100 * 100)
            .flat_map(|k| {
                let (i, j) = (k / 100, k % 100);
                [[at(i, j), at(i + 1, j), at(i + 1, j + 1)], [at(i, j), at(i + 1, j + 1), at(i, j + 1)]]
            })
            .collect();
        let coarse = simplified(fine, MESH_TRIANGLES);
        assert!(coarse.len() <= MESH_TRIANGLES && coarse.len() > MESH_TRIANGLES / 4, "{}", coarse.len());
        let mut seen = std::collections::HashSet::new();
        for t in &coarse {
            assert!(
                t.iter().all(|p| p.z == 0.0 && p.min_element() >= 0.0 && p.max_element() <= 1.0),
                "{t:?}"
            );
            assert!(t[0] != t[1] && t[1] != t[2] && t[0] != t[2], "{t:?}");
            let mut key = t.map(|p| p.to_array().map(|x| x.to_bits()));
            key.sort();
            assert!(seen.insert(key), "{t:?} twice");
        }
    }
    #[test]
    fn a_box_has_twelve_triangles_on_its_faces() {
        let triangles = cuboid(Vec3::ZERO, Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(triangles.len(), 12);
        for p in triangles.iter().flatten() {
            let on_face = p.x == 0.0 || p.x == 1.0 || p.y == 0.0 || p.y == 2.0 || p.z == 0.0 || p.z == 3.0;
            assert!(on_face, "{p}");
        }
    }
}
