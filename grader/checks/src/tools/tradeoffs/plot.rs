//! The plots: error against time for a render sweep, one series per
//! precision, each point labelled with its setting, the Pareto front drawn.

use std::path::Path;

use plotters::prelude::*;

use super::row::{Pair, Row};

/// The colour of each precision's points.
fn precision_color(precision: &str) -> RGBColor {
    if precision == "f64" { RGBColor(0, 130, 60) } else { RGBColor(30, 90, 200) }
}

/// Writes `path`: the rows of `pair` as points (x: median time, y: metric `error` on a log
/// scale), coloured by precision, the first precision's labelled by variant; the rows marked
/// `pareto` joined by a red line in time order. An error of exactly 0 (the reference's own
/// image) is drawn on the floor of the axis, a third of the smallest non-zero error, and its
/// label says "= 0".
pub fn plot_sweep(path: &Path, pair: Pair, rows: &[Row], error: &str) -> Result<(), String> {
    let fail = |e: &dyn std::fmt::Debug| format!("{}: {e:?}", path.display());
    let points: Vec<(f64, f64, &Row)> = rows
        .iter()
        .filter(|r| r.pair == pair)
        .filter_map(|r| Some((r.time.median, r.metric(error)?, r)))
        .filter(|(t, e, _)| t.is_finite() && e.is_finite())
        .collect();
    if points.is_empty() {
        return Err(format!("{}: no {} rows to plot", path.display(), pair.key()));
    }
    let x_max = points.iter().map(|p| p.0).fold(0.0, f64::max) * 1.15;
    let smallest = points.iter().map(|p| p.1).filter(|&e| e > 0.0).fold(f64::INFINITY, f64::min);
    let floor = if smallest.is_finite() { smallest / 3.0 } else { 1e-4 };
    let y_max = points.iter().map(|p| p.1).fold(floor, f64::max) * 2.0;
    let shown = |e: f64| e.max(floor);
    let label =
        |row: &Row, e: f64| if e > 0.0 { row.variant.clone() } else { format!("{} (= 0)", row.variant) };

    let root = SVGBackend::new(path, (900, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| fail(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(pair.title(), ("sans-serif", 20))
        .margin(16)
        .x_label_area_size(44)
        .y_label_area_size(64)
        .build_cartesian_2d(0.0..x_max, (floor * 0.8..y_max).log_scale())
        .map_err(|e| fail(&e))?;
    chart
        .configure_mesh()
        .max_light_lines(2)
        .y_labels(12)
        .y_label_formatter(&|v| super::table::fmt_value(*v))
        .x_desc(format!("time ({})", pair.time_unit()))
        .y_desc(format!("error ({error}, log scale)"))
        .draw()
        .map_err(|e| fail(&e))?;

    // The Pareto front, fastest first.
    let mut front: Vec<(f64, f64)> =
        points.iter().filter(|p| p.2.pareto).map(|p| (p.0, shown(p.1))).collect();
    front.sort_by(|a, b| a.0.total_cmp(&b.0));
    chart
        .draw_series(LineSeries::new(front.iter().copied(), RED.stroke_width(2)))
        .map_err(|e| fail(&e))?
        .label("Pareto front")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], RED.stroke_width(2)));
    chart.draw_series(front.iter().map(|&p| Circle::new(p, 7, RED.stroke_width(2)))).map_err(|e| fail(&e))?;

    // Each precision's points; the first precision's labelled with their setting.
    let mut precisions: Vec<&str> = points.iter().map(|p| p.2.precision.as_str()).collect();
    precisions.sort_unstable();
    precisions.dedup();
    for (k, &precision) in precisions.iter().enumerate() {
        let color = precision_color(precision);
        chart
            .draw_series(points.iter().filter(|p| p.2.precision == precision).map(|&(t, e, row)| {
                let text = if k == 0 { label(row, e) } else { String::new() };
                EmptyElement::at((t, shown(e)))
                    + Circle::new((0, 0), 4, color.filled())
                    + Text::new(text, (6, -14), ("sans-serif", 12).into_font())
            }))
            .map_err(|e| fail(&e))?
            .label(precision.to_string())
            .legend(move |(x, y)| Circle::new((x + 10, y), 4, color.filled()));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(|e| fail(&e))?;
    root.present().map_err(|e| fail(&e))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tools::tradeoffs::timing::Timing;

    #[test]
    fn a_sweep_plot_is_an_svg_with_its_labels() {
        let row = |variant: &str, precision: &str, t: f64, e: f64, pareto: bool| Row {
            pair: Pair::Spp,
            case: "c".into(),
            variant: variant.into(),
            precision: precision.into(),
            time: Timing { median: t, min: t, max: t, runs: 5 },
            metrics: vec![("mean FLIP".into(), e)],
            fails: false,
            pareto,
        };
        let rows = [
            row("spp 1", "f32", 1.0, 0.2, true),
            row("spp 4", "f32", 4.0, 0.0, true),
            row("spp 4", "f64", 5.0, 0.06, false),
        ];
        let dir = std::env::temp_dir().join(format!("raylab-tradeoffs-plot-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("spp.svg");
        plot_sweep(&path, Pair::Spp, &rows, "mean FLIP").unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        assert!(svg.starts_with("<svg"), "{}", &svg[..40.min(svg.len())]);
        for label in ["spp 1", "spp 4 (= 0)", "Pareto front", "f32", "f64", "mean FLIP"] {
            assert!(svg.contains(label), "{label} missing");
        }
        // No rows of the pair: an error, not an empty plot.
        assert!(plot_sweep(&path, Pair::Depth, &rows, "mean FLIP").is_err());
    }
}
