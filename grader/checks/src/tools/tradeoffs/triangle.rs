//! The triangle pair: lecture 03's three tests on rays aimed exactly at the
//! shared edges and vertices of closed meshes.

use std::hint::black_box;

use l03_polygons_triangles::{
    TriangleHit, hit_triangle_cramer, hit_triangle_moller_trumbore, hit_triangle_watertight,
};
use raylab::random::Rng;
use raylab::scene::Mesh;
use raylab::{Interval, Ray, Vec3};
use raylab_testing::meshes::{edge_and_vertex_rays, wobbly_octahedron};

use super::row::{Pair, Row, own_precision};
use super::timing::{Effort, time_per_item};

type HitTriangle = fn(&Ray, Vec3, Vec3, Vec3, Interval) -> Option<TriangleHit>;

/// The three tests, the reference method last.
pub const VARIANTS: [(&str, HitTriangle); 3] = [
    ("cramer", hit_triangle_cramer),
    ("moller_trumbore", hit_triangle_moller_trumbore),
    ("watertight", hit_triangle_watertight),
];

/// The mesh moved by `offset` (far from the world origin the rounding grows).
fn moved(mut mesh: Mesh, offset: Vec3) -> Mesh {
    mesh.positions.iter_mut().for_each(|p| *p += offset);
    mesh
}

/// The cases: meshes with the point inside that the rays start from.
fn cases(effort: &Effort) -> Vec<(String, Vec<(Mesh, Vec3)>)> {
    let mut rng = Rng::new(5);
    // About `samples` rays: 42 per octahedron.
    let octahedra = (effort.samples / 42).max(10);
    let wobbly = (0..octahedra).map(|_| (wobbly_octahedron(&mut rng), rng.in_cube(0.05))).collect();
    let far = Vec3::splat(1e3);
    vec![
        (format!("{octahedra} wobbly octahedra"), wobbly),
        ("icosphere(2), off-centre".into(), vec![(Mesh::icosphere(2), Vec3::new(0.1, -0.2, 0.05))]),
        (
            "icosphere(2) at 1e3".into(),
            vec![(moved(Mesh::icosphere(2), far), far + Vec3::new(0.1, 0.2, -0.1))],
        ),
    ]
}

/// Every variant on every case: leaks (of the rays), ns per ray–triangle test.
pub fn measure(effort: &Effort) -> Vec<Row> {
    let mut rows = Vec::new();
    for (case, meshes) in cases(effort) {
        let shots: Vec<(Vec<[Vec3; 3]>, Vec<Ray>)> = meshes
            .iter()
            .map(|(mesh, origin)| {
                let triangles = (0..mesh.triangles.len()).map(|i| mesh.triangle(i)).collect();
                (triangles, edge_and_vertex_rays(mesh, *origin))
            })
            .collect();
        let rays: usize = shots.iter().map(|(_, r)| r.len()).sum();
        let tests: usize = shots.iter().map(|(t, r)| t.len() * r.len()).sum();
        for (name, hit_triangle) in VARIANTS {
            let leaks: usize = shots
                .iter()
                .map(|(triangles, rays)| {
                    let hits_any = |ray: &Ray| {
                        triangles
                            .iter()
                            .any(|&[a, b, c]| hit_triangle(ray, a, b, c, Interval::POSITIVE).is_some())
                    };
                    rays.iter().filter(|ray| !hits_any(ray)).count()
                })
                .sum();
            // Every ray against every triangle, no early exit: the cost of one test.
            let time = time_per_item(effort, tests, || {
                for (triangles, rays) in &shots {
                    for ray in rays {
                        for &[a, b, c] in triangles {
                            black_box(hit_triangle(black_box(ray), a, b, c, Interval::POSITIVE));
                        }
                    }
                }
            });
            rows.push(Row {
                pair: Pair::Triangle,
                case: format!("{case} ({rays} rays)"),
                variant: name.to_string(),
                precision: own_precision().to_string(),
                time,
                metrics: vec![
                    ("leaks".into(), leaks as f64),
                    ("leaks %".into(), 100.0 * leaks as f64 / rays.max(1) as f64),
                ],
                fails: leaks > 0,
                pareto: false,
            });
        }
    }
    rows
}
