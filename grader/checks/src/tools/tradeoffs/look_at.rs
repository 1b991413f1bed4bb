//! The look-at pair: lecture 01's `look_at` against the plain Gram–Schmidt
//! that students write first, with up parallel or nearly parallel to the
//! view and views near −z.

use std::hint::black_box;

use l01_transforms::{CameraError, look_at};
use raylab::random::Rng;
use raylab::{Float, Mat4, Vec3};

use super::reference::unit;
use super::row::{Pair, Row, own_precision};
use super::timing::{Effort, time_per_item};
use raylab_testing::{wide, wide3};

/// The catalogued naive look-at: w = (eye − at)/|eye − at|, u = (up × w)/|up × w|,
/// v = w × u, and the matrix with columns u, v, w, eye; no test that up is
/// across the view, no rescaling, no second Gram–Schmidt step.
///
/// With up parallel to the view, up × w is zero (normalised: 0/0, a NaN
/// basis) or, when rounding leaves a few ulp of it, a direction made of
/// rounding noise that need not be perpendicular to w; with up within δ of
/// the view it loses digits to cancellation and u drifts off ⟂ w by ~ε/δ.
/// Errors only for eye = at. Book: §1.6 The look-at transform.
pub fn look_at_gram_schmidt(eye: Vec3, at: Vec3, up: Vec3) -> Result<Mat4, CameraError> {
    if eye == at {
        return Err(CameraError::EyeAtTarget);
    }
    let w = (eye - at).normalize();
    let u = up.cross(w).normalize();
    let v = w.cross(u);
    Ok(Mat4::from_cols(u.extend(0.0), v.extend(0.0), w.extend(0.0), eye.extend(1.0)))
}

type LookAt = fn(Vec3, Vec3, Vec3) -> Result<Mat4, CameraError>;

/// The naive form first, the reference method last.
pub const VARIANTS: [(&str, LookAt); 2] = [("gram_schmidt", look_at_gram_schmidt), ("look_at", look_at)];

/// A basis farther than this from orthonormal (or from the true w) fails.
pub const MAX_ORTHONORMALITY_ERROR: f64 = 1e-6;

/// A camera: eye, at, up.
type Camera = (Vec3, Vec3, Vec3);

/// Up exactly parallel to the view: views along each axis (both ways) with up
/// along that axis (both ways), random views with up a random multiple of the
/// view (rounding may leave a few ulp of up × w), and a zero up.
fn parallel_cameras(count: usize, seed: u64) -> Vec<Camera> {
    let mut rng = Rng::new(seed);
    let mut cameras = Vec::new();
    for axis in [Vec3::X, Vec3::Y, Vec3::Z] {
        for (view, up) in [(axis, axis), (axis, -axis), (-axis, axis), (-axis, -axis)] {
            cameras.push((view * 5.0, Vec3::ZERO, up));
        }
    }
    while cameras.len() < count {
        let eye = rng.in_cube(10.0);
        let at = rng.in_cube(10.0);
        let up = match cameras.len() % 4 {
            0 => Vec3::ZERO,
            _ => (at - eye) * rng.range(-3.0, 3.0),
        };
        if eye != at && up.is_finite() {
            cameras.push((eye, at, up));
        }
    }
    cameras
}

/// Up within δ = 10⁻³ … 3·10⁻⁶ rad of the view, either way: ordinary cameras
/// whose up × w cancels. Half the views are within 10⁻² of −z (the eye above
/// the origin, slightly off the z axis), half in random directions (where the
/// rounding of up × w is largest across w).
fn near_parallel_cameras(count: usize, seed: u64) -> Vec<Camera> {
    let mut rng = Rng::new(seed);
    let deltas: [Float; 4] = [1e-3, 1e-4, 1e-5, 3e-6];
    (0..count)
        .map(|k| {
            let eye = if k % 8 < 4 {
                Vec3::new(0.0, 0.0, 5.0) + rng.in_cube(0.05)
            } else {
                5.0 * rng.unit_vector()
            };
            let view = (-eye).normalize();
            let across = view.any_orthonormal_vector();
            let delta = deltas[k % deltas.len()];
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            (eye, Vec3::ZERO, sign * (delta.cos() * view + delta.sin() * across))
        })
        .collect()
}

/// Views near −z with up +y: the eye 10⁻² … 10⁻⁸ off the z axis, the basis near the identity.
fn near_minus_z_cameras(count: usize, seed: u64) -> Vec<Camera> {
    let mut rng = Rng::new(seed);
    let offsets: [Float; 4] = [1e-2, 1e-4, 1e-6, 1e-8];
    (0..count)
        .map(|k| {
            let (off, phi) = (offsets[k % offsets.len()], rng.range(0.0, std::f64::consts::TAU as Float));
            (Vec3::new(off * phi.cos(), off * phi.sin(), 5.0), Vec3::ZERO, Vec3::Y)
        })
        .collect()
}

/// How far a returned basis is from orthonormal and from the true w: the
/// largest of ||u| − 1|, ||v| − 1|, ||w| − 1|, |u·v|, |v·w|, |w·u|, |u × v − w|
/// and |w − ŵ| (components, ŵ the unit eye − at in f64), all in f64 on the
/// `Float` columns; NaN for a basis with a NaN.
pub fn orthonormality_error(m: &Mat4, eye: Vec3, at: Vec3) -> f64 {
    use super::reference::{cross, dot};
    let [u, v, w] = [m.x_axis, m.y_axis, m.z_axis].map(|c| wide3(c.truncate()));
    let w_true = unit([0, 1, 2].map(|k| wide(eye[k]) - wide(at[k])));
    let uv = cross(u, v);
    let mut errors = vec![
        (dot(u, u).sqrt() - 1.0).abs(),
        (dot(v, v).sqrt() - 1.0).abs(),
        (dot(w, w).sqrt() - 1.0).abs(),
        dot(u, v).abs(),
        dot(v, w).abs(),
        dot(w, u).abs(),
    ];
    errors.extend((0..3).map(|k| (uv[k] - w[k]).abs()));
    errors.extend((0..3).map(|k| (w[k] - w_true[k]).abs()));
    // A NaN anywhere stays (f64::max would drop it at the next number).
    errors.into_iter().fold(0.0, |m: f64, e| if m.is_nan() || e.is_nan() { f64::NAN } else { m.max(e) })
}

/// What a variant did on a set of cameras: (refused, NaN bases, max orthonormality error of
/// the finite bases).
fn judge(look_at: LookAt, cameras: &[Camera]) -> (usize, usize, f64) {
    let (mut refused, mut nans, mut worst) = (0usize, 0usize, 0.0f64);
    for &(eye, at, up) in cameras {
        match look_at(eye, at, up) {
            Err(_) => refused += 1,
            Ok(m) if !m.is_finite() => nans += 1,
            Ok(m) => worst = worst.max(orthonormality_error(&m, eye, at)),
        }
    }
    (refused, nans, worst)
}

/// Every variant on every case: refused, NaN bases, max orthonormality error, ns per call.
pub fn measure(effort: &Effort) -> Vec<Row> {
    let cases = [
        ("up ∥ view", parallel_cameras(effort.samples, 0x100c_0001)),
        ("up within 1e-3…3e-6 rad of the view", near_parallel_cameras(effort.samples, 0x100c_0002)),
        ("views near −z, up +y", near_minus_z_cameras(effort.samples, 0x100c_0003)),
    ];
    let mut rows = Vec::new();
    for (case, cameras) in cases {
        for (name, look_at) in VARIANTS {
            let (refused, nans, worst) = judge(look_at, &cameras);
            let time = time_per_item(effort, cameras.len(), || {
                for &(eye, at, up) in &cameras {
                    let _ = black_box(look_at(black_box(eye), at, up));
                }
            });
            rows.push(Row {
                pair: Pair::LookAt,
                case: format!("{case} ({} cameras)", cameras.len()),
                variant: name.to_string(),
                precision: own_precision().to_string(),
                time,
                metrics: vec![
                    ("refused".into(), refused as f64),
                    ("NaN bases".into(), nans as f64),
                    ("max orthonormality error".into(), worst),
                ],
                fails: nans > 0 || worst.is_nan() || worst > MAX_ORTHONORMALITY_ERROR,
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
    fn the_identity_camera_is_orthonormal_and_a_broken_one_is_not() {
        // Eye on +z looking at the origin, up +y: u, v, w = x, y, z exactly, error 0.
        let eye = Vec3::new(0.0, 0.0, 5.0);
        let m = look_at_gram_schmidt(eye, Vec3::ZERO, Vec3::Y).unwrap();
        assert_eq!(orthonormality_error(&m, eye, Vec3::ZERO), 0.0);
        // v swapped for w: u·v = 0 still, but u × v = −y ≠ w = z (error 1), and w off by 1.
        let bad =
            Mat4::from_cols(Vec3::X.extend(0.0), Vec3::Z.extend(0.0), Vec3::Z.extend(0.0), eye.extend(1.0));
        assert_eq!(orthonormality_error(&bad, eye, Vec3::ZERO), 1.0);
        // Up along the view: up × w = 0, normalised 0/0.
        let parallel = look_at_gram_schmidt(eye, Vec3::ZERO, Vec3::Z).unwrap();
        assert!(!parallel.is_finite());
    }

    #[test]
    fn a_reduced_run_fails_gram_schmidt_and_passes_look_at() {
        // The exactly parallel ups give NaN bases in f32 and f64 alike; lecture 01 refuses
        // them. Near parallel, only f32's drift ε/δ (4·10⁻² at 3·10⁻⁶ rad) exceeds 10⁻⁶.
        let effort = Effort { samples: 200, runs: 1, min_batch: std::time::Duration::ZERO, ..Effort::QUICK };
        let rows = measure(&effort);
        for r in rows.iter().filter(|r| r.variant == "look_at") {
            assert!(!r.fails, "{r:#?}");
        }
        let parallel =
            rows.iter().find(|r| r.variant == "gram_schmidt" && r.case.starts_with("up ∥")).unwrap();
        assert!(parallel.fails && parallel.metric("NaN bases").unwrap() > 0.0, "{parallel:#?}");
        let refused = rows.iter().find(|r| r.variant == "look_at" && r.case.starts_with("up ∥")).unwrap();
        assert_eq!(refused.metric("refused"), Some(200.0), "{refused:#?}");
    }
}
