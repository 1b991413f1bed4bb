//! The checks of `filter.rs`: filter_weight.

use super::common::*;

pub(super) fn filter_cases(filter_weight: FilterFn) -> CheckResult {
    let w = |f: Filter, x: Float, y: Float| filter_weight(f, uv(x, y));
    // Box: 1 on [−½, ½)², closed below and open above, 0 outside.
    for (x, y, expected, what) in [
        (0.0, 0.0, 1.0, "the centre"),
        (-0.5, 0.2, 1.0, "the lower edge x = −½ (closed)"),
        (0.2, -0.5, 1.0, "the lower edge y = −½ (closed)"),
        (0.5, 0.0, 0.0, "the upper edge x = ½ (open)"),
        (0.0, -0.7, 0.0, "outside, y = −0.7"),
        (0.49, 0.49, 1.0, "inside a corner"),
    ] {
        let got = w(Filter::Box, x, y);
        let cause = if x == 0.5 {
            "the box is half-open, −½ ≤ x < ½: neighbouring pixels' boxes must not overlap"
        } else {
            "the box weighs 1 inside the pixel, −½ ≤ x, y < ½, and 0 outside"
        };
        ensure(got == expected, format!("box filter at ({x}, {y}), {what}"), num(expected), num(got), cause)?;
    }
    // Tent: (1 − |x|)(1 − |y|) clamped at 0 per factor; exact for these dyadic values.
    for (x, y, expected, what) in [
        (0.0, 0.0, 1.0, "the centre"),
        (0.5, -0.25, 0.375, "(1 − ½)(1 − ¼)"),
        (1.0, 0.0, 0.0, "the rim x = 1"),
        (-3.0, 0.5, 0.0, "beyond the rim, x = −3"),
        (-3.0, -3.0, 0.0, "beyond the rim in both, (−3, −3)"),
    ] {
        let got = w(Filter::Tent, x, y);
        let cause = if (got - 0.25).abs() <= EPS && x == 0.5 {
            "the tent is a product of two triangles, (1 − |x|)(1 − |y|), not 1 − |x| − |y|"
        } else if got != 0.0 && x.abs() >= 1.0 {
            "clamp each factor at 0 before multiplying, max(0, 1 − |x|)·max(0, 1 − |y|): beyond the rim \
             (1 − |x|) is negative, and two negatives make a positive"
        } else {
            "tent: max(0, 1 − |x|)·max(0, 1 − |y|)"
        };
        ensure(
            got == expected,
            format!("tent filter at ({x}, {y}), {what}"),
            num(expected),
            num(got),
            cause,
        )?;
    }
    // NaN offsets weigh 0 (never NaN).
    for f in [Filter::Box, Filter::Tent] {
        let got = w(f, Float::NAN, 0.0);
        ensure(
            got == 0.0,
            format!("{f:?} filter at (NaN, 0)"),
            "0",
            num(got),
            "a NaN offset weighs 0: range tests are false for NaN, and max(NaN, 0) = 0",
        )?;
    }
    // Both integrate to 1: the midpoint rule on [−1, 1]² with 200 × 200 cells of side 0.01,
    // whose edges fall on ±½, 0 and ±1, where the box jumps and the tent bends, so each cell
    // is integrated exactly; what is left is rounding, ≤ 4ε of Float summed in f64. Allowed
    // 10⁻⁵, far below the error of a wrong filter (one row of cells is 0.01).
    let n = 200u32;
    let h = 2.0 / f64::from(n);
    for f in [Filter::Box, Filter::Tent] {
        let mut integral = 0.0f64;
        for i in 0..n {
            for j in 0..n {
                let x = -1.0 + (f64::from(i) + 0.5) * h;
                let y = -1.0 + (f64::from(j) + 0.5) * h;
                integral += filter_weight(f, uv(x as Float, y as Float)) as f64 * h * h;
            }
        }
        ensure(
            (integral - 1.0).abs() <= 1e-5,
            format!("the {f:?} filter integrated over [−1, 1]² by the midpoint rule"),
            "1 (± 1e-5)",
            format!("{integral:.6}"),
            "a filter integrates to 1: box of side 1 and height 1; tent of half-width 1 and height 1",
        )?;
    }
    Ok("11 points, NaN, 2 integrals".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    use l10_textures_sampling::Filter;

    use raylab::{Float, Vec2};

    #[test]
    fn planted_filter_mistakes_are_caught() {
        fn box_closed(f: Filter, d: Vec2) -> Float {
            match f {
                Filter::Box => Float::from(u8::from(d.x.abs() <= 0.5 && d.y.abs() <= 0.5)),
                Filter::Tent => (1.0 - d.x.abs()).max(0.0) * (1.0 - d.y.abs()).max(0.0),
            }
        }
        caught(filter_cases(box_closed), "half-open");
        fn unclamped(f: Filter, d: Vec2) -> Float {
            match f {
                Filter::Box => {
                    Float::from(u8::from((-0.5..0.5).contains(&d.x) && (-0.5..0.5).contains(&d.y)))
                }
                Filter::Tent => (1.0 - d.x.abs()) * (1.0 - d.y.abs()),
            }
        }
        caught(filter_cases(unclamped), "clamp each factor");
        fn pyramid(f: Filter, d: Vec2) -> Float {
            match f {
                Filter::Box => {
                    Float::from(u8::from((-0.5..0.5).contains(&d.x) && (-0.5..0.5).contains(&d.y)))
                }
                Filter::Tent => (1.0 - d.x.abs() - d.y.abs()).max(0.0),
            }
        }
        caught(filter_cases(pyramid), "product of two triangles");
    }
}
