//! `target/grader/report.html`: every check with its verdict, and for each
//! scene the expected, your and the difference (FLIP) images side by side.
//! Clicking a pixel shows the command that prints its ray tree; for a failed
//! scene the tree of the first differing pixel is in the page. One file with
//! its style and script inline and images beside it: it opens with no network.

use std::fmt::Write;
use std::path::{Path, PathBuf};

// The script the checks write beside a failed scene's images: its 3D view's data (geometry, and
// the expected and your ray trees of a grid of pixels), loaded when the view is opened; or the
// reason there is none.
use raylab_protocol::{VIEW_DATA, VIEW_MISSING};

use crate::grade::Grade;
use crate::verdict::{Info, Status, Verdict};
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
    // The 3D views' drawing code, once, where a failed scene has a view.
    let view3d = if body.contains("class=\"view3d-box\"") {
        format!("<script>{}</script>\n", raylab_protocol::VIEW3D_SCRIPT)
    } else {
        String::new()
    };
    let view3d_style = raylab_protocol::VIEW3D_STYLE;
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>raylab grade {got}/{max}</title>\n\
         <style>{STYLE}{view3d_style}</style>\n</head>\n<body>\n{body}<div id=\"picked\" hidden></div>\n{view3d}<script>{SCRIPT}</script>\n</body>\n</html>\n"
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
    images_row(body, ws, v, out);
}

/// Where a picture's check writes its images (expected.png, yours.png, diff.png).
pub struct PictureDir<'a> {
    /// The folder's name in the check's lecture's folder of `target/grader`.
    pub name: String,
    /// The lecture whose scene it draws, and the scene's name.
    pub scene_lecture: &'a str,
    pub scene: &'a str,
}

impl<'a> PictureDir<'a> {
    /// The folder of a picture's check (`NN/image/S`, `10/final/MM-S`); None for other checks.
    pub fn of(info: &'a Info) -> Option<Self> {
        if !matches!(info.exercise.as_str(), "image" | "final") {
            return None;
        }
        let name = info.id.rsplit('/').next().unwrap_or_default();
        // `NN/image/S` writes into NN/S and draws lecture NN's S; `10/final/MM-S` writes into
        // 10/final-MM-S and draws lecture MM's S.
        Some(match name.split_once('-') {
            Some((lecture, scene)) if info.exercise == "final" => {
                Self { name: format!("final-{name}"), scene_lecture: lecture, scene }
            }
            _ => Self { name: name.to_owned(), scene_lecture: &info.lecture, scene: name },
        })
    }

    /// The folder itself, under the grader's output folder `out`.
    pub fn under(&self, out: &Path, info: &Info) -> PathBuf {
        out.join(&info.lecture).join(&self.name)
    }
}

/// The three images of a scene, when the check wrote them.
fn images_row(body: &mut String, ws: &Workspace, v: &Verdict, out: &Path) {
    let Some(picture) = PictureDir::of(&v.info) else {
        return;
    };
    let scene_dir = picture.under(out, &v.info);
    let PictureDir { name: dir_name, scene_lecture, scene: scene_name } = picture;
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
    // The command a click shows draws with the stage that drew this picture: the check's lecture's
    // (the final pictures' is lecture 10's, the complete tracer).
    let scene = format!("lectures/{folder}/scenes/{scene_name}.toml --stage {}", v.info.lecture);
    let tree = std::fs::read_to_string(scene_dir.join("tree.txt")).unwrap_or_default();
    let _ = writeln!(
        body,
        "<tr class=\"images\"><td colspan=\"4\" data-scene=\"{}\"{}>\
         <figure><img src=\"{}\" alt=\"expected\"><figcaption>expected</figcaption></figure>\
         <figure><img src=\"{}\" alt=\"yours\"><figcaption>yours</figcaption></figure>\
         <figure><img src=\"{}\" alt=\"difference (FLIP)\"><figcaption>difference (FLIP), mean {}</figcaption></figure>\
         <p class=\"hint\">Click a pixel for the command that prints its ray tree{}.</p>{}{}</td></tr>",
        escape(&scene),
        // A final picture is drawn smaller than its scene: the click's command draws it at its size.
        if v.info.exercise == "final" { " data-final" } else { "" },
        relative("expected.png"),
        relative("yours.png"),
        relative("diff.png"),
        escape(&flip),
        if scene_dir.join(VIEW_DATA).is_file() {
            " and, in the 3D view, the trees of the nearest pixel of a grid"
        } else {
            ""
        },
        if tree.is_empty() { String::new() } else { format!("<pre class=\"tree\">{}</pre>", escape(&tree)) },
        view_box(&scene_dir, &relative(""))
    );
}

/// The 3D view of a failed scene: a box that loads its data when opened (the first is open).
fn view_box(scene_dir: &Path, relative: &str) -> String {
    if scene_dir.join(VIEW_DATA).is_file() {
        let key = relative.trim_end_matches('/');
        format!(
            "<details class=\"view3d-box\" data-view=\"{}\" data-src=\"{}{VIEW_DATA}\"><summary>The ray trees in 3D: \
             expected and yours over the scene</summary><p class=\"picked3d\"></p><div class=\"view3d-root\"></div></details>",
            escape(key),
            escape(relative)
        )
    } else if let Ok(why) = std::fs::read_to_string(scene_dir.join(VIEW_MISSING)) {
        format!("<p class=\"hint\">No 3D view: {}</p>", escape(why.trim()))
    } else {
        String::new()
    }
}

pub(crate) fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The report's styles (the 3D view's are the protocol's, `VIEW3D_STYLE`).
const STYLE: &str = include_str!("../assets/report.css");

/// The report's script: a failed scene's 3D view loaded when its box opens, a click on a picture
/// picking a pixel.
const SCRIPT: &str = include_str!("../assets/report.js");
