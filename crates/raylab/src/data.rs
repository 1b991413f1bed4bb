//! Where the shared test data lives: `../shared/data` beside the workspace
//! (the MIT 6.837 scenes and the Stanford bunny, which the project does not
//! ship). Tests that need it skip loudly when it is absent.

use std::path::PathBuf;

/// The workspace root (the folder of the top-level `Cargo.toml`).
pub fn workspace_root() -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../.."))
}

/// The shared data folder: `$RAYLAB_SHARED_DATA` if set, else
/// `<workspace>/../shared/data`; `None` when it does not exist.
pub fn shared_data_dir() -> Option<PathBuf> {
    let dir = match std::env::var_os("RAYLAB_SHARED_DATA") {
        Some(d) => PathBuf::from(d),
        None => workspace_root().join("../shared/data"),
    };
    dir.is_dir().then_some(dir)
}

/// The path of `relative` inside the shared data, or `None` after printing a
/// loud SKIPPED line naming `what` (so a skipped test is never a silent pass).
pub fn shared_data(relative: &str, what: &str) -> Option<PathBuf> {
    let found = shared_data_dir().map(|d| d.join(relative)).filter(|p| p.exists());
    if found.is_none() {
        eprintln!(
            "SKIPPED {what}: ../shared/data/{relative} is not here (set RAYLAB_SHARED_DATA to the shared data folder)"
        );
    }
    found
}
