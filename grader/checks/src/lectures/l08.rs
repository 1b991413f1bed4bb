//! Lecture 08: checks being written.

use crate::check::Meta;

pub const CHECKS: &[Meta] = &[];

#[cfg(feature = "l08")]
pub use code::run;

#[cfg(feature = "l08")]
mod code {
    use crate::check::CheckResult;

    pub fn run(_name: &str) -> Option<CheckResult> {
        None
    }
}
