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

/// A judge of check `id`, and the address it listens on.
fn judge(id: &str) -> (Child, String) {
    let out = std::env::temp_dir().join(format!("raylab-judge-{}", std::process::id()));
    let mut child = Command::new(env!("CARGO_BIN_EXE_raylab-checks"))
        .args(["judge", id, "--out"])
        .arg(&out)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the judge starts");
    let mut line = String::new();
    BufReader::new(child.stdout.as_mut().unwrap()).read_line(&mut line).unwrap();
    let address = line.trim().strip_prefix("listening ").expect("the judge says where it listens").to_owned();
    (child, address)
}

fn send(stream: &mut TcpStream, frame: &Frame) {
    let bytes = postcard::to_stdvec(frame).unwrap();
    stream.write_all(&(bytes.len() as u32).to_le_bytes()).unwrap();
    stream.write_all(&bytes).unwrap();
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
    let subject = Command::new(env!("CARGO_BIN_EXE_raylab-checks"))
        .args(["run", "02/hit_sphere_stable/unit", "--channel", &address, "--out"])
        .arg(std::env::temp_dir())
        .output()
        .unwrap();
    assert!(subject.status.success(), "{}", String::from_utf8_lossy(&subject.stderr));
    let (code, verdict) = verdict(judging);
    assert_eq!(code, Some(0));
    assert_eq!(verdict.as_deref(), Some(r#"{"status":"passed","detail":"7 cases"}"#));
}

#[test]
fn a_subject_that_ends_at_once_leaves_no_verdict() {
    let (judging, address) = judge("02/hit_sphere_stable/unit");
    drop(TcpStream::connect(&address).unwrap());
    assert_eq!(verdict(judging), (Some(3), None));
}

#[test]
fn a_value_from_another_call_site_fails_the_check() {
    let (judging, address) = judge("02/hit_sphere_stable/unit");
    let mut stream = TcpStream::connect(&address).unwrap();
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
    let mut stream = TcpStream::connect(&address).unwrap();
    stream.write_all(&[7, 0, 0, 0, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff]).unwrap();
    let (code, verdict) = verdict(judging);
    assert_eq!(code, Some(0));
    assert!(verdict.expect("a verdict").starts_with(r#"{"status":"failed""#));
}

#[test]
fn a_reported_panic_is_judged_as_the_students_panic() {
    let (judging, address) = judge("02/hit_sphere_stable/unit");
    let mut stream = TcpStream::connect(&address).unwrap();
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
