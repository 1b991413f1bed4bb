//! `grader bless`: the snapshots written from the reference (instructors').

use crate::path;
use crate::scenes::{SceneFile, calls_snapshot, scene_files, trees_snapshot};
use crate::stages::{self, FINAL_STAGE};
use raylab::Scene;

/// Writes the expected trees of the report's grid of pixels for `file` at `stage`.
#[cfg(feature = "complete")]
fn bless_trees(file: &SceneFile, stage: &str, scene: &Scene) -> Result<(), String> {
    let trees =
        stages::grid_trees(stage, scene).ok_or_else(|| format!("stage {stage} is not in this build"))?;
    let grid =
        crate::trees::GridTrees { grid: crate::trees::GRID, width: scene.width, height: scene.height, trees };
    let path = trees_snapshot(file, stage);
    let json = serde_json::to_string(&grid).map_err(|e| e.to_string())?;
    std::fs::write(&path, json + "\n").map_err(|e| format!("{}: {e}", path.display()))
}

/// Writes the reference's calls on the picture's path at the report's grid of pixels for `file`
/// at `stage`, where the stage has calls ([`stages::calls`]).
#[cfg(feature = "complete")]
fn bless_calls(file: &SceneFile, stage: &str, scene: &Scene) -> Result<(), String> {
    let pixels = crate::trees::grid(scene.width, scene.height);
    let Some(calls) = pixels.iter().map(|&p| stages::calls(stage, scene, p)).collect::<Option<Vec<_>>>()
    else {
        return Ok(());
    };
    let grid = path::GridCalls::new(scene.width, scene.height, calls);
    let path = calls_snapshot(file, stage);
    let json = serde_json::to_string(&grid).map_err(|e| e.to_string())?;
    std::fs::write(&path, json + "\n").map_err(|e| format!("{}: {e}", path.display()))
}

/// `grader bless`: writes every scene's snapshots (or one lecture's) from
/// the current code: `S.png` by the scene's stage, `S.final.png` by the
/// complete tracer (scenes of lectures 01–09, at the final pictures' size:
/// `SceneFile::drawn_by`), and the geometry images.
#[cfg(feature = "complete")]
pub fn bless(only: Option<&str>) -> Result<(), String> {
    use crate::lectures::l10::tracer::{Aov, render_scene, scene_sampling, scene_settings};
    for file in scene_files(only)? {
        let load = |stage| file.drawn_by(stage).map_err(|e| e.to_string());
        let scene = load(&file.lecture)?;
        std::fs::create_dir_all(&file.snapshots).map_err(|e| format!("{}: {e}", file.snapshots.display()))?;
        let error = |e: raylab::ImageError| e.to_string();
        let render = |scene: &Scene, aov| {
            render_scene(scene, aov, &scene_settings(scene), scene_sampling(scene)).map(|(image, _)| image)
        };
        stages::render(&file.lecture, &scene)?.save_png(file.snapshot(".png")).map_err(error)?;
        if file.lecture != FINAL_STAGE {
            render(&load(FINAL_STAGE)?, None)?.save_png(file.snapshot(".final.png")).map_err(error)?;
        }
        for stage in stages::drawing(&file) {
            let scene = load(stage)?;
            bless_trees(&file, stage, &scene)?;
            bless_calls(&file, stage, &scene)?;
        }
        let render = |aov| render(&scene, aov);
        render(Some(Aov::Id))?.save_png(file.snapshot(".id.png")).map_err(error)?;
        render(Some(Aov::Depth))?.save_exr(file.snapshot(".depth.exr")).map_err(error)?;
        render(Some(Aov::Normal))?.save_exr(file.snapshot(".normal.exr")).map_err(error)?;
        println!("blessed {}/{}", file.folder, file.name());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::trees::GridTrees;
    use raylab::Float;

    /// Every scene, at each stage that draws it, has its blessed trees, of its grid, as the
    /// reference traces them today. In f32, the precision they are blessed in, equal to the
    /// last printed digit. In f64 the structure alone (kinds, hit objects, children): its numbers
    /// are not f32's — 0.06 apart at 10⁴ from the origin (06's far-from-origin, a ray's t of 55
    /// is 55.690 in f32 and 55.712 in f64), and an area light's samples land elsewhere (06's
    /// soft-shadows-sphere) — which the pictures' comparison tolerates in its thresholds.
    #[test]
    fn every_tree_stage_scene_has_its_current_blessed_trees() {
        crate::lectures::install();
        /// `a` against `b` as JSON values: the same shape and keys, numbers equal in f32 (any in
        /// f64), a hit's object (`h`'s first number) equal in both.
        fn same(a: &serde_json::Value, b: &serde_json::Value, at: &str) -> Result<(), String> {
            use serde_json::Value;
            let fits = match (a, b) {
                (Value::Number(x), Value::Number(y)) => size_of::<Float>() == 8 || x.as_f64() == y.as_f64(),
                (Value::Array(x), Value::Array(y)) if x.len() == y.len() => {
                    return x
                        .iter()
                        .zip(y)
                        .enumerate()
                        .try_for_each(|(i, (x, y))| same(x, y, &format!("{at}/{i}")));
                }
                (Value::Object(x), Value::Object(y)) if x.keys().eq(y.keys()) => {
                    if let (Some(x), Some(y)) = (x.get("h"), y.get("h"))
                        && x[0] != y[0]
                    {
                        return Err(format!("{at}: h blessed {x}, traced {y}"));
                    }
                    return x.iter().try_for_each(|(key, x)| same(x, &y[key], &format!("{at}.{key}")));
                }
                _ => a == b,
            };
            if fits { Ok(()) } else { Err(format!("{at}: blessed {a}, traced {b}")) }
        }
        let mut checked = 0;
        let mut wrong = Vec::new();
        for file in scene_files(None).unwrap() {
            for stage in stages::drawing(&file) {
                let scene = file.drawn_by(stage).unwrap();
                let path = trees_snapshot(&file, stage);
                let Ok(text) = std::fs::read_to_string(&path) else {
                    wrong.push(format!("{}: missing (grader bless)", path.display()));
                    continue;
                };
                let blessed: GridTrees = serde_json::from_str(&text).unwrap();
                let pixels = crate::trees::grid(scene.width, scene.height);
                assert_eq!(
                    (blessed.grid, blessed.width, blessed.height),
                    (crate::trees::GRID, scene.width, scene.height)
                );
                let traced = stages::grid_trees(stage, &scene).unwrap();
                assert_eq!(blessed.trees.len(), traced.len(), "{}", path.display());
                for ((b, t), (x, y)) in blessed.trees.iter().zip(&traced).zip(pixels) {
                    let (b, t) = (serde_json::to_value(b).unwrap(), serde_json::to_value(t).unwrap());
                    if let Err(e) = same(&b, &t, &format!("{} pixel ({x}, {y})", path.display())) {
                        wrong.push(e);
                    }
                }
                checked += 1;
            }
        }
        // The 46 scenes at their own stage, the 41 of lectures 01–09 at stage 10 too.
        assert_eq!(checked, 46 + 41);
        assert!(
            wrong.is_empty(),
            "{} trees differ:\n{}",
            wrong.len(),
            wrong[..wrong.len().min(20)].join("\n")
        );
    }
}
