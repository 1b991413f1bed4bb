//! (being written)
use super::{Scene, SceneError};
use std::path::Path;
pub fn load_toml(path: &Path) -> Result<Scene, SceneError> {
    let _ = path;
    unimplemented!()
}
pub fn parse_toml(text: &str, path: &Path) -> Result<Scene, SceneError> {
    let _ = (text, path);
    unimplemented!()
}
