//! Checks on this lecture's scene files (`scenes/*.toml`): small, and every
//! object inside the frame of the camera they describe.
//!
//! The files are read with the `toml` crate directly and the camera is built
//! with this lecture's own code, so the framing checks do not depend on the
//! kit's scene loader; a last test checks that the loader agrees.

use std::path::PathBuf;

use raylab::{Float, Vec3, radians, scene};
use toml::{Table, Value};

use crate::camera::Camera;
use crate::testing::from_f64;
use crate::transforms::transform_point;

fn scene_path(name: &str) -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes")).join(name)
}

fn read(name: &str) -> Table {
    let text = std::fs::read_to_string(scene_path(name)).expect("scene file");
    toml::from_str(&text).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn num(v: &Value) -> Float {
    // Read in f64 and rounded to Float, as the loader does.
    from_f64(v.as_float().or_else(|| v.as_integer().map(|i| i as f64)).expect("a number"))
}

fn vec3(v: &Value) -> Vec3 {
    let a = v.as_array().expect("a triple");
    assert_eq!(a.len(), 3);
    Vec3::new(num(&a[0]), num(&a[1]), num(&a[2]))
}

/// The scene's camera (degrees turned to radians, as the loader does) and image size.
fn camera(t: &Table) -> (scene::Camera, u32, u32) {
    let image = t["image"].as_table().expect("[image]");
    let (w, h) = (image["width"].as_integer().unwrap() as u32, image["height"].as_integer().unwrap() as u32);
    let c = t["camera"].as_table().expect("[camera]");
    let (eye, at) = (vec3(&c["eye"]), vec3(&c["at"]));
    let up = c.get("up").map_or(Vec3::Y, vec3);
    let cam = match c["type"].as_str() {
        Some("perspective") => scene::Camera::Perspective { eye, at, up, fovy: radians(num(&c["fovy"])) },
        Some("orthographic") => scene::Camera::Orthographic { eye, at, up, height: num(&c["height"]) },
        other => panic!("camera type {other:?}"),
    };
    (cam, w, h)
}

/// Points that must be on screen: sphere centres and box corners.
fn key_points(t: &Table) -> Vec<Vec3> {
    let mut points = Vec::new();
    for o in t["objects"].as_array().expect("[[objects]]") {
        match o["type"].as_str() {
            Some("sphere") => points.push(vec3(&o["center"])),
            Some("box") => {
                let (lo, hi) = (vec3(&o["min"]), vec3(&o["max"]));
                for k in 0..8 {
                    let pick = |bit: usize, a: Float, b: Float| if k & bit == 0 { a } else { b };
                    points.push(Vec3::new(pick(1, lo.x, hi.x), pick(2, lo.y, hi.y), pick(4, lo.z, hi.z)));
                }
            }
            _ => {}
        }
    }
    points
}

/// Screen coordinates of a world point, by inverting the projection (not
/// through generate_ray): camera space, then divide by depth (perspective)
/// or by the window's half-size (orthographic).
fn project(cam: &Camera, p: Vec3) -> (Float, Float, Float) {
    match cam {
        Camera::Perspective(c) => {
            let q = transform_point(&c.world_from_camera.inverse(), p);
            let half = (0.5 * c.fovy).tan();
            (q.x / (-q.z * c.aspect * half), q.y / (-q.z * half), q.z)
        }
        Camera::Orthographic(c) => {
            let q = transform_point(&c.world_from_camera.inverse(), p);
            (q.x / (0.5 * c.height * c.aspect), q.y / (0.5 * c.height), q.z)
        }
    }
}

#[test]
fn scenes_are_small_and_frame_every_object() {
    for name in ["perspective.toml", "orthographic.toml", "rolled.toml"] {
        let t = read(name);
        let (desc, w, h) = camera(&t);
        assert!(w <= 200 && h <= 150, "{name}: {w}×{h} is larger than 200×150");
        assert_ne!(w, h, "{name}: the lecture's scenes use non-square images");
        let cam = Camera::from_scene(&desc, w, h).unwrap_or_else(|e| panic!("{name}: {e}"));
        for p in key_points(&t) {
            let (sx, sy, z) = project(&cam, p);
            assert!(z < 0.0, "{name}: {p} is behind the camera");
            assert!(sx.abs() < 0.95 && sy.abs() < 0.95, "{name}: {p} is off screen at ({sx}, {sy})");
        }
    }
}

#[test]
fn perspective_and_orthographic_show_the_same_objects() {
    let (p, o) = (read("perspective.toml"), read("orthographic.toml"));
    for key in ["objects", "materials", "lights", "image"] {
        assert_eq!(p[key], o[key], "`{key}` differs");
    }
    let (pc, oc) = (p["camera"].as_table().unwrap(), o["camera"].as_table().unwrap());
    for key in ["eye", "at", "up"] {
        assert_eq!(pc[key], oc[key], "camera `{key}` differs");
    }
}

#[test]
fn rolled_scene_is_tilted_and_rolled() {
    let (desc, w, h) = camera(&read("rolled.toml"));
    let Camera::Perspective(c) = Camera::from_scene(&desc, w, h).unwrap() else {
        panic!("perspective expected")
    };
    let (u, w_axis) = (c.world_from_camera.x_axis.truncate(), c.world_from_camera.z_axis.truncate());
    // Tilted: it looks down (the view direction −w has a negative y).
    assert!(-w_axis.y < -0.2, "view direction {}", -w_axis);
    // Rolled: the image's horizontal axis u leaves the horizontal plane.
    assert!(u.y.abs() > 0.2, "u = {u} is horizontal: no roll");
}

#[test]
fn the_kit_loader_reads_the_same_cameras() {
    // The kit's loader checks every key (unknown keys are errors) and must
    // find the camera and image size that the reading above finds.
    for name in ["perspective.toml", "orthographic.toml", "rolled.toml"] {
        let scene = scene::load(scene_path(name)).unwrap_or_else(|e| panic!("{e}"));
        let (desc, w, h) = camera(&read(name));
        assert_eq!((scene.width, scene.height), (w, h), "{name}");
        assert_eq!(scene.camera, desc, "{name}");
        assert_eq!(scene.objects.len(), 5, "{name}: a plane, three spheres and a box");
    }
}
