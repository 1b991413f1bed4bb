//! The TOML reader's own errors (syntax, types, unknown and missing keys,
//! duplicates) in the words of the scene format: the key and its path
//! (`materials.glass.texture`, `objects[2].radius`), what was found and what
//! was expected, never a Rust type name; a duplicate names both lines; a
//! value longer than 40 characters is cut with an ellipsis.

use std::ops::Range;

use super::error::cut;

/// `message` (from the `toml` crate, about the bytes `span` of `text`) in the
/// scene format's words.
pub fn explain(text: &str, span: Option<Range<usize>>, message: &str) -> String {
    let message = message.trim().replace('\n', "; ");
    let Some(span) = span else { return cut(&message) };
    let start = span.start.min(text.len());
    // A span over the whole file (a key missing at the top level) is in no table.
    let whole = span.start == 0 && span.end >= text.trim_end().len();
    let (table, key) = if whole { (None, None) } else { where_in(text, start) };
    let path = match (&table, &key) {
        (Some(t), Some(k)) => format!("`{t}.{k}`"),
        (None, Some(k)) => format!("`{k}`"),
        (Some(t), None) => format!("[{t}]"),
        (None, None) => "the file".to_owned(),
    };
    let said = if message.starts_with("duplicate key") {
        duplicate(text, start, table.as_deref(), key.as_deref())
    } else if let Some(rest) = message.strip_prefix("invalid type: ") {
        match rest.split_once(", expected ") {
            Some((found, expected)) => {
                format!("{path} must be {}, found {}", expected_words(expected), found_words(found))
            }
            None => format!("{path}: {rest}"),
        }
    } else if let Some(rest) = message.strip_prefix("unknown field ") {
        let rest = rest.replacen(", expected one of ", ": expected one of ", 1).replacen(
            ", expected ",
            ": expected ",
            1,
        );
        match &table {
            Some(t) => format!("unknown key {rest} (in [{t}])"),
            None => format!("unknown key {rest}"),
        }
    } else if let Some(rest) = message.strip_prefix("missing field ") {
        match &table {
            // The one table every scene needs (toml points at the file's first table).
            _ if rest == "`camera`" => "the file needs a [camera] table".to_owned(),
            Some(t) => format!("[{t}] needs the key {rest}"),
            None => format!("the file needs the key {rest}"),
        }
    } else if message.contains("number overflowed") {
        format!("{path}: the number is beyond the range of a 64-bit number ({message})")
    } else if let Some(rest) = message.strip_prefix("unknown variant ") {
        format!("{path}: unknown value {rest}")
    } else if key.is_some() && !message.contains(" key") {
        format!("{path}: {message}")
    } else {
        message
    };
    cut(&said)
}

/// The table (`image`, `materials.glass`, `objects[2]`) and the key whose
/// line holds byte `at`.
fn where_in(text: &str, at: usize) -> (Option<String>, Option<String>) {
    let mut table = None;
    let mut arrays: Vec<(String, usize)> = Vec::new();
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let end = offset + line.len();
        let t = line.trim();
        if let Some(name) = t.strip_prefix("[[").and_then(|r| r.split("]]").next()) {
            let name = name.trim().to_owned();
            let index = match arrays.iter_mut().find(|(n, _)| *n == name) {
                Some((_, count)) => {
                    *count += 1;
                    *count - 1
                }
                None => {
                    arrays.push((name.clone(), 1));
                    0
                }
            };
            table = Some(format!("{name}[{index}]"));
            if at < end {
                return (table, None);
            }
        } else if let Some(name) = t.strip_prefix('[').and_then(|r| r.split(']').next()) {
            table = Some(name.trim().to_owned());
            if at < end {
                return (table, None);
            }
        } else if at < end {
            let key = t.split_once('=').map(|(k, _)| k.trim().trim_matches('"').to_owned()).filter(|k| {
                !k.is_empty() && k.chars().all(|c| c.is_alphanumeric() || matches!(c, '_' | '-' | '.'))
            });
            return (table, key);
        }
        offset = end;
    }
    (table, None)
}

/// "duplicate key `width` in [image]: first at line 7, again at line 8", or
/// the same of a table written twice.
fn duplicate(text: &str, at: usize, table: Option<&str>, key: Option<&str>) -> String {
    let line_of = |offset: usize| text[..offset.min(text.len())].matches('\n').count() + 1;
    let again = line_of(at);
    let lines: Vec<&str> = text.lines().collect();
    let here = lines.get(again - 1).map_or("", |l| l.trim());
    if here.starts_with('[') {
        // A table header written twice: its first header.
        let first = lines.iter().position(|l| l.trim() == here).map_or(again, |i| i + 1);
        return format!("duplicate table {here}: first at line {first}, again at line {again}");
    }
    let Some(key) = key else { return format!("duplicate key at line {again}") };
    // The first line of the same table that sets the same key.
    let mut current: Option<String> = None;
    let mut first = again;
    for (i, line) in lines.iter().enumerate().take(again - 1) {
        let t = line.trim();
        if t.starts_with('[') {
            current = Some(t.trim_matches(|c| c == '[' || c == ']').trim().to_owned());
        } else if t.split_once('=').is_some_and(|(k, _)| k.trim().trim_matches('"') == key)
            && current
                .as_deref()
                .map(|c| c.split('[').next() == table.map(|t| t.split('[').next().unwrap_or(t)))
                .unwrap_or(table.is_none())
        {
            first = i + 1;
            break;
        }
    }
    let inside = table.map(|t| format!(" in [{t}]")).unwrap_or_default();
    format!("duplicate key `{key}`{inside}: first at line {first}, again at line {again}")
}

/// serde's "expected …" in the format's words.
fn expected_words(expected: &str) -> String {
    let e = expected.trim();
    if ["i64", "u64", "i32", "u32", "usize", "u8", "u16"].contains(&e) {
        "a whole number".into()
    } else if ["f64", "f32"].contains(&e) {
        "a number".into()
    } else if e.starts_with("struct ") || e == "a map" || e == "map" {
        "a table".into()
    } else if e == "a sequence" || e.starts_with("a sequence") {
        "an array".into()
    } else if e == "a boolean" {
        "true or false".into()
    } else if e.starts_with("enum ") {
        "one of the names the format lists".into()
    } else {
        e.to_owned()
    }
}

/// serde's "found" part (`floating point \`2.5\``, `string "ten"`) in the format's words.
fn found_words(found: &str) -> String {
    let f = found.trim();
    for (rust, ours) in [
        ("floating point ", "the number "),
        ("integer ", "the whole number "),
        ("string ", "the string "),
        ("boolean ", ""),
    ] {
        if let Some(value) = f.strip_prefix(rust) {
            return format!("{ours}{}", value.trim_matches('`'));
        }
    }
    match f {
        "sequence" => "an array".into(),
        "map" => "a table".into(),
        other => other.to_owned(),
    }
}
