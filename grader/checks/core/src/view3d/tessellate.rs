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
pub(super) fn simplified(triangles: Vec<[Vec3; 3]>, budget: usize) -> Vec<[Vec3; 3]> {
    use std::collections::{HashMap, HashSet};
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
        let key = |p: Vec3| {
            let k = ((p - min) / cell).floor();
            (k.x as i64, k.y as i64, k.z as i64)
        };
        let mut means: HashMap<(i64, i64, i64), (Vec3, Float)> = HashMap::new();
        for p in triangles.iter().flatten() {
            let entry = means.entry(key(*p)).or_insert((Vec3::ZERO, 0.0));
            *entry = (entry.0 + *p, entry.1 + 1.0);
        }
        let mut seen = HashSet::new();
        let mut kept = Vec::new();
        for t in &triangles {
            let k = t.map(key);
            let mut sorted = k;
            sorted.sort();
            if k[0] != k[1] && k[1] != k[2] && k[0] != k[2] && seen.insert(sorted) {
                kept.push(k.map(|k| means[&k].0 / means[&k].1));
            }
        }
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
