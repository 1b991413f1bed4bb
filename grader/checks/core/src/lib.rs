//! `raylab-checks-core`: what every lecture's checks are written with and graded by, knowing no
//! lecture (it depends on none of their crates, so a student's edit never rebuilds it). The
//! binary, `raylab-checks`, puts it together with the lectures' checks crates
//! (`grader/checks/lectures/lNN`), each of which lends the stages its code (`stages::Lent`).

pub mod check;
pub mod cli;
pub mod images;
pub mod judge;
pub mod path;
pub mod platform;
pub mod remote;
pub mod rows;
pub mod scenes;
pub mod stages;
pub mod trees;
pub mod view3d;
