//! What the checks do differently by operating system, in one place.
//!
//! On Unix (Linux, macOS) a check caps its own address space, so a student's
//! runaway allocation ends the check ("memory allocation of N bytes failed")
//! instead of swapping the machine. Elsewhere (Windows) there is no cap: the
//! grader's time limit and its cap on printed output still hold. `bench-rays`
//! reads the thread's CPU clock on Unix, and reports wall time only elsewhere.
//!
//! The cargo feature `portable` builds the code of the platforms without Unix
//! calls on Unix too, so that CI compiles and tests it here.

/// Caps this process's address space at `bytes`; whether a cap is in force.
/// Best effort: where the limit cannot be set, the grader's time limit still holds.
#[cfg(all(unix, not(feature = "portable")))]
pub fn limit_memory(bytes: u64) -> bool {
    rlimit::setrlimit(rlimit::Resource::AS, bytes, bytes).is_ok()
}

/// Caps this process's address space at `bytes`; whether a cap is in force
/// (never, on platforms without `setrlimit`).
#[cfg(any(not(unix), feature = "portable"))]
pub fn limit_memory(bytes: u64) -> bool {
    let _ = bytes;
    false
}

/// Caps the size of every file this process (and what it starts) writes at `bytes`, and its
/// core dumps at nothing; whether the caps are in force. A write past the cap ends the process
/// (SIGXFSZ), which the driver reports as such.
#[cfg(all(unix, not(feature = "portable")))]
pub fn limit_files(bytes: u64) -> bool {
    rlimit::setrlimit(rlimit::Resource::FSIZE, bytes, bytes).is_ok()
        && rlimit::setrlimit(rlimit::Resource::CORE, 0, 0).is_ok()
}

/// Caps file sizes: not on platforms without `setrlimit`.
#[cfg(any(not(unix), feature = "portable"))]
pub fn limit_files(bytes: u64) -> bool {
    let _ = bytes;
    false
}

/// The CPU time this thread has used, in seconds (the thread's CPU clock,
/// `clock_gettime`); `None` where there is no such clock.
#[cfg(all(unix, not(feature = "portable")))]
#[allow(dead_code)] // used by bench-rays, built with every lecture
pub fn thread_cpu_seconds() -> Option<f64> {
    use nix::time::{ClockId, clock_gettime};
    let now = clock_gettime(ClockId::CLOCK_THREAD_CPUTIME_ID).ok()?;
    Some(now.tv_sec() as f64 + now.tv_nsec() as f64 * 1e-9)
}

/// The CPU time this thread has used; `None`: not measured on this platform.
#[cfg(any(not(unix), feature = "portable"))]
#[allow(dead_code)] // used by bench-rays, built with every lecture
pub fn thread_cpu_seconds() -> Option<f64> {
    None
}

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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_memory_cap_is_in_force_exactly_where_the_platform_has_one() {
        // Run in a child process: the cap must not limit the test harness itself.
        if std::env::var_os("RAYLAB_PLATFORM_CHILD").is_some() {
            let capped = limit_memory(1 << 30);
            assert_eq!(capped, cfg!(all(unix, not(feature = "portable"))));
            if capped {
                // Two gigabytes do not fit under a one-gigabyte cap: the allocation fails.
                let mut v: Vec<u8> = Vec::new();
                assert!(v.try_reserve_exact(2 << 30).is_err(), "2 GiB allocated under a 1 GiB cap");
            }
            return;
        }
        let me = std::env::current_exe().unwrap();
        let out = std::process::Command::new(me)
            .args([
                "--exact",
                "platform::tests::the_memory_cap_is_in_force_exactly_where_the_platform_has_one",
            ])
            .env("RAYLAB_PLATFORM_CHILD", "1")
            .output()
            .unwrap();
        let said = String::from_utf8_lossy(&out.stdout);
        assert!(out.status.success() && said.contains("1 passed"), "{said}");
    }
}
