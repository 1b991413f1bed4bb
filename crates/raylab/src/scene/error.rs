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
    /// An error at `line` and `column` of `file`; values quoted in `message`
    /// longer than 40 characters are cut with an ellipsis ([`cut`]).
    pub fn new(file: impl Into<PathBuf>, line: usize, column: usize, message: impl Into<String>) -> Self {
        Self { file: file.into(), line, column, message: cut(&message.into()) }
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

/// The longest value quoted in a message; longer ones end in "…".
const QUOTED: usize = 40;

/// `message` with every quoted value (between backquotes or double quotes)
/// longer than 40 characters cut to its first 39 and an ellipsis.
pub fn cut(message: &str) -> String {
    let mut out = String::with_capacity(message.len().min(400));
    let mut rest = message;
    while let Some(open) = rest.find(['`', '"']) {
        let quote = rest[open..].chars().next().unwrap_or('`');
        out.push_str(&rest[..=open]);
        let after = &rest[open + 1..];
        let close = after.find(quote).unwrap_or(after.len());
        let value = &after[..close];
        if value.chars().count() > QUOTED {
            out.extend(value.chars().take(QUOTED - 1));
            out.push('…');
        } else {
            out.push_str(value);
        }
        rest = &after[close..];
        if let Some(q) = rest.chars().next() {
            out.push(q);
            rest = &rest[q.len_utf8()..];
        }
    }
    out.push_str(rest);
    // A number without quotes (a 100,000-digit literal in an overflow message) is cut too.
    out.split(' ')
        .map(|w| {
            if w.chars().count() > 2 * QUOTED {
                format!("{}…", w.chars().take(QUOTED - 1).collect::<String>())
            } else {
                w.to_owned()
            }
        })
        .collect::<Vec<_>>()
        .join(" ")
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
    fn long_values_are_cut_with_an_ellipsis() {
        let long = "9".repeat(100_000);
        let said = SceneError::new("a.txt", 1, 1, format!("radius must be a number, found `{long}`")).message;
        assert_eq!(said, format!("radius must be a number, found `{}…`", "9".repeat(39)));
        let said = SceneError::new("a.txt", 1, 1, format!("expected a number, found {long}")).message;
        assert_eq!(said, format!("expected a number, found {}…", "9".repeat(39)));
        assert_eq!(cut("short `values` stay \"as they are\""), "short `values` stay \"as they are\"");
    }

    #[test]
    fn whole_file_errors_print_without_position() {
        assert_eq!(SceneError::new("a.toml", 0, 0, "empty").to_string(), "a.toml: empty");
        assert_eq!(SceneError::new("a.toml", 3, 7, "bad").to_string(), "a.toml:3:7: bad");
    }
}
