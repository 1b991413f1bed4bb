//! What the checks of lecture 10's files share.

pub(super) use std::collections::HashSet;

pub(super) use l01_transforms::Camera;
pub(super) use l04_quadrics_transforms::BruteForce;
pub(super) use l08_ray_tree::{TraceSettings, World};
pub(super) use l10_textures_sampling::{Filter, Pattern, render_supersampled};
pub(super) use raylab::random::Rng;
pub(super) use raylab::stats::{Counter, RayStats};
pub(super) use raylab::{Color, Float, Image, Scene, Vec2, Vec3};

pub(super) use crate::check::{CheckResult, Failure, ensure, fail, lazy, num, vec3};

// The student's functions, each value taken through `judge::student` (the lecture is `judged`).
crate::rows::student_fns! { l10_textures_sampling:
    fn sphere_uv(p: Vec3) -> Vec2 as SphereUvFn;
    fn plane_uv(p: Vec3, origin: Vec3, u_axis: Vec3, v_axis: Vec3) -> Vec2 as PlaneUvFn;
    fn triangle_uv(uvs: &[Vec2; 3], beta: Float, gamma: Float) -> Vec2 as TriangleUvFn;
    fn checker(uv: Vec2, scale: Float, a: Color, b: Color) -> Color as CheckerFn;
    fn checker_3d(p: Vec3, scale: Float, a: Color, b: Color) -> Color as Checker3dFn;
    fn bilinear(image: &Image, uv: Vec2) -> Color as BilinearFn;
    fn filter_weight(filter: Filter, offset: Vec2) -> Float as FilterFn;
    fn noise(p: Vec3) -> Float as NoiseFn;
    fn fractal_noise(p: Vec3, octaves: u32) -> Float as FractalFn;
    fn marble(p: Vec3, octaves: u32, frequency: Float, amplitude: Float) -> Float as VeinFn;
    fn wood(p: Vec3, octaves: u32, frequency: Float, amplitude: Float) -> Float;
    fn sample_offsets(pattern: Pattern, n: u32, rng: &mut Rng) -> Vec<Vec2> as SamplesFn
        => crate::judge::drawn(rng, |rng| l10_textures_sampling::sample_offsets(pattern, n, rng));
}
pub(super) type SupersampleFn =
    fn(&World, &Camera, u32, u32, &TraceSettings, u32, Pattern, Filter, u64) -> (Image, RayStats);

pub(super) const EPS: Float = Float::EPSILON;

pub(super) fn v3(x: Float, y: Float, z: Float) -> Vec3 {
    Vec3::new(x, y, z)
}

pub(super) fn uv(u: Float, v: Float) -> Vec2 {
    Vec2::new(u, v)
}

pub(super) fn show2(p: Vec2) -> String {
    format!("({}, {})", num(p.x), num(p.y))
}

/// Never with a NaN in either (see `check::near3`).
pub(super) fn near2(a: Vec2, b: Vec2, tolerance: Float) -> bool {
    let d = (a - b).abs();
    !d.is_nan() && d.max_element() <= tolerance
}

pub(super) fn same_uv(
    case: &str,
    got: Vec2,
    expected: Vec2,
    tolerance: Float,
    cause: &str,
) -> Result<(), Failure> {
    let shown = if tolerance == 0.0 {
        format!("{} exactly", show2(expected))
    } else {
        format!("{} (± {tolerance:.1e})", show2(expected))
    };
    ensure(near2(got, expected, tolerance), case, shown, show2(got), cause)
}
