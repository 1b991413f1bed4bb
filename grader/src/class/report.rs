// INSTRUCTOR ONLY: left out of the handout, with the rest of `grader class`.
//! `DIR/class.html`: what a class gets wrong, for the next lecture. One page, offline, no script:
//!
//! - first, the class's mistakes at a glance: the students who fail the same checks together,
//!   each check for one cause or with one wrong picture (likely one mistake), the most students
//!   first, with the checks, the cause and who;
//! - then the checks the most students fail, each with its causes (the checks' "likely: …"),
//!   how many students each, and who; under a picture's check, its clusters of wrong pictures
//!   (`clusters.rs`), the largest first, each shown by one picture and its difference from the
//!   expected, with its size, its students and the cause the check gave most often in it;
//! - then, per lecture and exercise in course order, how many students passed, failed, did not
//!   start, were blocked or crashed (a heat map: each cell shaded by its share of the class);
//! - last, the submissions that could not be graded, and why.

use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::Path;

use super::clusters::{Clusters, clusters};
use super::{PICTURES, StudentGrade};
use crate::report::escape;

/// The outcomes a heat map's columns count, in order, with their cells' colours.
const COLUMNS: [(&str, &str); 5] = [
    ("passed", "#2e7d32"),
    ("failed", "#c62828"),
    ("not started", "#757575"),
    ("blocked", "#ef6c00"),
    ("crashed, timed out, does not compile", "#6a1b9a"),
];

/// The column of a check's status.
fn column(status: &str) -> usize {
    match status {
        "passed" => 0,
        "FAILED" => 1,
        "not started" => 2,
        "blocked" => 3,
        _ => 4,
    }
}

/// The page for `grades` (every student's, graded or not), whose pictures are in `out`.
pub fn html(grades: &[StudentGrade], out: &Path) -> String {
    let graded: Vec<&StudentGrade> = grades.iter().filter(|g| g.error.is_none()).collect();
    let mut page = String::new();
    let _ = write!(
        page,
        "<!doctype html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>raylab: the class</title>\
         <style>{STYLE}</style></head><body><h1>The class</h1><p>{} submissions, {} graded.</p>",
        grades.len(),
        graded.len()
    );
    let mut missing = Vec::new();
    let clusters = clusters(out, grades, &mut missing);
    let failed = failed_causes(&graded);
    at_a_glance(&mut page, &failed, &clusters);
    causes(&mut page, graded.len(), &failed, &clusters);
    heat_map(&mut page, &graded);
    let not_graded: Vec<&StudentGrade> = grades.iter().filter(|g| g.error.is_some()).collect();
    if !not_graded.is_empty() {
        page.push_str("<h2 id=\"not-graded\">Not graded</h2><ul>");
        for g in not_graded {
            let _ = write!(
                page,
                "<li><b>{}</b>: {}</li>",
                escape(&g.student),
                escape(g.error.as_deref().unwrap_or_default())
            );
        }
        page.push_str("</ul>");
    }
    if !missing.is_empty() {
        let _ = write!(
            page,
            "<p id=\"missing\">Pictures gone since their grade (left out of the clusters): {}</p>",
            escape(&missing.join(", "))
        );
    }
    page.push_str("</body></html>\n");
    page
}

/// A failed check's causes, by [`cause_key`]: each with its words as its first student's check
/// said them, and the students whose failure names it.
type Causes<'a> = BTreeMap<String, (&'a str, Vec<&'a str>)>;

/// What makes two causes one: their words, not their numbers. A picture's cause names the pixel
/// and the values it saw there (`expected normal (0.1, 0.9, 0.0) at pixel (59, 52)`), which
/// differ from student to student with the same mistake; every number (a run of digits and
/// points, with its sign) reads as `#`.
pub fn cause_key(cause: &str) -> String {
    let mut key = String::with_capacity(cause.len());
    let mut chars = cause.chars().peekable();
    while let Some(c) = chars.next() {
        if c.is_ascii_digit() {
            if key.ends_with('-') || key.ends_with('−') {
                key.pop();
            }
            while chars.next_if(|c| c.is_ascii_digit() || *c == '.').is_some() {}
            key.push('#');
        } else {
            key.push(c);
        }
    }
    key
}

/// Every failed check of `graded`, with its causes.
fn failed_causes<'a>(graded: &[&'a StudentGrade]) -> BTreeMap<&'a str, Causes<'a>> {
    let mut failed: BTreeMap<&str, Causes> = BTreeMap::new();
    for g in graded {
        for c in g.checks.iter().filter(|c| c.status == "FAILED") {
            let cause = c.cause.as_deref().unwrap_or("(no cause named)");
            let group =
                failed.entry(&c.id).or_default().entry(cause_key(cause)).or_insert((cause, Vec::new()));
            group.1.push(&g.student);
        }
    }
    failed
}

/// A check that sets students apart: its id, the cause, and whether it is a picture's cluster.
type Apart<'a> = (&'a str, &'a str, bool);

/// At most this many of the class's mistakes at a glance.
const AT_A_GLANCE: usize = 20;

/// The class's mistakes at a glance: every group of students a check sets apart (a cause group;
/// for a picture's check, a cluster of wrong pictures), the groups of the same students joined:
/// students who fail those checks together, each for one cause or with one picture, likely made
/// one mistake. Groups of two students or more, the largest first; the cause shown is the first
/// function's check's (it names the exercise), else the first picture's.
fn at_a_glance(page: &mut String, failed: &BTreeMap<&str, Causes>, clusters: &[Clusters]) {
    // Per set of students, the checks (by id) and causes that set them apart.
    let mut together: BTreeMap<Vec<&str>, Vec<Apart>> = BTreeMap::new();
    for (check, causes) in failed {
        if let Some(pictures) = clusters.iter().find(|c| c.check == *check) {
            for cluster in &pictures.clusters {
                let mut students = cluster.students.clone();
                students.sort_unstable();
                together.entry(students).or_default().push((check, cluster.cause.0, true));
            }
        } else {
            for (cause, students) in causes.values() {
                let mut students = students.clone();
                students.sort_unstable();
                together.entry(students).or_default().push((check, cause, false));
            }
        }
    }
    let mut mistakes: Vec<(Vec<&str>, Vec<Apart>)> =
        together.into_iter().filter(|(students, _)| students.len() >= 2).collect();
    if mistakes.is_empty() {
        return;
    }
    mistakes.sort_by(|a, b| b.0.len().cmp(&a.0.len()).then(a.1[0].0.cmp(b.1[0].0)));
    let _ = write!(
        page,
        "<h2 id=\"mistakes\">The class's mistakes at a glance</h2><p>Students who fail the same checks \
         together, each check for one cause or with one wrong picture: likely one mistake each. The \
         most students first{}.</p><table class=\"mistakes\"><tr><th>students</th><th>fail together\
         </th><th>likely cause</th><th>who</th></tr>",
        if mistakes.len() > AT_A_GLANCE {
            format!("; the first {AT_A_GLANCE} of {}", mistakes.len())
        } else {
            String::new()
        }
    );
    for (students, checks) in mistakes.iter().take(AT_A_GLANCE) {
        let cause = checks.iter().find(|c| !c.2).unwrap_or(&checks[0]).1;
        let ids: Vec<&str> = checks.iter().map(|c| c.0).collect();
        let _ = write!(
            page,
            "<tr data-checks=\"{}\" data-students=\"{}\"><td class=\"n\">{}</td><td class=\"id\">{}</td>\
             <td>{}</td><td>{}</td></tr>",
            escape(&ids.join("\n")),
            escape(&students.join("\n")),
            students.len(),
            ids.iter().map(|id| escape(id)).collect::<Vec<_>>().join("<br>"),
            escape(cause),
            escape(&students.join(", "))
        );
    }
    page.push_str("</table>");
}

/// The checks failed by the most students, most first, each with its causes and, for a
/// picture's check, its clusters of wrong pictures.
fn causes(page: &mut String, graded: usize, failed: &BTreeMap<&str, Causes>, clusters: &[Clusters]) {
    let mut checks: Vec<(&str, usize, &Causes)> =
        failed.iter().map(|(id, causes)| (*id, causes.values().map(|c| c.1.len()).sum(), causes)).collect();
    checks.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(b.0)));
    page.push_str("<h2 id=\"causes\">What the class gets wrong</h2>");
    if checks.is_empty() {
        page.push_str("<p>No check failed.</p>");
        return;
    }
    page.push_str(
        "<table class=\"causes\"><tr><th>check</th><th>students</th><th>likely cause</th><th>who</th></tr>",
    );
    for (id, count, causes) in checks {
        let head = |rows: usize| {
            format!(
                "<td rowspan=\"{rows}\" class=\"id\">{}</td><td rowspan=\"{rows}\" class=\"n\">{count} of {graded}</td>",
                escape(id)
            )
        };
        // A picture's check: its clusters of wrong pictures, each with the cause its check gave
        // most often in it.
        if let Some(clusters) = clusters.iter().find(|c| c.check == id) {
            let _ = write!(
                page,
                "<tr data-check=\"{}\">{}<td colspan=\"2\">{} wrong picture{}, below</td></tr>",
                escape(id),
                head(1),
                clusters.clusters.len(),
                if clusters.clusters.len() == 1 { "" } else { "s" }
            );
            pictures(page, clusters);
            continue;
        }
        let mut causes: Vec<&(&str, Vec<&str>)> = causes.values().collect();
        causes.sort_by(|a, b| b.1.len().cmp(&a.1.len()).then(a.0.cmp(b.0)));
        for (i, (cause, students)) in causes.iter().enumerate() {
            let head = if i == 0 { head(causes.len()) } else { String::new() };
            let _ = write!(
                page,
                "<tr data-check=\"{}\" data-cause=\"{}\" data-students=\"{}\">{head}\
                 <td>{} <span class=\"n\">({})</span></td><td>{}</td></tr>",
                escape(id),
                escape(cause),
                escape(&students.join("\n")),
                escape(cause),
                students.len(),
                escape(&students.join(", "))
            );
        }
    }
    page.push_str("</table>");
}

/// A picture's check's row of clusters: the expected picture, then each cluster's first picture
/// and its difference, its size, students and most given cause.
fn pictures(page: &mut String, Clusters { check, clusters, apart }: &Clusters) {
    let expected = format!("{PICTURES}/{}/expected.png", check.replace('/', "-"));
    // The distances, as a share of pixels a viewer tells apart at a glance.
    let spread = clusters.iter().map(|c| c.spread).fold(0.0, f64::max);
    let apart = apart.map_or_else(String::new, |d| format!(", the nearest two {:.2} % apart", 100.0 * d));
    let _ = write!(
        page,
        "<tr class=\"clusters\" data-check=\"{}\"><td colspan=\"4\"><p>{} wrong picture{} of {} \
         <span class=\"n\">(pictures in a cluster at most {:.2} % of pixels apart{apart})</span>:</p>\
         <figure><img src=\"{}\" alt=\"expected\"><figcaption>expected</figcaption></figure>",
        escape(check),
        clusters.len(),
        if clusters.len() == 1 { "" } else { "s" },
        escape(check),
        100.0 * spread,
        href(&expected)
    );
    for cluster in clusters {
        let (cause, said) = cluster.cause;
        let _ = write!(
            page,
            "<figure class=\"cluster\" data-students=\"{}\">\
             <img src=\"{}\" alt=\"{}'s picture\"><img src=\"{}\" alt=\"its difference from the expected (FLIP)\">\
             <figcaption><b>{} student{}</b>: {}<br>likely: {} <span class=\"n\">({said} of {})</span></figcaption></figure>",
            escape(&cluster.students.join("\n")),
            href(&format!("{}/yours.png", cluster.picture)),
            escape(cluster.students[0]),
            href(&format!("{}/diff.png", cluster.picture)),
            cluster.students.len(),
            if cluster.students.len() == 1 { "" } else { "s" },
            escape(&cluster.students.join(", ")),
            escape(cause),
            cluster.students.len()
        );
    }
    page.push_str("</td></tr>");
}

/// A relative path as a URL's path: every byte but letters, digits and `/-_.~` percent-encoded
/// (a student's folder may be named anything), then escaped for an attribute.
fn href(path: &str) -> String {
    let mut url = String::new();
    for byte in path.bytes() {
        if byte.is_ascii_alphanumeric() || b"/-_.~".contains(&byte) {
            url.push(byte as char);
        } else {
            let _ = write!(url, "%{byte:02X}");
        }
    }
    escape(&url)
}

/// Per exercise, in course order, how many students' checks of it ended each way: an exercise
/// is passed when all its checks pass, and otherwise counts as its first check that did not.
fn heat_map(page: &mut String, graded: &[&StudentGrade]) {
    let mut order: Vec<&str> = Vec::new();
    let mut counts: BTreeMap<&str, [usize; 5]> = BTreeMap::new();
    for g in graded {
        let mut by_exercise: BTreeMap<&str, usize> = BTreeMap::new();
        for c in &g.checks {
            if !order.contains(&c.exercise.as_str()) {
                order.push(&c.exercise);
            }
            let worst = by_exercise.entry(&c.exercise).or_insert(0);
            if *worst == 0 {
                *worst = column(&c.status);
            }
        }
        for (exercise, col) in by_exercise {
            counts.entry(exercise).or_default()[col] += 1;
        }
    }
    page.push_str(
        "<h2 id=\"exercises\">Exercise by exercise</h2><table class=\"heat\"><tr><th>exercise</th>",
    );
    for (name, _) in COLUMNS {
        let _ = write!(page, "<th>{name}</th>");
    }
    page.push_str("</tr>");
    let total = graded.len().max(1);
    for exercise in order {
        let row = counts.get(exercise).copied().unwrap_or_default();
        let _ = write!(
            page,
            "<tr data-exercise=\"{}\"><td class=\"id\">{}</td>",
            escape(exercise),
            escape(exercise)
        );
        for (n, (_, colour)) in row.iter().zip(COLUMNS) {
            // The cell's shade is its share of the class: a glance finds the exercises to revisit.
            let alpha = (*n as f64 / total as f64 * 0.85 + if *n > 0 { 0.15 } else { 0.0 }).min(1.0);
            let _ = write!(
                page,
                "<td class=\"n\" style=\"background: color-mix(in srgb, {colour} {:.0}%, white)\">{n}</td>",
                alpha * 100.0
            );
        }
        page.push_str("</tr>");
    }
    page.push_str("</table>");
}

const STYLE: &str = "body{font:15px/1.4 system-ui,sans-serif;margin:2em;color:#222}\
table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:.25em .6em;vertical-align:top}\
th{background:#f4f4f4;text-align:left}.id{font-family:ui-monospace,monospace;white-space:nowrap}\
.n{text-align:right;font-variant-numeric:tabular-nums}\
tr.clusters figure{display:inline-block;margin:.3em .8em .3em 0;vertical-align:top;max-width:26em}\
tr.clusters img{width:12em;image-rendering:pixelated;margin-right:.2em}\
tr.clusters figure:first-of-type img{border:2px solid #2e7d32}figcaption{font-size:90%}";

#[cfg(test)]
mod tests {
    use super::*;
    use crate::class::CheckGrade;

    fn check(id: &str, status: &str, cause: Option<&str>) -> CheckGrade {
        let exercise = id.rsplit_once('/').map_or(id, |(e, _)| e).to_owned();
        let points = u32::from(status == "passed");
        let cause = cause.map(str::to_owned);
        CheckGrade {
            id: id.into(),
            exercise,
            points,
            max_points: 1,
            status: status.into(),
            cause,
            picture: None,
        }
    }

    fn student(name: &str, checks: Vec<CheckGrade>) -> StudentGrade {
        StudentGrade::new(name, checks)
    }

    #[test]
    fn causes_that_differ_in_their_numbers_only_are_one() {
        let a =
            "expected normal (-0.095, 0.995, 0.007) at pixel (59, 52), got (0.276, 0.5, -1) (2124 pixels)";
        let b = "expected normal (0.1, −0.9, 7) at pixel (3, 152), got (1.5, 0, 0) (7 pixels)";
        assert_eq!(cause_key(a), cause_key(b));
        assert_eq!(cause_key(a), "expected normal (#, #, #) at pixel (#, #), got (#, #, #) (# pixels)");
        assert_ne!(cause_key("keep the nearest hit"), cause_key("keep the farthest hit"));
    }

    #[test]
    fn the_most_failed_check_comes_first_with_its_causes_and_students() {
        let far = Some("the far root");
        let grades = [
            student(
                "ann",
                vec![check("02/sphere/unit", "FAILED", far), check("02/plane/unit", "passed", None)],
            ),
            student(
                "ben",
                vec![check("02/sphere/unit", "FAILED", far), check("02/plane/unit", "FAILED", Some("n·d"))],
            ),
            student(
                "cy <3",
                vec![
                    check("02/sphere/unit", "FAILED", Some("t < 0")),
                    check("02/plane/unit", "not started", None),
                ],
            ),
        ];
        let page = html(&grades, Path::new("nowhere"));
        let sphere = page.find("data-check=\"02/sphere/unit\"").unwrap();
        let plane = page.find("data-check=\"02/plane/unit\"").unwrap();
        assert!(sphere < plane, "the check three students fail comes before the one one student fails");
        assert!(page.contains("3 of 3"), "{page}");
        assert!(page.contains("the far root <span class=\"n\">(2)</span></td><td>ann, ben</td>"), "{page}");
        assert!(page.contains("data-cause=\"the far root\" data-students=\"ann\nben\""), "{page}");
        assert!(page.contains("cy &lt;3"), "names are escaped");
        // At a glance, first: ann and ben fail 02/sphere/unit for one cause (ben's plane and cy's
        // sphere are one student's each).
        let glance = page.find("<tr data-checks=\"02/sphere/unit\" data-students=\"ann\nben\">").unwrap();
        assert!(glance < sphere, "{page}");
        assert_eq!(page.matches("<tr data-checks=").count(), 1, "{page}");
        // The heat map: 02/plane passed by one, failed by one, not started by one.
        let row = &page[page.find("data-exercise=\"02/plane\"").unwrap()..];
        let cells: Vec<&str> =
            row.split("white)\">").skip(1).take(5).map(|c| c.split('<').next().unwrap()).collect();
        assert_eq!(cells, ["1", "1", "1", "0", "0"], "{row}");
    }
}
