//! The tiny glass sphere: lecture 06's three ray origins used to start the
//! refracted ray inside a glass sphere of radius 10⁻⁵, judged by where that
//! ray leaves the sphere.

use std::hint::black_box;

use l02_ray_casting::hit_sphere_stable;
use l07_reflection_refraction::{interface, refract};
use raylab::random::Rng;
use raylab::{Float, Hit, Interval, Ray, Vec3};

use super::offsets::VARIANTS;
use super::reference::{dot, unit};
use super::row::{Pair, Row, own_precision};
use super::timing::{Effort, time_per_item};
use raylab_testing::{wide, wide3};

/// The sphere's radius.
pub const RADIUS: Float = 1e-5;

/// The index of refraction of the glass.
pub const IOR: Float = 1.5;

/// An exit farther than this many radii from the truth is wrong. The f32 error
/// of a hit point is a few ulp of the eye's coordinates (at 0.1, ulp = 7.5·10⁻⁹,
/// 10⁻³ r) and the scaled offset is 8ε(|p|₁ + |eye|₁) ≈ 0.02 r with the eye at
/// 0.1; a tenth of a radius is several times both, far below the radius that a
/// start outside the sphere or past it is off by.
pub const MAX_EXIT_ERROR: f64 = 0.1;

/// One ray into the sphere, refracted at its entry, with the f64 truth of its exit.
struct Entry {
    /// The eye the ray came from (the `from` of the offset).
    eye: Vec3,
    /// The entry hit (normal facing the incoming ray, so outward).
    hit: Hit,
    /// The refracted direction into the glass.
    inside: Vec3,
    /// Where the chord from the true entry along the true refracted direction ends, in f64.
    exit: [f64; 3],
}

/// The ray from `eye` along `d` through the sphere (the origin, `RADIUS`) in
/// f64: the entry by the geometric root, Snell's law with η = 1/ior, and the
/// end of the chord, whose length is −2(t·n)·r for the unit refracted t and
/// the outward unit n at the entry.
pub fn exit_f64(eye: Vec3, d: Vec3) -> Option<[f64; 3]> {
    let (o, d, r, eta) = (wide3(eye), unit(wide3(d)), wide(RADIUS), 1.0 / wide(IOR));
    let t_ca = -dot(o, d);
    let closest = [0, 1, 2].map(|k| o[k] + t_ca * d[k]);
    let h2 = r * r - dot(closest, closest);
    if h2 < 0.0 {
        return None;
    }
    let entry = [0, 1, 2].map(|k| o[k] + (t_ca - h2.sqrt()) * d[k]);
    let n = entry.map(|x| x / r);
    let cos_i = -dot(d, n);
    let cos_t = (1.0 - eta * eta * (1.0 - cos_i * cos_i)).sqrt();
    let inside = [0, 1, 2].map(|k| eta * d[k] + (eta * cos_i - cos_t) * n[k]);
    let chord = -2.0 * dot(inside, n) * r;
    Some([0, 1, 2].map(|k| entry[k] + chord * inside[k]))
}

/// `count` rays from eyes in random directions at `distance(rng)` from the
/// sphere's centre, aimed at random points of the disc of radius 0.95 r
/// across the view, with their entries found and refracted by lectures 02 and
/// 07 (rays whose entry is missed in `Float` are drawn again).
fn entries(count: usize, seed: u64, distance: impl Fn(&mut Rng) -> Float) -> Vec<Entry> {
    let mut rng = Rng::new(seed);
    let mut found = Vec::with_capacity(count);
    while found.len() < count {
        let eye = rng.unit_vector() * distance(&mut rng);
        let toward = -eye.normalize();
        let across = rng.in_ball(0.95 * RADIUS);
        let aim = across - across.dot(toward) * toward;
        let d = (aim - eye).normalize();
        let (Some(hit), Some(exit)) =
            (hit_sphere_stable(&Ray::new(eye, d), Vec3::ZERO, RADIUS, Interval::POSITIVE), exit_f64(eye, d))
        else {
            continue;
        };
        let into = interface(&hit, IOR);
        let inside = refract(d, into.normal, into.eta_ratio()).expect("air to glass always refracts");
        found.push(Entry { eye, hit, inside, exit });
    }
    found
}

/// The exit found from `origin` along the refracted direction: the first hit
/// from inside (a back face), if any.
fn exit(entry: &Entry, origin: Vec3) -> Option<Hit> {
    hit_sphere_stable(&Ray::new(origin, entry.inside), Vec3::ZERO, RADIUS, Interval::POSITIVE)
        .filter(|h| !h.front_face)
}

/// The distance of the exit found from the truth, in radii (∞ for none).
fn exit_error(entry: &Entry, found: Option<Hit>) -> f64 {
    found.map_or(f64::INFINITY, |h| {
        let p = wide3(h.point);
        let d = [0, 1, 2].map(|k| p[k] - entry.exit[k]);
        dot(d, d).sqrt() / wide(RADIUS)
    })
}

/// Every offset on eyes 2–10 r away and 0.1 away: wrong exits %, no exit from inside %, max
/// exit error in radii over the exits found, ns per offset and exit ray.
pub fn measure(effort: &Effort) -> Vec<Row> {
    let cases: [(&str, Vec<Entry>); 2] = [
        ("eyes 2–10 r away", entries(effort.samples, 0x61_a55, |rng| rng.range(2.0, 10.0) * RADIUS)),
        ("eyes 0.1 away (1e4 r)", entries(effort.samples, 0x61_a56, |_| 0.1)),
    ];
    let mut rows = Vec::new();
    for (case, list) in cases {
        for (name, offset) in VARIANTS {
            let (mut wrong, mut none, mut worst) = (0usize, 0usize, None::<f64>);
            for entry in &list {
                let origin = offset(entry.hit.point, entry.hit.normal, entry.inside, entry.eye);
                let found = exit(entry, origin);
                let error = exit_error(entry, found);
                none += usize::from(found.is_none());
                wrong += usize::from(error.is_nan() || error > MAX_EXIT_ERROR);
                if error.is_finite() {
                    worst = Some(worst.map_or(error, |w| w.max(error)));
                }
            }
            let time = time_per_item(effort, list.len(), || {
                for entry in &list {
                    let origin = offset(entry.hit.point, entry.hit.normal, entry.inside, entry.eye);
                    black_box(exit(black_box(entry), origin));
                }
            });
            let percent = |k: usize| 100.0 * k as f64 / list.len().max(1) as f64;
            let mut metrics = vec![
                ("wrong exit %".to_string(), percent(wrong)),
                ("no exit from inside %".into(), percent(none)),
            ];
            // Over the exits found (left blank when there are none).
            metrics.extend(worst.map(|w| ("max exit error r".to_string(), w)));
            rows.push(Row {
                pair: Pair::GlassSphere,
                case: format!("{case} ({} rays)", list.len()),
                variant: name.to_string(),
                precision: own_precision().to_string(),
                time,
                metrics,
                fails: wrong > 0,
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
    fn the_f64_exit_of_a_central_ray_is_the_far_pole() {
        // Straight at the centre from (0, 0, 1): normal incidence, no bending, the chord is
        // the diameter and the exit is (0, 0, −r), to f64 rounding at the eye's distance 1
        // (the entry 1 − (1 − r) carries a few 10⁻¹⁶): tolerance 10⁻¹⁵, 10⁻¹⁰ r.
        let exit = exit_f64(Vec3::Z, -Vec3::Z).unwrap();
        let r = wide(RADIUS);
        assert!(exit[0] == 0.0 && exit[1] == 0.0 && (exit[2] + r).abs() < 1e-15, "{exit:?}");
        // A line 1.5 r from the centre misses.
        assert_eq!(exit_f64(Vec3::new(1.5 * RADIUS, 0.0, 1.0), -Vec3::Z), None);
    }

    #[test]
    fn a_reduced_run_fails_both_fixed_epsilons_and_passes_the_offset() {
        // 10⁻⁴ is ten radii: from p + 10⁻⁴·t the chord (≤ 2 r) is behind the origin, and
        // p + 10⁻⁴·n is outside the sphere, so hardly any ray finds the exit, in f32 and f64.
        let effort = Effort { samples: 300, runs: 1, min_batch: std::time::Duration::ZERO, ..Effort::QUICK };
        let rows = measure(&effort);
        for r in &rows {
            let wrong = r.metric("wrong exit %").unwrap();
            if r.variant == "offset_origin" {
                assert!(!r.fails && wrong == 0.0, "{r:#?}");
            } else {
                assert!(r.fails && wrong > 90.0, "{r:#?}");
            }
        }
    }
}
