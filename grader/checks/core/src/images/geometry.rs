//! The geometry images — which object each pixel sees, how far, its normal — drawn with the
//! student's intersections and compared with the snapshots: the `NN/geometry/S` checks, and the
//! first question when a picture differs.

use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use raylab::compare::compare;
use raylab::{Color, Float, Hit, Image, Intersector, Interval, Ray, Scene};

use super::no_snapshot;
use crate::check::{CheckResult, Failure, fail};
use crate::judge;
use crate::scenes::SceneFile;
use crate::stages::{self, GeometryImage};

/// Depth and normal tolerances of the geometry check: a pixel's depth
/// differs when it is off by more than 10⁻³ relative (f32 and f64 agree to
/// ~10⁻⁶ on these scenes; the catalogued mistakes are off by 10 % or more),
/// a normal when a component is off by more than 10⁻³.
const DEPTH_RELATIVE_TOLERANCE: Float = 1e-3;
const NORMAL_TOLERANCE: Float = 1e-3;

/// The three geometry images of `scene` drawn with the intersections of the
/// scene's lecture (its stage's `geometry`; see the module documentation).
pub fn geometry_images(lecture: &str, scene: &Scene) -> Result<[Image; 3], String> {
    let finds = stages::stage(lecture).map_or(stages::Finds::BruteForce, |s| s.geometry);
    let unbuilt = || format!("the intersections for lecture {lecture}'s scenes are not built");
    let (Some(objects), Some(geometry)) = (stages::finder(finds, scene), stages::geometry()) else {
        return Err(unbuilt());
    };
    let objects = objects.as_ref();
    let answers = Answers::default();
    let id = (geometry.image)(scene, GeometryImage::Id, &Recorded { objects, answers: &answers })?;
    let answers = answers.0.into_inner().unwrap_or_default();
    let replayed = || Replayed { objects, answers: &answers, next: AtomicUsize::new(0) };
    Ok([
        id,
        (geometry.image)(scene, GeometryImage::Depth, &replayed())?,
        (geometry.image)(scene, GeometryImage::Normal, &replayed())?,
    ])
}

/// The answers of an intersector, in the order it gave them: the three geometry images cast the
/// same rays in the same order (each pixel's centre, the camera's range), so the first image's
/// answers are the second's and the third's ([`Replayed`]) and the student's intersections are
/// asked once per pixel, not three times. Kept while the first image is drawn ([`Recorded`]).
#[derive(Default)]
struct Answers(Mutex<Vec<([u64; 8], Option<Hit>)>>);

/// A query as the answers hold it: its ray and range, to the bit. (Written out: the checks build
/// at opt-level 0, where an array's `map` cost a fifth of a geometry check of lecture 03.)
fn query(ray: &Ray, range: Interval) -> [u64; 8] {
    let (o, d) = (ray.origin, ray.dir);
    let bits = |x: Float| x.to_bits() as u64;
    [bits(o.x), bits(o.y), bits(o.z), bits(d.x), bits(d.y), bits(d.z), bits(range.min), bits(range.max)]
}

/// `objects`, its answers kept in `answers`.
struct Recorded<'a> {
    objects: &'a dyn Intersector,
    answers: &'a Answers,
}

impl Intersector for Recorded<'_> {
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let answer = self.objects.closest_hit(ray, range);
        if let Ok(mut answers) = self.answers.0.lock() {
            answers.push((query(ray, range), answer));
        }
        answer
    }

    fn any_hit(&self, ray: &Ray, range: Interval) -> bool {
        self.objects.any_hit(ray, range)
    }
}

/// `objects`, answering its n-th query from the recorded n-th answer when the two queries are the
/// same to the bit, and asking `objects` otherwise (an image that casts other rays, or in another
/// order: several threads). The student's intersections are functions of the query alone
/// (`&self`), so each image is what it would be without the replay (its ray counts aside, which
/// no geometry check reads); the images' rays are still cast by the student's lecture 02 code.
struct Replayed<'a> {
    objects: &'a dyn Intersector,
    answers: &'a [([u64; 8], Option<Hit>)],
    next: AtomicUsize,
}

impl Intersector for Replayed<'_> {
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        match self.answers.get(self.next.fetch_add(1, Ordering::Relaxed)) {
            Some((asked, answer)) if *asked == query(ray, range) => *answer,
            _ => self.objects.closest_hit(ray, range),
        }
    }

    fn any_hit(&self, ray: &Ray, range: Interval) -> bool {
        self.objects.any_hit(ray, range)
    }
}

/// The student's three geometry images of `scene` (see [`geometry_images`]), as one value of
/// their code (`judge::student`).
pub(super) fn student_geometry(lecture: &str, scene: &Scene) -> Result<[Image; 3], String> {
    judge::student(|| geometry_images(lecture, scene))
}

/// How the student's three geometry images differ from the snapshots: `None` when
/// they match. The judge's (it holds the snapshots).
pub(super) fn geometry_difference(
    file: &SceneFile,
    scene: &Scene,
    geometry: Result<[Image; 3], String>,
) -> Result<Option<Failure>, String> {
    let [id, depth, normal] = geometry?;
    let load_png = |suffix| Image::load_png(file.snapshot(suffix)).map_err(|e| no_snapshot(file, e));
    let load_exr = |suffix| Image::load_exr(file.snapshot(suffix)).map_err(|e| no_snapshot(file, e));
    let (id_ref, depth_ref, normal_ref) =
        (load_png(".id.png")?, load_exr(".depth.exr")?, load_exr(".normal.exr")?);
    let allowed = file.allowed_fraction();
    let case = format!("{}/{} ({}×{})", file.folder, file.name(), scene.width, scene.height);
    let size = |image: &Image| format!("{}×{}", image.width, image.height);
    for (yours, reference) in [(&id, &id_ref), (&depth, &depth_ref), (&normal, &normal_ref)] {
        if (yours.width, yours.height) != (reference.width, reference.height) {
            return Ok(Some(fail(
                &case,
                format!("a {} image", size(reference)),
                size(yours),
                "one pixel per (x, y) for x < width, y < height, row by row from the top",
            )));
        }
    }
    // The object ids: which object each pixel sees.
    let ids = compare(&id_ref, &id, 0)?;
    if ids.fraction_over() > allowed {
        let (x, y) = ids.first_over.unwrap_or_default();
        return Ok(Some(fail(
            &case,
            format!("object {} at pixel ({x}, {y})", describe_id(&id_ref, x, y, scene)),
            format!(
                "object {} there, and {:.2} % of pixels see another object than the reference",
                describe_id(&id, x, y, scene),
                100.0 * ids.fraction_over()
            ),
            "hit or miss, or which object is nearest, differs: check the intersection tests and that \
             closest_hit keeps the nearest hit (range shrinks to each hit's t)",
        )));
    }
    // The depths: the right objects at the wrong distance.
    let depth_off = differing(&depth_ref, &depth, |e, y| {
        let d = (e.x - y.x).abs();
        d.is_nan() || d > DEPTH_RELATIVE_TOLERANCE * e.x.abs().max(1e-3)
    });
    if depth_off.0 as f64 > allowed * depth.pixels.len() as f64 {
        let (x, y) = depth_off.1;
        return Ok(Some(fail(
            &case,
            format!(
                "depth {:.4} at pixel ({x}, {y}) (± {} %)",
                depth_ref.get(x, y).x,
                100.0 * DEPTH_RELATIVE_TOLERANCE
            ),
            format!("{:.4} ({} pixels off by more than 0.1 %)", depth.get(x, y).x, depth_off.0),
            "the right objects at the wrong distance: t must be in units of the ray's dir (depth = t·|d|), \
             and a transformed object's t must not come from a renormalised object-space direction",
        )));
    }
    // The normals.
    let normal_differs = |e: &Color, y: &Color| {
        let d = (*e - *y).abs().max_element();
        d.is_nan() || d > NORMAL_TOLERANCE
    };
    let normal_off = differing(&normal_ref, &normal, normal_differs);
    if normal_off.0 as f64 > allowed * normal.pixels.len() as f64 {
        let (x, y) = normal_off.1;
        let (e, g) = (normal_ref.get(x, y), normal.get(x, y));
        // Negated where most normals differ, not only at the first: a normal transformed by M
        // instead of (M⁻¹)ᵀ can come out flipped at one pixel and askew at the rest.
        let flipped = normal_ref
            .pixels
            .iter()
            .zip(&normal.pixels)
            .filter(|(e, g)| normal_differs(e, g) && (**e + **g).length() < 1e-2)
            .count();
        let cause = if 2 * flipped > normal_off.0 {
            "your normal is the reference's negated: it must face the ray (Hit::new flips it for hits from inside)"
        } else {
            "unit normals, facing the ray: (p − c)/r for spheres, the face normal for flat shapes, and \
             (M⁻¹)ᵀ n renormalised for transformed objects (not M n)"
        };
        return Ok(Some(fail(
            &case,
            format!("normal ({:.3}, {:.3}, {:.3}) at pixel ({x}, {y})", e.x, e.y, e.z),
            format!("({:.3}, {:.3}, {:.3}) ({} pixels differ)", g.x, g.y, g.z, normal_off.0),
            cause,
        )));
    }
    Ok(None)
}

/// How many pixels `differs` says differ, and the first of them.
fn differing(
    expected: &Image,
    yours: &Image,
    differs: impl Fn(&Color, &Color) -> bool,
) -> (usize, (u32, u32)) {
    let mut count = 0;
    let mut first = None;
    for (i, (e, y)) in expected.pixels.iter().zip(&yours.pixels).enumerate() {
        if differs(e, y) {
            count += 1;
            first.get_or_insert(((i % expected.width as usize) as u32, (i / expected.width as usize) as u32));
        }
    }
    (count, first.unwrap_or_default())
}

/// "#2 (sphere)" for the object whose id colour pixel (x, y) shows, "none" for the background.
fn describe_id(image: &Image, x: u32, y: u32, scene: &Scene) -> String {
    let pixel = raylab::color::to_srgb8(image.get(x, y));
    if pixel == [0, 0, 0] {
        return "none (background)".into();
    }
    match object_at(image, x, y, scene) {
        Some(index) => format!("#{index} ({})", scene.objects[index].shape.kind()),
        None => format!("with colour {pixel:?}"),
    }
}

/// The index of the object pixel (x, y) of an id image shows, by lecture 02's id colours.
pub(super) fn object_at(id: &Image, x: u32, y: u32, scene: &Scene) -> Option<usize> {
    let id_color = stages::geometry()?.id_color;
    let pixel = raylab::color::to_srgb8(id.get(x, y));
    (0..scene.objects.len()).find(|&i| raylab::color::to_srgb8(id_color(i)) == pixel)
}

pub(super) fn check_geometry(file: &SceneFile) -> CheckResult {
    let scene = raylab::scene::load(&file.scene)
        .map_err(|e| fail(&file.folder, "the scene loads", e, "the scene file"))?;
    let geometry = student_geometry(&file.lecture, &scene);
    judge::judge_only(|| match geometry_difference(file, &scene, geometry) {
        Ok(None) => Ok("object ids, depths and normals match".into()),
        Ok(Some(failure)) => Err(failure),
        Err(e) => Err(fail(format!("{}/{}", file.folder, file.name()), "the geometry images", e, "")),
    })
    .unwrap_or_else(|| Ok(String::new()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::Vec3;

    /// An intersector that hits everything at t = the ray's origin's x, and counts its queries.
    #[derive(Default)]
    struct Counting(AtomicUsize);

    impl Intersector for Counting {
        fn closest_hit(&self, ray: &Ray, _range: Interval) -> Option<Hit> {
            self.0.fetch_add(1, Ordering::Relaxed);
            (ray.origin.x > 0.0).then(|| Hit::new(ray, ray.origin.x, Vec3::Y))
        }
    }

    fn rays(n: usize) -> Vec<Ray> {
        (0..n).map(|i| Ray::new(Vec3::new(i as Float - 2.0, 0.0, 0.0), Vec3::Z)).collect()
    }

    #[test]
    fn the_same_queries_in_the_same_order_are_answered_from_the_first_images_answers() {
        let (objects, answers, range) = (Counting::default(), Answers::default(), Interval::new(0.0, 10.0));
        let first: Vec<_> = rays(6)
            .iter()
            .map(|r| Recorded { objects: &objects, answers: &answers }.closest_hit(r, range))
            .collect();
        let answers = answers.0.into_inner().unwrap();
        let replayed = Replayed { objects: &objects, answers: &answers, next: AtomicUsize::new(0) };
        let again: Vec<_> = rays(6).iter().map(|r| replayed.closest_hit(r, range)).collect();
        assert_eq!(again, first);
        assert_eq!(objects.0.load(Ordering::Relaxed), 6, "the second pass asked the intersector again");
    }

    #[test]
    fn other_queries_or_another_order_are_asked_of_the_intersector() {
        let (objects, answers, range) = (Counting::default(), Answers::default(), Interval::new(0.0, 10.0));
        let recorded = Recorded { objects: &objects, answers: &answers };
        for r in &rays(6) {
            let _ = recorded.closest_hit(r, range);
        }
        let answers = answers.0.into_inner().unwrap();
        let replayed = Replayed { objects: &objects, answers: &answers, next: AtomicUsize::new(0) };
        let mut reversed = rays(6);
        reversed.reverse();
        // Each answer is the intersector's own for its ray, not the recorded one at its place.
        for r in &reversed {
            assert_eq!(replayed.closest_hit(r, range), objects.closest_hit(r, range));
        }
        // Another range is another query too.
        let other = Replayed { objects: &objects, answers: &answers, next: AtomicUsize::new(0) };
        let shorter = Interval::new(0.0, 1.0);
        assert_eq!(other.closest_hit(&rays(1)[0], shorter), objects.closest_hit(&rays(1)[0], shorter));
        assert_eq!(objects.0.load(Ordering::Relaxed), 6 + 2 * 6 + 2);
    }
}
