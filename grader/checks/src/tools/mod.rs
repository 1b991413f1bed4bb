//! The instructor's and the curious student's tools, built on the complete tracer.

#[cfg(test)]
mod bad_scenes;
pub mod bench;
pub mod render;
pub mod tradeoffs;
