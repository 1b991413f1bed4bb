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

    /// An error at byte `offset` of the file's `text`, located as 1-based line
    /// and column (the column counts characters, so a tab or a `é` is one).
    pub fn at_offset(
        file: impl Into<PathBuf>,
        text: &str,
        offset: usize,
        message: impl Into<String>,
    ) -> Self {
        let (line, column) = line_column(text, offset);
        Self::new(file, line, column, message)
    }
}

/// The 1-based line and column of byte `offset` in `text` (an offset past the
/// end, or inside a character, is taken to the nearest character boundary
/// before it).
pub fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let mut offset = offset.min(text.len());
    while !text.is_char_boundary(offset) {
        offset -= 1;
    }
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    (line, before[line_start..].chars().count() + 1)
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn offsets_map_to_one_based_line_and_character_column() {
        // "ab\ncé\r\nd": 'a' at 0, 'c' at 3, 'é' (2 bytes) at 4, '\r' at 6, 'd' at 8.
        let text = "ab\ncé\r\nd";
        assert_eq!(line_column(text, 0), (1, 1));
        assert_eq!(line_column(text, 3), (2, 1));
        assert_eq!(line_column(text, 6), (2, 3), "é counts as one column");
        assert_eq!(line_column(text, 8), (3, 1), "CRLF ends a line once");
        assert_eq!(line_column(text, 5), (2, 2), "inside é: taken back to its start");
        assert_eq!(line_column(text, 99), (3, 2), "past the end: the end");
    }

    #[test]
    fn whole_file_errors_print_without_position() {
        assert_eq!(SceneError::new("a.toml", 0, 0, "empty").to_string(), "a.toml: empty");
        assert_eq!(SceneError::new("a.toml", 3, 7, "bad").to_string(), "a.toml:3:7: bad");
    }
}
