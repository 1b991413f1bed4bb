//! Transformed objects: intersect in object space, answer in world space.
//!
//! In a scene file every object takes an optional `transform` list, composed
//! into `world_from_object` (see `crates/raylab/SCENES.md`); the loader keeps
//! its inverse `object_from_world` beside it in a [`Transform`].

use raylab::scene::Transform;
use raylab::{Hit, Interval, Mat4, Ray, Vec3};

/// `ray` expressed in object space: origin' = M·origin as a point (w = 1),
/// dir' = M·dir as a vector (w = 0), with M = `object_from_world`.
///
/// dir' is **not** renormalised: the object-space point origin' + t·dir' is
/// the image of the world point origin + t·dir for the same t, so a t found in
/// object space is the world t, in world units, and the same interval of t
/// applies on both sides. `object_from_world` must be affine (its last row,
/// 0 0 0 1, is not read). Book: §4.4 Transforming the ray, not the object.
pub fn ray_to_object(ray: &Ray, object_from_world: &Mat4) -> Ray {
    // SOLUTION BEGIN
    Ray::new(object_from_world.transform_point3(ray.origin), object_from_world.transform_vector3(ray.dir))
    // SOLUTION END
}

/// An object-space normal `n` taken to world space: n_w = (A⁻¹)ᵀ n,
/// normalised, with A = `world_from_object`.
///
/// Normals are not vectors between points: they must stay perpendicular to
/// every tangent t, and (A⁻¹)ᵀn · A t = nᵀ A⁻¹ A t = n · t = 0. A⁻¹ is
/// `object_from_world`, so n_w is its upper 3×3 block transposed, times n
/// (the translation plays no part). Transforming n by A itself is the
/// classic mistake: it is right only for rotations and uniform scales.
/// The outward side stays outward, even for mirroring transforms. `n` need not
/// be unit length but must not be zero. Book: §4.5 Transforming normals.
pub fn normal_to_world(n: Vec3, object_from_world: &Mat4) -> Vec3 {
    debug_assert!(n != Vec3::ZERO, "a normal must not be zero");
    // SOLUTION BEGIN
    let world_from_object_normals = raylab::Mat3::from_mat4(*object_from_world).transpose();
    (world_from_object_normals * n).normalize()
    // SOLUTION END
}

/// The hit of `ray` with an object placed by `transform`, found by
/// `hit_local` in the object's own space.
///
/// Steps: take the ray to object space ([`ray_to_object`]), intersect there
/// with the same `range` (t is shared, see above), then build the world hit:
/// the same t, point = ray.at(t) on the world ray, normal = the local
/// **outward** normal taken to world space by [`normal_to_world`] and faced
/// against the world ray according to the local `front_face` (the sign of
/// n·d survives the map exactly: (A⁻¹)ᵀn · A d = n · d), and `front_face`,
/// `uv`, `object` and `material` kept from the local hit.
/// Book: §4.6 Instancing: one canonical shape, many placements.
pub fn hit_transformed(
    ray: &Ray,
    transform: &Transform,
    range: Interval,
    hit_local: impl Fn(&Ray, Interval) -> Option<Hit>,
) -> Option<Hit> {
    // SOLUTION BEGIN
    // Intersect in object space.
    let local_ray = ray_to_object(ray, &transform.object_from_world);
    let local = hit_local(&local_ray, range)?;
    // Back to the world: same t, world point, world outward normal faced against the ray.
    let outward = normal_to_world(local.outward_normal(), &transform.object_from_world);
    let normal = if local.front_face { outward } else { -outward };
    Some(Hit { point: ray.at(local.t), normal, ..local })
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hit_cylinder;
    use crate::testing::{
        EPS, angle_to, d3, ellipsoid_f64, ellipsoid_normal_sensitivity, ellipsoid_transform, unit,
        unit_sphere,
    };
    use approx::{assert_abs_diff_eq, assert_relative_eq};
    use raylab::math::consts::TAU;
    use raylab::random::Rng;
    use raylab::{Float, Vec2};

    /// T(1, 2, 3)·S(2, 0.5, 4) and its inverse written by hand: S(1/2, 2, 1/4)·T(−1, −2, −3).
    fn placed() -> Transform {
        Transform {
            world_from_object: Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0))
                * Mat4::from_scale(Vec3::new(2.0, 0.5, 4.0)),
            object_from_world: Mat4::from_scale(Vec3::new(0.5, 2.0, 0.25))
                * Mat4::from_translation(Vec3::new(-1.0, -2.0, -3.0)),
        }
    }

    #[test]
    fn ray_to_object_maps_every_point_of_the_ray_and_keeps_t() {
        let tr = placed();
        let world = Ray::new(Vec3::ZERO, Vec3::new(1.0, 1.0, 1.0));
        let local = ray_to_object(&world, &tr.object_from_world);
        // By hand: origin ((0 − 1)/2, (0 − 2)·2, (0 − 3)/4), dir (1/2, 2, 1/4), not renormalised.
        assert_eq!(local.origin, Vec3::new(-0.5, -4.0, -0.75));
        assert_eq!(local.dir, Vec3::new(0.5, 2.0, 0.25));
        // The image of the world point at t is the local point at the same t (dyadic: exact).
        for t in [0.0, 0.5, 3.0, -2.0] {
            assert_eq!(tr.object_from_world.transform_point3(world.at(t)), local.at(t));
        }
    }

    #[test]
    fn normal_to_world_is_the_inverse_transpose() {
        // Squash y by 4: A = S(1, 1/4, 1), (A⁻¹)ᵀ = S(1, 4, 1), so n = (1, 1, 0) goes to
        // (1, 4, 0)/√17, not to A·n ∝ (1, 1/4, 0). Translation plays no part.
        let object_from_world =
            Mat4::from_scale(Vec3::new(1.0, 4.0, 1.0)) * Mat4::from_translation(Vec3::splat(-7.0));
        let n = normal_to_world(Vec3::new(1.0, 1.0, 0.0), &object_from_world);
        let expected = Vec3::new(1.0, 4.0, 0.0) / (17.0 as Float).sqrt();
        assert_abs_diff_eq!(n, expected, epsilon = 4.0 * EPS);
        // A rotation turns normals like any vector: R_z(90°) takes x to y (R⁻¹ = R_z(−90°)).
        let n = normal_to_world(Vec3::X, &Mat4::from_rotation_z(-raylab::math::consts::FRAC_PI_2));
        assert_abs_diff_eq!(n, Vec3::Y, epsilon = 4.0 * EPS);
        // A uniform scale changes nothing once normalised.
        assert_abs_diff_eq!(normal_to_world(Vec3::Z * 3.0, &Mat4::from_scale(Vec3::splat(0.1))), Vec3::Z);
    }

    #[test]
    fn transformed_normals_stay_perpendicular_to_transformed_tangents() {
        // (A⁻¹)ᵀn · A t = n · t = 0 for every tangent t ⟂ n. 1,000 random affine maps
        // R₁·S·R₂ + translation, scales in [1/4, 4] (condition number ≤ 16), random
        // directions; tolerance 64ε·|A t| covers the inverse and the products.
        let mut rng = Rng::new(6);
        let turn = |rng: &mut Rng| Mat4::from_axis_angle(rng.in_cube(1.0).normalize(), rng.range(0.0, 6.0));
        for _ in 0..1_000 {
            let scale = Vec3::new(rng.range(0.25, 4.0), rng.range(0.25, 4.0), rng.range(0.25, 4.0));
            let world_from_object = Mat4::from_translation(rng.in_cube(5.0))
                * turn(&mut rng)
                * Mat4::from_scale(scale)
                * turn(&mut rng);
            let object_from_world = world_from_object.inverse();
            let n = rng.in_cube(1.0);
            let tangent = n.normalize().any_orthonormal_vector() * rng.range(0.5, 2.0);
            let world_tangent = world_from_object.transform_vector3(tangent);
            let product = normal_to_world(n, &object_from_world).dot(world_tangent);
            assert!(product.abs() <= 64.0 * EPS * world_tangent.length(), "n_w · A t = {product}");
        }
    }

    #[test]
    fn t_is_in_world_units_under_extreme_scale() {
        // A unit sphere scaled 1e-3 : 1 : 1e3 and moved to (5, 0, 0): the ellipsoid
        // (x − 5)²/1e-6 + y² + z²/1e6 = 1. The hits by hand (4ε relative: c/q rounds a few times):
        let tr = ellipsoid_transform([5.0, 0.0, 0.0], [1e-3, 1.0, 1e3], [0.0, 0.0, 1.0], 0.0);
        let cases: [([Float; 3], [Float; 3], Float); 4] = [
            ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], 4.999),      // x = 5 − 1e-3
            ([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], 2.4995),     // the same point, dir ×2
            ([5.0, -3.0, 0.0], [0.0, 0.5, 0.0], 4.0),       // y = −1: (−1 + 3)/0.5
            ([5.0, 0.0, -3000.0], [0.0, 0.0, 2.0], 1000.0), // z = −1000: (−1000 + 3000)/2
        ];
        for (o, d, t) in cases {
            let world = Ray::new(Vec3::from_array(o), Vec3::from_array(d));
            let h = hit_transformed(&world, &tr, Interval::POSITIVE, unit_sphere).expect("on the ray's path");
            assert_relative_eq!(h.t, t, max_relative = 4.0 * EPS);
            assert_eq!(h.point, world.at(h.t));
        }
    }

    #[test]
    fn rotated_squashed_sphere_is_the_analytic_ellipsoid() {
        // Semi-axes 2, 0.5, 1 turned 35° about (1, 2, 2)/3, centred at (1, −2, 0.5),
        // against the same ellipsoid solved directly in world space in f64. 5,000 rays
        // from [−6, 6]³ through a point inside at half the semi-axes (so none is near
        // tangent). Tolerances: t within 64ε·max(1, t) and normals within 256ε rad: the
        // `Float` rotation, inverse and the local solve each add a few ε, on |o| ≤ 10,
        // times the ellipsoid's curvature ratio of at most (2/0.5)² = 16.
        let (center, semi, axis, angle) =
            ([1.0, -2.0, 0.5], [2.0, 0.5, 1.0], unit([1.0, 2.0, 2.0]), 35f64.to_radians());
        let tr = ellipsoid_transform(center, semi, axis, angle);
        let mut rng = Rng::new(7);
        for _ in 0..5_000 {
            let origin = rng.in_cube(6.0);
            let inside = tr.world_from_object.transform_point3(rng.in_cube(0.5));
            let world = Ray::new(origin, inside - origin);
            let Some((t, n)) = ellipsoid_f64(d3(world.origin), d3(world.dir), center, semi, axis, angle)
            else {
                panic!("the reference misses a ray through the inside");
            };
            let h = hit_transformed(&world, &tr, Interval::POSITIVE, unit_sphere).expect("hits");
            assert!((h.t as f64 - t).abs() <= 64.0 * EPS as f64 * t.max(1.0), "t {} vs {t}", h.t);
            assert!(angle_to(h.outward_normal(), n) <= 256.0 * EPS as f64, "normal {} vs {n:?}", h.normal);
            // Faced against the ray; front when the ray arrives from outside.
            assert!(h.normal.dot(world.dir) < 0.0);
            assert_eq!(h.front_face, crate::testing::dot(n, d3(world.dir)) < 0.0);
        }
    }

    #[test]
    fn extreme_scale_normals_within_1e_4_rad() {
        // Scale 1e-3 : 1 : 1e3, centred at (5, −2, 300). Rays come head-on from one
        // world unit out along the normal of 20,000 surface points, and are compared
        // with the f64 world-space ellipsoid. Where the normal turns by more than 1e-5
        // rad when the origin moves by one rounding (the pancake's rim has curvature
        // ~1e6), no `Float` method can be within 1e-4: those rays are skipped, and
        // at least 3/4 of them must remain. t: 16ε relative (measured ~3ε).
        let (center, semi, axis) = ([5.0, -2.0, 300.0], [1e-3, 1.0, 1e3], [0.0, 0.0, 1.0]);
        let tr = ellipsoid_transform(center, semi, axis, 0.0);
        let mut rng = Rng::new(8);
        let mut compared = 0;
        for _ in 0..20_000 {
            let (theta, phi) = (rng.range(0.05, 3.09) as f64, rng.range(0.0, TAU) as f64);
            let local = [theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos()];
            let p = [0, 1, 2].map(|i| center[i] + semi[i] * local[i]);
            let n = unit([0, 1, 2].map(|i| local[i] / semi[i]));
            let world = Ray::new(
                Vec3::new((p[0] + n[0]) as Float, (p[1] + n[1]) as Float, (p[2] + n[2]) as Float),
                Vec3::new(-n[0] as Float, -n[1] as Float, -n[2] as Float),
            );
            let (o, d) = (d3(world.origin), d3(world.dir));
            if ellipsoid_normal_sensitivity(o, d, center, semi, axis, 0.0) > 1e-5 {
                continue;
            }
            compared += 1;
            let (t, n) = ellipsoid_f64(o, d, center, semi, axis, 0.0).unwrap();
            let h = hit_transformed(&world, &tr, Interval::POSITIVE, unit_sphere).expect("head-on ray hits");
            assert!((h.t as f64 - t).abs() <= 16.0 * EPS as f64 * t, "t {} vs {t}", h.t);
            assert!(angle_to(h.outward_normal(), n) <= 1e-4, "normal {} vs {n:?}", h.outward_normal());
        }
        assert!(compared >= 15_000, "only {compared} well-conditioned rays");
    }

    #[test]
    fn catalogued_mistakes_are_caught() {
        // A sphere squashed to a quarter in y, hit where the local normal is (1, 1, 0)/√2:
        // the right world normal is ∝ (1, 4, 0), A·n is ∝ (1, 1/4, 0), 62° away.
        let (center, semi, axis) = ([0.0, 0.0, 0.0], [1.0, 0.25, 1.0], [0.0, 0.0, 1.0]);
        let tr = ellipsoid_transform(center, semi, axis, 0.0);
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let target = Vec3::new(s as Float, (0.25 * s) as Float, 0.0);
        let world = Ray::new(target + Vec3::new(2.0, 0.0, 0.0), Vec3::new(-1.0, 0.0, 0.0));
        let (_, analytic) = ellipsoid_f64(d3(world.origin), d3(world.dir), center, semi, axis, 0.0).unwrap();
        let h = hit_transformed(&world, &tr, Interval::POSITIVE, unit_sphere).unwrap();
        assert!(angle_to(h.outward_normal(), analytic) < 1e-5);

        // Mistake 1: the normal transformed by M instead of (M⁻¹)ᵀ.
        let local = ray_to_object(&world, &tr.object_from_world);
        let local_hit = unit_sphere(&local, Interval::POSITIVE).unwrap();
        let wrong_normal = tr.world_from_object.transform_vector3(local_hit.outward_normal()).normalize();
        assert!(angle_to(wrong_normal, analytic) > 0.1, "M·n should be visibly wrong");

        // Mistake 2: the object-space direction renormalised: its t is in object units,
        // here |M⁻¹ d| = 1 for d = −x, so try a ray along y, where |M⁻¹ d| = 4.
        let world = Ray::new(Vec3::new(0.0, -3.0, 0.0), Vec3::Y);
        let local = ray_to_object(&world, &tr.object_from_world);
        let renormalised = Ray::new(local.origin, local.dir.normalize());
        let wrong_t = unit_sphere(&renormalised, Interval::POSITIVE).unwrap().t;
        let h = hit_transformed(&world, &tr, Interval::POSITIVE, unit_sphere).unwrap();
        assert_relative_eq!(h.t, 2.75, max_relative = 4.0 * EPS); // y = −0.25, by hand
        assert!((wrong_t - 2.75).abs() > 1.0, "a renormalised direction gives t = {wrong_t}");
    }

    #[test]
    fn mirroring_keeps_the_outward_normal_outward() {
        // x ↦ −x maps the unit sphere onto itself; the hit from −x at (−1, 0, 0) must
        // still report the outward normal −x (the local point is (1, 0, 0)).
        let tr = Transform::new(Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0))).unwrap();
        let h = hit_transformed(
            &Ray::new(Vec3::new(-3.0, 0.0, 0.0), Vec3::X),
            &tr,
            Interval::POSITIVE,
            unit_sphere,
        )
        .unwrap();
        assert_eq!((h.t, h.point, h.front_face), (2.0, Vec3::new(-1.0, 0.0, 0.0), true));
        assert_eq!(h.normal, Vec3::new(-1.0, 0.0, 0.0));
    }

    #[test]
    fn the_local_hit_keeps_its_side_uv_and_ids() {
        // A stand-in local shape: the plane z = 0 seen from inside (front_face false),
        // with uv and ids set. hit_transformed must keep all four and face the normal.
        let tr = placed();
        let local_shape = |ray: &Ray, range: Interval| {
            let t = -ray.origin.z / ray.dir.z;
            range.contains(t).then(|| Hit {
                object: 3,
                material: 2,
                ..Hit::new(ray, t, -Vec3::Z).with_uv(Vec2::new(0.25, 0.75))
            })
        };
        // World z = 3 is the local plane z = 0; coming down from z = 5 along −z.
        let world = Ray::new(Vec3::new(1.0, 2.0, 5.0), Vec3::new(0.0, 0.0, -1.0));
        let h = hit_transformed(&world, &tr, Interval::POSITIVE, local_shape).unwrap();
        assert_eq!((h.t, h.point), (2.0, Vec3::new(1.0, 2.0, 3.0)));
        assert_eq!((h.front_face, h.uv, h.object, h.material), (false, Vec2::new(0.25, 0.75), 3, 2));
        assert_eq!((h.normal, h.outward_normal()), (Vec3::Z, -Vec3::Z));
    }

    #[test]
    fn cylinder_stood_up_along_y() {
        // T(0, −1, 0)·R_x(−90°)·S(2, 2, 3) takes the local axis z to world +y: radius 2,
        // from y = −1 to y = 2. By hand: from (−5, 0, 0) along +x, the side at x = −2,
        // t = 3; from (1, 10, 0) along −y, the top cap y = 2 at t = 8. Tolerance: R_x(−90°)
        // in `Float` has cos = ~−4e-8 (f32), not 0, which moves points by ~1e-7 on these
        // sizes: 1e-5 absolute in f32; 64ε in f64.
        let tolerance = (64.0 * EPS).max(if EPS > 1e-10 { 1e-5 } else { 0.0 });
        let tr = Transform::new(
            Mat4::from_translation(Vec3::new(0.0, -1.0, 0.0))
                * Mat4::from_rotation_x(-raylab::math::consts::FRAC_PI_2)
                * Mat4::from_scale(Vec3::new(2.0, 2.0, 3.0)),
        )
        .unwrap();
        let side = hit_transformed(
            &Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X),
            &tr,
            Interval::POSITIVE,
            hit_cylinder,
        )
        .unwrap();
        assert_abs_diff_eq!(side.t, 3.0, epsilon = tolerance);
        assert_abs_diff_eq!(side.normal, -Vec3::X, epsilon = tolerance);
        let top = hit_transformed(
            &Ray::new(Vec3::new(1.0, 10.0, 0.0), -Vec3::Y),
            &tr,
            Interval::POSITIVE,
            hit_cylinder,
        )
        .unwrap();
        assert_abs_diff_eq!(top.t, 8.0, epsilon = tolerance);
        assert_abs_diff_eq!(top.normal, Vec3::Y, epsilon = tolerance);
        assert!(side.front_face && top.front_face);
    }
}
