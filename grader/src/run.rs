//! Running one check in its own process, with a time limit and a cap on
//! what it may print: whatever the student's code does, the grader gets an
//! answer back and carries on.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitStatus, Stdio};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::thread;
use std::time::{Duration, Instant};

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
    let start = Instant::now();
    let mut child = Command::new(binary)
        .args(["run", id, "--verdict"])
        .arg(&verdict)
        .arg("--out")
        .arg(out)
        // Checks run side by side, one per core: each renders on one thread, and the same code gives
        // the same pixels on every run.
        .env("RAYON_NUM_THREADS", "1")
        .env("RUST_BACKTRACE", "0")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("could not start {}: {e}", binary.display()))?;
    let printed = Arc::new(AtomicU64::new(0));
    let flood = Arc::new(AtomicBool::new(false));
    let drain = |stream: Option<Box<dyn Read + Send>>| {
        let (printed, flood) = (printed.clone(), flood.clone());
        thread::spawn(move || drain_stream(stream, &printed, &flood))
    };
    let stdout = drain(child.stdout.take().map(|s| Box::new(s) as Box<dyn Read + Send>));
    let stderr = drain(child.stderr.take().map(|s| Box::new(s) as Box<dyn Read + Send>));
    let deadline = start + timeout;
    let (mut status, mut timed_out) = (None, false);
    loop {
        match child.try_wait() {
            Ok(Some(s)) => {
                status = Some(s);
                break;
            }
            Ok(None) if flood.load(Ordering::Relaxed) => break,
            Ok(None) if Instant::now() >= deadline => {
                timed_out = true;
                break;
            }
            Ok(None) => thread::sleep(Duration::from_millis(5)),
            Err(e) => return Err(format!("waiting for {id}: {e}")),
        }
    }
    if status.is_none() {
        let _ = child.kill();
        let _ = child.wait();
    }
    let stdout = stdout.join().unwrap_or_default();
    let stderr = stderr.join().unwrap_or_default();
    Ok(Ran {
        status,
        timed_out,
        too_much_output: flood.load(Ordering::Relaxed),
        verdict: std::fs::read_to_string(&verdict).ok(),
        stdout,
        stderr,
        seconds: start.elapsed().as_secs_f64(),
    })
}

/// Reads a stream to its end, keeping its first [`KEPT_OUTPUT`] bytes and
/// raising `flood` once all streams together passed [`MAX_OUTPUT`].
fn drain_stream(stream: Option<Box<dyn Read + Send>>, printed: &AtomicU64, flood: &AtomicBool) -> String {
    let Some(mut stream) = stream else { return String::new() };
    let mut kept = Vec::new();
    let mut buffer = [0u8; 64 * 1024];
    loop {
        match stream.read(&mut buffer) {
            Ok(0) | Err(_) => break,
            Ok(n) => {
                let room = KEPT_OUTPUT.saturating_sub(kept.len());
                kept.extend_from_slice(&buffer[..n.min(room)]);
                if printed.fetch_add(n as u64, Ordering::Relaxed) + n as u64 > MAX_OUTPUT {
                    flood.store(true, Ordering::Relaxed);
                }
            }
        }
    }
    String::from_utf8_lossy(&kept).into_owned()
}

/// A scratch folder for verdict files.
pub fn scratch_dir(out: &Path) -> Result<PathBuf, String> {
    let dir = out.join("verdicts");
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    Ok(dir)
}
