//! Building the bounding-volume hierarchy: binned SAH splits into a flat
//! array of compact nodes.

use raylab::Float;
use raylab::scene::{Object, Shape};

use crate::aabb::Aabb;
use crate::bounds::{object_bounds, triangle_bounds};
use crate::primitive::Primitive;
use crate::sah::{BINS, Bin, sah_split};

/// The most primitives a leaf holds: a node with more is always split.
pub const MAX_LEAF: usize = 4;

/// The size of the traversal stack, and the bound on the tree's depth.
pub const MAX_DEPTH: usize = 64;

/// Below this depth nodes are split by the SAH; from it on, by the median
/// centroid, which halves the primitives at each level: with fewer than 2³²
/// primitives the tree is then at most 32 + 31 levels deep, under
/// [`MAX_DEPTH`], whatever the scene (the SAH alone can build a chain as
/// deep as the primitives are many).
pub const SAH_DEPTH: usize = 32;

// The depth bound above, checked when compiling.
const _: () = assert!(SAH_DEPTH + 32 <= MAX_DEPTH);

/// A node of the hierarchy, in a flat array in depth-first order: an inner
/// node's first child is the next node, its second child is at `offset`.
///
/// A leaf (`count > 0`) holds the `count` primitives `offset..offset +
/// count` of [`Bvh::primitives`]; an inner node has `count == 0` and was split
/// along `axis` (0, 1, 2), its first child holding the smaller centroids.
///
/// Compact: 32 bytes in f32 (the box's six floats, the offset, the count,
/// the axis, one byte of padding), so two nodes share a 64-byte cache line
/// and the traversal, which reads a node for each box test, moves as little
/// memory as it can; the first child, next in the array, often arrives with
/// its parent. Book: §9.5 A flat array of nodes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Node {
    /// The box around everything beneath the node.
    pub bounds: Aabb,
    /// A leaf's first primitive, or an inner node's second child.
    pub offset: u32,
    /// How many primitives a leaf holds; 0 for an inner node.
    pub count: u16,
    /// The axis an inner node was split along.
    pub axis: u8,
}

// The node layout above, checked when compiling: 32 bytes in f32 (56 in f64).
const _: () = assert!(size_of::<Node>() == 6 * size_of::<Float>() + 8);

impl Node {
    pub fn is_leaf(&self) -> bool {
        self.count > 0
    }
}

/// A bounding-volume hierarchy over a scene's objects: a binary tree of
/// boxes whose leaves hold [`Primitive`]s (whole objects, or single
/// triangles of untransformed meshes). A ray visits only the subtrees whose
/// box it meets, nearest first, and skips those that start beyond the
/// closest hit so far, so it tests a handful of primitives instead of all.
///
/// Objects whose box is not finite (planes) cannot be bounded: they are kept
/// in [`Bvh::unbounded`] and tested on every ray, by brute force.
/// Book: §9.5 Bounding-volume hierarchies.
#[derive(Clone, Debug)]
pub struct Bvh<'a> {
    /// The scene's objects, which the primitives index.
    pub objects: &'a [Object],
    /// The tree, depth first; empty when there is nothing to bound.
    pub nodes: Vec<Node>,
    /// The primitives, in the order of the leaves that hold them.
    pub primitives: Vec<Primitive>,
    /// The objects tested on every ray, in the scene's order.
    pub unbounded: Vec<Primitive>,
}

/// A primitive with its world box and that box's centre, during the build.
#[derive(Clone, Copy, Debug)]
struct Item {
    primitive: Primitive,
    bounds: Aabb,
    centroid: raylab::Vec3,
}

impl<'a> Bvh<'a> {
    /// The hierarchy over `objects`, by binned SAH.
    ///
    /// Every untransformed mesh contributes one primitive per triangle (boxed
    /// by [`triangle_bounds`]); every other object with a finite box one
    /// primitive (boxed by [`object_bounds`]), a transformed mesh included,
    /// which its leaf then tests whole; the rest go to [`Bvh::unbounded`].
    ///
    /// Each node: the box around its primitives; one primitive is a leaf.
    /// Otherwise the primitives' centroids are binned into [`BINS`] equal
    /// bins along the longest axis of the centroids' box, and [`sah_split`]
    /// prices the splits between bins; the node becomes a leaf when it holds
    /// at most [`MAX_LEAF`] primitives and the SAH's best split costs no less
    /// than testing them all, else it is split there. Where the SAH cannot
    /// split (all centroids equal, a node of zero area) or below
    /// [`SAH_DEPTH`], a node of more than [`MAX_LEAF`] primitives is split at
    /// its median centroid instead.
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
        let mut bvh =
            Bvh { objects, nodes: Vec::with_capacity(2 * items.len()), primitives: Vec::new(), unbounded };
        if !items.is_empty() {
            bvh.build_node(&mut items, 0, 0);
        }
        bvh.primitives = items.iter().map(|item| item.primitive).collect();
        bvh
    }

    /// Builds the subtree over `items` (which start at `first` in the final
    /// primitive order) at `depth`; returns its node's index.
    fn build_node(&mut self, items: &mut [Item], first: usize, depth: usize) -> u32 {
        let index = self.nodes.len() as u32;
        let bounds = items.iter().fold(Aabb::EMPTY, |b, item| b.union(item.bounds));
        self.nodes.push(Node { bounds, offset: first as u32, count: 0, axis: 0 });
        let Some((split, axis)) = choose_split(items, depth) else {
            // A leaf of at most MAX_LEAF primitives.
            self.nodes[index as usize].count = items.len() as u16;
            return index;
        };
        let (left, right) = items.split_at_mut(split);
        self.build_node(left, first, depth + 1);
        let second = self.build_node(right, first + split, depth + 1);
        self.nodes[index as usize] = Node { bounds, offset: second, count: 0, axis: axis as u8 };
        index
    }

    /// How many levels the tree has (0 when empty, 1 for a single leaf).
    pub fn depth(&self) -> usize {
        fn below(nodes: &[Node], i: usize) -> usize {
            let node = &nodes[i];
            if node.is_leaf() { 1 } else { 1 + below(nodes, i + 1).max(below(nodes, node.offset as usize)) }
        }
        if self.nodes.is_empty() { 0 } else { below(&self.nodes, 0) }
    }
}

/// Whether and where to split a node: `Some((n, axis))` after reordering
/// `items` so that the first n go to the first child (0 < n < len), or
/// `None` for a leaf.
fn choose_split(items: &mut [Item], depth: usize) -> Option<(usize, usize)> {
    let n = items.len();
    if n == 1 {
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
    use crate::test_support::{Rng, mixed_scene, object, sphere};
    use raylab::Vec3;
    use raylab::scene::Mesh;
    use std::sync::Arc;

    /// The structural invariants of a built tree: every bounded primitive once,
    /// leaves of 1..=MAX_LEAF primitives, each node's box around its children's
    /// and its primitives' boxes, depth within MAX_DEPTH.
    fn assert_well_formed(bvh: &Bvh) {
        let mut seen = vec![0u32; bvh.primitives.len()];
        let mut stack = vec![0usize];
        while let Some(i) = stack.pop().filter(|_| !bvh.nodes.is_empty()) {
            let node = &bvh.nodes[i];
            if node.is_leaf() {
                assert!((1..=MAX_LEAF).contains(&(node.count as usize)), "leaf {i} holds {}", node.count);
                let leaf = bvh.primitives.iter().enumerate().skip(node.offset as usize);
                for (p, &primitive) in leaf.take(node.count as usize) {
                    seen[p] += 1;
                    let object = &bvh.objects[primitive.object as usize];
                    let b = match (&object.shape, primitive.triangle) {
                        (Shape::Mesh(mesh), t) if t != Primitive::WHOLE => {
                            triangle_bounds(&mesh.triangle(t as usize))
                        }
                        _ => object_bounds(object),
                    };
                    assert_eq!(node.bounds.union(b), node.bounds, "leaf {i} does not hold primitive {p}");
                }
            } else {
                for child in [i + 1, node.offset as usize] {
                    assert!(child > i && child < bvh.nodes.len());
                    assert_eq!(
                        node.bounds.union(bvh.nodes[child].bounds),
                        node.bounds,
                        "node {i}, child {child}"
                    );
                    stack.push(child);
                }
            }
        }
        assert!(seen.iter().all(|&s| s == 1), "a primitive is missing or repeated");
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
        assert_eq!((bvh.nodes[0].offset, bvh.nodes[0].count), (0, 1));
        assert_eq!(bvh.primitives, vec![Primitive::whole(0)]);
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
        // median splits give leaves of at most 4 and depth ⌈log₂(100/4)⌉ + 1 = 6.
        let objects: Vec<Object> = (0..100).map(|i| sphere(Vec3::ZERO, 0.1 + 0.01 * i as Float, 0)).collect();
        let bvh = Bvh::build(&objects);
        assert_well_formed(&bvh);
        assert_eq!(bvh.depth(), 6);
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
        assert_eq!(bvh.nodes.len(), 1);
        // Four far-apart spheres: splitting is far cheaper than testing all four.
        let objects: Vec<Object> =
            (0..4).map(|i| sphere(Vec3::new(10.0 * i as Float, 0.0, 0.0), 1.0, 0)).collect();
        assert!(Bvh::build(&objects).nodes.len() > 1);
    }
}
