//! `grader render --tree X,Y` prints the ray tree of one pixel: a snapshot of a
//! glass sphere's pixel (lecture 07's scene; lecture 08 snapshots two pixels of
//! its own Whitted scene).

use std::process::Command;

#[test]
fn the_tree_of_a_glass_sphere_pixel_reads_as_the_ray_tree_of_the_slides() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let scene = root.join("lectures/07-reflection-refraction/scenes/glass-spheres.toml");
    let out_png = std::env::temp_dir().join(format!("raylab-tree-{}.png", std::process::id()));
    let out = Command::new(env!("CARGO_BIN_EXE_raylab-checks"))
        .args(["render", scene.to_str().unwrap(), "--tree", "100,75", "-o", out_png.to_str().unwrap()])
        .output()
        .expect("the grader runs");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    // Read as the slides draw it: the eye ray hits the middle sphere (#2); its k_r = 0.1
    // and k_t = 0.9 split the weight; inside, the transmitted ray meets the back wall
    // of the same sphere (t = 1.482 both ways, a chord), the shadow ray from there is
    // blocked by the sphere itself (opaque shadows), and the light rays that leave
    // end on the floor or in the background. Branches under 0.01 are not spawned.
    let stdout = String::from_utf8_lossy(&out.stdout);
    insta::assert_snapshot!("glass_sphere_pixel_100_75", stdout);
}
