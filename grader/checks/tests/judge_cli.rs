//! `raylab-checks judge` end to end, against subjects that are not the checks'
//! own: a real judge process, a real loopback connection, frames written by
//! hand. What the judge makes of a subject's values decides a submission's
//! grade (`src/judge.rs`), so each way a forged subject could try it is here.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::process::{Child, Command, Stdio};

use serde::Serialize;

/// The subject → judge frame, as `src/judge.rs` defines it (same field order:
/// postcard encodes by position).
#[derive(Serialize)]
enum Frame {
    Value { site: String, bytes: Vec<u8> },
    Panic { message: String, file: String, line: u32 },
}

/// The token the tests' judges are given (on their standard input, as the driver gives it).
const TOKEN: u64 = 0x5ca1_ab1e_0000_0001;

/// A judge of check `id`, and the address it listens on.
fn judge(id: &str) -> (Child, String) {
    let out = std::env::temp_dir().join(format!("raylab-judge-{}", std::process::id()));
    let mut child = Command::new(env!("CARGO_BIN_EXE_raylab-checks"))
        .args(["judge", id, "--out"])
        .arg(&out)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the judge starts");
    child.stdin.take().unwrap().write_all(raylab_protocol::token_line(TOKEN).as_bytes()).unwrap();
    let mut line = String::new();
    BufReader::new(child.stdout.as_mut().unwrap()).read_line(&mut line).unwrap();
    let address = line.trim().strip_prefix("listening ").expect("the judge says where it listens").to_owned();
    (child, address)
}

/// A connection to the judge at `address` that says `hello` first.
fn connect(address: &str, hello: [u8; 8]) -> TcpStream {
    let mut stream = TcpStream::connect(address).unwrap();
    stream.write_all(&hello).unwrap();
    stream
}

/// The checks' own subject of `id`, connected to the judge at `address` with `token`.
fn own_subject(id: &str, address: &str, token: u64) -> std::process::Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_raylab-checks"))
        .args(["run", id, "--channel", address, "--out"])
        .arg(std::env::temp_dir())
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(raylab_protocol::token_line(token).as_bytes()).unwrap();
    child.wait_with_output().unwrap()
}

/// The verdict of check `id` run locally, in one process (`run ID --verdict FILE`): what the
/// judged run must agree with.
fn local_verdict(id: &str) -> String {
    // One file per call: the tests run in parallel threads of one process.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let call = CALLS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let file = std::env::temp_dir().join(format!("raylab-local-verdict-{}-{call}.json", std::process::id()));
    let out = Command::new(env!("CARGO_BIN_EXE_raylab-checks"))
        .args(["run", id, "--verdict"])
        .arg(&file)
        .arg("--out")
        .arg(std::env::temp_dir())
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let verdict = std::fs::read_to_string(&file).unwrap();
    let _ = std::fs::remove_file(&file);
    assert!(verdict.starts_with(r#"{"status":"passed""#), "{verdict}");
    verdict
}

fn send(stream: &mut TcpStream, frame: &Frame) {
    try_send(stream, frame).unwrap();
}

fn try_send(stream: &mut TcpStream, frame: &Frame) -> std::io::Result<()> {
    let bytes = postcard::to_stdvec(frame).unwrap();
    stream.write_all(&(bytes.len() as u32).to_le_bytes())?;
    stream.write_all(&bytes)
}

/// The judge's exit code and the verdict line it printed, if any.
fn verdict(mut child: Child) -> (Option<i32>, Option<String>) {
    let status = child.wait().unwrap();
    let mut out = String::new();
    child.stdout.take().unwrap().read_to_string(&mut out).unwrap();
    let verdict = out.lines().find_map(|l| l.strip_prefix("verdict ")).map(str::to_owned);
    (status.code(), verdict)
}

#[test]
fn the_checks_own_subject_is_judged_passed() {
    let (judging, address) = judge("02/hit_sphere_stable/unit");
    let subject = own_subject("02/hit_sphere_stable/unit", &address, TOKEN);
    assert!(subject.status.success(), "{}", String::from_utf8_lossy(&subject.stderr));
    let (code, verdict) = verdict(judging);
    assert_eq!(code, Some(0));
    assert_eq!(verdict, Some(local_verdict("02/hit_sphere_stable/unit")));
}

#[test]
fn a_subject_that_ends_at_once_leaves_no_verdict() {
    let (judging, address) = judge("02/hit_sphere_stable/unit");
    drop(connect(&address, raylab_protocol::hello(TOKEN)));
    assert_eq!(verdict(judging), (Some(3), None));
}

/// The driver's word that the subject ended without connecting: the judge stops waiting.
#[test]
fn no_subject_from_the_driver_ends_the_judge_without_a_verdict() {
    let (judging, address) = judge("02/hit_sphere_stable/unit");
    drop(connect(&address, raylab_protocol::no_subject(TOKEN)));
    assert_eq!(verdict(judging), (Some(3), None));
}

/// A judge's loopback port can be one an earlier judge had: the driver's word to that judge, a
/// connection that says nothing, and a subject of another judge's all reach this one first. It
/// drops them and takes its own subject's (CI once graded a check "crashed" when a judge took the
/// driver's word to the judge before it for its subject).
#[test]
fn connections_meant_for_another_judge_are_not_taken_for_the_subject() {
    let (judging, address) = judge("02/hit_sphere_stable/unit");
    let other = TOKEN ^ 0xff;
    drop(connect(&address, raylab_protocol::no_subject(other)));
    drop(TcpStream::connect(&address).unwrap());
    let mut stray = connect(&address, raylab_protocol::hello(other));
    // A stray subject's forged value is not read either. The judge may have dropped the stray
    // connection already (it read the wrong token), so the write may fail with a broken pipe or
    // a reset: either way the value does not reach it.
    let bytes = postcard::to_stdvec(&Option::<u8>::None).unwrap();
    let _ = try_send(&mut stray, &Frame::Value { site: "src/forged.rs:1".into(), bytes });
    let subject = own_subject("02/hit_sphere_stable/unit", &address, TOKEN);
    assert!(subject.status.success(), "{}", String::from_utf8_lossy(&subject.stderr));
    let (code, verdict) = verdict(judging);
    assert_eq!(code, Some(0));
    assert_eq!(verdict, Some(local_verdict("02/hit_sphere_stable/unit")));
}

#[test]
fn a_value_from_another_call_site_fails_the_check() {
    let (judging, address) = judge("02/hit_sphere_stable/unit");
    let mut stream = connect(&address, raylab_protocol::hello(TOKEN));
    // The right answer to the first case (t = 4 …), but claimed by a call the check never makes.
    let bytes = postcard::to_stdvec(&Option::<u8>::None).unwrap();
    send(&mut stream, &Frame::Value { site: "src/forged.rs:1".into(), bytes });
    let (code, verdict) = verdict(judging);
    assert_eq!(code, Some(0));
    let verdict = verdict.expect("a verdict");
    assert!(verdict.starts_with(r#"{"status":"failed""#), "{verdict}");
    assert!(verdict.contains("src/forged.rs:1"), "{verdict}");
}

#[test]
fn a_value_that_does_not_decode_fails_the_check() {
    let (judging, address) = judge("02/hit_sphere_stable/unit");
    let mut stream = connect(&address, raylab_protocol::hello(TOKEN));
    stream.write_all(&[7, 0, 0, 0, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff]).unwrap();
    let (code, verdict) = verdict(judging);
    assert_eq!(code, Some(0));
    assert!(verdict.expect("a verdict").starts_with(r#"{"status":"failed""#));
}

#[test]
fn a_reported_panic_is_judged_as_the_students_panic() {
    let (judging, address) = judge("02/hit_sphere_stable/unit");
    let mut stream = connect(&address, raylab_protocol::hello(TOKEN));
    let panic = Frame::Panic {
        message: "02/hit_sphere_stable: Book §2.4".into(),
        file: "lectures/02-ray-casting/src/sphere.rs".into(),
        line: 114,
    };
    send(&mut stream, &panic);
    let (code, verdict) = verdict(judging);
    assert_eq!(code, Some(0));
    let verdict = verdict.expect("a verdict");
    assert!(verdict.starts_with(r#"{"status":"panicked","message":"02/hit_sphere_stable"#), "{verdict}");
}
