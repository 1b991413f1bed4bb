//! The checks of `orthographic.rs`: OrthographicCamera::generate_ray.

use super::common::*;
use super::perspective::along_x;

pub(super) fn orthographic_cases(generate_ray: OrthographicFn) -> CheckResult {
    let cameras = [
        ("at the origin looking down −z, window 2 tall", Mat4::IDENTITY, 2.0),
        ("at (1, 2, 3) looking along +x (u = z, v = y, w = −x), window 4 tall", along_x(), 4.0),
    ];
    for (where_, world_from_camera, height) in cameras {
        let aspect: Float = 1.5;
        let cam = OrthographicCamera { world_from_camera, height, aspect };
        let view = apply(&world_from_camera, -Vec3::Z, 0.0);
        for (sx, sy) in [(0.0, 0.0), (1.0, 1.0), (-1.0, -1.0), (0.5, -0.25)] {
            let case = format!("orthographic camera {where_}, aspect 1.5, screen point ({sx}, {sy})");
            let got = generate_ray(&cam, sx, sy);
            // o = (sx·aspect·h/2, sy·h/2, 0) in camera space, as a point; d = −w. Dyadic: exact
            // apart from the products, 8ε·(size ≤ 6).
            let point = |o: Vec3| apply(&world_from_camera, o, 1.0);
            let expected = point(Vec3::new(sx * aspect * height / 2.0, sy * height / 2.0, 0.0));
            let cause = diagnose(
                got.origin,
                &[
                    (
                        point(Vec3::new(sx * aspect * height, sy * height, 0.0)),
                        "height is the full window: the origin is (sx·aspect·h/2, sy·h/2, 0)",
                    ),
                    (
                        point(Vec3::new(sx * height / 2.0, sy * height / 2.0, 0.0)),
                        "the window is aspect·h wide: multiply sx by the aspect",
                    ),
                    (
                        apply(
                            &world_from_camera,
                            Vec3::new(sx * aspect * height / 2.0, sy * height / 2.0, 0.0),
                            0.0,
                        ),
                        "the origin is a point: take it to the world with w = 1 (transform_point) so it \
                            moves with the eye",
                    ),
                ],
                TOL * 8.0,
                "an orthographic ray starts on the window (sx·aspect·h/2, sy·h/2, 0) in camera space, \
                    not at the eye",
            );
            close3(&case, got.origin, expected, TOL * 8.0, cause)?;
            let cause = diagnose(
                got.dir,
                &[
                    (-view, "the camera looks down −z: d = (0, 0, −1) in camera space"),
                    (-Vec3::Z, "take the direction to the world with world_from_camera"),
                ],
                TOL,
                "every orthographic ray has the view direction, unit length",
            );
            close3(&case, got.dir, view, TOL, cause)?;
        }
    }
    Ok("8 rays of two cameras".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l01_transforms::OrthographicCamera;
    use raylab::{Float, Ray, Vec3};

    /// An orthographic ray from the camera-space origin `o` taken with w = `w`.
    fn ortho_ray(c: &OrthographicCamera, o: Vec3, w: Float) -> Ray {
        let m = c.world_from_camera;
        Ray::new((m * o.extend(w)).truncate(), (m * Vec3::NEG_Z.extend(0.0)).truncate().normalize())
    }

    #[test]
    fn orthographic_mistakes() {
        caught(
            orthographic_cases(|c, sx, sy| {
                ortho_ray(c, Vec3::new(sx * c.aspect * c.height, sy * c.height, 0.0), 1.0)
            }),
            "full window",
        );
        caught(
            orthographic_cases(|c, sx, sy| {
                ortho_ray(c, Vec3::new(sx * c.aspect * c.height / 2.0, sy * c.height / 2.0, 0.0), 0.0)
            }),
            "w = 1",
        );
        caught(
            orthographic_cases(|c, sx, sy| {
                let m = c.world_from_camera;
                let o = Vec3::new(sx * c.aspect * c.height / 2.0, sy * c.height / 2.0, 0.0);
                Ray::new((m * o.extend(1.0)).truncate(), Vec3::NEG_Z)
            }),
            "take the direction to the world",
        );
    }
}
