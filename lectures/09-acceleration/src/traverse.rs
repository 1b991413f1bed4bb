//! Traversing the hierarchy: the closest hit (camera, reflected and refracted
//! rays) and any hit (shadow rays), each from a stack of children waiting.

use raylab::scene::Object;
use raylab::{Float, Hit, Intersector, Interval, Ray, Vec3};

use crate::bvh::{Bvh, MAX_DEPTH, WIDTH};
use crate::primitive::Primitive;
// INSTRUCTOR BEGIN
use crate::fast::{LeafLanes, Next, STACK_LEN, ShearedRay};
use l03_polygons_triangles::TriangleHit;
// INSTRUCTOR END

/// The closest hit found so far during a traversal, with its primitive's
/// key. Glue: it keeps brute force's answer among hits at the same t, and
/// builds a mesh triangle's hit record only once the traversal is over.
#[derive(Clone, Copy, Debug)]
pub struct Closest {
    range: Interval,
    found: Option<(Float, u64, Found)>,
}

/// What the closest hit so far is: a hit record, or a mesh triangle whose
/// record is still to be built.
#[derive(Clone, Copy, Debug)]
enum Found {
    Hit(Hit),
    Triangle(Primitive),
    // INSTRUCTOR BEGIN
    /// A mesh triangle hit in a leaf's lanes by the reference traversal: its
    /// place in the leaves' order and 03's t, β and γ, from which
    /// [`crate::fast::triangle_record`] builds its record.
    Lane(Primitive, u32, TriangleHit),
    // INSTRUCTOR END
}

impl Closest {
    /// Nothing found yet in `range`.
    pub fn new(range: Interval) -> Self {
        Self { range, found: None }
    }

    /// The parameters still worth searching: the range, its max shrunk to the
    /// closest t so far. Shrunk to the next float above that t, not to t
    /// itself, so that a primitive at exactly the same t is still tested: it
    /// wins if it comes first in the scene (a smaller key), as in brute force.
    pub fn search(&self) -> Interval {
        match self.found {
            Some((t, _, _)) => self.range.with_max(t.next_up()),
            None => self.range,
        }
    }

    /// Keeps `hit`, of the primitive with `key`, if it is nearer than the
    /// closest so far, or as near and first in the scene's order.
    /// Returns whether it was kept.
    pub fn offer(&mut self, hit: Hit, key: u64) -> bool {
        self.keep(hit.t, key, Found::Hit(hit))
    }

    /// Keeps the mesh-triangle `primitive`, hit at `t` (by
    /// [`Primitive::triangle_t`]), on the same terms as [`Closest::offer`];
    /// returns whether it was kept.
    pub fn offer_triangle(&mut self, t: Float, primitive: Primitive) -> bool {
        self.keep(t, primitive.key(), Found::Triangle(primitive))
    }

    // INSTRUCTOR BEGIN
    /// Keeps the mesh-triangle `primitive`, the `index`-th in the leaves'
    /// order, hit as `found` says, on the same terms as [`Closest::offer`];
    /// returns whether it was kept.
    pub(crate) fn offer_lane(&mut self, primitive: Primitive, index: usize, found: TriangleHit) -> bool {
        self.keep(found.t, primitive.key(), Found::Lane(primitive, index as u32, found))
    }

    /// The closest hit so far if it is a triangle of the leaves' lanes: its
    /// primitive, its place in the leaves' order, and 03's t, β and γ.
    pub(crate) fn lane(&self) -> Option<(Primitive, usize, TriangleHit)> {
        match self.found {
            Some((_, _, Found::Lane(primitive, index, found))) => Some((primitive, index as usize, found)),
            _ => None,
        }
    }
    // INSTRUCTOR END

    fn keep(&mut self, t: Float, key: u64, found: Found) -> bool {
        let better = match self.found {
            None => true,
            Some((best_t, best_key, _)) => t < best_t || (t == best_t && key < best_key),
        };
        if better {
            self.found = Some((t, key, found));
        }
        better
    }

    /// The closest hit of `ray` with the scene `objects`, its record built now
    /// if it is a mesh triangle's (the same record, bit for bit, as
    /// [`Primitive::hit`] builds: the same computation on the same inputs).
    pub fn hit(self, objects: &[Object], ray: &Ray) -> Option<Hit> {
        match self.found? {
            (_, _, Found::Hit(hit)) => Some(hit),
            (_, _, Found::Triangle(primitive)) => primitive.mesh_triangle_hit(objects, ray, self.range),
            // INSTRUCTOR BEGIN
            (_, _, Found::Lane(primitive, ..)) => primitive.mesh_triangle_hit(objects, ray, self.range),
            // INSTRUCTOR END
        }
    }
}

/// A child waiting on a traversal's stack: a node (`count == 0`) or a leaf
/// (`count` primitives from `offset`), as a [`crate::Node`] lists its
/// children, with the t at which the ray enters its box.
#[derive(Clone, Copy, Debug)]
pub struct Waiting {
    pub offset: u32,
    pub count: u32,
    pub t_enter: Float,
}

/// A stack of this many [`Waiting`] children never overflows: a node visited
/// takes one entry off and puts at most [`WIDTH`] on, and a path from the
/// root has at most [`MAX_DEPTH`] nodes.
pub const STACK_SIZE: usize = (WIDTH - 1) * MAX_DEPTH + 1;

impl Bvh<'_> {
    /// The closest hit of `ray` with the scene inside `range`: the same hit
    /// (object, t, normal, uv, bit for bit) as 04's `BruteForce`.
    ///
    /// The unbounded objects are tested first, by brute force. Then the tree,
    /// from the root. At a leaf, its primitives are tested, each hit
    /// shrinking the range still worth searching ([`Closest::search`]). At a
    /// node, its children's boxes are tested against that range; the
    /// traversal goes into the nearest child met, and the others wait on a
    /// stack ([`Waiting`]), the nearer ones on top. When a branch ends, the
    /// next child comes off the stack, unless it starts beyond the closest
    /// hit found since it was put there: then it is dropped unvisited, with
    /// its whole subtree. Where the speed comes from:
    ///
    /// - **Ordered traversal.** The nearest child first finds a close hit
    ///   early, and once found, every child waiting that starts beyond it is
    ///   dropped without a look.
    /// - **Four boxes at once.** A node's four children are tested in four
    ///   SIMD lanes, with what depends on the ray alone (the reciprocal
    ///   direction 1/d: no division; the origin; the widening for rounding)
    ///   computed once per ray; the four-wide tree has half the levels of a
    ///   binary one. On CPUs with AVX2, eight boxes at once: the build makes
    ///   the tree again with eight children per node, half the levels again,
    ///   traversed by a copy of the loop compiled for AVX2.
    /// - **A leaf's triangles at once.** The corners of a leaf's (up to
    ///   four) triangles sit in the four lanes of SIMD vectors, and 03's
    ///   watertight test runs on the four together, its shear of the ray
    ///   computed once per ray; only t, β and γ are found: the full [`Hit`]
    ///   (point, interpolated normal, uv) is built once, for the closest, when
    ///   the traversal ends, from a unit normal the build computed. Whole
    ///   objects (spheres, boxes, transformed meshes) are hit through
    ///   [`Primitive::hit`] as in brute force, out of the loop's code.
    /// - **Compact nodes** (see [`crate::Node`], 128 bytes) in one flat array,
    ///   and a tree built by the SAH (see [`Bvh::build`]).
    ///
    /// No ray allocates: a stack of [`STACK_SIZE`] entries is always enough
    /// (the reference keeps one per thread and reuses it). `dir` must not be
    /// zero. Book: §9.7 Ordered traversal.
    pub fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        debug_assert!(ray.dir != Vec3::ZERO, "the ray direction must not be zero");
        // SOLUTION BEGIN
        // The fast kernels count their triangle tests themselves (in the handout, every test goes
        // through Primitive, which counts it): these imports are the reference's alone, and so
        // are not left unused in a student's finished lecture.
        use crate::fast::{copy_for, eight_wide_closest, four_wide_closest, triangle_record};
        use raylab::stats::{Counter, count_n};

        /// The unbounded objects, every one: kept out of the traversal's code,
        /// whose registers and stack frame they would crowd (measured: 2–4 %
        /// of the bunny's time when inlined, though it has none).
        #[inline(never)]
        fn unbounded(bvh: &Bvh, ray: &Ray, closest: &mut Closest) {
            for &primitive in &bvh.unbounded {
                if let Some(hit) = primitive.hit(bvh.objects, ray, closest.search()) {
                    closest.offer(hit, primitive.key());
                }
            }
        }

        let mut closest = Closest::new(range);
        if !self.unbounded.is_empty() {
            unbounded(self, ray, &mut closest);
        }
        if self.nodes.is_empty() {
            return closest.hit(self.objects, ray);
        }
        // The tree, from the root, traversed by the copy made for the ray, the range
        // and the nodes: eight-wide where the CPU has AVX2 (the build made them), else
        // four-wide.
        let tree: fn(&Bvh, &Ray, &mut Closest) -> u64 =
            copy_for!(four_wide_closest, eight_wide_closest, self, ray, range);
        let triangle_tests = tree(self, ray, &mut closest);
        count_n(Counter::IntersectionTests, triangle_tests);
        match closest.lane() {
            Some((primitive, i, found)) => {
                triangle_record(self.objects, primitive, self.leaves.normals[i], ray, found)
            }
            None => closest.hit(self.objects, ray),
        }
        // SOLUTION END
    }

    /// Whether `ray` hits anything inside `range`: true exactly when
    /// [`Bvh::closest_hit`] finds a hit, but it stops at the first one
    /// found, as a shadow ray needs no more. Unbounded objects first, then
    /// the tree: every child whose box the ray meets is visited, in the
    /// order of the node's slots (with no closest hit to shrink the range,
    /// sorting by distance saves little); the range never shrinks, and no
    /// hit record is built. `dir` must not be zero.
    /// Book: §9.8 Any hit for shadow rays.
    pub fn any_hit(&self, ray: &Ray, range: Interval) -> bool {
        debug_assert!(ray.dir != Vec3::ZERO, "the ray direction must not be zero");
        // SOLUTION BEGIN
        use crate::fast::{copy_for, eight_wide_any, four_wide_any};
        use raylab::stats::{Counter, count_n};

        // The unbounded objects.
        if self.unbounded.iter().any(|primitive| primitive.hit(self.objects, ray, range).is_some()) {
            return true;
        }
        if self.nodes.is_empty() {
            return false;
        }
        // The tree, until the first blocker, by the copy made for the ray, the range and
        // the nodes.
        let tree: fn(&Bvh, &Ray, Interval) -> (bool, u64) =
            copy_for!(four_wide_any, eight_wide_any, self, ray, range);
        let (blocked, triangle_tests) = tree(self, ray, range);
        count_n(Counter::IntersectionTests, triangle_tests);
        blocked
        // SOLUTION END
    }
}

// INSTRUCTOR BEGIN
/// The tree's part of the closest-hit search of [`Bvh::closest_hit`]: what it
/// finds is offered to `closest` (a triangle of the leaves' lanes as its lane
/// result, [`Closest::offer_lane`]); returns the number of triangle tests made
/// (only that, in a register: a 40-byte result, returned through memory, was
/// copied by one wide load just after the loop had stored it in pieces, which
/// the CPU cannot forward from its store buffer: a stall per ray). For a
/// ray `sheared` for its dominant axis `KZ` (a constant, so that the triangle
/// test picks its coordinates with no test), with nodes of `N` children:
/// `node(index, search)` tests node `index`'s children against the range
/// still searched and returns the t at which the ray enters each, the mask of
/// those it meets (bit c for child c) and their names (as [`Next::child`]
/// has them). The same loop serves the four-wide nodes and the eight-wide
/// ones (`crate::fast`), each copy with its node test inlined; `stack` is the
/// thread's. Book: §9.7 Ordered traversal.
#[inline(always)]
pub(crate) fn closest_in_tree<'a, const KZ: usize, const N: usize>(
    bvh: &'a Bvh,
    ray: &Ray,
    sheared: &ShearedRay<KZ>,
    closest: &mut Closest,
    stack: &mut [Next; STACK_LEN],
    node: impl Fn(usize, Interval) -> ([Float; N], u32, &'a [u32; N]),
) -> u64 {
    // The search's state is the loop's own, so that it can stay in registers
    // (captured from outside the stack's closure, it cost the rays that miss 11 %).
    let mut search = closest.search();
    let mut triangle_tests = 0;
    // The children waiting are stack[..waiting], the nearest on top.
    let mut waiting = 0;
    let mut current = Next::ROOT;
    loop {
        if current.child & Next::LEAF != 0 {
            // A leaf: its triangles at once, then its whole objects.
            let lanes = &bvh.leaves.lanes[(current.child & !Next::LEAF) as usize];
            let (mut hit, found) = sheared.hit_lanes(lanes, search);
            triangle_tests += lanes.triangles_tested() as u64;
            while hit != 0 {
                let k = hit.trailing_zeros() as usize;
                hit &= hit - 1;
                let i = lanes.first as usize + k;
                closest.offer_lane(bvh.primitives[i], i, found[k]);
                search = closest.search();
            }
            if lanes.whole != 0 {
                whole_objects(bvh, lanes, ray, closest);
                search = closest.search();
            }
        } else {
            // A node: into the nearest child the ray meets; the others wait on the
            // stack, the nearer ones on top.
            let (t_enter, mut met, children) = node(current.child as usize, search);
            // The met child of lowest index, taken out of `met`.
            let next_met = |met: &mut u32| {
                let c = met.trailing_zeros() as usize % N;
                *met &= *met - 1;
                Next { child: children[c], t_enter: t_enter[c] }
            };
            match met.count_ones() {
                0 => {}
                1 => {
                    current = next_met(&mut met);
                    continue;
                }
                2 => {
                    let (a, b) = (next_met(&mut met), next_met(&mut met));
                    let (near, far) = if b.t_enter < a.t_enter { (b, a) } else { (a, b) };
                    stack[waiting] = far;
                    waiting += 1;
                    current = near;
                    continue;
                }
                _ => {
                    // Three or more: an insertion sort, the farthest at the bottom.
                    let bottom = waiting;
                    while met != 0 {
                        let child = next_met(&mut met);
                        let mut slot = waiting;
                        while slot > bottom && stack[slot - 1].t_enter < child.t_enter {
                            stack[slot] = stack[slot - 1];
                            slot -= 1;
                        }
                        stack[slot] = child;
                        waiting += 1;
                    }
                }
            }
        }
        // The nearest child waiting that starts before the closest hit so far.
        loop {
            if waiting == 0 {
                return triangle_tests;
            }
            waiting -= 1;
            if stack[waiting].t_enter < search.max {
                current = stack[waiting];
                break;
            }
        }
    }
}

/// The whole objects of a leaf's `lanes` offered to `closest`, after its
/// triangles. Out of the traversal's code, whose registers its inlined tests
/// would crowd (measured: 2 % of the bunny's time).
#[inline(never)]
fn whole_objects(bvh: &Bvh, lanes: &LeafLanes, ray: &Ray, closest: &mut Closest) {
    let mut whole = lanes.whole;
    while whole != 0 {
        let primitive = bvh.primitives[lanes.first as usize + whole.trailing_zeros() as usize];
        whole &= whole - 1;
        if let Some(hit) = primitive.hit(bvh.objects, ray, closest.search()) {
            closest.offer(hit, primitive.key());
        }
    }
}

/// The tree's part of [`Bvh::any_hit`], as [`closest_in_tree`] for the
/// closest: until the first blocker, every child met visited in the order of
/// its node's slots, the range never shrunk. Returns whether something blocks
/// the ray and the number of triangle tests made.
#[inline(always)]
pub(crate) fn any_in_tree<'a, const KZ: usize, const N: usize>(
    bvh: &'a Bvh,
    ray: &Ray,
    sheared: &ShearedRay<KZ>,
    range: Interval,
    stack: &mut [Next; STACK_LEN],
    node: impl Fn(usize, Interval) -> ([Float; N], u32, &'a [u32; N]),
) -> (bool, u64) {
    let mut triangle_tests = 0;
    let mut waiting = 0;
    let mut current = Next::ROOT;
    loop {
        if current.child & Next::LEAF != 0 {
            let lanes = &bvh.leaves.lanes[(current.child & !Next::LEAF) as usize];
            triangle_tests += lanes.triangles_tested() as u64;
            if sheared.hit_lanes(lanes, range).0 != 0 {
                return (true, triangle_tests);
            }
            let mut whole = lanes.whole;
            while whole != 0 {
                let primitive = bvh.primitives[lanes.first as usize + whole.trailing_zeros() as usize];
                whole &= whole - 1;
                if primitive.hit(bvh.objects, ray, range).is_some() {
                    return (true, triangle_tests);
                }
            }
        } else {
            // Into the first child met, the others onto the stack.
            let (t_enter, mut met, children) = node(current.child as usize, range);
            if met != 0 {
                let first = met.trailing_zeros() as usize % N;
                met &= met - 1;
                while met != 0 {
                    let c = met.trailing_zeros() as usize % N;
                    met &= met - 1;
                    stack[waiting] = Next { child: children[c], t_enter: t_enter[c] };
                    waiting += 1;
                }
                current = Next { child: children[first], t_enter: t_enter[first] };
                continue;
            }
        }
        if waiting == 0 {
            return (false, triangle_tests);
        }
        waiting -= 1;
        current = stack[waiting];
    }
}
// INSTRUCTOR END

/// The BVH behind the kit's trait, so lecture 08's tracer uses it unchanged.
impl Intersector for Bvh<'_> {
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        Bvh::closest_hit(self, ray, range)
    }

    fn any_hit(&self, ray: &Ray, range: Interval) -> bool {
        Bvh::any_hit(self, ray, range)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bvh::MAX_LEAF;
    use crate::testing::{Rng, mixed_scene, object, sphere};
    use l04_quadrics_transforms::BruteForce;
    use raylab::scene::{Mesh, Object, Shape};
    use raylab::stats::{Counter, measure};
    use raylab::{Float, Vec2};
    use raylab_testing::meshes::edge_and_vertex_targets;
    use std::sync::Arc;

    /// A scene's tree as built, and the same tree traversed four-wide: where
    /// the build made eight-wide nodes (AVX2 CPUs, f32) the two traversals
    /// differ, and every comparison with brute force is made with both.
    struct Trees<'a> {
        built: Bvh<'a>,
        four_wide: Bvh<'a>,
    }

    impl<'a> Trees<'a> {
        fn build(objects: &'a [Object]) -> Self {
            let built = Bvh::build(objects);
            Trees { four_wide: built.four_wide_twin(), built }
        }
    }

    impl<'a> std::ops::Deref for Trees<'a> {
        type Target = Bvh<'a>;
        fn deref(&self) -> &Bvh<'a> {
            &self.built
        }
    }

    /// Asserts that both traversals of the BVH answer `ray` in `range` exactly
    /// as brute force: the same hit bit for bit (or none), and any_hit
    /// agreeing with both. Returns whether it hit.
    fn assert_same(trees: &Trees, brute: &BruteForce, ray: &Ray, range: Interval) -> bool {
        let expected = brute.closest_hit(ray, range);
        for (bvh, name) in [(&trees.built, "as built"), (&trees.four_wide, "four-wide")] {
            assert_eq!(bvh.closest_hit(ray, range), expected, "{name}: {ray:?} in {range:?}");
            assert_eq!(bvh.any_hit(ray, range), expected.is_some(), "{name}: any_hit, {ray:?} in {range:?}");
        }
        assert_eq!(brute.any_hit(ray, range), expected.is_some());
        expected.is_some()
    }

    #[test]
    fn matches_brute_force_on_random_rays() {
        // 10⁴ rays through a random mixed scene (every shape kind, a transformed sphere,
        // box, cylinder and cone, a plane, a 1,024-triangle torus): from anywhere in
        // [−8, 8]³, half in random directions, half aimed at a random object's box centre,
        // one in ten axis-parallel in a component, with whole, shortened, late-starting and
        // early-starting (below 0) ranges. The BVH must give brute force's hit, bit for bit.
        let mut rng = Rng::new(7);
        let objects = mixed_scene(&mut rng);
        let (bvh, brute) = (Trees::build(&objects), BruteForce::new(&objects));
        let targets: Vec<Vec3> = objects.iter().map(|o| crate::object_bounds(o).centroid()).collect();
        let mut hits = 0;
        for n in 0..10_000 {
            let origin = rng.in_cube(8.0);
            let mut dir = if n % 2 == 0 {
                rng.direction()
            } else {
                let target = targets[1 + rng.below(targets.len() as u64 - 1) as usize];
                target + rng.in_cube(0.3) - origin
            };
            if n % 10 == 3 {
                dir[n % 3] = 0.0;
            }
            if dir == Vec3::ZERO {
                continue;
            }
            let range = match n % 5 {
                0 => Interval::new(0.0, rng.range(0.5, 10.0)),
                1 => Interval::new(rng.range(0.5, 5.0), Float::INFINITY),
                // Starting behind the origin: the traversal's copy that widens each box lane.
                2 => Interval::new(-rng.range(0.5, 5.0), Float::INFINITY),
                _ => Interval::POSITIVE,
            };
            hits += assert_same(&bvh, &brute, &Ray::new(origin, dir), range) as usize;
        }
        eprintln!("bvh vs brute force: {hits} of 10000 random rays hit, all identical");
        assert!((3_000..=9_500).contains(&hits), "{hits} hits: both outcomes must be common");
    }

    /// Where the ray toward a target point starts.
    type Origin = fn(Vec3) -> Vec3;

    /// Rays toward every vertex of `mesh` and toward three points of every edge
    /// (its midpoint, 0.1 and 0.7 along: `edge_and_vertex_targets`), each from
    /// `origin(target)`, inside.
    fn edge_and_vertex_rays(mesh: &Mesh, origin: Origin) -> Vec<Ray> {
        edge_and_vertex_targets(mesh).into_iter().map(|p| Ray::new(origin(p), p - origin(p))).collect()
    }

    #[test]
    fn shared_edges_and_vertices_never_leak() {
        // From inside closed meshes (the icosphere from its centre and from off-centre, the
        // torus from the point of its core circle nearest each target), rays aimed exactly
        // at every vertex and at points of every edge: with the watertight test every ray
        // hits, the BVH must not lose one where a box boundary passes through the edge, and
        // must pick the same triangle as brute force where two tie. (Measured: with the
        // entry of Aabb::hit left unwidened, as 03's hit_slabs leaves it, a vertex ray of the
        // icosphere gets a t one ulp off brute force's: the box's entry rounded above the
        // triangle's own t, and a neighbour won.)
        let ico = Arc::new(Mesh::icosphere(3));
        let torus = Arc::new(Mesh::torus(1.0, 0.3, 24, 12));
        let core = |p: Vec3| Vec3::new(p.x, p.y, 0.0).normalize();
        let cases: [(Arc<Mesh>, Origin); 3] =
            [(ico.clone(), |_| Vec3::ZERO), (ico, |_| Vec3::new(0.1, -0.2, 0.05)), (torus, core)];
        let mut total = 0;
        for (mesh, origin) in cases {
            let objects = [object(Shape::Mesh(mesh.clone()), 0, None)];
            let (bvh, brute) = (Trees::build(&objects), BruteForce::new(&objects));
            for ray in edge_and_vertex_rays(&mesh, origin) {
                assert!(assert_same(&bvh, &brute, &ray, Interval::POSITIVE), "leak: {ray:?}");
                total += 1;
            }
        }
        eprintln!("bvh: no leaks over {total} edge and vertex rays");
    }

    #[test]
    fn ties_go_to_the_first_in_the_scene_as_in_brute_force() {
        // Five copies of one sphere among others: every hit is the first copy's (index 3),
        // whatever order the tree visits them in.
        let mut objects: Vec<Object> =
            (0..12).map(|i| sphere(Vec3::new(3.0 * i as Float, 0.0, 0.0), 0.5, 0)).collect();
        for k in 0..5 {
            objects.insert(3 + k, sphere(Vec3::new(1.0, 1.0, 1.0), 0.75, k + 1));
        }
        let (bvh, brute) = (Trees::build(&objects), BruteForce::new(&objects));
        let ray = Ray::new(Vec3::new(1.0, 1.0, 5.0), -Vec3::Z);
        let hit = bvh.closest_hit(&ray, Interval::POSITIVE).unwrap();
        // From z = 5 to the top z = 1.75 of the sphere: t = 3.25 (exact).
        assert_eq!((hit.object, hit.material, hit.t), (3, 1, 3.25));
        assert_same(&bvh, &brute, &ray, Interval::POSITIVE);

        // One triangle twice in a mesh, its corners listed in another order: the same
        // plane and t, but (β, γ) differ; the first listed must win. Down at (0.25, 0.5):
        // in (a, b, c) = (0, x̂, ŷ), β = x = 0.25, γ = y = 0.5.
        let mesh = Mesh {
            positions: vec![Vec3::ZERO, Vec3::X, Vec3::Y],
            triangles: vec![[0, 1, 2], [1, 2, 0]],
            ..Mesh::default()
        };
        let objects = [object(Shape::Mesh(Arc::new(mesh)), 0, None)];
        let (bvh, brute) = (Trees::build(&objects), BruteForce::new(&objects));
        let down = Ray::new(Vec3::new(0.25, 0.5, 2.0), -Vec3::Z);
        assert_eq!(bvh.closest_hit(&down, Interval::POSITIVE).unwrap().uv, Vec2::new(0.25, 0.5));
        assert_same(&bvh, &brute, &down, Interval::POSITIVE);
    }

    #[test]
    fn flat_boxes_and_axis_parallel_rays_on_node_boundaries() {
        // A 4 × 4 floor of unit cubes [i, i+1] × [0, 1] × [j, j+1] whose faces touch, so
        // node boxes share the planes x = i and z = j, and above it flat tiles
        // [i, i+1] × {2} × [j, j+1] (zero thickness in y).
        let mut objects = Vec::new();
        for i in 0..4 {
            for j in 0..4 {
                let (x, z) = (i as Float, j as Float);
                objects.push(object(
                    Shape::Box { min: Vec3::new(x, 0.0, z), max: Vec3::new(x + 1.0, 1.0, z + 1.0) },
                    0,
                    None,
                ));
                objects.push(object(
                    Shape::Box { min: Vec3::new(x, 2.0, z), max: Vec3::new(x + 1.0, 2.0, z + 1.0) },
                    1,
                    None,
                ));
            }
        }
        let (bvh, brute) = (Trees::build(&objects), BruteForce::new(&objects));
        for k in 0..=4 {
            let x = k as Float;
            for y in [0.0, 0.5, 1.0, 2.0] {
                // Along +z from z = −1, exactly in the plane x = k (and y = 0, 1 or 2): the
                // cubes' (or tiles') z = 0 faces at t = 1.
                for dir in [Vec3::Z, Vec3::new(-0.0, 0.0, 1.0), Vec3::new(0.0, -0.0, 1.0)] {
                    let ray = Ray::new(Vec3::new(x, y, -1.0), dir);
                    assert!(assert_same(&bvh, &brute, &ray, Interval::POSITIVE), "{ray:?}");
                    assert_eq!(bvh.closest_hit(&ray, Interval::POSITIVE).unwrap().t, 1.0);
                }
                // Along −x from x = 5 in the plane z = k: the face x = 4 at t = 1.
                let ray = Ray::new(Vec3::new(5.0, y, x), -Vec3::X);
                assert!(assert_same(&bvh, &brute, &ray, Interval::POSITIVE), "{ray:?}");
                assert_eq!(bvh.closest_hit(&ray, Interval::POSITIVE).unwrap().t, 1.0);
            }
            // Straight down onto the flat tiles from y = 3, on the tiles' shared edge x = k:
            // the tile at y = 2, t = 1, its normal +y.
            let down = Ray::new(Vec3::new(x, 3.0, 1.5), -Vec3::Y);
            let hit = bvh.closest_hit(&down, Interval::POSITIVE).unwrap();
            assert_eq!((hit.t, hit.normal), (1.0, Vec3::Y));
            assert_same(&bvh, &brute, &down, Interval::POSITIVE);
            // Beside the floor (x = −0.5), parallel to its side: a miss.
            assert!(!assert_same(
                &bvh,
                &brute,
                &Ray::new(Vec3::new(-0.5, 0.5, -1.0), Vec3::Z),
                Interval::POSITIVE
            ));
        }
    }

    #[test]
    fn closest_of_a_row_listed_far_first() {
        // Spheres of radius 0.5 at z = −2k, k = 1..=50, listed far first (object 50 − k);
        // down −z from the origin: sphere k spans t ∈ [2k − 0.5, 2k + 0.5]. The nearest, k = 1,
        // at t = 1.5; starting the range at 10, inside sphere k = 5: its far side at t = 10.5;
        // ending the range at 1, nothing.
        let objects: Vec<Object> =
            (1..=50).rev().map(|k| sphere(Vec3::new(0.0, 0.0, -2.0 * k as Float), 0.5, 0)).collect();
        let bvh = Bvh::build(&objects);
        let ray = Ray::new(Vec3::ZERO, -Vec3::Z);
        let hit = bvh.closest_hit(&ray, Interval::POSITIVE).unwrap();
        assert_eq!((hit.object, hit.t), (49, 1.5));
        let hit = bvh.closest_hit(&ray, Interval::new(10.0, Float::INFINITY)).unwrap();
        assert_eq!((hit.object, hit.t), (45, 10.5));
        assert_eq!(bvh.closest_hit(&ray, Interval::new(0.0, 1.0)), None);
        // Through the trait, as lecture 08 sees it.
        let dynamic: &dyn Intersector = &bvh;
        assert_eq!(dynamic.closest_hit(&ray, Interval::POSITIVE).map(|h| h.t), Some(1.5));
        assert!(dynamic.any_hit(&ray, Interval::POSITIVE));
    }

    #[test]
    fn any_hit_stops_at_the_first_blocker_and_skips_what_is_out_of_range() {
        // 200 spheres on the ray: the first leaf reached holds a blocker, so any_hit makes
        // at most one leaf's tests; closest_hit, nearest first, stays far below 200 too.
        let objects: Vec<Object> =
            (1..=200).map(|k| sphere(Vec3::new(0.0, 0.0, -2.0 * k as Float), 0.5, 0)).collect();
        let bvh = Bvh::build(&objects);
        let ray = Ray::new(Vec3::ZERO, -Vec3::Z);
        let (blocked, stats) = measure(|| bvh.any_hit(&ray, Interval::POSITIVE));
        assert!(blocked);
        assert!(stats.get(Counter::IntersectionTests) <= MAX_LEAF as u64, "{stats}");
        let (_, stats) = measure(|| bvh.closest_hit(&ray, Interval::POSITIVE));
        assert!(stats.get(Counter::IntersectionTests) <= 2 * MAX_LEAF as u64, "{stats}");
        // The whole row starts at t = 1.5: a range ending at 1 tests no primitive at all.
        let (blocked, stats) = measure(|| bvh.any_hit(&ray, Interval::new(0.0, 1.0)));
        assert!(!blocked);
        assert_eq!(stats.get(Counter::IntersectionTests), 0);
    }

    #[test]
    fn degenerate_scenes_answer_like_brute_force() {
        let mut rng = Rng::new(12);
        let ico = Arc::new(Mesh::icosphere(1));
        let scenes: Vec<Vec<Object>> = vec![
            Vec::new(),
            vec![sphere(Vec3::ZERO, 1.0, 0)],
            vec![object(Shape::Plane { normal: Vec3::Y, offset: -1.0 }, 0, None)],
            // Concentric spheres: all centroids equal.
            (0..40).map(|i| sphere(Vec3::ZERO, 0.2 + 0.05 * i as Float, i % 3)).collect(),
            // One mesh, many placed copies of it: transformed meshes are whole primitives.
            (0..10)
                .map(|i| {
                    object(
                        Shape::Mesh(ico.clone()),
                        0,
                        Some(
                            raylab::Mat4::from_translation(Vec3::new(i as Float - 5.0, 0.0, 0.0))
                                * raylab::Mat4::from_scale(Vec3::splat(0.4)),
                        ),
                    )
                })
                .collect(),
        ];
        for objects in &scenes {
            let (bvh, brute) = (Trees::build(objects), BruteForce::new(objects));
            for _ in 0..500 {
                let ray = Ray::new(rng.in_cube(4.0), rng.direction());
                assert_same(&bvh, &brute, &ray, Interval::POSITIVE);
            }
        }
    }
}
