//! Lecture 01, transforms: matrices built column by column, points and
//! vectors, frames and the test for a basis, look-at, screen coordinates and
//! the two cameras.

use crate::check::Meta;

/// The cameras apply `world_from_camera` through the lecture's own helpers.
const CAMERA_NEEDS: &[&str] = &["01/transform_point", "01/transform_vector"];

declare_checks! {
    "l01";
    Meta::unit("translate", "translate(t): the origin goes to t (the last column), the axes stay")
        => translate_cases(translate),
    Meta::unit("scale", "scale(s) is diag(sₓ, s_y, s_z, 1): the origin stays, w stays 1")
        => scale_cases(scale),
    Meta::unit("rotate_x", "right-handed turns about x in radians: a quarter turn takes +y to +z")
        => rotation_cases(0, rotate_x),
    Meta::unit("rotate_y", "right-handed turns about y in radians: a quarter turn takes +z to +x")
        => rotation_cases(1, rotate_y),
    Meta::unit("rotate_z", "right-handed turns about z in radians: a quarter turn takes +x to +y")
        => rotation_cases(2, rotate_z),
    Meta::unit(
        "rotate_axis",
        "Rodrigues' formula: fixes its axis, orthonormal, right-handed, the coordinate axes, any axis length",
    ) => rotate_axis_cases(rotate_axis),
    Meta::unit("transform_point", "m·(p, 1): the translation applies, and w' ≠ 1 divides")
        => transform_point_cases(transform_point),
    Meta::unit("transform_vector", "m·(v, 0): the linear part only, no translation")
        => transform_vector_cases(transform_vector),
    Meta::unit("frame", "world_from_frame has the columns i, j, k and the origin") => frame_cases(frame),
    Meta::unit(
        "is_basis",
        "independent, dependent and nearly coplanar triples, judged by a relative \
        threshold",
    ) => is_basis_cases(is_basis),
    Meta::extreme(
        "is_basis",
        "any-units",
        "axes whose length product overflows or underflows: the verdict must not depend on units",
    ) => is_basis_any_units(is_basis),
    Meta::unit("look_at", "the columns u, v, w, eye for views along the axes and a generic one; eye = at")
        => look_at_cases(look_at),
    Meta::extreme(
        "look_at",
        "degenerate-up",
        "up parallel to the view: an error, never NaN; up nearly parallel, views near −z, tiny and huge \
            distances: an error or an orthonormal basis within 1e-6",
    ) => look_at_degenerate(look_at),
    Meta::unit("screen_coords", "pixel centres: corners, the centre pixel, a one-pixel image, large images")
        => screen_cases(screen_coords),
    Meta::unit(
        "PerspectiveCamera::generate_ray",
        "directions (sx·aspect·tan(fovy/2), sy·tan(fovy/2), −1) taken to the world and normalised, from the \
            eye",
    )
    .needs(CAMERA_NEEDS) => perspective_cases(PerspectiveCamera::generate_ray),
    Meta::unit(
        "OrthographicCamera::generate_ray",
        "origins (sx·aspect·h/2, sy·h/2, 0) taken to the world as points, one direction −w for every ray",
    )
    .needs(CAMERA_NEEDS) => orthographic_cases(OrthographicCamera::generate_ray),
}

#[cfg(feature = "l01")]
#[allow(clippy::result_large_err)] // Failure is check.rs's report, returned by value as in every lecture
#[allow(clippy::unnecessary_cast)] // widening Float to f64 for references is the identity in an f64 build
mod code {
    pub(super) use l01_transforms::{
        CameraError, OrthographicCamera, PerspectiveCamera, frame, is_basis, look_at, rotate_axis, rotate_x,
        rotate_y, rotate_z, scale, screen_coords, transform_point, transform_vector, translate,
    };
    use raylab::math::consts::{FRAC_PI_2, TAU};
    use raylab::{Float, Mat4, Ray, Vec3, Vec4, radians};

    use crate::check::{CheckResult, Failure, close3, ensure, fail, num, vec3};

    pub(super) type VecToMat = fn(Vec3) -> Mat4;
    pub(super) type AngleToMat = fn(Float) -> Mat4;
    pub(super) type AxisAngleFn = fn(Vec3, Float) -> Mat4;
    pub(super) type ApplyFn = fn(&Mat4, Vec3) -> Vec3;
    pub(super) type FrameFn = fn(Vec3, Vec3, Vec3, Vec3) -> Mat4;
    pub(super) type BasisFn = fn(Vec3, Vec3, Vec3) -> bool;
    pub(super) type LookAtFn = fn(Vec3, Vec3, Vec3) -> Result<Mat4, CameraError>;
    pub(super) type ScreenFn = fn(u32, u32, u32, u32) -> (Float, Float);
    pub(super) type PerspectiveFn = fn(&PerspectiveCamera, Float, Float) -> Ray;
    pub(super) type OrthographicFn = fn(&OrthographicCamera, Float, Float) -> Ray;

    /// Entries of unit-sized matrices and vectors: sin, cos, a product and a
    /// sum round a few times, each by ε/2 of a number ≤ 1; 8ε holds them
    /// (1e-6 in f32).
    const TOL: Float = 8.0 * Float::EPSILON;

    /// The course's bound on a look-at basis (issue 5): orthonormal within 1e-6.
    /// f32 rounding alone leaves a few ε ≈ 5e-7, so it must be no looser in f32;
    /// in f64, 8ε keeps the check as strict relative to the precision.
    const BASIS_TOL: Float = if Float::EPSILON > 1e-10 { 1e-6 } else { 8.0 * Float::EPSILON };

    const WRONG_WAY: &str = "the rotation turns the wrong way (you built its transpose, the inverse): \
        right-handed, a quarter turn takes the next axis to the one after (about z: +x to +y), so −sin θ \
        sits in the column of the second axis";

    /// A matrix row by row, for a student.
    fn rows(m: &Mat4) -> String {
        let row = |i: usize| {
            let r = m.row(i);
            format!("[{}, {}, {}, {}]", num(r.x), num(r.y), num(r.z), num(r.w))
        };
        format!("rows {} {} {} {}", row(0), row(1), row(2), row(3))
    }

    /// The largest entry of |a − b| (NaN when either has a NaN).
    fn distance(a: &Mat4, b: &Mat4) -> Float {
        (*a - *b)
            .to_cols_array()
            .iter()
            .fold(0.0, |m: Float, e| if e.is_nan() { Float::NAN } else { m.max(e.abs()) })
    }

    fn near(a: &Mat4, b: &Mat4, tol: Float) -> bool {
        distance(a, b) <= tol
    }

    /// Fails unless `got` is `expected` within `tol` per entry; a transposed
    /// answer gets `transposed` as its cause.
    fn same_matrix(
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
    fn diagnose<'a>(got: Vec3, candidates: &[(Vec3, &'a str)], tol: Float, default: &'a str) -> &'a str {
        candidates.iter().find(|(v, _)| (got - *v).abs().max_element() <= tol).map_or(default, |(_, c)| c)
    }

    fn near3(a: Vec3, b: Vec3, tol: Float) -> bool {
        (a - b).abs().max_element() <= tol
    }

    /// m applied to (v, w) with glam's product: the check's own arithmetic.
    fn apply(m: &Mat4, v: Vec3, w: Float) -> Vec3 {
        (*m * v.extend(w)).truncate()
    }

    fn axis_name(axis: usize) -> &'static str {
        ["x", "y", "z"][axis]
    }

    fn unit(axis: usize) -> Vec3 {
        let mut v = Vec3::ZERO;
        v[axis] = 1.0;
        v
    }

    // ---- translate, scale, rotations ------------------------------------

    pub(super) fn translate_cases(translate: VecToMat) -> CheckResult {
        // Columns x, y, z unchanged; the last column (1, −2, 3, 1): where the origin goes.
        let t = Vec3::new(1.0, -2.0, 3.0);
        let expected = Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::Z, Vec4::new(1.0, -2.0, 3.0, 1.0));
        let got = translate(t);
        let case = "translate((1, −2, 3))";
        let cause = if near(&got, &Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::Z, t.extend(0.0)), 0.0) {
            "the last column is (t, 1): with w = 0 there a point would lose its w = 1"
        } else if near(&got, &Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::Z, (-t).extend(1.0)), 0.0) {
            "translate(t) moves points by +t: the last column is (t, 1), not (−t, 1)"
        } else {
            "the columns are the images of x, y, z (unchanged) and of the origin (t, 1)"
        };
        // Small integers: exact.
        same_matrix(
            case,
            &got,
            &expected,
            0.0,
            cause,
            "the translation belongs in the last column (Mat4::from_cols(X, Y, Z, (t, 1))), not the last row",
        )?;
        Ok("translate((1, −2, 3)) exact".into())
    }

    pub(super) fn scale_cases(scale: VecToMat) -> CheckResult {
        // diag(2, 3, −1, 1): (1, 1, 1) ↦ (2, 3, −1), the origin stays.
        let expected = Mat4::from_diagonal(Vec4::new(2.0, 3.0, -1.0, 1.0));
        let got = scale(Vec3::new(2.0, 3.0, -1.0));
        let cause = if got.w_axis != Vec4::W {
            "the last column stays (0, 0, 0, 1): scaling keeps the origin and w = 1"
        } else {
            "scale(s) = diag(sₓ, s_y, s_z, 1): each axis column is multiplied by its factor"
        };
        same_matrix("scale((2, 3, −1))", &got, &expected, 0.0, cause, cause)?;
        Ok("scale((2, 3, −1)) exact".into())
    }

    /// The right-handed rotation by θ about coordinate axis `axis`, from the
    /// images of the other two axes i → j (cyclic order x → y → z → x):
    /// i ↦ c·i + s·j and j ↦ −s·i + c·j. About z: x ↦ (c, s, 0), y ↦ (−s, c, 0).
    fn axis_rotation(axis: usize, angle: Float) -> Mat4 {
        let (s, c) = angle.sin_cos();
        let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
        let mut cols = [Vec4::X, Vec4::Y, Vec4::Z, Vec4::W];
        cols[i][i] = c;
        cols[i][j] = s;
        cols[j][i] = -s;
        cols[j][j] = c;
        Mat4::from_cols(cols[0], cols[1], cols[2], cols[3])
    }

    pub(super) fn rotation_cases(axis: usize, rotate: AngleToMat) -> CheckResult {
        let name = axis_name(axis);
        let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
        // A quarter turn takes the next axis to the one after it.
        let case = format!("rotate_{name}(π/2) applied to +{} (a vector)", axis_name(i));
        let got = apply(&rotate(FRAC_PI_2), unit(i), 0.0);
        let cause = diagnose(
            got,
            &[
                (-unit(j), WRONG_WAY),
                (
                    apply(&axis_rotation(axis, radians(FRAC_PI_2)), unit(i), 0.0),
                    "angles are in radians: π/2 is a quarter turn (do not convert from degrees)",
                ),
            ],
            1e-3,
            "a quarter turn about an axis takes the next axis to the one after it (cyclic x → y → z → x)",
        );
        close3(&case, got, unit(j), TOL, cause)?;
        // The axis itself stays, for generic angles; every entry by hand.
        for angle in [0.5, -2.0, 3.0] {
            let case = format!("rotate_{name}({angle})");
            let got = rotate(angle);
            let expected = axis_rotation(axis, angle);
            let cause = if near(&got, &axis_rotation(axis, radians(angle)), TOL) {
                "angles are in radians already: do not convert from degrees"
            } else if got.col(axis) != unit(axis).extend(0.0) {
                "the rotation axis is fixed: its column stays the unit axis"
            } else {
                "about z: x ↦ (cos θ, sin θ, 0), y ↦ (−sin θ, cos θ, 0), and cyclically for x and y"
            };
            same_matrix(&case, &got, &expected, TOL, cause, WRONG_WAY)?;
        }
        Ok("a quarter turn and 3 angles".into())
    }

    // ---- rotate_axis ----------------------------------------------------

    /// Rodrigues' rotation of vector `v` about the unit `k`, in f64:
    /// v cos θ + (k × v) sin θ + k (k·v)(1 − cos θ) — the vector form, not the matrix.
    fn rodrigues_f64(k: [f64; 3], angle: f64, v: [f64; 3]) -> [f64; 3] {
        let (s, c) = angle.sin_cos();
        let kxv = [k[1] * v[2] - k[2] * v[1], k[2] * v[0] - k[0] * v[2], k[0] * v[1] - k[1] * v[0]];
        let kv = k[0] * v[0] + k[1] * v[1] + k[2] * v[2];
        [0, 1, 2].map(|i| v[i] * c + kxv[i] * s + k[i] * kv * (1.0 - c))
    }

    /// The rotation matrix whose columns are the f64 Rodrigues images of x, y, z.
    fn rodrigues_matrix(axis: Vec3, angle: Float) -> Mat4 {
        let a = [axis.x as f64, axis.y as f64, axis.z as f64];
        let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        let k = a.map(|x| x / l);
        let col = |e: [f64; 3]| {
            let r = rodrigues_f64(k, angle as f64, e);
            Vec4::new(r[0] as Float, r[1] as Float, r[2] as Float, 0.0)
        };
        Mat4::from_cols(col([1.0, 0.0, 0.0]), col([0.0, 1.0, 0.0]), col([0.0, 0.0, 1.0]), Vec4::W)
    }

    pub(super) fn rotate_axis_cases(rotate_axis: AxisAngleFn) -> CheckResult {
        // 1. A generic unit axis is fixed: R·a = a (the slides' sign typo moves it).
        let a = Vec3::new(1.0, 2.0, 3.0).normalize();
        let r = rotate_axis(a, 0.7);
        close3(
            "rotate_axis((1, 2, 3)/√14, 0.7) applied to its own axis",
            apply(&r, a, 0.0),
            a,
            TOL,
            "R must fix its axis: the sin terms form the skew-symmetric s·[a]× (entry (i, j) is minus entry \
                (j, i)); the slides print some of those signs wrong",
        )?;
        // 2. Orthonormal: RᵀR = I.
        same_matrix(
            "RᵀR for rotate_axis((1, 2, 3)/√14, 0.7)",
            &(r.transpose() * r),
            &Mat4::IDENTITY,
            2.0 * TOL,
            "R = c·I + (1 − c)·a aᵀ + s·[a]× is orthonormal: check the cos and (1 − c) terms",
            "R = c·I + (1 − c)·a aᵀ + s·[a]× is orthonormal: check the cos and (1 − c) terms",
        )?;
        // 3. Right-handed: a quarter turn about +z takes +x to +y.
        let got = apply(&rotate_axis(Vec3::Z, FRAC_PI_2), Vec3::X, 0.0);
        let cause = diagnose(got, &[(-Vec3::Y, WRONG_WAY)], 1e-3, "rotate_axis(z, θ) must be rotate_z(θ)");
        close3("rotate_axis(+z, π/2) applied to +x", got, Vec3::Y, TOL, cause)?;
        // 4. Every entry against Rodrigues' vector formula in f64: the coordinate axes,
        //    the diagonal (a third of a turn cycles x → y → z), generic axes.
        let axes =
            [Vec3::X, Vec3::Y, Vec3::Z, Vec3::ONE.normalize(), a, Vec3::new(-0.3, 0.9, 0.1).normalize()];
        for axis in axes {
            for angle in [0.4, -1.1, TAU / 3.0, 2.9] {
                let case = format!("rotate_axis({}, {})", vec3(axis), num(angle));
                same_matrix(
                    &case,
                    &rotate_axis(axis, angle),
                    &rodrigues_matrix(axis, angle),
                    TOL,
                    "R = c·I + (1 − c)·a aᵀ + s·[a]×: column x is (c + (1−c)aₓ², (1−c)aₓa_y + s a_z, \
                        (1−c)aₓa_z − s a_y)",
                    WRONG_WAY,
                )?;
            }
        }
        // 5. Any length names the same rotation.
        for axis in [7.0 * Vec3::Z, Vec3::new(1e-3, 4e-3, -2e-3), Vec3::new(5.0, -5.0, 2.0)] {
            let case = format!("rotate_axis({}, 0.4): an axis that is not unit length", vec3(axis));
            same_matrix(
                &case,
                &rotate_axis(axis, 0.4),
                &rodrigues_matrix(axis, 0.4),
                TOL,
                "normalise the axis first: any length of axis names the same rotation",
                WRONG_WAY,
            )?;
        }
        Ok("axis fixed, orthonormal, right-handed, 27 matrices against Rodrigues in f64".into())
    }

    // ---- points and vectors ------------------------------------------------

    /// Scale by (2, 3, −1), then move by (1, −2, 3): columns by hand.
    fn scale_then_move() -> Mat4 {
        Mat4::from_cols(
            Vec4::new(2.0, 0.0, 0.0, 0.0),
            Vec4::new(0.0, 3.0, 0.0, 0.0),
            Vec4::new(0.0, 0.0, -1.0, 0.0),
            Vec4::new(1.0, -2.0, 3.0, 1.0),
        )
    }

    pub(super) fn transform_point_cases(transform_point: ApplyFn) -> CheckResult {
        // (1, 1, 1) ↦ (2, 3, −1) + (1, −2, 3) = (3, 1, 2): small integers, exact.
        let got = transform_point(&scale_then_move(), Vec3::ONE);
        let cause = diagnose(
            got,
            &[(
                Vec3::new(2.0, 3.0, -1.0),
                "a point has w = 1: extend it with 1.0 so the translation column applies",
            )],
            0.0,
            "m·(p, 1) = pₓ·col₀ + p_y·col₁ + p_z·col₂ + col₃",
        );
        close3(
            "scale (2, 3, −1) then translate (1, −2, 3), applied to the point (1, 1, 1)",
            got,
            Vec3::new(3.0, 1.0, 2.0),
            0.0,
            cause,
        )?;
        // A general affine matrix: the sum of its columns weighted by (p, 1).
        let m = Mat4::from_cols(
            Vec4::new(0.5, -1.25, 2.0, 0.0),
            Vec4::new(0.75, 0.5, -0.25, 0.0),
            Vec4::new(-1.5, 0.25, 1.0, 0.0),
            Vec4::new(4.0, 5.0, -6.0, 1.0),
        );
        let p = Vec3::new(2.0, -4.0, 0.5);
        // Dyadic entries, exact: x = 0.5·2 + 0.75·(−4) − 1.5·0.5 + 4 = 1.25,
        // y = −2.5 − 2 + 0.125 + 5 = 0.625, z = 4 + 1 + 0.5 − 6 = −0.5.
        close3(
            "an affine matrix with dyadic entries, applied to (2, −4, 0.5)",
            transform_point(&m, p),
            Vec3::new(1.25, 0.625, -0.5),
            0.0,
            "m·(p, 1) = pₓ·col₀ + p_y·col₁ + p_z·col₂ + col₃",
        )?;
        // A projective matrix (last row 0 0 0 2): w' = 2 divides, (2, 4, 6) ↦ (1, 2, 3).
        let mut half = Mat4::IDENTITY;
        half.w_axis.w = 2.0;
        let got = transform_point(&half, Vec3::new(2.0, 4.0, 6.0));
        let cause = diagnose(
            got,
            &[(Vec3::new(2.0, 4.0, 6.0), "divide by w' when it is not 1: a projective matrix gives w' ≠ 1")],
            0.0,
            "(x', y', z', w') = m·(p, 1), then (x', y', z')/w'",
        );
        close3(
            "the identity with w_axis.w = 2, applied to (2, 4, 6)",
            got,
            Vec3::new(1.0, 2.0, 3.0),
            0.0,
            cause,
        )?;
        // The perspective divide: w' = −z maps (2, 4, −2) to (1, 2, −1).
        let mut perspective = Mat4::IDENTITY;
        perspective.z_axis.w = -1.0;
        perspective.w_axis.w = 0.0;
        let got = transform_point(&perspective, Vec3::new(2.0, 4.0, -2.0));
        close3(
            "a perspective matrix (w' = −z), applied to (2, 4, −2)",
            got,
            Vec3::new(1.0, 2.0, -1.0),
            0.0,
            "divide by w' = −z = 2",
        )?;
        Ok("4 points, exact".into())
    }

    pub(super) fn transform_vector_cases(transform_vector: ApplyFn) -> CheckResult {
        // (1, 1, 1) ↦ (2, 3, −1): the translation (1, −2, 3) does not apply.
        let got = transform_vector(&scale_then_move(), Vec3::ONE);
        let cause = diagnose(
            got,
            &[(Vec3::new(3.0, 1.0, 2.0), "a vector has w = 0: the translation column must not move it")],
            0.0,
            "m·(v, 0) = vₓ·col₀ + v_y·col₁ + v_z·col₂",
        );
        close3(
            "scale (2, 3, −1) then translate (1, −2, 3), applied to the vector (1, 1, 1)",
            got,
            Vec3::new(2.0, 3.0, -1.0),
            0.0,
            cause,
        )?;
        // (1, −2, 4) ↦ (2, −6, −4).
        let got = transform_vector(&scale_then_move(), Vec3::new(1.0, -2.0, 4.0));
        close3(
            "the same matrix, applied to the vector (1, −2, 4)",
            got,
            Vec3::new(2.0, -6.0, -4.0),
            0.0,
            "m·(v, 0) = vₓ·col₀ + v_y·col₁ + v_z·col₂",
        )?;
        Ok("2 vectors, exact".into())
    }

    // ---- frames and bases -------------------------------------------------

    pub(super) fn frame_cases(frame: FrameFn) -> CheckResult {
        // A rotated frame: i = y, j = −x, k = z at (1, 2, 3); a skewed one at (5, −1, 2).
        let frames = [
            (Vec3::new(1.0, 2.0, 3.0), Vec3::Y, -Vec3::X, Vec3::Z),
            (Vec3::new(5.0, -1.0, 2.0), Vec3::new(2.0, 0.0, 0.0), Vec3::new(1.0, 1.0, 0.0), Vec3::ONE),
        ];
        for (o, i, j, k) in frames {
            let case = format!("frame(origin {}, i {}, j {}, k {})", vec3(o), vec3(i), vec3(j), vec3(k));
            let got = frame(o, i, j, k);
            let expected = Mat4::from_cols(i.extend(0.0), j.extend(0.0), k.extend(0.0), o.extend(1.0));
            let cause = if near(&got, &expected.inverse(), 1e-4) {
                "frame returns world_from_frame, whose columns are the axes and the origin themselves (you \
                    built its inverse, frame_from_world)"
            } else if got.w_axis.w != 1.0 {
                "the origin column is (origin, 1): a point, w = 1"
            } else {
                "the columns are i, j, k (w = 0) and the origin (w = 1): frame coordinates (a, b, c) name \
                    origin + a·i + b·j + c·k"
            };
            same_matrix(
                &case,
                &got,
                &expected,
                0.0,
                cause,
                "i, j, k and the origin are the columns (Mat4::from_cols), not the rows",
            )?;
        }
        Ok("2 frames, exact".into())
    }

    pub(super) fn is_basis_cases(is_basis: BasisFn) -> CheckResult {
        const RELATIVE: &str = "the threshold is relative: compare |det| = |i·(j × k)| with \
            1e-6·|i|·|j|·|k|, not with a fixed number";
        let v = Vec3::new;
        let nan = Float::NAN;
        let cases: [(Vec3, Vec3, Vec3, bool, &str); 13] = [
            (Vec3::X, Vec3::Y, Vec3::Z, true, "the coordinate axes are a basis"),
            (
                Vec3::Y,
                Vec3::X,
                Vec3::Z,
                true,
                "a left-handed triple (det = −1) is a basis too: compare |det|",
            ),
            (
                Vec3::X,
                v(1.0, 1.0, 0.0),
                Vec3::ONE,
                true,
                "a skewed triple with det = 1 (triangular) is a basis",
            ),
            // (7, 8, 9) = 2·(4, 5, 6) − (1, 2, 3): det = 0 exactly.
            (
                v(1.0, 2.0, 3.0),
                v(4.0, 5.0, 6.0),
                v(7.0, 8.0, 9.0),
                false,
                "coplanar vectors (det = 0) are no basis",
            ),
            (Vec3::X, Vec3::Y, Vec3::X, false, "two equal vectors are no basis"),
            (Vec3::X, Vec3::Y, -Vec3::Y, false, "two opposite vectors are no basis"),
            (Vec3::X, Vec3::ZERO, Vec3::Z, false, "a zero vector is never part of a basis"),
            // det = 1e-7 < 1e-6·|i||j||k| ≈ 1e-6: dependent by the course's threshold.
            (
                Vec3::X,
                Vec3::Y,
                v(1.0, 0.0, 1e-7),
                false,
                "nearly coplanar (|det| = 1e-7 < 1e-6·|i||j||k|): test |det| against the relative \
                    threshold, not det ≠ 0",
            ),
            // det = 1e-5 > 1e-6.
            (Vec3::X, Vec3::Y, v(1.0, 0.0, 1e-5), true, "|det| = 1e-5 > 1e-6·|i||j||k|: a basis"),
            // det = 1e-9 and |i||j||k| = 1e-9: a basis in millimetres is a basis.
            (1e-3 * Vec3::X, 1e-3 * Vec3::Y, 1e-3 * Vec3::Z, true, RELATIVE),
            // det = 10, |i||j||k| ≈ 1e8: still nearly coplanar at this scale.
            (1e4 * Vec3::X, Vec3::Y, v(1e4, 0.0, 1e-3), false, RELATIVE),
            (
                v(nan, 0.0, 0.0),
                Vec3::Y,
                Vec3::Z,
                false,
                "a NaN component is never part of a basis: check is_finite",
            ),
            (
                Vec3::X,
                v(0.0, Float::INFINITY, 0.0),
                Vec3::Z,
                false,
                "an infinite component is never part of a basis: check is_finite",
            ),
        ];
        for (i, j, k, expected, cause) in cases {
            let got = is_basis(i, j, k);
            ensure(
                got == expected,
                format!("is_basis({}, {}, {})", vec3(i), vec3(j), vec3(k)),
                expected,
                got,
                cause,
            )?;
        }
        Ok("13 triples".into())
    }

    /// Lengths whose product of three overflows (`big`) or underflows to zero
    /// (`tiny`) in the precision under test: MAX^(1/3)·10 and MIN_POSITIVE^(1/3)·1e-6
    /// (f32: 7e13 and 2e-19; f64: 6e103 and 3e-109).
    fn extreme_lengths() -> (Float, Float) {
        (Float::MAX.cbrt() * 10.0, Float::MIN_POSITIVE.cbrt() * 1e-6)
    }

    pub(super) fn is_basis_any_units(is_basis: BasisFn) -> CheckResult {
        let (big, tiny) = extreme_lengths();
        let cause = "|i|·|j|·|k| (and the determinant) overflow or underflow at these lengths: rescale each \
            vector by its largest component first (the test does not care about lengths)";
        let v = Vec3::new;
        let cases = [
            (big * Vec3::X, big * Vec3::Y, big * Vec3::Z, true),
            (tiny * Vec3::X, tiny * Vec3::Y, tiny * Vec3::Z, true),
            (tiny * Vec3::X, big * Vec3::Y, big * Vec3::Z, true),
            (big * v(1.0, 1.0, 0.0), big * Vec3::Y, tiny * Vec3::Z, true),
            (big * v(1.0, 2.0, 3.0), big * v(4.0, 5.0, 6.0), big * v(7.0, 8.0, 9.0), false),
            (tiny * Vec3::X, tiny * Vec3::Y, tiny * v(1.0, 0.0, 1e-7), false),
        ];
        for (i, j, k, expected) in cases {
            let got = is_basis(i, j, k);
            let case = format!("is_basis({}, {}, {})", vec3(i), vec3(j), vec3(k));
            ensure(got == expected, case, expected, got, cause)?;
        }
        Ok(format!("6 triples at lengths {} and {}", num(big), num(tiny)))
    }

    // ---- look-at -------------------------------------------------------------

    fn f64s(v: Vec3) -> [f64; 3] {
        [v.x as f64, v.y as f64, v.z as f64]
    }

    fn cross64(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    }

    /// `a` normalised in f64, rescaled first so that tiny and huge vectors neither underflow nor overflow.
    fn unit64(a: [f64; 3]) -> Vec3 {
        let scale = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        let a = a.map(|x| x / scale);
        let l = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
        Vec3::new((a[0] / l) as Float, (a[1] / l) as Float, (a[2] / l) as Float)
    }

    /// The look-at basis (u, v, w) by its definition, in f64.
    fn basis_f64(eye: Vec3, at: Vec3, up: Vec3) -> (Vec3, Vec3, Vec3) {
        let w = unit64(f64s(eye - at));
        let u = unit64(cross64(f64s(up), f64s(w)));
        let v = unit64(cross64(f64s(w), f64s(u)));
        (u, v, w)
    }

    fn columns(m: &Mat4) -> (Vec3, Vec3, Vec3, Vec4) {
        (m.x_axis.truncate(), m.y_axis.truncate(), m.z_axis.truncate(), m.w_axis)
    }

    fn show_look_at(r: &Result<Mat4, CameraError>) -> String {
        match r {
            Ok(m) => {
                let (u, v, w, e) = columns(m);
                format!("Ok: u {}, v {}, w {}, last column {}", vec3(u), vec3(v), vec3(w), vec3(e.truncate()))
            }
            Err(e) => format!("Err({e:?})"),
        }
    }

    /// One look-at camera against its f64 basis, each likely mistake with its cause.
    fn look_at_case(look_at: LookAtFn, eye: Vec3, at: Vec3, up: Vec3) -> Result<(), Failure> {
        let case = format!("look_at(eye {}, at {}, up {})", vec3(eye), vec3(at), vec3(up));
        let (u, v, w) = basis_f64(eye, at, up);
        let expected = Mat4::from_cols(u.extend(0.0), v.extend(0.0), w.extend(0.0), eye.extend(1.0));
        let result = look_at(eye, at, up);
        let Ok(got) = result else {
            return Err(fail(
                case,
                rows(&expected),
                show_look_at(&result),
                "this camera is well defined: up is across the view",
            ));
        };
        // Positions of size ≤ 5: 8ε relative on them; unit vectors 8ε.
        let tol = TOL * 5.0;
        if near(&got, &expected, tol) {
            return Ok(());
        }
        let (gu, gv, gw, ge) = columns(&got);
        let cause = if near(&got.transpose(), &expected, tol) {
            "u, v, w and the eye are the columns of world_from_camera (Mat4::from_cols), not its rows"
        } else if near3(gw, -w, TOL) {
            "w points backwards, from at to the eye: w = (eye − at)/|eye − at| (the camera looks down −w)"
        } else if !near3(gw, w, TOL) {
            "w = (eye − at)/|eye − at|: the unit vector from at to the eye"
        } else if near3(gu, -u, TOL) {
            "u = up × w, in this order (w × up points left, not right)"
        } else if (gu.length() - 1.0).abs() > TOL {
            "normalise u = (up × w)/|up × w|: up need not be unit length or perpendicular to the view"
        } else if !near3(gu, u, TOL) {
            "u = (up × w)/|up × w|"
        } else if near3(gv, up.normalize(), TOL) && !near3(gv, v, TOL) {
            "the true up is v = w × u, not the up vector you were given"
        } else if !near3(gv, v, TOL) {
            "v = w × u (the true up, unit and perpendicular to both)"
        } else if ge.w != 1.0 {
            "the last column is (eye, 1): a point"
        } else {
            "the last column is the eye: camera space has the eye at its origin"
        };
        Err(fail(case, format!("{} (± {tol:.1e} each)", rows(&expected)), rows(&got), cause))
    }

    pub(super) fn look_at_cases(look_at: LookAtFn) -> CheckResult {
        let v = Vec3::new;
        // Eye on +z looking at the origin, up +y: u = x, v = y, w = z, so a translation by (0, 0, 5).
        look_at_case(look_at, v(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y)?;
        // Along +x with up y: w = −x, u = y × −x = z, v = −x × z = y.
        look_at_case(look_at, Vec3::ZERO, Vec3::X, Vec3::Y)?;
        // Straight down with up −z: w = y, u = −z × y = x, v = y × x = −z.
        look_at_case(look_at, v(0.0, 5.0, 0.0), Vec3::ZERO, -Vec3::Z)?;
        // Generic: up neither unit nor perpendicular to the view.
        look_at_case(look_at, v(1.0, 2.0, 3.0), v(-2.0, 0.0, -1.0), v(0.0, 3.0, 0.5))?;
        look_at_case(look_at, v(-3.0, 1.0, 2.0), v(0.5, -1.0, 0.25), v(0.2, -1.0, 0.1))?;
        // eye = at: no view direction.
        let p = v(1.0, 2.0, 3.0);
        let got = look_at(p, p, Vec3::Y);
        ensure(
            got == Err(CameraError::EyeAtTarget),
            "look_at(eye = at = (1, 2, 3), up +y)",
            "Err(EyeAtTarget)",
            show_look_at(&got),
            "eye = at has no view direction: return CameraError::EyeAtTarget before normalising eye − at",
        )?;
        Ok("5 cameras and eye = at".into())
    }

    /// Fails unless `got` is an error or a right-handed orthonormal basis with
    /// the right w, each within [`BASIS_TOL`], and a finite matrix.
    fn error_or_basis(
        case: &str,
        got: &Result<Mat4, CameraError>,
        eye: Vec3,
        at: Vec3,
        cause: &str,
    ) -> Result<(), Failure> {
        let Ok(m) = got else { return Ok(()) };
        let (u, v, w, e) = columns(m);
        let w_exact = unit64(f64s(eye - at));
        let worst = [
            (u.length() - 1.0).abs(),
            (v.length() - 1.0).abs(),
            (w.length() - 1.0).abs(),
            u.dot(v).abs(),
            v.dot(w).abs(),
            w.dot(u).abs(),
            (u.cross(v) - w).abs().max_element(),
            (w - w_exact).abs().max_element(),
        ]
        .into_iter()
        .fold(0.0, |m: Float, x| if x.is_nan() { Float::NAN } else { m.max(x) });
        let ok = m.is_finite() && worst <= BASIS_TOL && e == eye.extend(1.0);
        ensure(
            ok,
            case,
            format!("an error, or u, v, w orthonormal with w = {} within {BASIS_TOL:.0e}", vec3(w_exact)),
            format!("{} (off by {worst:.1e})", show_look_at(got)),
            cause,
        )
    }

    pub(super) fn look_at_degenerate(look_at: LookAtFn) -> CheckResult {
        const PARALLEL: &str = "up × w is zero when up is parallel to the view: return \
            CameraError::UpParallelToView instead of normalising a zero vector (NaN)";
        const CANCEL: &str = "with up nearly parallel to the view, up × w cancels and loses digits: make u \
            perpendicular to w again (u − (u·w)w, normalised) or reject |up × w| ≤ 1e-6·|up|";
        let v = Vec3::new;
        // 1. Up exactly parallel to the view, either way, or zero: an error, never NaN.
        let (eye, at) = (v(1.0, 2.0, 3.0), v(4.0, -2.0, 3.0));
        let view = at - eye;
        for (eye, at, up) in [
            (eye, at, view),
            (eye, at, -2.5 * view),
            (eye, at, Vec3::ZERO),
            (v(0.0, 5.0, 0.0), Vec3::ZERO, Vec3::Y),
            (v(0.0, -5.0, 0.0), Vec3::ZERO, Vec3::Y),
        ] {
            let got = look_at(eye, at, up);
            ensure(
                got == Err(CameraError::UpParallelToView),
                format!(
                    "look_at(eye {}, at {}, up {}): up parallel to the view",
                    vec3(eye),
                    vec3(at),
                    vec3(up)
                ),
                "Err(UpParallelToView)",
                show_look_at(&got),
                PARALLEL,
            )?;
        }
        // 2. Up at an angle δ to the view, generic view directions, both senses. From
        //    1e-3 rad on it is a camera; closer, an error is allowed.
        let mut checked = 0;
        for dir in [v(1.0, 2.0, 3.0), v(-0.3, 0.7, -0.2), -Vec3::Y, Vec3::Z, v(0.6, -0.8, 0.05)] {
            let dir = dir.normalize();
            let across = dir.any_orthonormal_vector();
            for delta in [1e-2 as Float, 1e-3, 1e-4, 1e-5, 3e-6] {
                let up = delta.cos() * dir + delta.sin() * across;
                for sign in [1.0, -1.0] {
                    let eye = v(0.5, -1.0, 2.0);
                    let at = eye + sign * dir;
                    let case = format!(
                        "look_at(eye {}, at {}, up {}): up {delta:.0e} rad from the view",
                        vec3(eye),
                        vec3(at),
                        vec3(sign * up)
                    );
                    let got = look_at(eye, at, sign * up);
                    if delta >= 1e-3 && got.is_err() {
                        return Err(fail(
                            case,
                            "a camera",
                            show_look_at(&got),
                            "1e-3 rad is far from parallel: only |up × w| ≤ 1e-6·|up| is an error",
                        ));
                    }
                    error_or_basis(&case, &got, eye, at, CANCEL)?;
                    checked += 1;
                }
            }
        }
        // 3. Views near −z (eye just off the z axis), up +y: bases near the identity.
        for off in [1e-2, 1e-4, 1e-6, 1e-8] {
            for eye in [v(off, 0.0, 5.0), v(-off, off, 5.0), v(0.0, off, 5.0)] {
                let case = format!("look_at(eye {}, at the origin, up +y): a view near −z", vec3(eye));
                let got = look_at(eye, Vec3::ZERO, Vec3::Y);
                if got.is_err() {
                    return Err(fail(
                        case,
                        "a camera",
                        show_look_at(&got),
                        "a view near −z with up +y is an ordinary camera",
                    ));
                }
                error_or_basis(
                    &case,
                    &got,
                    eye,
                    Vec3::ZERO,
                    "u = (up × w)/|up × w|, v = w × u: an orthonormal basis",
                )?;
                checked += 1;
            }
        }
        // 4. Tiny and huge distances: |eye − at|² underflows or overflows.
        let (tiny, huge) = (Float::MIN_POSITIVE.sqrt() * 1e-10, Float::MAX.sqrt() * 1e3);
        for d in [tiny, huge] {
            for (eye, up) in [(v(0.0, 0.0, d), Vec3::Y), (v(d, d, 0.0), Vec3::Z)] {
                let case = format!("look_at(eye {}, at the origin, up {})", vec3(eye), vec3(up));
                let got = look_at(eye, Vec3::ZERO, up);
                error_or_basis(
                    &case,
                    &got,
                    eye,
                    Vec3::ZERO,
                    "|eye − at|² underflows or overflows at this distance: rescale eye − at by its largest \
                        component before normalising",
                )?;
                checked += 1;
            }
        }
        Ok(format!(
            "5 parallel ups are errors, {checked} near-degenerate cameras are orthonormal within \
                {BASIS_TOL:.0e}"
        ))
    }

    // ---- screen coordinates ----------------------------------------------------

    pub(super) fn screen_cases(screen_coords: ScreenFn) -> CheckResult {
        // sx = 2(x + ½)/w − 1 and sy = 1 − 2(y + ½)/h in f64 (rounding: < 2ε of Float, see below).
        // By hand: 200 × 100, pixel (0, 0) is (−0.995, 0.99), (199, 99) is (0.995, −0.99);
        // 3 × 5 pixel (1, 2) and 1 × 1 pixel (0, 0) are the centre (0, 0).
        let cases = [
            (0, 0, 200, 100),
            (199, 99, 200, 100),
            (199, 0, 200, 100),
            (1, 2, 3, 5),
            (0, 0, 1, 1),
            (99, 49, 200, 100),
            (100, 50, 200, 100),
            (0, 0, 16384, 3),
            (16383, 2, 16384, 3),
            (5461, 1, 16384, 3),
        ];
        let book = |x: f64, y: f64, w: f64, h: f64| (2.0 * (x + 0.5) / w - 1.0, 1.0 - 2.0 * (y + 0.5) / h);
        for (x, y, w, h) in cases {
            let (ex, ey) = book(x as f64, y as f64, w as f64, h as f64);
            let got = screen_coords(x, y, w, h);
            // The f64 formula rounds twice (≤ ¾ ε_f64); the answer rounds once to Float: within 2ε of Float.
            let tol = 2.0 * Float::EPSILON as f64;
            let ok = (got.0 as f64 - ex).abs() <= tol && (got.1 as f64 - ey).abs() <= tol;
            if ok {
                continue;
            }
            let g = Vec3::new(got.0, got.1, 0.0);
            let at = |(a, b): (f64, f64)| Vec3::new(a as Float, b as Float, 0.0);
            let (xf, yf, wf, hf) = (x as f64, y as f64, w as f64, h as f64);
            let cause = diagnose(
                g,
                &[
                    (
                        at((2.0 * xf / wf - 1.0, 1.0 - 2.0 * yf / hf)),
                        "use the pixel centre: x + ½ and y + ½, not the corner",
                    ),
                    (at((ex, -ey)), "pixel rows go down but sy goes up: sy = 1 − 2(y + ½)/h"),
                    (at(book(xf, yf, hf, wf)), "sx divides by the width, sy by the height"),
                    (at((-ex, ey)), "sx goes from left (−1) to right (+1): sx = 2(x + ½)/w − 1"),
                ],
                1e-5,
                "sx = 2(x + ½)/w − 1, sy = 1 − 2(y + ½)/h, computed in Float (integer division truncates)",
            );
            return Err(fail(
                format!("screen_coords({x}, {y}, {w}, {h})"),
                format!("({}, {}) (± {tol:.1e})", num(ex as Float), num(ey as Float)),
                format!("({}, {})", num(got.0), num(got.1)),
                cause,
            ));
        }
        Ok(format!("{} pixels", cases.len()))
    }

    // ---- cameras -------------------------------------------------------------

    /// A camera at (1, 2, 3) looking along +x: u = z, v = y, w = −x (u × v = w).
    fn along_x() -> Mat4 {
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
                let case =
                    format!("perspective camera {where_}, fovy 60°, aspect 2, screen point ({sx}, {sy})");
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
}

#[cfg(all(test, feature = "l01"))]
#[allow(clippy::result_large_err)]
mod tests {
    //! The checks pass on the reference, and planted mistakes (the catalogue's
    //! and a few more) fail them with the intended cause.

    use crate::check::testing::caught;

    pub(super) use l01_transforms::{CameraError, OrthographicCamera, PerspectiveCamera, rotate_axis};
    use raylab::{Float, Mat4, Ray, Vec3, Vec4, radians};

    use super::code::*;

    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }

    #[test]
    fn translate_and_scale_mistakes() {
        caught(
            translate_cases(|t| Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::Z, t.extend(1.0)).transpose()),
            "not the last row",
        );
        caught(translate_cases(|t| Mat4::from_cols(Vec4::X, Vec4::Y, Vec4::Z, (-t).extend(1.0))), "+t");
        caught(scale_cases(|s| Mat4::from_diagonal(s.extend(0.0))), "w = 1");
    }

    /// The reference rotate_z with the signs of the sin terms swapped (left-handed).
    fn rotate_z_left_handed(angle: Float) -> Mat4 {
        let (s, c) = angle.sin_cos();
        Mat4::from_cols(Vec4::new(c, -s, 0.0, 0.0), Vec4::new(s, c, 0.0, 0.0), Vec4::Z, Vec4::W)
    }

    #[test]
    fn rotation_mistakes() {
        caught(rotation_cases(2, rotate_z_left_handed), "wrong way");
        caught(rotation_cases(0, |a| l01_transforms::rotate_x(-a)), "wrong way");
        caught(rotation_cases(1, |a| l01_transforms::rotate_y(radians(a))), "radians");
    }

    /// Rodrigues with the slides' sign typo: the sin terms of the upper triangle
    /// take the sign of the lower one, so s·[a]× becomes symmetric.
    fn slide_typo(axis: Vec3, angle: Float) -> Mat4 {
        let a = axis.normalize();
        let (s, c) = angle.sin_cos();
        let t = 1.0 - c;
        Mat4::from_cols(
            Vec4::new(c + t * a.x * a.x, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y, 0.0),
            Vec4::new(t * a.x * a.y + s * a.z, c + t * a.y * a.y, t * a.y * a.z + s * a.x, 0.0),
            Vec4::new(t * a.x * a.z - s * a.y, t * a.y * a.z + s * a.x, c + t * a.z * a.z, 0.0),
            Vec4::W,
        )
    }

    /// Rodrigues without normalising the axis.
    fn unnormalised(a: Vec3, angle: Float) -> Mat4 {
        let (s, c) = angle.sin_cos();
        let t = 1.0 - c;
        Mat4::from_cols(
            Vec4::new(c + t * a.x * a.x, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y, 0.0),
            Vec4::new(t * a.x * a.y - s * a.z, c + t * a.y * a.y, t * a.y * a.z + s * a.x, 0.0),
            Vec4::new(t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, c + t * a.z * a.z, 0.0),
            Vec4::W,
        )
    }

    #[test]
    fn rotate_axis_mistakes() {
        caught(rotate_axis_cases(slide_typo), "skew-symmetric");
        caught(rotate_axis_cases(|a, t| rotate_axis(a, t).transpose()), "wrong way");
        caught(rotate_axis_cases(unnormalised), "normalise the axis");
    }

    #[test]
    fn point_and_vector_mistakes() {
        caught(transform_point_cases(|m, p| (*m * p.extend(0.0)).truncate()), "w = 1");
        caught(transform_point_cases(|m, p| (*m * p.extend(1.0)).truncate()), "divide by w'");
        caught(transform_vector_cases(|m, v| (*m * v.extend(1.0)).truncate()), "w = 0");
    }

    #[test]
    fn frame_mistakes() {
        caught(frame_cases(|o, i, j, k| l01_transforms::frame(o, i, j, k).transpose()), "not the rows");
        caught(frame_cases(|o, i, j, k| l01_transforms::frame(o, i, j, k).inverse()), "inverse");
        caught(
            frame_cases(|o, i, j, k| {
                Mat4::from_cols(i.extend(0.0), j.extend(0.0), k.extend(0.0), o.extend(0.0))
            }),
            "w = 1",
        );
    }

    fn det(i: Vec3, j: Vec3, k: Vec3) -> Float {
        i.dot(j.cross(k))
    }

    #[test]
    fn is_basis_mistakes() {
        caught(is_basis_cases(|i, j, k| det(i, j, k) != 0.0), "not det ≠ 0");
        caught(is_basis_cases(|i, j, k| det(i, j, k).abs() > 1e-6), "relative");
        caught(
            is_basis_cases(|i, j, k| det(i, j, k) > 1e-6 * i.length() * j.length() * k.length()),
            "left-handed",
        );
        // The relative test without rescaling: right at ordinary lengths, wrong at extreme ones.
        let naive =
            |i: Vec3, j: Vec3, k: Vec3| det(i, j, k).abs() > 1e-6 * i.length() * j.length() * k.length();
        assert!(is_basis_cases(naive).is_ok());
        caught(is_basis_any_units(naive), "rescale");
    }

    /// look_at built step by step, with switches for the classic mistakes.
    #[derive(Clone, Copy, Default)]
    struct LookAt {
        backwards: bool,
        w_cross_up: bool,
        v_is_up: bool,
        u_unnormalised: bool,
        no_parallel_check: bool,
        no_gram_schmidt: bool,
    }

    impl LookAt {
        fn build(self, eye: Vec3, at: Vec3, up: Vec3) -> Result<Mat4, CameraError> {
            if eye == at {
                return Err(CameraError::EyeAtTarget);
            }
            let w = if self.backwards { at - eye } else { eye - at }.normalize();
            let right = if self.w_cross_up { w.cross(up) } else { up.cross(w) };
            if !self.no_parallel_check && right.length() <= 1e-6 * up.length() {
                return Err(CameraError::UpParallelToView);
            }
            let mut u = if self.u_unnormalised { right } else { right.normalize() };
            if !self.no_gram_schmidt && !self.u_unnormalised {
                u = (u - u.dot(w) * w).normalize();
            }
            let v = if self.v_is_up { up } else { w.cross(u) };
            Ok(Mat4::from_cols(u.extend(0.0), v.extend(0.0), w.extend(0.0), eye.extend(1.0)))
        }
    }

    thread_local! {
        static PLANTED: std::cell::Cell<LookAt> = std::cell::Cell::new(LookAt::default());
    }

    fn planted(eye: Vec3, at: Vec3, up: Vec3) -> Result<Mat4, CameraError> {
        PLANTED.with(|p| p.get()).build(eye, at, up)
    }

    fn with(mistake: LookAt) -> LookAtFn {
        PLANTED.with(|p| p.set(mistake));
        planted
    }

    #[test]
    fn look_at_mistakes() {
        // The step-by-step build without mistakes passes the unit check (it does not rescale).
        assert!(look_at_cases(with(LookAt::default())).is_ok());
        caught(look_at_cases(with(LookAt { backwards: true, ..LookAt::default() })), "backwards");
        caught(look_at_cases(with(LookAt { w_cross_up: true, ..LookAt::default() })), "in this order");
        caught(look_at_cases(with(LookAt { v_is_up: true, ..LookAt::default() })), "the true up");
        caught(look_at_cases(with(LookAt { u_unnormalised: true, ..LookAt::default() })), "normalise u");
        caught(
            look_at_cases(|e, a, u| l01_transforms::look_at(e, a, u).map(|m| m.transpose())),
            "not its rows",
        );
        caught(
            look_at_cases(|e, a, u| {
                l01_transforms::look_at(e, a, u).map(|mut m| {
                    m.w_axis.w = 0.0;
                    m
                })
            }),
            "(eye, 1)",
        );
        let no_check = LookAt { no_parallel_check: true, ..LookAt::default() };
        caught(look_at_degenerate(with(no_check)), "UpParallelToView");
        // Without rescaling, |eye − at|² underflows for tiny distances.
        caught(look_at_degenerate(with(LookAt::default())), "rescale");
        // Without the Gram–Schmidt step, u drifts off ⟂ w by ~ε/δ: 1e-2 at δ = 1e-5 in f32
        // (in f64 the drift, 2e-11, is within the bound: the mistake costs nothing there).
        if Float::EPSILON > 1e-10 {
            caught(
                look_at_degenerate(with(LookAt { no_gram_schmidt: true, ..LookAt::default() })),
                "cancels",
            );
        }
    }

    #[test]
    fn screen_mistakes() {
        caught(
            screen_cases(|x, y, w, h| {
                (2.0 * x as Float / w as Float - 1.0, 1.0 - 2.0 * y as Float / h as Float)
            }),
            "pixel centre",
        );
        caught(
            screen_cases(|x, y, w, h| {
                (2.0 * (x as Float + 0.5) / w as Float - 1.0, 2.0 * (y as Float + 0.5) / h as Float - 1.0)
            }),
            "rows go down",
        );
        caught(
            screen_cases(|x, y, w, h| {
                (2.0 * (x as Float + 0.5) / h as Float - 1.0, 1.0 - 2.0 * (y as Float + 0.5) / w as Float)
            }),
            "divides by the width",
        );
    }

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
