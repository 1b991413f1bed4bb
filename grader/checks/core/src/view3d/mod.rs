//! The ray tree of a pixel in 3D over its scene, as one offline HTML page: the grader tessellates
//! the scene into triangles and walks the tree into segments (nothing is traced in the browser),
//! and `grader/protocol/assets/view3d.js`, a small hand-written WebGL module (the report draws
//! with it too), draws them with an orbiting camera. `grader render SCENE --tree X,Y --view
//! FILE` writes one.

use std::f64::consts::PI;
use std::fmt::Write as _;

use raylab::scene::{Camera, LightKind, Shape};
use raylab::{Color, Float, Scene, Vec3};
use serde::Serialize;

use crate::trees::{GRID, GridTrees, Kind, TreeNode, grid, nearest};

mod tessellate;
use tessellate::{simplified, world_triangles};

/// The drawing code, put into each page whole.
const SCRIPT: &str = raylab_protocol::VIEW3D_SCRIPT;

/// Slices around a sphere's axis (and half as many rings from pole to pole) where the scene has
/// few spheres; sides of a cylinder or a cone.
const SLICES: usize = 32;

/// The page's weight is its triangles (~60 bytes each): the spheres of a scene are drawn in at
/// most this many (32, 16 or 8 slices: 06's hundred spheres in 8), and a mesh in at most
/// [`MESH_TRIANGLES`] (simplified where it has more).
const SPHERE_TRIANGLES: usize = 8192;
const MESH_TRIANGLES: usize = 8192;

/// What the page draws.
#[derive(Serialize)]
pub struct View {
    title: String,
    camera: ViewCamera,
    /// Half the diagonal of the scene's bounds (planes aside): the length of a ray that escapes.
    radius: f32,
    objects: Vec<ViewObject>,
    /// The lights as line segments (x₀ y₀ z₀ x₁ y₁ z₁): a cross at a point, a rect's outline.
    lights: Vec<[f32; 6]>,
    trees: Vec<ViewTree>,
    /// In the report: the expected and your trees of every grid pixel, for a click to pick from.
    #[serde(skip_serializing_if = "Option::is_none")]
    grid: Option<GridPair>,
    #[serde(skip)]
    extent: Extent,
}

#[derive(Serialize)]
struct GridPair {
    step: u32,
    expected: Vec<ViewTree>,
    yours: Vec<ViewTree>,
}

#[derive(Serialize)]
struct ViewCamera {
    eye: [f32; 3],
    at: [f32; 3],
    up: [f32; 3],
    /// The vertical field of view in radians (an orthographic camera is shown in perspective).
    fovy: f32,
}

#[derive(Serialize)]
struct ViewObject {
    /// `#N`, as the text tree names it.
    name: String,
    color: [f32; 3],
    /// 1 for an opaque object; a transparent one lets the rays inside it be seen.
    opacity: f32,
    /// Nine numbers a triangle, in world space.
    triangles: Vec<f32>,
}

/// One pixel's tree: its rays as segments, and its text (as `grader render --tree` prints it).
#[derive(Clone, Debug, Serialize)]
pub struct ViewTree {
    label: String,
    pixel: [u32; 2],
    text: String,
    segments: Vec<Segment>,
}

#[derive(Clone, Copy, Debug, Serialize)]
#[serde(rename_all = "lowercase")]
enum SegmentKind {
    Eye,
    Shadow,
    Reflected,
    Transmitted,
}

#[derive(Clone, Debug, Serialize)]
struct Segment {
    kind: SegmentKind,
    from: [f32; 3],
    to: [f32; 3],
    weight: f32,
    /// The object the ray hit (for a shadow ray: its blocker), or `null`.
    hit: Option<usize>,
}

/// How large a scene is drawn: the length of a ray that escapes, and the step its coordinates are
/// rounded to.
#[derive(Clone, Copy, Debug, Default)]
pub struct Extent {
    /// Half the diagonal of the scene's bounds (planes aside).
    radius: Float,
    /// 10⁻⁴ of the scene's size, a pixel's worth of the view (five digits, not eight: the page's
    /// weight is its numbers).
    step: f64,
}

impl Extent {
    fn from_bounds(radius: Float) -> Self {
        Extent { radius, step: 10f64.powf((radius as f64).log10().floor() - 4.0) }
    }
}

impl ViewTree {
    /// The tree of pixel `pixel` under `label` ("yours", "expected"), its segments rounded to the
    /// scene's step.
    pub fn new(scene: &Scene, extent: Extent, label: &str, pixel: (u32, u32), tree: &TreeNode) -> Self {
        let mut segments = Vec::new();
        walk(scene, extent, tree, &mut segments);
        ViewTree { label: label.to_owned(), pixel: [pixel.0, pixel.1], text: tree.to_string(), segments }
    }
}

impl View {
    /// The scene's geometry and lights, with no tree yet.
    pub fn new(scene: &Scene, title: &str) -> Self {
        let spheres = scene.objects.iter().filter(|o| matches!(o.shape, Shape::Sphere { .. })).count();
        let slices =
            [32, 16, 8].into_iter().find(|&s| spheres * 2 * s * (s / 2 - 1) <= SPHERE_TRIANGLES).unwrap_or(8);
        let solids: Vec<Vec<[Vec3; 3]>> = scene
            .objects
            .iter()
            .map(|o| match o.shape {
                Shape::Mesh(_) => simplified(world_triangles(o, None, slices), MESH_TRIANGLES),
                _ => world_triangles(o, None, slices),
            })
            .collect();
        let (center, radius) = bounds(scene, &solids);
        let step = Extent::from_bounds(radius).step;
        let objects = scene
            .objects
            .iter()
            .zip(solids)
            .enumerate()
            .map(|(index, (object, solid))| {
                let triangles = if matches!(object.shape, Shape::Plane { .. }) {
                    world_triangles(object, Some((center, radius)), slices)
                } else {
                    solid
                };
                let material = scene.materials.get(object.material);
                let diffuse = material.map_or(Color::splat(0.7), |m| m.diffuse);
                let transparent =
                    material.map_or(0.0, |m| m.transparent.clamp(Color::ZERO, Color::ONE).max_element());
                ViewObject {
                    name: format!("#{index}"),
                    color: shown_color(diffuse),
                    opacity: (1.0 - 0.75 * transparent) as f32,
                    triangles: triangles
                        .iter()
                        .flatten()
                        .flat_map(|p| p.to_array())
                        .map(|x| quantized(x, step))
                        .collect(),
                }
            })
            .collect();
        let (eye, at, up, fovy) = match scene.camera {
            Camera::Perspective { eye, at, up, fovy } => (eye, at, up, fovy as f64),
            Camera::Orthographic { eye, at, up, .. } => (eye, at, up, PI / 4.0),
        };
        View {
            title: title.to_owned(),
            camera: ViewCamera { eye: f32s(eye), at: f32s(at), up: f32s(up), fovy: fovy as f32 },
            radius: radius as f32,
            objects,
            lights: light_marks(scene, radius),
            trees: Vec::new(),
            grid: None,
            extent: Extent::from_bounds(radius),
        }
    }

    /// Adds the tree of pixel `pixel` under `label` ("yours", "expected").
    pub fn add_tree(&mut self, scene: &Scene, label: &str, pixel: (u32, u32), tree: &TreeNode) {
        self.trees.push(ViewTree::new(scene, self.extent, label, pixel, tree));
    }

    /// The report's view: the expected and your trees of every grid pixel, the pair of the grid
    /// pixel nearest `shown` drawn first. An error when the trees are not of this scene's grid.
    pub fn set_grid(
        &mut self,
        scene: &Scene,
        expected: &GridTrees,
        yours: &[TreeNode],
        shown: (u32, u32),
    ) -> Result<(), String> {
        let pixels = grid(scene.width, scene.height);
        if (expected.grid, expected.width, expected.height) != (GRID, scene.width, scene.height)
            || expected.trees.len() != pixels.len()
            || yours.len() != pixels.len()
        {
            return Err(format!(
                "the blessed trees are of a {}×{} image's grid of {} ({} trees), yours of {} trees; the scene is {}×{}, \
                 its grid of {GRID} has {} pixels",
                expected.width,
                expected.height,
                expected.grid,
                expected.trees.len(),
                yours.len(),
                scene.width,
                scene.height,
                pixels.len()
            ));
        }
        let views = |trees: &[TreeNode], label: &str| -> Vec<ViewTree> {
            pixels.iter().zip(trees).map(|(&p, t)| ViewTree::new(scene, self.extent, label, p, t)).collect()
        };
        let (expected, yours) = (views(&expected.trees, "expected"), views(yours, "yours"));
        let near = nearest(shown, scene.width, scene.height);
        let at = |trees: &[ViewTree]| trees.iter().find(|t| t.pixel == [near.0, near.1]).cloned();
        self.trees = at(&expected).into_iter().chain(at(&yours)).collect();
        self.grid = Some(GridPair { step: GRID, expected, yours });
        Ok(())
    }

    /// The data as a script for the report, which loads it when its view is opened:
    /// `raylabViewData[key] = {…}`.
    pub fn to_script(&self, key: &str) -> Result<String, String> {
        let data = serde_json::to_string(self).map_err(|e| e.to_string())?;
        let key = serde_json::to_string(key).map_err(|e| e.to_string())?;
        Ok(format!("(window.raylabViewData = window.raylabViewData || {{}})[{key}] = {data};\n"))
    }

    /// The page: the data as JSON and the drawing code, nothing fetched.
    pub fn to_html(&self) -> Result<String, String> {
        // `</` would end the script element the JSON is in.
        let data = serde_json::to_string(self).map_err(|e| e.to_string())?.replace("</", "<\\/");
        let mut page = String::new();
        let view_style = raylab_protocol::VIEW3D_STYLE;
        let _ = write!(
            page,
            "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{title}</title>\n<style>{STYLE}{view_style}</style></head>\n\
             <body><h1>{title}</h1>\n<div id=\"view\"></div>\n\
             <script type=\"application/json\" id=\"view3d-data\">{data}</script>\n<script>{SCRIPT}</script>\n\
             <script>raylabView3d(document.getElementById('view'), JSON.parse(document.getElementById('view3d-data').textContent));</script>\n\
             </body></html>\n",
            title = escape(&self.title),
        );
        Ok(page)
    }
}

/// A page's own styles besides the view's (`raylab_protocol::VIEW3D_STYLE`).
const STYLE: &str = include_str!("../../assets/view3d-page.css");

fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;")
}

/// `x` to the nearest multiple of `step`, as the f32 that prints shortest.
fn quantized(x: Float, step: f64) -> f32 {
    ((x as f64 / step).round() * step) as f32
}

fn f32s(v: Vec3) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}

/// A colour the flat shading can show: dark materials lifted so that they stand out from the
/// dark background, every channel in [0, 1].
fn shown_color(c: Color) -> [f32; 3] {
    let c = c.clamp(Color::ZERO, Color::ONE);
    let lifted = Color::splat(0.25) + 0.75 * c;
    f32s(lifted)
}

/// The segments of `tree` and of every ray below it.
fn walk(scene: &Scene, extent: Extent, tree: &TreeNode, out: &mut Vec<Segment>) {
    let v = |a: [f64; 3]| Vec3::new(a[0] as Float, a[1] as Float, a[2] as Float);
    let (origin, dir) = (v(tree.o), v(tree.d));
    let unit = dir.normalize_or_zero();
    let length = match (tree.k, tree.h) {
        (_, Some((_, t))) => t as Float * dir.length(),
        (Kind::Shadow, None) => reach_light(scene, origin, unit).unwrap_or(extent.radius),
        (_, None) => extent.radius,
    };
    let kind = match tree.k {
        Kind::Eye => SegmentKind::Eye,
        Kind::Shadow => SegmentKind::Shadow,
        Kind::Reflected => SegmentKind::Reflected,
        Kind::Transmitted => SegmentKind::Transmitted,
    };
    let rounded = |p: Vec3| f32s(p).map(|x| quantized(x as Float, extent.step));
    out.push(Segment {
        kind,
        from: rounded(origin),
        to: rounded(origin + length * unit),
        weight: tree.w as f32,
        hit: tree.h.map(|(object, _)| object),
    });
    for child in &tree.c {
        walk(scene, extent, child, out);
    }
}

/// How far along the unit `dir` from `origin` a shadow ray that saw its light went: to the
/// nearest light it points at (a point or spot light on the ray; a rect or the disc a ball light
/// is sampled on, crossed), `None` for a directional light or none found. The ray's numbers are
/// the printed ones (to 5·10⁻⁴ each): "on the ray" allows 2·10⁻³ per unit of distance, and a
/// rect's or a disc's edge as much.
fn reach_light(scene: &Scene, origin: Vec3, dir: Vec3) -> Option<Float> {
    let on_ray = |p: Vec3| {
        let t = (p - origin).dot(dir);
        (t > 0.0 && (origin + t * dir - p).length() <= 2e-3 * t.max(1.0)).then_some(t)
    };
    scene
        .lights
        .iter()
        .filter_map(|light| match light.kind {
            LightKind::Directional { .. } => None,
            LightKind::Point { position, .. } | LightKind::Spot { position, .. } => on_ray(position),
            LightKind::Rect { corner, edge_u, edge_v, .. } => {
                let n = edge_u.cross(edge_v);
                let t = (corner - origin).dot(n) / dir.dot(n);
                let p = origin + t * dir - corner;
                // The point's coordinates along the edges, from the dual basis.
                let (a, b) = (
                    p.dot(edge_v.cross(n)) / edge_u.dot(edge_v.cross(n)),
                    p.dot(edge_u.cross(n)) / edge_v.dot(edge_u.cross(n)),
                );
                let slack = 2e-3 * t.max(1.0) / edge_u.length().min(edge_v.length());
                let inside = (-slack..=1.0 + slack).contains(&a) && (-slack..=1.0 + slack).contains(&b);
                (t.is_finite() && t > 0.0 && inside).then_some(t)
            }
            LightKind::Sphere { center, radius, .. } => {
                let w = (origin - center).normalize_or_zero();
                let t = (center - origin).dot(w) / dir.dot(w);
                let inside = (origin + t * dir - center).length() <= radius * 1.001 + 2e-3 * t.max(1.0);
                (t.is_finite() && t > 0.0 && inside).then_some(t)
            }
        })
        .min_by(|a, b| a.total_cmp(b))
}

/// The lights, as segments: a small cross at a point or spot light, a rect's outline, three
/// great circles of a ball light.
fn light_marks(scene: &Scene, radius: Float) -> Vec<[f32; 6]> {
    let segment = |a: Vec3, b: Vec3| {
        let (a, b) = (f32s(a), f32s(b));
        [a[0], a[1], a[2], b[0], b[1], b[2]]
    };
    let mut marks = Vec::new();
    for light in &scene.lights {
        match light.kind {
            LightKind::Directional { .. } => {}
            LightKind::Point { position, .. } | LightKind::Spot { position, .. } => {
                let s = 0.03 * radius;
                for axis in [Vec3::X, Vec3::Y, Vec3::Z] {
                    marks.push(segment(position - s * axis, position + s * axis));
                }
            }
            LightKind::Rect { corner, edge_u, edge_v, .. } => {
                let corners = [corner, corner + edge_u, corner + edge_u + edge_v, corner + edge_v];
                for i in 0..4 {
                    marks.push(segment(corners[i], corners[(i + 1) % 4]));
                }
            }
            LightKind::Sphere { center, radius: r, .. } => {
                for (u, v) in [(Vec3::X, Vec3::Y), (Vec3::Y, Vec3::Z), (Vec3::Z, Vec3::X)] {
                    let at = |k: usize| {
                        let a = 2.0 * PI * k as f64 / SLICES as f64;
                        center + r * (a.cos() as Float * u + a.sin() as Float * v)
                    };
                    marks.extend((0..SLICES).map(|k| segment(at(k), at(k + 1))));
                }
            }
        }
    }
    marks
}

/// The centre and radius of the scene's bounds: every object but planes, the camera, the
/// lights that have a place. Never a zero radius.
fn bounds(scene: &Scene, solids: &[Vec<[Vec3; 3]>]) -> (Vec3, Float) {
    let (eye, at) = match scene.camera {
        Camera::Perspective { eye, at, .. } | Camera::Orthographic { eye, at, .. } => (eye, at),
    };
    let mut points: Vec<Vec3> = vec![eye, at];
    points.extend(solids.iter().flatten().flatten().copied());
    for light in &scene.lights {
        match light.kind {
            LightKind::Point { position, .. } | LightKind::Spot { position, .. } => points.push(position),
            LightKind::Rect { corner, edge_u, edge_v, .. } => {
                points.extend([corner, corner + edge_u + edge_v])
            }
            LightKind::Sphere { center, .. } => points.push(center),
            LightKind::Directional { .. } => {}
        }
    }
    let points: Vec<Vec3> = points.into_iter().filter(|p| p.is_finite()).collect();
    let min = points.iter().fold(Vec3::splat(Float::INFINITY), |m, p| m.min(*p));
    let max = points.iter().fold(Vec3::splat(Float::NEG_INFINITY), |m, p| m.max(*p));
    let center = 0.5 * (min + max);
    let radius = 0.5 * (max - min).length();
    if center.is_finite() && radius.is_finite() && radius > 0.0 {
        (center, radius)
    } else {
        (Vec3::ZERO, 1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The blessed trees of 08's Whitted scene at grid pixel (152, 72), as the report's view
    /// holds them: the text of `grader render --tree 152,72` (the snapshot below), read as the
    /// slides draw it. The eye ray hits the glass ball (#2); its k_r = 0.1 and k_t = 0.9 split
    /// the weight (0.1, 0.9; inside 0.9·0.1 = 0.09, 0.09·0.9 = 0.081, 0.9·0.9 = 0.81); the ray
    /// reflected inside crosses a chord as long as the one refracted in (t = 1.358 both: a
    /// reflection inside a sphere keeps the angle); the shadow ray from the back wall is blocked
    /// by the ball itself; the way out lands on a tile (#12) in the chrome ball's (#1) shadow.
    /// Each segment starts at its ray's printed origin and, for a hit, ends at origin + t·dir
    /// (to 2·10⁻³·(1 + t): the printed origin, direction and t are rounded to 10⁻³).
    #[test]
    fn the_blessed_whitted_trees_are_the_printed_tree() {
        let root = crate::scenes::workspace_root().join("lectures/08-ray-tree");
        let scene = raylab::scene::load(root.join("scenes/whitted.toml")).unwrap();
        let blessed: GridTrees = serde_json::from_str(
            &std::fs::read_to_string(root.join("snapshots/whitted.trees.json")).unwrap(),
        )
        .unwrap();
        let mut view = View::new(&scene, "whitted");
        view.set_grid(&scene, &blessed, &blessed.trees, (150, 70)).unwrap();
        let shown = &view.trees[0];
        assert_eq!(shown.pixel, [152, 72]);
        insta::assert_snapshot!(shown.text, @r"
        eye from (0.000, 2.200, 6.500) dir (0.247, -0.206, -0.947) weight 1.000: hits #2 at t = 5.610
          shadow from (1.385, 1.042, 1.188) dir (-0.610, 0.689, 0.391) weight 1.000: reaches the light
          reflected from (1.385, 1.042, 1.188) dir (0.985, 0.162, -0.051) weight 0.100: misses
          transmitted from (1.385, 1.042, 1.188) dir (-0.104, -0.271, -0.957) weight 0.900: hits #2 at t = 1.358
            shadow from (1.244, 0.673, -0.111) dir (-0.533, 0.670, 0.517) weight 0.900: blocked by #2 at t = 1.272
            reflected from (1.244, 0.673, -0.111) dir (-0.834, -0.002, 0.552) weight 0.090: hits #2 at t = 1.358
              transmitted from (0.112, 0.670, 0.639) dir (-0.596, 0.104, 0.796) weight 0.081: misses
            transmitted from (1.244, 0.673, -0.111) dir (-0.441, -0.302, -0.845) weight 0.810: hits #12 at t = 2.235
              shadow from (0.258, -0.002, -2.000) dir (-0.358, 0.660, 0.660) weight 0.810: blocked by #1 at t = 0.836
        ");
        // (That the blessed file is what the reference traces today is bless's test.)
        assert_eq!(shown.segments.len(), shown.text.lines().count(), "a segment per ray");
        // Each segment read against its line of the text: kind, origin, and for a hit the end.
        let triple = |line: &str, after: &str| -> Vec3 {
            let from = line.find(after).unwrap() + after.len() + 1;
            let v: Vec<Float> = line[from..from + line[from..].find(')').unwrap()]
                .split(", ")
                .map(|x| x.parse().unwrap())
                .collect();
            Vec3::new(v[0], v[1], v[2])
        };
        for (line, segment) in shown.text.lines().zip(&shown.segments) {
            let kind = serde_json::to_value(segment.kind).unwrap();
            assert_eq!(kind.as_str(), line.trim_start().split(' ').next(), "{line}");
            let (origin, dir) = (triple(line, " from "), triple(line, " dir "));
            let close =
                |a: [f32; 3], b: Vec3, within: Float| (0..3).all(|i| (a[i] as Float - b[i]).abs() <= within);
            assert!(close(segment.from, origin, 1e-3), "{line}: {segment:?}");
            let t = line.rsplit_once(" at t = ").map(|(_, t)| t.parse::<Float>().unwrap());
            assert_eq!(segment.hit.is_some(), t.is_some(), "{line}");
            if let Some(t) = t {
                assert!(close(segment.to, origin + t * dir, 2e-3 * (1.0 + t)), "{line}: {segment:?}");
            }
        }
    }

    /// A shadow ray's segment ends at the light it saw: the point light 5 away along it, the
    /// rect it crosses at t = 2, the ball light's disc at t = 4.
    #[test]
    fn an_unblocked_shadow_ray_ends_at_its_light() {
        use raylab::scene::{Attenuation, Light};
        let light = |kind| Light { color: Color::ONE, shadows: true, kind };
        let mut scene = Scene {
            camera: Camera::Perspective { eye: Vec3::Z, at: Vec3::ZERO, up: Vec3::Y, fovy: 1.0 },
            width: 4,
            height: 4,
            background: Color::ZERO,
            ambient: Color::ZERO,
            lights: Vec::new(),
            materials: Vec::new(),
            objects: Vec::new(),
            render: Default::default(),
        };
        scene.lights = vec![light(LightKind::Point {
            position: Vec3::new(0.0, 5.0, 0.0),
            attenuation: Attenuation::default(),
        })];
        assert_eq!(reach_light(&scene, Vec3::ZERO, Vec3::Y), Some(5.0));
        assert_eq!(reach_light(&scene, Vec3::ZERO, Vec3::X), None);
        scene.lights = vec![light(LightKind::Rect {
            corner: Vec3::new(-1.0, 2.0, -1.0),
            edge_u: Vec3::new(2.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 0.0, 2.0),
            attenuation: Attenuation::default(),
        })];
        assert_eq!(reach_light(&scene, Vec3::ZERO, Vec3::Y), Some(2.0));
        assert_eq!(reach_light(&scene, Vec3::ZERO, Vec3::new(0.8, 0.6, 0.0)), None);
        scene.lights = vec![light(LightKind::Sphere {
            center: Vec3::new(0.0, 4.0, 0.0),
            radius: 1.0,
            attenuation: Attenuation::default(),
        })];
        let t = reach_light(&scene, Vec3::ZERO, Vec3::new(0.1, 1.0, 0.0).normalize()).unwrap();
        assert!((t - 4.0 * Vec3::new(0.1, 1.0, 0.0).length()).abs() < 1e-4, "{t}");
    }
}
