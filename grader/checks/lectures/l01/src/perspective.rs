//! The checks of `perspective.rs`: PerspectiveCamera::generate_ray.

use super::common::*;

/// A camera at (1, 2, 3) looking along +x: u = z, v = y, w = −x (u × v = w).
pub(super) fn along_x() -> Mat4 {
    Mat4::from_cols(Vec4::Z, Vec4::Y, -Vec4::X, Vec4::new(1.0, 2.0, 3.0, 1.0))
}

pub(super) fn perspective_cases(generate_ray: PerspectiveFn) -> CheckResult {
    let fovy = radians(60.0);
    let cameras = [
        ("at the origin looking down −z", Mat4::IDENTITY),
        ("at (1, 2, 3) looking along +x (u = z, v = y, w = −x)", along_x()),
    ];
    for (where_, world_from_camera) in cameras {
        let cam = PerspectiveCamera { world_from_camera, fovy, aspect: 2.0 };
        let eye = world_from_camera.w_axis.truncate();
        for (sx, sy) in [(0.0, 0.0), (0.5, -0.25), (-1.0, 1.0), (1.0, -1.0)] {
            let case = format!("perspective camera {where_}, fovy 60°, aspect 2, screen point ({sx}, {sy})");
            let got = generate_ray(&cam, sx, sy);
            // d = (sx·aspect·t, sy·t, −1) with t = tan 30° = 1/√3, taken to the world, unit.
            let world = |d: Vec3| apply(&world_from_camera, d, 0.0);
            let camera_dir = |t: Float, aspect: Float| Vec3::new(sx * aspect * t, sy * t, -1.0);
            let t = 1.0 / (3.0 as Float).sqrt();
            let expected = world(camera_dir(t, 2.0)).normalize();
            close3(
                &case,
                got.origin,
                eye,
                TOL * 4.0,
                "every ray starts at the eye: world_from_camera·(0, 0, 0, 1)",
            )?;
            let cause = diagnose(
                got.dir,
                &[
                    (
                        world(camera_dir(fovy.tan(), 2.0)).normalize(),
                        "fovy is the full vertical angle: the image plane's half-height at distance 1 \
                            is tan(fovy/2)",
                    ),
                    (
                        world(camera_dir(radians(fovy / 2.0).tan(), 2.0)).normalize(),
                        "fovy is already in radians",
                    ),
                    (
                        world(camera_dir(t, 1.0)).normalize(),
                        "the image plane is aspect·tan(fovy/2) wide: multiply sx by the aspect",
                    ),
                    (
                        world(Vec3::new(sx * t, sy * 2.0 * t, -1.0)).normalize(),
                        "the aspect (width/height) multiplies sx, not sy",
                    ),
                    (
                        world(camera_dir(t, 0.5)).normalize(),
                        "aspect = width/height multiplies sx; do not divide by it",
                    ),
                    (
                        world(camera_dir(t, 2.0)),
                        "normalise the world direction: the camera's rays have unit directions",
                    ),
                    (
                        world(Vec3::new(sx * 2.0 * t, sy * t, 1.0)).normalize(),
                        "the camera looks down −z: the camera-space direction has z = −1",
                    ),
                    (
                        world(Vec3::new(sx * 2.0 * t, -sy * t, -1.0)).normalize(),
                        "sy goes up: the camera-space y is +sy·tan(fovy/2)",
                    ),
                    (
                        (world(camera_dir(t, 2.0)) + eye).normalize(),
                        "the direction is a vector: take it to the world with w = 0 (transform_vector), \
                            not as a point",
                    ),
                    (
                        camera_dir(t, 2.0).normalize(),
                        "take the direction to the world with world_from_camera",
                    ),
                ],
                TOL * 4.0,
                "d = (sx·aspect·tan(fovy/2), sy·tan(fovy/2), −1), taken to the world as a vector, \
                    normalised",
            );
            close3(&case, got.dir, expected, TOL, cause)?;
        }
    }
    Ok("8 rays of two cameras".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l01_transforms::PerspectiveCamera;
    use raylab::{Float, Ray, Vec3};

    /// The reference perspective ray with the camera-space direction `d(sx, sy, t)`
    /// (t = tan(fovy/2)), optionally as a point or not normalised.
    fn perspective(cam: &PerspectiveCamera, d: Vec3, as_point: bool, unit: bool) -> Ray {
        let m = cam.world_from_camera;
        let dir = (m * d.extend(if as_point { 1.0 } else { 0.0 })).truncate();
        Ray::new(m.w_axis.truncate(), if unit { dir.normalize() } else { dir })
    }

    fn half(c: &PerspectiveCamera) -> Float {
        (0.5 * c.fovy).tan()
    }

    #[test]
    fn perspective_mistakes() {
        caught(
            perspective_cases(|c, sx, sy| {
                let t = c.fovy.tan();
                perspective(c, Vec3::new(sx * c.aspect * t, sy * t, -1.0), false, true)
            }),
            "full vertical angle",
        );
        caught(
            perspective_cases(|c, sx, sy| {
                perspective(c, Vec3::new(sx * half(c), sy * half(c), -1.0), false, true)
            }),
            "multiply sx",
        );
        caught(
            perspective_cases(|c, sx, sy| {
                perspective(c, Vec3::new(sx * c.aspect * half(c), sy * half(c), -1.0), true, true)
            }),
            "w = 0",
        );
        caught(
            perspective_cases(|c, sx, sy| {
                perspective(c, Vec3::new(sx * c.aspect * half(c), sy * half(c), -1.0), false, false)
            }),
            "normalise",
        );
    }
}
