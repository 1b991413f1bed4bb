//! The refraction pair: lecture 07's `refract` against two naive forms of
//! Snell's law, at the critical angle ± 0.001°, where sin²θ_t rounds to
//! exactly 1, and at normal incidence.

use std::hint::black_box;

use l07_reflection_refraction::refract;
use raylab::random::Rng;
use raylab::{Float, Vec3};

use super::reference::{angle, dot, unit};
use super::row::{Pair, Row, own_precision};
use super::timing::{Effort, time_per_item};
use raylab_testing::{wide, wide3};

type Refract = fn(Vec3, Vec3, Float) -> Option<Vec3>;

/// The catalogued naive refraction with the strict test: cos θ_i = −i·n
/// without the clamp to [0, 1], sin²θ_t = η²(1 − cos²θ_i), total internal
/// reflection only when sin²θ_t > 1.
///
/// Where sin²θ_t rounds to exactly 1 (θ_t = 90°) it returns cos θ_t = 0 and
/// t = η·i + η·cos θ_i·n, a ray along the surface that never crosses it
/// (t·n = 0). `i` and `n` unit, n facing against i, η = η_i/η_t.
/// Book: §7.3 Total internal reflection.
pub fn refract_strict(i: Vec3, n: Vec3, eta_ratio: Float) -> Option<Vec3> {
    let cos_i = -i.dot(n);
    let sin2_t = eta_ratio * eta_ratio * (1.0 - cos_i * cos_i);
    if sin2_t > 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    Some(eta_ratio * i + (eta_ratio * cos_i - cos_t) * n)
}

/// The naive refraction through the sines, as Snell's law is first written:
/// sin θ_i = √(1 − cos²θ_i) with cos θ_i = −i·n unclamped, sin θ_t = η·sin θ_i,
/// total internal reflection when sin θ_t > 1, cos θ_t = √(1 − sin²θ_t).
///
/// At normal incidence rounding puts |i·n| above 1 about half the time
/// (|n|² = 1 ± a few ε), the first square root takes a negative number and
/// the NaN goes through the comparison (NaN > 1 is false) into t.
/// Book: §7.2 Snell's law and the refracted ray.
pub fn refract_via_sines(i: Vec3, n: Vec3, eta_ratio: Float) -> Option<Vec3> {
    let cos_i = -i.dot(n);
    let sin_t = eta_ratio * (1.0 - cos_i * cos_i).sqrt();
    if sin_t > 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    Some(eta_ratio * i + (eta_ratio * cos_i - cos_t) * n)
}

/// The naive forms first, the reference method last.
pub const VARIANTS: [(&str, Refract); 3] =
    [("strict_tir", refract_strict), ("via_sines", refract_via_sines), ("refract", refract)];

/// The ratios η = η_i/η_t of the critical-angle case (water, glass, diamond to air).
pub const CRITICAL_ETAS: [f64; 3] = [1.33, 1.5, 2.4];

/// How far from the critical angle the incoming rays are, in degrees.
pub const CRITICAL_OFFSET_DEGREES: f64 = 1e-3;

/// The largest angle error in radians that passes. Near the critical angle
/// cos θ_t ≈ 5.5·10⁻³ (η = 1.33, 0.001° below), and an absolute error of a few ε
/// in sin²θ_t moves θ_t by about that over 2 cos²θ_t: ~10⁻⁴ rad in f32. A tenth of
/// a degree (1.7·10⁻³ rad) is ten times that; a wrong formula is off by far more.
pub const MAX_ANGLE_ERROR: f64 = 1.7e-3;

/// One incoming direction and normal, with what the ground truth says of them.
struct Case {
    i: Vec3,
    n: Vec3,
    eta: Float,
    /// Total internal reflection by the f64 ground truth, if it is judged here.
    tir: Option<bool>,
    /// The transmitted direction by the f64 ground truth, if it is judged here.
    t: Option<[f64; 3]>,
}

/// Snell's law in f64 on the directions as the `Float` values are (each
/// normalised in f64): `None` on total internal reflection (sin²θ_t ≥ 1),
/// else the unit transmitted direction.
pub fn refract_f64(i: Vec3, n: Vec3, eta: Float) -> Option<[f64; 3]> {
    let (i, n, eta) = (unit(wide3(i)), unit(wide3(n)), wide(eta));
    let cos_i = -dot(i, n);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    Some([0, 1, 2].map(|k| eta * i[k] + (eta * cos_i - cos_t) * n[k]))
}

/// A judged case: the truth from [`refract_f64`].
fn judged(i: Vec3, n: Vec3, eta: Float) -> Case {
    let t = refract_f64(i, n, eta);
    Case { i, n, eta, tir: Some(t.is_none()), t }
}

/// Rays at θ_c ± 0.001° onto random planes (random normal, random azimuth), η
/// from [`CRITICAL_ETAS`] in turn: half just below θ_c (a ray leaving nearly
/// along the surface), half just above (total internal reflection). The
/// margin, |sin²θ_t − 1| ≥ 3·10⁻⁵, is hundreds of f32 roundings: the truth is
/// clear.
fn critical_cases(count: usize, seed: u64) -> Vec<Case> {
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|k| {
            let eta = CRITICAL_ETAS[k % CRITICAL_ETAS.len()];
            let critical = (1.0 / eta).asin();
            let offset = CRITICAL_OFFSET_DEGREES.to_radians();
            let theta = if k % 2 == 0 { critical - offset } else { critical + offset };
            let n = rng.unit_vector();
            let (a, b) = n.any_orthonormal_pair();
            let phi = rng.range(0.0, std::f64::consts::TAU as Float);
            let tangent = phi.cos() * a + phi.sin() * b;
            let i = (theta.sin() as Float * tangent - theta.cos() as Float * n).normalize();
            judged(i, n, eta as Float)
        })
        .collect()
}

/// Normal incidence: i = −n for random unit n (rounding leaves |i·n| a few ε
/// above or below 1), η from 1/2.4 to 2.4. The truth: no reflection, t = −n.
fn normal_cases(count: usize, seed: u64) -> Vec<Case> {
    let mut rng = Rng::new(seed);
    let etas = [1.0 / 2.4, 1.0 / 1.5, 1.0, 1.5, 2.4];
    (0..count)
        .map(|k| {
            let n = rng.unit_vector();
            judged(-n, n, etas[k % etas.len()])
        })
        .collect()
}

/// sin²θ_t = (η·η)(1 − cos θ_i·cos θ_i) rounding to exactly 1 (lecture 07's
/// construction): cos θ_i = k/64, so 1 − cos²θ_i is exact, η among the 17
/// floats nearest 1/sin θ_i, kept when the product is 1; each in the six
/// axis-aligned orientations (n = ±x, ±y, ±z, i with the same components
/// permuted, so i·n = −cos θ_i exactly). θ_t = 90°: no transmitted ray. Here the
/// contract is the truth (f64 puts the exact product a few 10⁻⁸ either side of
/// 1), so only a transmitted ray that does not cross the surface is judged.
fn exact_one_cases() -> Vec<Case> {
    let mut cases = Vec::new();
    for k in 1..64 {
        let cos_i = k as Float / 64.0;
        let sin2_i = 1.0 - cos_i * cos_i;
        let nearest = 1.0 / sin2_i.sqrt();
        for step in -8i64..=8 {
            let eta = Float::from_bits((nearest.to_bits() as i64 + step) as _);
            if eta * eta * sin2_i != 1.0 {
                continue;
            }
            for axis in 0..3 {
                for sign in [1.0, -1.0] {
                    let mut n = [0.0; 3];
                    n[axis] = sign;
                    let mut i = [0.0; 3];
                    i[axis] = -sign * cos_i;
                    i[(axis + 1) % 3] = sin2_i.sqrt();
                    let (n, i) = (Vec3::from_array(n), Vec3::from_array(i));
                    cases.push(Case { i, n, eta, tir: None, t: None });
                }
            }
        }
    }
    cases
}

/// What a variant got wrong on a set of cases.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Errors {
    /// Results holding a NaN.
    pub nans: usize,
    /// Total internal reflection where the truth transmits, or the reverse.
    pub wrong_tir: usize,
    /// Transmitted rays that do not cross the surface (t·n ≥ 0).
    pub not_crossing: usize,
    /// The largest angle between a transmitted ray and the truth, in radians (NaN when a NaN
    /// result was compared).
    pub max_angle: f64,
}

fn judge(refract: Refract, cases: &[Case]) -> Errors {
    let mut errors = Errors::default();
    for case in cases {
        let got = refract(case.i, case.n, case.eta);
        if let Some(t) = got {
            errors.nans += usize::from(!t.is_finite());
            errors.not_crossing += usize::from(t.dot(case.n) >= 0.0);
        }
        if let Some(tir) = case.tir {
            errors.wrong_tir += usize::from(got.is_none() != tir);
        }
        if let (Some(t), Some(truth)) = (got, case.t) {
            let error = angle(wide3(t), truth);
            errors.max_angle = if error.is_nan() { f64::NAN } else { errors.max_angle.max(error) };
        }
    }
    errors
}

/// The row's verdict: any NaN, wrong decision or ray along the surface, or an angle error
/// above [`MAX_ANGLE_ERROR`] (a NaN angle included).
pub fn fails(errors: &Errors) -> bool {
    errors.nans > 0
        || errors.wrong_tir > 0
        || errors.not_crossing > 0
        || errors.max_angle.is_nan()
        || errors.max_angle > MAX_ANGLE_ERROR
}

/// Every variant on every case: NaNs, wrong TIR decisions, rays that do not cross, max angle
/// error, ns per call.
pub fn measure(effort: &Effort) -> Vec<Row> {
    let cases = [
        ("critical angle ± 0.001°", critical_cases(effort.samples, 0x7c_0001), true),
        ("normal incidence", normal_cases(effort.samples, 0x7c_0002), true),
        ("sin²θ_t rounds to 1", exact_one_cases(), false),
    ];
    let mut rows = Vec::new();
    for (case, list, against_truth) in cases {
        for (name, refract) in VARIANTS {
            let errors = judge(refract, &list);
            let time = time_per_item(effort, list.len(), || {
                for case in &list {
                    black_box(refract(black_box(case.i), case.n, case.eta));
                }
            });
            let mut metrics = vec![("NaN".to_string(), errors.nans as f64)];
            if against_truth {
                metrics.push(("wrong TIR".into(), errors.wrong_tir as f64));
            }
            metrics.push(("t·n ≥ 0".into(), errors.not_crossing as f64));
            if against_truth {
                metrics.push(("max angle error rad".into(), errors.max_angle));
            }
            rows.push(Row {
                pair: Pair::Refraction,
                case: format!("{case} ({} rays)", list.len()),
                variant: name.to_string(),
                precision: own_precision().to_string(),
                time,
                metrics,
                fails: fails(&errors),
                pareto: false,
            });
        }
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_cases_are_what_they_say() {
        // Critical angle: the truth alternates (below, above) by construction, as the
        // margin 3·10⁻⁵ of sin²θ_t is far beyond the rounding of i and n.
        let critical = critical_cases(60, 1);
        for (k, case) in critical.iter().enumerate() {
            assert_eq!(case.tir, Some(k % 2 == 1), "case {k}");
        }
        // Normal incidence never reflects; its truth is −n.
        for case in normal_cases(20, 2) {
            assert_eq!(case.tir, Some(false));
            assert!(angle(case.t.unwrap(), wide3(-case.n)) < 1e-12);
        }
        // Lecture 07 measured 28 (f32) and 32 (f64) rounding-to-1 cases in one orientation.
        let ones = exact_one_cases();
        assert!(ones.len() >= 6 * 10, "{}", ones.len());
        for case in &ones {
            let cos_i = -case.i.dot(case.n);
            assert_eq!(case.eta * case.eta * (1.0 - cos_i * cos_i), 1.0, "{:?} {:?}", case.i, case.n);
        }
    }

    #[test]
    fn a_reduced_run_fails_each_naive_form_and_passes_the_reference() {
        // In f32 and f64 alike: `>` sends rays along the surface where sin²θ_t rounds to 1,
        // and the first square root of the sines takes 1 − cos²θ_i < 0 at normal incidence.
        let effort = Effort { samples: 400, runs: 1, min_batch: std::time::Duration::ZERO, ..Effort::QUICK };
        let rows = measure(&effort);
        let row = |case: &str, variant: &str| {
            rows.iter().find(|r| r.case.starts_with(case) && r.variant == variant).unwrap()
        };
        for r in rows.iter().filter(|r| r.variant == "refract") {
            assert!(!r.fails, "{r:#?}");
        }
        let strict = row("sin²θ_t rounds to 1", "strict_tir");
        assert!(strict.fails && strict.metric("t·n ≥ 0").unwrap() > 0.0, "{strict:#?}");
        let sines = row("normal incidence", "via_sines");
        assert!(sines.fails && sines.metric("NaN").unwrap() > 0.0, "{sines:#?}");
        // ± 0.001° is far from rounding: every form decides right there.
        for r in rows.iter().filter(|r| r.case.starts_with("critical")) {
            assert_eq!(r.metric("wrong TIR"), Some(0.0), "{r:#?}");
        }
    }
}
