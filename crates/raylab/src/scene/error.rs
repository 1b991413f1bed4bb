//! Scene errors: every one names the file, the line and column, and what was expected.

use std::fmt;
use std::path::PathBuf;

/// A scene file that could not be read, with where and why.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneError {
    pub file: PathBuf,
    /// 1-based line and column; 0 when the error concerns the whole file.
    pub line: usize,
    pub column: usize,
    pub message: String,
}

impl SceneError {
    pub fn new(file: impl Into<PathBuf>, line: usize, column: usize, message: impl Into<String>) -> Self {
        Self { file: file.into(), line, column, message: message.into() }
    }
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line == 0 {
            write!(f, "{}: {}", self.file.display(), self.message)
        } else {
            write!(f, "{}:{}:{}: {}", self.file.display(), self.line, self.column, self.message)
        }
    }
}

impl std::error::Error for SceneError {}
