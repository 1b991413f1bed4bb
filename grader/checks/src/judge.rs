//! Who decides a check's verdict: the process that runs the student's code
//! must not be the one that judges it.
//!
//! Graded locally (`cargo run -p grader`) a check runs in one process, as
//! ever ([`Mode::Direct`]). Graded as a submission, each judged check runs
//! twice, in step, in two processes the driver starts:
//!
//! - the **subject** (`raylab-checks run ID --channel ADDR`), built from the
//!   student's lectures, runs the check's code; each value the student's code
//!   returns ([`student`]) it sends to the judge, and each decision that needs
//!   what only the judge holds ([`decide`]: a snapshot, a hidden answer) it
//!   receives from the judge. It writes no verdict.
//! - the **judge** (`raylab-checks judge ID`), built from the
//!   course with every exercise stubbed (`todo!()`), runs the same code, but
//!   where the subject calls the student it takes the value the subject sent,
//!   so no student code (and no reference solution) runs in it; it makes the
//!   decisions and prints the verdict (a pipe only the driver reads; on
//!   Linux the judge is not dumpable, so the student's processes cannot open
//!   its pipes through `/proc` either).
//!
//! Both run the same deterministic code on the same inputs, so they take the
//! same path; a value of the wrong type or from another call site ends the
//! check as failed, and a subject that stops early (an exit, a crash, a
//! forged early end) leaves the judge without a verdict, which the driver
//! reports from how the subject ended. What the student's process can send
//! is what the student's code could return: values, never a verdict.

use std::io::{BufReader, BufWriter, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::panic::Location;
use std::sync::{Mutex, OnceLock};

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use raylab_protocol::{JUDGE_LISTENING, JUDGE_VERDICT, NO_VERDICT};

use crate::check::{Outcome, fail};

/// What one process tells the other.
#[derive(Debug, Serialize, Deserialize)]
enum Frame {
    /// A value of the student's code (subject → judge) or a decision (judge →
    /// subject), postcard-encoded, with the call site that made it.
    Value { site: String, bytes: Vec<u8> },
    /// The student's code panicked (subject → judge): what the check would have
    /// written itself.
    Panic { message: String, file: String, line: u32 },
    /// A call of the student's code for the subject to make (judge → subject, a hidden
    /// check's: the `remote` module's), postcard-encoded.
    Call { bytes: Vec<u8> },
}

/// How this process takes part in a check.
enum Mode {
    /// One process runs the student's code and judges it: local grading.
    Direct,
    /// Runs the student's code and reports its values.
    Subject(Channel),
    /// Judges from the values reported.
    Judge(Channel),
}

/// The connection to the other process, buffered both ways: a check may send
/// tens of thousands of small values (the leak test's rays), so the subject
/// writes them out in blocks, and flushes before it waits for a decision and
/// when the check ends (`flush`) or panics.
struct Channel {
    out: Mutex<BufWriter<TcpStream>>,
    input: Mutex<BufReader<TcpStream>>,
}

impl Channel {
    fn new(stream: TcpStream) -> Result<Self, String> {
        let _ = stream.set_nodelay(true);
        let reader = stream.try_clone().map_err(|e| format!("the channel: {e}"))?;
        Ok(Self {
            out: Mutex::new(BufWriter::with_capacity(1 << 16, stream)),
            input: Mutex::new(BufReader::with_capacity(1 << 16, reader)),
        })
    }
}

static MODE: OnceLock<Mode> = OnceLock::new();

fn mode() -> &'static Mode {
    MODE.get_or_init(|| Mode::Direct)
}

/// The largest frame read: a 1024 × 1024 image of f64 colours is 24 MiB.
const MAX_FRAME: u32 = 64 << 20;

/// A value computed by the student's code: `f()` in the subject (sent to the
/// judge) and locally, the subject's value in the judge (`f` is not run). A
/// `student` call inside another's `f` (a proxy handed to the student's code,
/// as `hit_transformed` takes the local shape's) is part of the outer value:
/// it is not sent on its own.
#[track_caller]
pub fn student<T: Serialize + DeserializeOwned>(f: impl FnOnce() -> T) -> T {
    // The call site is named only where a value crosses: local grading pays nothing.
    let at = Location::caller();
    match mode() {
        Mode::Direct => f(),
        Mode::Subject(_) if INSIDE.get() => f(),
        Mode::Subject(channel) => {
            INSIDE.set(true);
            let value = f();
            INSIDE.set(false);
            send(channel, &site(at), &value);
            value
        }
        Mode::Judge(channel) => receive(channel, &site(at)),
    }
}

/// The student's code run under [`raylab::stats::measure`]: its value and the rays it
/// counted, as one value through [`student`] (in the judge the code does not run, so it counts
/// nothing of its own).
#[track_caller]
pub fn measured<T: Serialize + DeserializeOwned>(f: impl FnOnce() -> T) -> (T, raylab::stats::RayStats) {
    student(|| raylab::stats::measure(f))
}

thread_local! {
    /// Whether this thread is inside a `student` call's `f` (the subject's).
    static INSIDE: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// A decision only the judge can make (it holds the snapshots and the hidden
/// answers): `f()` in the judge (sent to the subject) and locally; in the
/// subject, the judge's answer (`f` is not run).
#[track_caller]
pub fn decide<T: Serialize + DeserializeOwned>(f: impl FnOnce() -> T) -> T {
    let at = Location::caller();
    match mode() {
        Mode::Direct => f(),
        Mode::Judge(channel) => {
            let value = f();
            send(channel, &site(at), &value);
            value
        }
        Mode::Subject(channel) => receive(channel, &site(at)),
    }
}

/// Work only the judge does (it holds the snapshots and the hidden answers): `f()` in the
/// judge and locally; in the subject nothing (`None`). What the subject must know of its result
/// to take the same path it learns through [`decide`].
pub fn judge_only<T>(f: impl FnOnce() -> T) -> Option<T> {
    match mode() {
        Mode::Subject(_) => None,
        Mode::Direct | Mode::Judge(_) => Some(f()),
    }
}

/// `file:line` of a call, as the frames name it.
fn site(at: &Location) -> String {
    format!("{}:{}", at.file(), at.line())
}

/// Sends a value; a decision (the judge's) goes out at once, the subject's values in blocks.
fn send<T: Serialize>(channel: &Channel, site: &str, value: &T) {
    let bytes = postcard::to_stdvec(value).expect("a check's values encode");
    let now = matches!(mode(), Mode::Judge(_));
    write_frame(channel, &Frame::Value { site: site.to_owned(), bytes }, now);
}

fn write_frame(channel: &Channel, frame: &Frame, flush: bool) {
    let bytes = postcard::to_stdvec(frame).expect("a frame encodes");
    let Ok(mut stream) = channel.out.lock() else { std::process::exit(NO_VERDICT) };
    let length = u32::try_from(bytes.len()).unwrap_or(u32::MAX).to_le_bytes();
    let written = stream.write_all(&length).and_then(|()| stream.write_all(&bytes));
    // The other side gone: nothing left to do here.
    if written.and_then(|()| if flush { stream.flush() } else { Ok(()) }).is_err() {
        std::process::exit(NO_VERDICT);
    }
}

/// Sends what the subject has buffered: before it waits, and when its check ends.
pub fn flush() {
    if let Mode::Subject(channel) = mode()
        && let Ok(mut stream) = channel.out.lock()
    {
        let _ = stream.flush();
    }
}

fn read_frame(channel: &Channel) -> Result<Option<Frame>, String> {
    // A subject about to wait for a decision sends what it has first.
    flush();
    let Ok(mut stream) = channel.input.lock() else { return Ok(None) };
    let mut length = [0u8; 4];
    if stream.read_exact(&mut length).is_err() {
        return Ok(None);
    }
    let length = u32::from_le_bytes(length);
    if length > MAX_FRAME {
        return Err(format!("a frame of {length} bytes"));
    }
    let mut bytes = vec![0u8; length as usize];
    if stream.read_exact(&mut bytes).is_err() {
        return Ok(None);
    }
    postcard::from_bytes(&bytes).map(Some).map_err(|e| format!("an unreadable frame ({e})"))
}

/// The next value from the other process, for the call at `site`. In the
/// judge, a panic the subject reported ends the check with that panic's
/// outcome, and a value that does not fit ends it as failed.
fn receive<T: DeserializeOwned>(channel: &Channel, site: &str) -> T {
    let frame = match read_frame(channel) {
        Ok(Some(frame)) => frame,
        // The other side ended: the subject before the check did, or the judge with its verdict.
        Ok(None) => std::process::exit(NO_VERDICT),
        Err(e) => out_of_step(&e),
    };
    match frame {
        Frame::Value { site: sent, bytes } if sent == site => {
            postcard::from_bytes(&bytes).unwrap_or_else(|e| out_of_step(&format!("a value at {site} ({e})")))
        }
        Frame::Value { site: sent, .. } => out_of_step(&format!("a value from {sent} where {site} was due")),
        Frame::Panic { message, file, line } => conclude(&Outcome::Panicked { message, file, line }),
        Frame::Call { .. } => out_of_step("a call where a value was due"),
    }
}

/// Where the values of [`call`]s come from, as the frames name it.
const CALL_SITE: &str = "a call of the judge's";

/// A call of the student's code, `call` encoded (a hidden check's, the `remote` module's): made in
/// place locally, by `here`, which returns its value encoded; in the judge, sent to the subject,
/// which makes it and returns the value.
pub fn call<T: DeserializeOwned>(call: Vec<u8>, here: impl FnOnce() -> Result<Vec<u8>, String>) -> T {
    match mode() {
        Mode::Direct => {
            let bytes = here().unwrap_or_else(|e| panic!("{e}"));
            postcard::from_bytes(&bytes).unwrap_or_else(|e| panic!("a call's value: {e}"))
        }
        Mode::Judge(channel) => {
            write_frame(channel, &Frame::Call { bytes: call }, true);
            receive(channel, CALL_SITE)
        }
        // The subject's build has no hidden checks: nothing in it makes a call.
        Mode::Subject(_) => std::process::exit(NO_VERDICT),
    }
}

/// The subject of a hidden check (`raylab-checks serve`): makes each call the judge sends and
/// returns its value, until the judge ends (with its verdict): `answer` makes an encoded call
/// and encodes its value. A panic of the student's code goes to the judge through the panic
/// hook, as in a check.
pub fn serve_calls(answer: impl Fn(&[u8]) -> Result<Vec<u8>, String>) -> Result<(), String> {
    let Mode::Subject(channel) = mode() else { return Err("serve needs --channel".into()) };
    loop {
        let frame = match read_frame(channel) {
            Ok(Some(frame)) => frame,
            // The judge has its verdict.
            Ok(None) => return Ok(()),
            Err(e) => return Err(e),
        };
        let Frame::Call { bytes } = frame else {
            return Err("the judge sent a frame other than a call".into());
        };
        match answer(&bytes) {
            Ok(bytes) => write_frame(channel, &Frame::Value { site: CALL_SITE.to_owned(), bytes }, true),
            Err(message) => report_panic(&message, file!(), line!()),
        }
    }
}

/// Ends the judge with `outcome` as the verdict.
fn conclude(outcome: &Outcome) -> ! {
    if let Ok(json) = serde_json::to_string(outcome) {
        let _ = print_verdict(&json);
    }
    std::process::exit(0)
}

/// The judge's verdict, a `verdict JSON` line on its stdout: a pipe only the
/// driver reads (a file could be written by the student's process too).
pub fn print_verdict(json: &str) -> Result<(), String> {
    let mut out = std::io::stdout().lock();
    writeln!(out, "{JUDGE_VERDICT}{json}").and_then(|()| out.flush()).map_err(|e| e.to_string())
}

/// Values that no honest subject sends: the check fails (never passes), saying so.
fn out_of_step(what: &str) -> ! {
    if !matches!(mode(), Mode::Judge(_)) {
        std::process::exit(NO_VERDICT);
    }
    conclude(&Outcome::Failed(fail(
        "the values your code returned, as the check's process reported them",
        "one value of the expected type per call, in the check's order",
        what,
        "the process that ran your code sent what the check never sends: it ran something other than \
         the check (an exit or a write of its own in your code?)",
    )))
}

/// The subject's side: connects to the judge at `address` before any of the
/// student's code runs, and reports a panic of the student's code to it.
pub fn connect(address: &str, token: u64) -> Result<(), String> {
    let mut stream = TcpStream::connect(address).map_err(|e| format!("the judge at {address}: {e}"))?;
    stream.write_all(&raylab_protocol::hello(token)).map_err(|e| format!("the judge at {address}: {e}"))?;
    MODE.set(Mode::Subject(Channel::new(stream)?)).map_err(|_| "the mode is set twice".to_owned())
}

/// Tells the judge that the student's code panicked (the subject's panic hook).
pub fn report_panic(message: &str, file: &str, line: u32) {
    if let Mode::Subject(channel) = mode() {
        write_frame(
            channel,
            &Frame::Panic { message: message.to_owned(), file: file.to_owned(), line },
            true,
        );
    }
}

/// The judge's side: listens on a loopback port, prints `listening ADDR` on stdout for the
/// driver, and takes the first connection that says `token` as the subject's. Another
/// connection is dropped: one meant for an earlier judge on the same port (the driver's, sent
/// to a judge that had already ended). The driver's word that the subject ended without
/// connecting ends this judge without a verdict.
pub fn serve(token: u64) -> Result<(), String> {
    let listener = TcpListener::bind("127.0.0.1:0").map_err(|e| format!("a loopback port: {e}"))?;
    let address = listener.local_addr().map_err(|e| e.to_string())?;
    let mut out = std::io::stdout().lock();
    writeln!(out, "{JUDGE_LISTENING}{address}").and_then(|()| out.flush()).map_err(|e| e.to_string())?;
    let stream = loop {
        let (mut stream, _) = listener.accept().map_err(|e| format!("the subject's connection: {e}"))?;
        // A connection that says nothing is not waited for long.
        let _ = stream.set_read_timeout(Some(std::time::Duration::from_secs(2)));
        let mut hello = [0u8; 8];
        if stream.read_exact(&mut hello).is_err() {
            continue;
        }
        if hello == raylab_protocol::hello(token) {
            stream.set_read_timeout(None).map_err(|e| format!("the subject's connection: {e}"))?;
            break stream;
        }
        if hello == raylab_protocol::no_subject(token) {
            std::process::exit(NO_VERDICT);
        }
    };
    drop(listener);
    MODE.set(Mode::Judge(Channel::new(stream)?)).map_err(|_| "the mode is set twice".to_owned())
}

/// Functions of a lecture crate, each wrapped so that its value goes through
/// [`student`]: a lecture's checks import these instead of the crate's own,
/// and their code reads as before. A row's `as NameFn` also names the function's
/// type, for the checks that take the function under test as an argument (the
/// lecture's, or a planted mistake in the checks' tests): the signature is
/// written once outside the lecture, here.
///
/// ```ignore
/// student_fns! { l02_ray_casting:
///     fn hit_plane(ray: &Ray, normal: Vec3, offset: Float, range: Interval) -> Option<Hit> as PlaneFn;
/// }
/// ```
macro_rules! student_fns {
    ($krate:ident: $(fn $name:ident($($arg:ident: $ty:ty),* $(,)?) -> $ret:ty $(as $alias:ident)?;)+) => {
        $(
            #[doc = concat!("`", stringify!($krate), "::", stringify!($name), "`, its value taken through `judge::student`.")]
            #[track_caller]
            pub(super) fn $name($($arg: $ty),*) -> $ret {
                crate::judge::student(|| $krate::$name($($arg),*))
            }
            crate::judge::fn_type! { [$($alias)?] $name ($($ty),*) -> $ret }
        )+
    };
}
pub(crate) use student_fns;

/// The type a row of [`student_fns!`] names, `pub(super) type NameFn = fn(…) -> …;`, or nothing
/// for a row without `as NameFn`.
macro_rules! fn_type {
    ([] $name:ident ($($ty:ty),*) -> $ret:ty) => {};
    ([$alias:ident] $name:ident ($($ty:ty),*) -> $ret:ty) => {
        #[doc = concat!("The type of `", stringify!($name), "` and of the mistakes planted in its place.")]
        pub(super) type $alias = fn($($ty),*) -> $ret;
    };
}
pub(crate) use fn_type;
