//! Whole-workbench tests live in `tests/`: they drive `cargo run -p grader`
//! on the reference, on the handout and on patched copies of the reference.
