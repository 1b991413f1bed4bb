//! The lectures' scenes, `lectures/NN-name/scenes/S.toml`, and the names of what is blessed
//! beside them in `lectures/NN-name/snapshots/`: the picture of each stage that draws the scene
//! (`S.png` by its lecture's, `S.final.png` by the complete tracer), the geometry images
//! (`S.id.png`, `S.depth.exr`, `S.normal.exr`), and at the report's grid of pixels the ray trees
//! (`S.trees.json`, `S.final.trees.json`) and the calls on the picture's path (`S.calls.json`,
//! `S.final.calls.json`). A leaf: it knows no stage and no check.
//!
//! The final pictures (an earlier lecture's scene drawn by the complete tracer) are drawn at half
//! the scene's width and height ([`SceneFile::drawn_by`]): a quarter of the pixels, and of lecture
//! 10's grade (41 scenes drawn again by the student's own code, on every try).

use std::path::{Path, PathBuf};

/// One lecture scene.
#[derive(Clone, Debug)]
pub struct SceneFile {
    /// `02`.
    pub lecture: String,
    /// `02-ray-casting`.
    pub folder: String,
    pub scene: PathBuf,
    pub snapshots: PathBuf,
}

impl SceneFile {
    pub fn name(&self) -> String {
        self.scene.file_stem().unwrap_or_default().to_string_lossy().into_owned()
    }

    pub fn snapshot(&self, suffix: &str) -> PathBuf {
        self.snapshots.join(format!("{}{suffix}", self.name()))
    }

    /// The scene as stage `stage` draws it: as the file says at its own lecture's stage; at
    /// another's (the complete tracer's final picture of an earlier lecture's scene) at
    /// 1/[`FINAL_SHRINK`] of its width and height, rounded up, the camera's view the same (the
    /// pixel grid is coarser, the picture is not cropped). Its own lecture's picture grades each
    /// exercise at full size; the final picture grades the complete tracer's code on the scene,
    /// for a quarter of the drawing.
    pub fn drawn_by(&self, stage: &str) -> Result<raylab::Scene, raylab::scene::SceneError> {
        let mut scene = raylab::scene::load(&self.scene)?;
        if stage != self.lecture {
            scene.width = scene.width.div_ceil(FINAL_SHRINK);
            scene.height = scene.height.div_ceil(FINAL_SHRINK);
        }
        Ok(scene)
    }
}

/// How much smaller a final picture is than its lecture's, in width and in height.
pub const FINAL_SHRINK: u32 = 2;

/// The workspace root: this crate lives in `<root>/grader/checks/core`.
pub fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../..")
}

/// Every `lectures/NN-*/scenes/*.toml`, sorted; only lecture `only` if given
/// (`02` or `02-ray-casting`).
pub fn scene_files(only: Option<&str>) -> Result<Vec<SceneFile>, String> {
    let lectures = workspace_root().join("lectures");
    let mut found = Vec::new();
    for lecture in sorted_entries(&lectures)? {
        let folder = lecture.file_name().unwrap_or_default().to_string_lossy().into_owned();
        if only.is_some_and(|o| !folder.starts_with(o)) || !lecture.join("scenes").is_dir() {
            continue;
        }
        for scene in sorted_entries(&lecture.join("scenes"))? {
            if scene.extension().is_some_and(|e| e == "toml") {
                found.push(SceneFile {
                    lecture: folder.chars().take(2).collect(),
                    folder: folder.clone(),
                    scene,
                    snapshots: lecture.join("snapshots"),
                });
            }
        }
    }
    Ok(found)
}

fn sorted_entries(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let entries = std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut paths: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
    paths.sort();
    Ok(paths)
}

/// The snapshot of `file` drawn by stage `stage`: `S.png` by its own lecture's stage, `S.final.png` by
/// the complete tracer.
pub fn stage_snapshot(file: &SceneFile, stage: &str) -> PathBuf {
    file.snapshot(if stage == file.lecture { ".png" } else { ".final.png" })
}

/// The blessed ray trees of the report's grid of pixels beside [`stage_snapshot`]: `S.trees.json`,
/// `S.final.trees.json` (see `stages::grid_trees`).
pub fn trees_snapshot(file: &SceneFile, stage: &str) -> PathBuf {
    file.snapshot(if stage == file.lecture { ".trees.json" } else { ".final.trees.json" })
}

/// The blessed calls on the picture's path at the grid's pixels beside [`stage_snapshot`]:
/// `S.calls.json`, `S.final.calls.json` (see the `path` module), for the stages that have them.
pub fn calls_snapshot(file: &SceneFile, stage: &str) -> PathBuf {
    file.snapshot(if stage == file.lecture { ".calls.json" } else { ".final.calls.json" })
}
