//! The checks of `checker.rs`: checker and checker_3d.

use super::common::*;

pub(super) const A: Color = Color::new(1.0, 1.0, 1.0);
pub(super) const B: Color = Color::new(0.0, 0.0, 0.0);

pub(super) fn name(c: Color) -> &'static str {
    if c == A {
        "a"
    } else if c == B {
        "b"
    } else {
        "neither a nor b"
    }
}

pub(super) fn checker_cases(checker: CheckerFn) -> CheckResult {
    // Scale 4: edges at multiples of ¼; cell (⌊4u⌋, ⌊4v⌋), a when the sum is even.
    for (u, v, expected, why) in [
        (0.2, 0.1, A, "cell (0, 0)"),
        (0.3, 0.1, B, "cell (1, 0)"),
        (0.3, 0.3, A, "cell (1, 1)"),
        (0.2, 0.3, B, "cell (0, 1)"),
        (0.25, 0.1, B, "on the edge u = ¼: the cell to the right, (1, 0)"),
        (0.6, 0.9, B, "cell (2, 3)"),
        (-0.1, 0.1, B, "⌊−0.4⌋ = −1: cell (−1, 0)"),
        (-0.3, 0.1, A, "⌊−1.2⌋ = −2: cell (−2, 0)"),
        (-0.1, -0.1, A, "cell (−1, −1)"),
        (0.1, -0.1, B, "cell (0, −1)"),
        (-0.25, 0.1, B, "on the edge u = −¼: cell (−1, 0)"),
    ] {
        let got = checker(uv(u, v), 4.0, A, B);
        let case = format!("checker of scale 4 at (u, v) = ({u}, {v}), {why}");
        // The colour truncation toward zero would give, to name that mistake.
        let truncated = if ((u * 4.0) as i64 + (v * 4.0) as i64).rem_euclid(2) == 1 { B } else { A };
        let cause = if got == truncated && truncated != expected {
            "use the floor, not truncation toward zero: (−0.4) as i64 is 0, so the cells either side of 0 \
             get one colour (a double-width stripe)"
        } else if checker(uv(0.2, 0.1), 4.0, A, B) == B {
            "the cell (0, 0) and every cell with an even i + j is a"
        } else {
            "the cell is (⌊u·scale⌋, ⌊v·scale⌋); a when i + j is even, b when odd"
        };
        ensure(got == expected, case, name(expected), name(got), cause)?;
    }
    // Far and NaN coordinates: any of the two colours, never a panic (an overflowing sum).
    for (u, what) in [(1e30, "10³⁰"), (-1e30, "−10³⁰"), (Float::NAN, "NaN")] {
        let got = checker(uv(u, 0.1), 4.0, A, B);
        ensure(
            got == A || got == B,
            format!("checker of scale 4 at u = {what}"),
            "a or b",
            name(got),
            "never anything but a or b, whatever the coordinates",
        )?;
    }
    Ok("11 points, 3 far ones".into())
}

pub(super) fn checker_3d_cases(checker_3d: Checker3dFn) -> CheckResult {
    // Scale 1: cube (0, 0, 0) is a; across any one face (to −0.1 in that axis, cube −1) b;
    // across two faces a again, across three b; the positive neighbours first, where truncation
    // and the floor agree. Scale 2: cubes of side ½.
    for (p, scale, expected, why) in [
        (v3(0.5, 0.5, 0.5), 1.0, A, "cube (0, 0, 0)"),
        (v3(1.5, 0.5, 0.5), 1.0, B, "cube (1, 0, 0)"),
        (v3(0.5, 1.5, 0.5), 1.0, B, "cube (0, 1, 0)"),
        (v3(0.5, 0.5, 1.5), 1.0, B, "cube (0, 0, 1)"),
        (v3(-0.1, 0.5, 0.5), 1.0, B, "cube (−1, 0, 0)"),
        (v3(0.5, -0.1, 0.5), 1.0, B, "cube (0, −1, 0)"),
        (v3(0.5, 0.5, -0.1), 1.0, B, "cube (0, 0, −1)"),
        (v3(-0.1, -0.1, 0.5), 1.0, A, "cube (−1, −1, 0)"),
        (v3(-0.1, -0.1, -0.1), 1.0, B, "cube (−1, −1, −1)"),
        (v3(1.5, 2.5, 0.5), 1.0, B, "cube (1, 2, 0)"),
        (v3(0.6, 0.1, 0.1), 2.0, B, "scale 2: cube (1, 0, 0)"),
        (v3(0.6, 0.6, 0.1), 2.0, A, "scale 2: cube (1, 1, 0)"),
        (v3(0.1, 0.1, 0.6), 2.0, B, "scale 2: cube (0, 0, 1)"),
    ] {
        let got = checker_3d(p, scale, A, B);
        let case = format!("solid checker of scale {scale} at {}, {why}", vec3(p));
        let q = p * scale;
        let truncated = if (q.x as i64 + q.y as i64 + q.z as i64).rem_euclid(2) == 1 { B } else { A };
        let cause = if got == truncated && truncated != expected {
            "use the floor, not truncation toward zero: −0.1 is in cube −1, not 0"
        } else if scale != 1.0 {
            "the cube is (⌊x·scale⌋, ⌊y·scale⌋, ⌊z·scale⌋)"
        } else {
            "a when i + j + k is even (all three coordinates), b when odd"
        };
        ensure(got == expected, case, name(expected), name(got), cause)?;
    }
    Ok("13 points".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    use raylab::{Color, Float, Vec2, Vec3};

    #[test]
    fn planted_checker_mistakes_are_caught() {
        fn truncated(p: Vec2, s: Float, a: Color, b: Color) -> Color {
            if ((p.x * s) as i64 + (p.y * s) as i64).rem_euclid(2) == 1 { b } else { a }
        }
        caught(checker_cases(truncated), "not truncation");
        fn swapped(p: Vec2, s: Float, a: Color, b: Color) -> Color {
            if ((p.x * s).floor() as i64 + (p.y * s).floor() as i64).rem_euclid(2) == 1 { a } else { b }
        }
        caught(checker_cases(swapped), "even i + j is a");
        fn truncated_3d(p: Vec3, s: Float, a: Color, b: Color) -> Color {
            let q = p * s;
            if (q.x as i64 + q.y as i64 + q.z as i64).rem_euclid(2) == 1 { b } else { a }
        }
        caught(checker_3d_cases(truncated_3d), "not truncation");
        fn two_axes(p: Vec3, s: Float, a: Color, b: Color) -> Color {
            if ((p.x * s).floor() as i64 + (p.y * s).floor() as i64).rem_euclid(2) == 1 { b } else { a }
        }
        caught(checker_3d_cases(two_axes), "all three");
    }
}
