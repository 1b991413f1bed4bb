//! The tables: one per pair, as aligned text for the terminal and as
//! Markdown for the book.

use std::fmt::Write as _;

use super::row::{Pair, Report, Row};

/// A number with three significant digits (integers as they are, tiny values in
/// scientific notation): 12345 → `12345`, 2.5 → `2.50`, 0.01234 → `0.0123`, 3e-6 → `3.00e-6`.
pub fn fmt_value(v: f64) -> String {
    if v.is_nan() {
        return "NaN".into();
    }
    if v == v.round() && v.abs() < 1e9 {
        return format!("{v:.0}");
    }
    let a = v.abs();
    if a < 1e-3 {
        return format!("{v:.2e}");
    }
    let decimals = (2 - a.log10().floor() as i32).clamp(0, 6) as usize;
    format!("{v:.decimals$}")
}

/// A table: headers, which columns hold numbers (right-aligned), and the cells.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    pub headers: Vec<String>,
    pub numeric: Vec<bool>,
    pub cells: Vec<Vec<String>>,
}

/// The table of `pair` from `rows` (only that pair's rows are taken): case, variant,
/// precision, median time and the min–max of the runs, each metric, and the verdicts.
pub fn pair_table(pair: Pair, rows: &[Row]) -> Table {
    let rows: Vec<&Row> = rows.iter().filter(|r| r.pair == pair).collect();
    // The metrics in the order they first appear.
    let mut metrics: Vec<&str> = Vec::new();
    for row in &rows {
        for (name, _) in &row.metrics {
            if !metrics.contains(&name.as_str()) {
                metrics.push(name);
            }
        }
    }
    let unit = pair.time_unit();
    let mut headers: Vec<String> =
        ["case", "variant", "precision", unit, "min–max"].iter().map(|s| s.to_string()).collect();
    headers.extend(metrics.iter().map(|s| s.to_string()));
    headers.push(if pair.plotted() { "Pareto".into() } else { "fails".into() });
    let mut numeric = vec![false, false, false, true, true];
    numeric.extend(metrics.iter().map(|_| true));
    numeric.push(false);
    let cells = rows
        .iter()
        .map(|row| {
            let mut cells = vec![
                row.case.clone(),
                row.variant.clone(),
                row.precision.clone(),
                fmt_value(row.time.median),
                format!("{}–{}", fmt_value(row.time.min), fmt_value(row.time.max)),
            ];
            cells.extend(metrics.iter().map(|m| row.metric(m).map_or(String::new(), fmt_value)));
            let mark = match (pair.plotted(), row.pareto, row.fails) {
                (true, true, _) => "●",
                (false, _, true) => "✗",
                _ => "",
            };
            cells.push(mark.into());
            cells
        })
        .collect();
    Table { headers, numeric, cells }
}

/// `table` as Markdown (GitHub pipe tables; `|` in a cell escaped).
pub fn markdown(table: &Table) -> String {
    let escape = |s: &str| s.replace('|', "\\|");
    let line = |cells: &[String]| {
        format!("| {} |\n", cells.iter().map(|c| escape(c)).collect::<Vec<_>>().join(" | "))
    };
    let mut out = line(&table.headers);
    let rule: Vec<String> =
        table.numeric.iter().map(|&n| if n { "---:".into() } else { "---".into() }).collect();
    out += &format!("|{}|\n", rule.join("|"));
    for row in &table.cells {
        out += &line(row);
    }
    out
}

/// `table` as aligned text (numbers right-aligned), two spaces between columns.
pub fn text(table: &Table) -> String {
    let width = |i: usize| {
        std::iter::once(&table.headers[i])
            .chain(table.cells.iter().map(|r| &r[i]))
            .map(|s| s.chars().count())
            .max()
    };
    let widths: Vec<usize> = (0..table.headers.len()).map(|i| width(i).unwrap_or(0)).collect();
    let line = |cells: &[String]| {
        let mut out = String::new();
        for (i, cell) in cells.iter().enumerate() {
            let pad = " ".repeat(widths[i] - cell.chars().count());
            let sep = if i + 1 < cells.len() { "  " } else { "" };
            if table.numeric[i] {
                let _ = write!(out, "{pad}{cell}{sep}");
            } else {
                let _ = write!(out, "{cell}{pad}{sep}");
            }
        }
        out.trim_end().to_string() + "\n"
    };
    let mut out = line(&table.headers);
    for row in &table.cells {
        out += &line(row);
    }
    out
}

/// A sentence on the machine's noise in one precision's run.
pub fn noise_sentence(report: &Report) -> String {
    let n = &report.noise;
    format!(
        "{}: a fixed arithmetic loop timed {} times took {} ns per iteration (median), {}–{} (spread {:.1} %)",
        report.precision,
        n.runs,
        fmt_value(n.median),
        fmt_value(n.min),
        fmt_value(n.max),
        100.0 * n.spread()
    )
}

/// The whole Markdown document: a generated-file line, how it was measured, then per pair its
/// title, what it measures, the table and (for the sweeps) the plot.
pub fn markdown_document(reports: &[Report], rows: &[Row], profile: &str, seconds: f64) -> String {
    let mut out = String::from(
        "<!-- Generated by `grader tradeoffs` (grader/checks/src/tools/tradeoffs); do not edit, run it again. -->\n\
         # Speed against accuracy\n\n",
    );
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let _ = writeln!(
        out,
        "Measured by one `{profile}` run of `grader tradeoffs` on {cores} core(s) in {seconds:.0} s. Each time \
         is the median of repeated runs of a batch (at least 5; the geometric pairs repeat a batch within a run \
         until it lasts a few ms); `min–max` is the spread of those runs. The machine's noise:\n"
    );
    for report in reports {
        let _ = writeln!(out, "- {}", noise_sentence(report));
    }
    for pair in Pair::ALL {
        let table = pair_table(pair, rows);
        if table.cells.is_empty() {
            continue;
        }
        let _ = write!(out, "\n## {}\n\n{}\n\n{}", pair.title(), pair.about(), markdown(&table));
        if pair.plotted() {
            let _ = write!(
                out,
                "\n● marks the Pareto front (no other row is both faster and more accurate).\n\n\
                 ![{} error against time]({}.svg)\n",
                pair.key(),
                pair.key()
            );
        } else {
            let _ = writeln!(out, "\n✗ marks a row that fails the criterion stated above.");
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tools::tradeoffs::timing::Timing;

    #[test]
    fn values_keep_three_significant_digits() {
        let cases = [(12345.0, "12345"), (2.5, "2.50"), (0.01234, "0.0123"), (123.456, "123"), (-4.0, "-4")];
        for (v, s) in cases {
            assert_eq!(fmt_value(v), s, "{v}");
        }
        assert_eq!(fmt_value(3e-6), "3.00e-6");
        assert_eq!(fmt_value(f64::NAN), "NaN");
    }

    fn sample_rows() -> Vec<Row> {
        let row = |variant: &str, precision: &str, median: f64, leaks: f64| Row {
            pair: Pair::Triangle,
            case: "mesh | a".into(),
            variant: variant.into(),
            precision: precision.into(),
            time: Timing { median, min: median - 1.0, max: median + 0.5, runs: 5 },
            metrics: vec![("leaks".into(), leaks)],
            fails: leaks > 0.0,
            pareto: false,
        };
        vec![row("cramer", "f32", 12.0, 3.0), row("watertight", "f64", 9.5, 0.0)]
    }

    #[test]
    fn markdown_table_of_a_pair() {
        // Written by hand from the rows: the `|` of the case escaped, numbers right-aligned,
        // the time as median then min–max, a ✗ where the row fails.
        let expected = "\
| case | variant | precision | ns/test | min–max | leaks | fails |
|---|---|---|---:|---:|---:|---|
| mesh \\| a | cramer | f32 | 12 | 11–12.5 | 3 | ✗ |
| mesh \\| a | watertight | f64 | 9.50 | 8.50–10 | 0 |  |
";
        assert_eq!(markdown(&pair_table(Pair::Triangle, &sample_rows())), expected);
        // Another pair's rows are not taken.
        assert!(pair_table(Pair::Sphere, &sample_rows()).cells.is_empty());
    }

    #[test]
    fn text_table_aligns_columns() {
        let text = text(&pair_table(Pair::Triangle, &sample_rows()));
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], "case      variant     precision  ns/test  min–max  leaks  fails");
        assert_eq!(lines[1], "mesh | a  cramer      f32             12  11–12.5      3  ✗");
        assert_eq!(lines[2], "mesh | a  watertight  f64           9.50  8.50–10      0");
    }
}
