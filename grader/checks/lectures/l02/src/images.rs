//! The checks of `images.rs`: the object-id, depth and normal images, each on a scene the check
//! answers itself, so a wrong picture is the image function's and no intersection's.

use super::common::*;
use l01_transforms::Camera;
use l02_ray_casting::id_color;
use raylab::stats::Counter;
use raylab::{BLACK, Color, Image};
use std::sync::Mutex;

/// Width and height of the images the checks ask for: small, not square, odd, so that a
/// swapped x and y or a transposed image shows.
const SIZE: (u32, u32) = (7, 5);

/// The scene whose every closest hit the check knows without intersecting anything: a
/// function of the ray's direction. Above a slanted horizon nothing; below it, five objects in
/// bands of the direction's x, at a depth and with a normal of their own. A hit is given only
/// inside the range asked. Every question asked is recorded.
#[derive(Default)]
struct Answering {
    asked: Mutex<Vec<(Ray, Interval)>>,
}

/// The closest hit of `ray` in the answering scene, inside `range`.
fn answer(ray: &Ray, range: Interval) -> Option<Hit> {
    let d = ray.dir.normalize();
    if d.y > 0.3 * d.x + 0.05 {
        return None;
    }
    let object = (d.x * 4.0 + 2.5).floor().clamp(0.0, 4.0) as usize;
    let t = 2.0 + object as Float + d.y.abs();
    let outward = Vec3::new(object as Float - 2.0, 1.0, 0.5 + d.x);
    let hit = Hit { object, ..Hit::new(ray, t, outward) };
    range.contains(t).then_some(hit)
}

impl Intersector for Answering {
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        if let Ok(mut asked) = self.asked.lock() {
            asked.push((*ray, range));
        }
        answer(ray, range)
    }
}

/// What the student's image function made of the answering scene, with what it asked and counted,
/// and the camera's ray and range for each pixel (lecture 01's, the student's too: the expected
/// picture is built from them, so a camera's slip is not this check's).
#[derive(serde::Serialize, serde::Deserialize)]
struct Made {
    image: Image,
    asked: Vec<(Ray, Interval)>,
    primary: u64,
    rays: Vec<Ray>,
    range: Interval,
}

type ImageFn = fn(&Camera, &Answering, u32, u32) -> Image;

fn made(image_fn: ImageFn) -> Made {
    let (w, h) = SIZE;
    crate::judge::student(|| {
        let camera = Camera::from_scene(
            &raylab::scene::Camera::Perspective {
                eye: Vec3::new(0.5, 1.0, 4.0),
                at: Vec3::new(0.0, 0.0, 0.0),
                up: Vec3::Y,
                fovy: 1.0,
            },
            w,
            h,
        )
        .expect("a valid camera");
        let scene = Answering::default();
        let (image, stats) = raylab::stats::measure(|| image_fn(&camera, &scene, w, h));
        let rays =
            (0..h).flat_map(|y| (0..w).map(move |x| (x, y))).map(|(x, y)| camera.pixel_ray(x, y, w, h));
        Made {
            image,
            asked: scene.asked.into_inner().unwrap_or_default(),
            primary: stats.get(Counter::PrimaryRays),
            rays: rays.collect(),
            range: camera.t_range(),
        }
    })
}

/// The checks all three images share: the size, one question per pixel centre in the camera's
/// range, one primary ray counted per pixel; then each pixel against `expected` of its hit.
fn image_cases(
    image_fn: ImageFn,
    what: &str,
    expected: fn(Option<Hit>) -> Color,
    cause: &str,
) -> CheckResult {
    let (w, h) = SIZE;
    let m = made(image_fn);
    let case = format!("{what}({w}×{h}) of a scene the check answers itself (five objects under a horizon)");
    ensure(
        (m.image.width, m.image.height) == SIZE,
        &case,
        format!("a {w}×{h} image"),
        format!("{}×{}", m.image.width, m.image.height),
        "an image of width × height: render_image(width, height, …)",
    )?;
    ensure(
        m.asked.len() == m.rays.len(),
        &case,
        format!("{} closest-hit questions, one per pixel", m.rays.len()),
        m.asked.len(),
        "one primary ray per pixel, and one closest_hit for it",
    )?;
    if let Some((r, range)) = m.asked.iter().find(|(_, range)| *range != m.range) {
        return Err(fail(
            &case,
            format!("every ray asked in the camera's range ({}, {})", num(m.range.min), num(m.range.max)),
            format!(
                "({}, {}) for the ray from {} along {}",
                num(range.min),
                num(range.max),
                vec3(r.origin),
                vec3(r.dir)
            ),
            "look for the closest hit in camera.t_range()",
        ));
    }
    if let Some((r, _)) = m.asked.iter().find(|(r, _)| !m.rays.contains(r)) {
        return Err(fail(
            &case,
            "each pixel's ray, camera.pixel_ray(x, y, width, height)",
            format!("a ray from {} along {}, no pixel's", vec3(r.origin), vec3(r.dir)),
            "one ray per pixel centre: camera.pixel_ray(x, y, width, height), x across and y down",
        ));
    }
    ensure(
        m.primary == u64::from(w * h),
        &case,
        format!("{} PrimaryRays counted", w * h),
        m.primary,
        "count one Counter::PrimaryRays per pixel: count(Counter::PrimaryRays)",
    )?;
    for (i, r) in m.rays.iter().enumerate() {
        let (x, y) = (i as u32 % w, i as u32 / w);
        let hit = answer(r, m.range);
        let (want, got) = (expected(hit), m.image.get(x, y));
        if want != got {
            let shown = maybe(&hit, |h| {
                format!("object {} at t = {}, normal {}", h.object, num(h.t), vec3(h.normal))
            });
            return Err(fail(
                format!("{case}: pixel ({x}, {y}), whose ray hits {shown}"),
                format!("({:?}, {:?}, {:?})", want.x, want.y, want.z),
                format!("({:?}, {:?}, {:?})", got.x, got.y, got.z),
                cause,
            ));
        }
    }
    Ok(format!("{} pixels, {} hit", w * h, m.rays.iter().filter(|r| answer(r, m.range).is_some()).count()))
}

pub(super) fn object_id_cases() -> CheckResult {
    image_cases(
        object_id_image,
        "object_id_image",
        |hit| id_color(hit.map(|h| h.object)),
        "each pixel is id_color of the closest hit's object index (hit.object), black (id_color(None)) where \
         nothing is hit",
    )
}

pub(super) fn depth_cases() -> CheckResult {
    image_cases(
        depth_image,
        "depth_image",
        |hit| hit.map_or(BLACK, |h| Color::splat(h.t)),
        "each pixel is the closest hit's t in all three channels (Color::splat(hit.t)), black where nothing \
         is hit",
    )
}

pub(super) fn normal_cases() -> CheckResult {
    image_cases(
        normal_image,
        "normal_image",
        |hit| hit.map_or(BLACK, |h| h.normal),
        "each pixel is the closest hit's normal as it comes (facing the ray, raw x, y, z in r, g, b), black \
         where nothing is hit",
    )
}

// The student's image functions, each value taken through `judge::student` with the camera's
// rays (`made`): these are called inside that value, not on their own.
fn object_id_image(camera: &Camera, scene: &Answering, w: u32, h: u32) -> Image {
    l02_ray_casting::object_id_image(camera, scene, w, h)
}
fn depth_image(camera: &Camera, scene: &Answering, w: u32, h: u32) -> Image {
    l02_ray_casting::depth_image(camera, scene, w, h)
}
fn normal_image(camera: &Camera, scene: &Answering, w: u32, h: u32) -> Image {
    l02_ray_casting::normal_image(camera, scene, w, h)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    #[test]
    fn the_answering_scene_has_misses_and_every_object() {
        let (w, h) = SIZE;
        let m = made(l02_ray_casting::object_id_image);
        let hits: Vec<Option<Hit>> = m.rays.iter().map(|r| answer(r, m.range)).collect();
        assert!(hits.iter().any(Option::is_none), "no miss in {w}×{h}");
        for object in 0..5 {
            assert!(hits.iter().flatten().any(|h| h.object == object), "object {object} is never hit");
        }
    }

    #[test]
    fn planted_image_mistakes_are_caught() {
        fn transposed(c: &Camera, s: &Answering, w: u32, h: u32) -> Image {
            let image = l02_ray_casting::object_id_image(c, s, h, w);
            Image { width: w, height: h, pixels: image.pixels }
        }
        caught(image_cases(transposed, "object_id_image", |hit| id_color(hit.map(|h| h.object)), ""), "");
        fn positive(c: &Camera, s: &Answering, w: u32, h: u32) -> Image {
            raylab::render::render_image(w, h, |x, y| {
                raylab::stats::count(Counter::PrimaryRays);
                let hit = s.closest_hit(&c.pixel_ray(x, y, w, h), Interval::new(-1.0, Float::INFINITY));
                id_color(hit.map(|h| h.object))
            })
            .0
        }
        caught(object_id_cases_with(positive), "camera.t_range()");
        fn uncounted(c: &Camera, s: &Answering, w: u32, h: u32) -> Image {
            raylab::render::render_image(w, h, |x, y| {
                id_color(s.closest_hit(&c.pixel_ray(x, y, w, h), c.t_range()).map(|h| h.object))
            })
            .0
        }
        caught(object_id_cases_with(uncounted), "PrimaryRays");
        fn distance_from_origin(c: &Camera, s: &Answering, w: u32, h: u32) -> Image {
            raylab::render::render_image(w, h, |x, y| {
                raylab::stats::count(Counter::PrimaryRays);
                match s.closest_hit(&c.pixel_ray(x, y, w, h), c.t_range()) {
                    Some(hit) => Color::splat(hit.point.length()),
                    None => BLACK,
                }
            })
            .0
        }
        caught(
            image_cases(
                distance_from_origin,
                "depth_image",
                |hit| hit.map_or(BLACK, |h| Color::splat(h.t)),
                "t in",
            ),
            "t in",
        );
        fn white_background(c: &Camera, s: &Answering, w: u32, h: u32) -> Image {
            raylab::render::render_image(w, h, |x, y| {
                raylab::stats::count(Counter::PrimaryRays);
                s.closest_hit(&c.pixel_ray(x, y, w, h), c.t_range()).map_or(Color::ONE, |h| h.normal)
            })
            .0
        }
        caught(
            image_cases(
                white_background,
                "normal_image",
                |hit| hit.map_or(BLACK, |h| h.normal),
                "black where",
            ),
            "black where",
        );
        assert!(object_id_cases().is_ok(), "{:?}", object_id_cases());
        assert!(depth_cases().is_ok(), "{:?}", depth_cases());
        assert!(normal_cases().is_ok(), "{:?}", normal_cases());
    }

    fn object_id_cases_with(f: ImageFn) -> CheckResult {
        image_cases(f, "object_id_image", |hit| id_color(hit.map(|h| h.object)), "id_color")
    }
}
