//! What the lectures' tests and the grader's checks both test with: small
//! values made readable (`v`, `ray`), `Float` widened to f64 for ground truth
//! computed wider, independent references (sphere roots by Newton's method in
//! double-double arithmetic, ray–box by exact integer arithmetic), and the
//! fixtures both build (test scenes, a closed wobbly mesh and the rays that
//! find its leaks, polygons, rays against boxes, lights, refraction at the
//! edge of total internal reflection, shadow-ray offsets, sphere uvs): a
//! scenario a lecture's test shows and a check grades is written once, here.
//!
//! Its place: the lectures use it as a dev-dependency, the checks as a
//! dependency, and the handout ships it, so it holds no exercise solved: its
//! references are other methods than the exercises' (the handout's test finds
//! any SOLUTION lines copied into it). It depends on the kit only and is not
//! part of the kit's API: nothing a student writes calls it.

pub mod boxes;
pub mod exact;
pub mod lights;
pub mod meshes;
pub mod offsets;
pub mod polygons;
pub mod refraction;
pub mod roots;
pub mod scenes;
pub mod uv;

use raylab::{Float, Ray, Vec3};

/// (x, y, z).
pub fn v(x: Float, y: Float, z: Float) -> Vec3 {
    Vec3::new(x, y, z)
}

/// The ray from `o` along `d` (as given: not normalised).
pub fn ray(o: [Float; 3], d: [Float; 3]) -> Ray {
    Ray::new(Vec3::from_array(o), Vec3::from_array(d))
}

/// `x` in f64, whatever `Float` is, without rounding: for ground truth computed wider.
pub fn wide(x: Float) -> f64 {
    f64::from(x)
}

/// `v` in f64, component by component, without rounding.
pub fn wide3(v: Vec3) -> [f64; 3] {
    [wide(v.x), wide(v.y), wide(v.z)]
}

/// The unit in the last place of `x`: the gap from |x| to the next float up.
pub fn ulp(x: Float) -> Float {
    let x = x.abs();
    x.next_up() - x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ulp_is_the_spacing_of_floats() {
        // 1 and 1.5 lie in [1, 2), where floats are ε apart; 2 starts the next binade.
        assert_eq!(ulp(1.0), Float::EPSILON);
        assert_eq!(ulp(-1.5), Float::EPSILON);
        assert_eq!(ulp(2.0), 2.0 * Float::EPSILON);
        assert_eq!(wide3(v(0.5, -2.0, 3.0)), [0.5, -2.0, 3.0]);
    }
}
