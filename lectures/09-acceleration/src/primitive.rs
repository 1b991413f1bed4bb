//! What a leaf of the hierarchy holds: a whole scene object, or one triangle
//! of a mesh object, so that a mesh's triangles are spread over the tree
//! rather than tested all at once. Glue, not an exercise: each case calls the
//! routine of lectures 03–04 that owns it.

use l03_polygons_triangles::{hit_triangle, hit_triangle_watertight};
use l04_quadrics_transforms::hit_object;
use raylab::scene::{Mesh, Object, Shape};
use raylab::stats::{Counter, count};
use raylab::{Float, Hit, Interval, Ray};

/// A primitive of the BVH: `object` indexes the scene's objects; `triangle`
/// indexes the triangles of that object's mesh, or is [`Primitive::WHOLE`]
/// for an object tested as a whole (every shape but an untransformed mesh;
/// a transformed mesh is one primitive, tested whole by 04's `hit_object`).
/// Eight bytes, so a leaf's primitives share a cache line.
/// Book: §9.5 Primitives: objects and triangles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Primitive {
    pub object: u32,
    pub triangle: u32,
}

impl Primitive {
    /// The `triangle` of a primitive that is a whole object.
    pub const WHOLE: u32 = u32::MAX;

    /// The whole object `object`.
    pub fn whole(object: u32) -> Self {
        Self { object, triangle: Self::WHOLE }
    }

    /// Where brute force would meet this primitive: objects in the scene's
    /// order, triangles in their mesh's order. Brute force keeps the first of
    /// several hits at the same t (a later one must be strictly nearer), so a
    /// traversal that keeps, among equal t, the hit of the smallest key gives
    /// the very same hit whatever order it visits the primitives in.
    pub fn key(self) -> u64 {
        (u64::from(self.object) << 32) | u64::from(self.triangle)
    }

    /// The hit of `ray` with this primitive of `objects` inside `range`, with
    /// `hit.object` and `hit.material` filled in as 02's `closest_hit` does.
    /// A whole object goes through 04's [`hit_object`] (which counts its own
    /// intersection tests: one, or one per triangle of a transformed mesh); a
    /// mesh triangle through [`hit_mesh_triangle`], counted here as one test.
    /// The primitive must come from a BVH built over `objects`.
    pub fn hit(self, objects: &[Object], ray: &Ray, range: Interval) -> Option<Hit> {
        let index = self.object as usize;
        if self.triangle == Self::WHOLE {
            let hit = hit_object(&objects[index], ray, range)?;
            return Some(Hit { object: index, material: objects[index].material, ..hit });
        }
        count(Counter::IntersectionTests);
        self.mesh_triangle_hit(objects, ray, range)
    }

    /// For a mesh triangle: the t of its hit, `Some` exactly when [`Primitive::hit`]
    /// finds one and with the same t, but without building the [`Hit`] (the
    /// point, the normals, uv): among the triangles a ray meets only the
    /// closest needs its hit record, which [`Primitive::mesh_triangle_hit`]
    /// then builds once. Counted as one intersection test. `None` for a whole
    /// object. Book: §9.7 Ordered traversal.
    pub fn triangle_t(self, objects: &[Object], ray: &Ray, range: Interval) -> Option<Float> {
        let Shape::Mesh(mesh) = &objects[self.object as usize].shape else {
            return None;
        };
        if self.triangle == Self::WHOLE {
            return None;
        }
        count(Counter::IntersectionTests);
        let [a, b, c] = mesh.triangle(self.triangle as usize);
        let found = hit_triangle_watertight(ray, a, b, c, range)?;
        // No hit where 03's hit_triangle would find no face normal.
        (b - a).cross(c - a).try_normalize()?;
        Some(found.t)
    }

    /// The whole hit of a mesh-triangle primitive, as [`Primitive::hit`] gives
    /// it, not counted as a test (the traversal counted it when it asked
    /// [`Primitive::triangle_t`]).
    pub fn mesh_triangle_hit(self, objects: &[Object], ray: &Ray, range: Interval) -> Option<Hit> {
        let index = self.object as usize;
        let object = &objects[index];
        let Shape::Mesh(mesh) = &object.shape else {
            debug_assert!(false, "primitive {self:?} names a triangle of a {}", object.shape.kind());
            return None;
        };
        let hit = hit_mesh_triangle(mesh, self.triangle as usize, ray, range)?;
        Some(Hit { object: index, material: object.material, ..hit })
    }
}

/// The hit of `ray` with triangle `triangle` of `mesh`, exactly as 03's
/// `hit_mesh` computes it for that triangle: the watertight [`hit_triangle`]
/// with the mesh's vertex normals when it has them, and uv interpolated from
/// the mesh's, (1 − β − γ)uv_a + βuv_b + γuv_c, when it has them (else the
/// (β, γ) of the triangle hit). Same operations in the same order, so the
/// same bits. `triangle` must index `mesh.triangles`.
pub fn hit_mesh_triangle(mesh: &Mesh, triangle: usize, ray: &Ray, range: Interval) -> Option<Hit> {
    let corners = mesh.triangles[triangle].map(|i| i as usize);
    let vertices = corners.map(|i| mesh.positions[i]);
    let normals = (!mesh.normals.is_empty()).then(|| corners.map(|i| mesh.normals[i]));
    let hit = hit_triangle(ray, &vertices, normals.as_ref(), range)?;
    if mesh.uvs.is_empty() {
        return Some(hit);
    }
    let [a, b, c] = corners;
    let (beta, gamma) = (hit.uv.x, hit.uv.y);
    Some(hit.with_uv((1.0 - beta - gamma) * mesh.uvs[a] + beta * mesh.uvs[b] + gamma * mesh.uvs[c]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use l03_polygons_triangles::hit_mesh;
    use raylab::{Float, Vec3};

    #[test]
    fn each_triangle_answers_as_hit_mesh_does() {
        // Rays through the torus (normals and uvs interpolated): the nearest of the
        // per-triangle hits, first triangle on ties, is hit_mesh's hit, bit for bit.
        let mesh = Mesh::torus(1.0, 0.3, 12, 8);
        let mut rng = crate::testing::Rng::new(4);
        let mut hits = 0;
        for _ in 0..500 {
            // From anywhere near, aimed at a random vertex, give or take.
            let (origin, vertex) = (rng.in_cube(2.0), rng.below(mesh.positions.len() as u64) as usize);
            let ray = Ray::new(origin, mesh.positions[vertex] + rng.in_cube(0.1) - origin);
            let mut best: Option<Hit> = None;
            for t in 0..mesh.triangles.len() {
                let range = Interval::new(0.0, best.map_or(Float::INFINITY, |h| h.t));
                if let Some(h) = hit_mesh_triangle(&mesh, t, &ray, range) {
                    best = Some(h);
                }
            }
            assert_eq!(best, hit_mesh(&ray, &mesh, Interval::POSITIVE));
            hits += best.is_some() as usize;
        }
        assert!(hits > 300, "only {hits} of 500 rays hit the torus");
    }

    #[test]
    fn triangle_t_is_the_hits_t_without_the_record() {
        // Every triangle of a torus (normals, uvs) on 200 rays, and a triangle whose
        // face normal overflows (corners near Float::MAX: (b − a)×(c − a) is ∞, so 03's
        // hit_triangle gives no hit): triangle_t is Some exactly when hit is, same t bits.
        let big = Float::MAX / 4.0;
        let huge = Mesh {
            positions: vec![Vec3::new(-big, -big, 0.0), Vec3::new(big, -big, 0.0), Vec3::new(0.0, big, 0.0)],
            triangles: vec![[0, 1, 2]],
            ..Mesh::default()
        };
        let torus = Mesh::torus(1.0, 0.3, 12, 8);
        let vertices = torus.positions.clone();
        let objects = [
            crate::testing::object(Shape::Mesh(std::sync::Arc::new(torus)), 2, None),
            crate::testing::object(Shape::Mesh(std::sync::Arc::new(huge)), 0, None),
        ];
        let mut rng = crate::testing::Rng::new(5);
        let mut hits = 0;
        for _ in 0..200 {
            // From anywhere near, aimed at a random vertex, give or take.
            let (origin, vertex) = (rng.in_cube(2.0), rng.below(vertices.len() as u64) as usize);
            let ray = Ray::new(origin, vertices[vertex] + rng.in_cube(0.1) - origin);
            for t in 0..192 {
                let p = Primitive { object: 0, triangle: t };
                let (full, only_t) = (
                    p.hit(&objects, &ray, Interval::POSITIVE),
                    p.triangle_t(&objects, &ray, Interval::POSITIVE),
                );
                assert_eq!(full.map(|h| h.t), only_t, "{ray:?} triangle {t}");
                hits += full.is_some() as usize;
            }
        }
        assert!(hits > 200, "only {hits} triangle hits");
        let down = Ray::new(Vec3::new(0.0, 0.0, 1.0), -Vec3::Z);
        let p = Primitive { object: 1, triangle: 0 };
        assert_eq!(p.hit(&objects, &down, Interval::POSITIVE), None);
        assert_eq!(p.triangle_t(&objects, &down, Interval::POSITIVE), None);
        assert_eq!(Primitive::whole(0).triangle_t(&objects, &down, Interval::POSITIVE), None);
    }

    #[test]
    fn keys_order_objects_then_triangles() {
        let a = Primitive { object: 1, triangle: 7 };
        let b = Primitive { object: 1, triangle: 8 };
        let c = Primitive::whole(2);
        assert!(a.key() < b.key() && b.key() < c.key());
        assert!(Primitive::whole(1).key() < Primitive { object: 2, triangle: 0 }.key());
        // A whole object knows its index and material once hit.
        let objects =
            [crate::testing::sphere(Vec3::ZERO, 1.0, 3), crate::testing::sphere(Vec3::ZERO, 1.0, 5)];
        let hit = Primitive::whole(1)
            .hit(&objects, &Ray::new(Vec3::Z * 3.0, -Vec3::Z), Interval::POSITIVE)
            .unwrap();
        assert_eq!((hit.object, hit.material, hit.t), (1, 5, 2.0));
    }
}
