// INSTRUCTOR ONLY: a test of the checks crate (the handout leaves the checks' tests out).
//! Bad scenes through `grader render`, as a student writing their own meets
//! them: every lecture scene and a 6.837 scene with numbers at the edge of
//! the precision's range, numbers made large together so that their
//! products overflow, cameras moved far away or next to their target, and
//! files named that are endless, huge, pipes or folders. These are the
//! categories that found the errors of the bad-scenes issue.
//!
//! Each case must end in one of three ways: refused at load with a message
//! that names the scene file (and no Rust type name, no value over ~40
//! characters), refused by the work budget, or a finite image written (the
//! PNG writer refuses NaN and infinite pixels). A panic, a refused image or a
//! message without the file fails the test, which prints the counts.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};

use clap::Parser;

use crate::tools::{Tool, Tools};

/// Values at the edge of f32's and f64's range, and the integers past f32's
/// and u32's exact range.
const EDGES: [&str; 16] = [
    "3.4028235e38",
    "-3.4028235e38",
    "3.5e38",
    "1e39",
    "1.7976931348623157e308",
    "1e309",
    "-1e309",
    "1.4e-45",
    "1e-39",
    "5e-324",
    "0",
    "-0.0",
    "1e-30",
    "16777217",
    "4294967296",
    "1e15",
];

/// Values each finite in f32 whose products of two or three are not.
const LARGE: [&str; 5] = ["1e10", "1e13", "1e19", "1e20", "3e38"];

/// Cases drawn per seed scene and category: the whole cross product of the
/// lecture scenes' ~1,700 numbers and 16 values would take minutes in a
/// debug build.
const PER_SEED: usize = 48;

/// A 6.837 scene using every construct whose numbers matter, a mesh apart.
const MIT6837: &str = "PerspectiveCamera {
    center 0 0 10
    direction 0 0 -1
    up 0 1 0
    angle 30
}
Lights {
    numLights 2
    DirectionalLight { direction 0 0 -2 color 1 1 1 }
    PointLight { position 0 5 0 color 0.5 0.5 0.5 attenuation 1 0 0.25 }
}
Background { color 0.125 0.25 0.5 ambientLight 0.5 0.5 0.5 }
Materials {
    numMaterials 2
    Material { diffuseColor 1 0 0 }
    PhongMaterial { diffuseColor 0 1 0 specularColor 1 1 1 exponent 16 reflectiveColor 0.5 0.5 0.5
                    transparentColor 0.25 0.25 0.25 indexOfRefraction 1.5 }
}
Group {
    numObjects 4
    MaterialIndex 1
    Sphere { center 0 0 0 radius 1 }
    Plane { normal 0 2 0 offset -2 }
    Triangle { vertex0 0 0 0 vertex1 1 0 0 vertex2 0 1 0 }
    Transform {
        Translate 1 0 0
        Rotate { axis 1 1 0 angle 180 }
        Matrix { 1 0 0 4  0 1 0 5  0 0 1 6  0 0 0 1 }
        Scale 1 2 1
        Sphere { center 0 0 0 radius 0.5 }
    }
}
";

/// How a case ended, when it ended well.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Outcome {
    Refused,
    OverBudget,
    Rendered,
}

/// One category's counts.
#[derive(Default)]
struct Tally {
    cases: usize,
    refused: usize,
    over_budget: usize,
    rendered: usize,
    failures: Vec<String>,
    /// The distinct keys whose first number took every edge value (category 1).
    keys: usize,
}

impl Tally {
    /// Counts a case: `mutant`, made from `original`, ended with `outcome`.
    fn add(&mut self, what: &str, original: &str, mutant: &str, outcome: Result<Outcome, String>) {
        self.cases += 1;
        match outcome {
            Ok(Outcome::Refused) => self.refused += 1,
            Ok(Outcome::OverBudget) => self.over_budget += 1,
            Ok(Outcome::Rendered) => self.rendered += 1,
            Err(e) => {
                let changed: Vec<&str> =
                    mutant.lines().zip(original.lines()).filter(|(m, o)| m != o).map(|(m, _)| m).collect();
                self.failures.push(format!("{what}: {e}\n  lines changed: {changed:?}"));
            }
        }
    }
}

/// A deterministic generator (a linear congruential one, Knuth's MMIX constants).
struct Lcg(u64);

impl Lcg {
    fn below(&mut self, n: usize) -> usize {
        self.0 = self.0.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        ((self.0 >> 33) as usize) % n
    }
}

/// The byte ranges of the numbers in `text`, comments and strings left out:
/// a digit, or a sign or point before one, that starts no word.
fn numbers(text: &str) -> Vec<std::ops::Range<usize>> {
    let mut found = Vec::new();
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let bytes = line.as_bytes();
        let mut i = 0;
        let mut in_string = false;
        while i < bytes.len() {
            let c = bytes[i];
            if c == b'"' {
                in_string = !in_string;
            }
            if c == b'#' && !in_string {
                break;
            }
            let starts = !in_string
                && (c.is_ascii_digit()
                    || ((c == b'-' || c == b'.') && bytes.get(i + 1).is_some_and(u8::is_ascii_digit)))
                && (i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_'));
            if starts {
                let end = (i + 1..bytes.len())
                    .find(|&j| {
                        let d = bytes[j];
                        !(d.is_ascii_digit()
                            || d == b'.'
                            || d == b'e'
                            || d == b'E'
                            || ((d == b'-' || d == b'+') && matches!(bytes[j - 1], b'e' | b'E')))
                    })
                    .unwrap_or(bytes.len());
                found.push(offset + i..offset + end);
                i = end;
            } else {
                i += 1;
            }
        }
        offset += line.len();
    }
    found
}

/// `text` with the numbers at `ranges` (sorted, disjoint) replaced by `values`.
fn replaced(text: &str, ranges: &[std::ops::Range<usize>], values: &[&str]) -> String {
    let mut out = String::with_capacity(text.len() + 64);
    let mut last = 0;
    for (range, value) in ranges.iter().zip(values) {
        out.push_str(&text[last..range.start]);
        out.push_str(value);
        last = range.end;
    }
    out.push_str(&text[last..]);
    out
}

/// Writes `text` as `name` in `dir` and renders it at 6×4 as `grader render` does.
fn render_text(dir: &Path, name: &str, text: &str) -> Result<Outcome, String> {
    let scene = dir.join(name);
    std::fs::write(&scene, text).map_err(|e| e.to_string())?;
    render_path(dir, &scene)
}

/// `grader render SCENE --size 6x4` (and its image written): how it ended.
fn render_path(dir: &Path, scene: &Path) -> Result<Outcome, String> {
    let output = dir.join("out.png");
    let _ = std::fs::remove_file(&output);
    let argv =
        ["grader", "render", &scene.to_string_lossy(), "--size", "6x4", "-o", &output.to_string_lossy()]
            .map(str::to_owned);
    let Tool::Render(args) = Tools::try_parse_from(argv).map_err(|e| e.to_string())?.tool else {
        return Err("not a render command".to_owned());
    };
    let result =
        catch_unwind(AssertUnwindSafe(|| super::render::render_to_file(&args))).map_err(|panic| {
            let said = panic.downcast_ref::<String>().cloned();
            let said = said.or_else(|| panic.downcast_ref::<&str>().map(|s| (*s).to_owned()));
            format!("panicked: {}", said.unwrap_or_default())
        })?;
    match result {
        Ok(()) if output.is_file() => Ok(Outcome::Rendered),
        Ok(()) => Err("no image written and no error".to_owned()),
        Err(message) => judge(&message, scene),
    }
}

/// An error is good when it names the scene file, is short, and speaks no Rust.
fn judge(message: &str, scene: &Path) -> Result<Outcome, String> {
    if message.contains("--allow-large") {
        return Ok(Outcome::OverBudget);
    }
    let rust = ["invalid type", "struct ", "i64", "u32", "usize", "f32", "f64", "Spanned", "Option<"];
    if !message.starts_with(&scene.display().to_string()) {
        Err(format!("the error does not start with the scene file: {message}"))
    } else if let Some(word) = rust.iter().find(|w| message.contains(*w)) {
        Err(format!("the error speaks Rust ({word}): {message}"))
    } else if message.chars().count() > 400 {
        Err(format!("the error has {} characters: {message}", message.chars().count()))
    } else {
        Ok(Outcome::Refused)
    }
}

/// The seeds: every lecture scene, the 6.837 scene above.
fn seeds() -> Vec<(String, String)> {
    let mut seeds: Vec<(String, String)> = crate::scenes::scene_files(None)
        .expect("the lecture scenes are listed")
        .into_iter()
        .map(|f| {
            let name = format!("{}-{}", f.lecture, f.scene.file_name().unwrap().to_string_lossy());
            (name, std::fs::read_to_string(&f.scene).expect("a lecture scene reads"))
        })
        .collect();
    seeds.push(("mit6837.txt".to_owned(), MIT6837.to_owned()));
    seeds
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("raylab-bad-scenes-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// What a number of `text` at `range` is the value of: the words before it on
/// its line (`fovy =`, `radius`, `Sphere { center`) and its place among the
/// line's numbers, e.g. `eye = #2`.
fn key_of(text: &str, range: &std::ops::Range<usize>) -> String {
    let start = text[..range.start].rfind('\n').map_or(0, |i| i + 1);
    let line = &text[start..range.start];
    let words: String = line.chars().filter(|c| c.is_alphabetic() || *c == '_' || *c == ' ').collect();
    let place = numbers(line).len();
    format!("{} #{place}", words.split_whitespace().last().unwrap_or(""))
}

/// Category 1: one number replaced by a value at the edge of the range: every
/// value in place of the first number of each key (and place in its line) of
/// the seeds, then random numbers of each seed.
fn edge_numbers(dir: &Path, tally: &mut Tally) {
    let mut lcg = Lcg(0x2545_f491_4f6c_dd1d);
    let mut keys = std::collections::HashSet::new();
    for (name, text) in seeds() {
        let ranges = numbers(&text);
        let first_of_key = ranges.iter().filter(|r| keys.insert(key_of(&text, r)));
        let every_value = first_of_key.flat_map(|r| EDGES.map(|value| (r.clone(), value)));
        let random: Vec<_> = (0..PER_SEED)
            .map(|_| (ranges[lcg.below(ranges.len())].clone(), EDGES[lcg.below(EDGES.len())]))
            .collect();
        for (range, value) in every_value.collect::<Vec<_>>().into_iter().chain(random) {
            tally.keys = keys.len();
            let mutant = replaced(&text, std::slice::from_ref(&range), &[value]);
            let what = format!("{name}: {} → {value}", &text[range]);
            tally.add(&what, &text, &mutant, render_text(dir, &name, &mutant));
        }
    }
}

/// Category 2: two or three numbers made large together.
fn overflowing_products(dir: &Path, tally: &mut Tally) {
    let mut lcg = Lcg(0x9e37_79b9_7f4a_7c15);
    for (name, text) in seeds() {
        let ranges = numbers(&text);
        for _ in 0..PER_SEED {
            let mut chosen: Vec<_> =
                (0..2 + lcg.below(2)).map(|_| ranges[lcg.below(ranges.len())].clone()).collect();
            chosen.sort_by_key(|r| r.start);
            chosen.dedup();
            let values: Vec<&str> = chosen.iter().map(|_| LARGE[lcg.below(LARGE.len())]).collect();
            let mutant = replaced(&text, &chosen, &values);
            tally.add(&format!("{name}: {values:?}"), &text, &mutant, render_text(dir, &name, &mutant));
        }
    }
}

/// The three numbers of the line of `text` that starts (indented or not) with
/// `key` and a space or `=`, and the byte range they span.
fn vector_at(text: &str, key: &str) -> Option<([f64; 3], std::ops::Range<usize>)> {
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let trimmed = line.trim_start();
        let rest = trimmed.strip_prefix(key).filter(|r| r.starts_with([' ', '=']));
        if rest.is_some() {
            let found = numbers(line);
            if found.len() >= 3 {
                let values: Vec<f64> =
                    found[..3].iter().map(|r| line[r.clone()].parse().unwrap_or(0.0)).collect();
                let span = offset + found[0].start..offset + found[2].end;
                return Some(([values[0], values[1], values[2]], span));
            }
        }
        offset += line.len();
    }
    None
}

/// Category 3: the eye far away, the target far away or next to the eye.
fn far_and_near_cameras(dir: &Path, tally: &mut Tally) {
    for (name, text) in seeds() {
        let toml = name.ends_with(".toml");
        let (eye_key, second_key) = if toml { ("eye", "at") } else { ("center", "direction") };
        let (Some((eye, eye_span)), Some((second, second_span))) =
            (vector_at(&text, eye_key), vector_at(&text, second_key))
        else {
            tally.failures.push(format!("{name}: no camera {eye_key} and {second_key} found"));
            continue;
        };
        // The view direction: at − eye (TOML), direction (6.837).
        let view = if toml { [second[0] - eye[0], second[1] - eye[1], second[2] - eye[2]] } else { second };
        let list = |v: [f64; 3]| {
            if toml {
                format!("{:e}, {:e}, {:e}", v[0], v[1], v[2])
            } else {
                format!("{:e} {:e} {:e}", v[0], v[1], v[2])
            }
        };
        let mut cases: Vec<(String, [f64; 3], [f64; 3])> = Vec::new();
        for scale in [1e20, 1e30, 1e38, 1e300] {
            // The eye moved far along the view's opposite: the scene a speck in the middle.
            let far_eye = eye.map(|e| e * scale + 1.0);
            let second_for = |eye: [f64; 3]| if toml { [0, 1, 2].map(|i| eye[i] + view[i]) } else { view };
            cases.push((format!("eye ×{scale:e}"), far_eye, second_for(far_eye)));
            // The target far along the view: a direction by another name.
            let far = [0, 1, 2].map(|i| view[i] * scale);
            cases.push((
                format!("view ×{scale:e}"),
                eye,
                if toml { [0, 1, 2].map(|i| eye[i] + far[i]) } else { far },
            ));
        }
        for scale in [1e-7, 1e-20, 1e-38, 1e-45, 1e-300, 0.0] {
            let near = [0, 1, 2].map(|i| view[i] * scale);
            cases.push((
                format!("view ×{scale:e}"),
                eye,
                if toml { [0, 1, 2].map(|i| eye[i] + near[i]) } else { near },
            ));
        }
        for (what, new_eye, new_second) in cases {
            let spans = [eye_span.clone(), second_span.clone()];
            let (first, last) = if eye_span.start < second_span.start { (0, 1) } else { (1, 0) };
            let values = [list(new_eye), list(new_second)];
            let mutant = replaced(
                &text,
                &[spans[first].clone(), spans[last].clone()],
                &[&values[first], &values[last]],
            );
            tally.add(&format!("{name}: {what}"), &text, &mutant, render_text(dir, &name, &mutant));
        }
    }
}

/// Endless devices and a named pipe: Unix has them at known paths.
#[cfg(unix)]
fn special_files(dir: &Path) -> Vec<PathBuf> {
    let fifo = dir.join("pipe.obj");
    let _ = std::fs::remove_file(&fifo);
    assert!(std::process::Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let mut paths = ["/dev/zero", "/dev/urandom", "/dev/null"].map(PathBuf::from).to_vec();
    paths.push(fifo);
    paths
}

/// Windows' devices are not files a path test reaches the same way; the other cases stand.
#[cfg(not(unix))]
fn special_files(_dir: &Path) -> Vec<PathBuf> {
    Vec::new()
}

/// Category 4: a mesh, a texture and the scene itself named by paths that are
/// endless, huge, pipes, folders, missing or empty.
fn endless_and_huge_files(dir: &Path, tally: &mut Tally) {
    let huge = dir.join("huge.obj");
    // Sparse: 300 MiB on the file system's word, a few blocks on its disk.
    std::fs::File::create(&huge).and_then(|f| f.set_len(300 << 20)).unwrap();
    let empty = dir.join("empty.obj");
    std::fs::write(&empty, "").unwrap();
    let mut paths = vec![huge.clone(), empty, dir.to_path_buf(), dir.join("missing.obj")];
    paths.extend(special_files(dir));
    let camera = "[camera]\ntype = \"perspective\"\neye = [0, 0, 5]\nat = [0, 0, 0]\nfovy = 40\n";
    let six = "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 angle 40 }\n\
               Background { color 0 0 0 }\nMaterials { numMaterials 1 Material { diffuseColor 1 1 1 } }\n";
    for path in &paths {
        let p = path.display();
        let mesh = format!("{camera}[[objects]]\ntype = \"mesh\"\nfile = \"{p}\"\n");
        tally.add(&format!("mesh {p}"), "", &mesh, render_text(dir, "mesh.toml", &mesh));
        let texture = format!(
            "{camera}[materials.m]\ntexture = {{ type = \"image\", file = \"{p}\" }}\n\
             [[objects]]\ntype = \"sphere\"\ncenter = [0, 0, 0]\nradius = 1\nmaterial = \"m\"\n"
        );
        tally.add(&format!("texture {p}"), "", &texture, render_text(dir, "texture.toml", &texture));
        let obj = format!("{six}Group {{ numObjects 1 MaterialIndex 0 TriangleMesh {{ obj_file {p} }} }}\n");
        tally.add(&format!("6.837 mesh {p}"), "", &obj, render_text(dir, "mesh.txt", &obj));
        // The scene itself.
        tally.add(&format!("scene {p}"), "", "", render_path(dir, path));
    }
}

/// A category of cases: writes its scenes in the folder given and counts them.
type Category = fn(&Path, &mut Tally);

// One test a category, so that the test harness runs them side by side (together, one after
// another, they were the slowest test of the crate: 14.7 s of its 16 s).
#[test]
fn numbers_at_the_edge_of_the_range_are_refused_or_render_finite() {
    category("numbers at the edge of the range", edge_numbers);
}

#[test]
fn products_that_overflow_are_refused_or_render_finite() {
    category("products that overflow", overflowing_products);
}

#[test]
fn far_and_near_cameras_are_refused_or_render_finite() {
    category("far and near cameras", far_and_near_cameras);
}

#[test]
fn endless_huge_piped_and_missing_files_are_refused_by_name() {
    category("endless, huge, piped and missing files", endless_and_huge_files);
}

/// Runs a category's cases: each must be refused by file or budget or render finite; prints the
/// category's row of counts.
fn category(name: &str, run: Category) {
    let dir = temp_dir(&format!("fuzz-{}", name.split(' ').next().unwrap_or(name)));
    let mut tally = Tally::default();
    run(&dir, &mut tally);
    let t = &tally;
    println!("| category | cases | refused at load | over budget | rendered finite | failed |");
    println!("|---|---|---|---|---|---|");
    println!(
        "| {name} | {} | {} | {} | {} | {} |",
        t.cases,
        t.refused,
        t.over_budget,
        t.rendered,
        t.failures.len()
    );
    assert!(t.cases >= 10, "{name}: {} cases", t.cases);
    if t.keys > 0 {
        println!(
            "{name}: every value at the first number of each of {} keys, and {PER_SEED} random per seed",
            t.keys
        );
    }
    assert!(
        t.failures.is_empty(),
        "{name}: {} failures; the first:\n{}",
        t.failures.len(),
        t.failures[..t.failures.len().min(5)].join("\n\n")
    );
    let _ = std::fs::remove_dir_all(&dir);
}
