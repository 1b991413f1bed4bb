//! `grader tradeoffs`: the speed/accuracy trade measured side by side (being written).

/// The command line of `grader tradeoffs`.
#[derive(clap::Args, Debug)]
pub struct TradeoffsArgs {}

/// Runs every measurement and writes the tables and plots.
pub fn tradeoffs(_args: &TradeoffsArgs) -> Result<(), String> {
    Err("grader tradeoffs is being written".into())
}
