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

use std::cell::RefCell;
use std::io::{BufReader, BufWriter, Read, Write};
use std::net::{TcpListener, TcpStream};
use std::panic::{AssertUnwindSafe, Location, catch_unwind, resume_unwind};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, LazyLock, Mutex};

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use raylab_protocol::JUDGE_LISTENING;

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

/// How this process takes part in a check: made by `main` (local grading, or
/// [`Role::subject`] and [`Role::judge`] from the driver's arguments) and handed
/// to the check it runs ([`enter`]).
pub enum Role {
    /// One process runs the student's code and judges it: local grading.
    Direct,
    /// Runs the student's code and reports its values.
    Subject(Subject),
    /// Judges from the values reported.
    Judge(Channel),
}

/// The subject's side of a check: its channel, and whether the check's code is inside a
/// [`student`] call's `f` (whose values are part of the outer one, not sent on their own).
pub struct Subject {
    channel: Channel,
    inside: AtomicBool,
}

/// The connection to the other process, buffered both ways: a check may send
/// tens of thousands of small values (the leak test's rays), so the subject
/// writes them out in blocks, and flushes before it waits for a decision and
/// when the check ends (`flush`) or panics.
pub struct Channel {
    out: Mutex<BufWriter<TcpStream>>,
    input: Mutex<BufReader<TcpStream>>,
}

/// Why a check ended before its code did; `main` ends the process accordingly. Raised from deep
/// in a check's code ([`end`]) and returned by [`enter`].
#[derive(Debug)]
pub enum Ended {
    /// No verdict from this process: the other one is gone (a subject that stopped early, the
    /// judge with its verdict), or this subject was sent what no judge sends. The driver gives the
    /// verdict from how the subject ended (`NO_VERDICT`).
    Early,
    /// The judge's verdict, reached before the check's end: the panic the subject reported, or
    /// values out of step.
    Verdict(Outcome),
}

impl Role {
    /// The subject's role: connects to the judge at `address` before any of the student's code
    /// runs, and says `token`.
    pub fn subject(address: &str, token: u64) -> Result<Role, String> {
        let mut stream = TcpStream::connect(address).map_err(|e| format!("the judge at {address}: {e}"))?;
        stream
            .write_all(&raylab_protocol::hello(token))
            .map_err(|e| format!("the judge at {address}: {e}"))?;
        Ok(Role::Subject(Subject { channel: Channel::new(stream)?, inside: AtomicBool::new(false) }))
    }

    /// The judge's role: listens on a loopback port, prints `listening ADDR` on stdout for the
    /// driver, and takes the first connection that says `token` as the subject's. Another
    /// connection is dropped: one meant for an earlier judge on the same port (the driver's, sent
    /// to a judge that had already ended). `None`: the driver's word that the subject ended
    /// without connecting (no verdict).
    pub fn judge(token: u64) -> Result<Option<Role>, String> {
        let listener = TcpListener::bind("127.0.0.1:0").map_err(|e| format!("a loopback port: {e}"))?;
        let address = listener.local_addr().map_err(|e| e.to_string())?;
        let mut out = std::io::stdout().lock();
        writeln!(out, "{JUDGE_LISTENING}{address}").and_then(|()| out.flush()).map_err(|e| e.to_string())?;
        loop {
            let (mut stream, _) = listener.accept().map_err(|e| format!("the subject's connection: {e}"))?;
            // A connection that says nothing is not waited for long.
            let _ = stream.set_read_timeout(Some(std::time::Duration::from_secs(2)));
            let mut hello = [0u8; 8];
            if stream.read_exact(&mut hello).is_err() {
                continue;
            }
            if hello == raylab_protocol::hello(token) {
                stream.set_read_timeout(None).map_err(|e| format!("the subject's connection: {e}"))?;
                return Ok(Some(Role::Judge(Channel::new(stream)?)));
            }
            if hello == raylab_protocol::no_subject(token) {
                return Ok(None);
            }
        }
    }
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

/// The student's code drawing from the generator `rng`: its value and the generator as the code
/// left it, as one value through [`student`] (the check draws from it next; in the judge the code
/// does not run, so the generator comes from the subject).
#[track_caller]
pub fn drawn<T: Serialize + DeserializeOwned>(
    rng: &mut raylab::random::Rng,
    f: impl FnOnce(&mut raylab::random::Rng) -> T,
) -> T {
    let (value, after) = student(|| {
        let value = f(rng);
        (value, rng.clone())
    });
    *rng = after;
    value
}

thread_local! {
    /// The role of the check running on this thread, for the length of [`enter`]; none outside
    /// one (the checks' own tests): local grading.
    static ROLE: RefCell<Option<Arc<Role>>> = const { RefCell::new(None) };
}

/// Runs `check` in `role`: the values, decisions and calls of the student's code it makes
/// ([`student`], [`decide`], [`call`]) go where `role` says. Its value, or why it ended early
/// ([`Ended`]: the process then ends, in `main`). Any other panic goes on (after the panic hook
/// has recorded it).
pub fn enter<T>(role: Arc<Role>, check: impl FnOnce() -> T) -> Result<T, Ended> {
    let outer = ROLE.replace(Some(role));
    let result = catch_unwind(AssertUnwindSafe(check));
    ROLE.set(outer);
    match result {
        Ok(value) => Ok(value),
        Err(payload) => match payload.downcast::<Ended>() {
            Ok(ended) => Err(*ended),
            Err(panic) => resume_unwind(panic),
        },
    }
}

/// The role of the check running on this thread.
fn role() -> Arc<Role> {
    /// Local grading's role, made once: `role` is asked at every value of the student's code.
    static DIRECT: LazyLock<Arc<Role>> = LazyLock::new(|| Arc::new(Role::Direct));
    ROLE.with_borrow(|role| role.clone()).unwrap_or_else(|| DIRECT.clone())
}

/// Ends the check at once, up to [`enter`]: an unwind that the panic hook does not see (it is
/// not a panic of the check's code) and no code of the student's is on the stack to catch (the
/// subject calls none on the channel's side of a [`student`] call; the judge runs none).
fn end(ended: Ended) -> ! {
    resume_unwind(Box::new(ended))
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
    match &*role() {
        Role::Direct => f(),
        Role::Subject(subject) if subject.inside.load(Ordering::Relaxed) => f(),
        Role::Subject(subject) => {
            subject.inside.store(true, Ordering::Relaxed);
            let value = f();
            subject.inside.store(false, Ordering::Relaxed);
            send(&subject.channel, &site(at), &value, false);
            value
        }
        Role::Judge(channel) => receive(channel, &site(at), true),
    }
}

/// The student's code run under [`raylab::stats::measure`]: its value and the rays it
/// counted, as one value through [`student`] (in the judge the code does not run, so it counts
/// nothing of its own).
#[track_caller]
pub fn measured<T: Serialize + DeserializeOwned>(f: impl FnOnce() -> T) -> (T, raylab::stats::RayStats) {
    student(|| raylab::stats::measure(f))
}

/// A decision only the judge can make (it holds the snapshots and the hidden
/// answers): `f()` in the judge (sent to the subject) and locally; in the
/// subject, the judge's answer (`f` is not run).
#[track_caller]
pub fn decide<T: Serialize + DeserializeOwned>(f: impl FnOnce() -> T) -> T {
    let at = Location::caller();
    match &*role() {
        Role::Direct => f(),
        Role::Judge(channel) => {
            let value = f();
            send(channel, &site(at), &value, true);
            value
        }
        Role::Subject(subject) => receive(&subject.channel, &site(at), false),
    }
}

/// Work only the judge does (it holds the snapshots and the hidden answers): `f()` in the
/// judge and locally; in the subject nothing (`None`). What the subject must know of its result
/// to take the same path it learns through [`decide`].
pub fn judge_only<T>(f: impl FnOnce() -> T) -> Option<T> {
    match &*role() {
        Role::Subject(_) => None,
        Role::Direct | Role::Judge(_) => Some(f()),
    }
}

/// `file:line` of a call, as the frames name it.
fn site(at: &Location) -> String {
    format!("{}:{}", at.file(), at.line())
}

/// Sends a value: a decision (the judge's, `now`) goes out at once, the subject's values in
/// blocks. The other side gone ends the check: nothing left to do here.
fn send<T: Serialize>(channel: &Channel, site: &str, value: &T, now: bool) {
    let bytes = postcard::to_stdvec(value).expect("a check's values encode");
    if write_frame(channel, &Frame::Value { site: site.to_owned(), bytes }, now).is_err() {
        end(Ended::Early);
    }
}

/// Writes a frame (and sends it, if `flush`); an error when the other side is gone.
fn write_frame(channel: &Channel, frame: &Frame, flush: bool) -> Result<(), ()> {
    let bytes = postcard::to_stdvec(frame).expect("a frame encodes");
    let mut stream = channel.out.lock().map_err(|_| ())?;
    let length = u32::try_from(bytes.len()).unwrap_or(u32::MAX).to_le_bytes();
    let written = stream.write_all(&length).and_then(|()| stream.write_all(&bytes));
    written.and_then(|()| if flush { stream.flush() } else { Ok(()) }).map_err(|_| ())
}

fn flush_channel(channel: &Channel) {
    if let Ok(mut stream) = channel.out.lock() {
        let _ = stream.flush();
    }
}

/// The next frame, `None` once the other side has ended; a subject about to wait sends what it
/// has first.
fn read_frame(channel: &Channel) -> Result<Option<Frame>, String> {
    flush_channel(channel);
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

/// The next value from the other process, for the call at `site` (`judging`: this is the
/// judge). In the judge, a panic the subject reported ends the check with that panic's outcome,
/// and a value that does not fit ends it as failed.
fn receive<T: DeserializeOwned>(channel: &Channel, site: &str, judging: bool) -> T {
    let frame = match read_frame(channel) {
        Ok(Some(frame)) => frame,
        // The other side ended: the subject before the check did, or the judge with its verdict.
        Ok(None) => end(Ended::Early),
        Err(e) => out_of_step(&e, judging),
    };
    match frame {
        Frame::Value { site: sent, bytes } if sent == site => postcard::from_bytes(&bytes)
            .unwrap_or_else(|e| out_of_step(&format!("a value at {site} ({e})"), judging)),
        Frame::Value { site: sent, .. } => {
            out_of_step(&format!("a value from {sent} where {site} was due"), judging)
        }
        Frame::Panic { message, file, line } if judging => {
            end(Ended::Verdict(Outcome::Panicked { message, file, line }))
        }
        Frame::Panic { .. } => out_of_step("a panic report where a decision was due", judging),
        Frame::Call { .. } => out_of_step("a call where a value was due", judging),
    }
}

/// Where the values of [`call`]s come from, as the frames name it.
const CALL_SITE: &str = "a call of the judge's";

/// A call of the student's code, `call` encoded (a hidden check's, the `remote` module's): made in
/// place locally, by `here`, which returns its value encoded; in the judge, sent to the subject,
/// which makes it and returns the value.
pub fn call<T: DeserializeOwned>(call: Vec<u8>, here: impl FnOnce() -> Result<Vec<u8>, String>) -> T {
    match &*role() {
        Role::Direct => {
            let bytes = here().unwrap_or_else(|e| panic!("{e}"));
            postcard::from_bytes(&bytes).unwrap_or_else(|e| panic!("a call's value: {e}"))
        }
        Role::Judge(channel) => {
            if write_frame(channel, &Frame::Call { bytes: call }, true).is_err() {
                end(Ended::Early);
            }
            receive(channel, CALL_SITE, true)
        }
        // The subject's build has no hidden checks: nothing in it makes a call.
        Role::Subject(_) => end(Ended::Early),
    }
}

/// The subject of a hidden check (`raylab-checks serve`, in [`enter`]): makes each call the judge
/// sends and returns its value, until the judge ends (with its verdict): `answer` makes an
/// encoded call and encodes its value. A panic of the student's code goes to the judge through
/// the panic hook, as in a check.
pub fn serve_calls(answer: impl Fn(&[u8]) -> Result<Vec<u8>, String>) -> Result<(), String> {
    let role = role();
    let Role::Subject(subject) = &*role else { return Err("serve needs --channel".into()) };
    loop {
        let frame = match read_frame(&subject.channel) {
            Ok(Some(frame)) => frame,
            // The judge has its verdict.
            Ok(None) => return Ok(()),
            Err(e) => return Err(e),
        };
        let Frame::Call { bytes } = frame else {
            return Err("the judge sent a frame other than a call".into());
        };
        match answer(&bytes) {
            Ok(bytes) => {
                let value = Frame::Value { site: CALL_SITE.to_owned(), bytes };
                if write_frame(&subject.channel, &value, true).is_err() {
                    return Ok(());
                }
            }
            Err(message) => role.report_panic(&message, file!(), line!()),
        }
    }
}

/// The judge's verdict, a `verdict JSON` line on its stdout: a pipe only the
/// driver reads (a file could be written by the student's process too).
pub fn print_verdict(json: &str) -> Result<(), String> {
    let mut out = std::io::stdout().lock();
    writeln!(out, "{}{json}", raylab_protocol::JUDGE_VERDICT)
        .and_then(|()| out.flush())
        .map_err(|e| e.to_string())
}

/// Values that no honest process sends: in the judge, the check fails (never passes), saying so;
/// in the subject, it ends without a verdict.
fn out_of_step(what: &str, judging: bool) -> ! {
    if !judging {
        end(Ended::Early);
    }
    end(Ended::Verdict(Outcome::Failed(fail(
        "the values your code returned, as the check's process reported them",
        "one value of the expected type per call, in the check's order",
        what,
        "the process that ran your code sent what the check never sends: it ran something other than \
         the check (an exit or a write of its own in your code?)",
    ))))
}

impl Role {
    /// Sends what the subject has buffered: when its check ends (and before it waits: `read_frame`).
    pub fn flush(&self) {
        if let Role::Subject(subject) = self {
            flush_channel(&subject.channel);
        }
    }

    /// Tells the judge that the student's code panicked (the subject's panic hook, which holds
    /// the role itself: the panic may be on any thread of the check, a renderer's worker too).
    /// Called while panicking, it cannot end the check itself: a judge already gone is left to
    /// the panic.
    pub fn report_panic(&self, message: &str, file: &str, line: u32) {
        if let Role::Subject(subject) = self {
            let frame = Frame::Panic { message: message.to_owned(), file: file.to_owned(), line };
            let _ = write_frame(&subject.channel, &frame, true);
        }
    }
}

/// The protocol in one process: a judge and a subject on two threads, over a loopback
/// connection, running the same check code (as the two processes do).
#[cfg(test)]
mod tests {
    use super::*;
    use std::thread;

    /// A subject's role and a judge's, connected.
    fn pair() -> (Arc<Role>, Arc<Role>) {
        let listener = TcpListener::bind("127.0.0.1:0").unwrap();
        let client = TcpStream::connect(listener.local_addr().unwrap()).unwrap();
        let (server, _) = listener.accept().unwrap();
        let subject =
            Role::Subject(Subject { channel: Channel::new(client).unwrap(), inside: AtomicBool::new(false) });
        (Arc::new(subject), Arc::new(Role::Judge(Channel::new(server).unwrap())))
    }

    /// A check: one value of the student's code, then a decision on it (the judge's).
    fn doubled<T: Serialize + DeserializeOwned>(
        answer: impl FnOnce() -> T,
        double: impl FnOnce(T) -> u64,
    ) -> u64 {
        let value = student(answer);
        decide(|| double(value))
    }

    /// Runs `subject` and `judge` side by side in their roles; what each ended with.
    fn both<S: Send + 'static, J>(
        subject: impl FnOnce(&Role) -> S + Send + 'static,
        judge: impl FnOnce() -> J,
    ) -> (Result<S, Ended>, Result<J, Ended>) {
        let (subject_role, judge_role) = pair();
        let subject = thread::spawn(move || enter(subject_role.clone(), || subject(&subject_role)));
        let judged = enter(judge_role, judge);
        (subject.join().expect("the subject's thread"), judged)
    }

    #[test]
    fn the_judge_takes_the_subjects_value_and_the_subject_the_judges_decision() {
        let (subject, judged) = both(
            |_| doubled(|| 21u64, |_| unreachable!("the subject makes no decision")),
            || doubled(|| -> u64 { unreachable!("the judge runs no student code") }, |x| 2 * x),
        );
        assert_eq!(subject.unwrap(), 42);
        assert_eq!(judged.unwrap(), 42);
    }

    #[test]
    fn a_value_of_another_type_fails_the_check_in_the_judge_and_ends_the_subject_without_a_verdict() {
        let (subject, judged) = both(
            |_| doubled(|| u64::MAX, |_| unreachable!()),
            || doubled(|| -> bool { unreachable!() }, u64::from),
        );
        // The judge concluded, so the subject, waiting for the decision, finds the channel closed.
        assert!(matches!(subject, Err(Ended::Early)), "{subject:?}");
        let Err(Ended::Verdict(Outcome::Failed(failure))) = judged else { panic!("{judged:?}") };
        assert!(failure.cause.contains("never sends"), "{failure:?}");
    }

    #[test]
    fn a_panic_the_subject_reports_is_the_judges_verdict_from_any_thread() {
        // The panic hook holds the role: a renderer's worker thread, where no role was entered,
        // reports its panic as the check's main thread does.
        let (_, judged) = both(
            |role| {
                thread::scope(|s| s.spawn(|| role.report_panic("boom", "src/sphere.rs", 7)).join().unwrap())
            },
            || doubled(|| -> u64 { unreachable!() }, |x| x),
        );
        let Err(Ended::Verdict(Outcome::Panicked { message, file, line })) = judged else {
            panic!("{judged:?}")
        };
        assert_eq!((message.as_str(), file.as_str(), line), ("boom", "src/sphere.rs", 7));
    }

    #[test]
    fn a_subject_that_stops_early_leaves_the_judge_without_a_verdict() {
        let (subject, judged) = both(|_| (), || doubled(|| -> u64 { unreachable!() }, |x| x));
        assert!(subject.is_ok());
        assert!(matches!(judged, Err(Ended::Early)), "{judged:?}");
    }

    #[test]
    fn outside_a_role_and_directly_the_code_runs_in_place_and_a_panic_goes_on() {
        assert_eq!(doubled(|| 4u64, |x| x + 1), 5);
        assert_eq!(enter(Arc::new(Role::Direct), || doubled(|| 4u64, |x| x + 1)).unwrap(), 5);
        let panicked = catch_unwind(|| enter(Arc::new(Role::Direct), || panic!("the student's bug")));
        let payload = panicked.expect_err("the panic goes on");
        assert_eq!(payload.downcast_ref::<&str>(), Some(&"the student's bug"));
        // The role ends with its check.
        assert!(matches!(&*role(), Role::Direct));
    }
}
