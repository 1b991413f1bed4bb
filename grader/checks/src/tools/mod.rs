//! The instructor's and the curious student's tools, built on the complete tracer.

pub mod bench;
pub mod render;
pub mod tradeoffs;
