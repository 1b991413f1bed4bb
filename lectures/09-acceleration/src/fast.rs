// INSTRUCTOR ONLY: left out of the handout; the reference traversal's fast kernels.
//! The reference traversal's two kernels, with everything that depends on
//! the ray alone computed once per ray: the four boxes of a node tested at
//! once ([`Node::hit_children`] with a [`BoxRay`]), or the eight of a
//! [`WideNode`] on CPUs with AVX2, and lecture 03's watertight triangle test
//! on a leaf's four triangles at once, with the ray's shear precomputed
//! ([`ShearedRay::hit_lanes`] on [`LeafLanes`]); and the copies of the
//! traversal's loop ([`closest_in_tree`], [`any_in_tree`]) made with them.
//! Students traverse with [`crate::Aabb::hit`] and
//! [`crate::Primitive::triangle_t`]; the answers are the same, the speed is
//! not (`grader bench-rays`, benches/README.md). Book: §9.7 Ordered
//! traversal, §9.10 Measuring a hierarchy.

use l03_polygons_triangles::{TriangleHit, dominant_axis, interpolate_normal};
use raylab::math::gamma;
use raylab::scene::{Object, Shape};
use raylab::{Float, Hit, Interval, Ray, Vec2, Vec3, Vec4};

use crate::bvh::{MAX_DEPTH, MAX_LEAF, Node, WIDTH};
use crate::primitive::Primitive;
use crate::traverse::{Closest, any_in_tree, closest_in_tree};
use crate::{Aabb, Bvh};
use std::cell::RefCell;

thread_local! {
    /// The reference traversal's stack, one per thread, reused by every ray:
    /// nothing to allocate or clear per ray, only a count of the entries in
    /// use (a fresh array per ray, of the 193 entries the four-wide tree
    /// needs, [`crate::STACK_SIZE`], cost a third of the traversal's time,
    /// measured; a `Vec` reused the same way, its capacity checks and length
    /// kept in memory, about 5 %). [`STACK_LEN`] entries, enough for both trees.
    pub static STACK: RefCell<[Next; STACK_LEN]> = const { RefCell::new([Next::ROOT; STACK_LEN]) };
}

/// A stack of this many children never overflows, in either tree: a node
/// visited takes one entry off and puts at most [`WIDE`] − 1 more on, and a
/// path from the root has at most [`MAX_DEPTH`] nodes (the eight-wide tree is
/// the four-wide one with levels merged: no deeper).
pub const STACK_LEN: usize = (WIDE - 1) * MAX_DEPTH + 1;

/// What the reference traversal visits next, or keeps waiting on its stack:
/// a node, or a leaf's [`LeafLanes`] ([`Leaves::children`] says which), with
/// the t at which the ray enters its box.
#[derive(Clone, Copy, Debug)]
pub struct Next {
    pub child: u32,
    pub t_enter: Float,
}

impl Next {
    /// The root node, entered before anything.
    pub const ROOT: Next = Next { child: 0, t_enter: Float::NEG_INFINITY };

    /// Marks `child` as the index of a leaf's [`LeafLanes`], not of a node.
    pub const LEAF: u32 = 1 << 31;
}

/// The leaves of a [`crate::Bvh`] as the reference traversal tests them:
/// each leaf's primitives (at most [`MAX_LEAF`] = four) in the four lanes of
/// one [`LeafLanes`], and for every node its children as [`Next::child`]
/// says them (a node's index, or [`Next::LEAF`] and the leaf's lanes), so
/// that a child met is visited with no other lookup. Book: §9.7 Ordered
/// traversal.
#[derive(Clone, Debug, Default)]
pub struct Leaves {
    /// Every leaf's lanes, in the order of the leaves' primitives.
    pub lanes: Vec<LeafLanes>,
    /// `children[i][c]`: child c of node i (anything for an empty slot).
    pub children: Vec<[u32; WIDTH]>,
    /// The tree again with eight children per node ([`WideNode`]), the
    /// root first: built where the CPU has AVX2 ([`Leaves::avx2`]) and
    /// [`Float`] is f32 (eight f32 lanes fill an AVX register; empty
    /// otherwise), and then the one traversed.
    pub wide: Vec<WideNode>,
    /// Whether this CPU has the features the eight-wide traversal is
    /// compiled for (AVX2 and the rest: [`avx2::detected`]), asked once, by
    /// [`Leaves::new`], and set nowhere else: what makes calling it sound.
    avx2: bool,
    /// `normals[i]`: the unit outward normal of primitive i if it is a mesh
    /// triangle, as its hit record has it before facing the ray (03's
    /// `hit_triangle` normalises the cross product, then [`Hit::new`] again:
    /// done here once per triangle, so that [`triangle_record`] does no square
    /// root); anything for a whole object.
    pub normals: Vec<Vec3>,
}

/// One leaf's primitives in four lanes: lane k is the leaf's k-th primitive
/// (`first + k`); the corners of the mesh triangles among them, plane by
/// plane, and which lanes hold what.
#[derive(Clone, Copy, Debug)]
pub struct LeafLanes {
    /// `corners[3 j + a]`: coordinate a of corner j (a, b, c) of each lane's
    /// triangle; NaN in the lanes without one (so no edge function there is 0
    /// and sends the lane to the f64 recomputation; a NaN lane never hits).
    corners: [Vec4; 9],
    /// The lanes 03's triangle test can hit (bit k for lane k): mesh triangles
    /// with a plane and a normal that does not overflow.
    triangles: u32,
    /// The lanes that are whole objects, tested by [`Primitive::hit`].
    pub whole: u32,
    /// The leaf's first primitive (in [`crate::Bvh::primitives`]).
    pub first: u32,
}

const _: () = assert!(MAX_LEAF == 4 && WIDTH == 4, "a leaf's primitives fill the four lanes of a Vec4");

impl LeafLanes {
    /// The lanes of a leaf of `primitives` (at most four) from `first`, with
    /// corners `triangles` (anything for a whole object).
    pub fn new(first: u32, primitives: &[Primitive], triangles: &[[Vec3; 3]]) -> LeafLanes {
        debug_assert!(primitives.len() <= MAX_LEAF && triangles.len() == primitives.len());
        let mut lanes = LeafLanes { corners: [Vec4::NAN; 9], triangles: 0, whole: 0, first };
        for (k, (primitive, &[a, b, c])) in primitives.iter().zip(triangles).enumerate() {
            if primitive.triangle == Primitive::WHOLE {
                lanes.whole |= 1 << k;
                continue;
            }
            for (j, corner) in [a, b, c].into_iter().enumerate() {
                for axis in 0..3 {
                    lanes.corners[3 * j + axis][k] = corner[axis];
                }
            }
            // 03's hit_triangle: no hit for a triangle without a plane, or whose
            // normal overflows.
            let (ab, ac) = (b - a, c - a);
            if ac.cross(ab).length_squared() != 0.0 && ab.cross(ac).try_normalize().is_some() {
                lanes.triangles |= 1 << k;
            }
        }
        lanes
    }

    /// How many of the lanes are mesh triangles, all tested at once (for the
    /// ray statistics, which count triangle tests).
    pub fn triangles_tested(&self) -> u32 {
        self.triangles.count_ones()
    }
}

impl Leaves {
    /// The lanes of every leaf of the tree `nodes`, whose leaves hold
    /// `primitives` with corners `triangles` (as [`crate::Bvh`] keeps them).
    pub fn new(nodes: &[Node], primitives: &[Primitive], triangles: &[[Vec3; 3]]) -> Leaves {
        let normals = triangles
            .iter()
            .map(|&[a, b, c]| {
                let outward = (b - a).cross(c - a).try_normalize().unwrap_or(Vec3::Z);
                outward.try_normalize().unwrap_or(Vec3::Z)
            })
            .collect();
        let mut leaves = Leaves { normals, ..Leaves::default() };
        for node in nodes {
            let mut children = [0; WIDTH];
            for (c, child) in children.iter_mut().enumerate() {
                if node.is_empty_slot(c) {
                    continue;
                }
                if !node.is_leaf(c) {
                    *child = node.offset[c];
                    continue;
                }
                let (first, count) = (node.offset[c] as usize, node.count[c] as usize);
                let range = first..first + count;
                let lanes = LeafLanes::new(first as u32, &primitives[range.clone()], &triangles[range]);
                *child = Next::LEAF | leaves.lanes.len() as u32;
                leaves.lanes.push(lanes);
            }
            leaves.children.push(children);
        }
        #[cfg(all(target_arch = "x86_64", not(raylab_submission)))]
        {
            leaves.avx2 = avx2::detected();
        }
        if leaves.avx2 && size_of::<Float>() == 4 {
            leaves.wide = WideNode::tree(nodes, &leaves.children);
        }
        leaves
    }
}

impl Node {
    /// The four children's boxes tested against `ray` at once, each lane as
    /// [`crate::Aabb::hit`] tests one box: returns the entry t of each child
    /// (lane i; widened down, clipped to `range.min`) and a bit mask of the
    /// children the ray meets within `range` (bit i for child i). Empty
    /// slots are never met. `range.min` must be the one `ray` was prepared
    /// for; `range.max` may shrink.
    ///
    /// The slab method with everything that depends on the ray alone
    /// computed once per ray ([`BoxRay`]): the reciprocal direction for each
    /// plane with the widening folded in, and the origin. Per axis, two
    /// subtractions, two multiplications, a min and a max of four lanes; then
    /// the latest entry and the earliest exit, each a max or min of four,
    /// taken two by two, and a lane is met when it enters before it
    /// leaves (strictly: an empty slot, at +∞, enters and leaves at +∞; a
    /// flat box still spans the width of the widening, unless at t = 0, where
    /// no range holds a hit). Conservative like [`crate::Aabb::hit`]:
    /// both ends widened by 2γ₄, and a ray lying in a box's face still meets
    /// the box. Book: §9.7 Ordered traversal.
    #[inline(always)] // once per node in the traversal's hot loop
    pub fn hit_children<const WIDEN_EACH: bool>(
        &self,
        ray: &BoxRay<WIDEN_EACH>,
        range: Interval,
    ) -> ([Float; WIDTH], u32) {
        // Slab a: the t of the min plane and of the max plane; the ray enters by the
        // nearer and leaves by the farther.
        let slab = |a: usize| {
            let t_min = (self.planes[a] - ray.origin_min[a]) * ray.inv_min[a];
            let t_max = (self.planes[3 + a] - ray.origin_max[a]) * ray.inv_max[a];
            (t_min.min(t_max), t_min.max(t_max))
        };
        let ((near_x, far_x), (near_y, far_y), (near_z, far_z)) = (slab(0), slab(1), slab(2));
        let mut enter = near_x.max(near_y).max(near_z.max(Vec4::splat(range.min)));
        let mut exit = far_x.min(far_y).min(far_z.min(Vec4::splat(range.max)));
        if WIDEN_EACH {
            (enter, exit) =
                ((enter * WIDEN_DOWN).min(enter * WIDEN_UP), (exit * WIDEN_UP).max(exit * WIDEN_DOWN));
        }
        (enter.to_array(), enter.cmplt(exit).bitmask())
    }
}

/// The factors that widen a box's span by 2γ₄ (relative).
const WIDEN_DOWN: Float = 1.0 - 2.0 * gamma(4);
const WIDEN_UP: Float = 1.0 + 2.0 * gamma(4);

/// What a box test needs of a ray, computed once per ray: per axis the
/// reciprocal direction and the origin, each in all four lanes, for the
/// slab's min plane and for its max plane.
///
/// **Widening.** Each t = (plane − o)·(1/d) is computed with at most four
/// roundings (the difference, the reciprocal, the widening factor, the
/// product): a relative error of at most γ₄. Entries are scaled down and
/// exits up by 2γ₄, which covers that and leaves as much again for the
/// primitives' own rounding, as [`crate::Aabb::hit`]'s 2γ₃ does for its
/// three. When the range starts at 0 or later, the factors are folded into
/// 1/d, at no cost per node: the plane the ray enters a slab by (the min
/// plane for d > 0, the max plane for d < 0) gets 1/d scaled down, the other
/// 1/d scaled up. That scales each t's magnitude, which widens it only for
/// t ≥ 0; but an entry clipped to range.min ≥ 0 is ≥ 0, and an exit below 0
/// misses anyway (the sign of each t is exact). A range starting below 0 has
/// each lane widened after, by the factor its sign needs: `WIDEN_EACH`
/// ([`BoxRay::widens_each`] says which a range needs), a constant of the
/// type, so that the usual traversal has no test for it per node (measured:
/// 3 % of the instructions the bunny's rays execute, when it was a field).
///
/// **Parallel axes.** An axis along which the ray does not move (1/d not
/// finite: d = ±0 or so small that 1/d overflows) has its slab all or
/// nothing: the ray is inside when min ≤ o ≤ max. There 1/d is +∞ and the
/// origin is moved one step up for the min plane and one step down for the
/// max plane, so that an origin on a plane (which would give 0·∞ = NaN)
/// gives −∞ and +∞: inside, as [`crate::Aabb::hit`] counts it. (An origin
/// one step outside can then give NaN: such a lane may be met or not, and
/// either is right for a culling test that must only never miss.)
/// Book: §9.7 Ordered traversal.
#[derive(Clone, Copy, Debug)]
pub struct BoxRay<const WIDEN_EACH: bool> {
    origin_min: [Vec4; 3],
    origin_max: [Vec4; 3],
    inv_min: [Vec4; 3],
    inv_max: [Vec4; 3],
}

impl BoxRay<false> {
    /// Whether ranges starting at `range_min` need each lane widened after
    /// (a `BoxRay<true>`): when they start below 0 (or at a NaN or ±∞).
    pub fn widens_each(range_min: Float) -> bool {
        !(range_min >= 0.0 && range_min.is_finite())
    }
}

impl<const WIDEN_EACH: bool> BoxRay<WIDEN_EACH> {
    /// The per-ray part of the box tests of `ray` (`dir` not zero), for
    /// ranges starting where [`BoxRay::widens_each`] says `WIDEN_EACH`.
    #[inline(always)] // once per ray, built in place
    pub fn new(ray: &Ray) -> Self {
        let (down, up) = match WIDEN_EACH {
            true => (Vec4::ONE, Vec4::ONE),
            false => (Vec4::splat(WIDEN_DOWN), Vec4::splat(WIDEN_UP)),
        };
        // 1/d of the three axes in one division of four lanes (each lane rounded as
        // the scalar 1/d is).
        let inv = Vec4::ONE / ray.dir.extend(1.0);
        let forward = inv.cmpgt(Vec4::ZERO);
        let (inv_min, inv_max) =
            (inv * Vec4::select(forward, down, up), inv * Vec4::select(forward, up, down));
        let lanes = |v: Vec4| [v.x, v.y, v.z].map(Vec4::splat);
        let origin = lanes(ray.origin.extend(0.0));
        let mut prepared = BoxRay {
            origin_min: origin,
            origin_max: origin,
            inv_min: lanes(inv_min),
            inv_max: lanes(inv_max),
        };
        // Axes along which the ray does not move (rare).
        if !inv.is_finite() {
            for a in (0..3).filter(|&a| !inv[a].is_finite()) {
                prepared.origin_min[a] = Vec4::splat(ray.origin[a].next_up());
                prepared.origin_max[a] = Vec4::splat(ray.origin[a].next_down());
                prepared.inv_min[a] = Vec4::INFINITY;
                prepared.inv_max[a] = Vec4::INFINITY;
            }
        }
        prepared
    }
}

/// The reference's closest-hit search in the four-wide tree, for rays whose
/// dominant axis is `KZ` and ranges that need `WIDEN_EACH`: one copy of
/// [`closest_in_tree`] with [`Node::hit_children`] inlined.
pub fn four_wide_closest<const KZ: usize, const WIDEN_EACH: bool>(
    bvh: &Bvh,
    ray: &Ray,
    closest: &mut Closest,
) -> u64 {
    let (boxes, sheared) = (BoxRay::<WIDEN_EACH>::new(ray), ShearedRay::<KZ>::new(ray));
    STACK.with_borrow_mut(|stack| {
        closest_in_tree(bvh, ray, &sheared, closest, stack, |index, search| {
            let (t_enter, met) = bvh.nodes[index].hit_children(&boxes, search);
            (t_enter, met, &bvh.leaves.children[index])
        })
    })
}

/// The reference's any-hit search in the four-wide tree: [`any_in_tree`] with
/// [`Node::hit_children`], as [`four_wide_closest`].
pub fn four_wide_any<const KZ: usize, const WIDEN_EACH: bool>(
    bvh: &Bvh,
    ray: &Ray,
    range: Interval,
) -> (bool, u64) {
    let (boxes, sheared) = (BoxRay::<WIDEN_EACH>::new(ray), ShearedRay::<KZ>::new(ray));
    STACK.with_borrow_mut(|stack| {
        any_in_tree(bvh, ray, &sheared, range, stack, |index, range| {
            let (t_enter, met) = bvh.nodes[index].hit_children(&boxes, range);
            (t_enter, met, &bvh.leaves.children[index])
        })
    })
}

/// The copy of a search (`$four` or `$eight`, generic over the dominant axis
/// `KZ` and `WIDEN_EACH`) made for `$bvh`'s nodes (eight-wide where it has
/// them), the dominant axis of `$ray` and the widening `$range` needs: each
/// picked once per ray, as a function pointer, so that the loop has no test
/// for them.
macro_rules! copy_for {
    ($four:ident, $eight:ident, $bvh:expr, $ray:expr, $range:expr) => {
        match (
            !$bvh.leaves.wide.is_empty(),
            l03_polygons_triangles::dominant_axis($ray.dir),
            crate::fast::BoxRay::widens_each($range.min),
        ) {
            (false, 0, false) => $four::<0, false>,
            (false, 1, false) => $four::<1, false>,
            (false, _, false) => $four::<2, false>,
            (false, 0, true) => $four::<0, true>,
            (false, 1, true) => $four::<1, true>,
            (false, _, true) => $four::<2, true>,
            (true, 0, false) => $eight::<0, false>,
            (true, 1, false) => $eight::<1, false>,
            (true, _, false) => $eight::<2, false>,
            (true, 0, true) => $eight::<0, true>,
            (true, 1, true) => $eight::<1, true>,
            (true, _, true) => $eight::<2, true>,
        }
    };
}
pub(crate) use copy_for;

/// The closest-hit search in the eight-wide tree ([`Leaves::wide`], which
/// exists only where the CPU has AVX2), compiled for AVX2; the four-wide one
/// on any other CPU.
pub fn eight_wide_closest<const KZ: usize, const WIDEN_EACH: bool>(
    bvh: &Bvh,
    ray: &Ray,
    closest: &mut Closest,
) -> u64 {
    #[cfg(all(target_arch = "x86_64", not(raylab_submission)))]
    if bvh.leaves.avx2 {
        #[allow(unsafe_code)]
        // SAFETY: the function is compiled for the CPU features that `avx2` says
        // this CPU has (detected by `Leaves::new`), which is all that calling a
        // `#[target_feature]` function requires.
        return unsafe { avx2::closest::<KZ, WIDEN_EACH>(bvh, ray, closest) };
    }
    four_wide_closest::<KZ, WIDEN_EACH>(bvh, ray, closest)
}

/// The any-hit search in the eight-wide tree, as [`eight_wide_closest`].
pub fn eight_wide_any<const KZ: usize, const WIDEN_EACH: bool>(
    bvh: &Bvh,
    ray: &Ray,
    range: Interval,
) -> (bool, u64) {
    #[cfg(all(target_arch = "x86_64", not(raylab_submission)))]
    if bvh.leaves.avx2 {
        #[allow(unsafe_code)]
        // SAFETY: as in `eight_wide_closest`: this CPU has the features.
        return unsafe { avx2::any::<KZ, WIDEN_EACH>(bvh, ray, range) };
    }
    four_wide_any::<KZ, WIDEN_EACH>(bvh, ray, range)
}

/// How many children a [`WideNode`] has.
pub const WIDE: usize = 8;

/// A node of eight children: the four-wide tree's node with some of its
/// children replaced by theirs (grandchildren pulled up, the inner child with
/// the largest box first, while they fit in eight slots), so that a ray
/// decides eight children in one box test, of about the cost of a four-wide
/// one on AVX's 256-bit registers, and goes down half as many levels (the
/// bunny: 10,225 four-wide nodes in 10 levels, 5,099 eight-wide ones in 6).
/// The planes as in [`Node`], eight lanes of f32; the children as
/// [`Next::child`] names them, the leaves the same [`LeafLanes`].
/// 256 bytes, four cache lines, aligned to one. Book: §9.7 Ordered traversal.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
#[cfg_attr(any(not(target_arch = "x86_64"), raylab_submission), allow(dead_code))] // built, never traversed there
pub struct WideNode {
    /// `planes[a][i]`: plane a of child i's box (a point at +∞ in an empty
    /// slot), as lane i of [`Node::planes`]`[a]`.
    planes: [[f32; WIDE]; 6],
    /// Child i as [`Next::child`] names it (anything in an empty slot).
    children: [u32; WIDE],
}

impl WideNode {
    /// A node whose eight slots are all empty.
    const EMPTY: WideNode = WideNode { planes: [[f32::INFINITY; WIDE]; 6], children: [0; WIDE] };

    /// The eight-wide tree of the four-wide `nodes`, whose children are named
    /// by `children` (as [`Leaves::children`] names them): the root first,
    /// each node before its subtrees.
    fn tree(nodes: &[Node], children: &[[u32; WIDTH]]) -> Vec<WideNode> {
        let mut wide = Vec::with_capacity(nodes.len());
        if !nodes.is_empty() {
            WideNode::add(nodes, children, 0, &mut wide);
        }
        wide
    }

    /// Adds to `wide` the node standing for four-wide node `n`, then its
    /// subtrees; returns its index.
    fn add(nodes: &[Node], children: &[[u32; WIDTH]], n: usize, wide: &mut Vec<WideNode>) -> u32 {
        // Node n's children: their boxes and names.
        let slots = |n: usize| {
            (0..WIDTH)
                .filter(move |&c| !nodes[n].is_empty_slot(c))
                .map(move |c| (nodes[n].child_bounds(c), children[n][c]))
        };
        let mut list: Vec<(Aabb, u32)> = slots(n).collect();
        // The inner child with the largest box whose children fit in its place and
        // the free slots, replaced by them; until none fits.
        while let Some(k) = (0..list.len())
            .filter(|&k| {
                list[k].1 & Next::LEAF == 0 && list.len() - 1 + slots(list[k].1 as usize).count() <= WIDE
            })
            .max_by(|&a, &b| list[a].0.surface_area().total_cmp(&list[b].0.surface_area()))
        {
            let inner = list[k].1 as usize;
            list.splice(k..k + 1, slots(inner));
        }
        let index = wide.len();
        wide.push(WideNode::EMPTY);
        let mut node = WideNode::EMPTY;
        for (i, &(bounds, child)) in list.iter().enumerate() {
            for a in 0..3 {
                let (min, max) = (bounds.min[a] as f32, bounds.max[a] as f32);
                (node.planes[a][i], node.planes[3 + a][i]) = (min, max);
            }
            node.children[i] = match child & Next::LEAF {
                0 => WideNode::add(nodes, children, child as usize, wide),
                _ => child,
            };
        }
        wide[index] = node;
        index as u32
    }
}

/// The eight-wide traversal, compiled for AVX2 (safe code: the intrinsics
/// are safe to call in functions compiled for their features, and bytemuck
/// moves eight f32 in and out of an AVX register). Everything inlined into
/// [`avx2::closest`] and [`avx2::any`] — the loop, the box test, 03's
/// triangle test on a leaf's lanes — is compiled for AVX2, so the four-lane
/// (SSE) parts get AVX's encodings too.
#[cfg(all(target_arch = "x86_64", not(raylab_submission)))]
mod avx2 {
    use super::*;
    use std::arch::x86_64::{
        __m256, _CMP_LT_OS, _mm256_cmp_ps, _mm256_max_ps, _mm256_min_ps, _mm256_movemask_ps, _mm256_mul_ps,
        _mm256_set1_ps, _mm256_sub_ps,
    };

    /// Whether this CPU has every feature the functions here are compiled
    /// for (std caches the answer).
    pub fn detected() -> bool {
        is_x86_feature_detected!("avx2")
            && is_x86_feature_detected!("bmi1")
            && is_x86_feature_detected!("lzcnt")
            && is_x86_feature_detected!("popcnt")
    }

    /// [`BoxRay`] in eight lanes.
    struct WideRay {
        origin_min: [__m256; 3],
        origin_max: [__m256; 3],
        inv_min: [__m256; 3],
        inv_max: [__m256; 3],
    }

    impl WideRay {
        #[target_feature(enable = "avx2")]
        fn new<const WIDEN_EACH: bool>(ray: &BoxRay<WIDEN_EACH>) -> Self {
            let lanes = |v: &[Vec4; 3]| v.map(|lanes| _mm256_set1_ps(lanes.x as f32));
            WideRay {
                origin_min: lanes(&ray.origin_min),
                origin_max: lanes(&ray.origin_max),
                inv_min: lanes(&ray.inv_min),
                inv_max: lanes(&ray.inv_max),
            }
        }
    }

    impl WideNode {
        /// The eight children's boxes tested against `ray` at once: each lane
        /// exactly as [`Node::hit_children`] tests one (the same operations
        /// in the same order, on the same numbers).
        #[target_feature(enable = "avx2")]
        fn hit_children<const WIDEN_EACH: bool>(
            &self,
            ray: &WideRay,
            range: Interval,
        ) -> ([Float; WIDE], u32) {
            let slab = |a: usize| {
                let (min, max): (__m256, __m256) =
                    (bytemuck::cast(self.planes[a]), bytemuck::cast(self.planes[3 + a]));
                let t_min = _mm256_mul_ps(_mm256_sub_ps(min, ray.origin_min[a]), ray.inv_min[a]);
                let t_max = _mm256_mul_ps(_mm256_sub_ps(max, ray.origin_max[a]), ray.inv_max[a]);
                (_mm256_min_ps(t_min, t_max), _mm256_max_ps(t_min, t_max))
            };
            let ((near_x, far_x), (near_y, far_y), (near_z, far_z)) = (slab(0), slab(1), slab(2));
            let (range_min, range_max) = (_mm256_set1_ps(range.min as f32), _mm256_set1_ps(range.max as f32));
            let mut enter = _mm256_max_ps(_mm256_max_ps(near_x, near_y), _mm256_max_ps(near_z, range_min));
            let mut exit = _mm256_min_ps(_mm256_min_ps(far_x, far_y), _mm256_min_ps(far_z, range_max));
            if WIDEN_EACH {
                let (down, up) = (_mm256_set1_ps(WIDEN_DOWN as f32), _mm256_set1_ps(WIDEN_UP as f32));
                enter = _mm256_min_ps(_mm256_mul_ps(enter, down), _mm256_mul_ps(enter, up));
                exit = _mm256_max_ps(_mm256_mul_ps(exit, up), _mm256_mul_ps(exit, down));
            }
            let met = _mm256_movemask_ps(_mm256_cmp_ps::<_CMP_LT_OS>(enter, exit)) as u32;
            (bytemuck::cast::<__m256, [f32; WIDE]>(enter).map(Float::from), met)
        }
    }

    /// [`WideNode::hit_children`] where this CPU has the features it is
    /// compiled for (None elsewhere): for the tests, which compare it lane by
    /// lane with [`Node::hit_children`].
    #[cfg(test)]
    pub fn hit_children_here<const WIDEN_EACH: bool>(
        node: &WideNode,
        ray: &BoxRay<WIDEN_EACH>,
        range: Interval,
    ) -> Option<([Float; WIDE], u32)> {
        #[allow(unsafe_code)]
        // SAFETY: the functions are compiled for the features just detected.
        detected().then(|| unsafe { node.hit_children::<WIDEN_EACH>(&WideRay::new(ray), range) })
    }

    /// [`closest_in_tree`] on the eight-wide nodes.
    #[target_feature(enable = "avx2,bmi1,lzcnt,popcnt")]
    pub fn closest<const KZ: usize, const WIDEN_EACH: bool>(
        bvh: &Bvh,
        ray: &Ray,
        closest: &mut Closest,
    ) -> u64 {
        let (boxes, sheared) = (WideRay::new(&BoxRay::<WIDEN_EACH>::new(ray)), ShearedRay::<KZ>::new(ray));
        STACK.with_borrow_mut(|stack| {
            closest_in_tree(bvh, ray, &sheared, closest, stack, |index, search| {
                let node = &bvh.leaves.wide[index];
                let (t_enter, met) = node.hit_children::<WIDEN_EACH>(&boxes, search);
                (t_enter, met, &node.children)
            })
        })
    }

    /// [`any_in_tree`] on the eight-wide nodes.
    #[target_feature(enable = "avx2,bmi1,lzcnt,popcnt")]
    pub fn any<const KZ: usize, const WIDEN_EACH: bool>(
        bvh: &Bvh,
        ray: &Ray,
        range: Interval,
    ) -> (bool, u64) {
        let (boxes, sheared) = (WideRay::new(&BoxRay::<WIDEN_EACH>::new(ray)), ShearedRay::<KZ>::new(ray));
        STACK.with_borrow_mut(|stack| {
            any_in_tree(bvh, ray, &sheared, range, stack, |index, range| {
                let node = &bvh.leaves.wide[index];
                let (t_enter, met) = node.hit_children::<WIDEN_EACH>(&boxes, range);
                (t_enter, met, &node.children)
            })
        })
    }
}

/// Lecture 03's watertight test (`hit_triangle_watertight`, Woop, Benthin and
/// Wald 2013) split in two: the part that depends on the ray alone (the
/// shear Sₓ = −dₓ/d_z, S_y = −d_y/d_z and 1/d_z, three divisions done as one
/// of four lanes) made once per ray here, the rest per triangle in
/// [`ShearedRay::hit_lanes`], four triangles at once. The ray's dominant
/// axis `KZ` (03's `dominant_axis`, which becomes z; (KZ + 1) mod 3 becomes
/// x and (KZ + 2) mod 3 y) is a constant of the type, so that the
/// traversal, made once per axis, picks the coordinates with no test per
/// triangle. The same operations on the same
/// numbers in the same order as 03's: the same t, β and γ, bit for bit, so
/// the BVH's answers stay brute force's. Book: §9.7 Ordered traversal.
#[derive(Clone, Copy, Debug)]
pub struct ShearedRay<const KZ: usize> {
    origin: Vec3,
    /// Sₓ, S_y and 1/d_z.
    shear: Vec3,
}

impl<const KZ: usize> ShearedRay<KZ> {
    /// The axes that become x and y.
    const KX: usize = (KZ + 1) % 3;
    const KY: usize = (KZ + 2) % 3;

    /// The per-ray part of the triangle tests of `ray`, whose dominant axis
    /// must be `KZ`.
    pub fn new(ray: &Ray) -> Self {
        debug_assert_eq!(dominant_axis(ray.dir), KZ, "{ray:?}");
        let d = ray.dir;
        // −dₓ/d_z, −d_y/d_z and 1/d_z: (−a)/b is −(a/b) exactly, so these are 03's.
        let shear = Vec4::new(-d[Self::KX], -d[Self::KY], 1.0, 1.0) / Vec4::splat(d[KZ]);
        Self { origin: ray.origin, shear: shear.truncate() }
    }

    /// The triangles of a leaf's lanes tested at once, each lane exactly as
    /// 03's `hit_triangle` tests one: the same operations, lane by lane
    /// (an edge function that is 0 in f32 recomputed in f64 for that lane, as
    /// 03's `edge_function` does). Returns the mask of the lanes hit inside
    /// `range` (bit k for lane k) and each lane's t, β and γ (meaningful in
    /// the lanes hit).
    #[inline(always)] // once per leaf in the traversal's hot loop
    pub fn hit_lanes(&self, lanes: &LeafLanes, range: Interval) -> (u32, [TriangleHit; 4]) {
        let origin = self.origin.extend(0.0);
        let (kx, ky) = (Self::KX, Self::KY);
        let (sx, sy, sz) = (Vec4::splat(self.shear.x), Vec4::splat(self.shear.y), Vec4::splat(self.shear.z));
        let to_ray_space = |j: usize| {
            let c = &lanes.corners[3 * j..3 * j + 3];
            let (x, y, z) = (
                c[kx] - Vec4::splat(origin[kx]),
                c[ky] - Vec4::splat(origin[ky]),
                c[KZ] - Vec4::splat(origin[KZ]),
            );
            [x + sx * z, y + sy * z, z * sz]
        };
        let (p0, p1, p2) = (to_ray_space(0), to_ray_space(1), to_ray_space(2));
        let edge = |p: &[Vec4; 3], q: &[Vec4; 3]| {
            let e = p[0] * q[1] - p[1] * q[0];
            // 03's edge_function: a 0 in f32 is recomputed in f64 (rare: rays through
            // an edge's line or a corner).
            if Float::MANTISSA_DIGITS < f64::MANTISSA_DIGITS && e.cmpeq(Vec4::ZERO).any() {
                let wide = |v: Vec4, k: usize| v[k] as f64;
                return Vec4::from_array(std::array::from_fn(|k| match e[k] == 0.0 {
                    true => (wide(p[0], k) * wide(q[1], k) - wide(p[1], k) * wide(q[0], k)) as Float,
                    false => e[k],
                }));
            }
            e
        };
        let (e0, e1, e2) = (edge(&p1, &p2), edge(&p2, &p0), edge(&p0, &p1));
        let negative = e0.cmplt(Vec4::ZERO) | e1.cmplt(Vec4::ZERO) | e2.cmplt(Vec4::ZERO);
        let positive = e0.cmpgt(Vec4::ZERO) | e1.cmpgt(Vec4::ZERO) | e2.cmpgt(Vec4::ZERO);
        // No lane inside its triangle: no division, no t.
        if (!(negative & positive)).bitmask() & lanes.triangles == 0 {
            let none = TriangleHit { t: Float::NAN, beta: Float::NAN, gamma: Float::NAN };
            return (0, [none; 4]);
        }
        let det = e0 + e1 + e2;
        let inv_det = Vec4::ONE / det;
        let t = (e0 * p0[2] + e1 * p1[2] + e2 * p2[2]) * inv_det;
        // Inside (all edge functions of one sign, zeros allowed), not edge-on, in range.
        let inside = !(negative & positive) & det.cmpne(Vec4::ZERO);
        let in_range = Vec4::splat(range.min).cmplt(t) & t.cmplt(Vec4::splat(range.max));
        let hit = (inside & in_range).bitmask() & lanes.triangles;
        let (t, beta, gamma) = (t.to_array(), (e1 * inv_det).to_array(), (e2 * inv_det).to_array());
        (hit, std::array::from_fn(|k| TriangleHit { t: t[k], beta: beta[k], gamma: gamma[k] }))
    }
}

/// The hit record of the mesh triangle `primitive`, whose unit outward
/// normal is `normal` (from [`Leaves::normals`]), where `ray` meets it as
/// `found` (from [`ShearedRay::hit_lanes`]) says: the very record lecture
/// 03's `hit_triangle` and 09's `hit_mesh_triangle` build (the geometric
/// normal, turned to face the ray; the interpolated vertex normal on that
/// side, if the mesh has normals; uv from the mesh's, or (β, γ)), the same
/// operations on the same numbers, but from the t, β and γ the traversal
/// found, without testing the triangle a second time, and with the normal's
/// two normalisations done at build time. Built once per ray, for the
/// closest hit. Measured on the bunny: calling `hit_mesh_triangle` instead
/// made the whole query about 15 % slower (its second watertight test and
/// index lookups cost as much as a third of the traversal), and normalising
/// here, with the corners looked up, about 20 % slower (the two square roots
/// and divisions and a cache miss on each hit ray).
/// Book: §9.7 Ordered traversal.
pub fn triangle_record(
    objects: &[Object],
    primitive: Primitive,
    normal: Vec3,
    ray: &Ray,
    found: TriangleHit,
) -> Option<Hit> {
    let index = primitive.object as usize;
    let object = &objects[index];
    let Shape::Mesh(mesh) = &object.shape else {
        return None;
    };
    let corners = || mesh.triangles[primitive.triangle as usize].map(|i| i as usize);
    let (beta, gamma) = (found.beta, found.gamma);
    let mut hit = Hit::facing(ray, found.t, normal).with_uv(Vec2::new(beta, gamma));
    if !mesh.normals.is_empty() {
        let shading = interpolate_normal(&corners().map(|i| mesh.normals[i]), beta, gamma);
        if shading != Vec3::ZERO {
            hit.normal = if shading.dot(hit.normal) < 0.0 { -shading } else { shading };
        }
    }
    if !mesh.uvs.is_empty() {
        let [i, j, k] = corners();
        hit = hit.with_uv((1.0 - beta - gamma) * mesh.uvs[i] + beta * mesh.uvs[j] + gamma * mesh.uvs[k]);
    }
    Some(Hit { object: index, material: object.material, ..hit })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Aabb;
    use crate::testing::Rng;
    use l03_polygons_triangles::hit_triangle;

    /// A node holding `boxes` in its first slots, the rest empty.
    fn node_of(boxes: &[Aabb]) -> Node {
        let mut node = Node::EMPTY;
        for (i, &b) in boxes.iter().enumerate() {
            node.set_child_bounds(i, b);
            node.count[i] = 1;
        }
        node
    }

    /// [`Node::hit_children`] with the [`BoxRay`] that `range` needs, as the
    /// traversal picks it.
    fn hit_children(node: &Node, ray: &Ray, range: Interval) -> ([Float; WIDTH], u32) {
        match BoxRay::widens_each(range.min) {
            true => node.hit_children(&BoxRay::<true>::new(ray), range),
            false => node.hit_children(&BoxRay::<false>::new(ray), range),
        }
    }

    /// A random box in [−4, 4]³, a tenth of them flat along one axis.
    fn random_box(rng: &mut Rng, n: usize) -> Aabb {
        let (p, q) = (rng.in_cube(4.0), rng.in_cube(4.0));
        let mut b = Aabb::new(p.min(q), p.max(q));
        if n.is_multiple_of(10) {
            b.max[n % 3] = b.min[n % 3];
        }
        b
    }

    /// A random ray from [−6, 6]³ (two in three aimed into [−2, 2]³), one in
    /// five with a direction component of ±0 (an axis-parallel ray), and a
    /// range: whole, shortened, late-starting or starting below 0.
    fn random_query(rng: &mut Rng, n: usize) -> (Ray, Interval) {
        let origin = rng.in_cube(6.0);
        // Two in three aimed into the middle, where the boxes are.
        let mut dir =
            if n.is_multiple_of(3) { rng.direction() } else { (rng.in_cube(2.0) - origin).normalize() };
        if n % 5 == 1 {
            dir[n % 3] = if n.is_multiple_of(2) { 0.0 } else { -0.0 };
        }
        let range = match n % 4 {
            0 => Interval::new(0.0, rng.range(0.5, 8.0)),
            1 => Interval::new(rng.range(0.5, 4.0), Float::INFINITY),
            2 => Interval::new(rng.range(-6.0, -0.1), rng.range(0.0, 8.0)),
            _ => Interval::POSITIVE,
        };
        (Ray::new(origin, dir), range)
    }

    #[test]
    fn four_lanes_never_miss_what_the_box_test_meets() {
        // 10⁴ nodes of four random boxes against random rays: every box that 09's
        // Aabb::hit meets is met in its lane, entered no later (up to both tests'
        // widening: the lane's 2γ₄ against the box test's 2γ₃, so within 4γ₄
        // relative); lanes met that Aabb::hit misses (both are conservative, by
        // different margins) must be rare: boundary cases only.
        let mut rng = Rng::new(21);
        let (mut met, mut extra) = (0, 0);
        for n in 0..10_000 {
            let boxes: Vec<Aabb> = (0..4).map(|k| random_box(&mut rng, 4 * n + k)).collect();
            let (ray, range) = random_query(&mut rng, n);
            let node = node_of(&boxes);
            let (entries, mask) = hit_children(&node, &ray, range);
            for (i, b) in boxes.iter().enumerate() {
                let lane = mask & (1 << i) != 0;
                match b.hit(&ray, ray.dir.recip(), range) {
                    Some((t0, _)) => {
                        met += 1;
                        assert!(lane, "{ray:?} {range:?}: box {b:?} met by Aabb::hit, missed in lane {i}");
                        let slack = 4.0 * gamma(4) * t0.abs();
                        assert!(
                            entries[i] <= t0 + slack,
                            "lane {i} entered at {}, the box at {t0}",
                            entries[i]
                        );
                    }
                    None => extra += lane as usize,
                }
            }
        }
        eprintln!("four-wide box test: {met} boxes met, {extra} more lanes met than Aabb::hit meets");
        assert!(met > 4_000, "{met}: too few boxes met for the test to mean much");
        assert!(extra <= 4, "{extra} lanes met that Aabb::hit misses");
    }

    #[test]
    fn a_range_starting_behind_the_origin_widens_each_lane_by_its_sign() {
        // The box [−2, −1] × [−0.5, 1] × [−1, 1] behind the origin, the ray from it along
        // (1, 0.5, 0) in a range from −5: x in the box for t ∈ [−2, −1], y for t ∈ [−1, 2]
        // (1/0.5 = 2, exact): the ray touches the box at the single point t = −1, its edge.
        // Each lane widened by its sign's factor, entries down and exits up, it is met,
        // entered at or before −1.
        let node = node_of(&[Aabb::new(Vec3::new(-2.0, -0.5, -1.0), Vec3::new(-1.0, 1.0, 1.0))]);
        let ray = Ray::new(Vec3::ZERO, Vec3::new(1.0, 0.5, 0.0));
        let range = Interval::new(-5.0, Float::INFINITY);
        assert!(BoxRay::widens_each(range.min) && !BoxRay::widens_each(0.0));
        let (entries, mask) = hit_children(&node, &ray, range);
        assert_eq!(mask, 1);
        assert!(entries[0] <= -1.0, "{}", entries[0]);
        // The factors folded into 1/d, right only for t ≥ 0, would shrink the box here
        // (x's exit −1 scaled up to −1 − 2γ₄, y's entry −1 down to −1 + 2γ₄): missed.
        // That is why a range starting below 0 takes the other copy.
        assert_eq!(node.hit_children(&BoxRay::<false>::new(&ray), range).1, 0);
        // The same edge in front, at t = 1 (the box mirrored through the origin), for a
        // range from 0: met with the folded factors.
        let ahead = node_of(&[Aabb::new(Vec3::new(1.0, -1.0, -1.0), Vec3::new(2.0, 0.5, 1.0))]);
        assert_eq!(ahead.hit_children(&BoxRay::<false>::new(&ray), Interval::POSITIVE).1, 1);
    }

    #[test]
    fn rays_along_a_face_meet_the_box_and_empty_slots_none() {
        // The box [0, 1]³ in slot 0, slots 1–3 empty. Rays along +z or −z (x and y
        // components +0 or −0) with the origin on the planes x = 0, x = 1, y = 0,
        // y = 1 (in a face or along an edge) meet it; one step outside they may (either
        // is right for a culling test); 0.01 outside they do not.
        let node = node_of(&[Aabb::new(Vec3::ZERO, Vec3::ONE)]);
        let zeros = [0.0, -0.0];
        for (x, y) in [(0.0, 0.5), (1.0, 0.5), (0.5, 0.0), (0.5, 1.0), (0.0, 0.0), (1.0, 1.0)] {
            for (zx, zy, dz) in [(0, 0, 1.0), (1, 0, 1.0), (0, 1, -1.0), (1, 1, -1.0)] {
                let dir = Vec3::new(zeros[zx], zeros[zy], dz);
                let origin = Vec3::new(x, y, -2.0 * dz);
                let (entries, mask) = hit_children(&node, &Ray::new(origin, dir), Interval::POSITIVE);
                assert_eq!(mask, 1, "{origin} along {dir}");
                // It enters the face z = 0 (or z = 1) at t = 2 (1 going −z), widened down.
                let t = if dz > 0.0 { 2.0 } else { 1.0 };
                assert!(entries[0] <= t && entries[0] > t * (1.0 - 3.0 * gamma(4)), "{}", entries[0]);
                // 0.01 outside across the plane the origin lies on.
                let outside = match (x, y) {
                    (0.0, _) => Vec3::new(-0.01, y, origin.z),
                    (1.0, _) => Vec3::new(1.01, y, origin.z),
                    (_, 0.0) => Vec3::new(x, -0.01, origin.z),
                    _ => Vec3::new(x, 1.01, origin.z),
                };
                let (_, mask) = hit_children(&node, &Ray::new(outside, dir), Interval::POSITIVE);
                assert_eq!(mask, 0, "{outside} along {dir}");
            }
        }
        // Empty slots: never met, from anywhere, in any direction, parallel or not.
        let mut rng = Rng::new(22);
        for n in 0..2_000 {
            let (ray, range) = random_query(&mut rng, n);
            let (_, mask) = hit_children(&Node::EMPTY, &ray, range);
            assert_eq!(mask, 0, "{ray:?} {range:?}");
        }
    }

    /// [`ShearedRay::hit_lanes`] of the copy for `ray`'s dominant axis, as the traversal picks it.
    fn hit_lanes(ray: &Ray, lanes: &LeafLanes, range: Interval) -> (u32, [TriangleHit; 4]) {
        match dominant_axis(ray.dir) {
            0 => ShearedRay::<0>::new(ray).hit_lanes(lanes, range),
            1 => ShearedRay::<1>::new(ray).hit_lanes(lanes, range),
            _ => ShearedRay::<2>::new(ray).hit_lanes(lanes, range),
        }
    }

    #[test]
    fn leaf_lanes_find_03s_t_beta_and_gamma_bit_for_bit() {
        // Leaves of one to four random triangles (a tenth degenerate: two corners equal,
        // or all three on a line; every third leaf's second triangle shares the first's
        // edge ab; every seventh leaf with a whole object in a lane) and rays aimed at a
        // random point of one of them (so about half hit), plus rays aimed exactly at
        // corners and at the midpoint of the shared edge, where edge functions are 0 and
        // are recomputed in f64, lane by lane. Every lane must be 03's hit_triangle (what
        // brute force uses): hit or not alike, and t and (β, γ) = uv bit for bit.
        let mut rng = Rng::new(23);
        let (mut hits, mut edge_hits) = (0, 0);
        for n in 0..20_000 {
            let count = 1 + n % 4;
            let mut triangles: Vec<[Vec3; 3]> = Vec::new();
            for k in 0..count {
                let (a, mut b, mut c) = (rng.in_cube(2.0), rng.in_cube(2.0), rng.in_cube(2.0));
                match (n + k) % 20 {
                    0 => b = a,
                    1 => c = a.lerp(b, 0.25),
                    _ => {}
                }
                if k == 1 && n % 3 == 0 {
                    let [a0, b0, _] = triangles[0];
                    (b, c) = (a0, b0);
                }
                triangles.push([a, b, c]);
            }
            let mut primitives: Vec<Primitive> =
                (0..count).map(|k| Primitive { object: 0, triangle: k as u32 }).collect();
            if n % 7 == 0 {
                primitives[n % count] = Primitive::whole(1);
            }
            let lanes = LeafLanes::new(0, &primitives, &triangles);
            let [a, b, c] = triangles[n % count];
            let (beta, gamma) = rng.barycentric();
            let mut targets = vec![a + (b - a) * beta as Float * 1.2 + (c - a) * gamma as Float * 1.2];
            if n % 10 == 0 {
                targets.extend([a, b, c, triangles[0][0].lerp(triangles[0][1], 0.5)]);
            }
            for target in targets {
                let origin = rng.in_cube(5.0);
                if target == origin {
                    continue;
                }
                let ray = Ray::new(origin, target - origin);
                let range =
                    if n % 3 == 1 { Interval::new(0.0, rng.range(0.5, 2.0)) } else { Interval::POSITIVE };
                let (mask, found) = hit_lanes(&ray, &lanes, range);
                assert_eq!(mask >> count, 0, "a lane beyond the leaf hit");
                for (k, triangle) in triangles.iter().enumerate() {
                    let expected = match primitives[k].triangle {
                        Primitive::WHOLE => None,
                        _ => hit_triangle(&ray, triangle, None, range).map(|h| [h.t, h.uv.x, h.uv.y]),
                    };
                    let lane = (mask & 1 << k != 0).then_some([found[k].t, found[k].beta, found[k].gamma]);
                    let bits = |v: Option<[Float; 3]>| v.map(|v| v.map(Float::to_bits));
                    assert_eq!(bits(lane), bits(expected), "lane {k} of {count}: {ray:?} {triangle:?}");
                    hits += lane.is_some() as usize;
                    edge_hits += lane.is_some_and(|[_, beta, gamma]| beta == 0.0 || gamma == 0.0) as usize;
                }
            }
        }
        eprintln!("leaf lanes: {hits} hits ({edge_hits} on an edge), all 03's t, β and γ bit for bit");
        assert!(hits > 10_000 && edge_hits > 100, "only {hits} hits, {edge_hits} on an edge");
    }

    /// Two random nodes of four boxes and the eight-wide node holding both's
    /// boxes, first's in lanes 0–3 and second's in lanes 4–7.
    #[cfg(target_arch = "x86_64")]
    fn two_nodes_and_a_wide_one(rng: &mut Rng, n: usize) -> ([Node; 2], WideNode) {
        let nodes =
            [0, 1].map(|h| node_of(&(0..4).map(|k| random_box(rng, 8 * n + 4 * h + k)).collect::<Vec<_>>()));
        let mut wide = WideNode::EMPTY;
        for (h, node) in nodes.iter().enumerate() {
            for (a, plane) in node.planes.iter().enumerate() {
                for lane in 0..WIDTH {
                    let value = plane[lane] as f32;
                    wide.planes[a][WIDTH * h + lane] = value;
                }
            }
        }
        (nodes, wide)
    }

    #[test]
    fn eight_lanes_are_the_four_lane_test_bit_for_bit() {
        // 10⁴ eight-wide nodes (two random four-wide nodes side by side) against random
        // rays and ranges (whole, shortened, late-starting, starting below 0, a fifth of
        // the rays axis-parallel): each lane's entry t and met bit are those of the same
        // box's lane in the four-wide test, bit for bit, for both copies of the range's
        // widening. The AVX2 test then inherits everything the four-wide one is tested
        // for (never missing what Aabb::hit meets, faces, empty slots).
        if size_of::<Float>() != 4 {
            eprintln!("SKIPPED eight_lanes_are_the_four_lane_test_bit_for_bit: no eight-wide nodes in f64");
            return;
        }
        #[cfg(not(target_arch = "x86_64"))]
        eprintln!("SKIPPED eight_lanes_are_the_four_lane_test_bit_for_bit: not an x86-64 CPU, no AVX2");
        #[cfg(target_arch = "x86_64")]
        {
            let mut rng = Rng::new(33);
            let mut met = 0;
            for n in 0..10_000 {
                let (nodes, wide) = two_nodes_and_a_wide_one(&mut rng, n);
                let (ray, range) = random_query(&mut rng, n);
                let eight = match BoxRay::widens_each(range.min) {
                    true => avx2::hit_children_here(&wide, &BoxRay::<true>::new(&ray), range),
                    false => avx2::hit_children_here(&wide, &BoxRay::<false>::new(&ray), range),
                };
                let Some((entries, mask)) = eight else {
                    eprintln!("SKIPPED eight_lanes_are_the_four_lane_test_bit_for_bit: this CPU has no AVX2");
                    return;
                };
                for (h, node) in nodes.iter().enumerate() {
                    let (four_entries, four_mask) = hit_children(node, &ray, range);
                    assert_eq!((mask >> (WIDTH * h)) & 0xf, four_mask, "{ray:?} {range:?} node {h}");
                    for lane in 0..WIDTH {
                        let (a, b) = (entries[WIDTH * h + lane], four_entries[lane]);
                        assert!(a.to_bits() == b.to_bits(), "lane {lane} of node {h}: {a} against {b}");
                    }
                    met += four_mask.count_ones();
                }
                assert_eq!(mask >> (2 * WIDTH), 0, "no lane beyond the eighth");
            }
            eprintln!("eight-wide box test: {met} lanes met, all as in the four-wide test");
            assert!(met > 8_000, "{met}: too few lanes met for the test to mean much");
        }
    }

    #[test]
    fn the_eight_wide_tree_holds_the_four_wide_ones_children() {
        // On the mixed scene and on a 20,000-triangle torus: walking the eight-wide tree
        // from its root reaches every leaf of the four-wide one exactly once, and every
        // wide node once; a leaf's box in its wide node is the one the four-wide tree gave
        // it, an inner child's box the union of its own children's (as in the four-wide
        // tree, whose boxes are their subtrees' bounds); the wide tree has fewer levels.
        let torus = crate::testing::object(
            Shape::Mesh(std::sync::Arc::new(raylab::scene::Mesh::torus(1.0, 0.4, 200, 50))),
            0,
            None,
        );
        for objects in [crate::testing::mixed_scene(&mut Rng::new(5)), vec![torus]] {
            let bvh = crate::Bvh::build(&objects);
            if bvh.leaves.wide.is_empty() {
                eprintln!(
                    "SKIPPED the_eight_wide_tree_holds_the_four_wide_ones_children: no eight-wide tree here (no AVX2, or f64)"
                );
                return;
            }
            // Every leaf of the four-wide tree, by name, with its box.
            let mut leaf_boxes = std::collections::HashMap::new();
            for (node, children) in bvh.nodes.iter().zip(&bvh.leaves.children) {
                for c in (0..WIDTH).filter(|&c| !node.is_empty_slot(c) && node.is_leaf(c)) {
                    leaf_boxes.insert(children[c], node.child_bounds(c));
                }
            }
            // The boxes of a wide node's children, empty slots left out.
            let child_boxes = |node: &WideNode| -> Vec<Aabb> {
                (0..WIDE)
                    .filter(|&i| node.planes[0][i] != f32::INFINITY)
                    .map(|i| {
                        let p = |a: usize| Float::from(node.planes[a][i]);
                        Aabb::new(Vec3::new(p(0), p(1), p(2)), Vec3::new(p(3), p(4), p(5)))
                    })
                    .collect()
            };
            let (wide, mut leaves, mut visited) =
                (&bvh.leaves.wide, vec![0; bvh.leaves.lanes.len()], vec![0; bvh.leaves.wide.len()]);
            let mut depth = 0;
            let mut todo = vec![(0u32, 1)];
            while let Some((index, level)) = todo.pop() {
                visited[index as usize] += 1;
                depth = depth.max(level);
                let node = &wide[index as usize];
                for i in 0..WIDE {
                    if node.planes[0][i] == f32::INFINITY {
                        assert!((0..6).all(|a| node.planes[a][i] == f32::INFINITY), "an empty slot is empty");
                        continue;
                    }
                    let child = node.children[i];
                    let b = match child & Next::LEAF {
                        0 => {
                            todo.push((child, level + 1));
                            child_boxes(&wide[child as usize]).into_iter().reduce(Aabb::union).unwrap()
                        }
                        _ => {
                            leaves[(child & !Next::LEAF) as usize] += 1;
                            leaf_boxes[&child]
                        }
                    };
                    let planes = [b.min.x, b.min.y, b.min.z, b.max.x, b.max.y, b.max.z].map(|p| p as f32);
                    assert_eq!(
                        (0..6).map(|a| node.planes[a][i]).collect::<Vec<_>>(),
                        planes,
                        "node {index} slot {i}"
                    );
                }
            }
            assert!(leaves.iter().all(|&n| n == 1), "every leaf reached once");
            assert!(visited.iter().all(|&n| n == 1), "every wide node reached once");
            let four_depth = bvh.depth() - 1;
            assert!(depth < four_depth, "{depth} wide levels, {four_depth} four-wide");
            eprintln!(
                "{} four-wide nodes in {four_depth} levels, {} wide in {depth}",
                bvh.nodes.len(),
                wide.len()
            );
        }
    }

    #[test]
    fn leaves_list_every_child_of_the_tree() {
        // A mixed scene (whole objects and a 1,024-triangle torus): every node's children
        // as the reference visits them are its nodes, or its leaves' lanes, whose
        // primitives are the leaf's, each lane a triangle (with its corners) or a whole
        // object as the leaf holds it.
        let objects = crate::testing::mixed_scene(&mut Rng::new(5));
        let bvh = crate::Bvh::build(&objects);
        assert_eq!(bvh.leaves.children.len(), bvh.nodes.len());
        let mut leaves = 0;
        for (node, children) in bvh.nodes.iter().zip(&bvh.leaves.children) {
            for c in (0..WIDTH).filter(|&c| !node.is_empty_slot(c)) {
                if !node.is_leaf(c) {
                    assert_eq!(children[c], node.offset[c]);
                    continue;
                }
                assert_eq!(children[c], Next::LEAF | leaves, "leaves in order");
                let lanes = &bvh.leaves.lanes[leaves as usize];
                assert_eq!(lanes.first, node.offset[c]);
                for k in 0..WIDTH {
                    let i = lanes.first as usize + k;
                    let whole = k < node.count[c] as usize && bvh.primitives[i].triangle == Primitive::WHOLE;
                    assert_eq!(lanes.whole & 1 << k != 0, whole);
                    if lanes.triangles & 1 << k != 0 {
                        assert!(k < node.count[c] as usize && !whole);
                        let corners = (0..9).map(|j| lanes.corners[j][k]).collect::<Vec<_>>();
                        assert_eq!(
                            corners,
                            bvh.triangles[i].iter().flat_map(|v| v.to_array()).collect::<Vec<_>>()
                        );
                    }
                }
                leaves += 1;
            }
        }
        assert_eq!(leaves as usize, bvh.leaves.lanes.len());
        assert!(
            bvh.leaves.lanes.iter().any(|l| l.whole != 0)
                && bvh.leaves.lanes.iter().any(|l| l.triangles != 0)
        );
    }
}
