// INSTRUCTOR ONLY: left out of the handout; the reference traversal's fast kernels.
//! The reference traversal's two kernels, with everything that depends on
//! the ray alone computed once per ray: the four boxes of a node tested at
//! once ([`Node::hit_children`] with a [`BoxRay`]), and lecture 03's
//! watertight triangle test with its shear precomputed ([`ShearedRay`]).
//! Students traverse with [`crate::Aabb::hit`] and
//! [`crate::Primitive::triangle_t`]; the answers are the same, the speed is
//! not (`grader bench-rays`, benches/README.md). Book: §9.7 Ordered
//! traversal, §9.10 Measuring a hierarchy.

use l03_polygons_triangles::{TriangleHit, dominant_axis, edge_function, interpolate_normal};
use raylab::math::gamma;
use raylab::scene::{Object, Shape};
use raylab::{Float, Hit, Interval, Ray, Vec2, Vec3, Vec4};

use crate::bvh::{Node, WIDTH};
use crate::primitive::Primitive;
use crate::traverse::Waiting;

thread_local! {
    /// The reference traversal's stack, one per thread, reused by every ray:
    /// no allocation once it has grown, and nothing to clear but its length
    /// (a fresh array of [`crate::STACK_SIZE`] entries per ray cost a third
    /// of the traversal's time, measured).
    pub static STACK: std::cell::RefCell<Vec<Waiting>> = const { std::cell::RefCell::new(Vec::new()) };
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
    pub fn hit_children(&self, ray: &BoxRay, range: Interval) -> ([Float; WIDTH], u32) {
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
        if ray.widen_each {
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
/// each lane widened after, by the factor its sign needs.
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
pub struct BoxRay {
    origin_min: [Vec4; 3],
    origin_max: [Vec4; 3],
    inv_min: [Vec4; 3],
    inv_max: [Vec4; 3],
    widen_each: bool,
}

impl BoxRay {
    /// The per-ray part of the box tests of `ray` (`dir` not zero) for
    /// ranges starting at `range_min`.
    pub fn new(ray: &Ray, range_min: Float) -> Self {
        let widen_each = !(range_min >= 0.0 && range_min.is_finite());
        let (down, up) = if widen_each { (1.0, 1.0) } else { (WIDEN_DOWN, WIDEN_UP) };
        let mut prepared = BoxRay {
            origin_min: [Vec4::ZERO; 3],
            origin_max: [Vec4::ZERO; 3],
            inv_min: [Vec4::ZERO; 3],
            inv_max: [Vec4::ZERO; 3],
            widen_each,
        };
        for a in 0..3 {
            let (o, inv) = (ray.origin[a], 1.0 / ray.dir[a]);
            let (origin_min, origin_max, inv_min, inv_max) = if !inv.is_finite() {
                (o.next_up(), o.next_down(), Float::INFINITY, Float::INFINITY)
            } else if inv > 0.0 {
                (o, o, inv * down, inv * up)
            } else {
                (o, o, inv * up, inv * down)
            };
            prepared.origin_min[a] = Vec4::splat(origin_min);
            prepared.origin_max[a] = Vec4::splat(origin_max);
            prepared.inv_min[a] = Vec4::splat(inv_min);
            prepared.inv_max[a] = Vec4::splat(inv_max);
        }
        prepared
    }
}

/// Lecture 03's watertight test (`hit_triangle_watertight`, Woop, Benthin and
/// Wald 2013) split in two: the part that depends on the ray alone (the
/// dominant axis kz and the shear Sₓ = −dₓ/d_z, S_y = −d_y/d_z, 1/d_z, two
/// divisions and a reciprocal) made once per ray here, the rest per triangle
/// in [`ShearedRay::hit`]. The same operations on the same numbers in the
/// same order as 03's: the same t, bit for bit, so the BVH's answers stay
/// brute force's. Book: §9.7 Ordered traversal.
#[derive(Clone, Copy, Debug)]
pub struct ShearedRay {
    origin: Vec3,
    /// kx, ky, kz: the axes that become x, y and z (kz the direction's dominant one).
    axes: [usize; 3],
    /// Sₓ, S_y and 1/d_z.
    shear: Vec3,
}

impl ShearedRay {
    /// The per-ray part of the triangle tests of `ray` (`dir` not zero).
    pub fn new(ray: &Ray) -> Self {
        let kz = dominant_axis(ray.dir);
        let (kx, ky) = ((kz + 1) % 3, (kz + 2) % 3);
        let d = Vec3::new(ray.dir[kx], ray.dir[ky], ray.dir[kz]);
        Self { origin: ray.origin, axes: [kx, ky, kz], shear: Vec3::new(-d.x / d.z, -d.y / d.z, 1.0 / d.z) }
    }

    /// Where the ray meets the triangle (a, b, c) inside `range` (t, β, γ),
    /// as lecture 03's `hit_triangle` finds it (the watertight test, and no
    /// hit for a triangle without a plane or whose normal overflows), or
    /// `None`.
    #[inline(always)] // once per triangle in the traversal's hot loop
    pub fn hit(&self, [a, b, c]: &[Vec3; 3], range: Interval) -> Option<TriangleHit> {
        let [kx, ky, kz] = self.axes;
        let to_ray_space = |v: Vec3| {
            let p = v - self.origin;
            let (x, y, z) = (p[kx], p[ky], p[kz]);
            Vec3::new(x + self.shear.x * z, y + self.shear.y * z, z * self.shear.z)
        };
        let (p0, p1, p2) = (to_ray_space(*a), to_ray_space(*b), to_ray_space(*c));
        let e0 = edge_function(p1, p2);
        let e1 = edge_function(p2, p0);
        let e2 = edge_function(p0, p1);
        if (e0 < 0.0 || e1 < 0.0 || e2 < 0.0) && (e0 > 0.0 || e1 > 0.0 || e2 > 0.0) {
            return None;
        }
        let det = e0 + e1 + e2;
        if det == 0.0 {
            return None;
        }
        let inv_det = 1.0 / det;
        let t = (e0 * p0.z + e1 * p1.z + e2 * p2.z) * inv_det;
        if !range.contains(t) {
            return None;
        }
        // Rare, so last: 03 gives no hit for a triangle without a plane, or whose
        // normal overflows (checked there first; the order does not change the answer).
        let (ab, ac) = (*b - *a, *c - *a);
        if ac.cross(ab).length_squared() == 0.0 || ab.cross(ac).try_normalize().is_none() {
            return None;
        }
        Some(TriangleHit { t, beta: e1 * inv_det, gamma: e2 * inv_det })
    }
}

/// The hit record of the mesh triangle `primitive`, with corners `corners`,
/// where `ray` meets it as `found` (from [`ShearedRay::hit`]) says: the very
/// record lecture 03's `hit_triangle` and 09's `hit_mesh_triangle` build
/// (the geometric normal, turned to face the ray; the interpolated vertex
/// normal on that side, if the mesh has normals; uv from the mesh's, or
/// (β, γ)), the same operations on the same numbers, but from the t, β and
/// γ the traversal found, without testing the triangle a second time. Built
/// once per ray, for the closest hit; measured on the bunny, it makes the
/// whole query about 15 % faster than calling `hit_mesh_triangle` (whose
/// second watertight test and index lookups cost as much as a third of the
/// traversal). Book: §9.7 Ordered traversal.
pub fn triangle_record(
    objects: &[Object],
    primitive: Primitive,
    [a, b, c]: &[Vec3; 3],
    ray: &Ray,
    found: TriangleHit,
) -> Option<Hit> {
    let index = primitive.object as usize;
    let object = &objects[index];
    let Shape::Mesh(mesh) = &object.shape else {
        return None;
    };
    let corners = mesh.triangles[primitive.triangle as usize].map(|i| i as usize);
    let (beta, gamma) = (found.beta, found.gamma);
    let outward = (*b - *a).cross(*c - *a).try_normalize()?;
    let mut hit = Hit::new(ray, found.t, outward).with_uv(Vec2::new(beta, gamma));
    if !mesh.normals.is_empty() {
        let shading = interpolate_normal(&corners.map(|i| mesh.normals[i]), beta, gamma);
        if shading != Vec3::ZERO {
            hit.normal = if shading.dot(hit.normal) < 0.0 { -shading } else { shading };
        }
    }
    if !mesh.uvs.is_empty() {
        let [i, j, k] = corners;
        hit = hit.with_uv((1.0 - beta - gamma) * mesh.uvs[i] + beta * mesh.uvs[j] + gamma * mesh.uvs[k]);
    }
    Some(Hit { object: index, material: object.material, ..hit })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Aabb;
    use crate::test_support::Rng;
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

    /// A random box in [−4, 4]³, a tenth of them flat along one axis.
    fn random_box(rng: &mut Rng, n: usize) -> Aabb {
        let (p, q) = (rng.in_cube(4.0), rng.in_cube(4.0));
        let mut b = Aabb::new(p.min(q), p.max(q));
        if n.is_multiple_of(10) {
            b.max[n % 3] = b.min[n % 3];
        }
        b
    }

    /// A random ray from [−6, 6]³ (two in three aimed into [−2, 2]³), one in five with a direction component of
    /// ±0 (an axis-parallel ray), and a range: whole, shortened, late-starting
    /// or starting below 0.
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
            let (entries, mask) = node.hit_children(&BoxRay::new(&ray, range.min), range);
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
                let (entries, mask) =
                    node.hit_children(&BoxRay::new(&Ray::new(origin, dir), 0.0), Interval::POSITIVE);
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
                let (_, mask) =
                    node.hit_children(&BoxRay::new(&Ray::new(outside, dir), 0.0), Interval::POSITIVE);
                assert_eq!(mask, 0, "{outside} along {dir}");
            }
        }
        // Empty slots: never met, from anywhere, in any direction, parallel or not.
        let mut rng = Rng::new(22);
        for n in 0..2_000 {
            let (ray, range) = random_query(&mut rng, n);
            let (_, mask) = Node::EMPTY.hit_children(&BoxRay::new(&ray, range.min), range);
            assert_eq!(mask, 0, "{ray:?} {range:?}");
        }
    }

    #[test]
    fn sheared_ray_finds_03s_t_beta_and_gamma_bit_for_bit() {
        // Random triangles (a tenth degenerate: two corners equal, or all three on a
        // line) and rays aimed at a random point of each (so about half hit), plus rays
        // aimed exactly at the corners and edge midpoints: ShearedRay::hit gives the t and
        // (β, γ) = uv of 03's hit_triangle (what brute force uses), bit for bit, or None with it.
        let mut rng = Rng::new(23);
        let mut hits = 0;
        for n in 0..20_000 {
            let (a, mut b, mut c) = (rng.in_cube(2.0), rng.in_cube(2.0), rng.in_cube(2.0));
            match n % 20 {
                0 => b = a,
                1 => c = a.lerp(b, 0.25),
                _ => {}
            }
            let (beta, gamma) = rng.barycentric();
            let mut targets = vec![a + (b - a) * beta as Float * 1.2 + (c - a) * gamma as Float * 1.2];
            if n % 50 == 0 {
                targets.extend([a, b, c, a.lerp(b, 0.5), b.lerp(c, 0.5)]);
            }
            for target in targets {
                let origin = rng.in_cube(5.0);
                if target == origin {
                    continue;
                }
                let ray = Ray::new(origin, target - origin);
                let range =
                    if n % 3 == 0 { Interval::new(0.0, rng.range(0.5, 2.0)) } else { Interval::POSITIVE };
                let expected = hit_triangle(&ray, &[a, b, c], None, range).map(|h| [h.t, h.uv.x, h.uv.y]);
                let found = ShearedRay::new(&ray).hit(&[a, b, c], range).map(|f| [f.t, f.beta, f.gamma]);
                let bits = |v: Option<[Float; 3]>| v.map(|v| v.map(Float::to_bits));
                assert_eq!(bits(found), bits(expected), "{ray:?} {a} {b} {c}");
                hits += found.is_some() as usize;
            }
        }
        eprintln!("sheared triangle test: {hits} hits, all 03's t, β and γ bit for bit");
        assert!(hits > 5_000, "only {hits} hits");
    }
}
