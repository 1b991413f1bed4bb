//! `raylab-checks`: the grader's checks and the complete tracer, in a binary
//! the `grader` driver builds with the lectures that compile (one cargo
//! feature per lecture) and runs in child processes, one per check. Its
//! command line (`list`, `run`, `serve`, `judge`) is the core's
//! (`raylab_checks_core::cli`): this crate, compiled again after every edit of
//! a lecture, holds only the table of lectures (`lectures/mod.rs`) and the tools.
//!
//! `render`, `bless` and `bench-rays` are the tools of `grader render`, `grader bless` and
//! `grader bench-rays` (`tools/`), built with the feature `tools` (every lecture; the grader
//! asks for it for them, not to grade).

// Built with some lectures only (those that compile), parts of the crate go unused:
// that is expected and not worth a warning in the student's terminal.
#![cfg_attr(not(feature = "tools"), allow(unused))]

mod lectures;
#[cfg(feature = "tools")]
mod tools;

// The core's modules, where this crate's code (and the tools') has always named them.
use raylab_checks_core::{check, path, platform, remote, scenes, stages, trees, view3d};

use std::process::ExitCode;

use raylab_checks_core::cli::{self, Catalogue};

/// The lectures this binary is built with, as the command line reaches them.
const CATALOGUE: Catalogue = Catalogue {
    install: lectures::install,
    infos: lectures::infos,
    run: lectures::run,
    answers: lectures::ANSWERS,
};

fn main() -> ExitCode {
    #[cfg(feature = "tools")]
    if let Some(code) = tools::main() {
        return code;
    }
    cli::main(&CATALOGUE)
}

#[cfg(test)]
mod tests {
    use super::CATALOGUE;
    use std::collections::HashSet;

    #[test]
    fn ids_are_unique_and_every_need_names_an_exercise_of_an_earlier_or_same_lecture_images_included() {
        let infos = raylab_checks_core::cli::listed(&CATALOGUE);
        let mut seen = HashSet::new();
        for info in &infos {
            assert!(seen.insert(info.id.clone()), "{} is declared twice", info.id);
        }
        let exercises: HashSet<String> =
            infos.iter().map(|i| format!("{}/{}", i.lecture, i.exercise)).collect();
        for info in &infos {
            for need in &info.needs {
                assert!(exercises.contains(need), "{} needs {need}, which no check tests", info.id);
                assert!(need[..2] <= info.lecture[..], "{} needs the later {need}", info.id);
            }
        }
    }

    /// Graded as a submission, every check runs apart from the student's code (`judge.rs`):
    /// one that was not would let a submission write its own verdict.
    #[test]
    fn every_check_is_judged_hidden_ones_included() {
        let infos = raylab_checks_core::cli::listed(&CATALOGUE);
        let unjudged: Vec<&str> = infos.iter().filter(|i| !i.judged).map(|i| i.id.as_str()).collect();
        assert!(unjudged.is_empty(), "not judged: {unjudged:?}");
        assert!(infos.iter().any(|i| i.hidden) || !cfg!(feature = "hidden"), "no hidden check listed");
    }
}
