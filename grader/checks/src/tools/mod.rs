//! The instructor's and the curious student's tools, built on the complete tracer.

pub mod bench;
pub mod bless;
pub mod render;
// INSTRUCTOR BEGIN
// (Out of the handout: the tradeoffs' naive variants and f64 truths are near-solutions.)
pub mod tradeoffs;
// INSTRUCTOR END

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// The tools' command line: `raylab-checks render`, `bless`, `bench-rays`, ….
#[derive(Parser)]
#[command(name = "raylab-checks", about = "The raylab tools (run through `cargo run -p grader`).")]
pub(crate) struct Tools {
    #[command(subcommand)]
    pub(crate) tool: Tool,
}

#[derive(Subcommand)]
pub(crate) enum Tool {
    /// Render a TOML or MIT 6.837 scene with the complete tracer.
    Render(render::RenderArgs),
    /// Regenerate the lectures' snapshots (PNG and AOVs) from the reference.
    Bless {
        /// Only this lecture (e.g. 02).
        lecture: Option<String>,
    },
    /// Primary-ray throughput of lecture 09's BVH on a mesh (run with --release).
    BenchRays(bench::BenchArgs),
    // INSTRUCTOR BEGIN
    /// Speed against accuracy, side by side: tables and plots under target/grader/tradeoffs (run with
    /// --release).
    Tradeoffs(tradeoffs::TradeoffsArgs),
    // INSTRUCTOR END
}

/// The tools' names, as the first argument.
const NAMES: &[&str] = &[
    "render",
    "bless",
    "bench-rays",
    // INSTRUCTOR BEGIN
    "tradeoffs",
    // INSTRUCTOR END
];

/// Runs the tool the first argument names; `None` when it names none (the checks' command line
/// then takes the arguments).
pub fn main() -> Option<ExitCode> {
    let first = std::env::args().nth(1)?;
    if !NAMES.contains(&first.as_str()) {
        return None;
    }
    let tools = Tools::parse();
    // The stages' code, lent by the lectures built (every one: the feature `tools` turns them on).
    crate::lectures::install();
    let result = match tools.tool {
        Tool::Render(args) => render::render(&args),
        Tool::Bless { lecture } => bless::bless(lecture.as_deref()),
        Tool::BenchRays(args) => bench::bench_rays(&args),
        // INSTRUCTOR BEGIN
        Tool::Tradeoffs(args) => tradeoffs::tradeoffs(&args),
        // INSTRUCTOR END
    };
    Some(raylab_checks_core::cli::exit(result.map(|()| ExitCode::SUCCESS)))
}

#[cfg(test)]
mod bad_scenes;
