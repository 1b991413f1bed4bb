//! Ground truth for the sphere: its roots to about one f64 rounding, whatever
//! the precision of `Float`, by an independent method (f64, then Newton steps
//! on a residual evaluated in double-double arithmetic).

use raylab::{Float, Vec3};
use raylab_testing::roots::residual;
use raylab_testing::{wide, wide3};

/// u·v in f64.
pub fn dot(u: [f64; 3], v: [f64; 3]) -> f64 {
    u[0] * v[0] + u[1] * v[1] + u[2] * v[2]
}

/// u × v in f64.
pub fn cross(u: [f64; 3], v: [f64; 3]) -> [f64; 3] {
    [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
}

/// u / |u| in f64.
pub fn unit(u: [f64; 3]) -> [f64; 3] {
    let length = dot(u, u).sqrt();
    u.map(|x| x / length)
}

/// The angle between two directions in radians, atan2(|u × v|, u·v): accurate near 0 and
/// near π alike (acos of the dot is not), whatever their lengths; NaN when either holds a NaN.
pub fn angle(u: [f64; 3], v: [f64; 3]) -> f64 {
    let c = cross(u, v);
    dot(c, c).sqrt().atan2(dot(u, v))
}

/// What the reference knows of a ray and a sphere.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereTruth {
    /// r² − l² in f64, l the distance from the centre to the line: ≥ 0 for a hit.
    pub h2: f64,
    /// l / r, the line's distance from the centre in radii.
    pub closeness: f64,
    /// The roots t₀ ≤ t₁ (in units of `dir`) when the line meets the sphere.
    pub roots: Option<(f64, f64)>,
}

/// The reference for the ray o + t·d against the sphere (c, r).
///
/// The line's closest point to the centre and h² = r² − l² are computed in
/// f64 (from f32 inputs the differences o − c are exact in f64, so h² is off
/// by a few f64 roundings of |o − c|²: ~10⁻⁶ at |o − c| = 10⁵, far below an f32
/// ulp of t); the roots t_ca ∓ √(h²/a) are then polished by two Newton steps
/// on g(t) = |o − c + t·d|² − r², whose value is summed in double-double
/// arithmetic (error-free products by fused multiply–add), so they are
/// accurate to about one f64 rounding even where f64 itself cancels.
pub fn sphere_truth(origin: Vec3, dir: Vec3, center: Vec3, radius: Float) -> SphereTruth {
    let (o, d, c, r) = (wide3(origin), wide3(dir), wide3(center), wide(radius));
    let f = [o[0] - c[0], o[1] - c[1], o[2] - c[2]];
    let a = dot(d, d);
    let t_ca = -dot(f, d) / a;
    let closest = [f[0] + t_ca * d[0], f[1] + t_ca * d[1], f[2] + t_ca * d[2]];
    let l2 = dot(closest, closest);
    let h2 = r * r - l2;
    let roots = (h2 >= 0.0).then(|| {
        let t_hc = (h2 / a).sqrt();
        let polish = |mut t: f64| {
            for _ in 0..2 {
                let (g, slope) = residual(f, d, r, t);
                if slope != 0.0 {
                    t -= g / slope;
                }
            }
            t
        };
        (polish(t_ca - t_hc), polish(t_ca + t_hc))
    });
    SphereTruth { h2, closeness: l2.sqrt() / r, roots }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_of_a_known_sphere_are_exact() {
        // Unit sphere at the origin, ray from (0, 0, 5) along −z: roots 5 ∓ 1, l = 0.
        let truth = sphere_truth(Vec3::new(0.0, 0.0, 5.0), -Vec3::Z, Vec3::ZERO, 1.0);
        assert_eq!(truth.roots, Some((4.0, 6.0)));
        assert_eq!((truth.h2, truth.closeness), (1.0, 0.0));
    }

    #[test]
    fn angles_between_known_directions() {
        // Perpendicular: π/2; opposite: π; a 10⁻⁹ rad tilt, where acos(1 − 5·10⁻¹⁹) would say 0:
        // atan2(10⁻⁹, 1) = 10⁻⁹ to f64 rounding.
        assert_eq!(angle([1.0, 0.0, 0.0], [0.0, 3.0, 0.0]), std::f64::consts::FRAC_PI_2);
        assert_eq!(angle([0.0, 0.0, 2.0], [0.0, 0.0, -1.0]), std::f64::consts::PI);
        assert!((angle([1.0, 1e-9, 0.0], [1.0, 0.0, 0.0]) - 1e-9).abs() < 1e-24);
        assert!(angle([f64::NAN, 0.0, 0.0], [1.0, 0.0, 0.0]).is_nan());
    }

    #[test]
    fn far_roots_are_accurate_where_plain_f64_cancels() {
        // Radius 1 at x = 10⁸, ray along +x at height y = 0.6 (rounded to Float): roots
        // 10⁸ ∓ √(1 − y²). Plain f64 loses y² in |c − o|² − t_ca² (the spacing near 10¹⁶
        // is 2); here t_ca and l come straight from the geometry. Tolerance 3·10⁻⁸: two
        // f64 roundings near 10⁸ (spacing 1.5·10⁻⁸).
        let y = 0.6 as Float;
        let truth = sphere_truth(Vec3::new(0.0, y, 0.0), Vec3::X, Vec3::new(1e8, 0.0, 0.0), 1.0);
        let (t0, t1) = truth.roots.expect("passes 0.6 from the centre");
        let h = (1.0 - wide(y) * wide(y)).sqrt();
        assert!((t0 - (1e8 - h)).abs() <= 3e-8, "{t0}");
        assert!((t1 - (1e8 + h)).abs() <= 3e-8, "{t1}");
        // And a line 1.5 from the centre misses: h² = 1 − 2.25.
        let miss = sphere_truth(Vec3::new(0.0, 1.5, 0.0), Vec3::X, Vec3::new(1e3, 0.0, 0.0), 1.0);
        assert_eq!((miss.roots, miss.h2), (None, -1.25));
    }
}
