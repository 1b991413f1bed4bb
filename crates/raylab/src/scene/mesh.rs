//! Triangle meshes: indexed triangles with optional per-vertex normals and
//! texture coordinates, read from OBJ files (through tobj) or built by the
//! kit ([`Mesh::icosphere`], [`Mesh::torus`]).

use std::io::Cursor;
use std::path::Path;

use crate::math::{Float, Vec2, Vec3};

/// A triangle mesh.
///
/// `triangles` index `positions`; `normals` and `uvs` are either empty or
/// hold one entry per position (unit normals). Triangles wind
/// counter-clockwise seen from the side their face normal (b − a)×(c − a)
/// points to. Book: §3.6 Triangle meshes.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    pub positions: Vec<Vec3>,
    pub normals: Vec<Vec3>,
    pub uvs: Vec<Vec2>,
    pub triangles: Vec<[u32; 3]>,
}

impl Mesh {
    /// Reads a Wavefront OBJ file: polygons are split into triangle fans,
    /// every model (`o`, `g`) of the file goes into this one mesh, and normals
    /// (`vn`) and texture coordinates (`vt`) are kept only when every vertex
    /// has them. Materials (`mtllib`) are ignored. Errors (as sentences naming
    /// the file): unreadable, not a regular file or larger than
    /// [`files::MESH_LIMIT`](super::files::MESH_LIMIT), not UTF-8 (with the line
    /// and column of the first bad byte), OBJ syntax, no faces, a face index
    /// out of range, a non-finite number, a zero normal.
    pub fn load_obj(path: &Path) -> Result<Mesh, String> {
        let bytes = super::files::read_limited(path, super::files::MESH_LIMIT, "the mesh file")
            .map_err(|e| format!("{}: {e}", path.display()))?;
        // tobj reads lines of UTF-8 and says only "read error" of a bad byte: say where it is.
        let bytes = super::files::utf8(bytes)
            .map_err(|(line, column, e)| {
                format!("{}:{line}:{column}: not a valid OBJ file: {e}", path.display())
            })?
            .into_bytes();
        let options = tobj::LoadOptions { triangulate: true, single_index: true, ..Default::default() };
        let (models, _materials) =
            tobj::load_obj_buf(&mut Cursor::new(bytes), &options, |_| Err(tobj::LoadError::OpenFileFailed))
                .map_err(|e| format!("{}: not a valid OBJ file: {e}", path.display()))?;
        Mesh::from_models(&models).map_err(|e| format!("{}: {e}", path.display()))
    }

    /// Merges tobj's models into one mesh and checks it.
    fn from_models(models: &[tobj::Model]) -> Result<Mesh, String> {
        let mut mesh = Mesh::default();
        let every = |f: fn(&tobj::Mesh) -> bool| models.iter().all(|m| f(&m.mesh));
        let keep_normals = every(|m| m.normals.len() == m.positions.len());
        let keep_uvs = every(|m| m.texcoords.len() / 2 == m.positions.len() / 3);
        for model in models {
            let m = &model.mesh;
            let base = mesh.positions.len();
            let count = m.positions.len() / 3;
            let vec3 = |v: &[f32]| Vec3::new(v[0] as Float, v[1] as Float, v[2] as Float);
            mesh.positions.extend(m.positions.chunks_exact(3).map(vec3));
            if keep_normals {
                mesh.normals.extend(m.normals.chunks_exact(3).map(vec3));
            }
            if keep_uvs {
                mesh.uvs.extend(m.texcoords.chunks_exact(2).map(|t| Vec2::new(t[0] as Float, t[1] as Float)));
            }
            for face in m.indices.chunks_exact(3) {
                if let Some(&i) = face.iter().find(|&&i| i as usize >= count) {
                    return Err(format!(
                        "model `{}` has a face index {i} beyond its {count} vertices",
                        model.name
                    ));
                }
                let index = |i: u32| u32::try_from(base + i as usize).map_err(|_| "too many vertices");
                mesh.triangles.push([index(face[0])?, index(face[1])?, index(face[2])?]);
            }
        }
        if mesh.triangles.is_empty() {
            return Err("the file holds no faces".to_string());
        }
        if let Some(i) = mesh.positions.iter().position(|p| !p.is_finite()) {
            return Err(format!("vertex {i} has a coordinate that is not a finite number"));
        }
        if let Some(i) = mesh.uvs.iter().position(|t| !t.is_finite()) {
            return Err(format!("the texture coordinate of vertex {i} is not finite"));
        }
        for (i, n) in mesh.normals.iter_mut().enumerate() {
            *n = n.try_normalize().ok_or_else(|| {
                format!(
                    "the normal of vertex {i} is zero or not finite (remove the `vn` lines for face normals)"
                )
            })?;
        }
        Ok(mesh)
    }

    /// The three corners of triangle `i`. Panics when `i` is out of range.
    pub fn triangle(&self, i: usize) -> [Vec3; 3] {
        let [a, b, c] = self.triangles[i];
        [self.positions[a as usize], self.positions[b as usize], self.positions[c as usize]]
    }

    /// The smallest axis-aligned box (min, max) holding every position; an
    /// empty box (min = +∞, max = −∞) for a mesh without positions.
    pub fn bounds(&self) -> (Vec3, Vec3) {
        self.positions
            .iter()
            .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), &p| (lo.min(p), hi.max(p)))
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use std::fmt::Write as _;
    use std::path::PathBuf;

    use super::*;

    /// A fresh, empty folder for one test's files.
    pub(crate) fn temp_dir(test: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("raylab-{}-{test}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    /// `mesh` as OBJ text, with `vn` lines when `normals` (an independent
    /// writer, so the round trip tests the reader).
    fn to_obj(mesh: &Mesh, normals: bool) -> String {
        let mut s = String::from("# written by a raylab test\n");
        for p in &mesh.positions {
            writeln!(s, "v {} {} {}", p.x, p.y, p.z).unwrap();
        }
        for n in mesh.normals.iter().filter(|_| normals) {
            writeln!(s, "vn {} {} {}", n.x, n.y, n.z).unwrap();
        }
        for t in &mesh.triangles {
            let [a, b, c] = t.map(|i| i + 1);
            if normals {
                writeln!(s, "f {a}//{a} {b}//{b} {c}//{c}").unwrap();
            } else {
                writeln!(s, "f {a} {b} {c}").unwrap();
            }
        }
        s
    }

    /// tobj reads f32, so a written-and-read coordinate of size ≤ 1 is off by
    /// at most one f32 rounding (6·10⁻⁸) from the f64 original.
    const OBJ_ROUNDING: Float = 1e-6;

    fn assert_same_triangles(read: &Mesh, written: &Mesh, with_normals: bool) {
        assert_eq!(read.triangles.len(), written.triangles.len());
        for (r, w) in read.triangles.iter().zip(&written.triangles) {
            for k in 0..3 {
                let (r, w) = (r[k] as usize, w[k] as usize);
                approx::assert_abs_diff_eq!(read.positions[r], written.positions[w], epsilon = OBJ_ROUNDING);
                if with_normals {
                    approx::assert_abs_diff_eq!(read.normals[r], written.normals[w], epsilon = OBJ_ROUNDING);
                }
            }
        }
    }

    #[test]
    fn obj_round_trip_keeps_triangles_with_and_without_normals() {
        let dir = temp_dir("obj-round-trip");
        let sphere = Mesh::icosphere(1);
        for with_normals in [true, false] {
            let path = dir.join(format!("sphere-{with_normals}.obj"));
            std::fs::write(&path, to_obj(&sphere, with_normals)).unwrap();
            let read = Mesh::load_obj(&path).unwrap();
            assert_same_triangles(&read, &sphere, with_normals);
            assert_eq!(read.normals.is_empty(), !with_normals);
            assert!(read.uvs.is_empty());
        }
    }

    #[test]
    fn models_merge_and_normals_survive_only_when_every_vertex_has_one() {
        let dir = temp_dir("obj-merge");
        // Two models: a triangle with normals and texture coordinates, a quad without.
        let text = "o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\nf 1/1/1 2/1/1 3/1/1\n\
                    o b\nv 0 0 2\nv 1 0 2\nv 1 1 2\nv 0 1 2\nf 4 5 6 7\n";
        let path = dir.join("two.obj");
        std::fs::write(&path, text).unwrap();
        let mesh = Mesh::load_obj(&path).unwrap();
        // 1 triangle + the quad split into 2.
        assert_eq!(mesh.triangles.len(), 3);
        assert!(mesh.normals.is_empty() && mesh.uvs.is_empty(), "model b has neither");
        // The quad's fan starts at its first corner (0, 0, 2): indices were offset past model a.
        assert_eq!(mesh.triangle(1)[0], Vec3::new(0.0, 0.0, 2.0));
        assert_eq!(mesh.bounds(), (Vec3::ZERO, Vec3::new(1.0, 1.0, 2.0)));
    }

    #[test]
    fn bad_obj_files_are_errors_naming_the_file() {
        let dir = temp_dir("obj-bad");
        let cases = [
            ("missing.obj", None, "cannot read"),
            ("empty.obj", Some("v 0 0 0\n"), "no faces"),
            ("range.obj", Some("v 0 0 0\nv 1 0 0\nf 1 2 9\n"), "valid OBJ"),
            ("nan.obj", Some("v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "not a finite"),
            ("zero.obj", Some("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n"), "normal of vertex"),
        ];
        for (name, text, expected) in cases {
            let path = dir.join(name);
            if let Some(text) = text {
                std::fs::write(&path, text).unwrap();
            }
            let err = Mesh::load_obj(&path).unwrap_err();
            assert!(err.contains(expected) && err.contains(name), "{name}: {err}");
        }
    }

    #[test]
    fn odd_obj_lines_are_errors_or_meshes_never_panics() {
        let dir = temp_dir("obj-odd");
        let texts = [
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -5 1 2\n",
            "v 0 0\nf 1 1 1\n",
            "v 0 0 0\nf 1\n",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/9/9 2/9/9 3/9/9\n",
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2 3\n",
            "v 1e40 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
            "\u{0}\u{1}garbage\nf\n",
        ];
        for (i, text) in texts.iter().enumerate() {
            let path = dir.join(format!("odd{i}.obj"));
            std::fs::write(&path, text).unwrap();
            if let Ok(mesh) = Mesh::load_obj(&path) {
                // Whatever was accepted is usable.
                assert!(mesh.positions.iter().all(|p| p.is_finite()), "{text:?}");
                let n = mesh.positions.len() as u32;
                assert!(mesh.triangles.iter().flatten().all(|&k| k < n), "{text:?}");
                assert!(mesh.normals.is_empty() || mesh.normals.len() == mesh.positions.len());
            }
        }
    }

    #[test]
    fn bounds_of_an_empty_mesh_are_empty() {
        let (lo, hi) = Mesh::default().bounds();
        assert!(lo.x > hi.x);
    }
}
