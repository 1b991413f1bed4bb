// INSTRUCTOR ONLY: left out of the handout, with the rest of `grader class`.
//! A class as it comes: a zip of submission folders, or Gradescope's "Export Submissions" (a
//! zip, or its unpacked folder, of `submission_NNN/` folders and `submission_metadata.yml`,
//! which names each submission's students and holds the autograder's results of each).
//!
//! The metadata is YAML written by Ruby (its keys `:submitters`, `:sid`, …); what is read of it:
//! per submission folder, its submitters (`:name`, `:sid`, `:email`: a group submission has
//! several, each a row of the gradebook) and, for `grader class --results`, its `:results` (the
//! `results.json` our autograder wrote on Gradescope: `tests`, each with `name`, `score`,
//! `max_score` and `output`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
use yaml_rust2::{Yaml, YamlLoader};

use super::{CheckGrade, StudentGrade};

/// The export's file of who submitted what.
pub const METADATA: &str = "submission_metadata.yml";

/// One student of a submission, as the export names them.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Submitter {
    pub name: String,
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub sid: String,
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub email: String,
}

/// A submission of the export's metadata.
#[derive(Debug, Default)]
pub struct Submission {
    pub submitters: Vec<Submitter>,
    /// The autograder's results (Gradescope's `results.json`), as JSON.
    pub results: Option<serde_json::Value>,
}

/// The folder of submissions that `path` is: itself if a folder, else the zip unpacked into
/// `into` (emptied first). An archive of one folder (`assignment_1_export/`, `submissions/`) is
/// that folder.
pub fn submissions_folder(path: &Path, into: &Path) -> Result<PathBuf, String> {
    if path.is_dir() {
        return Ok(path.to_owned());
    }
    let file = std::fs::File::open(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut archive = zip::ZipArchive::new(file)
        .map_err(|e| format!("{}: not a zip of submissions: {e}", path.display()))?;
    let _ = std::fs::remove_dir_all(into);
    // Every entry's path is checked to stay inside `into` (`..` or an absolute path is an error).
    archive.extract(into).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut dir = into.to_owned();
    loop {
        let entries: Vec<PathBuf> = std::fs::read_dir(&dir)
            .map_err(|e| format!("{}: {e}", dir.display()))?
            .filter_map(Result::ok)
            .map(|e| e.path())
            .filter(|p| {
                p.file_name().is_some_and(|n| n != "__MACOSX" && !n.to_string_lossy().starts_with('.'))
            })
            .collect();
        match entries.as_slice() {
            [only] if only.is_dir() && !only.join("lectures").is_dir() => dir = only.clone(),
            _ => return Ok(dir),
        }
    }
}

/// The export's metadata in `dir`, by submission folder; empty without one.
pub fn metadata(dir: &Path) -> Result<BTreeMap<String, Submission>, String> {
    let file = dir.join(METADATA);
    let Ok(text) = std::fs::read_to_string(&file) else {
        return Ok(BTreeMap::new());
    };
    let error = |what: &str| format!("{}: {what}", file.display());
    let docs = YamlLoader::load_from_str(&text).map_err(|e| error(&e.to_string()))?;
    let Some(Yaml::Hash(submissions)) = docs.into_iter().next() else {
        return Err(error("expected a mapping of submission folders"));
    };
    let mut read = BTreeMap::new();
    for (folder, fields) in submissions {
        let folder = scalar(&folder).ok_or_else(|| error("a submission's folder is not a name"))?;
        let submitters = match field(&fields, "submitters") {
            Some(Yaml::Array(people)) => people
                .iter()
                .map(|p| Submitter {
                    name: field(p, "name").and_then(scalar).unwrap_or_default(),
                    sid: field(p, "sid").and_then(scalar).unwrap_or_default(),
                    email: field(p, "email").and_then(scalar).unwrap_or_default(),
                })
                .collect(),
            _ => Vec::new(),
        };
        let results = field(&fields, "results").map(json);
        read.insert(folder, Submission { submitters, results });
    }
    Ok(read)
}

/// A field of a mapping, under its Ruby symbol's key (`:name`) or a plain one (`name`).
fn field<'a>(map: &'a Yaml, name: &str) -> Option<&'a Yaml> {
    let Yaml::Hash(map) = map else { return None };
    map.get(&Yaml::String(format!(":{name}"))).or_else(|| map.get(&Yaml::String(name.to_owned())))
}

/// A scalar as text (a student id may be read as a number).
fn scalar(value: &Yaml) -> Option<String> {
    match value {
        Yaml::String(s) | Yaml::Real(s) => Some(s.clone()),
        Yaml::Integer(i) => Some(i.to_string()),
        Yaml::Boolean(b) => Some(b.to_string()),
        _ => None,
    }
}

/// A YAML value as JSON, keys without Ruby's leading colon.
fn json(value: &Yaml) -> serde_json::Value {
    use serde_json::Value;
    match value {
        Yaml::Real(s) => s.parse::<f64>().map_or_else(|_| Value::String(s.clone()), Value::from),
        Yaml::Integer(i) => Value::from(*i),
        Yaml::String(s) => Value::String(s.clone()),
        Yaml::Boolean(b) => Value::Bool(*b),
        Yaml::Array(items) => Value::Array(items.iter().map(json).collect()),
        Yaml::Hash(map) => Value::Object(
            map.iter()
                .filter_map(|(k, v)| Some((scalar(k)?.trim_start_matches(':').to_owned(), json(v))))
                .collect(),
        ),
        _ => Value::Null,
    }
}

/// A student's grade read back from our autograder's results on Gradescope (`results.json`, as
/// `output::gradescope` writes it): a test per check, named `NN exercise/case`, its output's
/// first line `STATUS: summary` and, for a failure, a line `likely cause: …`.
pub fn grade_from_results(student: &str, results: &serde_json::Value) -> StudentGrade {
    let tests = results["tests"].as_array().map(Vec::as_slice).unwrap_or_default();
    let checks: Vec<CheckGrade> = tests
        .iter()
        .map(|test| {
            let name = test["name"].as_str().unwrap_or_default();
            let id = name.replacen(' ', "/", 1);
            let exercise = id.rsplit_once('/').map_or(id.as_str(), |(e, _)| e).to_owned();
            let output = test["output"].as_str().unwrap_or_default();
            let points = |key: &str| test[key].as_f64().unwrap_or(0.0).round() as u32;
            let status = output.split_once(": ").map_or("", |(s, _)| s);
            let status = if status.is_empty() || status.contains('\n') {
                if test["status"] == "passed" { "passed" } else { "FAILED" }
            } else {
                status
            };
            let cause = output
                .lines()
                .find_map(|l| l.strip_prefix("likely cause: "))
                .or_else(|| (status != "passed").then(|| output.split_once(": ").map_or(output, |(_, s)| s)))
                .map(|c| c.lines().next().unwrap_or_default().to_owned());
            CheckGrade {
                id,
                exercise,
                points: points("score"),
                max_points: points("max_score"),
                status: status.to_owned(),
                cause,
                picture: None,
            }
        })
        .collect();
    StudentGrade::new(student, checks)
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;

    /// A Gradescope export's metadata, in the shape its export writes (Ruby symbols as keys, a
    /// group submission with two submitters, a numeric sid, our autograder's results).
    const METADATA_SAMPLE: &str = r#"---
submission_101:
  :submitters:
  - :name: Ada Lovelace
    :sid: '1815'
    :email: ada@example.edu
  :created_at: 2026-11-20 23:58:01.000000000 -08:00
  :score: 3.0
  :results:
    score: 3.0
    tests:
    - name: 02 hit_plane/unit
      score: 1.0
      max_score: 1.0
      status: passed
      output: |
        passed: 12 cases
    - name: 02 hit_sphere_stable/unit
      score: 0.0
      max_score: 2.0
      status: failed
      output: |
        FAILED: a tangent ray
        expected: a hit at t = 4
        got: a miss
        likely cause: zero discriminant: a tangent ray touches
submission_102:
  :submitters:
  - :name: Ben Ng
    :sid: 2001
    :email: ben@example.edu
  - :name: Cy Ortiz
    :sid: 2002
    :email: cy@example.edu
  :created_at: 2026-11-21 10:00:00.000000000 -08:00
  :score: 0.0
  :history: []
"#;

    /// A zip of `(name, contents)` entries, stored.
    fn zip(file: &Path, entries: &[(&str, &str)]) {
        use std::io::Write;
        let mut writer = zip::ZipWriter::new(std::fs::File::create(file).unwrap());
        let options =
            zip::write::SimpleFileOptions::default().compression_method(zip::CompressionMethod::Stored);
        for (name, contents) in entries {
            writer.start_file(*name, options).unwrap();
            writer.write_all(contents.as_bytes()).unwrap();
        }
        writer.finish().unwrap();
    }

    #[test]
    fn a_zip_of_submissions_is_unpacked_to_its_one_folder_and_never_outside() {
        let dir = std::env::temp_dir().join(format!("raylab-zip-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        // Gradescope's export: one folder, the metadata and a folder per submission; and the
        // folder a Mac's archive adds.
        let export = dir.join("export.zip");
        zip(
            &export,
            &[
                ("assignment_7_export/submission_metadata.yml", METADATA_SAMPLE),
                ("assignment_7_export/submission_101/lectures/01-transforms/src/lib.rs", "// ada"),
                ("assignment_7_export/submission_102/lectures/01-transforms/src/lib.rs", "// ben, cy"),
                ("__MACOSX/assignment_7_export/._submission_101", ""),
            ],
        );
        let folder = submissions_folder(&export, &dir.join("unpacked")).unwrap();
        assert!(folder.ends_with("unpacked/assignment_7_export"), "{}", folder.display());
        assert!(folder.join("submission_101/lectures/01-transforms/src/lib.rs").is_file());
        assert_eq!(metadata(&folder).unwrap().len(), 2);
        // A folder is taken as it is.
        assert_eq!(submissions_folder(&folder, &dir.join("unused")).unwrap(), folder);
        assert!(!dir.join("unused").exists());
        // An entry that climbs out of the folder: refused, nothing written outside.
        let evil = dir.join("evil.zip");
        zip(&evil, &[("ada/lectures/01-transforms/src/lib.rs", ""), ("../../escaped.txt", "out")]);
        let error = submissions_folder(&evil, &dir.join("deep/er/unpacked")).unwrap_err();
        assert!(error.contains("evil.zip"), "{error}");
        assert!(!dir.join("escaped.txt").exists() && !dir.join("deep/escaped.txt").exists());
        // Not a zip: an error naming the file.
        std::fs::write(dir.join("notes.txt"), "not a zip").unwrap();
        let error = submissions_folder(&dir.join("notes.txt"), &dir.join("x")).unwrap_err();
        assert!(error.contains("notes.txt") && error.contains("not a zip"), "{error}");
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn gradescopes_metadata_names_each_submissions_students_and_holds_its_results() {
        let dir = std::env::temp_dir().join(format!("raylab-export-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join(METADATA), METADATA_SAMPLE).unwrap();
        let read = metadata(&dir).unwrap();
        assert_eq!(read.len(), 2);
        let ada = &read["submission_101"];
        assert_eq!(
            ada.submitters,
            [Submitter { name: "Ada Lovelace".into(), sid: "1815".into(), email: "ada@example.edu".into() }]
        );
        let group: Vec<&str> = read["submission_102"].submitters.iter().map(|s| s.sid.as_str()).collect();
        assert_eq!(group, ["2001", "2002"], "a numeric sid reads as text");
        assert!(read["submission_102"].results.is_none());
        // The results, read back as the grade they were.
        let grade = grade_from_results("submission_101", ada.results.as_ref().unwrap());
        assert_eq!((grade.score, grade.max_score), (1, 3));
        let failed = &grade.checks[1];
        assert_eq!(failed.id, "02/hit_sphere_stable/unit");
        assert_eq!(failed.exercise, "02/hit_sphere_stable");
        assert_eq!(failed.status, "FAILED");
        assert_eq!(failed.cause.as_deref(), Some("zero discriminant: a tangent ray touches"));
        assert_eq!((grade.checks[0].status.as_str(), grade.checks[0].cause.as_deref()), ("passed", None));
        // No metadata: an empty map, not an error; a broken one: an error naming the file.
        assert!(metadata(&dir.join("nowhere")).unwrap().is_empty());
        std::fs::write(dir.join(METADATA), "submission_1: [unclosed").unwrap();
        let error = metadata(&dir).unwrap_err();
        assert!(error.contains(METADATA), "{error}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
