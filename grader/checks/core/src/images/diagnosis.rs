//! What a differing picture points to: the first exercise on its path whose value differs
//! (`crate::path`), and what the differing pixels show where they lie (NaN, negative colours,
//! light from behind a surface, shadow acne, mirrors).

use raylab::{Color, Float, Image, Scene, Vec3};

use super::CHANNEL_THRESHOLD;
use super::geometry::object_at;
use crate::path;
use crate::scenes::{SceneFile, calls_snapshot};
use crate::stages::{self, Draws};

/// Where the student's calls at grid pixel `at` first differ from the blessed ones: the cause
/// of a failed picture whose geometry matches; where every call agrees and the pixel there
/// differs (`differs_there`), the pixel loop's ([`stages::pixel_loop`]). `None` where the stage has
/// no calls, the pixel is not the grid's, or nothing is named.
pub(super) fn path_difference(
    file: &SceneFile,
    stage: &str,
    scene: &Scene,
    at: (u32, u32),
    differs_there: bool,
    yours: &[path::Call],
) -> Option<String> {
    let text = std::fs::read_to_string(calls_snapshot(file, stage)).ok()?;
    let blessed: path::GridCalls = serde_json::from_str(&text).ok()?;
    let index = crate::trees::grid(blessed.width, blessed.height).iter().position(|p| *p == at)?;
    let (x, y) = at;
    match path::first_difference(&blessed.pixel(index)?, yours) {
        Some((exercise, how)) => Some(format!(
            "at pixel ({x}, {y}), the first value on this picture's path that differs: {how}. Check {exercise}"
        )),
        None => stages::pixel_loop(stage, scene).filter(|_| differs_there).map(|exercise| {
            format!(
                "at pixel ({x}, {y}) every exercise on this picture's path returns the reference's values, \
                 yet the pixel differs: check {exercise}, which makes the pixel from them"
            )
        }),
    }
}

/// Why stage 01's picture (the rays' directions as colours) differs.
pub(super) fn camera_diagnosis(yours: &Image) -> String {
    if yours.pixels.iter().any(|c| !c.is_finite()) {
        return "some rays have a NaN or infinite direction or origin: look_at with a degenerate up, or a \
                division by zero in screen_coords"
            .into();
    }
    "the rays point elsewhere than the reference's: the colour is the ray's world direction (red +x, green \
     +y, blue +z) with bands every 15°. Check screen_coords (pixel centres, y down), fovy as the full \
     vertical angle (tan(fovy/2)), the aspect on x, look_at's columns (u, v, w with w = (eye − at)/|…|), \
     and for orthographic cameras the origins (sx·aspect·h/2, sy·h/2)"
        .into()
}

/// What the differing pixels of a shaded image show, from where they lie (the reference's
/// geometry from the snapshots), at stage `stage`.
pub(super) enum Seen {
    /// A symptom seen in the pixels, and its fix: NaN, negative colours, light from behind a
    /// surface, shadow acne.
    Symptom(String),
    /// A guess from the differences' share on glossy, darker or brighter pixels.
    Guess(String),
}

/// Where the differing pixels of a shaded image lie, and what that points to
/// at stage `stage`: the reference's geometry from the snapshots, or `geometry` (id, depth,
/// normal) where given (a final picture, smaller than the snapshots: the student's, which
/// matched them).
pub(super) fn shading_diagnosis(
    stage: &str,
    file: &SceneFile,
    scene: &Scene,
    (expected, yours): (&Image, &Image),
    geometry: Option<[Image; 3]>,
    rays: Option<&[raylab::Ray]>,
) -> Seen {
    let geometry = geometry.map(Ok).unwrap_or_else(|| {
        Ok::<_, raylab::ImageError>([
            Image::load_png(file.snapshot(".id.png"))?,
            Image::load_exr(file.snapshot(".depth.exr"))?,
            Image::load_exr(file.snapshot(".normal.exr"))?,
        ])
    });
    let Ok([id, depth, normal]) = geometry else {
        return Seen::Guess("the shading differs".into());
    };
    let (w, h) = (expected.width, expected.height);
    // The student's images (a final picture's) are a subject's values: each must fill the picture.
    let fits =
        |image: &Image| (image.width, image.height) == (w, h) && image.pixels.len() == (w * h) as usize;
    if ![&id, &depth, &normal, yours].into_iter().all(fits) {
        return Seen::Guess("the shading differs".into());
    }
    let mut over = vec![false; (w * h) as usize];
    for (i, (e, g)) in expected.pixels.iter().zip(&yours.pixels).enumerate() {
        let (e, g) = (raylab::color::to_srgb8(*e), raylab::color::to_srgb8(*g));
        over[i] = (0..3).any(|c| e[c].abs_diff(g[c]) > CHANNEL_THRESHOLD) || !yours.pixels[i].is_finite();
    }
    let (mut total, mut glossy, mut facing_away, mut isolated, mut darker, mut nan) = (0, 0, 0, 0, 0, 0);
    let mut negative = 0;
    for y in 0..h {
        for x in 0..w {
            let i = (y * w + x) as usize;
            if !over[i] {
                continue;
            }
            total += 1;
            nan += usize::from(!yours.pixels[i].is_finite());
            negative += usize::from(yours.pixels[i].min_element() < 0.0);
            darker += usize::from(luminance(yours.pixels[i]) < luminance(expected.pixels[i]));
            let neighbours = [(x.wrapping_sub(1), y), (x + 1, y), (x, y.wrapping_sub(1)), (x, y + 1)];
            isolated += usize::from(
                neighbours
                    .iter()
                    .filter(|&&(nx, ny)| nx < w && ny < h)
                    .all(|&(nx, ny)| !over[(ny * w + nx) as usize]),
            );
            let object = object_at(&id, x, y, scene);
            if let Some(material) = object.and_then(|o| scene.materials.get(scene.objects[o].material)) {
                let reflective =
                    material.reflective.max_element() > 0.0 || material.transparent.max_element() > 0.0;
                glossy += usize::from(reflective);
            }
            if let (Some(ray), Some(_)) = (rays.and_then(|r| r.get(i)), object) {
                let point = ray.origin + ray.dir.normalize() * depth.get(x, y).x;
                let n = normal.get(x, y);
                let lit = scene
                    .lights
                    .iter()
                    .any(|light| light_direction(light, point).is_some_and(|l| n.dot(l) > 0.05));
                facing_away += usize::from(!lit);
            }
        }
    }
    let share = |n: usize| n as f64 / total.max(1) as f64;
    let draws = stages::stage(stage).map_or(Draws::Complete, |s| s.draws);
    let headlight = draws == Draws::Headlight;
    if nan > 0 {
        Seen::Symptom(format!(
            "{nan} of your pixels are NaN or infinite: a division by zero or the sqrt of a negative number"
        ))
    } else if negative > 0 {
        Seen::Symptom(format!(
            "{negative} of your pixels have a negative colour: light from behind a surface subtracts light. \
             Clamp with max(N·L, 0) in the diffuse term (and the specular terms' cosines)"
        ))
    } else if headlight {
        Seen::Guess("the headlight shading k_d·(½ + ½ N·V) differs where your ids and depths match: the normals differ \
         (unit, facing the ray), or the hit's material index"
            .into())
    } else if share(facing_away) >= 0.5 {
        Seen::Symptom("the shading differs where the surface faces away from every light (N·L ≤ 0): clamp with max(N·L, 0) \
         in the diffuse and the specular terms"
            .into())
    } else if share(glossy) >= 0.5 && draws.mirrors() {
        Seen::Guess(if draws == Draws::Mirrored {
            "the differences are on reflective or transparent objects, which show the sky in your mirror and \
             refracted directions: check 07 mirror_direction, interface and refract"
                .into()
        } else {
            "the differences are on reflective or transparent objects: check the mirror and refracted rays \
             (07 mirror_direction, refract, fresnel_dielectric; 08 trace and its weights)"
                .into()
        })
    } else if share(isolated) >= 0.3 && share(darker) >= 0.7 && draws.shadows() {
        Seen::Symptom("speckled dark pixels on lit surfaces: shadow acne. Offset the shadow ray's origin off the surface \
         (06 offset_origin) and ignore blockers beyond the light"
            .into())
    } else if share(darker) >= 0.8 {
        Seen::Guess("your image is darker where it differs: a light missing (or wrongly in shadow), its attenuation or \
         intensity, or a colour multiplied twice"
            .into())
    } else if share(darker) <= 0.2 {
        Seen::Guess(if draws == Draws::Local {
            "your image is brighter where it differs: light from behind the surface (max(N·L, 0)), a \
             missing falloff, or a colour added twice"
                .into()
        } else {
            "your image is brighter where it differs: a missing shadow, light from behind the surface \
             (max(N·L, 0)), or the sRGB encoding applied twice"
                .into()
        })
    } else {
        Seen::Guess("the shading differs: compare expected.png and yours.png, and print the ray tree of a differing pixel \
         (grader render SCENE --tree X,Y)"
            .into())
    }
}

/// The primary ray of each pixel of `scene`, row by row, from the student's camera when lecture 01
/// is built.
pub(super) fn camera_rays(scene: &Scene) -> Option<Vec<raylab::Ray>> {
    let rays = stages::camera(scene)?.ok()?;
    let (w, h) = (scene.width, scene.height);
    Some((0..h).flat_map(|y| (0..w).map(move |x| (x, y))).map(|(x, y)| rays(x, y)).collect())
}

fn luminance(c: Color) -> Float {
    0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z
}

/// The unit direction from `point` toward the light (any point of an area light's centre).
fn light_direction(light: &raylab::scene::Light, point: Vec3) -> Option<Vec3> {
    use raylab::scene::LightKind;
    match light.kind {
        LightKind::Directional { direction } => Some(-direction.normalize()),
        LightKind::Point { position, .. } | LightKind::Spot { position, .. } => {
            (position - point).try_normalize()
        }
        LightKind::Rect { corner, edge_u, edge_v, .. } => {
            (corner + 0.5 * (edge_u + edge_v) - point).try_normalize()
        }
        LightKind::Sphere { center, .. } => (center - point).try_normalize(),
    }
}
