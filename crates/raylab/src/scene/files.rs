//! Reading the files a scene names, within stated sizes: a scene, mesh or
//! texture path that names an endless or huge file (`/dev/zero`, a
//! mistyped path to a disk image) is refused before it is read whole, and
//! text that is not UTF-8 is refused with the line and column of the first
//! bad byte.

use std::io::Read;
use std::path::Path;

/// The largest scene file read: 16 MiB (the lecture scenes are a few KiB,
/// 6.837's largest under 100 KiB; a mesh belongs in an OBJ file).
pub const SCENE_LIMIT: u64 = 16 << 20;

/// The largest OBJ mesh read: 256 MiB (the 69,451-triangle Stanford bunny is
/// 3 MiB as OBJ text; 256 MiB holds meshes of several million triangles).
pub const MESH_LIMIT: u64 = 256 << 20;

/// The largest texture image read: 64 MiB of PNG (decoded within the image
/// decoder's own 512 MiB limit).
pub const TEXTURE_LIMIT: u64 = 64 << 20;

/// The bytes of the regular file at `path`, at most `limit` of them; `what`
/// names the file's role in the error ("the mesh file").
pub fn read_limited(path: &Path, limit: u64, what: &str) -> Result<Vec<u8>, String> {
    // Asked of the path before opening it: opening a named pipe waits, forever, for a writer.
    let meta = std::fs::metadata(path).map_err(|e| format!("cannot read {what}: {e}"))?;
    if !meta.is_file() {
        return Err(format!("{what} is not a regular file (a folder, a device or a pipe?)"));
    }
    // Should the path name something else by now, the bounded read below still stops.
    let file = std::fs::File::open(path).map_err(|e| format!("cannot read {what}: {e}"))?;
    let too_big = |size: String| {
        format!("{what} {} is {size}, more than the {} MiB a scene may read", path.display(), limit >> 20)
    };
    if meta.len() > limit {
        return Err(too_big(format!("{} MiB", meta.len() >> 20)));
    }
    let mut bytes = Vec::with_capacity(meta.len() as usize);
    file.take(limit + 1).read_to_end(&mut bytes).map_err(|e| format!("cannot read {what}: {e}"))?;
    if bytes.len() as u64 > limit {
        return Err(too_big("larger still than its size said".to_owned()));
    }
    Ok(bytes)
}

/// `bytes` as UTF-8 text, or where the first byte that is not: "line 3,
/// column 7: byte 0xE9 is not UTF-8".
pub fn utf8(bytes: Vec<u8>) -> Result<String, (usize, usize, String)> {
    String::from_utf8(bytes).map_err(|e| {
        let bytes = e.as_bytes();
        let at = e.utf8_error().valid_up_to();
        let before = String::from_utf8_lossy(&bytes[..at]);
        let line = before.matches('\n').count() + 1;
        let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        (line, column, format!("byte 0x{:02X} is not UTF-8 text (save the file as UTF-8)", bytes[at]))
    })
}

/// The text of the scene file at `path` (at most [`SCENE_LIMIT`] bytes of UTF-8).
pub fn read_scene(path: &Path) -> Result<String, super::SceneError> {
    let bytes = read_limited(path, SCENE_LIMIT, "the scene file")
        .map_err(|e| super::SceneError::new(path, 0, 0, e))?;
    utf8(bytes).map_err(|(line, column, e)| super::SceneError::new(path, line, column, e))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::mesh::tests::temp_dir;

    #[test]
    fn endless_and_oversized_files_are_refused_before_they_are_read_whole() {
        #[cfg(unix)]
        {
            let said = read_limited(Path::new("/dev/zero"), MESH_LIMIT, "the mesh file").unwrap_err();
            assert_eq!(said, "the mesh file is not a regular file (a folder, a device or a pipe?)");
            // A named pipe with no writer: opening it would wait forever.
            let fifo = temp_dir("files-fifo").join("pipe.obj");
            let _ = std::fs::remove_file(&fifo);
            assert!(std::process::Command::new("mkfifo").arg(&fifo).status().unwrap().success());
            let said = read_limited(&fifo, MESH_LIMIT, "the mesh file").unwrap_err();
            assert!(said.ends_with("is not a regular file (a folder, a device or a pipe?)"), "{said}");
        }
        let dir = temp_dir("files-limit");
        let path = dir.join("big.obj");
        std::fs::write(&path, vec![b'#'; 3 << 20]).unwrap();
        let said = read_limited(&path, 2 << 20, "the mesh file").unwrap_err();
        assert!(said.ends_with("is 3 MiB, more than the 2 MiB a scene may read"), "{said}");
        assert_eq!(read_limited(&path, 4 << 20, "the mesh file").unwrap().len(), 3 << 20);
        assert!(read_limited(&dir, 1, "the mesh file").unwrap_err().contains("not a regular file"));
    }

    #[test]
    fn a_bad_byte_is_located_by_line_and_character_column() {
        assert_eq!(
            utf8(b"v 1 2 3\nv caf\xC3\xA9 \xE9\n".to_vec()).unwrap_err(),
            (2, 8, "byte 0xE9 is not UTF-8 text (save the file as UTF-8)".to_owned())
        );
        assert_eq!(utf8(b"ok".to_vec()).unwrap(), "ok");
    }
}
