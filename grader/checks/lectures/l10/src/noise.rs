//! The checks of `noise.rs`: noise, fractal_noise, marble and wood.
//!
//! The expected values come from Perlin's own formulation of improved noise (his 2002
//! reference code: the permutation doubled to 512 entries, the gradient picked by bit tests
//! on the hash), computed here in f64: not the lecture's gradient table and wrapped hash.
//! Tolerances are multiples of the student's precision ε, derived below; the reference's
//! worst errors are measured in this module's tests.

use raylab::random::PERLIN_PERMUTATION;

use super::common::*;

/// How the expected noise is computed: the right way, or with one of the mistakes a check
/// names when the student's values match it instead.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Variant {
    Right,
    /// Linear weights: the fractions themselves, no fade curve.
    Linear,
    /// Perlin 1985's fade 3t² − 2t³.
    Cubic,
    /// The cell by truncation toward zero, not the floor.
    Truncated,
}

/// Perlin's doubled permutation: p[i] = P[i mod 256] for i < 512.
fn p(i: usize) -> usize {
    usize::from(PERLIN_PERMUTATION[i % 256])
}

/// Perlin's grad(hash, x, y, z): the low 4 bits of the hash pick two of ±x, ±y, ±z.
fn grad(hash: usize, x: f64, y: f64, z: f64) -> f64 {
    let h = hash & 15;
    let u = if h < 8 { x } else { y };
    let v = if h < 4 {
        y
    } else if h == 12 || h == 14 {
        x
    } else {
        z
    };
    (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
}

/// Improved noise at (x, y, z) in f64, as Perlin's reference computes it, or with `variant`.
fn perlin(x: f64, y: f64, z: f64, variant: Variant) -> f64 {
    let cell = |c: f64| if variant == Variant::Truncated { c.trunc() } else { c.floor() };
    let (fx, fy, fz) = (cell(x), cell(y), cell(z));
    // The lattice index mod 256, for negative cells too.
    let index = |c: f64| (c as i64).rem_euclid(256) as usize;
    let (xi, yi, zi) = (index(fx), index(fy), index(fz));
    let (x, y, z) = (x - fx, y - fy, z - fz);
    let fade = |t: f64| match variant {
        Variant::Linear => t,
        Variant::Cubic => t * t * (3.0 - 2.0 * t),
        _ => t * t * t * (t * (t * 6.0 - 15.0) + 10.0),
    };
    let (u, v, w) = (fade(x), fade(y), fade(z));
    let lerp = |t: f64, a: f64, b: f64| a + t * (b - a);
    let a = p(xi) + yi;
    let (aa, ab) = (p(a) + zi, p(a + 1) + zi);
    let b = p(xi + 1) + yi;
    let (ba, bb) = (p(b) + zi, p(b + 1) + zi);
    lerp(
        w,
        lerp(
            v,
            lerp(u, grad(p(aa), x, y, z), grad(p(ba), x - 1.0, y, z)),
            lerp(u, grad(p(ab), x, y - 1.0, z), grad(p(bb), x - 1.0, y - 1.0, z)),
        ),
        lerp(
            v,
            lerp(u, grad(p(aa + 1), x, y, z - 1.0), grad(p(ba + 1), x - 1.0, y, z - 1.0)),
            lerp(u, grad(p(ab + 1), x, y - 1.0, z - 1.0), grad(p(bb + 1), x - 1.0, y - 1.0, z - 1.0)),
        ),
    )
}

fn wide(p: Vec3) -> (f64, f64, f64) {
    (p.x as f64, p.y as f64, p.z as f64)
}

/// The expected noise at p.
fn expected_noise(p: Vec3) -> f64 {
    let (x, y, z) = wide(p);
    perlin(x, y, z, Variant::Right)
}

/// Σ_{k<octaves} noise(2ᵏp)/2ᵏ in f64, each term scaled by `amplitude(k)` and at frequency
/// `frequency(k)` (the right sum: 2⁻ᵏ and 2ᵏ).
fn octave_sum(p: Vec3, octaves: u32, frequency: &dyn Fn(u32) -> f64, amplitude: &dyn Fn(u32) -> f64) -> f64 {
    let (x, y, z) = wide(p);
    (0..octaves)
        .map(|k| {
            let f = frequency(k);
            amplitude(k) * perlin(f * x, f * y, f * z, Variant::Right)
        })
        .sum()
}

fn expected_fractal(p: Vec3, octaves: u32) -> f64 {
    octave_sum(p, octaves, &|k| 2f64.powi(k as i32), &|k| 2f64.powi(-(k as i32)))
}

/// Noise's error bound in the student's precision: the fractions are exact (p − ⌊p⌋), each
/// corner term g·(p − c) a sum of two exact numbers (one rounding), the fade a few roundings
/// of a value in [0, 1], and each of the 7 lerps three roundings, a weight's error of ~5ε
/// multiplied by a difference of terms up to 4: about 3 levels × (20 + 3)ε < 70ε. 96ε leaves
/// room; the reference's worst is measured in the tests (under 10ε). Mistakes are off by 10⁻².
const NOISE_TOLERANCE: f64 = 96.0 * EPS as f64;

/// Random points in [−8, 8)³ (negative cells included) and a few chosen ones.
fn sample_points() -> Vec<Vec3> {
    let mut rng = Rng::new(1985);
    let mut points: Vec<Vec3> = (0..2000).map(|_| rng.in_cube(8.0)).collect();
    points.extend([
        v3(-0.5, 0.5, 0.5),
        v3(0.25, -0.75, 0.5),
        v3(-3.3, -7.1, -0.2),
        v3(255.5, 0.5, 0.25),
        v3(-300.25, 17.5, 3.75),
        // No fraction left, and cell indices that saturate `as i64`: an unreduced i + 1
        // overflows (a panic in a debug build).
        v3(1e30, 0.5, 0.5),
        v3(-1e30, 3.25, 1e20),
    ]);
    points
}

/// What a student's noise that misses `expected` at p matches instead.
fn noise_cause(got: Float, p: Vec3) -> &'static str {
    let (x, y, z) = wide(p);
    let near = |variant| (got as f64 - perlin(x, y, z, variant)).abs() <= NOISE_TOLERANCE;
    if near(Variant::Linear) {
        "weight the corners with the fade curve 6t⁵ − 15t⁴ + 10t³ of each fraction, not the fraction itself"
    } else if near(Variant::Cubic) {
        "the fade is Perlin's 2002 curve 6t⁵ − 15t⁴ + 10t³, not 1985's 3t² − 2t³"
    } else if near(Variant::Truncated) {
        "the cell is the floor ⌊p⌋: `x as i64` truncates −0.5 to 0, the wrong cell for negative coordinates"
    } else {
        "each corner c of the cell ⌊p⌋ contributes lattice_gradient(c)·(p − c), weighted by fade of the \
         fractions, interpolated along x, then y, then z"
    }
}

pub(super) fn noise_cases(noise: NoiseFn) -> CheckResult {
    // Lattice points: the corner's own term is g·0 and every other weight fade(0) = 0.
    for (i, j, k) in [(0, 0, 0), (1, 2, 3), (-1, -1, -1), (-5, 3, 255), (256, -256, 7), (-300, 0, 1)] {
        let p = v3(i as Float, j as Float, k as Float);
        let got = noise(p);
        ensure(
            got == 0.0,
            lazy(|f| write!(f, "noise at the lattice point {}", vec3(p))),
            "0 exactly",
            lazy(|f| f.write_str(&num(got))),
            "at a lattice point the corner's own term is g·0 and the other corners weigh fade(0) = 0",
        )?;
    }
    // Continuous across cell faces: either side of x = 3, y = −2 or z = 5, 10⁻³ apart, the
    // values differ by less than 0.011 (|∂noise/∂x| < (15/8)·2·√6 + √2 < 11, §10.3); the
    // wrong cell's corners on one side (a seam) jump by ~0.1.
    let mut rng = Rng::new(2002);
    for n in 0..300 {
        let (a, b) = (rng.range(-8.0, 8.0), rng.range(-8.0, 8.0));
        let side = |t: Float| match n % 3 {
            0 => v3(3.0 + t, a, b),
            1 => v3(a, -2.0 + t, b),
            _ => v3(a, b, 5.0 + t),
        };
        let (p0, p1) = (side(-5e-4), side(5e-4));
        let (before, after) = (noise(p0), noise(p1));
        // The side that is wrong names the mistake, if it is a known one.
        let off = |got: Float, p: Vec3| (got as f64 - expected_noise(p)).abs() > NOISE_TOLERANCE;
        let cause = match (off(before, p0), off(after, p1)) {
            (true, _) => noise_cause(before, p0),
            (_, true) => noise_cause(after, p1),
            _ => {
                "a cell's corners are shared with its neighbours: take the cell and the fractions from one ⌊p⌋"
            }
        };
        ensure(
            (before - after).abs() < 0.011,
            lazy(|f| write!(f, "noise either side of a cell face, at {} and {}", vec3(p0), vec3(p1))),
            "values within 0.011 of each other (the noise is continuous)",
            lazy(|f| write!(f, "{} and {}", num(before), num(after))),
            cause,
        )?;
    }
    let points = sample_points();
    let mut worst: f64 = 0.0;
    for &p in &points {
        let (got, expected) = (noise(p), expected_noise(p));
        let case = lazy(|f| write!(f, "noise at {}", vec3(p)));
        let (shown, cause) = (lazy(|f| f.write_str(&num(got))), lazy(|f| f.write_str(noise_cause(got, p))));
        // The bound any table of edge gradients allows (l10's NOISE_BOUND), derived in §10.3.
        ensure(got.abs() <= 1.0364, &case, "a value in [−1.0364, 1.0364]", &shown, &cause)?;
        let error = (got as f64 - expected).abs();
        let wanted = lazy(|f| f.write_str(&num(expected as Float)));
        ensure(error <= NOISE_TOLERANCE, &case, wanted, &shown, &cause)?;
        worst = worst.max(error);
    }
    Ok(format!(
        "6 lattice points, 300 cell faces, {} others (worst error {:.1}ε)",
        points.len(),
        worst / EPS as f64
    ))
}

pub(super) fn fractal_cases(fractal_noise: FractalFn) -> CheckResult {
    let points = sample_points();
    for &p in points.iter().take(20) {
        let got = fractal_noise(p, 0);
        ensure(
            got == 0.0,
            lazy(|f| write!(f, "fractal_noise at {} with 0 octaves", vec3(p))),
            "0",
            lazy(|f| f.write_str(&num(got))),
            "no octaves sum to 0",
        )?;
    }
    for &p in points.iter().take(500) {
        for octaves in [1, 2, 5, 8] {
            let (got, expected) = (fractal_noise(p, octaves) as f64, expected_fractal(p, octaves));
            // Each octave's noise within NOISE_TOLERANCE, the sum's roundings one ε per octave.
            let tolerance = 2.0 * NOISE_TOLERANCE + octaves as f64 * 2.0 * EPS as f64;
            // The known mistakes' sums, computed only to name a failure's cause.
            let cause = lazy(|f| {
                let doubled = octave_sum(p, octaves, &|k| 2f64.powi(k as i32), &|k| 2f64.powi(k as i32));
                let unscaled = octave_sum(p, octaves, &|_| 1.0, &|k| 2f64.powi(-(k as i32)));
                let near = |x: f64| (got - x).abs() <= tolerance;
                f.write_str(if near(doubled) {
                    "octave k is 2ᵏ times finer and 2ᵏ times weaker: divide its noise by 2ᵏ, not multiply"
                } else if near(unscaled) {
                    "octave k samples the noise at 2ᵏ·p: each octave adds detail half the size"
                } else if near(expected_fractal(p, octaves + 1)) {
                    "`octaves` octaves, k = 0 … octaves − 1"
                } else {
                    "N(p) = Σ_{k=0}^{octaves−1} noise(2ᵏ·p) / 2ᵏ"
                })
            });
            ensure(
                (got - expected).abs() <= tolerance,
                lazy(|f| write!(f, "fractal_noise at {} with {octaves} octaves", vec3(p))),
                lazy(|f| f.write_str(&num(expected as Float))),
                lazy(|f| f.write_str(&num(got as Float))),
                cause,
            )?;
        }
    }
    Ok("0 octaves at 20 points; 1, 2, 5 and 8 octaves at 500".into())
}

/// A distance a student may take in place of the right one, and the cause to name.
type WrongDistance = (fn(Vec3) -> f64, &'static str);

/// Marble's or wood's expected blend value, and the ones of the likely mistakes.
struct Vein {
    what: &'static str,
    /// The sine's argument but for the noise: frequency·x (marble) or frequency·r (wood).
    along: fn(Vec3) -> f64,
    /// The wrong distances students take, with the cause to name.
    wrong: &'static [WrongDistance],
}

const MARBLE: Vein = Vein {
    what: "marble",
    along: |p| p.x as f64,
    wrong: &[(|p| p.y as f64, "marble's veins run along x: sin(frequency·x + amplitude·N)")],
};

const WOOD: Vein = Vein {
    what: "wood",
    along: |p| (p.x as f64).hypot(p.z as f64),
    wrong: &[
        (|p| (p.x as f64).hypot(p.y as f64), "the rings are around the y axis: r = √(x² + z²)"),
        (|p| (p.x as f64).powi(2) + (p.z as f64).powi(2), "r is the distance √(x² + z²), not its square"),
        (|p| p.x as f64, "wood takes the distance from the y axis, √(x² + z²), where marble takes x"),
    ],
};

fn vein_cases(vein: &Vein, f: &dyn Fn(Vec3, u32, Float, Float) -> Float) -> CheckResult {
    let points = sample_points();
    let mut cases = 0;
    for (n, &p) in points.iter().take(600).enumerate() {
        let (octaves, frequency, amplitude) = [(0, 3.0, 2.0), (5, 3.0, 2.0), (3, 7.0, 4.0)][n % 3];
        let got = f(p, octaves, frequency as Float, amplitude as Float) as f64;
        let noise = expected_fractal(p, octaves);
        let phase = |along: f64| frequency * along + amplitude * noise;
        let expected = (1.0 + phase((vein.along)(p)).sin()) / 2.0;
        // The phase's error: amplitude times the octave sum's, and a few ε of frequency·r
        // (up to ~80); sin passes it on at most once, the map halves it.
        let tolerance =
            (amplitude * 2.0 * NOISE_TOLERANCE / EPS as f64 + 4.0 * phase((vein.along)(p)).abs() + 8.0)
                * EPS as f64;
        let near = |x: f64| (got - x).abs() <= tolerance;
        let along = (vein.along)(p);
        let cause = if near(phase(along).sin()) {
            "map sin's [−1, 1] to [0, 1]: s = (1 + sin(…))/2"
        } else if near((1.0 - phase(along).sin()) / 2.0) {
            "s = (1 + sin(…))/2: s = 0 is the first material"
        } else if near((1.0 + phase(along).cos()) / 2.0) {
            "the sine, not the cosine"
        } else if let Some((_, cause)) =
            vein.wrong.iter().find(|(wrong, _)| near((1.0 + phase(wrong(p)).sin()) / 2.0))
        {
            cause
        } else if near((1.0 + (frequency * along + amplitude * expected_noise(p)).sin()) / 2.0) && octaves > 1
        {
            "the noise is the fractal sum of `octaves` octaves (fractal_noise), not one octave"
        } else {
            "s = (1 + sin(frequency·x + amplitude·N(p)))/2, N the fractal noise of `octaves` octaves \
             (wood: the distance √(x² + z²) in place of x)"
        };
        ensure(
            (0.0..=1.0).contains(&got) && (got - expected).abs() <= tolerance,
            format!(
                "{} at {} with {octaves} octaves, frequency {frequency}, amplitude {amplitude}",
                vein.what,
                vec3(p)
            ),
            num(expected as Float),
            num(got as Float),
            cause,
        )?;
        cases += 1;
    }
    Ok(format!("{cases} points at three settings, with and without noise"))
}

pub(super) fn marble_cases(marble: VeinFn) -> CheckResult {
    vein_cases(&MARBLE, &marble)
}

pub(super) fn wood_cases(wood: VeinFn) -> CheckResult {
    vein_cases(&WOOD, &wood)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lecture's reference, within the stated tolerance with room to spare.
    #[test]
    fn the_reference_noise_is_within_a_quarter_of_the_tolerance() {
        let worst = sample_points()
            .into_iter()
            .map(|p| (l10_textures_sampling::noise(p) as f64 - expected_noise(p)).abs())
            .fold(0.0, f64::max);
        eprintln!("the reference noise's worst error: {:.2}ε", worst / EPS as f64);
        assert!(worst <= NOISE_TOLERANCE / 4.0, "{worst}");
    }

    #[test]
    fn perlins_formulation_agrees_with_the_definition_by_hand() {
        // At (½, ½, ½) in cell 0 every weight is ½: the mean of the 8 corner terms, each
        // grad(P[P[P[i] + j] + k], …) by hand from the table.
        let by_hand: f64 =
            [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1), (1, 1, 1)]
                .iter()
                .map(|&(i, j, k)| {
                    let hash = p(p(p(i) + j) + k);
                    grad(hash, 0.5 - i as f64, 0.5 - j as f64, 0.5 - k as f64) / 8.0
                })
                .sum();
        assert_eq!(perlin(0.5, 0.5, 0.5, Variant::Right), by_hand);
        // And 0 at lattice points, negative ones included.
        assert_eq!(perlin(-3.0, 4.0, -1.0, Variant::Right), 0.0);
    }
}
