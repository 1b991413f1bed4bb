//! Rays against boxes, the cases lecture 03's slabs and lecture 09's boxes
//! are tested on, by their own tests and by the checks: rays along a face
//! plane of the cube [−1, 1]³, and random boxes and rays on the grid of
//! sixteenths, which [`crate::exact`] decides with no rounding.

use raylab::random::Rng;
use raylab::{Float, Vec3};

/// Rays whose origin lies exactly on a face plane of the cube [−1, 1]³
/// (y = 1, y = −1) or on an edge line (y = z = 1, y = z = −1), moving along
/// ±x with +0 and −0 in the other components, as (origin, direction): 0·∞ =
/// NaN must count as inside the slab the ray runs along. Each meets the cube
/// over t ∈ [2, 4], its x span.
pub const FACE_PLANE_RAYS: [([Float; 3], [Float; 3]); 5] = [
    ([-3.0, 1.0, 0.0], [1.0, 0.0, 0.0]),
    ([-3.0, 1.0, 0.0], [1.0, -0.0, 0.0]),
    ([-3.0, -1.0, 0.0], [1.0, -0.0, -0.0]),
    ([-3.0, 1.0, 1.0], [1.0, -0.0, 0.0]),
    ([3.0, -1.0, -1.0], [-1.0, 0.0, -0.0]),
];

/// A box [lo, hi], a ray's origin `o` and direction `d` on the grid of
/// sixteenths, in sixteenths: [`sixteenths`] gives the coordinates, exact in
/// any float, so exact arithmetic on the integers sees the very numbers the
/// code under test sees.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GridRay {
    pub lo: [i64; 3],
    pub hi: [i64; 3],
    pub o: [i64; 3],
    pub d: [i64; 3],
}

/// The next random box and ray from `rng`: corners lo in [−40, 40]³ and hi
/// up to 40 above (one axis in eight flat, hi = lo), an origin in
/// [−100, 100]³; a random direction with one component in four exactly
/// zero, or, when `aimed`, the direction toward a point of the box's
/// boundary, exactly: a face, an edge or a corner (a point inside is moved
/// to the max-x face). The direction may be zero: skip that one.
pub fn grid_ray(rng: &mut Rng, aimed: bool) -> GridRay {
    let mut lo = [0i64; 3];
    let mut hi = [0i64; 3];
    for i in 0..3 {
        lo[i] = rng.int(-40, 40);
        // One box in eight is flat along this axis.
        hi[i] = if rng.int(0, 7) == 0 { lo[i] } else { lo[i] + rng.int(1, 40) };
    }
    let o: [i64; 3] = std::array::from_fn(|_| rng.int(-100, 100));
    let d: [i64; 3] = if aimed {
        // Aimed exactly at the box's boundary: a face, an edge or a corner.
        let target: [i64; 3] = std::array::from_fn(|i| match rng.int(0, 2) {
            0 => lo[i],
            1 => hi[i],
            _ => rng.int(lo[i], hi[i]),
        });
        let on_boundary = (0..3).any(|i| target[i] == lo[i] || target[i] == hi[i]);
        let mut d = [target[0] - o[0], target[1] - o[1], target[2] - o[2]];
        if !on_boundary {
            d[0] = hi[0] - o[0]; // make it a point of the max-x face
        }
        d
    } else {
        // A random direction, one component in four exactly zero.
        std::array::from_fn(|_| if rng.int(0, 3) == 0 { 0 } else { rng.int(-60, 60) })
    };
    GridRay { lo, hi, o, d }
}

/// The point of the grid `v` stands for: v/16, exact in any float.
pub fn sixteenths(v: [i64; 3]) -> Vec3 {
    Vec3::new(v[0] as Float, v[1] as Float, v[2] as Float) * (1.0 / 16.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn aimed_rays_point_at_the_boundary() {
        // Half the rays aimed: their target o + d is on a face plane of the box and inside
        // its other two slabs.
        let mut rng = Rng::new(1);
        for n in 0..200 {
            let GridRay { lo, hi, o, d } = grid_ray(&mut rng, n % 2 == 1);
            assert!((0..3).all(|i| lo[i] <= hi[i] && hi[i] - lo[i] <= 40), "{lo:?}..{hi:?}");
            if n % 2 == 1 {
                let target: [i64; 3] = std::array::from_fn(|i| o[i] + d[i]);
                assert!((0..3).all(|i| lo[i] <= target[i] && target[i] <= hi[i]), "{target:?}");
                assert!((0..3).any(|i| target[i] == lo[i] || target[i] == hi[i]), "{target:?}");
            }
        }
        assert_eq!(sixteenths([16, -8, 1]), Vec3::new(1.0, -0.5, 0.0625));
    }
}
