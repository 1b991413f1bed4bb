//! The instructor's and the curious student's tools, built on the complete tracer.

pub mod bench;
pub mod bless;
pub mod render;
// INSTRUCTOR BEGIN
// (Out of the handout: the tradeoffs' naive variants and f64 truths are near-solutions.)
pub mod tradeoffs;
// INSTRUCTOR END

#[cfg(test)]
mod bad_scenes;
