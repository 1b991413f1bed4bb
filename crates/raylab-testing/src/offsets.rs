//! Where a secondary ray starts: random points, normals, directions and the
//! origins of the rays that found them, at scales from 10⁻³⁰ to 10²⁰, the
//! cases lecture 06's tests and checks of the shadow-ray offset both draw.

use raylab::Vec3;
use raylab::random::Rng;

/// A hit point `p`, its unit normal `n`, the unit direction `dir` a ray
/// leaves it along, and the origin `from` of the ray that found it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OffsetCase {
    pub p: Vec3,
    pub n: Vec3,
    pub dir: Vec3,
    pub from: Vec3,
}

/// `per` random cases for each scale 10⁻³⁰, 10⁻⁴, 1, 7, 10⁴, 10⁵, 10²⁰ of p
/// (uniform in the ball of that radius) and each ray origin 0, 1 and 100 times
/// as far out, the normal and the direction uniform on the sphere, drawn from
/// one seeded generator: the same cases on every run.
pub fn random_offset_cases(per: usize) -> Vec<OffsetCase> {
    let mut rng = Rng::new(0x0ff5e7);
    let mut cases = Vec::new();
    for scale in [1e-30, 1e-4, 1.0, 7.0, 1e4, 1e5, 1e20] {
        for from_scale in [0.0, 1.0, 100.0] {
            for _ in 0..per {
                let p = rng.in_ball(scale);
                let from = rng.in_ball(scale * from_scale);
                let n = rng.unit_vector();
                let dir = rng.unit_vector();
                cases.push(OffsetCase { p, n, dir, from });
            }
        }
    }
    cases
}
