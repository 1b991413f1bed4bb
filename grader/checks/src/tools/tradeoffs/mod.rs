//! `grader tradeoffs`: the speed/accuracy trade measured side by side.
//!
//! Every place where a faster method gives a less accurate answer is
//! measured in one run, in time and in error against ground truth:
//! - the sphere three ways (lecture 02): wrong hit/miss and |Δt| in ulp on a
//!   small sphere 10³–10⁵ away, against roots polished in double-double;
//! - the triangle three ways (lecture 03): leaks through the shared edges and
//!   vertices of closed meshes;
//! - the box by six planes and by slabs (lecture 03): false misses and NaNs
//!   against exact rational arithmetic;
//! - shadow-ray origins (lecture 06): acne at coordinates 1–10⁵ and light
//!   leaks through a tiny sphere;
//! - refraction (lecture 07): NaNs, wrong total internal reflection and angle
//!   errors at the critical angle ± 0.001°, where sin²θ_t rounds to 1 and at
//!   normal incidence, against Snell's law in f64;
//! - the refracted ray through a glass sphere of radius 10⁻⁵ (lectures 06 and
//!   07): the exit it finds from each ray origin, against the chord in f64;
//! - non-uniform scale to 1e-3 : 1e3 (lecture 04): normal angle by (M⁻¹)ᵀ and
//!   by M against the cofactor matrix, and t against the f64 root;
//! - look-at (lecture 01) with up parallel or nearly parallel to the view:
//!   NaN bases and orthonormality error;
//! - rendering: mean FLIP against a converged reference, against time, for
//!   samples per pixel, ray-tree depth and weight cut-off (with their Pareto
//!   fronts), and BVH against brute force (same pixels, less time);
//! - f32 against f64: the command runs itself in the other precision
//!   (`cargo run -p raylab-checks [--features raylab/f64] -- tradeoffs --json`)
//!   and merges the rows.
//!
//! Output: the tables in the terminal, and `tradeoffs.md` (the tables, the
//! machine's noise) with SVG plots under `target/grader/tradeoffs/`, which
//! the book includes. Run it with `--release`: debug timings mean little.
//! Book: §9.10 Measuring a hierarchy, and the "trade" sections of chapters
//! 2, 3, 6, 8 and 10.

mod boxes;
mod glass_sphere;
mod look_at;
mod offsets;
mod pareto;
mod plot;
mod reference;
mod refraction;
mod rendering;
mod row;
mod scale;
mod sphere;
mod table;
mod timing;
mod triangle;

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

use pareto::pareto_front;
use row::{Pair, Report, Row, own_precision};
use timing::Effort;

/// Set in the environment of the child run of the other precision: a run that
/// finds it set never starts another one.
pub const CHILD_ENV: &str = "RAYLAB_TRADEOFFS_CHILD";

/// The command line of `grader tradeoffs`.
#[derive(clap::Args, Debug, Default)]
pub struct TradeoffsArgs {
    /// Print this precision's measurements as JSON on standard output and write nothing (what the
    /// run of the other precision is asked for).
    #[arg(long)]
    pub json: bool,
    /// Measure only the precision this binary was built with (no child run).
    #[arg(long)]
    pub single_precision_only: bool,
    /// A reduced run: fewer rays, smaller and fewer-sampled renders (seconds, not minutes).
    #[arg(long)]
    pub quick: bool,
    /// Where the Markdown and the plots go (default: <workspace>/target/grader/tradeoffs).
    #[arg(long)]
    pub out: Option<PathBuf>,
}

/// Runs every measurement and writes the tables and plots.
pub fn tradeoffs(args: &TradeoffsArgs) -> Result<(), String> {
    let effort = if args.quick { Effort::QUICK } else { Effort::FULL };
    if mode(std::env::var_os(CHILD_ENV).is_some(), args.json)? == Mode::Json {
        let report = measure_all(&effort, &mut |line| eprintln!("  [{}] {line}", own_precision()))?;
        let json = serde_json::to_string(&report).map_err(|e| e.to_string())?;
        println!("{json}");
        return Ok(());
    }
    if cfg!(debug_assertions) {
        eprintln!("note: a debug build; run with --release for timings that mean something");
    }
    let start = Instant::now();
    let mut reports = vec![measure_all(&effort, &mut |line| eprintln!("[{}] {line}", own_precision()))?];
    if !args.single_precision_only {
        match run_other_precision(args) {
            Ok(report) => reports.push(report),
            Err(e) => eprintln!("warning: the other precision was not measured: {e}"),
        }
    }
    let rows = merge(&reports);
    let seconds = start.elapsed().as_secs_f64();

    for pair in Pair::ALL {
        let t = table::pair_table(pair, &rows);
        if !t.cells.is_empty() {
            println!("\n{}\n{}", pair.title(), table::text(&t));
        }
    }
    for report in &reports {
        println!("noise {}", table::noise_sentence(report));
    }
    let out = args.out.clone().unwrap_or_else(default_out_dir);
    let written = write_outputs(&out, &reports, &rows, seconds)?;
    println!("\n{} s in all; wrote {}", seconds.round(), written.join(", "));
    Ok(())
}

/// What a run does: print this precision's report as JSON, or the whole command.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Json,
    Full,
}

/// The mode of a run that is (or not) a child of another and was (or not) asked for `--json`.
/// A child must be a JSON run: one that is not would start a child of its own.
pub fn mode(is_child: bool, json: bool) -> Result<Mode, String> {
    match (is_child, json) {
        (_, true) => Ok(Mode::Json),
        (false, false) => Ok(Mode::Full),
        (true, false) => {
            Err(format!("{CHILD_ENV} is set: a child run must be asked for --json (no recursion)"))
        }
    }
}

/// `<workspace>/target/grader/tradeoffs`.
pub fn default_out_dir() -> PathBuf {
    let root = crate::scenes::workspace_root();
    std::fs::canonicalize(&root).unwrap_or(root).join("target/grader/tradeoffs")
}

/// Every pair in this precision, saying on `progress` what it is doing.
pub fn measure_all(effort: &Effort, progress: &mut dyn FnMut(&str)) -> Result<Report, String> {
    let mut rows = Vec::new();
    progress("machine noise");
    let noise = timing::machine_noise(effort);
    progress("sphere");
    rows.extend(sphere::measure(effort));
    progress("triangle");
    rows.extend(triangle::measure(effort));
    progress("box");
    rows.extend(boxes::measure(effort));
    progress("shadow offsets");
    rows.extend(offsets::measure(effort));
    progress("refraction");
    rows.extend(refraction::measure(effort));
    progress("tiny glass sphere");
    rows.extend(glass_sphere::measure(effort));
    progress("non-uniform scale");
    rows.extend(scale::measure(effort));
    progress("look-at");
    rows.extend(look_at::measure(effort));
    progress("samples per pixel");
    rows.extend(rendering::measure_spp(effort)?);
    progress("ray-tree depth and weight");
    rows.extend(rendering::measure_tree(effort)?);
    progress("BVH against brute force");
    rows.extend(rendering::measure_bvh(effort)?);
    Ok(Report { precision: own_precision().to_string(), noise, rows })
}

/// The cargo command that runs this tool in the other precision, with the same profile, as a
/// child that prints JSON: (program, arguments).
pub fn other_precision_command(args: &TradeoffsArgs) -> (String, Vec<String>) {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    let mut argv: Vec<String> = vec!["run".into(), "--quiet".into(), "-p".into(), "raylab-checks".into()];
    if !cfg!(debug_assertions) {
        argv.push("--release".into());
    }
    // Every lecture (the default features), and raylab's f64 feature when this run is f32.
    if own_precision() == "f32" {
        argv.extend(["--features".into(), "raylab/f64".into()]);
    }
    argv.extend(["--".into(), "tradeoffs".into(), "--json".into()]);
    if args.quick {
        argv.push("--quick".into());
    }
    (cargo, argv)
}

/// Builds and runs the other precision (its build and progress on standard error) and reads
/// its report.
fn run_other_precision(args: &TradeoffsArgs) -> Result<Report, String> {
    let (program, argv) = other_precision_command(args);
    eprintln!("running the other precision: {program} {}", argv.join(" "));
    let output = Command::new(&program)
        .args(&argv)
        .current_dir(crate::scenes::workspace_root())
        .env(CHILD_ENV, "1")
        .stdin(Stdio::null())
        .stderr(Stdio::inherit())
        .output()
        .map_err(|e| format!("{program}: {e}"))?;
    if !output.status.success() {
        return Err(format!("the child run failed ({})", output.status));
    }
    let stdout = String::from_utf8_lossy(&output.stdout);
    let json = stdout.lines().rev().find(|l| l.starts_with('{')).ok_or("the child printed no report")?;
    let report: Report = serde_json::from_str(json).map_err(|e| format!("the child's report: {e}"))?;
    if report.precision == own_precision() {
        return Err(format!("the child measured {} too", report.precision));
    }
    Ok(report)
}

/// The rows of every report, each row of the later reports placed right after the row of the
/// first with the same pair, case and variant (so f32 and f64 stand side by side), then the
/// Pareto front marked on each plotted sweep over both precisions.
pub fn merge(reports: &[Report]) -> Vec<Row> {
    let mut rows: Vec<Row> = reports.first().map(|r| r.rows.clone()).unwrap_or_default();
    for report in reports.iter().skip(1) {
        for row in &report.rows {
            let same = |r: &Row| r.pair == row.pair && r.case == row.case && r.variant == row.variant;
            let at = match rows.iter().rposition(same) {
                Some(i) => i + 1,
                None => rows.iter().rposition(|r| r.pair == row.pair).map_or(rows.len(), |i| i + 1),
            };
            rows.insert(at, row.clone());
        }
    }
    for pair in Pair::ALL.into_iter().filter(|p| p.plotted()) {
        let indices: Vec<usize> = (0..rows.len()).filter(|&i| rows[i].pair == pair).collect();
        let points: Vec<(f64, f64)> = indices
            .iter()
            .map(|&i| (rows[i].time.median, rows[i].metric(rendering::FLIP).unwrap_or(f64::NAN)))
            .collect();
        for (&i, on_front) in indices.iter().zip(pareto_front(&points)) {
            rows[i].pareto = on_front;
        }
    }
    rows
}

/// Writes tradeoffs.md, tradeoffs.json and one SVG per sweep into `out`; returns the paths.
fn write_outputs(out: &Path, reports: &[Report], rows: &[Row], seconds: f64) -> Result<Vec<String>, String> {
    std::fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
    let profile = if cfg!(debug_assertions) { "debug" } else { "release" };
    let mut written = Vec::new();
    let mut write = |name: &str, text: String| -> Result<(), String> {
        let path = out.join(name);
        std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
        written.push(path.display().to_string());
        Ok(())
    };
    write("tradeoffs.md", table::markdown_document(reports, rows, profile, seconds))?;
    write("tradeoffs.json", serde_json::to_string_pretty(reports).map_err(|e| e.to_string())?)?;
    for pair in Pair::ALL.into_iter().filter(|p| p.plotted()) {
        let path = out.join(format!("{}.svg", pair.key()));
        plot::plot_sweep(&path, pair, rows, rendering::FLIP)?;
        written.push(path.display().to_string());
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::timing::Timing;
    use super::*;

    /// The reduced run of the geometric pairs, once for all the tests below.
    fn reduced() -> &'static [Row] {
        static ROWS: std::sync::OnceLock<Vec<Row>> = std::sync::OnceLock::new();
        ROWS.get_or_init(|| {
            let effort =
                Effort { samples: 2000, runs: 1, min_batch: std::time::Duration::ZERO, ..Effort::QUICK };
            let mut rows = sphere::measure(&effort);
            rows.extend(triangle::measure(&effort));
            rows.extend(boxes::measure(&effort));
            rows.extend(offsets::measure(&effort));
            rows
        })
    }

    #[test]
    fn every_pair_shows_a_naive_variant_failing_and_the_reference_passing() {
        // The naive variants fail where the lectures say they do, in f32 and f64 alike:
        // the textbook quadratic loses about log₂(D²) bits at D = 10⁵ (> 4 ulp), Cramer leaks
        // through shared edges, six planes miss edge-aimed rays, fixed offsets jump through a
        // sphere of radius 10⁻⁴. The reference methods never fail.
        let rows = reduced();
        let cases = [
            (Pair::Sphere, "stable"),
            (Pair::Triangle, "watertight"),
            (Pair::Box, "slabs"),
            (Pair::Offset, "offset_origin"),
        ];
        for (pair, reference) in cases {
            let of_pair: Vec<&Row> = rows.iter().filter(|r| r.pair == pair).collect();
            assert!(
                of_pair.iter().any(|r| r.variant != reference && r.fails),
                "{pair:?}: no naive variant fails: {of_pair:#?}"
            );
            for r in of_pair.iter().filter(|r| r.variant == reference) {
                assert!(!r.fails, "{pair:?}: the reference fails: {r:#?}");
            }
        }
    }

    #[test]
    fn the_naive_variants_fail_by_the_expected_measures() {
        let rows = reduced();
        let find = |pair: Pair, case: &str, variant: &str| {
            rows.iter()
                .find(|r| r.pair == pair && r.case.starts_with(case) && r.variant == variant)
                .unwrap_or_else(|| panic!("no row {pair:?} {case} {variant}"))
        };
        // The algebraic sphere at 10⁵: far more than the stable form's few ulp.
        let algebraic = find(Pair::Sphere, "D = 1e5", "algebraic");
        assert!(algebraic.metric("max |Δt| ulp").unwrap() > 100.0, "{algebraic:#?}");
        // Edge-aimed rays leak through Cramer's triangles on the octahedra (measured in the
        // lecture: about 5 % of the rays in f32 and f64).
        assert!(find(Pair::Triangle, "", "cramer").metric("leaks").unwrap() > 0.0);
        // Six planes miss some edge- and corner-aimed rays; the slabs none, and no NaN.
        let six = find(Pair::Box, "aimed", "six_planes");
        assert!(six.metric("false misses").unwrap() > 0.0, "{six:#?}");
        let slabs = find(Pair::Box, "axis-parallel", "slabs");
        assert_eq!((slabs.metric("false misses"), slabs.metric("NaN")), (Some(0.0), Some(0.0)));
        // The fixed epsilons through a sphere of radius 10⁻⁴: about 47 % (fixed_t) and 86 %
        // (fixed_normal) of the dark-side rays miss it (lecture 06's derivation); allow ±5 %
        // for 2000 samples (binomial spread ±1.6 %).
        let tiny = |v| find(Pair::Offset, "r = 1e-4", v).metric("leaks %").unwrap();
        assert!((tiny("fixed_t") - 47.4).abs() < 5.0, "{}", tiny("fixed_t"));
        assert!((tiny("fixed_normal") - 85.9).abs() < 5.0, "{}", tiny("fixed_normal"));
        assert_eq!(tiny("offset_origin"), 0.0);
    }

    #[test]
    fn merge_puts_the_other_precision_beside_and_marks_the_front() {
        let row = |precision: &str, variant: &str, t: f64, e: f64| Row {
            pair: Pair::Spp,
            case: "c".into(),
            variant: variant.into(),
            precision: precision.into(),
            time: Timing { median: t, min: t, max: t, runs: 5 },
            metrics: vec![(rendering::FLIP.into(), e)],
            fails: false,
            pareto: false,
        };
        let noise = Timing { median: 1.0, min: 1.0, max: 1.0, runs: 5 };
        let f32_rows = vec![row("f32", "spp 1", 1.0, 0.3), row("f32", "spp 2", 2.0, 0.1)];
        let f64_rows = vec![row("f64", "spp 2", 3.0, 0.1), row("f64", "spp 1", 1.5, 0.3)];
        let merged = merge(&[
            Report { precision: "f32".into(), noise, rows: f32_rows },
            Report { precision: "f64".into(), noise, rows: f64_rows },
        ]);
        let order: Vec<(&str, &str)> =
            merged.iter().map(|r| (r.variant.as_str(), r.precision.as_str())).collect();
        assert_eq!(order, [("spp 1", "f32"), ("spp 1", "f64"), ("spp 2", "f32"), ("spp 2", "f64")]);
        // (1, 0.3) and (2, 0.1) are the front; (1.5, 0.3) and (3, 0.1) are each beaten.
        let front: Vec<bool> = merged.iter().map(|r| r.pareto).collect();
        assert_eq!(front, [true, false, true, false]);
    }

    #[test]
    fn the_child_is_the_other_precision_and_cannot_recurse() {
        let (_, argv) = other_precision_command(&TradeoffsArgs { quick: true, ..TradeoffsArgs::default() });
        let joined = argv.join(" ");
        assert!(
            joined.contains("-p raylab-checks") && joined.ends_with("-- tradeoffs --json --quick"),
            "{joined}"
        );
        assert_eq!(joined.contains("raylab/f64"), own_precision() == "f32", "{joined}");
        // A child asked for JSON measures and prints; one that is not refuses; only a run that
        // is no child starts a child.
        assert_eq!(mode(true, true), Ok(Mode::Json));
        assert!(mode(true, false).unwrap_err().contains("no recursion"));
        assert_eq!(mode(false, true), Ok(Mode::Json));
        assert_eq!(mode(false, false), Ok(Mode::Full));
    }
}
