//! What the driver does differently by operating system, in one place: how a
//! killed child is described, and making the Gradescope scripts executable.
//!
//! The cargo feature `portable` builds the code of the platforms without Unix
//! calls (Windows) on Unix too, so that CI compiles and tests it here.

use std::path::Path;

/// Keeps other processes of this user out of this one (Linux: not dumpable, so
/// they can neither open its `/proc/PID/fd` pipes nor attach a debugger): the
/// student's code runs as the same user when a submission is graded on an
/// instructor's machine. Best effort; elsewhere nothing (a separate user, as
/// on Gradescope, keeps them out everywhere).
#[cfg(all(target_os = "linux", not(feature = "portable")))]
pub fn keep_others_out() {
    let _ = nix::sys::prctl::set_dumpable(false);
}

/// Keeps other processes of this user out of this one: nothing to do here.
#[cfg(any(not(target_os = "linux"), feature = "portable"))]
pub fn keep_others_out() {}

/// A user the student's code is built and run as (`grade --run-as`): on
/// Gradescope, one that cannot read the autograder's source, where the judge,
/// the snapshots and the hidden checks are.
#[derive(Clone, Debug)]
#[cfg_attr(any(not(unix), feature = "portable"), allow(dead_code, reason = "made on Unix only"))]
pub struct RunAs {
    pub name: String,
    pub uid: u32,
    pub gid: u32,
}

/// The user named `name`.
#[cfg(all(unix, not(feature = "portable")))]
pub fn user(name: &str) -> Result<RunAs, String> {
    let user = nix::unistd::User::from_name(name)
        .map_err(|e| format!("the user {name}: {e}"))?
        .ok_or_else(|| format!("no user {name} on this machine (useradd --system {name})"))?;
    Ok(RunAs { name: name.to_owned(), uid: user.uid.as_raw(), gid: user.gid.as_raw() })
}

/// Another user: Unix only.
#[cfg(any(not(unix), feature = "portable"))]
pub fn user(name: &str) -> Result<RunAs, String> {
    Err(format!("--run-as {name}: running the student's code as another user needs Unix"))
}

/// Makes `command` run as `user` (its supplementary groups dropped).
#[cfg(all(unix, not(feature = "portable")))]
pub fn run_as(command: &mut std::process::Command, user: &RunAs) {
    use std::os::unix::process::CommandExt;
    command.uid(user.uid).gid(user.gid);
}

/// Another user: never reached (see [`user`]).
#[cfg(any(not(unix), feature = "portable"))]
pub fn run_as(command: &mut std::process::Command, user: &RunAs) {
    let _ = (command, user);
}

/// Gives `path` to `user` (not following a symbolic link).
#[cfg(all(unix, not(feature = "portable")))]
pub fn give(path: &Path, user: &RunAs) -> Result<(), String> {
    std::os::unix::fs::lchown(path, Some(user.uid), Some(user.gid))
        .map_err(|e| format!("{}: {e}", path.display()))
}

/// Another user: never reached (see [`user`]).
#[cfg(any(not(unix), feature = "portable"))]
pub fn give(path: &Path, user: &RunAs) -> Result<(), String> {
    let _ = (path, user);
    Ok(())
}

/// Takes `path` back for this process's user (not following a symbolic link).
#[cfg(all(unix, not(feature = "portable")))]
pub fn reclaim(path: &Path) -> Result<(), String> {
    use nix::unistd::{getgid, getuid};
    std::os::unix::fs::lchown(path, Some(getuid().as_raw()), Some(getgid().as_raw()))
        .map_err(|e| format!("{}: {e}", path.display()))
}

/// This process's user: nothing to take back (see [`user`]).
#[cfg(any(not(unix), feature = "portable"))]
pub fn reclaim(path: &Path) -> Result<(), String> {
    let _ = path;
    Ok(())
}

/// Gives the tree at `path` to `user` (every file and folder, links not followed): the folder
/// cargo builds the student's code in, theirs while cargo builds.
pub fn give_tree(path: &Path, user: &RunAs) -> Result<(), String> {
    each_in_tree(path, &|p| give(p, user))
}

/// Takes the tree at `path` back for this process's user (links not followed): once built, the
/// student's build folder is the grader's, so that the student's code, run as the grading user,
/// can neither rewrite the binary later checks run nor fill the work folder.
pub fn reclaim_tree(path: &Path) -> Result<(), String> {
    each_in_tree(path, &reclaim)
}

/// `f` on `path` and everything under it, folders before their contents, symbolic links as
/// themselves (never followed).
fn each_in_tree(path: &Path, f: &dyn Fn(&Path) -> Result<(), String>) -> Result<(), String> {
    let mut stack = vec![path.to_owned()];
    while let Some(at) = stack.pop() {
        f(&at)?;
        let kind = std::fs::symlink_metadata(&at).map_err(|e| format!("{}: {e}", at.display()))?;
        if kind.is_dir() {
            for entry in std::fs::read_dir(&at).map_err(|e| format!("{}: {e}", at.display()))? {
                stack.push(entry.map_err(|e| format!("{}: {e}", at.display()))?.path());
            }
        }
    }
    Ok(())
}

/// How many processes (threads included) the grading user may have at once: the student's
/// build (cargo, two rustc and their threads) and two checks at a time need a few dozen; a fork
/// bomb stops here instead of taking the machine.
pub const USER_PROCESSES: u64 = 256;

/// Caps the processes of every user but root that this process's children become (`--run-as`):
/// RLIMIT_NPROC is inherited and counted per user, and root, the grader, is exempt.
#[cfg(all(target_os = "linux", not(feature = "portable")))]
pub fn limit_user_processes(count: u64) -> Result<(), String> {
    use nix::sys::resource::{Resource, setrlimit};
    setrlimit(Resource::RLIMIT_NPROC, count, count).map_err(|e| format!("RLIMIT_NPROC: {e}"))
}

/// No per-user process limit here: the time limit and the process groups still hold.
#[cfg(any(not(target_os = "linux"), feature = "portable"))]
pub fn limit_user_processes(count: u64) -> Result<(), String> {
    let _ = count;
    Ok(())
}

/// Ends what a check of `user`'s left behind: every process of theirs whose process group is
/// not in `live` (the checks running now), again until none is left (a fork bomb forks while
/// it is being killed); and their files and folders at the top of the machine's temporary
/// folders (a subject writes no file of its own; a full disk would fail the grader's writes).
#[cfg(all(target_os = "linux", not(feature = "portable")))]
pub fn sweep(user: &RunAs, live: &std::collections::BTreeSet<u32>) {
    use nix::sys::signal::{Signal, kill};
    use nix::sys::wait::{WaitPidFlag, WaitStatus, waitpid};
    use nix::unistd::Pid;
    // A killed process counts against the user's process limit until it is reaped: those
    // orphaned to this process (`adopt_orphans`) are reaped here.
    for _ in 0..1000 {
        let (strays, zombies) = user_processes(user.uid, live);
        let mut reaped = 0;
        for pid in zombies {
            let done = waitpid(Pid::from_raw(pid), Some(WaitPidFlag::WNOHANG));
            reaped += usize::from(matches!(done, Ok(s) if s != WaitStatus::StillAlive));
        }
        if strays.is_empty() && reaped == 0 {
            break;
        }
        for pid in strays {
            let _ = kill(Pid::from_raw(pid), Signal::SIGKILL);
        }
        std::thread::sleep(std::time::Duration::from_millis(1));
    }
    for folder in TEMPORARY_FOLDERS {
        let Ok(entries) = std::fs::read_dir(folder) else { continue };
        for entry in entries.filter_map(Result::ok) {
            use std::os::unix::fs::MetadataExt;
            let Ok(meta) = entry.path().symlink_metadata() else { continue };
            if meta.uid() != user.uid {
                continue;
            }
            // std's remove_dir_all does not follow links, nor one swapped in while it runs.
            let _ = if meta.is_dir() {
                std::fs::remove_dir_all(entry.path())
            } else {
                std::fs::remove_file(entry.path())
            };
        }
    }
}

/// Where any user may write on a Linux machine.
#[cfg(all(target_os = "linux", not(feature = "portable")))]
const TEMPORARY_FOLDERS: [&str; 3] = ["/tmp", "/var/tmp", "/dev/shm"];

/// The processes of user `uid` (real or effective) whose process group is not in `live`: those
/// running, and those ended but not yet reaped (zombies).
#[cfg(all(target_os = "linux", not(feature = "portable")))]
fn user_processes(uid: u32, live: &std::collections::BTreeSet<u32>) -> (Vec<i32>, Vec<i32>) {
    let Ok(entries) = std::fs::read_dir("/proc") else { return (Vec::new(), Vec::new()) };
    let (mut found, mut zombies) = (Vec::new(), Vec::new());
    for entry in entries.filter_map(Result::ok) {
        let Some(pid) = entry.file_name().to_str().and_then(|n| n.parse::<i32>().ok()) else { continue };
        let Ok(status) = std::fs::read_to_string(entry.path().join("status")) else { continue };
        // "Uid:\treal\teffective\tsaved\tfs"
        let ids: Vec<u32> = status
            .lines()
            .find_map(|l| l.strip_prefix("Uid:"))
            .map(|l| l.split_whitespace().filter_map(|n| n.parse().ok()).collect())
            .unwrap_or_default();
        if !ids.contains(&uid) {
            continue;
        }
        // /proc/PID/stat: "pid (comm) state ppid pgrp …"; comm may hold spaces and parentheses.
        // A check running now, its subject ended or not, is its own job's to wait for.
        let Ok(stat) = std::fs::read_to_string(entry.path().join("stat")) else { continue };
        let group = stat.rsplit_once(')').and_then(|(_, rest)| rest.split_whitespace().nth(2)?.parse().ok());
        if group.is_some_and(|g: u32| live.contains(&g)) {
            continue;
        }
        if status.lines().any(|l| l.starts_with("State:") && l.contains('Z')) {
            zombies.push(pid);
        } else {
            found.push(pid);
        }
    }
    (found, zombies)
}

/// Makes this process the one that the orphans of its descendants are handed to (Linux: a child
/// subreaper), so that [`sweep`] can reap the processes a check left and ended, which count
/// against the grading user's process limit until they are reaped, whatever the machine's init
/// does with orphans.
#[cfg(all(target_os = "linux", not(feature = "portable")))]
pub fn adopt_orphans() {
    let _ = nix::sys::prctl::set_child_subreaper(true);
}

/// Orphans go to init here.
#[cfg(any(not(target_os = "linux"), feature = "portable"))]
pub fn adopt_orphans() {}

/// Nothing to end here: another user is Unix only (see [`user`]).
#[cfg(any(not(target_os = "linux"), feature = "portable"))]
pub fn sweep(user: &RunAs, live: &std::collections::BTreeSet<u32>) {
    let _ = (user, live);
}

/// Starts the child in a process group of its own (its id the group's), so that
/// [`end_group`] ends whatever it started.
#[cfg(all(unix, not(feature = "portable")))]
pub fn own_group(command: &mut std::process::Command) {
    use std::os::unix::process::CommandExt;
    command.process_group(0);
}

/// Ends the process group of a child started by [`own_group`]: the processes it
/// started and left running (a `sleep` holding its output pipe, say).
#[cfg(all(unix, not(feature = "portable")))]
pub fn end_group(child: &std::process::Child) {
    use nix::sys::signal::{Signal, killpg};
    use nix::unistd::Pid;
    if let Ok(id) = i32::try_from(child.id()) {
        let _ = killpg(Pid::from_raw(id), Signal::SIGKILL);
    }
}

/// A process group of its own: none here (the child alone is stopped; what it
/// started and left running is not waited for past the drains' grace).
#[cfg(any(not(unix), feature = "portable"))]
pub fn own_group(command: &mut std::process::Command) {
    let _ = command;
}

/// Ends the child's process group: nothing here (see [`own_group`]).
#[cfg(any(not(unix), feature = "portable"))]
pub fn end_group(child: &std::process::Child) {
    let _ = child;
}

/// How a child that ended without an exit code was stopped: its signal.
#[cfg(all(unix, not(feature = "portable")))]
pub fn signal_name(status: std::process::ExitStatus) -> String {
    use std::os::unix::process::ExitStatusExt;
    match status.signal() {
        Some(6) => "SIGABRT: an abort, e.g. a panic while panicking".into(),
        Some(9) => "SIGKILL: out of memory?".into(),
        Some(11) => "SIGSEGV".into(),
        Some(25) => "SIGXFSZ: a file past the 16 MiB a check may write".into(),
        Some(n) => format!("signal {n}"),
        None => "no signal".into(),
    }
}

/// How a child that ended without an exit code was stopped (Windows always gives a code).
#[cfg(any(not(unix), feature = "portable"))]
pub fn signal_name(status: std::process::ExitStatus) -> String {
    format!("{status}")
}

/// Marks a script executable (`rwxr-xr-x`) where files have such a mode.
#[cfg(all(unix, not(feature = "portable")))]
pub fn make_executable(path: &Path) -> Result<(), String> {
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(path, std::fs::Permissions::from_mode(0o755))
        .map_err(|e| format!("{}: {e}", path.display()))
}

/// Nothing to do where files have no executable bit (Windows); Gradescope
/// runs the scripts through bash.
#[cfg(any(not(unix), feature = "portable"))]
pub fn make_executable(path: &Path) -> Result<(), String> {
    let _ = path;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_killed_child_is_described_and_scripts_become_executable_where_they_can() {
        let status = std::process::Command::new("sh").args(["-c", "kill -9 $$"]).status().unwrap();
        let said = signal_name(status);
        if cfg!(all(unix, not(feature = "portable"))) {
            assert_eq!(said, "SIGKILL: out of memory?");
        } else {
            assert!(said.contains('9'), "{said}");
        }
        let dir = std::env::temp_dir().join(format!("raylab-platform-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let script = dir.join("run");
        std::fs::write(&script, "#!/bin/sh\n").unwrap();
        make_executable(&script).unwrap();
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let mode = std::fs::metadata(&script).unwrap().permissions().mode();
            assert_eq!(mode & 0o111 != 0, cfg!(not(feature = "portable")), "mode {mode:o}");
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
