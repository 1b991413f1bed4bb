//! The stages: how lecture N's scenes are drawn with the kit and the lectures
//! up to N, nothing later, so a student sees each lecture's pictures as soon
//! as that lecture is done (the course's third promise, "model only what a
//! scene requires", applied to grading). Book: "What you should see" in each
//! chapter.
//!
//! | stage | draws with | what the picture shows |
//! |---|---|---|
//! | 01 | the camera | each primary ray's direction as a colour, in soft bands (and its origin, for orthographic rays) |
//! | 02–04 | + the lecture's intersections | the closest hit's diffuse colour under a headlight: k_d·(½ + ½ N·V) |
//! | 05 | 04's intersections, 05's `shade_local` | local shading, every light unblocked |
//! | 06 | + 06's `shade_with_shadows` | shadows, hard and soft |
//! | 07 | 05's local shading, 07's mirror and refracted directions | mirrors and glass showing stage 01's sky in the directions 07 computes |
//! | 08 | 08's `render_scene` (04's brute force, no textures) | the Whitted ray tree |
//! | 09 | 09's hierarchy | stage 02–04's headlight picture through the BVH |
//! | 10 | the complete tracer | textures, supersampling: the course's final pictures |
//!
//! No stage does what an exercise asks: stage 01's colours and the headlight
//! are not lecture functions, and the later stages only call the student's
//! functions in a pixel loop (the kit's `render_image`). Stage 07 shows the
//! sky in the mirror and refracted directions instead of tracing them into the
//! scene: that is lecture 08's `trace`.

use raylab::{Color, Image, Ray, Scene, Vec3};

#[allow(unused_imports, reason = "used by the stages that shade, where their lectures are built")]
use crate::settings;

/// One lecture's stage: what its pictures are drawn with and how they are explained. The
/// declaration of the stages is [`STAGES`], one row per lecture; everything else asks it.
#[derive(Clone, Copy, Debug)]
pub struct Stage {
    /// The lecture whose scenes it draws: `02`.
    pub lecture: &'static str,
    /// What it draws, in one line (the image checks' `about`).
    pub about: &'static str,
    /// What it makes of each eye ray.
    pub draws: Draws,
    /// The intersector it finds hits with.
    pub finds: Finds,
    /// The intersector its scenes' geometry images (object ids, depths, normals) are drawn
    /// with, to compare with the snapshots': the lecture's own intersections where it teaches
    /// some, 04's brute force elsewhere.
    pub geometry: Finds,
    /// Whether those geometry images are checks of their own (`NN/geometry/S`): the lectures
    /// that teach intersections. Elsewhere the geometry only explains a failed picture.
    pub geometry_graded: bool,
    /// It draws with the exercises of [`DRAWN_WITH`] of the lectures before this one: when one
    /// of them fails, its failed picture is blocked by it (see [`needs`]).
    pub needs_before: &'static str,
}

/// What a stage makes of each eye ray.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Draws {
    /// The ray's direction (and origin) as a colour: [`sky`].
    Sky,
    /// The closest hit under a light at the eye: [`headlight`].
    Headlight,
    /// 05's local shading, every light unblocked.
    Local,
    /// 06's shading with shadow rays.
    Shadowed,
    /// 05's local shading plus the sky in 07's mirror and refracted directions.
    Mirrored,
    /// 08's Whitted tracer over 04's brute force.
    Whitted,
    /// The complete tracer: textures, the hierarchy, supersampling.
    Complete,
}

impl Draws {
    /// Whether the picture is shaded by the lectures' shading (05 on): the stages whose
    /// pictures have calls on their path (the `path` module).
    pub fn shades(self) -> bool {
        !matches!(self, Draws::Sky | Draws::Headlight)
    }

    /// Whether it casts shadow rays (06's shading).
    pub fn shadows(self) -> bool {
        matches!(self, Draws::Shadowed | Draws::Whitted | Draws::Complete)
    }

    /// Whether mirrors and glass show something in 07's directions.
    pub fn mirrors(self) -> bool {
        matches!(self, Draws::Mirrored | Draws::Whitted | Draws::Complete)
    }

    /// Whether it traces lecture 08's ray tree.
    pub fn traces(self) -> bool {
        matches!(self, Draws::Whitted | Draws::Complete)
    }
}

/// The intersector a stage finds hits with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Finds {
    /// None: the camera's rays alone.
    Nothing,
    /// 02's group of spheres and planes.
    Group,
    /// 03's boxes, polygons and meshes besides.
    Shapes,
    /// 04's brute force over every shape, transforms included.
    BruteForce,
    /// 09's choice: a hierarchy where the scene has enough primitives, brute force otherwise.
    Hierarchy,
}

/// The stages, in course order: the declaration every question about a stage is answered from
/// (the image checks, their diagnosis, the calls on a picture's path, `render`, the report's
/// trees). The last is the complete tracer, [`FINAL_STAGE`], which also draws every earlier
/// lecture's scenes (`10/final/NN-S`).
pub const STAGES: &[Stage] = &[
    Stage {
        lecture: "01",
        about: "the camera's rays, coloured by direction (and origin), against the snapshot (stage 01)",
        draws: Draws::Sky,
        finds: Finds::Nothing,
        geometry: Finds::BruteForce,
        geometry_graded: false,
        needs_before: "01",
    },
    Stage {
        lecture: "02",
        about: "02's spheres and planes, closest hit under a headlight, against the snapshot (stage 02)",
        draws: Draws::Headlight,
        finds: Finds::Group,
        geometry: Finds::Group,
        geometry_graded: true,
        needs_before: "02",
    },
    Stage {
        lecture: "03",
        about: "03's boxes, polygons and meshes under a headlight, against the snapshot (stage 03)",
        draws: Draws::Headlight,
        finds: Finds::Shapes,
        geometry: Finds::Shapes,
        geometry_graded: true,
        needs_before: "03",
    },
    Stage {
        lecture: "04",
        about: "04's quadrics and transformed objects under a headlight, against the snapshot (stage 04)",
        draws: Draws::Headlight,
        finds: Finds::BruteForce,
        geometry: Finds::BruteForce,
        geometry_graded: true,
        needs_before: "04",
    },
    Stage {
        lecture: "05",
        about: "local shading (05) of 04's intersections, against the snapshot (stage 05)",
        draws: Draws::Local,
        finds: Finds::BruteForce,
        geometry: Finds::BruteForce,
        geometry_graded: false,
        needs_before: "05",
    },
    Stage {
        lecture: "06",
        about: "local shading with shadow rays (06), against the snapshot (stage 06)",
        draws: Draws::Shadowed,
        finds: Finds::BruteForce,
        geometry: Finds::BruteForce,
        geometry_graded: false,
        needs_before: "06",
    },
    // 07 draws with 05's shading, not 06's.
    Stage {
        lecture: "07",
        about: "local shading, mirrors and glass showing the sky in 07's directions (stage 07)",
        draws: Draws::Mirrored,
        finds: Finds::BruteForce,
        geometry: Finds::BruteForce,
        geometry_graded: false,
        needs_before: "06",
    },
    Stage {
        lecture: "08",
        about: "the Whitted ray tree of 08, against the snapshot (stage 08)",
        draws: Draws::Whitted,
        finds: Finds::BruteForce,
        geometry: Finds::BruteForce,
        geometry_graded: false,
        needs_before: "08",
    },
    // 09 draws with the intersections of 01–04 and its own hierarchy.
    Stage {
        lecture: "09",
        about: "09's hierarchy under the headlight of stages 02–04, against the snapshot (stage 09)",
        draws: Draws::Headlight,
        finds: Finds::Hierarchy,
        geometry: Finds::Hierarchy,
        geometry_graded: true,
        needs_before: "05",
    },
    // The hierarchy is left out of 10's needs: most scenes are drawn without one (32 primitives
    // or fewer), and where a hierarchy draws a scene wrong, `09/geometry/…` names it.
    Stage {
        lecture: "10",
        about: "the complete tracer (textures, supersampling) against the snapshot (stage 10)",
        draws: Draws::Complete,
        finds: Finds::Hierarchy,
        geometry: Finds::BruteForce,
        geometry_graded: false,
        needs_before: "09",
    },
];

/// The exercises the stages draw with, in course order: a stage needs those of the lectures
/// before its row's `needs_before`.
const DRAWN_WITH: &[&str] = &[
    "01/look_at",
    "01/screen_coords",
    "01/PerspectiveCamera::generate_ray",
    "01/OrthographicCamera::generate_ray",
    "02/hit_sphere_stable",
    "02/hit_plane",
    "02/closest_hit",
    "03/hit_box",
    "03/hit_polygon",
    "03/hit_triangle",
    "03/hit_mesh",
    "04/hit_cylinder",
    "04/hit_cone",
    "04/hit_transformed",
    "05/shade_local",
    "06/shade_with_shadows",
    "07/mirror_direction",
    "07/interface",
    "07/refract",
    "07/fresnel_dielectric",
    "08/trace_ray",
    "08/render",
];

/// Lecture `lecture`'s stage; `None` for a lecture without one.
pub fn stage(lecture: &str) -> Option<&'static Stage> {
    STAGES.iter().find(|s| s.lecture == lecture)
}

/// The lecture whose stage is the complete tracer, and that grades every
/// other lecture's scenes with it (`10/final/NN-S`): the last row of [`STAGES`].
pub const FINAL_STAGE: &str = STAGES[STAGES.len() - 1].lecture;

/// The first stage: the camera alone.
pub const FIRST_STAGE: &str = STAGES[0].lecture;

/// What stage `lecture` draws, in one line (the image checks' `about`); a lecture without a
/// stage of its own is drawn by the complete tracer.
pub fn about(lecture: &str) -> &'static str {
    stage(lecture).unwrap_or(&STAGES[STAGES.len() - 1]).about
}

/// The exercises of earlier lectures a stage draws with: when one of them
/// fails, a failed image check of this lecture is reported as blocked by it
/// (the earlier exercise is at fault, not this lecture's).
pub fn needs(lecture: &str) -> &'static [&'static str] {
    let before = stage(lecture).map_or(lecture, |s| s.needs_before);
    let count = DRAWN_WITH.iter().take_while(|need| need[..2] < *before).count();
    &DRAWN_WITH[..count]
}

/// The stages `file` is drawn by: its lecture's, and the complete tracer's for the scenes of the
/// lectures before it (`10/final/NN-S`).
pub fn drawing(file: &crate::scenes::SceneFile) -> Vec<&str> {
    if file.lecture == FINAL_STAGE { vec![FINAL_STAGE] } else { vec![file.lecture.as_str(), FINAL_STAGE] }
}

/// Whether stage `lecture`'s code is in this build (its lecture and the ones it draws with
/// compiled: the lecture's feature turns those on; the final stage's is every lecture).
pub fn built(lecture: &str) -> bool {
    if lecture == FINAL_STAGE {
        return cfg!(feature = "complete");
    }
    crate::lectures::lectures().iter().any(|l| l.number == lecture && !l.hidden && l.run.is_some())
}

/// Stage 01's colour of a ray: its unit direction d as a colour, ½ + ½d
/// (+x red, +y green, +z blue), times soft bands of period 2π/24 (15°) in
/// each component of d and of period 1 world unit in each coordinate of the
/// origin. The bands make a small turn of the camera move every pixel (a
/// half-pixel shift changes a channel by several 8-bit steps where the bands
/// are steepest); they are smooth, so f32 and f64 renders agree.
pub fn sky(ray: &Ray) -> Color {
    let d = ray.dir.normalize();
    let o = ray.origin;
    direction_color(d) * bands(o, std::f64::consts::TAU as raylab::Float)
}

/// The direction part of [`sky`]: what stage 07's mirrors and glass show.
pub fn direction_color(d: Vec3) -> Color {
    (Vec3::splat(0.5) + 0.5 * d) * bands(d, 24.0)
}

/// 0.8 + 0.2·cos(k x)·cos(k y)·cos(k z).
fn bands(p: Vec3, k: raylab::Float) -> raylab::Float {
    0.8 + 0.2 * (k * p.x).cos() * (k * p.y).cos() * (k * p.z).cos()
}

/// Stages 02–04 and 09's shading: the hit's diffuse colour k_d under a light
/// at the eye, k_d·(½ + ½ N·V) with V = −d/|d|. A normal that faces the ray
/// gives ½ to 1 (head-on is brightest); a normal flipped away from the ray
/// gives less than ½, so a wrong sign shows as a dark surface. Not lecture
/// 05's Lambert term: no light of the scene, no clamp.
pub fn headlight(scene: &Scene, ray: &Ray, hit: &raylab::Hit) -> Color {
    let k_d = scene.materials.get(hit.material).map_or(Color::splat(0.5), |m| m.diffuse);
    let v = -ray.dir.normalize();
    k_d * (0.5 + 0.5 * hit.normal.dot(v))
}

/// Scene `scene` drawn by stage `lecture`.
#[allow(unused_variables)]
pub fn render(lecture: &str, scene: &Scene) -> Result<Image, String> {
    let unbuilt =
        || format!("stage {lecture} is not in this build: its lecture or one it draws with does not compile");
    let Some(stage) = stage(lecture).filter(|_| built(lecture)) else { return Err(unbuilt()) };
    #[cfg(feature = "l01")]
    {
        let camera = l01_transforms::Camera::from_scene(&scene.camera, scene.width, scene.height)
            .map_err(|e| e.to_string())?;
        let (w, h) = (scene.width, scene.height);
        let pixels = |f: &(dyn Fn(&Ray) -> Color + Sync)| {
            raylab::render::render_image(w, h, |x, y| f(&camera.pixel_ray(x, y, w, h))).0
        };
        // The closest hit in (0, ∞) of `objects`, shaded by `shade`, or the background.
        type Shade<'a> = &'a (dyn Fn(&Ray, &raylab::Hit) -> Color + Sync);
        #[allow(unused)]
        let drawn = |objects: &dyn raylab::Intersector, shade: Shade| {
            Ok::<Image, String>(pixels(
                &|ray: &Ray| match objects.closest_hit(ray, raylab::Interval::POSITIVE) {
                    Some(hit) => shade(ray, &hit),
                    None => scene.background,
                },
            ))
        };
        let headlit: Shade = &|ray, hit| headlight(scene, ray, hit);
        // The tracing stages find their own hits.
        let objects = if stage.draws.traces() { None } else { intersector(lecture, scene) };
        match (stage.draws, objects.as_deref()) {
            (Draws::Sky, _) => return Ok(pixels(&sky)),
            (Draws::Headlight, Some(objects)) => return drawn(objects, headlit),
            #[cfg(feature = "l05")]
            (Draws::Local, Some(objects)) => return drawn(objects, &|ray, hit| local(scene, ray, hit)),
            #[cfg(feature = "l06")]
            (Draws::Shadowed, Some(objects)) => {
                return drawn(objects, &|ray, hit| shadowed(scene, objects, ray, hit));
            }
            #[cfg(feature = "l07")]
            (Draws::Mirrored, Some(objects)) => return drawn(objects, &|ray, hit| mirrored(scene, ray, hit)),
            #[cfg(feature = "l08")]
            (Draws::Whitted, _) => {
                return l08_ray_tree::render_scene(scene, &settings::scene_settings(scene))
                    .map(|(image, _)| image);
            }
            #[cfg(feature = "complete")]
            (Draws::Complete, _) => {
                use crate::tracer::{render_scene, scene_sampling};
                return render_scene(scene, None, &settings::scene_settings(scene), scene_sampling(scene))
                    .map(|(image, _)| image);
            }
            _ => {}
        }
    }
    Err(unbuilt())
}

/// The intersector stage `lecture` finds the closest hits with (its row's [`Finds`]); `None`
/// at a stage that finds none, or where it is not built.
pub fn intersector<'a>(lecture: &str, scene: &'a Scene) -> Option<Box<dyn raylab::Intersector + 'a>> {
    finder(stage(lecture)?.finds, scene)
}

/// The intersector `finds` names, over `scene`'s objects, where it is built.
#[allow(unused_variables)]
pub fn finder(finds: Finds, scene: &Scene) -> Option<Box<dyn raylab::Intersector + '_>> {
    match finds {
        #[cfg(feature = "l02")]
        Finds::Group => Some(Box::new(l02_ray_casting::Group::new(&scene.objects))),
        #[cfg(feature = "l03")]
        Finds::Shapes => Some(Box::new(crate::scene_objects::Lecture03(&scene.objects))),
        #[cfg(feature = "l04")]
        Finds::BruteForce => Some(Box::new(l04_quadrics_transforms::BruteForce::new(&scene.objects))),
        #[cfg(feature = "l09")]
        Finds::Hierarchy => Some(l09_acceleration::intersector_for(&scene.objects)),
        _ => None,
    }
}

/// Stage 05: 05's `shade_local` with the material's own colour, V = −d/|d|.
#[cfg(feature = "l05")]
fn local(scene: &Scene, ray: &Ray, hit: &raylab::Hit) -> Color {
    let Some(material) = scene.materials.get(hit.material) else { return scene.background };
    l05_shading::shade_local(
        material,
        material.diffuse,
        hit,
        -ray.dir.normalize(),
        &scene.lights,
        scene.ambient,
    )
}

/// Stage 06: 06's `shade_with_shadows` with the scene's shadow settings.
#[cfg(feature = "l06")]
fn shadowed(scene: &Scene, objects: &dyn raylab::Intersector, ray: &Ray, hit: &raylab::Hit) -> Color {
    use l06_shadows::Surface;
    let Some(material) = scene.materials.get(hit.material) else { return scene.background };
    let settings = settings::shadow_settings(scene);
    let surface = Surface {
        material,
        diffuse: material.diffuse,
        hit: *hit,
        v: -ray.dir.normalize(),
        origin: ray.origin,
    };
    l06_shadows::shade_with_shadows(
        objects,
        &scene.materials,
        &surface,
        &scene.lights,
        scene.ambient,
        settings,
    )
}

/// Stage 07: local shading, plus k_r times the sky ([`direction_color`]) in
/// 07's mirror direction, plus k_t times the sky in 07's refracted direction
/// (with 07's `interface`), or in the mirror direction where `refract` finds
/// total internal reflection. One bounce, to the sky: the rays are not traced
/// into the scene (lecture 08), and there is no Fresnel split.
#[cfg(feature = "l07")]
fn mirrored(scene: &Scene, ray: &Ray, hit: &raylab::Hit) -> Color {
    let mut color = local(scene, ray, hit);
    for (k, direction, _) in sky_rays(scene, ray, hit) {
        color += k * direction_color(direction);
    }
    color
}

/// Stage 07's rays to the sky from `hit`: (k_r, 07's mirror direction) on a reflective material,
/// (k_t, 07's refracted direction, or the mirror direction where `refract` finds total internal
/// reflection) on a transparent one, each with whether it is the transmitted one.
#[cfg(feature = "l07")]
fn sky_rays(scene: &Scene, ray: &Ray, hit: &raylab::Hit) -> Vec<(Color, Vec3, bool)> {
    use l07_reflection_refraction::{interface, mirror_direction, refract};
    let Some(material) = scene.materials.get(hit.material) else { return Vec::new() };
    let d = ray.dir.normalize();
    let mirror = || mirror_direction(d, hit.normal);
    let mut rays = Vec::new();
    if material.reflective != raylab::BLACK {
        rays.push((material.reflective, mirror(), false));
    }
    if material.transparent != raylab::BLACK {
        let crossing = interface(hit, material.ior);
        let through = refract(d, crossing.normal, crossing.eta_ratio()).unwrap_or_else(mirror);
        rays.push((material.transparent, through, true));
    }
    rays
}

/// The ray tree of pixel (x, y) of `scene` at a stage that traces one (08 and
/// 10), as text with the pixel's colour; `None` at the other stages.
#[allow(unused_variables)]
pub fn pixel_tree(stage: &str, scene: &Scene, (x, y): (u32, u32)) -> Option<String> {
    #[cfg(feature = "l08")]
    {
        let (color, tree) = traced(stage, scene, &[(x, y)])?.pop()?;
        Some(format!("colour ({:.3}, {:.3}, {:.3})\n{tree}", color.x, color.y, color.z))
    }
    #[cfg(not(feature = "l08"))]
    None
}

/// The ray trees of the report's grid of pixels ([`crate::trees::grid`]) for its 3D view: at
/// stages 08 and 10 the traced trees (lecture 08's), before them the rays the stage draws with —
/// the camera's ray (01), its closest hit (02–07, 09; stages 05 and 06 shade inside 05's and 06's
/// functions, which record nothing), and at 07 the mirror and refracted rays to the sky. `None`
/// where the stage is not built.
pub fn grid_trees(stage: &str, scene: &Scene) -> Option<Vec<crate::trees::TreeNode>> {
    trees(stage, scene, &crate::trees::grid(scene.width, scene.height))
}

/// The ray trees of `pixels` at stage `stage`, as [`grid_trees`] makes them.
#[allow(unused_variables)]
pub fn trees(stage: &str, scene: &Scene, pixels: &[(u32, u32)]) -> Option<Vec<crate::trees::TreeNode>> {
    use crate::trees::{Kind, TreeNode};
    let pixels = pixels.to_vec();
    let row = self::stage(stage)?;
    #[cfg(feature = "l08")]
    if row.draws.traces() {
        return Some(traced(stage, scene, &pixels)?.iter().map(|(_, tree)| tree.into()).collect());
    }
    #[cfg(feature = "l01")]
    {
        let camera = l01_transforms::Camera::from_scene(&scene.camera, scene.width, scene.height).ok()?;
        let objects = if row.finds == Finds::Nothing { None } else { Some(intersector(stage, scene)?) };
        let tree = |(x, y): (u32, u32)| {
            let ray = camera.pixel_ray(x, y, scene.width, scene.height);
            let hit = objects.as_ref().and_then(|o| o.closest_hit(&ray, raylab::Interval::POSITIVE));
            #[allow(unused_mut)]
            let mut children = Vec::new();
            #[cfg(feature = "l07")]
            if let (Some(hit), Draws::Mirrored) = (&hit, row.draws) {
                for (k, direction, through) in sky_rays(scene, &ray, hit) {
                    let kind = if through { Kind::Transmitted } else { Kind::Reflected };
                    children.push(TreeNode::new(
                        kind,
                        hit.point,
                        direction,
                        k.max_element(),
                        None,
                        Vec::new(),
                    ));
                }
            }
            TreeNode::new(Kind::Eye, ray.origin, ray.dir, 1.0, hit.map(|h| (h.object, h.t)), children)
        };
        return Some(pixels.into_iter().map(tree).collect());
    }
    #[allow(unreachable_code)]
    None
}

/// The colours and ray trees of `pixels` of `scene` at stage 08 or 10.
#[cfg(feature = "l08")]
fn traced(stage: &str, scene: &Scene, pixels: &[(u32, u32)]) -> Option<Vec<(Color, l08_ray_tree::RayTree)>> {
    match self::stage(stage)?.draws {
        #[cfg(feature = "complete")]
        Draws::Complete => crate::tracer::pixel_trees(scene, pixels, &settings::scene_settings(scene)).ok(),
        Draws::Whitted => {
            let camera = l01_transforms::Camera::from_scene(&scene.camera, scene.width, scene.height).ok()?;
            let objects = l04_quadrics_transforms::BruteForce::new(&scene.objects);
            let world = l08_ray_tree::World::new(scene, &objects);
            let settings = settings::scene_settings(scene);
            let trace = |(x, y): (u32, u32)| {
                l08_ray_tree::trace_recorded(
                    &world,
                    &camera.pixel_ray(x, y, scene.width, scene.height),
                    &settings,
                )
            };
            Some(pixels.iter().map(|&pixel| trace(pixel)).collect())
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_abs_diff_eq;
    use raylab::{Float, Hit};

    #[test]
    fn the_sky_is_the_direction_as_a_colour_times_its_bands() {
        // Along −z from the origin: d = (0, 0, −1) → ½ + ½d = (½, ½, 0); the direction's bands
        // 0.8 + 0.2·cos 0·cos 0·cos(−24) = 0.8 + 0.2·0.4241790… = 0.8848358…; the origin's
        // bands at the origin 0.8 + 0.2 = 1. The length of dir plays no part.
        let ray = Ray::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -3.0));
        let expected = 0.5 * (0.8 + 0.2 * (24.0 as Float).cos());
        assert_abs_diff_eq!(sky(&ray), Color::new(expected, expected, 0.0), epsilon = 1e-6);
        assert_abs_diff_eq!(expected, 0.442_417_9, epsilon = 1e-6);
        // An origin half a unit along x: the origin's bands 0.8 + 0.2·cos(π) = 0.6.
        let moved = Ray::new(Vec3::new(0.5, 0.0, 0.0), ray.dir);
        assert_abs_diff_eq!(sky(&moved), 0.6 * sky(&ray), epsilon = 1e-6);
    }

    #[test]
    fn the_headlight_is_full_head_on_half_at_grazing_and_dim_for_a_flipped_normal() {
        let text = "[image]\nwidth = 4\nheight = 3\n[camera]\ntype = \"perspective\"\neye = [0, 0, 5]\n\
                    at = [0, 0, 0]\nfovy = 40\n";
        let scene = raylab::scene::parse_toml(text, std::path::Path::new("headlight.toml")).unwrap();
        let grey = Color::splat(0.5); // no material: the stage's grey
        let ray = Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::new(0.0, 0.0, -2.0));
        let hit = |normal: Vec3| Hit { normal, ..Hit::new(&ray, 2.0, Vec3::Z) };
        assert_abs_diff_eq!(headlight(&scene, &ray, &hit(Vec3::Z)), grey, epsilon = 1e-6);
        assert_abs_diff_eq!(headlight(&scene, &ray, &hit(Vec3::X)), 0.5 * grey, epsilon = 1e-6);
        assert_abs_diff_eq!(headlight(&scene, &ray, &hit(-Vec3::Z)), Color::ZERO, epsilon = 1e-6);
    }

    #[test]
    fn every_lecture_has_a_stage_and_its_needs_come_before_it() {
        // The rows in course order, one per lecture with scenes, the complete tracer last.
        let lectures: Vec<&str> = STAGES.iter().map(|s| s.lecture).collect();
        assert!(lectures.windows(2).all(|w| w[0] < w[1]), "{lectures:?}");
        assert_eq!(stage(FINAL_STAGE).map(|s| s.draws), Some(Draws::Complete));
        for file in crate::scenes::scene_files(None).unwrap() {
            assert!(stage(&file.lecture).is_some(), "lecture {} has scenes and no stage", file.lecture);
        }
        for row in STAGES {
            assert!(built(row.lecture), "stage {} is not built with every lecture", row.lecture);
            assert!(needs(row.lecture).iter().all(|need| need[..2] < *row.lecture), "stage {}", row.lecture);
            // A stage that finds hits draws with the camera; one that draws the camera's rays alone
            // finds none.
            assert_eq!(row.finds == Finds::Nothing, row.draws == Draws::Sky, "stage {}", row.lecture);
            // Its geometry is graded only with intersections of its own.
            assert!(!row.geometry_graded || row.geometry == row.finds, "stage {}", row.lecture);
        }
    }
}
