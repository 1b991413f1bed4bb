//! `grader`: the raylab workbench command.
//!
//! `cargo run -p grader` grades every lecture: it builds the checks
//! (`grader/checks`) with the lectures that compile, runs each check in its
//! own process with a time limit, and prints a table of verdicts and points
//! (and writes `target/grader/report.html`). `grader 03` grades one lecture,
//! `grader 03/hit_slabs` one exercise. The driver links no lecture: a
//! lecture that does not compile, or student code that panics, loops or
//! aborts, costs its own checks and never the grading.

// INSTRUCTOR BEGIN
mod class;
// INSTRUCTOR END
mod compile;
mod grade;
mod gradescope;
mod handout;
mod output;
mod platform;
mod progress;
mod report;
mod run;
mod submission;
// INSTRUCTOR BEGIN
mod sync;
// INSTRUCTOR END
mod verdict;
mod watch;
mod workspace;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};

use crate::grade::{GradeOptions, Selection};
use crate::workspace::Workspace;

#[derive(Parser)]
#[command(
    name = "grader",
    about = "The raylab workbench: grade the lectures, hints, the report, handouts; render scenes.",
    args_conflicts_with_subcommands = true
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Cmd>,
    #[command(flatten)]
    grade: GradeArgs,
}

#[derive(Args, Clone, Debug)]
struct GradeArgs {
    /// What to grade: lectures (03), exercises (03/hit_slabs) or single checks (03/hit_slabs/unit)
    /// [default: everything]. With a selection only the lectures it needs are built.
    select: Vec<String>,
    /// Exit with a failure unless every check passes.
    #[arg(long)]
    strict: bool,
    /// How to print the verdicts.
    #[arg(long, value_enum, default_value = "table")]
    format: Format,
    /// Write the JSON or Gradescope output to this file instead of stdout.
    #[arg(long, short)]
    output: Option<PathBuf>,
    /// Checks run at once [default: the number of cores].
    #[arg(long)]
    jobs: Option<usize>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum Format {
    Table,
    Json,
    /// Gradescope's results.json.
    Gradescope,
}

#[derive(Subcommand)]
enum Cmd {
    /// Hints for a lecture's exercises (e.g. `grader hint 05`, `grader hint 05/lambert`).
    Hint {
        /// A lecture or exercise.
        select: String,
    },
    /// Re-grade a lecture whenever one of its files changes.
    Watch,
    /// Write the student workspace to DIR: every solution becomes `todo!()`.
    Handout {
        dir: PathBuf,
        /// Replace DIR if it exists.
        #[arg(long)]
        force: bool,
    },
    /// Grade a student's tree: only its `lectures/*/src` is taken, into a pristine copy, hidden checks included.
    Grade {
        /// The student's workspace (or a folder with its `lectures/`).
        #[arg(long)]
        submission: PathBuf,
        /// The scratch workspace to grade in (kept between runs so that builds are incremental;
        /// one grade's at a time: another grader given it waits) [default: target/grader/submission].
        #[arg(long)]
        workdir: Option<PathBuf>,
        /// Build and run the student's code as these users (Unix; the grader runs as root): users
        /// who cannot read this workspace, where the judge, the snapshots and the hidden checks
        /// are. The first builds, and owns only the folder cargo builds in (work/target/student)
        /// while it does; each runs the checks of one job at a time (at most one job per user),
        /// so that what one check's processes take (its user's process limit) is not another's.
        /// What Gradescope's `run_autograder` does.
        #[arg(long, value_name = "USER,…", value_delimiter = ',')]
        run_as: Vec<String>,
        #[command(flatten)]
        grade: GradeArgs,
    },
    /// Write the Gradescope autograder bundle (setup.sh, run_autograder, the pristine workspace) to DIR.
    Gradescope {
        dir: PathBuf,
        /// Replace DIR if it exists.
        #[arg(long)]
        force: bool,
    },
    /// Render a scene with the complete tracer (`grader render --help` for the options).
    #[command(disable_help_flag = true)]
    Render {
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        args: Vec<String>,
    },
    /// Regenerate the lectures' snapshots from the reference (instructors).
    #[command(disable_help_flag = true)]
    Bless {
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        args: Vec<String>,
    },
    /// Primary-ray throughput of lecture 09's BVH (run with --release).
    #[command(disable_help_flag = true)]
    BenchRays {
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        args: Vec<String>,
    },
    // INSTRUCTOR BEGIN
    /// Grade a whole class: every submission folder in SUBMISSIONS (or a zip of them) as `grade
    /// --submission` grades it; in DIR, gradebook.csv, class.html (what the class gets wrong, its
    /// wrong pictures in clusters) and per student results.json and grade.json.
    Class(class::ClassArgs),
    /// Speed against accuracy, side by side (run with --release).
    #[command(disable_help_flag = true)]
    Tradeoffs {
        #[arg(trailing_var_arg = true, allow_hyphen_values = true)]
        args: Vec<String>,
    },
    /// The course's maintenance (instructors).
    Dev {
        #[command(subcommand)]
        command: DevCmd,
    },
    // INSTRUCTOR END
}

// INSTRUCTOR BEGIN
#[derive(Subcommand)]
enum DevCmd {
    /// Rewrite the lists of lectures that Cargo and mdBook cannot read from the lectures'
    /// Cargo.toml (features, dependencies, SUMMARY.md, the tables of the README and the book).
    Sync {
        /// Change nothing; fail naming every stale list.
        #[arg(long)]
        check: bool,
    },
}
// INSTRUCTOR END

/// The precision and profile this grader was built with, which the checks
/// are built with too: `cargo run -p grader --features raylab/f64` grades in f64.
fn precision_is_f64() -> bool {
    size_of::<raylab::Float>() == 8
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => grade_command(&Workspace::open(&workspace::own_root()), &cli.grade, None),
        Some(Cmd::Hint { select }) => {
            Workspace::open(&workspace::own_root()).and_then(|ws| hint(&ws, &select))
        }
        Some(Cmd::Watch) => {
            Workspace::open(&workspace::own_root()).and_then(|ws| watch::watch(&ws, options()))
        }
        Some(Cmd::Handout { dir, force }) => {
            handout::write(&workspace::own_root(), &dir, force).map(|()| true)
        }
        Some(Cmd::Grade { submission, workdir, run_as, grade }) => {
            // The student's code may run as this user: keep it out of this process's pipes.
            platform::keep_others_out();
            let run_as: Result<Vec<platform::RunAs>, String> =
                run_as.iter().map(|u| platform::user(u)).collect();
            run_as.and_then(|run_as| {
                if !run_as.is_empty() {
                    // The grading user's processes are capped (a fork bomb); root, this, is not. What
                    // a check leaves is ended and reaped here.
                    platform::limit_user_processes(platform::USER_PROCESSES)?;
                    platform::adopt_orphans();
                }
                let root = workspace::own_root();
                // Held until the grade ends (the rest of `prepared` lives to the end of this
                // closure): another grader given this work folder waits for this grade.
                let prepared = submission::prepare(&root, &submission, workdir.as_deref(), run_as.first())?;
                let (ws, target) = (prepared.ws, prepared.target);
                // Built beside the submission's build; waited for when its list is read.
                let judge = submission::Judge::building(&root, &options());
                let graded =
                    grade_command(&Ok(ws), &grade, Some(Submission { target, judge: judge.clone(), run_as }));
                // Whatever the grade came to, the judge's build ends before this process does (its
                // tree and lock are left whole for the next grade).
                let _ = judge.binary();
                graded
            })
        }
        Some(Cmd::Gradescope { dir, force }) => {
            gradescope::bundle(&workspace::own_root(), &dir, force).map(|()| true)
        }
        Some(Cmd::Render { args }) => forward("render", &args),
        Some(Cmd::Bless { args }) => forward("bless", &args),
        Some(Cmd::BenchRays { args }) => forward("bench-rays", &args),
        // INSTRUCTOR BEGIN
        Some(Cmd::Tradeoffs { args }) => forward("tradeoffs", &args),
        Some(Cmd::Dev { command: DevCmd::Sync { check } }) => sync::sync(&workspace::own_root(), check),
        Some(Cmd::Class(args)) => class::command(&args, &options()),
        // INSTRUCTOR END
    };
    match result {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::from(2)
        }
    }
}

/// The grading options of this build of the grader, for all lectures.
fn options() -> GradeOptions {
    GradeOptions {
        selection: Selection::default(),
        hidden: false,
        release: !cfg!(debug_assertions),
        f64: precision_is_f64(),
        target_dir: None,
        only_prerequisites: false,
        jobs: std::thread::available_parallelism().map_or(2, |n| n.get()),
        show_progress: true,
        binary: std::env::var_os("RAYLAB_CHECKS_BINARY").map(PathBuf::from),
        judge: None,
        run_as: Vec::new(),
        out_dir: None,
    }
}

/// Grades and prints; `Ok(false)` when `--strict` and not everything passed.
/// A submission graded in a work folder (`grader grade --submission`).
struct Submission {
    /// The work folder's target folder.
    target: PathBuf,
    /// The judge (`submission::judge`), maybe still building.
    judge: submission::Judge,
    /// The users the student's code runs as (`--run-as`), one per job.
    run_as: Vec<platform::RunAs>,
}

fn grade_command(
    ws: &Result<Workspace, String>,
    args: &GradeArgs,
    submission: Option<Submission>,
) -> Result<bool, String> {
    let ws = ws.as_ref().map_err(Clone::clone)?;
    let mut options = options();
    options.selection = Selection::parse(&args.select)?;
    options.only_prerequisites = true;
    if let Some(Submission { target, judge, run_as }) = submission {
        // A submission: hidden checks in, judged checks judged apart from the student's code.
        options.hidden = true;
        options.target_dir = Some(target);
        options.judge = Some(judge);
        options.run_as = run_as;
        // The grader's output stays its own, beside the student's build (see submission::prepare).
        options.out_dir = Some(ws.root.join("target").join("grader"));
    }
    if let Some(jobs) = args.jobs {
        options.jobs = jobs;
    }
    // Progress lines would spoil machine-readable output on a terminal that merges the streams.
    options.show_progress = args.format == Format::Table;
    let grade = grade::grade(ws, &options)?;
    let out = grade::out_dir(ws, &options);
    let report = report::write(ws, &grade, &out);
    let text = match args.format {
        Format::Table => output::table(ws, &grade),
        Format::Json => pretty_json(&output::json(ws, &grade))?,
        Format::Gradescope => pretty_json(&output::gradescope(&grade))?,
    };
    match &args.output {
        Some(path) => std::fs::write(path, &text).map_err(|e| format!("{}: {e}", path.display()))?,
        None => print!("{text}"),
    }
    if args.format == Format::Table {
        match report {
            Ok(path) => println!("report: {}", path.display()),
            Err(e) => eprintln!("the report could not be written: {e}"),
        }
    }
    Ok(!args.strict || grade.all_passed())
}

fn pretty_json(value: &serde_json::Value) -> Result<String, String> {
    serde_json::to_string_pretty(value).map(|s| s + "\n").map_err(|e| e.to_string())
}

/// `grader hint 05` or `grader hint 05/lambert`.
fn hint(ws: &Workspace, select: &str) -> Result<bool, String> {
    let selection = Selection::parse(&[select])?;
    let lecture = selection.lectures()[0];
    let hints = ws.hints(lecture)?;
    let exercise = selection.0[0].split('/').nth(1);
    let mut shown = 0;
    for (name, lines) in &hints {
        if exercise.is_some_and(|e| e != name) {
            continue;
        }
        println!("{lecture}/{name}");
        for (i, line) in lines.iter().enumerate() {
            println!("  {}. {line}", i + 1);
        }
        shown += 1;
    }
    if shown == 0 {
        let known: Vec<&str> = hints.keys().map(String::as_str).collect();
        return Err(format!("no hints for {select}; lecture {lecture} has hints for: {}", known.join(", ")));
    }
    Ok(true)
}

/// The exit status of a tool stopped by Ctrl-C (`raylab-checks render`): 128 + SIGINT.
const INTERRUPTED: i32 = 130;

/// Builds the checks with every lecture and runs one of its tools.
fn forward(tool: &str, args: &[String]) -> Result<bool, String> {
    let ws = Workspace::open(&workspace::own_root())?;
    let mut options = options();
    options.show_progress = true;
    let binary = match options.binary.clone() {
        Some(binary) => binary,
        None => {
            let all = ws.lectures.iter().map(|l| l.number.clone()).collect();
            let built = compile::build(
                &ws,
                &compile::BuildOptions {
                    lectures: all,
                    tools: true,
                    hidden: false,
                    release: options.release,
                    f64: options.f64,
                    target_dir: None,
                    build_dir: None,
                    show_progress: true,
                    run_as: None,
                    submission: false,
                },
            )?;
            if let Some((lecture, error)) = built.failed.iter().next() {
                return Err(format!(
                    "`grader {tool}` uses every lecture, and lecture {lecture} does not compile: {} at {}",
                    error.message, error.location
                ));
            }
            built.binary
        }
    };
    // Ctrl-C reaches the tool too (one process group): the tool stops cleanly and says so, and
    // this process waits for it instead of dying first, then exits as it did.
    let _ = ctrlc::set_handler(|| {});
    let status = std::process::Command::new(&binary)
        .arg(tool)
        .args(args)
        .status()
        .map_err(|e| format!("could not run {}: {e}", binary.display()))?;
    if status.code() == Some(INTERRUPTED) {
        std::process::exit(INTERRUPTED);
    }
    Ok(status.success())
}
