//! Tests of the MIT 6.837 reader: the course's own scene files (from the
//! shared data), values checked by hand against their text, error messages
//! with line and column counted by hand, and inputs that must never panic.

use std::path::PathBuf;

use super::*;
use crate::data::shared_data;
use crate::math::consts::{FRAC_PI_6, PI};
use crate::scene::{Scene, SolidPattern, Texture};

/// Conversions degrees → radians, normalisations and products of a few
/// matrices are a few roundings off the exact value (values of size ≤ 12).
const ROUNDING: Float = 64.0 * Float::EPSILON;

fn parse(text: &str) -> Result<Scene, SceneError> {
    parse_mit6837(text, Path::new("scenes/a.txt"))
}

fn error(text: &str) -> String {
    match parse(text) {
        Ok(_) => panic!("expected an error from:\n{text}"),
        Err(e) => e.to_string(),
    }
}

/// A valid camera on line 1, so that what follows starts on line 2.
const CAMERA: &str = "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 5 }\n";

/// `CAMERA`, then a group (line 2) with the count (line 3) and `body` (line 4 on).
fn group_error(count: usize, body: &str) -> String {
    error(&format!("{CAMERA}Group {{\n    numObjects {count}\n{body}\n}}\n"))
}

/// The shared 6.837 scene files whose names start with `prefix`; `None` (after
/// a SKIPPED line) when the shared data is absent.
fn scene_files(prefix: &str) -> Option<Vec<PathBuf>> {
    let dir = shared_data("mit6837", "the MIT 6.837 scenes")?;
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| {
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            name.starts_with(prefix) && name.ends_with(".txt")
        })
        .collect();
    files.sort();
    Some(files)
}

fn load_shared(name: &str) -> Option<Scene> {
    let path = shared_data(&format!("mit6837/{name}"), name)?;
    Some(load_mit6837(&path).unwrap_or_else(|e| panic!("{e}")))
}

/// What the loaders promise: finite numbers, unit normals and directions,
/// invertible finite transforms, material indices in range, valid meshes.
fn assert_usable(scene: &Scene, name: &str) {
    let (Camera::Perspective { eye, at, up, .. } | Camera::Orthographic { eye, at, up, .. }) = scene.camera;
    assert!(eye.is_finite() && at.is_finite() && up.is_finite() && eye != at, "{name}: camera");
    let unit = |v: Vec3| (v.length() - 1.0).abs() <= ROUNDING;
    for light in &scene.lights {
        assert!(light.color.is_finite(), "{name}: light colour");
        match light.kind {
            LightKind::Directional { direction } => assert!(unit(direction), "{name}: light direction"),
            LightKind::Point { position, .. } => assert!(position.is_finite(), "{name}: light position"),
            LightKind::Spot { .. } | LightKind::Rect { .. } | LightKind::Sphere { .. } => {
                panic!("{name}: 6.837 has no spot or area lights")
            }
        }
    }
    for m in &scene.materials {
        let colors = [m.diffuse, m.specular, m.reflective, m.transparent];
        assert!(colors.iter().all(|c| c.is_finite()) && m.exponent.is_finite() && m.ior > 0.0, "{name}");
    }
    for (i, object) in scene.objects.iter().enumerate() {
        assert!(object.material < scene.materials.len(), "{name}: object {i} material");
        if let Some(t) = object.transform {
            assert!(t.world_from_object.is_finite() && t.object_from_world.is_finite(), "{name}: object {i}");
        }
        match &object.shape {
            Shape::Sphere { center, radius } => assert!(center.is_finite() && *radius > 0.0),
            Shape::Plane { normal, offset } => assert!(unit(*normal) && offset.is_finite()),
            Shape::Triangle { vertices, .. } => assert!(vertices.iter().all(|v| v.is_finite())),
            Shape::Mesh(mesh) => {
                assert!(mesh.positions.iter().all(|p| p.is_finite()), "{name}: object {i} positions");
                let n = mesh.positions.len() as u32;
                assert!(mesh.triangles.iter().flatten().all(|&k| k < n), "{name}: object {i} indices");
            }
            other => panic!("{name}: 6.837 has no {}", other.kind()),
        }
    }
}

#[test]
fn every_scene_of_assignments_1_to_4_loads() {
    for prefix in ["scene1_", "scene2_", "scene3_", "scene4_"] {
        let Some(files) = scene_files(prefix) else { return };
        assert!(!files.is_empty(), "no {prefix}* files");
        for file in files {
            let name = file.file_name().unwrap().to_string_lossy().into_owned();
            let scene = load_mit6837(&file).unwrap_or_else(|e| panic!("{e}"));
            assert_usable(&scene, &name);
            assert_eq!((scene.width, scene.height), (200, 200), "{name}");
        }
    }
}

/// Every scene of assignments 5–8 loads, the procedural textures of assignment 6 included
/// (`Noise`, `Marble`, `Wood`, and a `Checkerboard` of two `Wood`s in the logo scenes).
#[test]
fn later_scenes_load() {
    let Some(files) = scene_files("scene") else { return };
    let early = |f: &PathBuf| {
        let name = f.file_name().unwrap().to_string_lossy().into_owned();
        ["scene1_", "scene2_", "scene3_", "scene4_"].iter().any(|p| name.starts_with(p))
    };
    let later: Vec<PathBuf> = files.into_iter().filter(|f| !early(f)).collect();
    assert!(later.len() >= 40, "the assignments 5–8 scenes are there");
    let mut procedural = 0;
    for file in later {
        let name = file.file_name().unwrap().to_string_lossy().into_owned();
        let scene = load_mit6837(&file).unwrap_or_else(|e| panic!("{e}"));
        assert_usable(&scene, &name);
        let noisy = |m: &Material| matches!(&m.texture, Some(Texture::Solid { pattern, .. }) if *pattern != SolidPattern::Checker);
        procedural += usize::from(scene.materials.iter().any(noisy));
    }
    assert_eq!(procedural, 7, "the scenes with Noise, Marble or Wood");
}

#[test]
fn scene1_01_is_one_red_sphere_seen_orthographically() {
    let Some(scene) = load_shared("scene1_01.txt") else { return };
    // center 0 0 10, direction 0 0 -1, up 0 1 0, size 5.
    let expected = Camera::Orthographic {
        eye: Vec3::new(0.0, 0.0, 10.0),
        at: Vec3::new(0.0, 0.0, 9.0),
        up: Vec3::Y,
        height: 5.0,
    };
    assert_eq!(scene.camera, expected);
    // No `Lights` block and no ambientLight: the loader makes the ambient light white, so
    // the unlit object shows its diffuse colour (assignment 1 has no shading).
    assert_eq!((scene.background, scene.ambient), (BLACK, WHITE), "no Lights, no ambientLight");
    assert!(scene.lights.is_empty());
    assert_eq!(scene.materials.len(), 1);
    assert_eq!(
        (scene.materials[0].diffuse, scene.materials[0].model),
        (Color::X, super::super::Specular::Blinn)
    );
    let Shape::Sphere { center, radius } = scene.objects[0].shape else { panic!() };
    assert_eq!((center, radius, scene.objects[0].material), (Vec3::ZERO, 1.0, 0));
    assert!(scene.objects[0].transform.is_none());
}

#[test]
fn scene2_16_first_sphere_is_translated_then_scaled_by_5() {
    let Some(scene) = load_shared("scene2_16_t_scale.txt") else { return };
    let first = &scene.objects[0];
    // MaterialIndex 3; Transform { Translate -1.25 -1.25 -2  Scale 5 5 5  Sphere { radius 0.25 } }.
    assert_eq!(first.material, 3);
    let Shape::Sphere { radius, .. } = first.shape else { panic!() };
    assert_eq!(radius, 0.25);
    let m = first.transform.unwrap().world_from_object;
    assert_eq!(m.transform_point3(Vec3::ZERO), Vec3::new(-1.25, -1.25, -2.0));
    assert_eq!(m.transform_vector3(Vec3::X).length(), 5.0);
    // The third object has no Transform around it.
    assert!(scene.objects[2].transform.is_none());
    // DirectionalLight direction -0.5 -0.5 -1, normalised by √1.5; ambientLight 0.5.
    let LightKind::Directional { direction } = scene.lights[0].kind else { panic!() };
    let expected = Vec3::new(-0.5, -0.5, -1.0) / (1.5 as Float).sqrt();
    approx::assert_abs_diff_eq!(direction, expected, epsilon = ROUNDING);
    assert_eq!((scene.ambient, scene.lights[0].color), (Color::splat(0.5), Color::splat(0.5)));
}

#[test]
fn scene2_15_nested_transforms_compose_and_the_mesh_is_shared() {
    let Some(scene) = load_shared("scene2_15_crazy_transforms.txt") else { return };
    // UniformScale 0.5 · XRotate 20 · Translate -3 0 0 · Translate 1 0 0 · (ZRotate 45 · Scale 1 2 1):
    // the cube's origin goes to 0.5·Rx·(-2, 0, 0) = (-1, 0, 0), and the second
    // cube's (with Translate 6 0 0) to 0.5·(3, 0, 0) = (1.5, 0, 0); Rx fixes the x axis.
    let origin =
        |i: usize| scene.objects[i].transform.unwrap().world_from_object.transform_point3(Vec3::ZERO);
    approx::assert_abs_diff_eq!(origin(0), Vec3::new(-1.0, 0.0, 0.0), epsilon = ROUNDING);
    approx::assert_abs_diff_eq!(origin(1), Vec3::new(1.5, 0.0, 0.0), epsilon = ROUNDING);
    assert_eq!((scene.objects[0].material, scene.objects[1].material), (0, 1));
    let (Shape::Mesh(a), Shape::Mesh(b)) = (&scene.objects[0].shape, &scene.objects[1].shape) else {
        panic!()
    };
    assert!(Arc::ptr_eq(a, b), "cube.obj is read once");
    // cube.obj: 8 vertices, 12 triangles, no normals.
    assert_eq!((a.positions.len(), a.triangles.len(), a.normals.len()), (8, 12, 0));
}

#[test]
fn scene4_values_match_the_file() {
    let Some(scene) = load_shared("scene4_12_point_light_circle_d_attenuation.txt") else { return };
    // center 0 10 10, direction 0 -1.2 -1, angle 50.
    let Camera::Perspective { eye, at, up, fovy } = scene.camera else { panic!() };
    assert_eq!((eye, up), (Vec3::new(0.0, 10.0, 10.0), Vec3::Y));
    approx::assert_abs_diff_eq!(at, Vec3::new(0.0, 8.8, 9.0), epsilon = ROUNDING);
    approx::assert_abs_diff_eq!(fovy, 50.0 * PI / 180.0, epsilon = ROUNDING);
    // PointLight { position 0 2.5 0  color 0.8 0.8 0.8  attenuation 0 0.2 0 }.
    let attenuation = super::super::Attenuation { constant: 0.0, linear: 0.2, quadratic: 0.0 };
    assert_eq!(scene.lights[0].kind, LightKind::Point { position: Vec3::new(0.0, 2.5, 0.0), attenuation });
    // Plane { normal 0 1 0  offset -1 }.
    let Shape::Plane { normal, offset } = scene.objects[0].shape else { panic!() };
    assert_eq!((normal, offset), (Vec3::Y, -1.0));
    // Transform { YRotate 60  Translate 0 0 -3 }: the origin moves to Ry(60°)·(0, 0, -3)
    // = (-3 sin 60°, 0, -3 cos 60°) (in the other order it would stay at (0, 0, -3)).
    let m = scene.objects[3].transform.unwrap().world_from_object;
    let expected = Vec3::new(-3.0 * (3.0 as Float).sqrt() / 2.0, 0.0, -1.5);
    approx::assert_abs_diff_eq!(m.transform_point3(Vec3::ZERO), expected, epsilon = ROUNDING);

    let Some(scene) = load_shared("scene4_05_transparent_bar.txt") else { return };
    // PhongMaterial { diffuseColor 0.3 0.3 0.3  reflectiveColor 0.5 0.5 0.9
    //                 transparentColor 0.5 0.9 0.9  indexOfRefraction 4 }.
    let m = &scene.materials[1];
    assert_eq!((m.diffuse, m.reflective), (Color::splat(0.3), Color::new(0.5, 0.5, 0.9)));
    assert_eq!((m.transparent, m.ior, m.specular), (Color::new(0.5, 0.9, 0.9), 4.0, BLACK));
}

/// Every feature of the format in one file.
const FULL: &str = "PerspectiveCamera {
    center 0 0 10
    direction 0 0 -1
    up 0 1 0
    angle 30
}
Lights {
    numLights 2
    DirectionalLight { direction 0 0 -2 color 1 1 1 }
    PointLight { position 0 5 0 color 0.5 0.5 0.5 attenuation 1 0 0.25 }
}
Background { color 0.125 0.25 0.5 ambientLight 0.5 0.5 0.5 }
Materials {
    numMaterials 2
    Material { diffuseColor 1 0 0 }
    PhongMaterial { diffuseColor 0 1 0 specularColor 1 1 1 exponent 16 reflectiveColor 0.5 0.5 0.5
                    transparentColor 0.25 0.25 0.25 indexOfRefraction 1.5 }
}
Group {
    numObjects 4
    Sphere { center 0 0 0 radius 1 }
    MaterialIndex 1
    Plane { normal 0 2 0 offset -2 }
    Group {
        numObjects 1
        MaterialIndex 0
        Triangle { vertex0 0 0 0 vertex1 1 0 0 vertex2 0 1 0 }
    }
    Transform {
        Translate 1 0 0
        ZRotate 90
        UniformScale 2
        Rotate { axis 1 1 0 angle 180 }
        Matrix { 1 0 0 4  0 1 0 5  0 0 1 6  0 0 0 1 }
        Scale 1 1 1
        XRotate 0
        YRotate 0
        Sphere { center 0 0 0 radius 0.5 }
    }
}
";

#[test]
fn every_construct_reads_to_the_values_written() {
    let scene = parse(FULL).unwrap();
    let Camera::Perspective { fovy, .. } = scene.camera else { panic!() };
    approx::assert_abs_diff_eq!(fovy, FRAC_PI_6, epsilon = ROUNDING); // angle 30
    assert_eq!(scene.lights[0].kind, LightKind::Directional { direction: Vec3::NEG_Z });
    let LightKind::Point { attenuation, .. } = scene.lights[1].kind else { panic!() };
    assert_eq!((attenuation.constant, attenuation.linear, attenuation.quadratic), (1.0, 0.0, 0.25));
    assert_eq!((scene.background, scene.ambient), (Color::new(0.125, 0.25, 0.5), Color::splat(0.5)));
    let phong = &scene.materials[1];
    assert_eq!((phong.specular, phong.exponent, phong.ior), (WHITE, 16.0, 1.5));
    assert_eq!((phong.reflective, phong.transparent), (Color::splat(0.5), Color::splat(0.25)));
    // The first sphere precedes every MaterialIndex: the default material, appended last.
    // MaterialIndex 0 inside the nested group stays in force after it (as in the course's parser).
    let materials: Vec<usize> = scene.objects.iter().map(|o| o.material).collect();
    assert_eq!(materials, [2, 1, 0, 0]);
    assert_eq!(scene.materials[2].name, "default");
    // normal 0 2 0, offset -2: the plane y = -1.
    let Shape::Plane { normal, offset } = scene.objects[1].shape else { panic!() };
    assert_eq!((normal, offset), (Vec3::Y, -1.0));
    // The origin through Matrix (→ (4, 5, 6)), the half turn about (1, 1, 0)
    // (v ↦ 2(a·v)a − v → (5, 4, -6)), UniformScale 2 (→ (10, 8, -12)), ZRotate 90
    // ((x, y) ↦ (−y, x) → (-8, 10, -12)) and Translate 1 0 0: (-7, 10, -12).
    let m = scene.objects[3].transform.unwrap().world_from_object;
    approx::assert_abs_diff_eq!(
        m.transform_point3(Vec3::ZERO),
        Vec3::new(-7.0, 10.0, -12.0),
        epsilon = ROUNDING
    );
}

#[test]
fn tokens_keep_their_line_and_column() {
    let (tokens, end) = tokenize("A{b 1}\r\n\t c\u{e9}  -.5");
    let found: Vec<(&str, usize, usize)> = tokens.iter().map(|t| (t.text, t.line, t.column)).collect();
    // Braces split words; CRLF ends line 1; the tab is one column; é is one character.
    assert_eq!(
        found,
        [("A", 1, 1), ("{", 1, 2), ("b", 1, 3), ("1", 1, 5), ("}", 1, 6), ("c\u{e9}", 2, 3), ("-.5", 2, 7)]
    );
    assert_eq!(end, (2, 10));
}

#[test]
fn camera_and_file_errors() {
    insta::assert_snapshot!(error("PerspectiveCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 angle 180 }"),
        @"scenes/a.txt:1:67: angle must be in (0, 180) degrees, found 180");
    insta::assert_snapshot!(error("OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 0 1 size 5 }"),
        @"scenes/a.txt:1:56: up [0, 0, 1] is zero or parallel to direction [0, 0, -1], to within 10⁻⁶ radians: the camera's roll is undefined");
    // In the format's words: a 6.837 camera has a direction, not an `at`.
    insta::assert_snapshot!(error("OrthographicCamera { center 0 0 10 direction 0 0 0 up 0 1 0 size 5 }"),
        @"scenes/a.txt:1:46: direction must be a non-zero vector, found [0, 0, 0]");
    insta::assert_snapshot!(error("Group { numObjects 0 }"),
        @"scenes/a.txt: no camera: expected an OrthographicCamera or a PerspectiveCamera");
    insta::assert_snapshot!(error(&format!("{CAMERA}{CAMERA}")),
        @"scenes/a.txt:2:1: a second Camera block (the first is at 1:1)");
    insta::assert_snapshot!(error("Camera { }"),
        @"scenes/a.txt:1:1: unexpected `Camera`, expected OrthographicCamera, PerspectiveCamera, Lights, Background, Materials or Group");
    insta::assert_snapshot!(error(&format!("{CAMERA}Materials {{\n    numMaterials 1\n    Marble {{ }}\n}}\n")),
        @"scenes/a.txt:4:14: expected `Transform`, found `}`");
}

#[test]
fn object_errors() {
    insta::assert_snapshot!(group_error(1, "    TriangleMesh { obj_file missing.obj }"),
        @"scenes/a.txt:4:29: obj_file `missing.obj`: scenes/missing.obj: cannot read the mesh file: No such file or directory (os error 2)");
    insta::assert_snapshot!(group_error(3, "    Sphere { center 0 0 0 radius 1 }"),
        @"scenes/a.txt:3:16: numObjects is 3 but the block holds 1");
    insta::assert_snapshot!(group_error(1, "    BezierCurve { }"),
        @"scenes/a.txt:4:5: `BezierCurve` (spline curve of 6.837 assignment 8) is not supported yet");
    insta::assert_snapshot!(group_error(1, "    Sphere { center 0 0 0 radius 1 color 1 0 0 }"),
        @"scenes/a.txt:4:36: unknown key `color` in Sphere, expected center or radius");
    insta::assert_snapshot!(group_error(1, "    Sphere { center 0 0 0 radius -1 }"),
        @"scenes/a.txt:4:34: radius must be > 0, found -1");
    insta::assert_snapshot!(group_error(1, "    Sphere { center 0 0 0 radius abc }"),
        @"scenes/a.txt:4:34: expected a number for radius, found `abc`");
    insta::assert_snapshot!(group_error(1, "    Sphere { center 0 0 0 radius inf }"),
        @"scenes/a.txt:4:34: radius must be a finite number, found inf");
    insta::assert_snapshot!(group_error(0, "    MaterialIndex 2"),
        @"scenes/a.txt:4:19: material index 2 is out of range: the scene has 0 materials");
    insta::assert_snapshot!(group_error(1, "    Triangle { vertex0 0 0 0 vertex1 1 1 1 vertex2 2 2 2 }"),
        @"scenes/a.txt:4:5: the triangle [0, 0, 0], [1, 1, 1], [2, 2, 2] is degenerate: its corners lie on a line");
    insta::assert_snapshot!(group_error(1, "    Transform { Translate 1 0 0 Sphere { center 0 0 0 radius 1 } Sphere { center 0 0 0 radius 1 } }"),
        @"scenes/a.txt:4:66: a Transform holds one object: expected `}` after it, found `Sphere`");
    insta::assert_snapshot!(group_error(1, "    Transform { Scale 1 0 1 Sphere { center 0 0 0 radius 1 } }"),
        @"scenes/a.txt:4:23: scale factors must be non-zero, found [1, 0, 1]");
    // The file ends inside the sphere's center: the error is at the end (line 4, after 23 characters).
    insta::assert_snapshot!(error(&format!("{CAMERA}Group {{\n    numObjects 1\n    Sphere {{ center 0 0")),
        @"scenes/a.txt:4:24: the file ends where a number for center should follow");
}

#[test]
fn truncated_files_never_panic() {
    // Every prefix of a file using every construct: an error or (for the whole file) a scene.
    for (cut, _) in FULL.char_indices() {
        if let Ok(scene) = parse(&FULL[..cut]) {
            assert_usable(&scene, "prefix");
        }
    }
    assert!(parse(FULL).is_ok());
}

#[test]
fn garbage_never_panics() {
    // A deterministic soup of the format's own words (a linear congruential generator).
    let words = [
        "{",
        "}",
        "Group",
        "numObjects",
        "Transform",
        "Sphere",
        "center",
        "radius",
        "MaterialIndex",
        "Materials",
        "numMaterials",
        "PhongMaterial",
        "diffuseColor",
        "Lights",
        "numLights",
        "PointLight",
        "attenuation",
        "OrthographicCamera",
        "direction",
        "up",
        "size",
        "Matrix",
        "Rotate",
        "Scale",
        "Triangle",
        "vertex0",
        "0",
        "1",
        "-1",
        "1e400",
        "nan",
        "18446744073709551616",
        "TriangleMesh",
        "obj_file",
        "Checkerboard",
    ];
    let mut state: u64 = 0x2545_f491_4f6c_dd1d;
    let mut next = |n: usize| {
        state = state.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        (state >> 33) as usize % n
    };
    for _ in 0..2000 {
        let len = next(60);
        let text: Vec<&str> = (0..len).map(|_| words[next(words.len())]).collect();
        if let Ok(scene) = parse(&format!("{CAMERA}{}", text.join(" "))) {
            assert_usable(&scene, "garbage");
        }
    }
}

#[test]
fn huge_counts_and_deep_nesting_are_errors_not_crashes() {
    // A count far beyond the objects that follow: compared, never allocated.
    let message = group_error(4_000_000_000, "    Sphere { center 0 0 0 radius 1 }");
    assert!(message.contains("numObjects is 4000000000 but the block holds 1"), "{message}");
    let message = group_error(1, "    MaterialIndex 99999999999999999999999");
    assert!(message.contains("expected a whole number"), "{message}");
    // Ten thousand nested groups would overflow the stack of a naive parser.
    let deep = format!("{CAMERA}{}", "Group { numObjects 1 ".repeat(10_000));
    assert!(error(&deep).contains(&format!("nest deeper than {MAX_DEPTH} levels")));
}

#[test]
fn a_file_without_lights_shows_flat_diffuse_colour_through_a_white_ambient_light() {
    // Assignment 1 renders each object in its diffuse colour: k_a·I_a = k_d needs I_a = 1.
    let camera = "OrthographicCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 size 5 }";
    let group = "Group { numObjects 1 Sphere { center 0 0 0 radius 1 } }";
    let unlit = parse(&format!("{camera} Background {{ color 0 0 0 }} {group}")).unwrap();
    assert_eq!((unlit.ambient, unlit.lights.len()), (WHITE, 0));
    // With lights, or with an ambient light of its own, a file keeps what it says.
    let lit = parse(&format!(
        "{camera} Lights {{ numLights 1 DirectionalLight {{ direction 0 0 -1 color 1 1 1 }} }} {group}"
    ))
    .unwrap();
    assert_eq!(lit.ambient, BLACK);
    let dim = parse(&format!("{camera} Background {{ ambientLight 0.2 0.2 0.2 }} {group}")).unwrap();
    assert_eq!(dim.ambient, Color::splat(0.2));
}

/// `CAMERA`, then materials 0 (red) and 1 (`second`, lines 4 and 5) and `checkerboard` on line 6.
fn checkerboard_scene(second: &str, checkerboard: &str) -> String {
    format!(
        "{CAMERA}Materials {{\n    numMaterials 3\n    PhongMaterial {{ diffuseColor 1 0 0 specularColor 1 1 1 \
         exponent 64 }}\n    {second}\n    {checkerboard}\n}}\n\
         Group {{ numObjects 1 MaterialIndex 2 Sphere {{ center 0 0 0 radius 1 }} }}\n"
    )
}

const BLUE: &str = "PhongMaterial { diffuseColor 0 0 1 specularColor 1 1 1 exponent 64 }";

/// The material a solid texture over materials 0 and 1 of `scene` makes, as the reader should.
fn solid_of(scene: &Scene, pattern_from_world: Mat4, pattern: SolidPattern) -> Option<Texture> {
    let (a, b) = (Box::new(scene.materials[0].clone()), Box::new(scene.materials[1].clone()));
    Some(Texture::Solid { pattern_from_world, pattern, a, b })
}

#[test]
fn a_checkerboard_is_a_solid_checker_between_two_materials() {
    // The steps compose left to right, M = UniformScale 2 · Translate (0, 1, 0): p′ = 2(p + ŷ).
    // The material carries material 0's properties (red, white highlight, exponent 64).
    let text = checkerboard_scene(
        BLUE,
        "Checkerboard { Transform { UniformScale 2 Translate 0 1 0 } materialIndex 0 materialIndex 1 }",
    );
    let scene = parse(&text).unwrap_or_else(|e| panic!("{e}"));
    let m = &scene.materials[2];
    let pattern_from_world = Mat4::from_scale(Vec3::splat(2.0)) * Mat4::from_translation(Vec3::Y);
    assert_eq!(m.texture, solid_of(&scene, pattern_from_world, SolidPattern::Checker));
    assert_eq!(scene.materials[1].diffuse, Color::new(0.0, 0.0, 1.0));
    assert_eq!((m.diffuse, m.specular, m.exponent), (Color::new(1.0, 0.0, 0.0), WHITE, 64.0));
    assert_eq!(m.blended(), vec![&scene.materials[0], &scene.materials[1]]);
    assert_eq!(scene.objects[0].material, 2);
}

#[test]
fn noise_marble_and_wood_read_their_parameters_in_order() {
    let read = |texture: &str| {
        let scene = parse(&checkerboard_scene(BLUE, texture)).unwrap_or_else(|e| panic!("{texture}: {e}"));
        (scene.materials[2].texture.clone(), scene)
    };
    let (texture, scene) =
        read("Noise { Transform { XRotate 90 } materialIndex 0 materialIndex 1 octaves 5 }");
    let rotated = Mat4::from_rotation_x(radians(90.0));
    assert_eq!(texture, solid_of(&scene, rotated, SolidPattern::Noise { octaves: 5 }));
    let (texture, scene) =
        read("Marble { Transform { } materialIndex 0 materialIndex 1 octaves 0 frequency 3 amplitude 2.5 }");
    let marble = SolidPattern::Marble { octaves: 0, frequency: 3.0, amplitude: 2.5 };
    assert_eq!(texture, solid_of(&scene, Mat4::IDENTITY, marble));
    let (texture, scene) =
        read("Wood { Transform { } materialIndex 0 materialIndex 1 octaves 3 frequency 6 amplitude 2 }");
    let wood = SolidPattern::Wood { octaves: 3, frequency: 6.0, amplitude: 2.0 };
    assert_eq!(texture, solid_of(&scene, Mat4::IDENTITY, wood));
}

#[test]
fn a_solid_texture_of_textured_materials_blends_all_they_blend() {
    // 6.837's logo: a Checkerboard of two Woods. Materials 0 and 1, a noise of them (2), and a
    // checkerboard of 2 and 1 (3): it shows 0 and 1 through 2, and 1 again.
    let text = format!(
        "{CAMERA}Materials {{\n    numMaterials 4\n    PhongMaterial {{ diffuseColor 1 0 0 }}\n    \
         PhongMaterial {{ diffuseColor 0 0 1 reflectiveColor 0.3 0.3 0.3 }}\n    \
         Noise {{ Transform {{ }} materialIndex 0 materialIndex 1 octaves 2 }}\n    \
         Checkerboard {{ Transform {{ }} materialIndex 2 materialIndex 1 }}\n}}\n\
         Group {{ numObjects 1 MaterialIndex 3 Sphere {{ center 0 0 0 radius 1 }} }}\n"
    );
    let scene = parse(&text).unwrap_or_else(|e| panic!("{e}"));
    let m = &scene.materials;
    assert_eq!(m[3].blended(), vec![&m[0], &m[1], &m[1]]);
    let Some(Texture::Solid { a, .. }) = &m[3].texture else { panic!("{:?}", m[3].texture) };
    assert_eq!(**a, m[2]);
}

#[test]
fn checkerboard_errors() {
    // Columns counted in `    Checkerboard { Transform { … } materialIndex a materialIndex b }`.
    let error_of = |second: &str, checkerboard: &str| error(&checkerboard_scene(second, checkerboard));
    insta::assert_snapshot!(error_of("PhongMaterial { diffuseColor 0 0 1 }",
        "Checkerboard { Transform { } materialIndex 0 materialIndex 1 }"),
        @"scenes/a.txt:6:5: a Checkerboard of materials 0 and 1 that differ in exponent or indexOfRefraction is not supported yet (it blends their colours only)");
    insta::assert_snapshot!(error_of(BLUE, "Checkerboard { Transform { } materialIndex 0 materialIndex 7 }"),
        @"scenes/a.txt:6:64: material index 7 is out of range: 2 materials are defined before it");
    insta::assert_snapshot!(error_of(BLUE, "Checkerboard { materialIndex 0 materialIndex 1 }"),
        @"scenes/a.txt:6:20: expected `Transform`, found `materialIndex`");
    insta::assert_snapshot!(error_of(BLUE, "Checkerboard { Transform { Sphere } materialIndex 0 materialIndex 1 }"),
        @"scenes/a.txt:6:32: expected a transformation or `}` in the Checkerboard's Transform, found `Sphere`");
    insta::assert_snapshot!(error_of(BLUE, "Marble { Transform { } materialIndex 0 materialIndex 1 octaves 2 amplitude 1 }"),
        @"scenes/a.txt:6:70: expected `frequency`, found `amplitude`");
    insta::assert_snapshot!(error_of(BLUE, "Noise { Transform { } materialIndex 0 materialIndex 1 octaves 99 }"),
        @"scenes/a.txt:6:67: octaves must be at most 24 (octave 24 is already finer than a Float resolves), found 99");
    insta::assert_snapshot!(error_of(BLUE, "Wood { Transform { } materialIndex 0 materialIndex 1 octaves 2 frequency 1 amplitude nan }"),
        @"scenes/a.txt:6:90: amplitude must be a finite number, found nan");
}

#[test]
fn the_course_checkerboard_scenes_load() {
    // scene6_13: a red/blue checkerboard (UniformScale 2) on the sphere, material 2, and a
    // green/yellow one (UniformScale 0.75) on the floor, material 5. scene7_02: red/blue at
    // UniformScale 10 on two triangles.
    let solid = |scene: &Scene, i: usize, scale: Float| {
        let Some(Texture::Solid { pattern_from_world, pattern, a, b }) = &scene.materials[i].texture else {
            panic!("material {i}: {:?}", scene.materials[i].texture)
        };
        assert_eq!(
            (*pattern_from_world, *pattern),
            (Mat4::from_scale(Vec3::splat(scale)), SolidPattern::Checker)
        );
        (a.diffuse, b.diffuse)
    };
    let (red, blue) = (Color::new(1.0, 0.0, 0.0), Color::new(0.0, 0.0, 1.0));
    if let Some(scene) = load_shared("scene6_13_checkerboard.txt") {
        assert_usable(&scene, "scene6_13");
        assert_eq!(solid(&scene, 2, 2.0), (red, blue));
        assert_eq!(solid(&scene, 5, 0.75).1, Color::new(1.0, 1.0, 0.0));
        assert_eq!((scene.objects[0].material, scene.objects[1].material), (2, 5));
    }
    if let Some(scene) = load_shared("scene7_02_checkerboard.txt") {
        assert_usable(&scene, "scene7_02");
        assert_eq!(solid(&scene, 2, 10.0), (red, blue));
        assert_eq!(scene.materials[2].diffuse, red);
    }
}

/// A transparent colour whose powers overflow down the ray tree is refused in 6.837's words
/// (found by corrupting scene files: `transparentColor 1e15` rendered to an image the writer
/// refused as NaN).
#[test]
fn colours_whose_products_overflow_are_refused_in_the_formats_words() {
    // g = MAX^¼·10: g⁵ (depth 5) is beyond the range in f32 and f64 alike.
    let g = (Float::MAX as f64).powf(0.25) * 10.0;
    let text = format!(
        "{CAMERA}Background {{ color 0.5 0.5 0.5 }}\nMaterials {{\n    numMaterials 1\n    PhongMaterial {{ \
         diffuseColor 1 1 1 transparentColor {g:e} {g:e} {g:e} indexOfRefraction 1.5 }}\n}}\n\
         Group {{\n    numObjects 1\n    MaterialIndex 0\n    Sphere {{ center 0 0 0 radius 1 }}\n}}\n"
    );
    let said = error(&text);
    assert!(said.starts_with("scenes/a.txt: the transparentColor of material 0 = "), "{said}");
    assert!(said.contains("the largest value it may have here is"), "{said}");
}
