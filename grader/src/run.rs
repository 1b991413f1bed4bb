//! Running one check in its own process, with a time limit and a cap on
//! what it may print: whatever the student's code does, the grader gets an
//! answer back and carries on.

use std::collections::BTreeSet;
use std::ffi::OsString;
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError};
use std::sync::{Arc, Mutex};
use std::thread;
use std::time::{Duration, Instant};

use raylab_protocol::{JUDGE_LISTENING, JUDGE_VERDICT, NO_VERDICT};

/// How much of a check's stdout and stderr the grader keeps (each): enough
/// for a panic message and a backtrace's first frames.
pub const KEPT_OUTPUT: usize = 16 * 1024;

/// A check that prints more than this in all is stopped: a print in a pixel
/// loop, say, which would otherwise fill the disk of a grading machine.
pub const MAX_OUTPUT: u64 = 32 * 1024 * 1024;

/// How a check's process ended.
#[derive(Debug)]
pub struct Ran {
    /// The process's exit status; `None` when the grader stopped it.
    pub status: Option<ExitStatus>,
    pub timed_out: bool,
    pub too_much_output: bool,
    /// What the check wrote to its verdict file (its outcome, or a panic).
    pub verdict: Option<String>,
    /// The first [`KEPT_OUTPUT`] bytes of each stream.
    pub stdout: String,
    pub stderr: String,
    pub seconds: f64,
}

/// Runs `binary run ID --verdict … --out …` with a time limit.
pub fn run_check(
    binary: &Path,
    id: &str,
    scratch: &Path,
    out: &Path,
    timeout: Duration,
) -> Result<Ran, String> {
    let verdict = scratch.join(format!("{}.json", id.replace(['/', ':'], "_")));
    let _ = std::fs::remove_file(&verdict);
    let mut args: Vec<OsString> = vec!["run".into(), id.into(), "--verdict".into(), verdict.clone().into()];
    args.extend(["--out".into(), out.into()]);
    let mut ran = run_process(binary, id, &args, timeout, None, None)?;
    ran.verdict = std::fs::read_to_string(&verdict).ok();
    Ok(ran)
}

/// How long a judge may take once its subject has ended: it runs no student
/// code, only the check's own (an image comparison at most).
const JUDGE_GRACE: Duration = Duration::from_secs(60);

/// Runs a judged check (`grader/checks/core/src/judge.rs`): `judge ID` from the
/// `judge` binary, which runs no student code and prints the verdict, and
/// `run ID --channel ADDR` (a hidden check: `serve --channel ADDR`) from
/// `subject`, the student's build, under the time limit and output caps. The
/// verdict is the judge's; when it has none (the subject ended before the
/// check did), how the subject ended.
pub fn run_judged(
    subject: &Path,
    judge: &Path,
    info: &raylab_protocol::Info,
    out: &Path,
    timeout: Duration,
    run_as: Option<&crate::platform::RunAs>,
) -> Result<Ran, String> {
    let id = info.id.as_str();
    let token = fresh_token();
    // The token goes on the standard input of both, never on a command line (which every process
    // of the machine may read under /proc).
    let mut judging = Command::new(judge)
        .args(["judge", id, "--out"])
        .arg(out)
        .env("RAYON_NUM_THREADS", "1")
        .env("RUST_BACKTRACE", "0")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("could not start the judge {}: {e}", judge.display()))?;
    if let Some(mut input) = judging.stdin.take() {
        let _ = input.write_all(raylab_protocol::token_line(token).as_bytes());
    }
    let mut first = String::new();
    let mut judge_out = BufReader::new(judging.stdout.take().ok_or("the judge's stdout")?);
    let _ = judge_out.read_line(&mut first);
    let Some(address) = first.trim().strip_prefix(JUDGE_LISTENING).map(str::to_owned) else {
        let _ = judging.kill();
        let _ = judging.wait();
        let mut stderr = String::new();
        if let Some(mut e) = judging.stderr.take() {
            let _ = e.read_to_string(&mut stderr);
        }
        return Err(format!("the judge of {id} did not start: {}", stderr.trim()));
    };
    let judge_err = judging.stderr.take();
    let (judge_closed, judge_streams_closed) = mpsc::channel();
    let judge_streams = thread::spawn(move || {
        let (mut out, mut err) = (String::new(), String::new());
        let _ = judge_out.read_to_string(&mut out);
        if let Some(mut e) = judge_err {
            let _ = e.read_to_string(&mut err);
        }
        let _ = judge_closed.send(());
        (out, err)
    });
    // A hidden check runs in the judge alone; its subject makes the calls the judge asks for.
    let mut args: Vec<OsString> = if info.hidden {
        vec!["serve".into()]
    } else {
        vec!["run".into(), id.into(), "--out".into(), out.into()]
    };
    args.extend(["--channel".into(), address.clone().into()]);
    let token_line = raylab_protocol::token_line(token);
    let ran = run_process(subject, id, &args, timeout, run_as, Some(token_line.as_bytes()));
    // A subject that never connected leaves the judge waiting for it: this word ends that wait.
    // After a subject did connect, the judge listens no more; and should its port be another
    // judge's by now, that judge has another token and drops this connection.
    if let Ok(address) = address.parse()
        && let Ok(mut stream) = TcpStream::connect_timeout(&address, Duration::from_secs(1))
    {
        let _ = stream.write_all(&raylab_protocol::no_subject(token));
    }
    let deadline = Instant::now() + JUDGE_GRACE;
    let (judged, _) = wait_for(&mut judging, deadline, &judge_streams_closed, &|| false)
        .map_err(|e| format!("waiting for the judge of {id}: {e}"))?;
    if judged.is_none() {
        let _ = judging.kill();
        let _ = judging.wait();
    }
    let (printed, errors) = judge_streams.join().unwrap_or_default();
    let mut ran = ran?;
    match judged {
        Some(status) if status.success() => {
            ran.verdict =
                printed.lines().rev().find_map(|l| l.strip_prefix(JUDGE_VERDICT)).map(str::to_owned);
            Ok(ran)
        }
        // The subject ended before the check did: how it ended is the verdict.
        Some(status) if status.code() == Some(NO_VERDICT) => Ok(ran),
        Some(status) => Err(format!("the judge of {id} failed ({status}): {}", errors.trim())),
        None => Err(format!("the judge of {id} took longer than {} s", JUDGE_GRACE.as_secs())),
    }
}

/// A token no other judge of this machine's has now: what pairs a judge with its subject.
fn fresh_token() -> u64 {
    use std::hash::{BuildHasher, Hasher};
    static COUNT: AtomicU64 = AtomicU64::new(0);
    // std's hasher keys are random per process; the count and the time tell this process's apart.
    let mut hasher = std::collections::hash_map::RandomState::new().build_hasher();
    hasher.write_u64(COUNT.fetch_add(1, Ordering::Relaxed));
    hasher.write_u32(std::process::id());
    hasher.write_u128(
        std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_nanos()),
    );
    hasher.finish()
}

/// The process groups of the subjects running as the grading user now (each its leader's id):
/// what [`crate::platform::sweep`] leaves alone of that user's processes.
static LIVE: Mutex<BTreeSet<u32>> = Mutex::new(BTreeSet::new());

/// Runs `binary ARGS` (one check, `id`) with a time limit and a cap on its output, as `run_as` if
/// given, `input` on its standard input. As another user, whatever the check leaves behind is
/// ended with it: its process group, every other process of that user's not in the group of a
/// check running now (one that left its group: `setsid`, a double fork), and that user's files
/// in the machine's temporary folders.
fn run_process(
    binary: &Path,
    id: &str,
    args: &[OsString],
    timeout: Duration,
    run_as: Option<&crate::platform::RunAs>,
    input: Option<&[u8]>,
) -> Result<Ran, String> {
    let start = Instant::now();
    let mut command = Command::new(binary);
    command
        .args(args)
        // Checks run side by side, one per core: each renders on one thread, and the same code gives
        // the same pixels on every run.
        .env("RAYON_NUM_THREADS", "1")
        .env("RUST_BACKTRACE", "0")
        .stdin(if input.is_some() { Stdio::piped() } else { Stdio::null() })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    // In a process group of its own, so that what it starts ends with it.
    crate::platform::own_group(&mut command);
    if let Some(user) = run_as {
        crate::platform::run_as(&mut command, user);
    }
    // Registered as live before a sweep can see it.
    let mut child = {
        let mut live = LIVE.lock().map_err(|_| "the live checks' lock")?;
        let child = command.spawn().map_err(|e| format!("could not start {}: {e}", binary.display()))?;
        if run_as.is_some() {
            live.insert(child.id());
        }
        child
    };
    if let (Some(bytes), Some(mut stdin)) = (input, child.stdin.take()) {
        let _ = stdin.write_all(bytes);
    }
    let printed = Arc::new(AtomicU64::new(0));
    let flood = Arc::new(AtomicBool::new(false));
    // Each drain says when its stream has closed and all it kept is in.
    let (closed, streams_closed) = mpsc::channel();
    let drain = |stream: Option<Box<dyn Read + Send>>| {
        let (printed, flood, closed) = (printed.clone(), flood.clone(), closed.clone());
        let kept = Arc::new(Mutex::new(Vec::new()));
        let into = kept.clone();
        thread::spawn(move || {
            drain_stream(stream, &into, &printed, &flood);
            let _ = closed.send(());
        });
        kept
    };
    let stdout = drain(child.stdout.take().map(|s| Box::new(s) as Box<dyn Read + Send>));
    let stderr = drain(child.stderr.take().map(|s| Box::new(s) as Box<dyn Read + Send>));
    drop(closed);
    let deadline = start + timeout;
    let (status, mut drained) =
        wait_for(&mut child, deadline, &streams_closed, &|| flood.load(Ordering::Relaxed))
            .map_err(|e| format!("waiting for {id}: {e}"))?;
    let timed_out = status.is_none() && !flood.load(Ordering::Relaxed);
    if status.is_none() {
        let _ = child.kill();
        let _ = child.wait();
    }
    // Whatever it started goes too (a child holding its output pipe would keep the drains waiting).
    crate::platform::end_group(&child);
    if let Some(user) = run_as {
        let mut live = LIVE.lock().map_err(|_| "the live checks' lock")?;
        live.remove(&child.id());
        crate::platform::sweep(user, &live);
    }
    // And a process that left the group and kept the pipes is not waited for.
    let grace = Instant::now() + DRAIN_GRACE;
    while drained < 2 {
        match streams_closed.recv_timeout(grace.saturating_duration_since(Instant::now())) {
            Ok(()) => drained += 1,
            Err(_) => break,
        }
    }
    let text = |kept: &Arc<Mutex<Vec<u8>>>| {
        String::from_utf8_lossy(&kept.lock().map(|k| k.clone()).unwrap_or_default()).into_owned()
    };
    Ok(Ran {
        status,
        timed_out,
        too_much_output: flood.load(Ordering::Relaxed),
        verdict: None,
        stdout: text(&stdout),
        stderr: text(&stderr),
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// How long the grader waits for a check's output pipes to close once the
/// check has ended and its process group is gone.
const DRAIN_GRACE: Duration = Duration::from_secs(2);

/// How often a running process is looked at while nothing else wakes the wait.
const POLL: Duration = Duration::from_millis(5);

/// Waits for `child` to end, until `deadline` or until `stop` says so: its status, or `None`, and
/// how many of its streams said they closed (`closed`: a message each). A process's end closes its
/// streams, so the wait wakes when one closes and looks again at once (then every 0.1 ms, doubling
/// up to [`POLL`], while the process is being reaped); otherwise it looks every [`POLL`]. Sleeping
/// 5 ms between looks (and 5 ms more for the drains) cost lecture 10's grade, 90 processes two at a
/// time, 0.1 s of its 1.6 s.
fn wait_for(
    child: &mut Child,
    deadline: Instant,
    closed: &Receiver<()>,
    stop: &dyn Fn() -> bool,
) -> std::io::Result<(Option<ExitStatus>, usize)> {
    let (mut streams_closed, mut pause) = (0, POLL);
    loop {
        if let Some(status) = child.try_wait()? {
            return Ok((Some(status), streams_closed));
        }
        let now = Instant::now();
        if stop() || now >= deadline {
            return Ok((None, streams_closed));
        }
        match closed.recv_timeout(pause.min(deadline - now)) {
            Ok(()) => {
                streams_closed += 1;
                pause = Duration::from_micros(100);
            }
            Err(RecvTimeoutError::Timeout) => pause = (pause * 2).min(POLL),
            Err(RecvTimeoutError::Disconnected) => {
                thread::sleep(pause.min(deadline - now));
                pause = (pause * 2).min(POLL);
            }
        }
    }
}

/// Reads a stream to its end, keeping its first [`KEPT_OUTPUT`] bytes in `kept`
/// and raising `flood` once all streams together passed [`MAX_OUTPUT`].
fn drain_stream(
    stream: Option<Box<dyn Read + Send>>,
    kept: &Mutex<Vec<u8>>,
    printed: &AtomicU64,
    flood: &AtomicBool,
) {
    let Some(mut stream) = stream else { return };
    let mut buffer = [0u8; 64 * 1024];
    loop {
        match stream.read(&mut buffer) {
            Ok(0) | Err(_) => break,
            Ok(n) => {
                if let Ok(mut kept) = kept.lock() {
                    let room = KEPT_OUTPUT.saturating_sub(kept.len());
                    kept.extend_from_slice(&buffer[..n.min(room)]);
                }
                if printed.fetch_add(n as u64, Ordering::Relaxed) + n as u64 > MAX_OUTPUT {
                    flood.store(true, Ordering::Relaxed);
                }
            }
        }
    }
}

/// A scratch folder for verdict files.
pub fn scratch_dir(out: &Path) -> Result<PathBuf, String> {
    let dir = out.join("verdicts");
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    Ok(dir)
}
