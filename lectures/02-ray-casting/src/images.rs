//! Ray casting: one primary ray per pixel centre, and what it hits shown as
//! an image. The object-id image is the slides' "scene signature"; the depth
//! and normal images show the geometry that shading will use. The grader
//! compares these three first when a rendered image differs, to say which
//! stage went wrong.

use l01_transforms::Camera;
use raylab::render::render_image;
use raylab::stats::{Counter, count};
use raylab::{BLACK, Color, Float, Image, Intersector};

/// A distinct colour for each object index, the same on every run; `None`
/// (nothing hit) is black.
///
/// Hues step around the colour wheel by the golden ratio (0.618…), so
/// consecutive indices land far apart and no two of the first hundreds
/// coincide; the brightness cycles over three levels to separate the few
/// that land close. No index is black.
pub fn id_color(id: Option<usize>) -> Color {
    let Some(id) = id else {
        return BLACK;
    };
    let hue = ((id as f64 + 0.5) * 0.618_033_988_749_894_9).fract() as Float;
    let value = [0.95, 0.7, 0.45][id % 3];
    hsv_to_rgb(hue, 0.75, value)
}

/// HSV (hue in [0, 1), saturation and value in [0, 1]) to RGB: the hexcone
/// model, six linear pieces around the wheel.
fn hsv_to_rgb(hue: Float, saturation: Float, value: Float) -> Color {
    let sector = hue * 6.0;
    let i = sector.floor();
    let f = sector - i;
    let p = value * (1.0 - saturation);
    let q = value * (1.0 - saturation * f);
    let t = value * (1.0 - saturation * (1.0 - f));
    match i as u32 % 6 {
        0 => Color::new(value, t, p),
        1 => Color::new(q, value, p),
        2 => Color::new(p, value, t),
        3 => Color::new(p, q, value),
        4 => Color::new(t, p, value),
        _ => Color::new(value, p, q),
    }
}

/// The scene signature: each pixel shows [`id_color`] of the object its
/// primary ray hits first, black where it hits nothing.
///
/// One ray per pixel centre, `camera.pixel_ray(x, y, width, height)`, looking
/// for the closest hit in `camera.t_range()`; counts one
/// [`Counter::PrimaryRays`] per pixel. Book: §2.7 The scene signature.
pub fn object_id_image(camera: &Camera, scene: &impl Intersector, width: u32, height: u32) -> Image {
    // SOLUTION BEGIN
    let (image, _stats) = render_image(width, height, |x, y| {
        count(Counter::PrimaryRays);
        let ray = camera.pixel_ray(x, y, width, height);
        id_color(scene.closest_hit(&ray, camera.t_range()).map(|hit| hit.object))
    });
    image
    // SOLUTION END
}

/// The depth image: the hit's t in all three channels, 0 where nothing is hit.
///
/// Primary rays have unit directions, so t is the distance from the ray's
/// origin: from the eye for a perspective camera, from the image plane for an
/// orthographic one. Same rays and counts as [`object_id_image`].
/// Book: §2.7 The scene signature.
pub fn depth_image(camera: &Camera, scene: &impl Intersector, width: u32, height: u32) -> Image {
    // SOLUTION BEGIN
    let (image, _stats) = render_image(width, height, |x, y| {
        count(Counter::PrimaryRays);
        let ray = camera.pixel_ray(x, y, width, height);
        match scene.closest_hit(&ray, camera.t_range()) {
            Some(hit) => Color::splat(hit.t),
            None => BLACK,
        }
    });
    image
    // SOLUTION END
}

/// The normal image: the hit's unit normal, facing the camera, as raw
/// (x, y, z) components in (r, g, b) — not remapped to [0, 1], so negative
/// components show as black in a PNG; 0 where nothing is hit. Same rays and
/// counts as [`object_id_image`]. Book: §2.7 The scene signature.
pub fn normal_image(camera: &Camera, scene: &impl Intersector, width: u32, height: u32) -> Image {
    // SOLUTION BEGIN
    let (image, _stats) = render_image(width, height, |x, y| {
        count(Counter::PrimaryRays);
        let ray = camera.pixel_ray(x, y, width, height);
        match scene.closest_hit(&ray, camera.t_range()) {
            Some(hit) => hit.normal,
            None => BLACK,
        }
    });
    image
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::group::Group;
    use raylab::color::to_srgb8;
    use raylab::scene::{self, Object, Shape};
    use raylab::{Hit, Interval, Ray, Vec3};
    use std::sync::atomic::{AtomicUsize, Ordering};

    const EPS: Float = Float::EPSILON;

    fn sphere(center: Vec3, radius: Float) -> Object {
        Object { shape: Shape::Sphere { center, radius }, material: 0, transform: None }
    }

    /// A 5 × 5 orthographic view of a window 5 units square from (0, 0, 5) down −z:
    /// pixel centres start at x, y ∈ {−2, −1, 0, 1, 2} (screen coordinates
    /// ±0.8, ±0.4, 0 times the half-height 2.5), row 0 at the top (y = 2).
    fn ortho_5x5() -> Camera {
        let desc = scene::Camera::Orthographic {
            eye: Vec3::new(0.0, 0.0, 5.0),
            at: Vec3::ZERO,
            up: Vec3::Y,
            height: 5.0,
        };
        Camera::from_scene(&desc, 5, 5).expect("a valid camera")
    }

    #[test]
    fn single_sphere_in_a_5x5_orthographic_view() {
        // A sphere of radius 1.5 at the origin: the ray from (X, Y, 5) along −z hits when
        // X² + Y² < 2.25, i.e. the centre 3 × 3 pixels (corners: 2 < 2.25; X = ±2: 4 > 2.25),
        // at t = 5 − √(2.25 − X² − Y²) with normal (X, Y, √(2.25 − X² − Y²))/1.5:
        //   centre (0, 0): t = 3.5, n = (0, 0, 1);
        //   edges (±1, 0), (0, ±1): t = 5 − √1.25 ≈ 3.881966, n = (±1, 0, √1.25)/1.5 …;
        //   corners (±1, ±1): t = 5 − 0.5 = 4.5, n = (±2/3, ±2/3, 1/3).
        // Tolerance: the pixel origins carry a few roundings of numbers ≤ 5 (screen
        // coordinates, the look-at frame); t and n move at most 2× as much (∂t/∂X =
        // X/√(2.25 − X² − Y²) ≤ 2): allow 32ε·5.
        let objects = [sphere(Vec3::ZERO, 1.5)];
        let group = Group::new(&objects);
        let camera = ortho_5x5();
        let ids = object_id_image(&camera, &group, 5, 5);
        let depth = depth_image(&camera, &group, 5, 5);
        let normals = normal_image(&camera, &group, 5, 5);
        let tolerance = 32.0 * EPS * 5.0;
        for row in 0..5u32 {
            for column in 0..5u32 {
                let (x, y) = (column as Float - 2.0, 2.0 - row as Float);
                let what = format!("pixel ({column}, {row}) at ({x}, {y})");
                let h2 = 2.25 - x * x - y * y;
                if h2 > 0.0 {
                    assert_eq!(ids.get(column, row), id_color(Some(0)), "{what}");
                    let t = 5.0 - h2.sqrt();
                    assert!(
                        (depth.get(column, row) - Color::splat(t)).abs().max_element() <= tolerance,
                        "{what}"
                    );
                    let n = Vec3::new(x, y, h2.sqrt()) / 1.5;
                    let got = normals.get(column, row);
                    assert!((got - n).abs().max_element() <= tolerance, "{what}: normal {got} vs {n}");
                } else {
                    assert_eq!(ids.get(column, row), BLACK, "{what}");
                    assert_eq!(depth.get(column, row), BLACK, "{what}");
                    assert_eq!(normals.get(column, row), BLACK, "{what}");
                }
            }
        }
        // The three values derived above, spelled out for the centre and a corner.
        assert!((depth.get(2, 2).x - 3.5).abs() <= tolerance);
        assert!((depth.get(1, 1).x - 4.5).abs() <= tolerance);
        let corner = Vec3::new(-2.0, 2.0, 1.0) / 3.0;
        assert!((normals.get(1, 1) - corner).abs().max_element() <= tolerance);
    }

    #[test]
    fn nearer_object_wins_and_the_background_plane_shows_its_id() {
        // The same view with a plane z = −1 facing +z behind the sphere: the 16 border
        // pixels now hit the plane (object 1) at t = 6 with normal +z, exactly
        // (a ray along −z from z = 5 to z = −1).
        let objects = [
            sphere(Vec3::ZERO, 1.5),
            Object { shape: Shape::Plane { normal: Vec3::Z, offset: -1.0 }, material: 0, transform: None },
        ];
        let group = Group::new(&objects);
        let camera = ortho_5x5();
        let ids = object_id_image(&camera, &group, 5, 5);
        let depth = depth_image(&camera, &group, 5, 5);
        let normals = normal_image(&camera, &group, 5, 5);
        for (column, row) in [(0, 0), (4, 0), (0, 2), (2, 4), (4, 4)] {
            assert_eq!(ids.get(column, row), id_color(Some(1)), "({column}, {row})");
            assert_eq!(depth.get(column, row), Color::splat(6.0), "({column}, {row})");
            assert_eq!(normals.get(column, row), Vec3::Z, "({column}, {row})");
        }
        assert_eq!(ids.get(2, 2), id_color(Some(0)));
        assert!(depth.get(2, 2).x < 6.0, "the sphere is in front of the plane");
    }

    #[test]
    fn perspective_depth_is_the_distance_from_the_eye() {
        // Depth along a unit primary ray is the distance to the hit: eye + depth·dir must
        // lie on the sphere, |p − c| = r up to a few roundings of |p| ≈ 5 (allow 32ε·5).
        // The centre pixel of an odd-sized image looks straight at the sphere: depth 5 − 1 = 4.
        let objects = [sphere(Vec3::ZERO, 1.0)];
        let group = Group::new(&objects);
        let eye = Vec3::new(0.0, 0.0, 5.0);
        let desc =
            scene::Camera::Perspective { eye, at: Vec3::ZERO, up: Vec3::Y, fovy: raylab::radians(30.0) };
        let camera = Camera::from_scene(&desc, 9, 9).expect("a valid camera");
        let depth = depth_image(&camera, &group, 9, 9);
        let tolerance = 32.0 * EPS * 5.0;
        assert!((depth.get(4, 4).x - 4.0).abs() <= tolerance, "centre depth {}", depth.get(4, 4));
        let mut hits = 0;
        for row in 0..9 {
            for column in 0..9 {
                let d = depth.get(column, row).x;
                if d > 0.0 {
                    hits += 1;
                    let p = eye + d * camera.pixel_ray(column, row, 9, 9).dir;
                    assert!((p.length() - 1.0).abs() <= tolerance, "({column}, {row}): |p| = {}", p.length());
                }
            }
        }
        // The sphere's disc (half-angle asin(1/5), tan = 0.204) covers a fraction
        // π·0.204²/(2·tan 15°)² ≈ 0.46 of the square view: about 37 of the 81 pixels.
        assert!((30..=45).contains(&hits), "{hits} pixels hit");
    }

    /// An intersector that hits nothing and counts the rays it is asked about.
    struct Counting {
        calls: AtomicUsize,
    }

    impl Intersector for Counting {
        fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
            assert_eq!(range, Interval::POSITIVE, "the camera's t range");
            assert!(ray.dir.is_normalized(), "primary rays are unit");
            self.calls.fetch_add(1, Ordering::Relaxed);
            None
        }
    }

    #[test]
    fn one_primary_ray_per_pixel() {
        let camera = ortho_5x5();
        type ImageFn = fn(&Camera, &Counting, u32, u32) -> Image;
        let images: [(&str, ImageFn); 3] =
            [("id", object_id_image), ("depth", depth_image), ("normal", normal_image)];
        for (name, image_of) in images {
            let scene = Counting { calls: AtomicUsize::new(0) };
            let image = image_of(&camera, &scene, 7, 3);
            assert_eq!((image.width, image.height), (7, 3), "{name}");
            assert_eq!(scene.calls.into_inner(), 21, "{name}: one closest_hit per pixel");
            assert!(image.pixels.iter().all(|&c| c == BLACK), "{name}: nothing hit is black");
        }
    }

    #[test]
    fn id_colors_are_distinct_deterministic_and_never_black() {
        // Compared as the 8-bit sRGB a PNG stores, so distinct means distinct on screen.
        let colors: Vec<[u8; 3]> = (0..64).map(|i| to_srgb8(id_color(Some(i)))).collect();
        for (i, a) in colors.iter().enumerate() {
            assert_ne!(*a, [0, 0, 0], "id {i} is black");
            for (j, b) in colors.iter().enumerate().skip(i + 1) {
                assert_ne!(a, b, "ids {i} and {j} share a colour");
            }
        }
        assert_eq!(id_color(None), BLACK);
        assert_eq!(id_color(Some(5)), id_color(Some(5)));
    }
}
