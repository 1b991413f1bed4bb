//! The complete Whitted tracer over an image: one eye ray per pixel centre.

use l01_transforms::Camera;
use l04_quadrics_transforms::BruteForce;
use raylab::render::render_image;
use raylab::stats::{Counter, RayStats, count};
use raylab::{Image, Scene};

use crate::settings::TraceSettings;
use crate::trace::trace;
use crate::world::World;

/// A `width × height` image of `world` seen by `camera`: for each pixel the
/// eye ray through its centre (01's `pixel_ray`), traced by [`trace`] at
/// depth 0 with weight 1, with the ray statistics of the whole render.
///
/// Counts one [`Counter::PrimaryRays`] per pixel (`trace` counts the rest).
/// Runs on the kit's pixel loop, [`render_image`] (rows in parallel).
/// Book: §8.4 The whole picture.
pub fn render(
    world: &World,
    camera: &Camera,
    width: u32,
    height: u32,
    settings: &TraceSettings,
) -> (Image, RayStats) {
    // SOLUTION BEGIN
    render_image(width, height, |x, y| {
        // One eye ray through the pixel centre, the root of the pixel's ray tree.
        count(Counter::PrimaryRays);
        let ray = camera.pixel_ray(x, y, width, height);
        trace(world, &ray, 0, 1.0, settings)
    })
    // SOLUTION END
}

/// `scene` rendered at its own size through its own camera, every object
/// tested for every ray (04's [`BruteForce`]). An error (never a panic) when
/// the camera cannot be built. Book: §8.4 The whole picture.
pub fn render_scene(scene: &Scene, settings: &TraceSettings) -> Result<(Image, RayStats), String> {
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).map_err(|e| e.to_string())?;
    let objects = BruteForce::new(&scene.objects);
    Ok(render(&World::new(scene, &objects), &camera, scene.width, scene.height, settings))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{directional, glass, matte, plane, scene, sphere, v};
    use raylab::scene as description;
    use raylab::stats::measure;
    use raylab::{Color, Float, Vec3};

    /// The mirror, glass and matte balls over a floor, for the 40 × 30 camera of
    /// `testing::scene` (eye (0, 0, 5), looking at the origin).
    fn three_balls() -> Scene {
        Scene { width: 40, height: 30, ..raylab_testing::scenes::three_balls() }
    }

    #[test]
    fn render_traces_each_pixel_centre_once() {
        // Every pixel is `trace` of 01's pixel_ray, bit for bit; one primary ray per pixel
        // (40·30 = 1200), and the other counts are the sums of the pixels' own.
        let s = three_balls();
        let camera = Camera::from_scene(&s.camera, s.width, s.height).unwrap();
        let objects = BruteForce::new(&s.objects);
        let world = World::new(&s, &objects);
        let settings = TraceSettings::default();
        let (image, stats) = render(&world, &camera, s.width, s.height, &settings);
        assert_eq!(stats.get(Counter::PrimaryRays), 1200);
        let mut sum = RayStats::default();
        for y in 0..s.height {
            for x in 0..s.width {
                let ray = camera.pixel_ray(x, y, s.width, s.height);
                let (color, counted) = measure(|| trace(&world, &ray, 0, 1.0, &settings));
                assert_eq!(image.get(x, y), color, "pixel ({x}, {y})");
                sum += counted;
            }
        }
        for c in [Counter::ShadowRays, Counter::ReflectionRays, Counter::RefractionRays] {
            assert_eq!(stats.get(c), sum.get(c), "{c:?}");
            assert!(sum.get(c) > 0, "{c:?}: the scene has every kind of ray");
        }
        // render_scene is the same render, at the scene's size with the brute-force objects.
        assert_eq!(render_scene(&s, &settings).unwrap(), (image, stats));
    }

    #[test]
    fn a_camera_inside_a_glass_ball_renders_finite_pixels() {
        // The eye at (0, 0, 2.5) inside a clear glass ball of radius 3 (η = 1.5, k_t = 1,
        // k_r = 0) looking out at two matte balls and a floor. A ray meets the ball from
        // inside at sin θ = (distance from the centre to its line)/3; off the axis by α that
        // distance is 2.5·sin α, past the critical sin θ_c = 2/3 for α > 53°: the image's
        // sides (fovy 100°, aspect 4/3: up to 57.8° across) are totally reflected, which
        // makes mirror rays out of a material without k_r. Every pixel finite and
        // non-negative, with or without Fresnel.
        let mut s = scene(
            vec![
                sphere(Vec3::ZERO, 3.0, 0),
                sphere(v(-1.5, 0.0, -6.0), 1.0, 1),
                sphere(v(2.0, 0.5, -5.0), 1.0, 2),
                plane(Vec3::Y, -3.5, 1),
            ],
            vec![glass(1.5), matte(v(0.9, 0.3, 0.2)), matte(v(0.2, 0.8, 0.3))],
            vec![directional(v(1.0, 3.0, 2.0).normalize(), Color::ONE)],
            v(0.3, 0.4, 0.6),
            Color::splat(0.1),
        );
        s.camera = description::Camera::Perspective {
            eye: v(0.0, 0.0, 2.5),
            at: v(0.0, 0.0, -5.0),
            up: Vec3::Y,
            fovy: raylab::radians(100.0),
        };
        for fresnel in [false, true] {
            let settings = TraceSettings { fresnel, ..TraceSettings::default() };
            let (image, stats) = render_scene(&s, &settings).unwrap();
            assert_eq!(image.non_finite(), None);
            assert!(image.pixels.iter().all(|c| c.min_element() >= 0.0));
            assert!(stats.get(Counter::RefractionRays) > 600, "the middle of the view leaves the ball");
            assert!(stats.get(Counter::ReflectionRays) > 0, "total internal reflection at the sides");
        }
    }

    #[test]
    fn a_camera_that_cannot_be_built_is_an_error_not_a_panic() {
        // A scene made in code (no loader to check it) whose eye is where it looks.
        let mut s = three_balls();
        s.camera = description::Camera::Perspective {
            eye: Vec3::ONE,
            at: Vec3::ONE,
            up: Vec3::Y,
            fovy: 1.0 as Float,
        };
        let error = render_scene(&s, &TraceSettings::default()).unwrap_err();
        assert!(error.contains("same point"), "{error}");
    }
}
