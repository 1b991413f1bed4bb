//! The checks of `render.rs`: render.

use super::common::*;

/// A 16 × 12 render of [`three_balls`]: each pixel against `trace` of 01's `pixel_ray` at
/// depth 0 and weight 1 (the student's own trace and camera, checked by their own checks),
/// and the primary-ray count.
pub(super) fn render_cases(render: RenderFn) -> CheckResult {
    let s = three_balls();
    let (w, h) = (s.width, s.height);
    // Depth 2: a ray through the glass ball needs both levels to get out (in at depth 1,
    // out at depth 2), so an eye ray traced at depth 1 shows black glass.
    let settings = TraceSettings { max_depth: 2, ..TraceSettings::default() };
    let case = format!("render of three balls (mirror, glass, matte) over a floor, {w} × {h}, max_depth 2");
    // The student's camera, render and trace of each pixel's eye ray, as one value (the
    // camera is theirs: lecture 01's).
    let (image, stats, eye_colors) = student(|| {
        with_world(&s, |world, camera| {
            let (image, stats) = render(world, camera, w, h, &settings);
            let eye = (0..h).flat_map(|y| (0..w).map(move |x| (x, y)));
            let colors: Vec<Color> =
                eye.map(|(x, y)| trace(world, &camera.pixel_ray(x, y, w, h), 0, 1.0, &settings)).collect();
            (image, stats, colors)
        })
    })
    .map_err(|e| {
        fail("the camera of the check scene", "a camera", e, "01's PerspectiveCamera::new must accept it")
    })?;
    ensure(
        image.width == w && image.height == h && image.pixels.len() == (w * h) as usize,
        &case,
        format!("a {w} × {h} image"),
        format!("{} × {} ({} pixels)", image.width, image.height, image.pixels.len()),
        "one pixel per (x, y), x < width, y < height",
    )?;
    // Each pixel against its eye ray's colour. The same ray and the same trace give the
    // same colour; 64ε allows a student's render that rounds the ray differently.
    for y in 0..h {
        for x in 0..w {
            let expected = eye_colors[(y * w + x) as usize];
            let got = image.get(x, y);
            if near(got, expected, COLOR_TOL) {
                continue;
            }
            let pixel = format!("{case}: pixel ({x}, {y})");
            // The colours of the likely mistakes at this pixel (the student's trace and camera).
            let [deeper, weightless, corner, flipped, transposed] = student(|| {
                with_world(&s, |world, camera| {
                    let at = |x: u32, y: u32, depth: u32, weight: Float| {
                        trace(world, &camera.pixel_ray(x, y, w, h), depth, weight, &settings)
                    };
                    let corner = camera.generate_ray(
                        2.0 * x as Float / w as Float - 1.0,
                        1.0 - 2.0 * y as Float / h as Float,
                    );
                    let transposed = if y < w && x < h { at(y, x, 0, 1.0) } else { Color::NAN };
                    [
                        at(x, y, 1, 1.0),
                        at(x, y, 0, 0.0),
                        trace(world, &corner, 0, 1.0, &settings),
                        at(x, h - 1 - y, 0, 1.0),
                        transposed,
                    ]
                })
            })
            .unwrap_or([Color::NAN; 5]);
            let cause = if near(got, deeper, COLOR_TOL) {
                "the eye ray is the root of the ray tree: trace it at depth 0, not 1"
            } else if near(got, weightless, COLOR_TOL) {
                "the eye ray has weight 1: pass 1.0 to trace"
            } else if near(got, corner, COLOR_TOL) {
                "trace the ray through the pixel's centre (x + ½, y + ½): camera.pixel_ray(x, y, w, h)"
            } else if near(got, flipped, COLOR_TOL) {
                "pixel (0, 0) is the top-left: y grows downward, as pixel_ray takes it"
            } else if near(got, transposed, COLOR_TOL) {
                "x is the column and y the row: image pixel (x, y) is camera.pixel_ray(x, y, width, height)"
            } else {
                "each pixel is trace(world, &camera.pixel_ray(x, y, width, height), 0, 1.0, settings)"
            };
            return Err(fail(pixel, vec3(expected), vec3(got), cause));
        }
    }
    let primary = stats.get(Counter::PrimaryRays);
    ensure(
        primary == u64::from(w * h),
        &case,
        format!("{} primary rays", w * h),
        format!("{primary} primary rays"),
        "count one Counter::PrimaryRays per pixel, inside the pixel closure (trace counts the other rays)",
    )?;
    let secondary = stats.get(Counter::ReflectionRays) + stats.get(Counter::RefractionRays);
    ensure(
        secondary > 0,
        &case,
        "the pixels' mirror and refracted rays in the statistics",
        "none",
        "return the statistics of render_image, which adds up what every pixel counted",
    )?;
    Ok(format!("{} pixels, {primary} primary rays", w * h))
}

/// `f` of the world of `s` (brute force) and the student's camera of it; the camera's error as text.
fn with_world<T>(s: &Scene, f: impl FnOnce(&World, &Camera) -> T) -> Result<T, String> {
    let camera = Camera::from_scene(&s.camera, s.width, s.height).map_err(|e| e.to_string())?;
    let objects = BruteForce::new(&s.objects);
    Ok(f(&World::new(s, &objects), &camera))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l01_transforms::Camera;

    use l08_ray_tree::{TraceSettings, World, trace};
    use raylab::render::render_image;
    use raylab::stats::{Counter, RayStats, count};
    use raylab::{Float, Image};

    /// The slips planted in the copy of the reference render.
    #[derive(Clone, Copy, PartialEq, Eq)]
    enum RenderSlip {
        /// Primary rays traced at depth 1, not 0.
        DepthOne,
        /// Primary rays traced with weight 0, not 1.
        WeightZero,
        /// Rays through the pixels' corners, not their centres.
        CornerRays,
        /// Primary rays not counted.
        Uncounted,
        /// Rows from the bottom: the image upside down.
        UpsideDown,
    }

    /// The reference render with a slip.
    fn render_with(
        world: &World,
        camera: &Camera,
        w: u32,
        h: u32,
        s: &TraceSettings,
        slip: RenderSlip,
    ) -> (Image, RayStats) {
        render_image(w, h, |x, y| {
            if slip != RenderSlip::Uncounted {
                count(Counter::PrimaryRays);
            }
            let ray = match slip {
                RenderSlip::CornerRays => camera
                    .generate_ray(2.0 * x as Float / w as Float - 1.0, 1.0 - 2.0 * y as Float / h as Float),
                RenderSlip::UpsideDown => camera.pixel_ray(x, h - 1 - y, w, h),
                _ => camera.pixel_ray(x, y, w, h),
            };
            match slip {
                RenderSlip::DepthOne => trace(world, &ray, 1, 1.0, s),
                RenderSlip::WeightZero => trace(world, &ray, 0, 0.0, s),
                _ => trace(world, &ray, 0, 1.0, s),
            }
        })
    }

    macro_rules! render_slips {
        ($($name:ident => $slip:expr),* $(,)?) => {
            $(fn $name(world: &World, camera: &Camera, w: u32, h: u32, s: &TraceSettings) -> (Image, RayStats) {
                render_with(world, camera, w, h, s, $slip)
            })*
        };
    }

    render_slips! {
        depth_one => RenderSlip::DepthOne,
        weight_zero => RenderSlip::WeightZero,
        corner_rays => RenderSlip::CornerRays,
        uncounted => RenderSlip::Uncounted,
        upside_down => RenderSlip::UpsideDown,
    }

    #[test]
    fn planted_render_mistakes_are_caught_with_their_cause() {
        for (render, cause) in [
            (depth_one as RenderFn, "depth 0, not 1"),
            (weight_zero, "weight 1"),
            (corner_rays, "through the pixel's centre"),
            (uncounted, "Counter::PrimaryRays per pixel"),
            (upside_down, "top-left"),
        ] {
            caught(render_cases(render), cause);
        }
    }
}
