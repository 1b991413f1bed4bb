//! What lecture 08 lends the stages (`stages::Lent`): stage 08's Whitted tracer over 04's brute
//! force (no textures), the tracer's settings a scene asks for, its ray trees as the report's
//! data, and the trace's calls on a picture's path, which stage 10 makes too.

use l08_ray_tree::{RayKind, RayTree, SurfaceMaterial, TraceSettings, World};
use raylab::{Color, Scene};

use crate::path::Trail;
use crate::stages::{Drawer, Draws, Lent};
use crate::trees::{Kind, TreeNode};
use raylab_checks_l05::stage::{AtHit, Lights, Walk, walk};
use raylab_checks_l06::stage::{Shadowed, shadow_settings};
use raylab_checks_l07::stage::directions;

/// Lends stage 08's drawing.
pub fn lend(lent: &mut Lent) {
    let render =
        |scene: &Scene| l08_ray_tree::render_scene(scene, &scene_settings(scene)).map(|(image, _)| image);
    let calls =
        |stage: &str, scene: &Scene, pixel, trail: &mut Trail| walk(&Whitted, stage, scene, pixel, trail);
    lent.drawers
        .push((Draws::Whitted, Drawer::Traces { render, traced, calls, pixel_loop: |_| "08/render" }));
}

/// The tracer's settings for `scene`: what its `[render]` table says, and
/// [`TraceSettings::default`] for what it does not (6.837 files say nothing); the shadow settings
/// are [`shadow_settings`]'s.
pub fn scene_settings(scene: &Scene) -> TraceSettings {
    let (own, default) = (scene.render, TraceSettings::default());
    let shadows = shadow_settings(scene);
    TraceSettings {
        max_depth: own.max_depth.unwrap_or(default.max_depth),
        min_weight: own.min_weight.unwrap_or(default.min_weight),
        shadow_mode: shadows.mode,
        area_samples: shadows.area_samples,
        ..default
    }
}

/// The colours and ray trees of `pixels` of `scene` at stage 08.
fn traced(scene: &Scene, pixels: &[(u32, u32)]) -> Option<Vec<(Color, TreeNode)>> {
    let camera = l01_transforms::Camera::from_scene(&scene.camera, scene.width, scene.height).ok()?;
    let objects = l04_quadrics_transforms::BruteForce::new(&scene.objects);
    let world = World::new(scene, &objects);
    let settings = scene_settings(scene);
    let trace = |&(x, y): &(u32, u32)| {
        let (color, tree) = l08_ray_tree::trace_recorded(
            &world,
            &camera.pixel_ray(x, y, scene.width, scene.height),
            &settings,
        );
        (color, tree_node(&tree))
    };
    Some(pixels.iter().map(trace).collect())
}

/// Lecture 08's ray tree as the report's data (`trees::TreeNode`), which prints as it does.
pub fn tree_node(tree: &RayTree) -> TreeNode {
    let kind = match tree.kind {
        RayKind::Eye => Kind::Eye,
        RayKind::Shadow => Kind::Shadow,
        RayKind::Reflected => Kind::Reflected,
        RayKind::Transmitted => Kind::Transmitted,
    };
    let children = tree.children.iter().map(tree_node).collect();
    TreeNode::new(kind, tree.origin, tree.dir, tree.weight, tree.hit, children)
}

/// Stage 08's calls: stage 06's lights, 07's directions (with the Fresnel split where the
/// settings ask for it), then the traced colour.
struct Whitted;

impl Walk for Whitted {
    fn lights(&self) -> &dyn Lights {
        &Shadowed
    }

    fn after(&self, trail: &mut Trail, at: &AtHit) {
        directions(trail, at, scene_settings(at.scene).fresnel);
        trace(trail, at, None);
    }
}

/// The colour lecture 08's `trace` gives the pixel's centre ray (stages 08 and 10: at 10 with
/// the textures, `surface`, and the hierarchy), the last call on the path.
pub fn trace(trail: &mut Trail, at: &AtHit, surface: Option<SurfaceMaterial>) {
    let settings = scene_settings(at.scene);
    let mut world = World::new(at.scene, at.objects);
    if let Some(surface) = surface {
        world = world.with_surface(surface);
    }
    let color = l08_ray_tree::trace(&world, at.ray, 0, 1.0, &settings);
    trail.push("08/trace_ray", "the colour of the pixel's centre ray, traced", &color);
}

#[cfg(test)]
mod tests {
    use raylab::{Float, Vec3};

    use super::*;

    fn node(kind: RayKind, origin: Vec3, dir: Vec3, hit: Option<(usize, Float)>, weight: Float) -> RayTree {
        RayTree { kind, origin, dir, hit, weight, children: Vec::new() }
    }

    /// A tree as data prints as lecture 08's `RayTree` prints: numbers rounded to three decimals
    /// as printed (−0.0004 prints 0.000 either way, 2.0006 as 2.001), through JSON and back.
    #[test]
    fn a_tree_as_data_prints_as_the_tree() {
        let mut tree = node(
            RayKind::Eye,
            Vec3::new(0.0, 2.2, 6.5),
            Vec3::new(0.24744, -0.0004, -0.9689),
            Some((2, 5.6096)),
            1.0,
        );
        let mut inside =
            node(RayKind::Transmitted, Vec3::new(1.38549, 1.0426, 1.1878), Vec3::Z, Some((2, 2.0006)), 0.9);
        inside.children.push(node(RayKind::Shadow, Vec3::ONE, Vec3::X, Some((1, 0.836)), 0.9));
        tree.children = vec![
            node(RayKind::Shadow, Vec3::ONE, Vec3::Y, None, 1.0),
            node(RayKind::Reflected, Vec3::ONE, -Vec3::Y, None, 0.1),
            inside,
        ];
        let data = tree_node(&tree);
        assert_eq!(data.to_string(), tree.to_string());
        let json = serde_json::to_string(&data).unwrap();
        let back: TreeNode = serde_json::from_str(&json).unwrap();
        assert_eq!(back, data);
        assert!(tree.to_string().contains("hits #2 at t = 2.001"), "{tree}");
        // A student's NaN direction and infinite t reach the report: null in JSON, NaN read back.
        let broken =
            node(RayKind::Eye, Vec3::ZERO, Vec3::new(Float::NAN, 0.0, -1.0), Some((0, Float::INFINITY)), 1.0);
        let json = serde_json::to_string(&tree_node(&broken)).unwrap();
        assert_eq!(json, r#"{"k":"e","o":[0.0,0.0,0.0],"d":[null,0.0,-1.0],"w":1.0,"h":[0,null]}"#);
        let back: TreeNode = serde_json::from_str(&json).unwrap();
        assert_eq!(
            back.to_string(),
            "eye from (0.000, 0.000, 0.000) dir (NaN, 0.000, -1.000) weight 1.000: hits #0 at t = NaN\n"
        );
        // Empty fields are left out: a ray that misses and has no children is kind, origin, dir,
        // weight (the second child, the reflected ray).
        let whole = serde_json::to_string(&data).unwrap();
        let reflected = r#"{"k":"r","o":[1.0,1.0,1.0],"d":[0.0,-1.0,0.0],"w":0.1}"#;
        assert!(whole.contains(&format!("{reflected},")), "{whole}");
    }
}
