//! What the checks of lecture 10's files share.

// Widening `Float` to f64 for exact comparisons is a cast in f32 builds and none in f64 ones.
#![allow(clippy::unnecessary_cast)]

pub(super) use std::collections::HashSet;

pub(super) use l01_transforms::Camera;
pub(super) use l04_quadrics_transforms::BruteForce;
pub(super) use l08_ray_tree::{TraceSettings, World};
pub(super) use l10_textures_sampling::{
    Filter, Pattern, bilinear, checker, checker_3d, filter_weight, plane_uv, render_supersampled,
    sample_offsets, sphere_uv, triangle_uv,
};
pub(super) use raylab::math::consts::{PI, TAU};
pub(super) use raylab::random::Rng;
pub(super) use raylab::stats::{Counter, RayStats};
pub(super) use raylab::{Color, Float, Image, Scene, Vec2, Vec3};

pub(super) use crate::check::{CheckResult, Failure, ensure, fail, num, vec3};

pub(super) type SphereUvFn = fn(Vec3) -> Vec2;
pub(super) type PlaneUvFn = fn(Vec3, Vec3, Vec3, Vec3) -> Vec2;
pub(super) type TriangleUvFn = fn(&[Vec2; 3], Float, Float) -> Vec2;
pub(super) type CheckerFn = fn(Vec2, Float, Color, Color) -> Color;
pub(super) type Checker3dFn = fn(Vec3, Float, Color, Color) -> Color;
pub(super) type BilinearFn = fn(&Image, Vec2) -> Color;
pub(super) type FilterFn = fn(Filter, Vec2) -> Float;
pub(super) type SamplesFn = fn(Pattern, u32, &mut Rng) -> Vec<Vec2>;
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

pub(super) fn near2(a: Vec2, b: Vec2, tolerance: Float) -> bool {
    (a - b).abs().max_element() <= tolerance
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
