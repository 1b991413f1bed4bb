//! (being written)
use super::{Scene, SceneError};
use std::path::Path;
pub fn load_mit6837(path: &Path) -> Result<Scene, SceneError> {
    let _ = path;
    unimplemented!()
}
