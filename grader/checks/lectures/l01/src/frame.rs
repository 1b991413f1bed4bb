//! The checks of `frame.rs`: frame and is_basis.

use super::common::*;

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
    let cases: [(Vec3, Vec3, Vec3, bool, &str); 15] = [
        (Vec3::X, Vec3::Y, Vec3::Z, true, "the coordinate axes are a basis"),
        (Vec3::Y, Vec3::X, Vec3::Z, true, "a left-handed triple (det = −1) is a basis too: compare |det|"),
        (Vec3::X, v(1.0, 1.0, 0.0), Vec3::ONE, true, "a skewed triple with det = 1 (triangular) is a basis"),
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
        // det = 1e-6 exactly, 1e-6·|i||j||k| = 1e-6·√(1 + 10⁻¹²): 1e-6 in f32, a little more in f64.
        // The test is strict: no basis.
        (
            Vec3::X,
            Vec3::Y,
            v(1.0, 0.0, 1e-6),
            false,
            "|det| at the threshold is not above it: the test is |det| > 1e-6·|i||j||k|, strictly",
        ),
        // Lengths √2, √2, √2 (to 10⁻¹²): det = 2·10⁻⁶ against 1e-6·2√2 = 2.83·10⁻⁶, no basis; a
        // threshold that divides by a length would be 1.41·10⁻⁶.
        (
            v(1.0, 1.0, 0.0),
            v(-1.0, 1.0, 0.0),
            v(1.0, 1.0, 1e-6),
            false,
            "the threshold is relative: 1e-6 times the product of the three lengths, here 2√2·10⁻⁶",
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
    Ok("15 triples".into())
}

/// Lengths whose product of three overflows (`big`) or underflows to zero
/// (`tiny`) in the precision under test: MAX^(1/3)·10 and MIN_POSITIVE^(1/3)·1e-6
/// (f32: 7e13 and 2e-19; f64: 6e103 and 3e-109).
pub(super) fn extreme_lengths() -> (Float, Float) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    use raylab::{Float, Mat4, Vec3};

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
}
