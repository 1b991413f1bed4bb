//! Ray–sphere roots to about one f64 rounding whatever the precision of
//! `Float`: the ground truth of lecture 02's sphere tests and checks, by a
//! method none of the lecture's three uses (Newton's method on a residual
//! evaluated in double-double arithmetic).

use raylab::{Float, Vec3};

use crate::{wide, wide3};

/// The roots t₀ ≤ t₁ of |o + t·d − c|² = r², accurate to about one f64
/// rounding whatever the precision of `Float`: the inputs are widened to f64
/// exactly, and Newton's method on g(t) = |o − c + t·d|² − r², its residual
/// evaluated in double-double arithmetic (error-free products by fused
/// multiply–add), finds each root. No closed form, none of this lecture's
/// three (§2.2–2.4): t_c = −(o − c)·d / d·d is the point of the line nearest
/// the centre; when g(t_c) > 0 the line misses, else both roots lie within
/// t_c ∓ r/|d|, where g ≥ 0. g is a convex parabola, so Newton's steps from
/// those two ends move toward their roots and never past them (linearly, by
/// halves, only where the roots nearly meet: at most ~60 steps).
/// `None` when the line misses the sphere (in f64).
pub fn sphere_roots_reference(origin: Vec3, dir: Vec3, center: Vec3, radius: Float) -> Option<(f64, f64)> {
    let (o, d, c, r) = (wide3(origin), wide3(dir), wide3(center), wide(radius));
    let f = [o[0] - c[0], o[1] - c[1], o[2] - c[2]];
    let dot = |u: [f64; 3], v: [f64; 3]| u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    let a = dot(d, d);
    let t_c = -dot(f, d) / a;
    if residual(f, d, r, t_c).0 > 0.0 {
        return None;
    }
    let newton = |mut t: f64| {
        for _ in 0..200 {
            let (g, slope) = residual(f, d, r, t);
            let next = t - g / slope;
            if g <= 0.0 || slope == 0.0 || next == t {
                break;
            }
            t = next;
        }
        t
    };
    let half = r / a.sqrt();
    Some((newton(t_c - half), newton(t_c + half)))
}

/// g(t) = |f + t·d|² − r² in double-double arithmetic, and g'(t) = 2 d·(f + t·d):
/// the residual of the line f + t·d (f = o − c, in f64) against the sphere of
/// radius r at the origin, accurate to about one f64 rounding where plain f64
/// cancels (for polishing roots found otherwise, as the trade-offs do).
pub fn residual(f: [f64; 3], d: [f64; 3], r: f64, t: f64) -> (f64, f64) {
    let mut sum = neg(two_prod(r, r));
    let mut slope = 0.0;
    for i in 0..3 {
        // p = f + t·d as an unevaluated sum hi + lo.
        let (td, td_err) = two_prod(t, d[i]);
        let (hi, s_err) = two_sum(f[i], td);
        let lo = s_err + td_err;
        // p² ≈ hi² + 2·hi·lo (lo² is below the last bit).
        let (sq, sq_err) = two_prod(hi, hi);
        sum = add(sum, (sq, sq_err + 2.0 * hi * lo));
        slope += 2.0 * d[i] * (hi + lo);
    }
    (sum.0 + sum.1, slope)
}

fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

fn add(x: (f64, f64), y: (f64, f64)) -> (f64, f64) {
    let (s, e) = two_sum(x.0, y.0);
    let e = e + x.1 + y.1;
    two_sum(s, e)
}

fn neg(x: (f64, f64)) -> (f64, f64) {
    (-x.0, -x.1)
}

/// One unit in the last place of `Float` near `x`, counted in f64 as the
/// lectures count it: |x|·ε.
pub fn ulp_wide(x: f64) -> f64 {
    x.abs() * wide(Float::EPSILON)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reference_roots_of_a_known_sphere() {
        // Unit sphere at the origin, ray from (0, 0, 5) along −z: roots 5 ∓ 1.
        let roots = sphere_roots_reference(Vec3::new(0.0, 0.0, 5.0), -Vec3::Z, Vec3::ZERO, 1.0);
        assert_eq!(roots, Some((4.0, 6.0)));
    }

    #[test]
    fn reference_is_accurate_where_plain_f64_cancels() {
        // Radius 1 at distance 1e8 along +x (exact in f32), ray along +x offset by y = 0.6
        // (rounded to Float): roots 1e8 ∓ √(1 − y²). In plain f64, |c − o|² − t_ca² would
        // lose y² entirely (the spacing of f64 near 1e16 is 2).
        let y = 0.6 as Float;
        let (t0, t1) = sphere_roots_reference(Vec3::new(0.0, y, 0.0), Vec3::X, Vec3::new(1e8, 0.0, 0.0), 1.0)
            .expect("the ray passes 0.6 from the centre");
        let h = (1.0 - wide(y) * wide(y)).sqrt();
        // Tolerance 3e-8: two roundings of f64 near 1e8 (spacing 1.5e-8).
        assert!((t0 - (1e8 - h)).abs() <= 3e-8, "{t0}");
        assert!((t1 - (1e8 + h)).abs() <= 3e-8, "{t1}");
    }
}
