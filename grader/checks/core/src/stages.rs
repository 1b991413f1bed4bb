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

use raylab::{Color, Hit, Image, Intersector, Ray, Scene, Vec3};

use crate::trees::TreeNode;

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
    /// Whether it casts shadow rays (06's shading).
    pub fn shadows(self) -> bool {
        matches!(self, Draws::Shadowed | Draws::Whitted | Draws::Complete)
    }

    /// Whether mirrors and glass show something in 07's directions.
    pub fn mirrors(self) -> bool {
        matches!(self, Draws::Mirrored | Draws::Whitted | Draws::Complete)
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

/// Whether stage `lecture`'s code is in this build: all it draws with is lent (its lecture and
/// the ones it draws with compiled: the lecture's feature turns those on).
pub fn built(lecture: &str) -> bool {
    let (Some(row), lent) = (stage(lecture), lent()) else { return false };
    let finds = row.finds == Finds::Nothing || lent.finder(row.finds).is_some();
    let draws = match row.draws {
        Draws::Sky | Draws::Headlight => lent.camera.is_some(),
        Draws::Local | Draws::Shadowed | Draws::Mirrored => {
            lent.camera.is_some() && lent.drawer(row.draws).is_some()
        }
        Draws::Whitted | Draws::Complete => lent.drawer(row.draws).is_some(),
    };
    finds && draws
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

/// The primary ray of pixel (x, y): lecture 01's camera over a scene.
pub type PixelRays = Box<dyn Fn(u32, u32) -> Ray + Sync>;

/// Lecture 01's camera over a scene, or why it has none.
pub type Camera = fn(&Scene) -> Result<PixelRays, String>;

/// The colours and ray trees of some pixels of a scene, at a stage that traces (08, 10).
pub type Traced = fn(&Scene, &[(u32, u32)]) -> Option<Vec<(Color, TreeNode)>>;

/// An intersector over a scene's objects.
pub type Finder = for<'a> fn(&'a Scene) -> Box<dyn Intersector + 'a>;

/// The calls on a picture's path at one pixel, made into a trail (the `path` module): the stage,
/// the scene, the pixel. `None` where the stage makes none there.
pub type Calls = fn(&str, &Scene, (u32, u32), &mut crate::path::Trail) -> Option<()>;

/// How a stage that shades (05 on) draws, lent by its lecture's checks.
#[derive(Clone, Copy)]
pub enum Drawer {
    /// The colour of each eye ray's closest hit, found by the stage's intersector (05–07), and at
    /// 07 the rays to the sky that colour shows (k, direction, whether transmitted).
    Shades {
        shade: fn(&Scene, &dyn Intersector, &Ray, &Hit) -> Color,
        sky_rays: Option<SkyRays>,
        calls: Calls,
    },
    /// A tracer of its own (08, 10): the picture, the colours and ray trees of some pixels, and the
    /// exercise that makes a pixel from the calls on its path.
    Traces {
        render: fn(&Scene) -> Result<Image, String>,
        traced: Traced,
        calls: Calls,
        pixel_loop: fn(&Scene) -> &'static str,
    },
}

/// Stage 07's rays to the sky from a hit: (k, direction, whether it is the transmitted one).
pub type SkyRays = fn(&Scene, &Ray, &Hit) -> Vec<(Color, Vec3, bool)>;

/// Which geometry image: object ids, depths or normals (lecture 02's three).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GeometryImage {
    Id,
    Depth,
    Normal,
}

/// Lecture 02's geometry images and the colour of an object's id in them.
#[derive(Clone, Copy)]
pub struct Geometry {
    /// The image of `scene` through an intersector, from lecture 01's camera.
    pub image: fn(&Scene, GeometryImage, &dyn Intersector) -> Result<Image, String>,
    /// The colour object `index` has in an id image.
    pub id_color: fn(usize) -> Color,
}

/// The code the stages draw with, lent by the lectures built (each lecture's checks crate lends
/// its own, `stage::lend`, and the binary's `main` installs the whole, [`install`], before a check
/// runs): what lets the core draw a lecture's pictures without depending on the lecture. A stage is built
/// when all it draws with is lent ([`built`]).
#[derive(Default)]
pub struct Lent {
    /// Lecture 01's camera: each pixel's primary ray.
    pub camera: Option<Camera>,
    /// The intersectors, by the [`Finds`] that names them (02, 03, 04, 09).
    pub finders: Vec<(Finds, Finder)>,
    /// Lecture 02's geometry images.
    pub geometry: Option<Geometry>,
    /// The shading stages' drawing, by the [`Draws`] that names it (05, 06, 07, 08, 10).
    pub drawers: Vec<(Draws, Drawer)>,
}

impl Lent {
    fn finder(&self, finds: Finds) -> Option<Finder> {
        self.finders.iter().find(|(f, _)| *f == finds).map(|&(_, finder)| finder)
    }

    fn drawer(&self, draws: Draws) -> Option<Drawer> {
        self.drawers.iter().find(|(d, _)| *d == draws).map(|&(_, drawer)| drawer)
    }
}

static LENT: std::sync::OnceLock<Lent> = std::sync::OnceLock::new();

/// Makes `lent` the stages' code for the rest of the process; the first call wins.
pub fn install(lent: Lent) {
    let _ = LENT.set(lent);
}

/// The code lent to the stages; nothing before [`install`].
pub fn lent() -> &'static Lent {
    static NOTHING: std::sync::OnceLock<Lent> = std::sync::OnceLock::new();
    LENT.get().unwrap_or_else(|| NOTHING.get_or_init(Lent::default))
}

/// The drawer of stage `lecture`, where it shades and is lent.
pub fn drawer(lecture: &str) -> Option<Drawer> {
    lent().drawer(stage(lecture)?.draws)
}

/// Each pixel's primary ray of `scene` from lecture 01's camera, where it is lent.
pub fn camera(scene: &Scene) -> Option<Result<PixelRays, String>> {
    Some((lent().camera?)(scene))
}

/// Lecture 02's geometry images, where they are lent.
pub fn geometry() -> Option<Geometry> {
    lent().geometry
}

/// Scene `scene` drawn by stage `lecture`.
pub fn render(lecture: &str, scene: &Scene) -> Result<Image, String> {
    let unbuilt =
        || format!("stage {lecture} is not in this build: its lecture or one it draws with does not compile");
    let Some(stage) = stage(lecture).filter(|_| built(lecture)) else { return Err(unbuilt()) };
    let drawer = lent().drawer(stage.draws);
    if let Some(Drawer::Traces { render, .. }) = drawer {
        return render(scene);
    }
    let rays = camera(scene).ok_or_else(unbuilt)??;
    let (w, h) = (scene.width, scene.height);
    let pixels =
        |f: &(dyn Fn(&Ray) -> Color + Sync)| raylab::render::render_image(w, h, |x, y| f(&rays(x, y))).0;
    if stage.draws == Draws::Sky {
        return Ok(pixels(&sky));
    }
    let objects = intersector(lecture, scene).ok_or_else(unbuilt)?;
    let objects = objects.as_ref();
    // The closest hit in (0, ∞), shaded by the stage, or the background.
    let drawn = |shade: &(dyn Fn(&Ray, &Hit) -> Color + Sync)| {
        pixels(&|ray: &Ray| match objects.closest_hit(ray, raylab::Interval::POSITIVE) {
            Some(hit) => shade(ray, &hit),
            None => scene.background,
        })
    };
    match drawer {
        Some(Drawer::Shades { shade, .. }) => Ok(drawn(&|ray, hit| shade(scene, objects, ray, hit))),
        _ if stage.draws == Draws::Headlight => Ok(drawn(&|ray, hit| headlight(scene, ray, hit))),
        _ => Err(unbuilt()),
    }
}

/// The intersector stage `lecture` finds the closest hits with (its row's [`Finds`]); `None`
/// at a stage that finds none, or where it is not built.
pub fn intersector<'a>(lecture: &str, scene: &'a Scene) -> Option<Box<dyn Intersector + 'a>> {
    finder(stage(lecture)?.finds, scene)
}

/// The intersector `finds` names, over `scene`'s objects, where it is built.
pub fn finder(finds: Finds, scene: &Scene) -> Option<Box<dyn Intersector + '_>> {
    Some((lent().finder(finds)?)(scene))
}

/// The calls on stage `stage`'s path at pixel `pixel` of `scene` (the `path` module); `None` at a
/// stage without calls or whose code is not in this build.
pub fn calls(stage: &str, scene: &Scene, pixel: (u32, u32)) -> Option<Vec<crate::path::Call>> {
    let (Drawer::Shades { calls, .. } | Drawer::Traces { calls, .. }) =
        drawer(stage).filter(|_| built(stage))?;
    crate::path::record(|trail| calls(stage, scene, pixel, trail))
}

/// The exercise that makes a pixel of stage `stage` from the calls on its path, where that is a
/// student's: lecture 08's `render` (one eye ray per pixel centre), or lecture 10's
/// `render_supersampled` where the scene asks for several rays. A pixel that differs where every
/// call agrees is that exercise's.
pub fn pixel_loop(stage: &str, scene: &Scene) -> Option<&'static str> {
    match drawer(stage)? {
        Drawer::Traces { pixel_loop, .. } => Some(pixel_loop(scene)),
        Drawer::Shades { .. } => None,
    }
}

/// The ray tree of pixel (x, y) of `scene` at a stage that traces one (08 and
/// 10), as text with the pixel's colour; `None` at the other stages.
pub fn pixel_tree(stage: &str, scene: &Scene, pixel: (u32, u32)) -> Option<String> {
    let Some(Drawer::Traces { traced, .. }) = drawer(stage).filter(|_| built(stage)) else { return None };
    let (color, tree) = traced(scene, &[pixel])?.pop()?;
    Some(format!("colour ({:.3}, {:.3}, {:.3})\n{tree}", color.x, color.y, color.z))
}

/// The ray trees of the report's grid of pixels ([`crate::trees::grid`]) for its 3D view: at
/// stages 08 and 10 the traced trees (lecture 08's), before them the rays the stage draws with —
/// the camera's ray (01), its closest hit (02–07, 09; stages 05 and 06 shade inside 05's and 06's
/// functions, which record nothing), and at 07 the mirror and refracted rays to the sky. `None`
/// where the stage is not built.
pub fn grid_trees(stage: &str, scene: &Scene) -> Option<Vec<TreeNode>> {
    trees(stage, scene, &crate::trees::grid(scene.width, scene.height))
}

/// The ray trees of `pixels` at stage `stage`, as [`grid_trees`] makes them.
pub fn trees(stage: &str, scene: &Scene, pixels: &[(u32, u32)]) -> Option<Vec<TreeNode>> {
    use crate::trees::Kind;
    let row = self::stage(stage).filter(|_| built(stage))?;
    let drawer = lent().drawer(row.draws);
    if let Some(Drawer::Traces { traced, .. }) = drawer {
        return Some(traced(scene, pixels)?.into_iter().map(|(_, tree)| tree).collect());
    }
    let sky_rays = match drawer {
        Some(Drawer::Shades { sky_rays, .. }) => sky_rays,
        _ => None,
    };
    let rays = camera(scene)?.ok()?;
    let objects = if row.finds == Finds::Nothing { None } else { Some(intersector(stage, scene)?) };
    let tree = |&(x, y): &(u32, u32)| {
        let ray = rays(x, y);
        let hit = objects.as_ref().and_then(|o| o.closest_hit(&ray, raylab::Interval::POSITIVE));
        let mut children = Vec::new();
        if let (Some(hit), Some(sky_rays)) = (&hit, sky_rays) {
            for (k, direction, through) in sky_rays(scene, &ray, hit) {
                let kind = if through { Kind::Transmitted } else { Kind::Reflected };
                children.push(TreeNode::new(kind, hit.point, direction, k.max_element(), None, Vec::new()));
            }
        }
        TreeNode::new(Kind::Eye, ray.origin, ray.dir, 1.0, hit.map(|h| (h.object, h.t)), children)
    };
    Some(pixels.iter().map(tree).collect())
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
            assert!(needs(row.lecture).iter().all(|need| need[..2] < *row.lecture), "stage {}", row.lecture);
            // A stage that finds hits draws with the camera; one that draws the camera's rays alone
            // finds none.
            assert_eq!(row.finds == Finds::Nothing, row.draws == Draws::Sky, "stage {}", row.lecture);
            // Its geometry is graded only with intersections of its own.
            assert!(!row.geometry_graded || row.geometry == row.finds, "stage {}", row.lecture);
        }
    }
}
