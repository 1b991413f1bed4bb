//! Building the bounding-volume hierarchy: binned SAH splits into a binary
//! tree, collapsed into a flat array of four-wide nodes.

use raylab::scene::{Object, Shape};
use raylab::{Float, Vec3, Vec4};

use crate::aabb::Aabb;
use crate::bounds::{object_bounds, triangle_bounds};
use crate::primitive::Primitive;
use crate::sah::{BINS, Bin, sah_split};

/// The most primitives a leaf holds: a node with more is always split.
pub const MAX_LEAF: usize = 4;

/// The bound on the depth of the binary tree the build makes; the four-wide
/// tree collapsed from it is no deeper.
pub const MAX_DEPTH: usize = 64;

/// Below this depth nodes are split by the SAH; from it on, by the median
/// centroid, which halves the primitives at each level: with fewer than 2³²
/// primitives the tree is then at most 32 + 31 levels deep, under
/// [`MAX_DEPTH`], whatever the scene (the SAH alone can build a chain as
/// deep as the primitives are many).
pub const SAH_DEPTH: usize = 32;

// The depth bound above, checked when compiling.
const _: () = assert!(SAH_DEPTH + 32 <= MAX_DEPTH);

/// How many children a node has room for.
pub const WIDTH: usize = 4;

/// A node of the hierarchy: up to [`WIDTH`] children, each a subtree (another
/// node) or a leaf (a run of primitives), with their boxes. The nodes sit in
/// a flat array, the root first.
///
/// The children's boxes are stored plane by plane, not box by box: lane i of
/// `planes[a]` is the min along axis a (0, 1, 2) of child i's box, lane i of
/// `planes[3 + a]` its max. So one [`Vec4`] operation works on the same plane
/// of all four boxes, and the four can be tested with the instructions one
/// box test takes (the "structure of arrays" layout; Vec4 is four f32 in one
/// SIMD register).
///
/// Child i is a leaf holding the primitives `offset[i]..offset[i] +
/// count[i]` of [`Bvh::primitives`] when `count[i] > 0`, and the node
/// `offset[i]` when `count[i] == 0`. A node with fewer than four children
/// fills the rest with empty slots ([`Node::is_empty_slot`]): a point at
/// +∞ on every axis for a box, which no ray meets (from any finite origin,
/// every slab test puts it at t = +∞ or −∞).
///
/// 128 bytes in f32, two cache lines, aligned to one: everything the
/// traversal reads to decide four children arrives in two memory reads.
/// Book: §9.5 Four-wide nodes.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct Node {
    /// `planes[a]`: the children's mins along axis a; `planes[3 + a]`: their maxes.
    pub planes: [Vec4; 6],
    /// Child i: a node's index, or a leaf's first primitive.
    pub offset: [u32; WIDTH],
    /// Child i: how many primitives the leaf holds; 0 for a node (or an empty slot).
    pub count: [u32; WIDTH],
}

// The node layout above, checked when compiling: 128 bytes in f32 (256 in f64).
const _: () = assert!(size_of::<Node>() == if size_of::<Float>() == 4 { 128 } else { 256 });

impl Node {
    /// A node whose four slots are all empty.
    pub const EMPTY: Node = Node { planes: [Vec4::INFINITY; 6], offset: [0; WIDTH], count: [0; WIDTH] };

    /// The box of child `i`.
    pub fn child_bounds(&self, i: usize) -> Aabb {
        let lane = |a: usize| self.planes[a][i];
        Aabb::new(Vec3::new(lane(0), lane(1), lane(2)), Vec3::new(lane(3), lane(4), lane(5)))
    }

    /// Stores `bounds` as the box of child `i`.
    pub(crate) fn set_child_bounds(&mut self, i: usize, bounds: Aabb) {
        for a in 0..3 {
            self.planes[a][i] = bounds.min[a];
            self.planes[3 + a][i] = bounds.max[a];
        }
    }

    /// True when child `i` is a leaf (a run of primitives).
    pub fn is_leaf(&self, i: usize) -> bool {
        self.count[i] > 0
    }

    /// True when slot `i` holds no child (its box is the point at +∞).
    pub fn is_empty_slot(&self, i: usize) -> bool {
        self.count[i] == 0 && self.child_bounds(i) == Aabb::new(Vec3::INFINITY, Vec3::INFINITY)
    }
}

/// A bounding-volume hierarchy over a scene's objects: a tree of boxes whose
/// leaves hold [`Primitive`]s (whole objects, or single triangles of
/// untransformed meshes). A ray visits only the subtrees whose box it meets,
/// nearest first, and skips those that start beyond the closest hit so far,
/// so it tests a handful of primitives instead of all.
///
/// Objects whose box is not finite (planes) cannot be bounded: they are kept
/// in [`Bvh::unbounded`] and tested on every ray, by brute force.
/// Book: §9.5 Bounding-volume hierarchies.
#[derive(Clone, Debug)]
pub struct Bvh<'a> {
    /// The scene's objects, which the primitives index.
    pub objects: &'a [Object],
    /// The tree, the root first; empty when there is nothing to bound.
    pub nodes: Vec<Node>,
    /// The primitives, in the order of the leaves that hold them.
    pub primitives: Vec<Primitive>,
    /// The corners of each primitive that is a mesh triangle, in the same
    /// order (zeros for a whole object): a leaf's triangles side by side in
    /// memory, without going through the mesh's index list.
    pub triangles: Vec<[Vec3; 3]>,
    /// The objects tested on every ray, in the scene's order.
    pub unbounded: Vec<Primitive>,
    // INSTRUCTOR BEGIN
    /// The leaves as the reference traversal tests them (four primitives in
    /// four SIMD lanes).
    pub(crate) leaves: crate::fast::Leaves,
    // INSTRUCTOR END
}

/// A primitive with its world box and that box's centre, during the build.
#[derive(Clone, Copy, Debug)]
struct Item {
    primitive: Primitive,
    bounds: Aabb,
    centroid: Vec3,
}

/// A node of the binary tree the build makes before collapsing it, depth
/// first: an inner node's first child is the next node, its second child
/// at `offset`; a leaf (`count > 0`) holds the items `offset..offset + count`.
#[derive(Clone, Copy, Debug)]
struct BinaryNode {
    bounds: Aabb,
    offset: u32,
    count: u32,
}

impl<'a> Bvh<'a> {
    /// The hierarchy over `objects`, by binned SAH.
    ///
    /// Every untransformed mesh contributes one primitive per triangle (boxed
    /// by [`triangle_bounds`]); every other object with a finite box one
    /// primitive (boxed by [`object_bounds`]), a transformed mesh included,
    /// which its leaf then tests whole; the rest go to [`Bvh::unbounded`].
    ///
    /// First a binary tree. Each node: the box around its primitives; one
    /// primitive is a leaf. Otherwise the primitives' centroids are binned
    /// into [`BINS`] equal bins along the longest axis of the centroids' box,
    /// and [`sah_split`] prices the splits between bins; the node becomes a
    /// leaf when it holds at most [`MAX_LEAF`] primitives and the SAH's best
    /// split costs no less than testing them all, else it is split there.
    /// A node of at most [`MAX_LEAF`] mesh triangles is a leaf whatever the
    /// SAH says: the reference traversal tests a leaf's triangles at once, in
    /// four SIMD lanes, for less than the node a split would add.
    /// Where the SAH cannot split (all centroids equal, a node of zero area)
    /// or below [`SAH_DEPTH`], a node of more than [`MAX_LEAF`] primitives is
    /// split at its median centroid instead.
    ///
    /// Then the binary tree is collapsed into four-wide [`Node`]s: a node
    /// takes its two children, then replaces the inner child of largest area
    /// by that child's two children, until it has four or only leaves. Every
    /// other level of the binary tree disappears, and with it half of the
    /// nodes a ray visits.
    ///
    /// Deterministic: the same objects give the same tree (no hashing, no
    /// threads, ties broken by index). At most 2³¹ primitives.
    /// Book: §9.6 Building the hierarchy.
    pub fn build(objects: &'a [Object]) -> Bvh<'a> {
        let mut items = Vec::new();
        let mut unbounded = Vec::new();
        for (index, object) in objects.iter().enumerate() {
            let index = index as u32;
            match (&object.shape, &object.transform) {
                (Shape::Mesh(mesh), None) => {
                    for triangle in 0..mesh.triangles.len() {
                        let bounds = triangle_bounds(&mesh.triangle(triangle));
                        let primitive = Primitive { object: index, triangle: triangle as u32 };
                        items.push(Item { primitive, bounds, centroid: bounds.centroid() });
                    }
                }
                _ => {
                    let bounds = object_bounds(object);
                    let primitive = Primitive::whole(index);
                    if bounds.is_finite() {
                        items.push(Item { primitive, bounds, centroid: bounds.centroid() });
                    } else {
                        unbounded.push(primitive);
                    }
                }
            }
        }
        debug_assert!(items.len() < 1 << 31, "too many primitives for a BVH: {}", items.len());
        let mut binary = Vec::with_capacity(2 * items.len());
        if !items.is_empty() {
            build_binary(&mut binary, &mut items, 0, 0);
        }
        let mut nodes = Vec::with_capacity(binary.len() / 2 + 1);
        if !binary.is_empty() {
            collapse(&binary, 0, &mut nodes);
        }
        let primitives: Vec<Primitive> = items.iter().map(|item| item.primitive).collect();
        let triangles: Vec<[Vec3; 3]> = primitives
            .iter()
            .map(|p| match &objects[p.object as usize].shape {
                Shape::Mesh(mesh) if p.triangle != Primitive::WHOLE => mesh.triangle(p.triangle as usize),
                _ => [Vec3::ZERO; 3],
            })
            .collect();
        // INSTRUCTOR BEGIN
        let leaves = crate::fast::Leaves::new(&nodes, &primitives, &triangles);
        // INSTRUCTOR END
        Bvh {
            objects,
            nodes,
            primitives,
            triangles,
            unbounded,
            // INSTRUCTOR BEGIN
            leaves,
            // INSTRUCTOR END
        }
    }

    /// The same tree traversed four-wide, as on a CPU without AVX2 (the
    /// reference's eight-wide nodes left out; the same tree where there are
    /// none): the tests compare both traversals with brute force.
    #[cfg(test)]
    pub(crate) fn four_wide_twin(&self) -> Bvh<'a> {
        #[allow(unused_mut)] // in the handout, which has no eight-wide nodes
        let mut twin = self.clone();
        // INSTRUCTOR BEGIN
        twin.leaves.wide = Vec::new();
        // INSTRUCTOR END
        twin
    }

    /// How many levels the tree has, its leaves counted as one (0 when
    /// empty; a root holding only leaves has 2).
    pub fn depth(&self) -> usize {
        fn below(nodes: &[Node], i: usize) -> usize {
            let node = &nodes[i];
            let children = (0..WIDTH).filter(|&c| !node.is_empty_slot(c));
            1 + children
                .map(|c| if node.is_leaf(c) { 1 } else { below(nodes, node.offset[c] as usize) })
                .max()
                .unwrap_or(0)
        }
        if self.nodes.is_empty() { 0 } else { below(&self.nodes, 0) }
    }
}

/// Builds the binary subtree over `items` (which start at `first` in the
/// final primitive order) at `depth` into `nodes`; returns its node's index.
fn build_binary(nodes: &mut Vec<BinaryNode>, items: &mut [Item], first: usize, depth: usize) -> u32 {
    let index = nodes.len() as u32;
    let bounds = items.iter().fold(Aabb::EMPTY, |b, item| b.union(item.bounds));
    nodes.push(BinaryNode { bounds, offset: first as u32, count: 0 });
    let Some(split) = choose_split(items, depth).map(|(split, _axis)| split) else {
        // A leaf of at most MAX_LEAF primitives.
        nodes[index as usize].count = items.len() as u32;
        return index;
    };
    let (left, right) = items.split_at_mut(split);
    build_binary(nodes, left, first, depth + 1);
    let second = build_binary(nodes, right, first + split, depth + 1);
    nodes[index as usize].offset = second;
    index
}

/// Writes the four-wide node standing for the binary node `b` (its children,
/// and their children where there is room) and, before it returns, every
/// node beneath; returns the new node's index. A binary leaf at the root
/// becomes a node with that one leaf.
fn collapse(binary: &[BinaryNode], b: usize, nodes: &mut Vec<Node>) -> u32 {
    let index = nodes.len();
    nodes.push(Node::EMPTY);
    let children_of = |c: usize| [c + 1, binary[c].offset as usize];
    let mut children: Vec<usize> = if binary[b].count > 0 { vec![b] } else { children_of(b).to_vec() };
    while children.len() < WIDTH {
        // The inner child of largest area (the first of equal ones) opens up.
        let mut widest: Option<(usize, Float)> = None;
        for (k, &c) in children.iter().enumerate() {
            let area = binary[c].bounds.surface_area();
            if binary[c].count == 0 && widest.is_none_or(|(_, a)| area > a) {
                widest = Some((k, area));
            }
        }
        let Some((k, _)) = widest else { break };
        let [first, second] = children_of(children[k]);
        children[k] = first;
        children.insert(k + 1, second);
    }
    let mut node = Node::EMPTY;
    for (slot, &c) in children.iter().enumerate() {
        node.set_child_bounds(slot, binary[c].bounds);
        if binary[c].count > 0 {
            (node.offset[slot], node.count[slot]) = (binary[c].offset, binary[c].count);
        } else {
            node.offset[slot] = collapse(binary, c, nodes);
        }
    }
    nodes[index] = node;
    index as u32
}

/// Whether and where to split a node: `Some((n, axis))` after reordering
/// `items` so that the first n go to the first child (0 < n < len), or
/// `None` for a leaf.
fn choose_split(items: &mut [Item], depth: usize) -> Option<(usize, usize)> {
    let n = items.len();
    if n == 1 {
        return None;
    }
    // Up to four mesh triangles: a leaf, whatever the SAH says. The reference
    // traversal tests a leaf's triangles at once, in four SIMD lanes, for about
    // the price of one node: no split is cheaper (measured on the bunny, in a
    // prototype: 4 % faster than making leaves only of the subtrees of at most
    // four triangles the SAH builds; 3.1 times fewer nodes than before).
    if n <= MAX_LEAF && items.iter().all(|item| item.primitive.triangle != Primitive::WHOLE) {
        return None;
    }
    let centroids = items.iter().fold(Aabb::EMPTY, |b, item| b.union_point(item.centroid));
    let axis = centroids.longest_axis();
    let (lo, extent) = (centroids.min[axis], centroids.max[axis] - centroids.min[axis]);

    // The SAH's split, if it finds one and it beats a leaf.
    if depth < SAH_DEPTH && extent > 0.0 {
        let bin_of = |item: &Item| {
            let b = (BINS as Float * ((item.centroid[axis] - lo) / extent)) as usize;
            b.min(BINS - 1)
        };
        let mut bins = [Bin::EMPTY; BINS];
        for item in items.iter() {
            let bin = &mut bins[bin_of(item)];
            bin.bounds = bin.bounds.union(item.bounds);
            bin.count += 1;
        }
        if let Some((k, cost)) = sah_split(&bins) {
            if n <= MAX_LEAF && cost >= n as Float {
                return None;
            }
            return Some((partition(items, |item| bin_of(item) <= k), axis));
        }
    }

    // A small node the SAH could not split stays a leaf; a large one is halved.
    if n <= MAX_LEAF {
        return None;
    }
    let half = n / 2;
    items.select_nth_unstable_by(half, |a, b| a.centroid[axis].total_cmp(&b.centroid[axis]));
    Some((half, axis))
}

/// Moves the items for which `left` holds to the front, keeping the order
/// within each side; returns how many there are.
fn partition(items: &mut [Item], left: impl Fn(&Item) -> bool) -> usize {
    let (front, back): (Vec<Item>, Vec<Item>) = items.iter().partition(|item| left(item));
    let split = front.len();
    for (slot, item) in items.iter_mut().zip(front.into_iter().chain(back)) {
        *slot = item;
    }
    split
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{Rng, mixed_scene, object, sphere};
    use raylab::Vec3;
    use raylab::scene::Mesh;
    use std::sync::Arc;

    /// The structural invariants of a built tree: every bounded primitive once,
    /// leaves of 1..=MAX_LEAF primitives holding their primitives' boxes, every
    /// node reached once from the root (children after their parent), the empty
    /// slots after the children, `triangles` the corners of each mesh triangle,
    /// depth within MAX_DEPTH.
    fn assert_well_formed(bvh: &Bvh) {
        let mut seen = vec![0u32; bvh.primitives.len()];
        let mut reached = vec![0u32; bvh.nodes.len()];
        let mut stack = vec![0usize];
        while let Some(i) = stack.pop().filter(|_| !bvh.nodes.is_empty()) {
            reached[i] += 1;
            let node = &bvh.nodes[i];
            let children = (0..WIDTH).take_while(|&c| !node.is_empty_slot(c)).count();
            assert!(children >= 1, "node {i} has no child");
            assert!(
                (children..WIDTH).all(|c| node.is_empty_slot(c)),
                "node {i}: a child after an empty slot"
            );
            assert!(i == 0 || children >= 2, "node {i} (not the root) has one child");
            for c in 0..children {
                let bounds = node.child_bounds(c);
                if !node.is_leaf(c) {
                    let child = node.offset[c] as usize;
                    assert!(child > i && child < bvh.nodes.len(), "node {i}, child {c}: {child}");
                    for g in (0..WIDTH).filter(|&g| !bvh.nodes[child].is_empty_slot(g)) {
                        let inner = bvh.nodes[child].child_bounds(g);
                        assert_eq!(bounds.union(inner), bounds, "node {i}, child {c}, grandchild {g}");
                    }
                    stack.push(child);
                    continue;
                }
                let count = node.count[c] as usize;
                assert!((1..=MAX_LEAF).contains(&count), "node {i}, leaf {c} holds {count}");
                let leaf = bvh.primitives.iter().enumerate().skip(node.offset[c] as usize);
                for (p, &primitive) in leaf.take(count) {
                    seen[p] += 1;
                    let object = &bvh.objects[primitive.object as usize];
                    let b = match (&object.shape, primitive.triangle) {
                        (Shape::Mesh(mesh), t) if t != Primitive::WHOLE => {
                            assert_eq!(bvh.triangles[p], mesh.triangle(t as usize));
                            triangle_bounds(&mesh.triangle(t as usize))
                        }
                        _ => object_bounds(object),
                    };
                    assert_eq!(bounds.union(b), bounds, "node {i}, leaf {c} does not hold primitive {p}");
                }
            }
        }
        assert!(seen.iter().all(|&s| s == 1), "a primitive is missing or repeated");
        assert!(reached.iter().all(|&r| r == 1), "a node is unreachable or shared");
        assert_eq!(bvh.triangles.len(), bvh.primitives.len());
        assert!(bvh.depth() <= MAX_DEPTH);
    }

    #[test]
    fn mixed_scene_builds_a_well_formed_tree() {
        let objects = mixed_scene(&mut Rng::new(1));
        let bvh = Bvh::build(&objects);
        assert_well_formed(&bvh);
        // The plane is the only unbounded object; the torus gives 32·16·2 triangles.
        assert_eq!(bvh.unbounded, vec![Primitive::whole(0)]);
        assert_eq!(bvh.primitives.len(), objects.len() - 2 + 1024);
        assert!(bvh.depth() <= 24, "depth {}", bvh.depth());
    }

    #[test]
    fn two_builds_give_identical_trees() {
        let objects = mixed_scene(&mut Rng::new(2));
        let (a, b) = (Bvh::build(&objects), Bvh::build(&objects));
        assert_eq!(a.nodes, b.nodes);
        assert_eq!(a.primitives, b.primitives);
        assert_eq!(a.unbounded, b.unbounded);
    }

    #[test]
    fn zero_one_and_unbounded_only() {
        let none: Vec<Object> = Vec::new();
        let bvh = Bvh::build(&none);
        assert!(bvh.nodes.is_empty() && bvh.primitives.is_empty() && bvh.depth() == 0);
        let one = [sphere(Vec3::ZERO, 1.0, 0)];
        let bvh = Bvh::build(&one);
        assert_eq!(bvh.nodes.len(), 1);
        assert_eq!((bvh.nodes[0].offset, bvh.nodes[0].count), ([0; WIDTH], [1, 0, 0, 0]));
        assert!((1..WIDTH).all(|c| bvh.nodes[0].is_empty_slot(c)));
        assert_eq!(bvh.nodes[0].child_bounds(0), object_bounds(&one[0]));
        assert_eq!(bvh.primitives, vec![Primitive::whole(0)]);
        assert_eq!(bvh.depth(), 2);
        let planes = [object(Shape::Plane { normal: Vec3::Y, offset: 0.0 }, 0, None)];
        let bvh = Bvh::build(&planes);
        assert!(bvh.nodes.is_empty());
        assert_eq!(bvh.unbounded.len(), 1);
        // An empty mesh adds nothing; an empty transformed mesh is tested (and missed) on every ray.
        let empty = Arc::new(Mesh::default());
        let objects = [
            object(Shape::Mesh(empty.clone()), 0, None),
            object(Shape::Mesh(empty), 0, Some(raylab::Mat4::from_scale(Vec3::splat(2.0)))),
        ];
        let bvh = Bvh::build(&objects);
        assert!(bvh.nodes.is_empty());
        assert_eq!(bvh.unbounded, vec![Primitive::whole(1)]);
    }

    #[test]
    fn equal_centroids_are_split_at_the_median() {
        // 100 concentric spheres: every centroid is the origin, so no bin split exists;
        // median splits halve them: 100 → 50 → 25 → 12, 13 → 6, 7 → leaves of 3 and 4, a
        // binary tree of 6 levels. Collapsing never adds a level, and four-wide nodes
        // over 32 leaves need at least 1 + ⌈log₄ 32⌉ = 4 (the leaves counted).
        let objects: Vec<Object> = (0..100).map(|i| sphere(Vec3::ZERO, 0.1 + 0.01 * i as Float, 0)).collect();
        let bvh = Bvh::build(&objects);
        assert_well_formed(&bvh);
        assert!((4..=6).contains(&bvh.depth()), "depth {}", bvh.depth());
    }

    #[test]
    fn deep_nodes_split_at_the_median_not_by_the_sah() {
        // Nine spheres in a cluster at x ∈ [0, 0.8] and one at x = 100: near the root the
        // SAH cuts the far one off (9 | 1); from SAH_DEPTH on the median halves them
        // (5 | 5), the smaller centroids first, whatever the SAH would say. That bounds the
        // depth by SAH_DEPTH + log₂(primitives), under MAX_DEPTH.
        let mut objects: Vec<Object> =
            (0..9).map(|i| sphere(Vec3::new(0.1 * i as Float, 0.0, 0.0), 0.3, 0)).collect();
        objects.push(sphere(Vec3::new(100.0, 0.0, 0.0), 0.3, 0));
        let items = |objects: &[Object]| -> Vec<Item> {
            objects
                .iter()
                .enumerate()
                .map(|(i, o)| {
                    let bounds = object_bounds(o);
                    Item { primitive: Primitive::whole(i as u32), bounds, centroid: bounds.centroid() }
                })
                .collect()
        };
        let mut near_root = items(&objects);
        assert_eq!(choose_split(&mut near_root, 0), Some((9, 0)));
        let mut deep = items(&objects);
        assert_eq!(choose_split(&mut deep, SAH_DEPTH), Some((5, 0)));
        let (left, right) = deep.split_at(5);
        let largest_left = left.iter().map(|item| item.centroid.x).fold(Float::NEG_INFINITY, Float::max);
        assert!(right.iter().all(|item| item.centroid.x >= largest_left));
    }

    #[test]
    fn small_nodes_become_leaves_when_the_sah_says_so() {
        // Four overlapping unit spheres around the origin: any split's two children
        // overlap almost entirely, C ≈ 1/8 + 4·(nearly 1) > 4 = the leaf's cost: one leaf.
        let objects: Vec<Object> =
            [-0.01, 0.0, 0.01, 0.02].iter().map(|&x| sphere(Vec3::new(x, 0.0, 0.0), 1.0, 0)).collect();
        let bvh = Bvh::build(&objects);
        assert_eq!((bvh.nodes.len(), bvh.nodes[0].count), (1, [4, 0, 0, 0]));
        // Four far-apart spheres: splitting is far cheaper than testing all four, down to
        // leaves of one, which the root then holds side by side.
        let objects: Vec<Object> =
            (0..4).map(|i| sphere(Vec3::new(10.0 * i as Float, 0.0, 0.0), 1.0, 0)).collect();
        let bvh = Bvh::build(&objects);
        assert_eq!((bvh.nodes.len(), bvh.nodes[0].count), (1, [1, 1, 1, 1]));
    }

    #[test]
    fn up_to_four_triangles_are_one_leaf_whatever_the_sah_says() {
        // Four far-apart triangles of one mesh: the SAH would split them down to leaves of
        // one (as the far-apart spheres above), but four mesh triangles are always a leaf.
        // Five are split once, into two leaves of at most four (4 | 1, 3 | 2, …), which
        // the root then holds side by side.
        let tri = |x: Float| [Vec3::new(x, 0.0, 0.0), Vec3::new(x + 1.0, 0.0, 0.0), Vec3::new(x, 1.0, 0.0)];
        let mesh = |n: usize| {
            let positions: Vec<Vec3> = (0..n).flat_map(|i| tri(10.0 * i as Float)).collect();
            let triangles = (0..n as u32).map(|i| [3 * i, 3 * i + 1, 3 * i + 2]).collect();
            object(Shape::Mesh(Arc::new(Mesh { positions, triangles, ..Mesh::default() })), 0, None)
        };
        let (four, five) = ([mesh(4)], [mesh(5)]);
        let bvh = Bvh::build(&four);
        assert_eq!((bvh.nodes.len(), bvh.nodes[0].count), (1, [4, 0, 0, 0]));
        let bvh = Bvh::build(&five);
        assert_well_formed(&bvh);
        let [a, b, c, d] = bvh.nodes[0].count;
        assert_eq!((bvh.nodes.len(), a + b, c, d), (1, 5, 0, 0), "{:?}", bvh.nodes[0].count);
        assert!(a > 0 && b > 0);
    }
}
