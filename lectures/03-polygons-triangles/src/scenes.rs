//! Checks on this lecture's scene files (`scenes/*.toml`): they load, hold
//! only shapes of lectures 02–03, stay small, every object is seen, and each
//! shows what it is for.

use std::path::PathBuf;

use l01_transforms::Camera;
use l02_ray_casting::closest_hit;
use raylab::scene::{self, Scene, Shape};
use raylab::{Float, Hit, Interval, Ray, Vec3};

use crate::object::hit_flat_shape;

const SCENES: [&str; 4] = ["boxes.toml", "polygons.toml", "triangles.toml", "meshes.toml"];

fn load(name: &str) -> Scene {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes")).join(name);
    scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

fn trace(scene: &Scene, ray: &Ray, range: Interval) -> Option<Hit> {
    closest_hit(&scene.objects, ray, range, hit_flat_shape)
}

/// The closest hit of every pixel's primary ray, row-major, at the scene's
/// size, or half of it for scenes with meshes (brute force over 224
/// triangles per ray is slow in a debug build; every object stays in view).
fn primary_hits(scene: &Scene) -> Vec<Option<Hit>> {
    let has_mesh = scene.objects.iter().any(|o| matches!(o.shape, Shape::Mesh(_)));
    let (w, h) = if has_mesh { (scene.width / 2, scene.height / 2) } else { (scene.width, scene.height) };
    let camera = Camera::from_scene(&scene.camera, w, h).expect("a valid camera");
    let (hits, _) = raylab::render::render_map(w, h, |x, y| {
        trace(scene, &camera.pixel_ray(x, y, w, h), camera.t_range())
    });
    hits
}

fn eye(scene: &Scene) -> Vec3 {
    match scene.camera {
        scene::Camera::Perspective { eye, .. } | scene::Camera::Orthographic { eye, .. } => eye,
    }
}

#[test]
fn every_scene_is_small_and_made_of_this_lectures_shapes() {
    for name in SCENES {
        let scene = load(name);
        assert!(scene.width <= 200 && scene.height <= 150, "{name}: {}×{}", scene.width, scene.height);
        for object in &scene.objects {
            assert!(!matches!(object.shape, Shape::Cylinder | Shape::Cone), "{name}: {object:?}");
            assert!(object.transform.is_none(), "{name}: no transforms in lecture 03");
        }
    }
}

#[test]
fn every_object_is_seen_with_finite_unit_normals() {
    for name in SCENES {
        let scene = load(name);
        let hits = primary_hits(&scene);
        for i in 0..scene.objects.len() {
            assert!(hits.iter().flatten().any(|h| h.object == i), "{name}: object {i} is never seen");
        }
        for h in hits.iter().flatten() {
            assert!(h.t > 0.0 && h.t.is_finite() && h.point.is_finite(), "{name}: {h:?}");
            // Unit within the rounding of a normalisation (a few ε).
            assert!((h.normal.length() - 1.0).abs() < 8.0 * Float::EPSILON, "{name}: {h:?}");
        }
    }
}

#[test]
fn box_normals_are_exactly_the_axes() {
    let scene = load("boxes.toml");
    for h in primary_hits(&scene).iter().flatten() {
        let n = h.normal.abs();
        assert_eq!(n.x + n.y + n.z, 1.0, "{h:?}");
        assert_eq!(n.max_element(), 1.0, "{h:?}");
    }
}

#[test]
fn pentagram_centre_is_a_hole_that_shows_the_wall() {
    let scene = load("polygons.toml");
    let look = |target: Vec3| trace(&scene, &Ray::new(eye(&scene), target - eye(&scene)), Interval::POSITIVE);
    // The star is object 1, centred at (0, 0.3, 0) with radius 1.5; the wall is object 0.
    assert_eq!(
        look(Vec3::new(0.0, 0.3, 0.0)).map(|h| h.object),
        Some(0),
        "the centre is outside by even–odd"
    );
    assert_eq!(look(Vec3::new(0.0, 1.5, 0.0)).map(|h| h.object), Some(1), "a tip is inside");
    // The notch of the "U" (object 2) shows the wall too; its base does not.
    assert_eq!(look(Vec3::new(-2.55, 0.5, 0.0)).map(|h| h.object), Some(0));
    assert_eq!(look(Vec3::new(-2.55, -1.25, 0.0)).map(|h| h.object), Some(2));
}

#[test]
fn vertex_normals_round_off_the_facets() {
    let scene = load("triangles.toml");
    let hits = primary_hits(&scene);
    for (i, object) in scene.objects.iter().enumerate() {
        let Shape::Triangle { vertices: [a, b, c], normals } = object.shape else { continue };
        let on_it: Vec<&Hit> = hits.iter().flatten().filter(|h| h.object == i).collect();
        let facet = (b - a).cross(c - a).normalize();
        // Flat: every pixel has the facet normal (up to normalisation, 4ε). Smooth:
        // the normal turns across the face by far more than rounding.
        let spread = on_it.iter().map(|h| (h.normal - facet).length()).fold(0.0, Float::max);
        if normals.is_none() {
            assert!(spread < 4.0 * Float::EPSILON, "object {i}: flat but spread {spread}");
        } else {
            assert!(spread > 0.1, "object {i}: smooth but spread {spread}");
        }
    }
}

#[test]
fn closed_meshes_do_not_leak_at_edges_and_vertices() {
    // Rays from inside each mesh aimed exactly at every vertex and edge midpoint
    // must stop at that mesh no later than the aimed-at point (t = 1; 4ε allows
    // for rounding the direction). From inside the icosphere (object 1) they
    // start at its centre; from inside the torus (object 2) at the point of its
    // core circle (radius 2 in the xy plane) nearest the target.
    let scene = load("meshes.toml");
    for (i, object) in scene.objects.iter().enumerate() {
        let Shape::Mesh(mesh) = &object.shape else { continue };
        let inside = |p: Vec3| if i == 1 { Vec3::ZERO } else { 2.0 * p.truncate().normalize().extend(0.0) };
        let mut targets = mesh.positions.clone();
        for t in &mesh.triangles {
            // Each edge once: it runs the other way in the neighbouring triangle.
            for k in 0..3 {
                let (i, j) = (t[k] as usize, t[(k + 1) % 3] as usize);
                if i < j {
                    targets.push(mesh.positions[i].lerp(mesh.positions[j], 0.5));
                }
            }
        }
        for target in targets {
            let from = inside(target);
            let hit = trace(&scene, &Ray::new(from, target - from), Interval::POSITIVE);
            assert!(
                hit.is_some_and(|h| h.object == i && h.t <= 1.0 + 4.0 * Float::EPSILON),
                "leak from {from} toward {target}: {hit:?}"
            );
        }
    }
}
