//! Lecture 10: checks being written.

use crate::check::Meta;

pub const CHECKS: &[Meta] = &[];

#[cfg(feature = "l10")]
pub use code::run;

#[cfg(feature = "l10")]
mod code {
    use crate::check::CheckResult;

    pub fn run(_name: &str) -> Option<CheckResult> {
        None
    }
}
