//! The ray tree of one pixel, recorded while it is traced.
//!
//! Every ray the tracer casts for a pixel is a node: the eye ray at the
//! root, below each node the shadow rays of its local shading, then its
//! reflected and transmitted rays, each with its own subtree. The recording
//! is not a second tracer: [`trace_recorded`] runs the very code of
//! [`crate::trace`] with two hooks.
//!
//! - The tracer's one door for new rays, `trace_node`, opens a node for each
//!   eye, reflected or transmitted ray it is given and closes it when the
//!   ray's colour is known (and counts the ray), so the tree's shape is the
//!   recursion's shape.
//! - The [`Intersector`] the traced code sees is a recording wrapper around
//!   the world's one: a ray's first `closest_hit` is its own hit; every later
//!   call while its node is open is a shadow ray of its shading (06's
//!   `occluded` asks `any_hit`, its `transmittance` walk one `closest_hit`
//!   per segment), recorded as a shadow child.
//!
//! The exercise in `trace.rs` therefore holds no recording code: it hands
//! the recorder it was given to its recursive calls, that is all.
//! Book: §8.5 Seeing the ray tree.

use std::fmt;
use std::sync::{Mutex, MutexGuard};

use raylab::{Color, Float, Hit, Intersector, Interval, Ray, Vec3};

use crate::settings::TraceSettings;
use crate::trace::trace_node;
use crate::world::World;

/// What a ray in the tree is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RayKind {
    /// The ray from the camera (the root).
    Eye,
    /// A ray from a surface point toward a light.
    Shadow,
    /// A mirror ray.
    Reflected,
    /// A refracted ray, through a transparent surface.
    Transmitted,
}

impl RayKind {
    fn name(self) -> &'static str {
        match self {
            RayKind::Eye => "eye",
            RayKind::Shadow => "shadow",
            RayKind::Reflected => "reflected",
            RayKind::Transmitted => "transmitted",
        }
    }
}

/// One ray of a pixel's ray tree and, below it, the rays it spawned.
///
/// `hit` is the object the ray found first (its index in the scene's
/// objects) and the ray parameter t there; `None` when it found nothing
/// (the background, or for a shadow ray: the light is seen). A shadow ray's
/// `weight` is that of the ray whose shading cast it. `children` are in the
/// order they were cast: shadow rays, then the reflected ray, then the
/// transmitted one. `Display` prints the tree indented, floats with three
/// decimals. Book: §8.5 Seeing the ray tree.
#[derive(Clone, Debug, PartialEq)]
pub struct RayTree {
    pub kind: RayKind,
    pub origin: Vec3,
    pub dir: Vec3,
    pub hit: Option<(usize, Float)>,
    pub weight: Float,
    pub children: Vec<RayTree>,
}

impl RayTree {
    /// The number of rays of `kind` in the tree, this one included.
    pub fn count(&self, kind: RayKind) -> usize {
        (self.kind == kind) as usize + self.children.iter().map(|c| c.count(kind)).sum::<usize>()
    }

    /// The depth of the deepest reflected or transmitted ray below (the
    /// root's depth is 0; shadow rays do not add depth).
    pub fn depth(&self) -> u32 {
        self.children.iter().filter(|c| c.kind != RayKind::Shadow).map(|c| 1 + c.depth()).max().unwrap_or(0)
    }

    fn write(&self, f: &mut fmt::Formatter<'_>, indent: usize) -> fmt::Result {
        write!(
            f,
            "{:indent$}{} from {} dir {} weight {}: ",
            "",
            self.kind.name(),
            triple(self.origin),
            triple(self.dir),
            fixed(self.weight),
        )?;
        match (self.kind, self.hit) {
            (RayKind::Shadow, Some((object, t))) => writeln!(f, "blocked by #{object} at t = {}", fixed(t))?,
            (RayKind::Shadow, None) => writeln!(f, "reaches the light")?,
            (_, Some((object, t))) => writeln!(f, "hits #{object} at t = {}", fixed(t))?,
            (_, None) => writeln!(f, "misses")?,
        }
        self.children.iter().try_for_each(|c| c.write(f, indent + 2))
    }
}

impl fmt::Display for RayTree {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.write(f, 0)
    }
}

/// A float with three decimals, never "-0.000" (the sign of a zero is noise).
fn fixed(x: Float) -> String {
    let s = format!("{x:.3}");
    if s == "-0.000" { "0.000".to_owned() } else { s }
}

fn triple(v: Vec3) -> String {
    format!("({}, {}, {})", fixed(v.x), fixed(v.y), fixed(v.z))
}

/// The colour of `ray` traced as an eye ray (depth 0, weight 1) by
/// [`crate::trace`], and every ray that went into it, as a tree.
///
/// The colour is bit for bit the one `trace` returns; the rays counted in
/// [`raylab::stats`] are the same, except that the recorder answers a shadow
/// ray's `any_hit` by a `closest_hit` (to name the blocker in the tree), which
/// may cost more intersection tests. Book: §8.5 Seeing the ray tree.
pub fn trace_recorded(world: &World, ray: &Ray, settings: &TraceSettings) -> (Color, RayTree) {
    let recorder = Recorder::new(world.objects);
    let recording = World { objects: &recorder, ..*world };
    let color = trace_node(&recording, ray, RayKind::Eye, 0, 1.0, settings, Some(&recorder));
    (color, recorder.into_tree())
}

/// Records the rays of one pixel: an [`Intersector`] around the world's one
/// that logs every query into the node that is open, plus the `open`/`close`
/// calls of `trace_node`. A `Mutex` only because an `Intersector` must be
/// `Sync`; one pixel is traced on one thread.
pub(crate) struct Recorder<'a> {
    objects: &'a dyn Intersector,
    state: Mutex<Nodes>,
}

/// The rays recorded so far, flat: each with its parent, and the path of open nodes.
#[derive(Default)]
struct Nodes {
    nodes: Vec<(RayTree, Option<usize>)>,
    open: Vec<usize>,
    awaiting_hit: bool,
}

impl Nodes {
    fn push(&mut self, kind: RayKind, ray: &Ray, weight: Float, hit: Option<(usize, Float)>) -> usize {
        let node = RayTree { kind, origin: ray.origin, dir: ray.dir, hit, weight, children: Vec::new() };
        self.nodes.push((node, self.open.last().copied()));
        self.nodes.len() - 1
    }

    /// A query made while a node is open: its own hit first, shadow rays after.
    fn query(&mut self, ray: &Ray, hit: Option<&Hit>) {
        let hit = hit.map(|h| (h.object, h.t));
        match self.open.last().copied() {
            Some(current) if self.awaiting_hit => {
                self.nodes[current].0.hit = hit;
                self.awaiting_hit = false;
            }
            Some(current) => {
                let weight = self.nodes[current].0.weight;
                self.push(RayKind::Shadow, ray, weight, hit);
            }
            // A query outside any node is not part of the tree.
            None => {}
        }
    }
}

impl<'a> Recorder<'a> {
    fn new(objects: &'a dyn Intersector) -> Self {
        Self { objects, state: Mutex::new(Nodes::default()) }
    }

    fn lock(&self) -> MutexGuard<'_, Nodes> {
        self.state.lock().unwrap_or_else(|poisoned| poisoned.into_inner())
    }

    /// A new ray below the open one (or the root); its first query is its hit.
    pub(crate) fn open(&self, kind: RayKind, ray: &Ray, weight: Float) {
        let mut nodes = self.lock();
        let index = nodes.push(kind, ray, weight, None);
        nodes.open.push(index);
        nodes.awaiting_hit = true;
    }

    /// The open ray is done: its parent is open again.
    pub(crate) fn close(&self) {
        let mut nodes = self.lock();
        nodes.open.pop();
        nodes.awaiting_hit = false;
    }

    /// The recorded rays as a tree (children in the order they were cast).
    fn into_tree(self) -> RayTree {
        let nodes = self.state.into_inner().unwrap_or_else(|poisoned| poisoned.into_inner()).nodes;
        // Children come after their parents: attach them from the last one back.
        let mut slots: Vec<Option<RayTree>> = Vec::with_capacity(nodes.len());
        let mut parents = Vec::with_capacity(nodes.len());
        for (node, parent) in nodes {
            slots.push(Some(node));
            parents.push(parent);
        }
        for index in (1..slots.len()).rev() {
            let (Some(node), Some(parent)) = (slots[index].take(), parents[index]) else { continue };
            if let Some(p) = slots[parent].as_mut() {
                p.children.push(node);
            }
        }
        let mut root = slots.first_mut().and_then(Option::take).expect("trace_node opens the root first");
        reverse_children(&mut root);
        root
    }
}

fn reverse_children(node: &mut RayTree) {
    node.children.reverse();
    node.children.iter_mut().for_each(reverse_children);
}

impl Intersector for Recorder<'_> {
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        let hit = self.objects.closest_hit(ray, range);
        self.lock().query(ray, hit.as_ref());
        hit
    }

    /// Answered by the closest hit, so that the tree can name the blocker: by
    /// the `Intersector` contract the answer is the same.
    fn any_hit(&self, ray: &Ray, range: Interval) -> bool {
        let hit = self.objects.closest_hit(ray, range);
        self.lock().query(ray, hit.as_ref());
        hit.is_some()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{cuboid, matte, mirror_and_wall, plane, recorded, scene, sphere, v};
    use l06_shadows::ShadowMode;
    use raylab::scene::Material;

    fn node(kind: RayKind, hit: Option<(usize, Float)>, weight: Float, children: Vec<RayTree>) -> RayTree {
        RayTree { kind, origin: v(1.0, -0.0001, 2.5), dir: v(0.0, -1.0, 0.0), hit, weight, children }
    }

    #[test]
    fn display_indents_children_and_prints_three_decimals() {
        // By the format: two spaces per level, every float with three decimals (1 → 1.000,
        // 2.5 → 2.500, −0.0001 → 0.000, not −0.000; 0.12345 → 0.123, 0.0095 → 0.009 or
        // 0.010 as the float rounds: 0.0095 is stored a little below, so 0.009), "hits" or
        // "misses" for tracing rays, "blocked by" or "reaches the light" for shadow rays.
        let tree = node(
            RayKind::Eye,
            Some((3, 4.0)),
            1.0,
            vec![
                node(RayKind::Shadow, None, 1.0, vec![]),
                node(RayKind::Shadow, Some((7, 0.12345)), 1.0, vec![]),
                node(RayKind::Reflected, None, 0.5, vec![]),
                node(
                    RayKind::Transmitted,
                    Some((3, 2.0)),
                    0.5,
                    vec![node(RayKind::Reflected, None, 0.0095, vec![])],
                ),
            ],
        );
        insta::assert_snapshot!(tree, @r"
        eye from (1.000, 0.000, 2.500) dir (0.000, -1.000, 0.000) weight 1.000: hits #3 at t = 4.000
          shadow from (1.000, 0.000, 2.500) dir (0.000, -1.000, 0.000) weight 1.000: reaches the light
          shadow from (1.000, 0.000, 2.500) dir (0.000, -1.000, 0.000) weight 1.000: blocked by #7 at t = 0.123
          reflected from (1.000, 0.000, 2.500) dir (0.000, -1.000, 0.000) weight 0.500: misses
          transmitted from (1.000, 0.000, 2.500) dir (0.000, -1.000, 0.000) weight 0.500: hits #3 at t = 2.000
            reflected from (1.000, 0.000, 2.500) dir (0.000, -1.000, 0.000) weight 0.009: misses
        ");
        assert_eq!(tree.count(RayKind::Shadow), 2);
        assert_eq!(tree.count(RayKind::Reflected), 2);
        assert_eq!(tree.depth(), 2);
    }

    #[test]
    fn the_mirror_and_the_wall_behind_the_eye_by_hand() {
        // Derived in trace.rs's test of this scene: the eye ray meets the mirror (#0) at
        // t = 2, casts no shadow ray (black, lit from behind), its mirror ray starts (up to
        // the offset) at (0, 0, −2), goes back along +z and meets the wall (#1, z = 3) at
        // t = 5, whose shadow ray leaves along (0, 1, −1)/√2 = (0, 0.707, −0.707) and
        // reaches the light. All of it at three decimals, the offsets far below them.
        let (_, tree) =
            recorded(&mirror_and_wall(1.0), &Ray::new(Vec3::ZERO, -Vec3::Z), &TraceSettings::default());
        insta::assert_snapshot!(tree, @r"
        eye from (0.000, 0.000, 0.000) dir (0.000, 0.000, -1.000) weight 1.000: hits #0 at t = 2.000
          reflected from (0.000, 0.000, -2.000) dir (0.000, 0.000, 1.000) weight 1.000: hits #1 at t = 5.000
            shadow from (0.000, 0.000, 3.000) dir (0.000, 0.707, -0.707) weight 1.000: reaches the light
        ");
    }

    #[test]
    fn transmissive_shadows_record_one_shadow_ray_per_segment() {
        // A floor (#0) under a ball (#1) of k_t = ½, light straight down, Transmissive
        // shadows: from the floor point under the ball the shadow ray walks in three
        // segments (06's transmittance): to the ball's bottom (y = 1, t = 1), through it to
        // its top (y = 3, t = 2), then on to the light (nothing more). In Opaque mode the
        // one any-hit ray is recorded with the blocker it found (the bottom, t = 1).
        let see_through = Material { transparent: Color::splat(0.5), ..matte(Color::splat(0.5)) };
        let s = scene(
            vec![plane(Vec3::Y, 0.0, 0), sphere(v(0.0, 2.0, 0.0), 1.0, 1)],
            vec![matte(Color::splat(0.5)), see_through],
            vec![crate::testing::directional(Vec3::Y, Color::ONE)],
            Color::ZERO,
            Color::ZERO,
        );
        let ray = Ray::new(v(0.0, 0.5, 3.0), v(0.0, -0.5, -3.0).normalize());
        let transmissive =
            TraceSettings { shadow_mode: ShadowMode::Transmissive, ..TraceSettings::default() };
        let (_, tree) = recorded(&s, &ray, &transmissive);
        let shadows: Vec<_> = tree.children.iter().filter(|c| c.kind == RayKind::Shadow).collect();
        let found: Vec<_> =
            shadows.iter().map(|c| c.hit.map(|(object, t)| (object, (t * 1e3).round() / 1e3))).collect();
        assert_eq!(found, [Some((1, 1.0)), Some((1, 2.0)), None]);
        let (_, tree) = recorded(&s, &ray, &TraceSettings::default());
        let found: Vec<_> = tree
            .children
            .iter()
            .map(|c| (c.kind, c.hit.map(|(o, t)| (o, (t * 1e3).round() / 1e3))))
            .collect();
        assert_eq!(found, [(RayKind::Shadow, Some((1, 1.0)))]);
    }

    #[test]
    fn a_box_of_glass_records_both_children_in_order() {
        // A glass box (k_r = k_t = ½, η = 1.5) head-on: the eye ray's children are its mirror
        // ray, then its transmitted ray (the order of the formula), each of weight ½.
        let glass = Material {
            diffuse: Color::ZERO,
            reflective: Color::splat(0.5),
            transparent: Color::splat(0.5),
            ior: 1.5,
            ..Material::default()
        };
        let s = scene(
            vec![cuboid(v(-1.0, -1.0, -3.0), v(1.0, 1.0, -2.0), 0)],
            vec![glass],
            vec![],
            Color::ONE,
            Color::ZERO,
        );
        let settings = TraceSettings { max_depth: 1, ..TraceSettings::default() };
        let (color, tree) = recorded(&s, &Ray::new(Vec3::ZERO, -Vec3::Z), &settings);
        let kinds: Vec<_> = tree.children.iter().map(|c| (c.kind, c.weight)).collect();
        assert_eq!(kinds, [(RayKind::Reflected, 0.5), (RayKind::Transmitted, 0.5)]);
        // The mirror ray sees the white background, the transmitted one the glass's back
        // face from inside (black, depth limit reached): ½·1 + ½·0.
        assert_eq!(color, Color::splat(0.5));
    }
}
