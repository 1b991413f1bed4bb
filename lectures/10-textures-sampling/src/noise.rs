//! Solid textures from noise: Perlin's gradient noise, its fractal sum over
//! octaves, and the marble and wood of MIT 6.837 built from them.

use raylab::random::PERLIN_PERMUTATION;
use raylab::{Float, Vec3};

/// The gradient at a lattice point whose hash is `h` (its low 4 bits): one
/// of the 12 vectors from a cube's centre to its edges' midpoints, (±1, ±1,
/// 0) and the like, four of them twice ((1, 1, 0), (−1, 1, 0), (0, −1, 1),
/// (0, −1, −1)) so that 16 cases share one cheap lookup: the vectors of
/// Perlin's 2002 `grad(hash, x, y, z)`, written as a table. Given.
const GRADIENTS: [Vec3; 16] = [
    Vec3::new(1.0, 1.0, 0.0),
    Vec3::new(-1.0, 1.0, 0.0),
    Vec3::new(1.0, -1.0, 0.0),
    Vec3::new(-1.0, -1.0, 0.0),
    Vec3::new(1.0, 0.0, 1.0),
    Vec3::new(-1.0, 0.0, 1.0),
    Vec3::new(1.0, 0.0, -1.0),
    Vec3::new(-1.0, 0.0, -1.0),
    Vec3::new(0.0, 1.0, 1.0),
    Vec3::new(0.0, -1.0, 1.0),
    Vec3::new(0.0, 1.0, -1.0),
    Vec3::new(0.0, -1.0, -1.0),
    Vec3::new(1.0, 1.0, 0.0),
    Vec3::new(0.0, -1.0, 1.0),
    Vec3::new(-1.0, 1.0, 0.0),
    Vec3::new(0.0, -1.0, -1.0),
];

/// The gradient of the lattice point (i, j, k), each index taken modulo 256
/// (the noise repeats every 256 units): Perlin's hash P[P[P[i] + j] + k] of
/// his fixed permutation P ([`PERLIN_PERMUTATION`]), sums wrapping at 256.
/// Given.
pub fn lattice_gradient(i: i64, j: i64, k: i64) -> Vec3 {
    // Each index reduced first, so no sum can overflow, whatever the indices.
    let p = |n: i64| i64::from(PERLIN_PERMUTATION[n.rem_euclid(256) as usize]);
    let (j, k) = (j.rem_euclid(256), k.rem_euclid(256));
    GRADIENTS[(p(p(p(i) + j) + k) & 15) as usize]
}

/// The largest |noise| can be: 1.0364. The noise is a weighted mean of the
/// corners' g·(p − c), and the largest g·d over the 12 gradients is the sum
/// of d's two largest |components|; the weighted mean of those is at most
/// 1.03635, at p ≈ (0.355, 0.481, ½) in a cell (found numerically; Perlin's
/// own table reaches about 1.004 there). Not 1, as often said. Book §10.3 Noise.
pub const NOISE_BOUND: Float = 1.0364;

/// Perlin's fade curve 6t⁵ − 15t⁴ + 10t³: 0 at 0, 1 at 1, its first and
/// second derivatives 0 at both, so the noise's second derivative is
/// continuous across cell faces (Perlin 2002; his 1985 noise used 3t² − 2t³,
/// whose second derivative jumps). Given.
pub fn fade(t: Float) -> Float {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

/// Gradient noise (Perlin 1985, improved 2002) at p: in the lattice cell
/// whose low corner is ⌊p⌋, each of its 8 corners c contributes g_c·(p − c),
/// g_c its [`lattice_gradient`]; the 8 are interpolated trilinearly with the
/// weights [`fade`] of the fractions (x − ⌊x⌋, …): along x first, then y, then z.
///
/// So the noise is exactly 0 at every lattice point (the corner's own term
/// is g·0, the other weights are fade(0) = 0), continuous with continuous
/// first and second derivatives, and |noise| ≤ [`NOISE_BOUND`]. The
/// floor, not truncation toward zero: `x as i64` puts −0.5 in cell 0
/// instead of −1 (the catalogued mistake). Any finite p, 10³⁰ included,
/// gives a value within the bound and never panics: a huge coordinate's
/// index saturates in `as i64`, so reduce it mod 256 (`rem_euclid`) before
/// adding 1 for the far corner (the lattice repeats every 256 anyway).
/// Book: §10.3 Noise.
pub fn noise(p: Vec3) -> Float {
    // SOLUTION BEGIN
    // The cell and the position in it.
    let cell = p.floor();
    // The lattice repeats every 256: indices mod 256, so i + 1 cannot overflow.
    let wrap = |c: Float| (c as i64).rem_euclid(256);
    let (i, j, k) = (wrap(cell.x), wrap(cell.y), wrap(cell.z));
    let f = p - cell;
    let (u, v, w) = (fade(f.x), fade(f.y), fade(f.z));
    // The corner (i + a, j + b, k + c)'s term g·(p − corner).
    let term = |a: i64, b: i64, c: i64| {
        let offset = Vec3::new(a as Float, b as Float, c as Float);
        lattice_gradient(i + a, j + b, k + c).dot(f - offset)
    };
    let lerp = |t: Float, a: Float, b: Float| a + t * (b - a);
    // Along x on the cell's 4 edges, then y on its 2 faces, then z.
    let (x00, x10) = (lerp(u, term(0, 0, 0), term(1, 0, 0)), lerp(u, term(0, 1, 0), term(1, 1, 0)));
    let (x01, x11) = (lerp(u, term(0, 0, 1), term(1, 0, 1)), lerp(u, term(0, 1, 1), term(1, 1, 1)));
    lerp(w, lerp(v, x00, x10), lerp(v, x01, x11))
    // SOLUTION END
}

/// Fractal noise: the sum of `octaves` octaves of [`noise`], octave k at 2ᵏ
/// times the frequency and 2⁻ᵏ the amplitude,
///
///   N(p) = Σ_{k=0}^{octaves−1} noise(2ᵏ·p) / 2ᵏ,
///
/// as 6.837's `Noise`, `Marble` and `Wood` take it (0 octaves: N = 0). Each
/// octave adds detail half the size and half as strong, so |N| < 2·[`NOISE_BOUND`].
/// Book: §10.3 Noise.
pub fn fractal_noise(p: Vec3, octaves: u32) -> Float {
    // SOLUTION BEGIN
    // Octave k: frequency 2ᵏ, amplitude 2⁻ᵏ (both exact powers of two).
    let mut sum = 0.0;
    let mut scale = 1.0;
    for _ in 0..octaves {
        sum += noise(p * scale) / scale;
        scale *= 2.0;
    }
    sum
    // SOLUTION END
}

/// Marble: veins along x disturbed by noise, the blend value
///
///   s = (1 + sin(frequency·x + amplitude·N(p))) / 2 ∈ [0, 1],
///
/// N the [`fractal_noise`] of `octaves` octaves: 6.837's `Marble`
/// (sin(frequency·x + amplitude·N) remapped from [−1, 1] to [0, 1], the
/// classic form of Perlin 1985). Book: §10.3 Marble and wood.
pub fn marble(p: Vec3, octaves: u32, frequency: Float, amplitude: Float) -> Float {
    // SOLUTION BEGIN
    // The sine's phase, disturbed by the noise, and [−1, 1] mapped to [0, 1].
    let phase = frequency * p.x + amplitude * fractal_noise(p, octaves);
    (1.0 + phase.sin()) / 2.0
    // SOLUTION END
}

/// Wood: rings around the y axis disturbed by noise, the blend value
///
///   s = (1 + sin(frequency·√(x² + z²) + amplitude·N(p))) / 2 ∈ [0, 1],
///
/// marble's form with the distance from the y axis in place of x (the rings
/// of a trunk standing along y). 6.837's `Wood` takes these three
/// parameters; its handout's exact formula is not known here, so raylab
/// chose this classic one (Perlin 1985; Ebert et al., *Texturing and
/// Modeling*) and says so. Book: §10.3 Marble and wood.
pub fn wood(p: Vec3, octaves: u32, frequency: Float, amplitude: Float) -> Float {
    // SOLUTION BEGIN
    // The distance from the y axis, as marble's x.
    let radius = (p.x * p.x + p.z * p.z).sqrt();
    let phase = frequency * radius + amplitude * fractal_noise(p, octaves);
    (1.0 + phase.sin()) / 2.0
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use raylab::random::Rng;

    fn v(x: Float, y: Float, z: Float) -> Vec3 {
        Vec3::new(x, y, z)
    }

    /// Random points in [−8, 8)³ (negative cells included).
    fn points(n: usize) -> Vec<Vec3> {
        let mut rng = Rng::new(10);
        (0..n).map(|_| rng.in_cube(8.0)).collect()
    }

    #[test]
    fn noise_is_exactly_zero_at_every_lattice_point() {
        for i in -3..3 {
            for j in -3..3 {
                for k in [-300, -1, 0, 1, 255, 256] {
                    let p = v(i as Float, j as Float, k as Float);
                    assert_eq!(noise(p), 0.0, "{p}");
                }
            }
        }
    }

    #[test]
    fn noise_by_hand_at_a_cells_centre() {
        // At (½, ½, ½) in cell (0, 0, 0) every weight is fade(½) = ½, so the noise is the mean
        // of the 8 corners' g·(p − c), each a sum of two of (±½) products: by hand from the
        // gradients the hash gives (P[P[P[i] + j] + k] & 15 read off Perlin's table).
        let p = v(0.5, 0.5, 0.5);
        let mut by_hand = 0.0;
        for (a, b, c) in
            [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1), (1, 1, 1)]
        {
            let corner = v(a as Float, b as Float, c as Float);
            by_hand += lattice_gradient(a, b, c).dot(p - corner) / 8.0;
        }
        assert_eq!(noise(p), by_hand);
        // And fade(½) = ½ exactly: 0.125·(0.5·(3 − 15) + 10)·… = ½.
        assert_eq!(fade(0.5), 0.5);
    }

    #[test]
    fn the_hash_repeats_every_256_and_uses_the_floor() {
        // Lattice (i, j, k) and (i + 256, j, k) share a gradient, so the noise repeats.
        for p in points(50) {
            let shifted = noise(p + v(256.0, 0.0, -256.0));
            assert!((noise(p) - shifted).abs() < 1e-4, "{p}: {} vs {shifted}", noise(p));
        }
        // (−0.5, ½, ½) lies in cell −1: its noise is cell −1's, which truncation would get
        // wrong. Cell −1's x-corners are −1 and 0, so the point is at fraction ½ there.
        let p = v(-0.5, 0.5, 0.5);
        let mut by_hand = 0.0;
        for (a, b, c) in
            [(-1, 0, 0), (0, 0, 0), (-1, 1, 0), (0, 1, 0), (-1, 0, 1), (0, 0, 1), (-1, 1, 1), (0, 1, 1)]
        {
            let corner = v(a as Float, b as Float, c as Float);
            by_hand += lattice_gradient(a, b, c).dot(p - corner) / 8.0;
        }
        assert_eq!(noise(p), by_hand);
    }

    #[test]
    fn noise_is_continuous_across_cell_faces_and_within_its_bound() {
        // Either side of a face x = 3, 10⁻³ apart. Along x, each corner's term g·(p − c) is
        // at most |g|·|p − c| ≤ √2·√3 = √6 and changes at rate ≤ |g| = √2, and a weight's
        // rate is at most fade′(½) = 15/8; so |∂noise/∂x| ≤ (15/8)·2·√6 + √2 < 11, and the
        // two sides differ by < 0.011. The wrong cell's corners on one side jump by ~0.1.
        let mut rng = Rng::new(3);
        for _ in 0..200 {
            let (y, z) = (rng.range(0.0, 8.0), rng.range(0.0, 8.0));
            let (left, right) = (noise(v(3.0 - 5e-4, y, z)), noise(v(3.0 + 5e-4, y, z)));
            assert!((left - right).abs() < 0.011, "{left} {right}");
        }
        let biggest = points(20_000).into_iter().map(|p| noise(p).abs()).fold(0.0, Float::max);
        assert!(biggest <= NOISE_BOUND && biggest > 0.5, "{biggest}");
    }

    #[test]
    fn huge_coordinates_give_a_value_within_the_bound_without_panicking() {
        // 10³⁰ has no fraction left in a Float: a lattice point, 0; its index saturates in
        // `as i64`, which an unreduced i + 1 would overflow (found by scaling a scene by 10²⁰).
        for p in [v(1e30, 0.5, 0.5), v(-1e30, 3.25, 1e20), v(Float::MAX, -Float::MAX, 0.5)] {
            let n = noise(p);
            assert!(n.abs() <= NOISE_BOUND, "{p}: {n}");
        }
        assert_eq!(noise(v(1e30, 1e30, 1e30)), 0.0);
        assert_eq!(lattice_gradient(i64::MAX, i64::MAX, i64::MIN), lattice_gradient(255, 255, 0));
    }

    #[test]
    fn octaves_sum_halving_amplitudes() {
        for p in points(100) {
            assert_eq!(fractal_noise(p, 0), 0.0);
            assert_eq!(fractal_noise(p, 1), noise(p));
            let three = noise(p) + noise(2.0 * p) / 2.0 + noise(4.0 * p) / 4.0;
            assert!((fractal_noise(p, 3) - three).abs() <= 4.0 * Float::EPSILON, "{p}");
        }
    }

    #[test]
    fn marble_and_wood_map_their_sines_to_zero_one() {
        // 0 octaves: no noise, so marble is (1 + sin(f·x))/2 and wood (1 + sin(f·r))/2.
        use raylab::math::consts::PI;
        let quarter = 0.5 * PI / 3.0; // f·x = π/2 with f = 3: s = 1
        assert!((marble(v(quarter, 7.0, -2.0), 0, 3.0, 5.0) - 1.0).abs() < 1e-6);
        assert!((marble(v(-quarter, 7.0, -2.0), 0, 3.0, 5.0)).abs() < 1e-6);
        // r = 5 from (3, y, 4): f·r = π/2 with f = π/10.
        assert!((wood(v(3.0, -9.0, 4.0), 0, PI / 10.0, 2.0) - 1.0).abs() < 1e-6);
        for p in points(2000) {
            for s in [marble(p, 5, 3.0, 2.0), wood(p, 5, 7.0, 2.0)] {
                assert!((0.0..=1.0).contains(&s), "{p}: {s}");
            }
            // Wood depends on y only through the noise: with no noise, rings stand along y.
            assert_eq!(wood(p, 0, 6.0, 2.0), wood(v(p.x, p.y + 3.0, p.z), 0, 6.0, 2.0));
        }
    }
}
