//! The checks of `transformed.rs`: ray_to_object, normal_to_world, hit_transformed.

use super::common::*;

/// T(1, 2, 3)·S(2, 0.5, 4) and its inverse written by hand: S(½, 2, ¼)·T(−1, −2, −3).
pub(super) fn placed() -> Transform {
    Transform {
        world_from_object: Mat4::from_translation(Vec3::new(1.0, 2.0, 3.0))
            * Mat4::from_scale(Vec3::new(2.0, 0.5, 4.0)),
        object_from_world: Mat4::from_scale(Vec3::new(0.5, 2.0, 0.25))
            * Mat4::from_translation(Vec3::new(-1.0, -2.0, -3.0)),
    }
}

pub(super) fn to_object_cases(to_object: ToObjectFn) -> CheckResult {
    let m = placed().object_from_world;
    let world = ray([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]);
    let case = format!("object_from_world = S(½, 2, ¼)·T(−1, −2, −3), world {}", show_ray(&world));
    let got = to_object(&world, &m);
    // By hand: origin ((0 − 1)/2, (0 − 2)·2, (0 − 3)/4), dir (½, 2, ¼), not renormalised.
    let (origin, dir) = (Vec3::new(-0.5, -4.0, -0.75), Vec3::new(0.5, 2.0, 0.25));
    let cause = if near3(got.origin, Vec3::new(0.0, 0.0, 0.0), TOL) {
        "the origin is a point (w = 1): the translation applies to it"
    } else if near3(got.origin, Vec3::new(1.0, 2.0, 3.0), TOL) {
        "the matrix given is object_from_world already: apply it as it is (do not invert it)"
    } else {
        "origin' = M·(origin, 1)"
    };
    close3(&case, got.origin, origin, TOL, cause)?;
    let cause = if near3(got.dir, dir.normalize(), TOL) {
        "do not renormalise dir: the same t must name the same point in both spaces, so t stays in \
            world units"
    } else if near3(got.dir, origin + dir, TOL) {
        "dir is a vector (w = 0): the translation must not move it"
    } else {
        "dir' = M·(dir, 0)"
    };
    close3(&case, got.dir, dir, TOL, cause)?;
    // A rotation by 30° about z after moving by (−1, 0, 0): (1, 1, 0) ↦ R(0, 1, 0) = (−½, √3/2, 0);
    // (0, 2, 0) ↦ (−1, √3, 0).
    let m = Mat4::from_rotation_z(FRAC_PI_6) * Mat4::from_translation(-Vec3::X);
    let world = ray([1.0, 1.0, 0.0], [0.0, 2.0, 0.0]);
    let got = to_object(&world, &m);
    let case = format!("object_from_world = R_z(30°)·T(−1, 0, 0), world {}", show_ray(&world));
    let half_root3 = (3.0 as Float).sqrt() / 2.0;
    close3(&case, got.origin, Vec3::new(-0.5, half_root3, 0.0), TOL, "origin' = M·(origin, 1)")?;
    close3(
        &case,
        got.dir,
        Vec3::new(-1.0, 2.0 * half_root3, 0.0),
        TOL,
        "dir' = M·(dir, 0), not renormalised",
    )?;
    Ok("2 rays".into())
}

/// In f64: the unit normal to the plane spanned by A·t₁ and A·t₂, oriented as t₁ × t₂ is.
pub(super) fn spanned_normal(a: &Mat4, t1: Vec3, t2: Vec3) -> Vec3 {
    let (u, v) = (a.transform_vector3(t1), a.transform_vector3(t2));
    let w = |x: Vec3| [x.x as f64, x.y as f64, x.z as f64];
    let (u, v) = (w(u), w(v));
    let n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    Vec3::new((n[0] / l) as Float, (n[1] / l) as Float, (n[2] / l) as Float)
}

pub(super) fn normal_cases(to_world: NormalFn) -> CheckResult {
    // world_from_object A = T(7, 7, 7)·R_z(−30°)·S(1, ¼, 1); object_from_world M = A⁻¹ by hand.
    let a = Mat4::from_translation(Vec3::splat(7.0))
        * Mat4::from_rotation_z(-FRAC_PI_6)
        * Mat4::from_scale(Vec3::new(1.0, 0.25, 1.0));
    let m = Mat4::from_scale(Vec3::new(1.0, 4.0, 1.0))
        * Mat4::from_rotation_z(FRAC_PI_6)
        * Mat4::from_translation(Vec3::splat(-7.0));
    // The world normal is perpendicular to the images A·t of the tangents t ⟂ n, on
    // n's side (det A > 0): n_w ∝ A t₁ × A t₂ for t₁ × t₂ = n, an independent route to (A⁻¹)ᵀn.
    for n in [Vec3::new(1.0, 1.0, 0.0), Vec3::Z, Vec3::new(0.3, -0.5, 0.8), Vec3::new(0.0, 2.0, 0.0)] {
        let t1 = n.normalize().any_orthonormal_vector();
        let t2 = n.normalize().cross(t1);
        let expected = spanned_normal(&a, t1, t2);
        let got = to_world(n, &m);
        let case =
            format!("object_from_world = S(1, 4, 1)·R_z(30°)·T(−7, −7, −7), object-space normal {}", vec3(n));
        let m3 = raylab::Mat3::from_mat4(m);
        let cause = if near3(got, a.transform_vector3(n).normalize(), 1e-4) {
            "normals take (M⁻¹)ᵀ: transforming n like a tangent (by world_from_object) is right only \
                for rotations and uniform scales; n_w = object_from_worldᵀ·n"
        } else if near3(got, (m3 * n).normalize(), 1e-4) {
            "transpose the 3×3 block: n_w = object_from_worldᵀ·n, not object_from_world·n"
        } else if near3(got, m3.transpose() * n, 1e-4) {
            "normalise the result"
        } else {
            "n_w = (A⁻¹)ᵀn normalised, with A⁻¹ = object_from_world (its 3×3 block: no translation)"
        };
        close3(&case, got, expected, 4.0 * TOL, cause)?;
    }
    // A mirror x ↦ −x: the outward normal +x of the local point (1, 0, 0) becomes −x.
    let mirror = Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0));
    close3(
        "object_from_world = S(−1, 1, 1) (a mirror), normal +x",
        to_world(Vec3::X, &mirror),
        -Vec3::X,
        TOL,
        "n_w = (A⁻¹)ᵀn: a mirror maps the outward normal +x to −x",
    )?;
    Ok("4 normals and a mirror".into())
}

/// A unit sphere at the origin written for the checks (independent of
/// lecture 02): stable roots with the discriminant a − |o × d|², which keeps
/// its digits when a squashing transform puts the local origin far away.
pub(super) fn unit_sphere(ray: &Ray, range: Interval) -> Option<Hit> {
    let (o, d) = (ray.origin, ray.dir);
    let (a, b, c) = (d.dot(d), o.dot(d), o.dot(o) - 1.0);
    let disc = a - o.cross(d).length_squared();
    if disc < 0.0 {
        return None;
    }
    let q = -(b + disc.sqrt().copysign(b));
    let (t0, t1) = if q == 0.0 { (0.0, 0.0) } else { (q / a, c / q) };
    let t = [t0.min(t1), t0.max(t1)].into_iter().find(|&t| range.contains(t))?;
    Some(Hit::new(ray, t, ray.at(t)))
}

/// The plane z = 0 seen from inside (outward −z), with uv (¼, ¾), object 3, material 2.
pub(super) fn tagged_plane(ray: &Ray, range: Interval) -> Option<Hit> {
    let t = -ray.origin.z / ray.dir.z;
    range.contains(t).then(|| Hit {
        object: 3,
        material: 2,
        ..Hit::new(ray, t, -Vec3::Z).with_uv(Vec2::new(0.25, 0.75))
    })
}

pub(super) const WORLD_T: &str = "t must stay in world units: do not renormalise the object-space direction (the \
    same t names the same point in both spaces)";
pub(super) const NORMAL_WORLD: &str = "take the local outward normal to the world with normal_to_world ((M⁻¹)ᵀ), \
    then face it by the local front_face";

pub(super) fn transformed_cases(transformed: TransformedFn) -> CheckResult {
    let tr = placed();
    let name = "the unit sphere placed by T(1, 2, 3)·S(2, 0.5, 4)";
    // The ellipsoid ((x − 1)/2)² + ((y − 2)/0.5)² + ((z − 3)/4)² = 1; hits by hand.
    // (origin, direction, t, normal, front_face)
    type Case = ([Float; 3], [Float; 3], Float, Vec3, bool);
    let cases: [Case; 3] = [
        ([-5.0, 2.0, 3.0], [1.0, 0.0, 0.0], 4.0, -Vec3::X, true), // x = 1 − 2 = −1
        ([1.0, -3.0, 3.0], [0.0, 2.0, 0.0], 2.25, -Vec3::Y, true), // y = 1.5: (1.5 + 3)/2
        ([1.0, 2.0, 3.0], [0.0, 0.0, 1.0], 4.0, -Vec3::Z, false), // from the centre to z = 7
    ];
    for (o, d, t, normal, front) in cases {
        let r = ray(o, d);
        let case = format!("{name}, {}", show_ray(&r));
        let got = transformed(&r, &tr, ALL, unit_sphere);
        let Some(h) = got else {
            return Err(fail(
                case,
                format!("t = {t}"),
                "None (no hit)",
                "intersect the object-space ray (ray_to_object) with the local shape",
            ));
        };
        close(&case, h.t, t, TOL * t, WORLD_T)?;
        close3(
            &case,
            h.point,
            r.at(t),
            TOL * 8.0,
            "the hit point is on the world ray: ray.at(t), not the object-space point",
        )?;
        let cause = if near3(h.normal, -normal, TOL) {
            "face the world normal by the local front_face: from inside it points back into the object"
        } else {
            NORMAL_WORLD
        };
        close3(&case, h.normal, normal, TOL, cause)?;
        ensure(
            h.front_face == front,
            &case,
            format!("front_face {front}"),
            h.front_face,
            "keep the local hit's front_face",
        )?;
    }
    // Head-on at the point whose local normal is (1, 1, 0)/√2: the local point (1, 1, 0)/√2 is
    // (1 + √2, 2 + 0.5/√2, 3) in the world, where the normal is ∝ (x/a², y/b²) ∝ (1/2, 2) ∝ (1, 4, 0).
    let s = SQRT_HALF;
    let p = Vec3::new(1.0 + 2.0 * s, 2.0 + 0.5 * s, 3.0);
    let n = Vec3::new(1.0, 4.0, 0.0).normalize();
    let r = Ray::new(p + n, -n);
    let case = format!("{name}, {} (head-on where the local normal is (1, 1, 0)/√2)", show_ray(&r));
    let got = transformed(&r, &tr, ALL, unit_sphere);
    let Some(h) = got else {
        return Err(fail(case, "t = 1", "None (no hit)", "intersect in object space"));
    };
    close(&case, h.t, 1.0, 64.0 * Float::EPSILON, WORLD_T)?;
    let by_m = tr.world_from_object.transform_vector3(Vec3::new(s, s, 0.0)).normalize();
    let cause = if near3(h.normal, by_m, 1e-3) {
        "the normal went through world_from_object: normals take (M⁻¹)ᵀ, use normal_to_world"
    } else {
        NORMAL_WORLD
    };
    close3(&case, h.normal, n, 64.0 * Float::EPSILON, cause)?;
    // A stand-in local shape: the local plane z = 0 (world z = 3) seen from inside, with uv and ids.
    let r = ray([1.0, 2.0, 5.0], [0.0, 0.0, -1.0]);
    let case =
        format!("the plane z = 0 placed by T(1, 2, 3)·S(2, 0.5, 4), seen from its back, {}", show_ray(&r));
    let got = transformed(&r, &tr, ALL, tagged_plane);
    let Some(h) = got else {
        return Err(fail(case, "t = 2", "None (no hit)", "intersect in object space"));
    };
    close(&case, h.t, 2.0, TOL, WORLD_T)?;
    close3(
        &case,
        h.point,
        Vec3::new(1.0, 2.0, 3.0),
        TOL,
        "the hit point is on the world ray: ray.at(t), not the object-space point",
    )?;
    ensure(
        (h.front_face, h.uv, h.object, h.material) == (false, Vec2::new(0.25, 0.75), 3, 2),
        &case,
        "front_face false, uv (0.25, 0.75), object 3, material 2",
        format!(
            "front_face {}, uv ({}, {}), object {}, material {}",
            h.front_face,
            num(h.uv.x),
            num(h.uv.y),
            h.object,
            h.material
        ),
        "keep front_face, uv, object and material from the local hit (Hit { point, normal, ..local })",
    )?;
    close3(
        &case,
        h.normal,
        Vec3::Z,
        TOL,
        "the local outward normal −z, taken to the world and faced against the ray (+z)",
    )?;
    // A mirror x ↦ −x maps the unit sphere to itself: from (−3, 0, 0) along +x, t = 2, normal −x.
    let mirror = Transform::new(Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0))).expect("invertible");
    let r = ray([-3.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
    let case = format!("the unit sphere mirrored by S(−1, 1, 1), {}", show_ray(&r));
    let got = transformed(&r, &mirror, ALL, unit_sphere);
    let Some(h) = got else {
        return Err(fail(case, "t = 2", "None (no hit)", "intersect in object space"));
    };
    close3(
        &case,
        h.normal,
        -Vec3::X,
        TOL,
        "the outward side stays outward under a mirror: face the world normal by the local front_face, \
            not by recomputing the sign",
    )?;
    Ok("5 ellipsoid rays, a tagged plane, a mirror".into())
}

/// The axis-aligned ellipsoid Σ ((pᵢ − cᵢ)/sᵢ)² = 1 hit by a ray, in f64:
/// the first t > 0 and the unit outward normal (the gradient).
pub(super) fn ellipsoid_f64(
    o: [f64; 3],
    d: [f64; 3],
    center: [f64; 3],
    semi: [f64; 3],
) -> Option<(f64, [f64; 3])> {
    let u = [0, 1, 2].map(|i| (o[i] - center[i]) / semi[i]);
    let v = [0, 1, 2].map(|i| d[i] / semi[i]);
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let m = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    let (a, b, c) = (dot(v, v), dot(u, v), dot(u, u) - 1.0);
    let disc = a - dot(m, m);
    if disc < 0.0 {
        return None;
    }
    let q = -(b + disc.sqrt().copysign(b));
    let t = [(q / a).min(c / q), (q / a).max(c / q)].into_iter().find(|&t| t > 0.0)?;
    let g = [0, 1, 2].map(|i| (u[i] + t * v[i]) / semi[i]);
    let l = dot(g, g).sqrt();
    Some((t, g.map(|x| x / l)))
}

pub(super) fn angle(n: Vec3, reference: [f64; 3]) -> f64 {
    let a = [n.x as f64, n.y as f64, n.z as f64];
    let cross = [
        a[1] * reference[2] - a[2] * reference[1],
        a[2] * reference[0] - a[0] * reference[2],
        a[0] * reference[1] - a[1] * reference[0],
    ];
    let c = (cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]).sqrt();
    c.atan2(a[0] * reference[0] + a[1] * reference[1] + a[2] * reference[2])
}

pub(super) fn extreme_scale(transformed: TransformedFn) -> CheckResult {
    // 1. t in world units under the scale 1e-3 : 1 : 1e3, centred at (5, 0, 0), by hand (4ε relative).
    let tr = Transform::new(
        Mat4::from_translation(Vec3::new(5.0, 0.0, 0.0)) * Mat4::from_scale(Vec3::new(1e-3, 1.0, 1e3)),
    )
    .expect("invertible");
    let name = "the unit sphere scaled (1e-3, 1, 1e3) and moved to (5, 0, 0)";
    for (o, d, t) in [
        ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], 4.999),      // x = 5 − 1e-3
        ([0.0, 0.0, 0.0], [2.0, 0.0, 0.0], 2.4995),     // the same point, dir ×2
        ([5.0, -3.0, 0.0], [0.0, 0.5, 0.0], 4.0),       // y = −1: (−1 + 3)/0.5
        ([5.0, 0.0, -3000.0], [0.0, 0.0, 2.0], 1000.0), // z = −1000: (−1000 + 3000)/2
    ] {
        let r = ray(o, d);
        let case = format!("{name}, {}", show_ray(&r));
        let got = transformed(&r, &tr, ALL, unit_sphere);
        let Some(h) = got else {
            return Err(fail(
                case,
                format!("t = {t}"),
                "None (no hit)",
                "intersect the object-space ray with the local shape",
            ));
        };
        close(&case, h.t, t, 4.0 * Float::EPSILON * t, WORLD_T)?;
    }
    // 2. Head-on rays from one unit out along the normal at 4,000 points of the ellipsoid
    //    centred at (5, −2, 300), against the f64 world-space ellipsoid. Rays whose exact
    //    normal turns by more than 1e-5 rad when the origin moves by one rounding are
    //    ill-conditioned for any Float method (the pancake's rim) and skipped; at least
    //    3/4 remain. t within 16ε relative.
    let (center, semi) = ([5.0, -2.0, 300.0], [1e-3, 1.0, 1e3]);
    let v = |a: [f64; 3]| Vec3::new(a[0] as Float, a[1] as Float, a[2] as Float);
    let tr =
        Transform::new(Mat4::from_translation(v(center)) * Mat4::from_scale(v(semi))).expect("invertible");
    let mut rng = Rng::new(8);
    let (mut compared, mut worst) = (0, 0.0f64);
    for _ in 0..4000 {
        let (theta, phi) = (rng.range(0.05, 3.09) as f64, rng.range(0.0, TAU) as f64);
        let local = [theta.sin() * phi.cos(), theta.sin() * phi.sin(), theta.cos()];
        let p = [0, 1, 2].map(|i| center[i] + semi[i] * local[i]);
        let g = [0, 1, 2].map(|i| local[i] / semi[i]);
        let l = (g[0] * g[0] + g[1] * g[1] + g[2] * g[2]).sqrt();
        let n = g.map(|x| x / l);
        let world = Ray::new(v([0, 1, 2].map(|i| p[i] + n[i])), v(n.map(|x| -x)));
        let (o, d) = (
            [world.origin.x as f64, world.origin.y as f64, world.origin.z as f64],
            [world.dir.x as f64, world.dir.y as f64, world.dir.z as f64],
        );
        let Some((t, normal)) = ellipsoid_f64(o, d, center, semi) else { continue };
        // How far the exact normal turns when the origin moves by one rounding.
        let delta = Float::EPSILON as f64 * (o.iter().fold(0.0f64, |m, x| m.max(x.abs())) + 300.0);
        let sensitivity = (0..3)
            .map(|k| {
                let mut moved = o;
                moved[k] += delta;
                ellipsoid_f64(moved, d, center, semi).map_or(f64::INFINITY, |(_, m)| angle(v(m), normal))
            })
            .fold(0.0, f64::max);
        if sensitivity > 1e-5 {
            continue;
        }
        compared += 1;
        let case =
            lazy(|f| {
                let case = format!("{name}, {} (head-on)", show_ray(&world));
                f.write_str(&case.replace(
                    "(1e-3, 1, 1e3) and moved to (5, 0, 0)",
                    "(1e-3, 1, 1e3) and moved to (5, −2, 300)",
                ))
            });
        let got = transformed(&world, &tr, ALL, unit_sphere);
        let Some(h) = got else {
            return Err(fail(
                case,
                format!("t = {t:.6}"),
                "None (no hit)",
                "intersect in object space: the head-on ray hits",
            ));
        };
        ensure(
            (h.t as f64 - t).abs() <= 16.0 * Float::EPSILON as f64 * t,
            &case,
            lazy(|f| write!(f, "t = {t:.7} (± 16ε·t = {:.1e})", 16.0 * Float::EPSILON as f64 * t)),
            lazy(|f| f.write_str(&num(h.t))),
            WORLD_T,
        )?;
        let error = angle(h.outward_normal(), normal);
        worst = worst.max(error);
        ensure(
            error <= 1e-4,
            &case,
            lazy(|f| write!(f, "outward normal {} within 1e-4 rad", vec3(v(normal)))),
            lazy(|f| write!(f, "{} ({error:.1e} rad off)", vec3(h.outward_normal()))),
            "normals take (M⁻¹)ᵀ = object_from_worldᵀ (normal_to_world), normalised after the \
                transform; M itself tilts them by up to 90° at 1e-3 : 1e3",
        )?;
    }
    ensure(
        compared >= 3000,
        name,
        "at least 3,000 well-conditioned rays",
        compared,
        "(the check's own sampling)",
    )?;
    Ok(format!("4 hand t's; {compared} head-on rays, worst normal {worst:.1e} rad"))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l04_quadrics_transforms::{normal_to_world, ray_to_object};
    use raylab::scene::Transform;
    use raylab::{Hit, Interval, Ray};

    #[test]
    fn to_object_mistakes() {
        caught(
            to_object_cases(|r, m| {
                Ray::new(m.transform_point3(r.origin), m.transform_vector3(r.dir).normalize())
            }),
            "do not renormalise",
        );
        caught(
            to_object_cases(|r, m| Ray::new(m.transform_point3(r.origin), m.transform_point3(r.dir))),
            "w = 0",
        );
        caught(to_object_cases(|r, m| ray_to_object(r, &m.inverse())), "as it is");
    }

    #[test]
    fn normal_mistakes() {
        caught(normal_cases(|n, m| m.inverse().transform_vector3(n).normalize()), "(M⁻¹)ᵀ");
        caught(normal_cases(|n, m| m.transform_vector3(n).normalize()), "transpose");
        caught(normal_cases(|n, m| raylab::Mat3::from_mat4(*m).transpose() * n), "normalise the result");
    }

    /// hit_transformed as written, or with one planted mistake.
    #[derive(Clone, Copy, PartialEq, Eq)]
    enum TransformedMistake {
        Faithful,
        /// The hit point left in object space.
        ObjectSpacePoint,
        /// A fresh hit record: the local hit's uv and ids dropped.
        RecordDropped,
        /// The object-space direction renormalised, so t is no longer in world units.
        Renormalised,
        /// The normal taken to the world by world_from_object, not (M⁻¹)ᵀ.
        NormalByMatrix,
    }

    fn planted_transformed(
        ray: &Ray,
        tr: &Transform,
        range: Interval,
        local: ShapeFn,
        mistake: TransformedMistake,
    ) -> Option<Hit> {
        let mut local_ray = ray_to_object(ray, &tr.object_from_world);
        let scale = if mistake == TransformedMistake::Renormalised { local_ray.dir.length() } else { 1.0 };
        local_ray.dir /= scale;
        let h = local(&local_ray, Interval::new(range.min * scale, range.max * scale))?;
        let outward = if mistake == TransformedMistake::NormalByMatrix {
            tr.world_from_object.transform_vector3(h.outward_normal()).normalize()
        } else {
            normal_to_world(h.outward_normal(), &tr.object_from_world)
        };
        let normal = if h.front_face { outward } else { -outward };
        let point = if mistake == TransformedMistake::ObjectSpacePoint { h.point } else { ray.at(h.t) };
        Some(if mistake == TransformedMistake::RecordDropped {
            Hit { normal, point, ..Hit::new(ray, h.t, outward) }
        } else {
            Hit { point, normal, ..h }
        })
    }

    #[test]
    fn transformed_mistakes() {
        assert!(
            transformed_cases(|r, t, i, l| planted_transformed(r, t, i, l, TransformedMistake::Faithful))
                .is_ok()
        );
        assert!(
            extreme_scale(|r, t, i, l| planted_transformed(r, t, i, l, TransformedMistake::Faithful)).is_ok()
        );
        caught(
            transformed_cases(|r, t, i, l| {
                planted_transformed(r, t, i, l, TransformedMistake::ObjectSpacePoint)
            }),
            "the world ray",
        );
        caught(
            transformed_cases(|r, t, i, l| {
                planted_transformed(r, t, i, l, TransformedMistake::RecordDropped)
            }),
            "keep front_face, uv",
        );
        caught(
            transformed_cases(|r, t, i, l| planted_transformed(r, t, i, l, TransformedMistake::Renormalised)),
            "world units",
        );
        caught(
            transformed_cases(|r, t, i, l| {
                planted_transformed(r, t, i, l, TransformedMistake::NormalByMatrix)
            }),
            "world_from_object",
        );
        caught(
            extreme_scale(|r, t, i, l| planted_transformed(r, t, i, l, TransformedMistake::Renormalised)),
            "world units",
        );
        caught(
            extreme_scale(|r, t, i, l| planted_transformed(r, t, i, l, TransformedMistake::NormalByMatrix)),
            "(M⁻¹)ᵀ",
        );
    }
}
