//! Checks on this lecture's scene files (`scenes/*.toml`): they load, hold
//! only what this lecture can intersect, stay small, and their id, depth and
//! normal images show what each scene is for.

use std::collections::HashSet;
use std::path::PathBuf;

use l01_transforms::Camera;
use raylab::scene::{self, Scene, Shape};
use raylab::{BLACK, Image};

use crate::group::Group;
use crate::images::{depth_image, id_color, normal_image, object_id_image};

const SCENES: [&str; 4] =
    ["spheres-on-plane.toml", "overlapping-depths.toml", "inside-sphere.toml", "orthographic.toml"];

fn load(name: &str) -> Scene {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes")).join(name);
    scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// The id, depth and normal images of a scene at its own size.
fn signature(scene: &Scene) -> [Image; 3] {
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).expect("a valid camera");
    let group = Group::new(&scene.objects);
    let (w, h) = (scene.width, scene.height);
    [
        object_id_image(&camera, &group, w, h),
        depth_image(&camera, &group, w, h),
        normal_image(&camera, &group, w, h),
    ]
}

/// Which object ids appear in an id image (`None` for the background).
fn ids_seen(scene: &Scene, ids: &Image) -> HashSet<Option<usize>> {
    let palette: Vec<_> = (0..scene.objects.len()).map(|i| (id_color(Some(i)), Some(i))).collect();
    ids.pixels
        .iter()
        .map(|&c| palette.iter().find(|(p, _)| *p == c).map(|&(_, id)| id).unwrap_or(None))
        .collect()
}

#[test]
fn every_scene_is_small_and_made_of_spheres_and_planes() {
    for name in SCENES {
        let scene = load(name);
        assert!(scene.width <= 200 && scene.height <= 150, "{name}: {}×{}", scene.width, scene.height);
        for object in &scene.objects {
            assert!(matches!(object.shape, Shape::Sphere { .. } | Shape::Plane { .. }), "{name}: {object:?}");
            assert!(object.transform.is_none(), "{name}: no transforms in lecture 02");
        }
    }
}

#[test]
fn every_object_of_every_scene_is_seen_and_images_are_finite() {
    for name in SCENES {
        let scene = load(name);
        let [ids, depth, normals] = signature(&scene);
        for image in [&ids, &depth, &normals] {
            assert_eq!(image.non_finite(), None, "{name}: NaN or infinite pixels");
        }
        let seen = ids_seen(&scene, &ids);
        for i in 0..scene.objects.len() {
            assert!(seen.contains(&Some(i)), "{name}: object {i} is never the closest hit");
        }
        // Where something is hit, the depth is positive and the normal unit; elsewhere all zero.
        for ((id, d), n) in ids.pixels.iter().zip(&depth.pixels).zip(&normals.pixels) {
            if *id == BLACK {
                assert_eq!((*d, *n), (BLACK, BLACK), "{name}");
            } else {
                assert!(d.x > 0.0 && (n.length() - 1.0).abs() < 1e-3, "{name}: depth {d}, normal {n}");
            }
        }
    }
}

#[test]
fn camera_inside_a_sphere_sees_something_everywhere() {
    let scene = load("inside-sphere.toml");
    let [ids, _, _] = signature(&scene);
    assert!(!ids_seen(&scene, &ids).contains(&None), "a ray from inside a closed sphere always hits");
}

#[test]
fn object_order_never_changes_the_picture() {
    // The closest hit does not depend on the order of the objects: reversed, every
    // pixel shows the same depth and normal (object indices are renumbered, so ids
    // are compared through the reversal).
    for name in SCENES {
        let scene = load(name);
        let mut reversed = scene.clone();
        reversed.objects.reverse();
        let [ids, depth, normals] = signature(&scene);
        let [ids_r, depth_r, normals_r] = signature(&reversed);
        assert_eq!(depth, depth_r, "{name}: depth");
        assert_eq!(normals, normals_r, "{name}: normals");
        let n = scene.objects.len();
        let flip = |c| (0..n).find(|&i| id_color(Some(i)) == c).map(|i| id_color(Some(n - 1 - i)));
        for (a, b) in ids.pixels.iter().zip(&ids_r.pixels) {
            assert_eq!(flip(*a).unwrap_or(BLACK), *b, "{name}: ids");
        }
    }
}
