//! The checks' command line, `raylab-checks list | run | serve | judge`, for the lectures a
//! binary is built with (its [`Catalogue`]): here, compiled once, and not in the binary, which a
//! student's every edit compiles again (`grader/checks/src/main.rs`).
//!
//! - `raylab-checks list` prints every check as JSON, with whether its code is built;
//! - `raylab-checks run ID --verdict FILE --out DIR` runs one check and writes
//!   its outcome to FILE (a panic writes the panic there first);
//! - `raylab-checks judge ID --out DIR` and `raylab-checks run ID --channel ADDR
//!   --out DIR` run one check in two processes, the second the student's code
//!   and the first the verdict (`judge.rs`); a hidden check's subject is
//!   `raylab-checks serve --channel ADDR`, which makes the calls of the student's
//!   code the judge asks for (`remote.rs`).

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::Arc;

use clap::{Parser, Subcommand};

use crate::check::{self, CheckResult, Info, Outcome};
use crate::judge::{self, Ended, Role};
use crate::{images, path, platform, remote};

/// The lectures a binary is built with, as the command line reaches them: the binary's table
/// (`grader/checks/src/lectures/mod.rs`), its functions and its answers.
pub struct Catalogue {
    /// Lends the stages the code of the lectures built (`stages::install`), before a check runs.
    pub install: fn(),
    /// Every check the lectures declare (the scenes' are [`images::infos`]).
    pub infos: fn() -> Vec<Info>,
    /// Runs the unit or extreme check `NN/exercise/name`; `None` when no built lecture has it.
    pub run: fn(&str) -> Option<CheckResult>,
    /// The calls of the student's code the subject of a hidden check answers, by name.
    pub answers: &'static [(&'static str, remote::Answer)],
}

#[derive(Parser)]
#[command(
    name = "raylab-checks",
    about = "The raylab checks and tools (run through `cargo run -p grader`).",
    after_help = "Built with the tools (`grader render` and the others), it also takes their commands: \
                  `raylab-checks render --help`."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Every check, as JSON: id, lecture, exercise, kind, points, needs, and whether it is built.
    List,
    /// Run one check in this process (the grader runs each in its own).
    Run {
        /// `NN/exercise/name`.
        id: String,
        /// Where to write the outcome (JSON).
        #[arg(long, required_unless_present = "channel", conflicts_with = "channel")]
        verdict: Option<PathBuf>,
        /// Where image checks write expected / yours / diff.
        #[arg(long)]
        out: PathBuf,
        /// As the subject of a judged check: send the student's values to the judge listening
        /// at this loopback address, and write no verdict (src/judge.rs). The token it says
        /// first comes on standard input, as the judge's does.
        #[arg(long)]
        channel: Option<String>,
    },
    /// As the subject of a hidden check, which runs in its judge alone: make the calls of the
    /// student's code the judge at ADDR sends, and send their values back (src/remote.rs).
    Serve {
        #[arg(long)]
        channel: String,
    },
    /// Judge one check from the values a subject sends (`run ID --channel`): read the token on
    /// standard input, print `listening ADDR`, take the connection that says the token first,
    /// print `verdict JSON`.
    Judge {
        /// `NN/exercise/name`.
        id: String,
        /// Where image checks write expected / yours / diff.
        #[arg(long)]
        out: PathBuf,
    },
}

/// The checks' command line: `list`, `run`, `serve` and `judge` for the lectures of `catalogue`.
pub fn main(catalogue: &Catalogue) -> ExitCode {
    let cli = Cli::parse();
    // The stages' code, lent by the lectures built: no student code runs to collect it.
    (catalogue.install)();
    let result = match cli.command {
        // Written, not printed: a reader that stops early (`| head`) ends the listing, not a panic.
        Command::List => serde_json::to_string_pretty(&listed(catalogue))
            .map(|json| {
                use std::io::Write;
                let _ = writeln!(std::io::stdout(), "{json}");
            })
            .map(|()| ExitCode::SUCCESS)
            .map_err(|e| e.to_string()),
        Command::Run { id, verdict, out, channel } => match (channel, verdict) {
            // Connected before any student code runs: the judge takes the first connection.
            (Some(address), _) => {
                subject_limits();
                token().and_then(|token| Role::subject(&address, token)).and_then(|role| {
                    let role = Arc::new(role);
                    run(catalogue, &id, VerdictTo::Judge(role.clone()), &out, role)
                })
            }
            (None, Some(file)) => run(catalogue, &id, VerdictTo::File(file), &out, Arc::new(Role::Direct)),
            (None, None) => Err("--verdict FILE or --channel ADDR".into()),
        },
        Command::Serve { channel } => {
            subject_limits();
            token().and_then(|token| Role::subject(&channel, token)).and_then(|role| {
                let role = Arc::new(role);
                install_panic_hook(Box::leak(Box::new(VerdictTo::Judge(role.clone()))));
                match judge::enter(role, || {
                    judge::serve_calls(|call| remote::answer_encoded(catalogue.answers, call))
                }) {
                    Ok(served) => served.map(|()| ExitCode::SUCCESS),
                    Err(_) => Ok(no_verdict()),
                }
            })
        }
        Command::Judge { id, out } => {
            platform::keep_others_out();
            token().and_then(Role::judge).and_then(|role| match role {
                Some(role) => run(catalogue, &id, VerdictTo::Stdout, &out, Arc::new(role)),
                // The subject ended without connecting: how it ended is the verdict.
                None => Ok(no_verdict()),
            })
        }
    };
    exit(result)
}

/// How a command ends: its exit code, or its error printed and a failure (the tools' too).
pub fn exit(result: Result<ExitCode, String>) -> ExitCode {
    result.unwrap_or_else(|message| {
        eprintln!("error: {message}");
        ExitCode::FAILURE
    })
}

/// How a judge or a subject ends without a verdict of its own: the driver gives the verdict
/// from how the subject ended.
fn no_verdict() -> ExitCode {
    ExitCode::from(u8::try_from(raylab_protocol::NO_VERDICT).unwrap_or(u8::MAX))
}

/// The token the driver wrote on standard input for a judge and its subject.
fn token() -> Result<u64, String> {
    raylab_protocol::read_token(&mut std::io::stdin().lock())
}

/// The limits of a subject, set before any student code runs (a submission's code cannot run
/// before `main`: it is built with unsafe code forbidden): files of at most [`SUBJECT_FILE_LIMIT`]
/// (a subject sends values and writes nothing), no core dumps. Its memory is capped with every
/// check's ([`install_panic_hook`]); its processes, as the grading user's, by the driver.
fn subject_limits() {
    platform::limit_files(SUBJECT_FILE_LIMIT);
}

/// The largest file a subject may write: it writes none of its own (the judge writes the
/// report's images); a student's debugging output of a picture or two still fits.
const SUBJECT_FILE_LIMIT: u64 = 16 << 20;

/// The address space a check may use. The lecture checks need a few tens of
/// megabytes; a student's runaway allocation fails here ("memory allocation
/// of N bytes failed") instead of swapping the machine.
const MEMORY_LIMIT: u64 = 4 << 30;

/// Where a check's outcome goes.
enum VerdictTo {
    /// A file (`run --verdict`: local grading, one process).
    File(PathBuf),
    /// The judge's stdout, as a `verdict JSON` line (`judge`).
    Stdout,
    /// Nowhere: a subject (`run --channel`) reports values, never a verdict (its role's channel
    /// takes its last values, and a panic: the panic hook holds it).
    Judge(Arc<Role>),
}

impl VerdictTo {
    fn write(&self, outcome: &Outcome) -> Result<(), String> {
        let json = serde_json::to_string(outcome).map_err(|e| e.to_string())?;
        match self {
            VerdictTo::File(file) => {
                std::fs::write(file, json).map_err(|e| format!("{}: {e}", file.display()))
            }
            VerdictTo::Stdout => judge::print_verdict(&json),
            // The subject's last values, sent: the judge writes the verdict.
            VerdictTo::Judge(role) => {
                role.flush();
                Ok(())
            }
        }
    }
}

/// Runs check `id` in `role` (`judge.rs`): a panic hook records any panic as the outcome (the
/// grader tells `todo!()` from other panics by its message), then the outcome replaces it when
/// the check returns. A subject reports the panic to its judge instead, and writes nothing. A
/// check that ends early (the judge's verdict reached, or the other process gone) ends here.
fn run(
    catalogue: &Catalogue,
    id: &str,
    verdict: VerdictTo,
    out: &Path,
    role: Arc<Role>,
) -> Result<ExitCode, String> {
    // The panic hook holds it for the life of the process (a process per check).
    let verdict: &'static VerdictTo = Box::leak(Box::new(verdict));
    install_panic_hook(verdict);
    let image = id.split('/').nth(1).is_some_and(|kind| matches!(kind, "image" | "geometry" | "final"));
    let outcome = match judge::enter(role, || if image { images::run(id, out) } else { (catalogue.run)(id) })
    {
        Ok(None) => return Err(format!("no check {id} in this build")),
        Ok(Some(Ok(detail))) => Outcome::Passed { detail, images: None },
        Ok(Some(Err(failure))) => Outcome::Failed(failure),
        Err(Ended::Verdict(outcome)) => outcome,
        Err(Ended::Early) => return Ok(no_verdict()),
    };
    verdict.write(&outcome).map(|()| ExitCode::SUCCESS)
}

/// Caps the process's memory and records any panic as the outcome (written where `verdict` says; a
/// subject reports it to its judge).
fn install_panic_hook(verdict: &'static VerdictTo) {
    // Best effort: where limits cannot be set, the grader's time limit still holds.
    platform::limit_memory(MEMORY_LIMIT);
    let default_hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        // A call on a failed picture's path that panics is caught there: not this check's outcome.
        if path::probing() {
            return;
        }
        let message = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "(a panic without a message)".to_owned());
        let (path, line) = info.location().map_or((String::new(), 0), |l| (l.file().to_owned(), l.line()));
        match verdict {
            VerdictTo::Judge(role) => role.report_panic(&message, &path, line),
            to => {
                let _ = to.write(&check::Outcome::Panicked { message, file: path, line });
            }
        }
        default_hook(info);
    }));
}

/// Every declared check, as `list` prints them: the lectures' unit and extreme checks, then the
/// scenes' geometry, image and final checks.
pub fn listed(catalogue: &Catalogue) -> Vec<check::Info> {
    let mut infos = (catalogue.infos)();
    infos.extend(images::infos());
    infos
}
