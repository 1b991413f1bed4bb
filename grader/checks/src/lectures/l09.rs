//! Lecture 09: checks being written.

use crate::check::Meta;

pub const CHECKS: &[Meta] = &[];

#[cfg(feature = "l09")]
pub use code::run;

#[cfg(feature = "l09")]
mod code {
    use crate::check::CheckResult;

    pub fn run(_name: &str) -> Option<CheckResult> {
        None
    }
}
