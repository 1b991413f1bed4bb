//! Reconstruction filters: how much each sample counts toward a pixel.

use raylab::{Float, Vec2};

/// The filter that weighs a pixel's samples by their offset from its centre.
/// Both integrate to 1 over the plane. Book: §10.7 Reconstruction filters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filter {
    /// 1 inside the pixel, 0 outside: the plain average of the pixel's area.
    Box,
    /// (1 − |x|)(1 − |y|) over the 2 × 2 pixels around the centre: samples
    /// near the centre count more, and neighbouring pixels share samples'
    /// territory, which softens edges and hides more aliasing than the box.
    Tent,
}

impl Filter {
    /// The half-width of the filter's support in pixels: ½ for the box, 1
    /// for the tent. A pixel's samples are spread over [−r, r)² around its
    /// centre.
    pub fn radius(self) -> Float {
        match self {
            Filter::Box => 0.5,
            Filter::Tent => 1.0,
        }
    }
}

/// The weight of a sample at `offset` = (x, y) from the pixel centre, in
/// pixels (x right, y down):
///
/// ```text
/// box:  1 when −½ ≤ x < ½ and −½ ≤ y < ½, else 0
/// tent: max(0, 1 − |x|)·max(0, 1 − |y|)
/// ```
///
/// The box is half-open so that the boxes of neighbouring pixels tile the
/// plane without overlap. Both integrate to 1 (the box: area 1; the tent: the
/// product of two triangles of base 2 and height 1). Never negative, never
/// NaN (a NaN offset weighs 0). Book: §10.7 Reconstruction filters.
pub fn filter_weight(filter: Filter, offset: Vec2) -> Float {
    // SOLUTION BEGIN
    match filter {
        Filter::Box => {
            let inside = (-0.5..0.5).contains(&offset.x) && (-0.5..0.5).contains(&offset.y);
            if inside { 1.0 } else { 0.0 }
        }
        // Each factor is a triangle of height 1 on [−1, 1]; max ignores a NaN.
        Filter::Tent => (1.0 - offset.x.abs()).max(0.0) * (1.0 - offset.y.abs()).max(0.0),
    }
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weights_by_hand() {
        let w = |f, x, y| filter_weight(f, Vec2::new(x, y));
        // Box: inside, on the closed lower edge, on the open upper edge, outside.
        assert_eq!([w(Filter::Box, 0.0, 0.0), w(Filter::Box, -0.5, 0.2)], [1.0, 1.0]);
        assert_eq!([w(Filter::Box, 0.5, 0.0), w(Filter::Box, 0.0, -0.7)], [0.0, 0.0]);
        // Tent: 1 at the centre, (1 − ½)(1 − ¼) = 0.375 at (½, −¼), 0 on and beyond the rim.
        assert_eq!([w(Filter::Tent, 0.0, 0.0), w(Filter::Tent, 0.5, -0.25)], [1.0, 0.375]);
        assert_eq!([w(Filter::Tent, 1.0, 0.0), w(Filter::Tent, -3.0, 0.5)], [0.0, 0.0]);
        for f in [Filter::Box, Filter::Tent] {
            assert_eq!(w(f, Float::NAN, 0.0), 0.0);
        }
    }

    #[test]
    fn filter_weights_integrate_to_one() {
        // The midpoint rule on [−1, 1]² (the tent's support, which holds the box's) with N × N
        // cells of side h = 2/N, N = 200: the grid lines fall on ±½, 0 and ±1, where the box
        // jumps and the tent bends, so in every cell the box is constant and the tent is a
        // product of linear functions, which the midpoint rule integrates exactly. What is
        // left is rounding: each weight within 2ε relative, summed in f64, so |Σ − 1| ≤ 4ε
        // of Float; asserted within 1e-5, far above that in f32 (4.8e-7) and below any real
        // error (a box off by one cell row would be off by h = 0.01).
        // A second, misaligned grid (N = 201, cell edges off the jumps) is off by O(h): the
        // box's boundary cells count whole or not at all, a strip at most ½h wide along each
        // of its 4 unit sides: 2h = 0.0199 of area (measured 0.00998; the tent 5e-5).
        for (n, tolerance) in [(200u32, 1e-5), (201, 0.02)] {
            let h = 2.0 / f64::from(n);
            for filter in [Filter::Box, Filter::Tent] {
                let mut integral = 0.0f64;
                for i in 0..n {
                    for j in 0..n {
                        let x = -1.0 + (f64::from(i) + 0.5) * h;
                        let y = -1.0 + (f64::from(j) + 0.5) * h;
                        let weight = filter_weight(filter, Vec2::new(x as Float, y as Float));
                        integral += f64::from(weight) * h * h;
                    }
                }
                println!("{filter:?} on {n}×{n}: ∫ = {integral:.9}");
                assert!((integral - 1.0).abs() <= tolerance, "{filter:?} on {n}×{n}: {integral}");
            }
        }
    }
}
