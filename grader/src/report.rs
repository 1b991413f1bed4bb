//! `target/grader/report.html`: every check with its verdict, and for each
//! scene the expected, your and the difference (FLIP) images side by side.
//! Clicking a pixel shows the command that prints its ray tree; for a failed
//! scene the tree of the first differing pixel is in the page. One file with
//! its style and script inline and images beside it: it opens with no network.

use std::fmt::Write;
use std::path::{Path, PathBuf};

use crate::grade::Grade;
use crate::verdict::{Status, Verdict};
use crate::workspace::Workspace;

/// Writes the report into `out` and returns its path.
pub fn write(ws: &Workspace, grade: &Grade, out: &Path) -> Result<PathBuf, String> {
    std::fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
    let path = out.join("report.html");
    std::fs::write(&path, html(ws, grade, out)).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(path)
}

fn html(ws: &Workspace, grade: &Grade, out: &Path) -> String {
    let (got, max) = grade.points();
    let mut body = String::new();
    let _ = writeln!(
        body,
        "<h1>raylab grade: {got}/{max} points</h1>\n<p class=\"summary\">{} checks in {:.1} s. \
         Run <code>cargo run -p grader</code> again to refresh this page.</p>",
        grade.verdicts.len(),
        grade.seconds
    );
    // Where the student stands and the one file to open next.
    let progress = crate::progress::progress(ws, grade);
    let _ = writeln!(body, "<pre class=\"next\">{}</pre>", escape(crate::progress::text(&progress).trim()));
    for (lecture, error) in &grade.compile_errors {
        let _ = writeln!(
            body,
            "<div class=\"compile\"><b>Lecture {lecture} does not compile</b> at <code>{}</code>: {}<pre>{}</pre></div>",
            escape(&error.location),
            escape(&error.message),
            escape(&error.rendered)
        );
    }
    let mut lecture = "";
    for v in &grade.verdicts {
        if v.info.lecture != lecture {
            if !lecture.is_empty() {
                body.push_str("</table>\n");
            }
            lecture = &v.info.lecture;
            let folder = ws.lecture(lecture).map_or(lecture.to_owned(), |l| l.folder.clone());
            let (g, m) = grade
                .verdicts
                .iter()
                .filter(|x| x.info.lecture == lecture)
                .fold((0, 0), |(g, m), x| (g + x.points, m + x.info.points));
            let _ = write!(
                body,
                "<h2 id=\"l{lecture}\">{} <span class=\"pts\">{g}/{m}</span></h2>\n<table>\n\
                 <tr><th>check</th><th>verdict</th><th>points</th><th>detail</th></tr>\n",
                escape(&folder)
            );
        }
        row(&mut body, ws, v, out);
    }
    if !lecture.is_empty() {
        body.push_str("</table>\n");
    }
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>raylab grade {got}/{max}</title>\n\
         <style>{STYLE}</style>\n</head>\n<body>\n{body}<div id=\"picked\" hidden></div>\n<script>{SCRIPT}</script>\n</body>\n</html>\n"
    )
}

fn row(body: &mut String, ws: &Workspace, v: &Verdict, out: &Path) {
    let class = match v.status {
        Status::Passed => "passed",
        Status::NotStarted | Status::Blocked => "todo",
        _ => "failed",
    };
    let mut detail = escape(&v.summary);
    if let Some(f) = &v.failure {
        detail = format!(
            "<div>{}</div><div><b>expected</b> {}</div><div><b>got</b> {}</div><div><b>likely</b> {}</div>",
            escape(&f.case),
            escape(&f.expected),
            escape(&f.got),
            escape(&f.cause)
        );
    }
    let _ = writeln!(
        body,
        "<tr class=\"{class}\" id=\"{}\"><td><code>{}</code><div class=\"about\">{}</div></td><td>{}</td>\
         <td>{}/{}</td><td>{detail}</td></tr>",
        escape(&v.info.id),
        escape(v.info.short()),
        escape(&v.info.about),
        v.status.label(),
        v.points,
        v.info.points
    );
    if matches!(v.info.exercise.as_str(), "image" | "final") {
        images_row(body, ws, v, out);
    }
}

/// The three images of a scene, when the check wrote them.
fn images_row(body: &mut String, ws: &Workspace, v: &Verdict, out: &Path) {
    let name = v.info.id.rsplit('/').next().unwrap_or_default();
    // `NN/image/S` writes into NN/S and draws lecture NN's S; `10/final/MM-S` writes into
    // 10/final-MM-S and draws lecture MM's S.
    let (dir_name, scene_lecture, scene_name) = match name.split_once('-') {
        Some((lecture, scene)) if v.info.exercise == "final" => (format!("final-{name}"), lecture, scene),
        _ => (name.to_owned(), v.info.lecture.as_str(), name),
    };
    let scene_dir = out.join(&v.info.lecture).join(&dir_name);
    if !scene_dir.join("expected.png").is_file() {
        return;
    }
    let relative = |file: &str| format!("{}/{dir_name}/{file}", v.info.lecture);
    let flip = v.failure.as_ref().and_then(|f| f.images.as_ref()).map_or_else(
        || {
            v.summary
                .rsplit("mean FLIP ")
                .next()
                .map(str::to_owned)
                .filter(|s| s.len() < 12)
                .unwrap_or_default()
        },
        |i| format!("{:.4} ({:.2} % of pixels over 0.25)", i.flip_mean, 100.0 * i.flip_fraction_over),
    );
    let folder = ws.lecture(scene_lecture).map_or_else(String::new, |l| l.folder.clone());
    let scene = format!("lectures/{folder}/scenes/{scene_name}.toml");
    let tree = std::fs::read_to_string(scene_dir.join("tree.txt")).unwrap_or_default();
    let _ = writeln!(
        body,
        "<tr class=\"images\"><td colspan=\"4\" data-scene=\"{}\">\
         <figure><img src=\"{}\" alt=\"expected\"><figcaption>expected</figcaption></figure>\
         <figure><img src=\"{}\" alt=\"yours\"><figcaption>yours</figcaption></figure>\
         <figure><img src=\"{}\" alt=\"difference (FLIP)\"><figcaption>difference (FLIP), mean {}</figcaption></figure>\
         <p class=\"hint\">Click a pixel for the command that prints its ray tree.</p>{}</td></tr>",
        escape(&scene),
        relative("expected.png"),
        relative("yours.png"),
        relative("diff.png"),
        escape(&flip),
        if tree.is_empty() { String::new() } else { format!("<pre class=\"tree\">{}</pre>", escape(&tree)) }
    );
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

const STYLE: &str = "
body { font-family: system-ui, sans-serif; margin: 2em; color: #222; }
pre.next { background: #eef5ff; border-left: 4px solid #36c; padding: 0.6em 1em; white-space: pre-wrap; }
h2 .pts { font-weight: normal; color: #666; }
table { border-collapse: collapse; width: 100%; margin-bottom: 2em; }
td, th { border-bottom: 1px solid #ddd; padding: 0.3em 0.6em; text-align: left; vertical-align: top; }
tr.passed td:nth-child(2) { color: #1a7f37; }
tr.failed td:nth-child(2) { color: #cf222e; font-weight: bold; }
tr.todo td:nth-child(2) { color: #9a6700; }
.about { color: #777; font-size: 0.85em; }
figure { display: inline-block; margin: 0.3em; }
figure img { image-rendering: pixelated; width: 240px; cursor: crosshair; border: 1px solid #ccc; }
figcaption { font-size: 0.85em; color: #555; }
pre { background: #f6f8fa; padding: 0.6em; overflow-x: auto; }
.compile { border-left: 4px solid #cf222e; padding-left: 1em; }
#picked { position: fixed; bottom: 1em; right: 1em; background: #fff; border: 1px solid #888; padding: 0.6em; }
";

const SCRIPT: &str = "
for (const img of document.querySelectorAll('td[data-scene] img')) {
  img.addEventListener('click', (event) => {
    const rect = img.getBoundingClientRect();
    const x = Math.floor((event.clientX - rect.left) / rect.width * img.naturalWidth);
    const y = Math.floor((event.clientY - rect.top) / rect.height * img.naturalHeight);
    const scene = img.closest('td').dataset.scene;
    const box = document.getElementById('picked');
    box.hidden = false;
    box.textContent = 'pixel (' + x + ', ' + y + '): cargo run -p grader -- render ' + scene + ' --tree ' + x + ',' + y;
  });
}
";
