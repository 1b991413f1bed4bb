//! The checks of `screen.rs`: screen_coords.

use super::common::*;

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;

    use raylab::Float;

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
}
