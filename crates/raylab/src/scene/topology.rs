//! Test support: the mesh properties later lectures rely on (closed,
//! consistently wound, outward, no duplicate vertices), checked by counting.

use std::collections::{HashMap, HashSet};

use super::Mesh;
use crate::math::Vec3;

/// How many different positions the mesh holds (compared bit for bit).
pub fn distinct_positions(mesh: &Mesh) -> usize {
    let key = |p: &Vec3| (p.x.to_bits(), p.y.to_bits(), p.z.to_bits());
    mesh.positions.iter().map(key).collect::<HashSet<_>>().len()
}

/// Every directed edge a→b appears exactly once and its twin b→a exactly once:
/// the mesh is closed and consistently wound (each edge in exactly two
/// triangles, which traverse it in opposite directions).
pub fn assert_closed(mesh: &Mesh) {
    let mut directed: HashMap<(u32, u32), usize> = HashMap::new();
    for t in &mesh.triangles {
        for k in 0..3 {
            *directed.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
        }
    }
    for (&(a, b), &n) in &directed {
        assert_eq!(n, 1, "edge {a}→{b} is used {n} times in the same direction");
        assert_eq!(directed.get(&(b, a)), Some(&1), "edge {a}→{b} has no twin {b}→{a}");
    }
}

/// Every face normal (b − a)×(c − a) agrees with the shape's outward
/// direction at its corners (`outward(p)` at a vertex p, summed over the
/// three): the triangles wind counter-clockwise seen from outside. Summing at
/// the corners, rather than judging the centroid, holds for coarse meshes too.
pub fn assert_outward(mesh: &Mesh, outward: impl Fn(Vec3) -> Vec3) {
    for (i, t) in mesh.triangles.iter().enumerate() {
        let [a, b, c] = mesh.triangle(i);
        let face_normal = (b - a).cross(c - a);
        assert!(
            face_normal.dot(outward(a) + outward(b) + outward(c)) > 0.0,
            "triangle {i} {t:?} faces inward"
        );
    }
}
