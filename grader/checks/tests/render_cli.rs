//! The `grader render` command end to end: a real process, real files.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use raylab::{Float, Image, Vec3};

fn grader(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_raylab-checks")).args(args).output().expect("the grader runs")
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raylab-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A unit sphere at the origin seen by an orthographic camera from z = 5,
/// 4 world units of view on 8×8 pixels: the answers are known by hand.
const SPHERE: &str = r#"
[image]
width = 8
height = 8

[camera]
type = "orthographic"
eye = [0, 0, 5]
at = [0, 0, 0]
height = 4

[[lights]]
type = "directional"
direction = [0, 0, -1]

[[objects]]
type = "sphere"
center = [0, 0, 0]
radius = 1
"#;

fn write_scene(dir: &Path) -> PathBuf {
    let path = dir.join("sphere.toml");
    std::fs::write(&path, SPHERE).unwrap();
    path
}

#[test]
fn depth_and_normal_aovs_match_the_analytic_sphere() {
    let dir = temp_dir("aov");
    let scene = write_scene(&dir);
    let depth = dir.join("depth.exr");
    let out = grader(&["render", scene.to_str().unwrap(), "--aov", "depth", "-o", depth.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let normal = dir.join("normal.exr");
    let out = grader(&["render", scene.to_str().unwrap(), "--aov", "normal", "-o", normal.to_str().unwrap()]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let (depth, normal) = (Image::load_exr(&depth).unwrap(), Image::load_exr(&normal).unwrap());
    // Pixel (3, 3) has its centre at screen (−0.125, 0.125), world (−0.25, 0.25): the ray
    // meets the sphere at z = √(1 − 0.125) = 0.935414…, depth 5 − z, normal (−0.25, 0.25, z).
    let z = (1.0 - 0.125 as Float).sqrt();
    // Tolerance: a few f32 roundings of values near 5 (the EXR stores f32).
    approx::assert_abs_diff_eq!(depth.get(3, 3).x, 5.0 - z, epsilon = 1e-5);
    approx::assert_abs_diff_eq!(normal.get(3, 3), Vec3::new(-0.25, 0.25, z), epsilon = 1e-5);
    // Pixel (0, 0) is at world (−1.75, 1.75): outside the sphere, so 0 in both.
    assert_eq!(depth.get(0, 0), Vec3::ZERO);
    assert_eq!(normal.get(0, 0), Vec3::ZERO);
}

#[test]
fn stats_json_has_the_documented_keys_and_counts() {
    let dir = temp_dir("stats");
    let scene = write_scene(&dir);
    let png = dir.join("out.png");
    let out = grader(&[
        "render",
        scene.to_str().unwrap(),
        "--stats",
        "--json",
        "--size",
        "4x3",
        "-o",
        png.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    // 4×3 pixels, one primary ray each. Pixel centres sit at world x = ±2/3, ±2 and
    // y = 0, ±4/3 (view 16/3 × 4): only (±2/3, 0) fall inside the unit disc, and each of
    // those two lit points casts one shadow ray. One object tested per ray: 12 + 2.
    insta::assert_snapshot!(String::from_utf8_lossy(&out.stdout), @r#"
    {
      "rays.primary": 12,
      "rays.shadow": 2,
      "rays.reflection": 0,
      "rays.refraction": 0,
      "intersection_tests": 14
    }
    "#);
    let image = Image::load_png(&png).unwrap();
    assert_eq!((image.width, image.height), (4, 3));
}

#[test]
fn a_bad_scene_is_an_error_naming_file_line_and_column_not_a_panic() {
    let dir = temp_dir("bad");
    let scene = dir.join("bad.toml");
    std::fs::write(&scene, SPHERE.replace("radius = 1", "radius = -2")).unwrap();
    let out = grader(&["render", scene.to_str().unwrap(), "-o", dir.join("x.png").to_str().unwrap()]);
    assert!(!out.status.success());
    // Line 19 of SPHERE (its first line is empty) holds `radius`; the value starts in column 10.
    let stderr = String::from_utf8_lossy(&out.stderr).replace(scene.to_str().unwrap(), "bad.toml");
    insta::assert_snapshot!(stderr, @"error: bad.toml:19:10: radius must be > 0, found -2");
    assert!(!dir.join("x.png").exists());
}

/// All 96 scene files of the 6.837 assignments render, the procedural textures of assignment 6
/// (Noise, Marble, Wood) included: each at 48×48 with its own flags' defaults, to a PNG (which
/// the renderer refuses to write with a non-finite pixel), not blank.
#[test]
fn every_mit6837_scene_renders() {
    let Some(dir) = raylab::data::shared_data("mit6837", "the 96 scene files of the 6.837 assignments")
    else {
        return;
    };
    let out_dir = temp_dir("mit");
    let mut rendered = 0;
    let mut names: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
    names.sort();
    for path in names {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        if !(name.starts_with("scene") && name.ends_with(".txt")) {
            continue;
        }
        let png = out_dir.join(name.replace(".txt", ".png"));
        // 48×48 keeps the 40k-triangle bunny and the finest vase quick.
        let out = grader(&["render", path.to_str().unwrap(), "--size", "48x48", "-o", png.to_str().unwrap()]);
        assert!(out.status.success(), "{name}: {}", String::from_utf8_lossy(&out.stderr));
        let image = Image::load_png(&png).unwrap();
        assert!(image.pixels.iter().any(|&c| c != image.pixels[0]), "{name}: a blank image");
        rendered += 1;
    }
    assert_eq!(rendered, 96, "the 6.837 assignments have 96 scene files");
}

#[test]
fn supersampling_the_receding_checker_brings_it_closer_to_the_converged_image() {
    // Lecture 10's aliasing scene at 1, 16 and 256 jittered rays per pixel: 256 stands in
    // for the converged image; 16 must be nearer to it than 1 is (mean absolute error over
    // all pixels and channels), which is the speed/accuracy trade of supersampling.
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let scene = root.join("lectures/10-textures-sampling/scenes/checker-aliasing-1spp.toml");
    let dir = temp_dir("spp");
    let render = |spp: &str| {
        let png = dir.join(format!("spp{spp}.png"));
        let out = grader(&[
            "render",
            scene.to_str().unwrap(),
            "--size",
            "80x48",
            "--spp",
            spp,
            "--pattern",
            "jittered",
            "-o",
            png.to_str().unwrap(),
        ]);
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        Image::load_png(&png).unwrap()
    };
    let (one, sixteen, converged) = (render("1"), render("16"), render("256"));
    let error = |image: &Image| {
        let total: Float =
            image.pixels.iter().zip(&converged.pixels).map(|(a, b)| (*a - *b).abs().element_sum()).sum();
        total / (3 * image.pixels.len()) as Float
    };
    let (e1, e16) = (error(&one), error(&sixteen));
    eprintln!("mean absolute error against 256 spp: 1 spp {e1:.4}, 16 spp {e16:.4}");
    assert!(e16 < 0.5 * e1, "16 spp ({e16}) should at least halve the error of 1 spp ({e1})");
}

#[test]
#[cfg(unix)]
fn ctrl_c_stops_a_long_render_cleanly_without_writing_the_image() {
    use std::io::Read;
    let dir = temp_dir("interrupt");
    let scene = write_scene(&dir);
    let png = dir.join("out.png");
    // 2000×2000 pixels × 64 eye rays: minutes of work, stopped after half a second.
    let mut child = Command::new(env!("CARGO_BIN_EXE_raylab-checks"))
        .args(["render", scene.to_str().unwrap(), "--size", "2000x2000", "--spp", "64", "--allow-large"])
        .args(["-o", png.to_str().unwrap()])
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the grader runs");
    std::thread::sleep(std::time::Duration::from_millis(500));
    // SIGINT, as the terminal sends it on Ctrl-C.
    let kill = Command::new("kill").args(["-INT", &child.id().to_string()]).status().expect("kill runs");
    assert!(kill.success());
    let status = child.wait().unwrap();
    let mut stderr = String::new();
    child.stderr.take().unwrap().read_to_string(&mut stderr).unwrap();
    assert_eq!(status.code(), Some(130), "{status:?}: {stderr}");
    assert!(
        stderr.contains(&format!("interrupted: the render was stopped, {} not written", png.display())),
        "{stderr}"
    );
    assert!(!png.exists());
}
