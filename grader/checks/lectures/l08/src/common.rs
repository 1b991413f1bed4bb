//! What the checks of lecture 08's files share.

pub(super) use l01_transforms::Camera;
pub(super) use l04_quadrics_transforms::BruteForce;
pub(super) use l08_ray_tree::{TraceSettings, World};
pub(super) use raylab::stats::{Counter, RayStats};

pub(super) use crate::judge::{measured, student};

// The student's functions, each value taken through `judge::student` (the lecture is `judged`).
crate::rows::student_fns! { l08_ray_tree:
    fn trace(world: &World, ray: &Ray, depth: u32, weight: Float, settings: &TraceSettings) -> Color as TraceFn;
    fn render(world: &World, camera: &Camera, width: u32, height: u32, settings: &TraceSettings)
        -> (Image, RayStats) as RenderFn;
}
pub(super) use raylab::{Color, Float, Image, Ray, Scene, Vec3};

pub(super) use crate::check::{CheckResult, close, ensure, fail, v, vec3};
pub(super) use raylab_testing::scenes::{
    BACKGROUND, block_with_tile, directional, facing_mirrors, glass, matte, mirror_and_wall, plane, scene,
    sphere, three_balls, tile_in_glass,
};

pub(super) const EPS: Float = Float::EPSILON;

/// Colours by hand are sums of a few products of values at most 1: a handful of roundings,
/// taken in whatever order the student's code takes them. 64ε is far above that (a few ε)
/// and far below any mistake (the smallest one here changes a colour by 0.001).
pub(super) const COLOR_TOL: Float = 64.0 * EPS;

/// Reflected, refracted and shadow rays counted while tracing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Rays {
    pub(super) reflected: u64,
    pub(super) refracted: u64,
    pub(super) shadow: u64,
}

impl std::fmt::Display for Rays {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} mirror, {} refracted, {} shadow rays", self.reflected, self.refracted, self.shadow)
    }
}

pub(super) const fn rays(reflected: u64, refracted: u64, shadow: u64) -> Rays {
    Rays { reflected, refracted, shadow }
}

/// `trace` of one eye ray (depth 0, weight 1) through `s` with brute-force intersection,
/// and the rays it counted.
pub(super) fn traced(trace: TraceFn, s: &Scene, ray: &Ray, settings: &TraceSettings) -> (Color, Rays) {
    let objects = BruteForce::new(&s.objects);
    let world = World::new(s, &objects);
    let (color, stats) = measured(|| trace(&world, ray, 0, 1.0, settings));
    let counted = rays(
        stats.get(Counter::ReflectionRays),
        stats.get(Counter::RefractionRays),
        stats.get(Counter::ShadowRays),
    );
    (color, counted)
}

/// Never with a NaN in either (see `check::near3`).
pub(super) fn near(a: Color, b: Color, tolerance: Float) -> bool {
    crate::check::near3(a, b, tolerance)
}

pub(super) fn same_color(
    case: &str,
    got: Color,
    expected: Color,
    tolerance: Float,
    cause: &str,
) -> Result<(), crate::check::Failure> {
    ensure(
        near(got, expected, tolerance),
        case,
        format!("{} (± {tolerance:.1e})", vec3(expected)),
        vec3(got),
        cause,
    )
}

/// A traced colour and its rays against the expected ones: the colour within
/// [`COLOR_TOL`] per channel, the rays exactly.
pub(super) fn same_tree(
    case: &str,
    (color, counted): (Color, Rays),
    expected: Color,
    expected_rays: Rays,
    cause: &str,
) -> Result<(), crate::check::Failure> {
    ensure(
        counted == expected_rays && near(color, expected, COLOR_TOL),
        case,
        format!("{} (± {COLOR_TOL:.1e} each), {expected_rays}", vec3(expected)),
        format!("{}, {counted}", vec3(color)),
        cause,
    )
}
