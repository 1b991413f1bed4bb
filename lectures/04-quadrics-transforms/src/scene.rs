//! One door to every shape of lectures 02–04, transformed or not, and the
//! brute-force [`Intersector`] the tracer uses until lecture 09's BVH.
//! Glue, not exercises: each case calls the lecture routine that owns it.

use l02_ray_casting::closest_hit;
use raylab::scene::{Object, Shape};
use raylab::stats::{Counter, count};
use raylab::{Hit, Intersector, Interval, Ray};

use crate::{hit_cone, hit_cylinder, hit_transformed};

/// The hit of `ray` with `shape` (in the shape's own coordinates) inside
/// `range`: cylinders and cones by this lecture's canonical ones, every
/// earlier shape through [`l03_polygons_triangles::hit_shape`] (boxes,
/// polygons, triangles and meshes), which hands spheres and planes to
/// [`l02_ray_casting::hit_shape`].
///
/// Counts [`Counter::IntersectionTests`]: one per shape, one per triangle for a
/// mesh. Book: §4.8 Every shape behind one door.
pub fn hit_shape(shape: &Shape, ray: &Ray, range: Interval) -> Option<Hit> {
    match shape {
        Shape::Cylinder => {
            count(Counter::IntersectionTests);
            hit_cylinder(ray, range)
        }
        Shape::Cone => {
            count(Counter::IntersectionTests);
            hit_cone(ray, range)
        }
        // Every earlier shape through lecture 03's door (which hands spheres and planes to 02's).
        _ => l03_polygons_triangles::hit_shape(shape, ray, range),
    }
}

/// The hit of `ray` (in world space) with a scene object: through
/// [`hit_transformed`] when the object has a transform, else [`hit_shape`]
/// directly. `object` and `material` of the hit are left for the group to
/// fill in (02's [`closest_hit`] does). Book: §4.8 Every shape behind one door.
pub fn hit_object(object: &Object, ray: &Ray, range: Interval) -> Option<Hit> {
    match &object.transform {
        Some(transform) => {
            hit_transformed(ray, transform, range, |local, range| hit_shape(&object.shape, local, range))
        }
        None => hit_shape(&object.shape, ray, range),
    }
}

/// A scene's objects as a brute-force [`Intersector`]: every ray tests every
/// object with [`hit_object`]. `closest_hit` is 02's [`closest_hit`] (the hit
/// knows its object index and material); `any_hit` stops at the first object
/// hit, as a shadow ray needs no more. Book: §4.8 Every shape behind one door.
#[derive(Clone, Copy, Debug)]
pub struct BruteForce<'a> {
    pub objects: &'a [Object],
}

impl<'a> BruteForce<'a> {
    pub fn new(objects: &'a [Object]) -> Self {
        Self { objects }
    }
}

impl Intersector for BruteForce<'_> {
    fn closest_hit(&self, ray: &Ray, range: Interval) -> Option<Hit> {
        closest_hit(self.objects, ray, range, hit_object)
    }

    fn any_hit(&self, ray: &Ray, range: Interval) -> bool {
        self.objects.iter().any(|object| hit_object(object, ray, range).is_some())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{
        EPS, angle_to, d3, ellipsoid_f64, ellipsoid_normal_sensitivity, ellipsoid_transform, unit,
    };
    use approx::{assert_abs_diff_eq, assert_relative_eq};
    use raylab::math::consts::TAU;
    use raylab::random::Rng;
    use raylab::scene::{Mesh, Transform};
    use raylab::stats::measure;
    use raylab::{Float, Mat4, Vec3};
    use std::sync::Arc;

    fn object(shape: Shape, material: usize, world_from_object: Option<Mat4>) -> Object {
        Object { shape, material, transform: world_from_object.map(|m| Transform::new(m).unwrap()) }
    }

    /// The square −1 ≤ x, y ≤ 1 at height z as two triangles facing +z.
    fn square_mesh(z: Float) -> Mesh {
        Mesh {
            positions: vec![
                Vec3::new(-1.0, -1.0, z),
                Vec3::new(1.0, -1.0, z),
                Vec3::new(1.0, 1.0, z),
                Vec3::new(-1.0, 1.0, z),
            ],
            triangles: vec![[0, 1, 2], [0, 2, 3]],
            ..Mesh::default()
        }
    }

    /// Every shape with its top at z = 1 (the cone's side at z = 0.75 for x = 0.25),
    /// a ray from z = 10 straight down at (x, y) = (0.25, 0.5) or (0.25, 0), the t and
    /// outward normal by hand, and the number of intersection tests it costs.
    fn every_shape() -> Vec<(Shape, [Float; 2], Float, Vec3, u64)> {
        let up = Vec3::Z;
        let top = |x: Float, y: Float| Vec3::new(x, y, 1.0);
        vec![
            (Shape::Sphere { center: Vec3::ZERO, radius: 1.0 }, [0.0, 0.0], 9.0, up, 1),
            (Shape::Plane { normal: up, offset: 1.0 }, [0.25, 0.5], 9.0, up, 1),
            (Shape::Box { min: Vec3::splat(-1.0), max: Vec3::ONE }, [0.25, 0.5], 9.0, up, 1),
            (
                Shape::Polygon {
                    vertices: vec![top(-1.0, -1.0), top(1.0, -1.0), top(1.0, 1.0), top(-1.0, 1.0)],
                },
                [0.25, 0.5],
                9.0,
                up,
                1,
            ),
            (
                Shape::Triangle { vertices: [top(-1.0, -1.0), top(1.0, -1.0), top(0.0, 1.0)], normals: None },
                [0.25, 0.5],
                9.0,
                up,
                1,
            ),
            (Shape::Mesh(Arc::new(square_mesh(1.0))), [0.25, 0.5], 9.0, up, 2),
            (Shape::Cylinder, [0.25, 0.5], 9.0, up, 1),
            // The cone's side at x = 0.25 is at z = 0.75; gradient (0.25, 0, 0.25).
            (Shape::Cone, [0.25, 0.0], 9.25, Vec3::new(1.0, 0.0, 1.0).normalize(), 1),
        ]
    }

    #[test]
    fn every_shape_answers_and_is_counted() {
        for (shape, [x, y], t, n, tests) in every_shape() {
            let ray = Ray::new(Vec3::new(x, y, 10.0), -Vec3::Z);
            let (hit, stats) = measure(|| hit_shape(&shape, &ray, Interval::POSITIVE));
            let hit = hit.unwrap_or_else(|| panic!("{} missed", shape.kind()));
            // Exact inputs; 4ε for the roots and normalisations.
            assert_relative_eq!(hit.t, t, max_relative = 4.0 * EPS);
            assert_abs_diff_eq!(hit.normal, n, epsilon = 4.0 * EPS);
            assert!(hit.front_face, "{}", shape.kind());
            assert_eq!(stats.get(Counter::IntersectionTests), tests, "{} counted", shape.kind());
        }
    }

    #[test]
    fn a_transform_moves_every_shape() {
        // Moved by T(5, −3, 0): the same ray moved with it gives the same t and normal;
        // the count is unchanged (the transform is not a test).
        for (shape, [x, y], t, n, tests) in every_shape() {
            let moved = object(shape, 0, Some(Mat4::from_translation(Vec3::new(5.0, -3.0, 0.0))));
            let ray = Ray::new(Vec3::new(x + 5.0, y - 3.0, 10.0), -Vec3::Z);
            let (hit, stats) = measure(|| hit_object(&moved, &ray, Interval::POSITIVE));
            let hit = hit.unwrap_or_else(|| panic!("moved {} missed", moved.shape.kind()));
            assert_relative_eq!(hit.t, t, max_relative = 4.0 * EPS);
            assert_abs_diff_eq!(hit.normal, n, epsilon = 4.0 * EPS);
            assert_eq!(hit.point, ray.at(hit.t));
            assert_eq!(stats.get(Counter::IntersectionTests), tests);
        }
    }

    #[test]
    fn rotated_box_normals_are_the_rotated_axes() {
        // The cube [−1, 1]³ scaled to half-sizes (2, 1, 0.5), turned 30° about z, moved
        // to (1, 2, −5). Face ±axis i has outward normal R·(±eᵢ) (a diagonal scale keeps
        // the axes' directions) and centre c + R·(±sᵢ eᵢ). From 3 units out along that
        // normal, aimed back at the face centre: t = 3. Tolerance 16ε: the rotation's
        // sin and cos, the inverse and the slab divisions each round.
        let half = Vec3::new(2.0, 1.0, 0.5);
        let center = Vec3::new(1.0, 2.0, -5.0);
        let rotation = Mat4::from_rotation_z(raylab::radians(30.0));
        let cube = object(
            Shape::Box { min: -Vec3::ONE, max: Vec3::ONE },
            0,
            Some(Mat4::from_translation(center) * rotation * Mat4::from_scale(half)),
        );
        for axis in [Vec3::X, Vec3::Y, Vec3::Z, -Vec3::X, -Vec3::Y, -Vec3::Z] {
            let normal = rotation.transform_vector3(axis);
            let face = center + rotation.transform_vector3(axis * half);
            let hit = hit_object(&cube, &Ray::new(face + 3.0 * normal, -normal), Interval::POSITIVE).unwrap();
            assert_abs_diff_eq!(hit.t, 3.0, epsilon = 16.0 * EPS * 3.0);
            assert_abs_diff_eq!(hit.normal, normal, epsilon = 16.0 * EPS);
            assert!(hit.front_face);
        }
    }

    #[test]
    fn a_placed_sphere_hits_where_computed_by_hand() {
        // Sphere(centre (1, 0, 0), radius 2) under T(0, 0, −10)·S(1, 1, 0.5): an ellipsoid
        // centred (1, 0, −10), semi-axes (2, 2, 1). From (1, 0, 0) down: z = −9, t = 9; from
        // (−5, 0, −10) along +x with dir ×2: x = −1, t = 4/2 = 2.
        let placed = object(
            Shape::Sphere { center: Vec3::X, radius: 2.0 },
            0,
            Some(
                Mat4::from_translation(Vec3::new(0.0, 0.0, -10.0))
                    * Mat4::from_scale(Vec3::new(1.0, 1.0, 0.5)),
            ),
        );
        let down = hit_object(&placed, &Ray::new(Vec3::X, -Vec3::Z), Interval::POSITIVE).unwrap();
        assert_relative_eq!(down.t, 9.0, max_relative = 4.0 * EPS);
        assert_abs_diff_eq!(down.normal, Vec3::Z, epsilon = 4.0 * EPS);
        let side =
            hit_object(&placed, &Ray::new(Vec3::new(-5.0, 0.0, -10.0), Vec3::X * 2.0), Interval::POSITIVE);
        assert_relative_eq!(side.unwrap().t, 2.0, max_relative = 4.0 * EPS);
    }

    #[test]
    fn extreme_scale_through_the_whole_pipeline() {
        // The sphere object of a scene under S(1e-3, 1, 1e3), turned 20° about (0, 1, 1)/√2,
        // through hit_object and 02's hit_sphere_stable, against the f64 ellipsoid. Head-on
        // rays from one unit out, well-conditioned ones only (see transformed.rs): normals
        // within 1e-4 rad. t within 16ε·(|O|∞ + |C|∞): the rotation mixes the 1e3-long axis
        // into every coordinate, and one rounding of an origin up to 1e3 away moves the
        // hit along a unit ray by ε·|O| already.
        let (center, semi, axis, angle) = ([0.0, 1.0, -2.0], [1e-3, 1.0, 1e3], unit([0.0, 1.0, 1.0]), 0.35);
        let ellipsoid = Object {
            shape: Shape::Sphere { center: Vec3::ZERO, radius: 1.0 },
            material: 0,
            transform: Some(ellipsoid_transform(center, semi, axis, angle)),
        };
        let mut rng = Rng::new(10);
        let mut compared = 0;
        for _ in 0..5_000 {
            let (theta, phi) = (rng.range(0.05, 3.09) as f64, rng.range(0.0, TAU) as f64);
            let local = [theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos()];
            let p = crate::testing::rotate([0, 1, 2].map(|i| semi[i] * local[i]), axis, angle);
            let n = crate::testing::rotate(unit([0, 1, 2].map(|i| local[i] / semi[i])), axis, angle);
            let to_float = |v: [f64; 3]| Vec3::new(v[0] as Float, v[1] as Float, v[2] as Float);
            let ray = Ray::new(to_float([0, 1, 2].map(|i| center[i] + p[i] + n[i])), -to_float(n));
            let (o, d) = (d3(ray.origin), d3(ray.dir));
            if ellipsoid_normal_sensitivity(o, d, center, semi, axis, angle) > 1e-5 {
                continue;
            }
            compared += 1;
            let (t, n) = ellipsoid_f64(o, d, center, semi, axis, angle).unwrap();
            let hit = hit_object(&ellipsoid, &ray, Interval::POSITIVE).expect("a head-on ray hits");
            let size = o.iter().chain(&center).fold(0.0f64, |m, x| m.max(x.abs()));
            assert!((hit.t as f64 - t).abs() <= 16.0 * EPS as f64 * t.max(size), "t {} vs {t}", hit.t);
            assert!(angle_to(hit.outward_normal(), n) <= 1e-4, "normal {} vs {n:?}", hit.outward_normal());
        }
        assert!(compared >= 3_000, "only {compared} well-conditioned rays");
    }

    /// A small scene of every kind of shape, most of them placed by transforms.
    fn mixed_scene() -> Vec<Object> {
        let t = |x: Float, y: Float, z: Float| Mat4::from_translation(Vec3::new(x, y, z));
        vec![
            object(Shape::Sphere { center: Vec3::new(-2.0, 0.0, 0.0), radius: 0.7 }, 1, None),
            object(
                Shape::Sphere { center: Vec3::ZERO, radius: 1.0 },
                2,
                Some(
                    t(2.0, 1.0, 0.0)
                        * Mat4::from_rotation_x(0.7)
                        * Mat4::from_scale(Vec3::new(0.4, 1.2, 0.7)),
                ),
            ),
            object(Shape::Plane { normal: Vec3::Y, offset: -2.0 }, 0, None),
            object(
                Shape::Box { min: -Vec3::ONE, max: Vec3::ONE },
                3,
                Some(t(0.0, -1.0, 2.0) * Mat4::from_rotation_y(0.5) * Mat4::from_scale(Vec3::splat(0.5))),
            ),
            object(
                Shape::Cylinder,
                4,
                Some(
                    t(0.0, 1.5, -1.0)
                        * Mat4::from_rotation_x(-1.2)
                        * Mat4::from_scale(Vec3::new(0.5, 0.5, 1.5)),
                ),
            ),
            object(Shape::Cone, 5, Some(t(-1.0, -1.8, -2.0) * Mat4::from_rotation_x(-1.5))),
            object(
                Shape::Triangle {
                    vertices: [
                        Vec3::new(1.0, -1.0, -2.0),
                        Vec3::new(2.5, -1.0, -2.0),
                        Vec3::new(1.5, 0.5, -2.5),
                    ],
                    normals: None,
                },
                6,
                None,
            ),
            object(
                Shape::Mesh(Arc::new(Mesh::icosphere(1))),
                7,
                Some(t(0.0, 0.0, 0.0) * Mat4::from_scale(Vec3::splat(0.6))),
            ),
        ]
    }

    #[test]
    fn brute_force_finds_the_objects_in_order_of_distance() {
        // Straight down the y axis from y = 10 through a column of shapes listed out of
        // order. Their tops, by hand: the cylinder's cap at y = 3, the sphere at 1, the box
        // at −2, the cone's apex at −3, the plane at −5. Asking again from just past each
        // solid must give the next one down, with its index and material.
        let t = |y: Float| Mat4::from_translation(Vec3::new(0.0, y, 0.0));
        let to_y = Mat4::from_rotation_x(-raylab::math::consts::FRAC_PI_2); // local z → world y
        let objects = vec![
            object(Shape::Sphere { center: Vec3::ZERO, radius: 1.0 }, 11, None), // top y = 1
            object(Shape::Plane { normal: Vec3::Y, offset: -5.0 }, 12, None),    // y = −5
            object(Shape::Cylinder, 13, Some(t(2.0) * to_y)),                    // cap y = 3
            object(Shape::Box { min: Vec3::new(-1.0, -2.5, -1.0), max: Vec3::new(1.0, -2.0, 1.0) }, 14, None), // y = −2
            object(Shape::Cone, 15, Some(t(-4.0) * to_y)), // apex y = −3
        ];
        let order = [(2, 2.0 + 1.0), (0, 1.0), (3, -2.0), (4, -3.0), (1, -5.0)];
        let scene = BruteForce::new(&objects);
        let ray = Ray::new(Vec3::new(0.0, 10.0, 0.0), -Vec3::Y);
        let mut range = Interval::POSITIVE;
        for (index, top) in order {
            let hit = scene.closest_hit(&ray, range).expect("one more object below");
            assert_eq!((hit.object, hit.material), (index, objects[index].material));
            // Tolerance: R_x(−90°) rounds its cos to ~4e-8 in f32, on lengths ~10.
            assert_abs_diff_eq!(hit.t, 10.0 - top, epsilon = 1e-5);
            assert!(scene.any_hit(&ray, range));
            range = Interval::new(hit.t + 1e-3, Float::INFINITY);
            // The hits from inside (the far walls) come first: skip past the solid.
            if let Some(exit) = hit_object(&objects[index], &ray, range) {
                range = Interval::new(exit.t + 1e-3, Float::INFINITY);
            }
        }
        assert_eq!(scene.closest_hit(&ray, range), None);
        assert!(!scene.any_hit(&ray, range));
    }

    #[test]
    fn any_hit_agrees_with_closest_hit_on_random_rays() {
        // 1,000 rays from [−4, 4]³ in random directions with random ranges: any_hit is
        // true exactly when closest_hit finds something, and the closest hit is no
        // farther than any single object's own hit.
        let objects = mixed_scene();
        let scene = BruteForce::new(&objects);
        let mut rng = Rng::new(11);
        let mut hits = 0;
        for _ in 0..1_000 {
            let ray = Ray::new(rng.in_cube(4.0), rng.in_cube(1.0));
            let range = Interval::new(0.0, rng.range(0.5, 12.0));
            let closest = scene.closest_hit(&ray, range);
            assert_eq!(scene.any_hit(&ray, range), closest.is_some(), "{ray:?} in {range:?}");
            for (i, o) in objects.iter().enumerate() {
                if let Some(h) = hit_object(o, &ray, range) {
                    assert!(closest.is_some_and(|c| c.t <= h.t), "object {i} is nearer than {closest:?}");
                }
            }
            hits += closest.is_some() as usize;
        }
        // Both outcomes must occur often for the agreement to mean anything.
        assert!((200..=800).contains(&hits), "{hits} of 1000 rays hit");
    }

    #[test]
    fn any_hit_stops_at_the_first_blocker() {
        // Two spheres on the ray: any_hit tests only the first listed one that blocks.
        let objects = [
            object(Shape::Sphere { center: Vec3::new(0.0, 0.0, -5.0), radius: 1.0 }, 0, None),
            object(Shape::Sphere { center: Vec3::new(0.0, 0.0, -9.0), radius: 1.0 }, 0, None),
        ];
        let scene = BruteForce::new(&objects);
        let ray = Ray::new(Vec3::ZERO, -Vec3::Z);
        let (blocked, stats) = measure(|| scene.any_hit(&ray, Interval::POSITIVE));
        assert!(blocked);
        assert_eq!(stats.get(Counter::IntersectionTests), 1);
        let (_, stats) = measure(|| scene.closest_hit(&ray, Interval::POSITIVE));
        assert_eq!(stats.get(Counter::IntersectionTests), 2);
    }
}
