//! What the checks of lecture 01's files share.

pub(super) use l01_transforms::{CameraError, OrthographicCamera, PerspectiveCamera};
pub(super) use raylab::math::consts::{FRAC_PI_2, TAU};
pub(super) use raylab::{Float, Mat4, Ray, Vec3, Vec4, radians};

pub(super) use crate::check::{CheckResult, Failure, close3, ensure, fail, near3, num, vec3};

// The student's functions, each value taken through `judge::student` (the lecture is `judged`).
crate::rows::student_fns! { l01_transforms:
    fn translate(t: Vec3) -> Mat4 as VecToMat;
    fn scale(s: Vec3) -> Mat4;
    fn rotate_x(angle: Float) -> Mat4 as AngleToMat;
    fn rotate_y(angle: Float) -> Mat4;
    fn rotate_z(angle: Float) -> Mat4, remote;
    fn transform_point(m: &Mat4, p: Vec3) -> Vec3 as ApplyFn;
    fn transform_vector(m: &Mat4, v: Vec3) -> Vec3, remote;
    fn rotate_axis(axis: Vec3, angle: Float) -> Mat4 as AxisAngleFn;
    fn frame(origin: Vec3, i: Vec3, j: Vec3, k: Vec3) -> Mat4 as FrameFn;
    fn is_basis(i: Vec3, j: Vec3, k: Vec3) -> bool as BasisFn;
    fn screen_coords(x: u32, y: u32, width: u32, height: u32) -> (Float, Float) as ScreenFn;
    fn look_at(eye: Vec3, at: Vec3, up: Vec3) -> Result<Mat4, CameraError> as LookAtFn
        => camera_result(|| l01_transforms::look_at(eye, at, up));
    fn perspective_ray(camera: &PerspectiveCamera, sx: Float, sy: Float) -> Ray as PerspectiveFn
        = camera.generate_ray(sx, sy);
    fn orthographic_ray(camera: &OrthographicCamera, sx: Float, sy: Float) -> Ray as OrthographicFn
        = camera.generate_ray(sx, sy);
}

/// A camera's result of the student's code, through `judge::student` (its error as the variant's
/// index: the lecture's type is not the kit's).
#[track_caller]
fn camera_result(f: impl FnOnce() -> Result<Mat4, CameraError>) -> Result<Mat4, CameraError> {
    const ERRORS: [CameraError; 3] =
        [CameraError::EyeAtTarget, CameraError::UpParallelToView, CameraError::NotFinite];
    let got = crate::judge::student(|| {
        f().map_err(|e| match e {
            CameraError::EyeAtTarget => 0u8,
            CameraError::UpParallelToView => 1,
            CameraError::NotFinite => 2,
        })
    });
    got.map_err(|e| ERRORS[usize::from(e.min(2))])
}

/// Entries of unit-sized matrices and vectors: sin, cos, a product and a
/// sum round a few times, each by ε/2 of a number ≤ 1; 8ε holds them
/// (1e-6 in f32).
pub(super) const TOL: Float = 8.0 * Float::EPSILON;

/// The course's bound on a look-at basis (issue 5): orthonormal within 1e-6.
/// f32 rounding alone leaves a few ε ≈ 5e-7, so it must be no looser in f32;
/// in f64, 8ε keeps the check as strict relative to the precision.
pub(super) const BASIS_TOL: Float = if Float::EPSILON > 1e-10 { 1e-6 } else { 8.0 * Float::EPSILON };

pub(super) const WRONG_WAY: &str = "the rotation turns the wrong way (you built its transpose, the inverse): \
    right-handed, a quarter turn takes the next axis to the one after (about z: +x to +y), so −sin θ \
    sits in the column of the second axis";

/// A matrix row by row, for a student.
pub(super) fn rows(m: &Mat4) -> String {
    let row = |i: usize| {
        let r = m.row(i);
        format!("[{}, {}, {}, {}]", num(r.x), num(r.y), num(r.z), num(r.w))
    };
    format!("rows {} {} {} {}", row(0), row(1), row(2), row(3))
}

/// The largest entry of |a − b| (NaN when either has a NaN).
pub(super) fn distance(a: &Mat4, b: &Mat4) -> Float {
    (*a - *b)
        .to_cols_array()
        .iter()
        // A NaN anywhere stays (f32::max would drop it at the next number).
        .fold(0.0, |m: Float, e| if m.is_nan() || e.is_nan() { Float::NAN } else { m.max(e.abs()) })
}

pub(super) fn near(a: &Mat4, b: &Mat4, tol: Float) -> bool {
    distance(a, b) <= tol
}

/// Fails unless `got` is `expected` within `tol` per entry; a transposed
/// answer gets `transposed` as its cause.
pub(super) fn same_matrix(
    case: &str,
    got: &Mat4,
    expected: &Mat4,
    tol: Float,
    cause: &str,
    transposed: &str,
) -> Result<(), Failure> {
    if near(got, expected, tol) {
        return Ok(());
    }
    let cause = if near(got, &expected.transpose(), tol) { transposed } else { cause };
    Err(fail(case, format!("{} (± {tol:.1e} each)", rows(expected)), rows(got), cause))
}

/// The first of `candidates` (a wrong answer and the mistake that gives it)
/// that `got` matches, else `default`.
pub(super) fn diagnose<'a>(
    got: Vec3,
    candidates: &[(Vec3, &'a str)],
    tol: Float,
    default: &'a str,
) -> &'a str {
    candidates.iter().find(|(v, _)| (got - *v).abs().max_element() <= tol).map_or(default, |(_, c)| c)
}

/// m applied to (v, w) with glam's product: the check's own arithmetic.
pub(super) fn apply(m: &Mat4, v: Vec3, w: Float) -> Vec3 {
    (*m * v.extend(w)).truncate()
}

pub(super) fn axis_name(axis: usize) -> &'static str {
    ["x", "y", "z"][axis]
}

pub(super) fn unit(axis: usize) -> Vec3 {
    let mut v = Vec3::ZERO;
    v[axis] = 1.0;
    v
}
