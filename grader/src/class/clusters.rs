// INSTRUCTOR ONLY: left out of the handout, with the rest of `grader class`.
//! The wrong pictures of a class, grouped: per picture's check, the students whose pictures a
//! viewer could not tell apart form one cluster, shown by one of them.
//!
//! The distance is FLIP's (the perceptual difference the report already shows between expected
//! and yours; nv-flip at its default viewing distance), read as the fraction of pixels whose
//! error a viewer notices at a glance (above [`NOTICED`], the report's threshold). Two pictures
//! are the same wrong picture when at most [`SAME`] of their pixels are so noticed. Why that
//! size, measured (`scripts/measure-clusters.sh`: each catalogued mistake a picture's check
//! catches, 11 submissions, graded in f32 and again in f64, 64 pictures' checks): the same
//! mistake drawn by other arithmetic (the f32 and the f64 build of one wrong submission) is at
//! most 0.08 % of pixels apart (a few silhouette pixels); two different mistakes' pictures of one
//! scene, at least 2.18 %. 0.5 % sits in the middle of that gap (its geometric mean, 0.42 %,
//! rounded): six times the first, a quarter of the second.
//! Pictures are compared with the clusters' first pictures (a leader clustering, in the
//! students' order): the gap between the two figures makes the order immaterial, and a class of
//! n students with k kinds of wrong picture costs n·k comparisons, not n².

use std::collections::{BTreeMap, HashMap};
use std::path::Path;

use super::StudentGrade;

/// A FLIP error above this is noticed at a glance (FLIP's scale: 0 identical, 1 opposite): the
/// threshold of the report's "pixels over 0.25" (`raylab-checks`' `FLIP_THRESHOLD`).
pub const NOTICED: f32 = 0.25;

/// Two wrong pictures are one when at most this fraction of their pixels differ noticeably.
pub const SAME: f64 = 0.005;

/// The students of one wrong picture.
pub struct Cluster<'a> {
    /// The folder (relative to the class's output) of the picture shown for all: the first
    /// student's `yours.png` and `diff.png` (against the expected).
    pub picture: &'a str,
    pub students: Vec<&'a str>,
    /// The cause the check gave most often in the cluster, and how many times.
    pub cause: (&'a str, usize),
    /// The largest distance of a student's picture from the one shown.
    pub spread: f64,
}

/// A picture's check's clusters.
pub struct Clusters<'a> {
    pub check: &'a str,
    /// The largest first.
    pub clusters: Vec<Cluster<'a>>,
    /// The smallest distance between two clusters' pictures (None for one cluster): how far
    /// apart the wrong pictures the class drew are, beside each cluster's spread.
    pub apart: Option<f64>,
}

/// A failed picture: its student, its folder (relative to the class's output), its check's cause.
type Member<'a> = (&'a str, &'a str, Option<&'a str>);

/// Per picture's check, in the checks' order of `grades`, its clusters. Pictures that cannot be
/// read (removed since) are left out, and said so in `missing`.
pub fn clusters<'a>(out: &Path, grades: &'a [StudentGrade], missing: &mut Vec<String>) -> Vec<Clusters<'a>> {
    let mut order: Vec<&str> = Vec::new();
    let mut failed: HashMap<&str, Vec<Member>> = HashMap::new();
    for grade in grades {
        for check in &grade.checks {
            if let Some(picture) = &check.picture {
                if !order.contains(&check.id.as_str()) {
                    order.push(&check.id);
                }
                let cause = check.cause.as_deref();
                failed.entry(&check.id).or_default().push((&grade.student, picture, cause));
            }
        }
    }
    order
        .into_iter()
        .map(|id| {
            let mut groups: Vec<(image::RgbImage, Vec<Member>, f64)> = Vec::new();
            for (student, picture, cause) in failed.remove(id).unwrap_or_default() {
                let file = out.join(picture).join("yours.png");
                let Ok(yours) = image::open(&file).map(|i| i.to_rgb8()) else {
                    missing.push(file.display().to_string());
                    continue;
                };
                let nearest = groups
                    .iter_mut()
                    .map(|(first, members, spread)| (distance(first, &yours), members, spread))
                    .find(|(d, _, _)| *d <= SAME);
                match nearest {
                    Some((d, members, spread)) => {
                        members.push((student, picture, cause));
                        *spread = spread.max(d);
                    }
                    None => groups.push((yours, vec![(student, picture, cause)], 0.0)),
                }
            }
            let apart = groups
                .iter()
                .enumerate()
                .flat_map(|(i, a)| groups[i + 1..].iter().map(move |b| distance(&a.0, &b.0)))
                .min_by(f64::total_cmp);
            let mut clusters: Vec<Cluster> = groups
                .into_iter()
                .map(|(_, members, spread)| {
                    // Causes are counted by their words (`report::cause_key`), the first
                    // student's shown.
                    let mut causes: BTreeMap<String, (&str, usize)> = BTreeMap::new();
                    for (_, _, cause) in &members {
                        let cause = cause.unwrap_or("(no cause named)");
                        causes.entry(super::report::cause_key(cause)).or_insert((cause, 0)).1 += 1;
                    }
                    let cause = causes.into_values().max_by(|a, b| a.1.cmp(&b.1).then(b.0.cmp(a.0)));
                    Cluster {
                        picture: members[0].1,
                        students: members.iter().map(|m| m.0).collect(),
                        cause: cause.unwrap_or(("", 0)),
                        spread,
                    }
                })
                .collect();
            clusters.sort_by_key(|c| std::cmp::Reverse(c.students.len()));
            Clusters { check: id, clusters, apart }
        })
        .collect()
}

/// The fraction of pixels whose FLIP error between `a` and `b` is noticed at a glance (1 for
/// pictures of different sizes).
pub fn distance(a: &image::RgbImage, b: &image::RgbImage) -> f64 {
    if a.dimensions() != b.dimensions() {
        return 1.0;
    }
    if a == b {
        return 0.0;
    }
    let (w, h) = a.dimensions();
    let error = nv_flip::flip(
        nv_flip::FlipImageRgb8::with_data(w, h, a.as_raw()),
        nv_flip::FlipImageRgb8::with_data(w, h, b.as_raw()),
        nv_flip::DEFAULT_PIXELS_PER_DEGREE,
    )
    .to_vec();
    error.iter().filter(|&&e| e > NOTICED).count() as f64 / error.len().max(1) as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::class::CheckGrade;

    /// A student whose `02/image/s` failed, with their picture at `students/NAME/pictures/…`.
    fn student(out: &Path, name: &str, picture: Option<&image::RgbImage>) -> StudentGrade {
        let folder = format!("students/{name}/pictures/02-image-s");
        if let Some(picture) = picture {
            std::fs::create_dir_all(out.join(&folder)).unwrap();
            picture.save(out.join(&folder).join("yours.png")).unwrap();
        }
        let check = CheckGrade {
            id: "02/image/s".into(),
            exercise: "02/image".into(),
            points: 0,
            max_points: 3,
            status: "FAILED".into(),
            cause: Some(format!("the geometry differs at pixel ({}, 3)", name.len())),
            picture: Some(folder),
        };
        StudentGrade::new(name, vec![check])
    }

    #[test]
    fn pictures_a_viewer_cannot_tell_apart_are_one_cluster_and_others_are_not() {
        let out = std::env::temp_dir().join(format!("raylab-clusters-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&out);
        // 64×48 = 3072 pixels: a gradient; the same with 2 pixels magenta (FLIP notices each and
        // some of its neighbours: 0.35 %, under SAME); the same with a 20×20 block black (13 %).
        let base = image::RgbImage::from_fn(64, 48, |x, y| image::Rgb([(x * 4) as u8, (y * 5) as u8, 128]));
        let mut few = base.clone();
        for x in 0..2 {
            few.put_pixel(30 * x + 3, 20, image::Rgb([255, 0, 255]));
        }
        let mut block = base.clone();
        for (x, y) in (0..400).map(|i| (20 + i % 20, 10 + i / 20)) {
            block.put_pixel(x, y, image::Rgb([0, 0, 0]));
        }
        let grades = [
            student(&out, "ann", Some(&base)),
            student(&out, "bo", Some(&block)),
            student(&out, "cyd", Some(&few)),
            student(&out, "dee", Some(&base)),
            student(&out, "gone", None),
        ];
        assert!(distance(&base, &few) > 0.0 && distance(&base, &few) <= SAME, "{}", distance(&base, &few));
        assert!(distance(&base, &block) > 10.0 * SAME, "{}", distance(&base, &block));
        let mut missing = Vec::new();
        let found = clusters(&out, &grades, &mut missing);
        assert_eq!(found.len(), 1);
        let Clusters { check, clusters, apart } = &found[0];
        assert_eq!(*check, "02/image/s");
        let students: Vec<&Vec<&str>> = clusters.iter().map(|c| &c.students).collect();
        assert_eq!(students, [&vec!["ann", "cyd", "dee"], &vec!["bo"]], "the largest first");
        assert_eq!(clusters[0].picture, "students/ann/pictures/02-image-s", "shown by its first");
        assert!(clusters[0].spread > 0.0 && clusters[0].spread <= SAME);
        assert_eq!(clusters[1].spread, 0.0);
        assert!(apart.is_some_and(|d| d > 10.0 * SAME), "{apart:?}");
        // The causes differ in their numbers only: one cause, said by all three.
        assert_eq!(clusters[0].cause, ("the geometry differs at pixel (3, 3)", 3));
        assert_eq!(missing.len(), 1, "{missing:?}");
        assert!(missing[0].contains("gone"), "{missing:?}");
        std::fs::remove_dir_all(&out).unwrap();
    }
}
