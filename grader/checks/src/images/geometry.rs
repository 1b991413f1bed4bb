//! The geometry images — which object each pixel sees, how far, its normal — drawn with the
//! student's intersections and compared with the snapshots: the `NN/geometry/S` checks, and the
//! first question when a picture differs.

use raylab::compare::compare;
use raylab::{Color, Float, Image, Scene};

use super::no_snapshot;
use crate::check::{CheckResult, Failure, fail};
use crate::judge;
use crate::scenes::SceneFile;
use crate::stages;

/// Depth and normal tolerances of the geometry check: a pixel's depth
/// differs when it is off by more than 10⁻³ relative (f32 and f64 agree to
/// ~10⁻⁶ on these scenes; the catalogued mistakes are off by 10 % or more),
/// a normal when a component is off by more than 10⁻³.
const DEPTH_RELATIVE_TOLERANCE: Float = 1e-3;
const NORMAL_TOLERANCE: Float = 1e-3;

/// The three geometry images of `scene` drawn with the intersections of the
/// scene's lecture (its stage's `geometry`; see the module documentation).
#[allow(unused_variables)]
pub fn geometry_images(lecture: &str, scene: &Scene) -> Result<[Image; 3], String> {
    #[cfg(feature = "l02")]
    {
        use l01_transforms::Camera;
        use l02_ray_casting::{depth_image, normal_image, object_id_image};
        let finds = stages::stage(lecture).map_or(stages::Finds::BruteForce, |s| s.geometry);
        if let Some(objects) = stages::finder(finds, scene) {
            let camera =
                Camera::from_scene(&scene.camera, scene.width, scene.height).map_err(|e| e.to_string())?;
            let (w, h, objects) = (scene.width, scene.height, objects.as_ref());
            return Ok([
                object_id_image(&camera, &objects, w, h),
                depth_image(&camera, &objects, w, h),
                normal_image(&camera, &objects, w, h),
            ]);
        }
    }
    Err(format!("the intersections for lecture {lecture}'s scenes are not built"))
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
    #[cfg(feature = "l02")]
    for (index, object) in scene.objects.iter().enumerate() {
        if raylab::color::to_srgb8(l02_ray_casting::id_color(Some(index))) == pixel {
            return format!("#{index} ({})", object.shape.kind());
        }
    }
    format!("with colour {pixel:?}")
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
