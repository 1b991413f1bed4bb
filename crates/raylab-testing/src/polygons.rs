//! The polygons lecture 03's point-in-polygon and polygon tests and checks
//! both use: a square, a concave "U", the pentagram, and the square placed
//! in 3D across each axis.

use raylab::math::consts::PI;
use raylab::{Float, Vec2, Vec3};

/// The square [0, 2]², counter-clockwise.
pub fn square() -> Vec<Vec2> {
    [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]].map(Vec2::from_array).to_vec()
}

/// A "U", counter-clockwise: two arms x ∈ [0, 1] and [2, 3] rising to y = 3
/// from a base y ∈ [0, 1]; the notch x ∈ (1, 2), y ∈ (1, 3) is outside.
pub fn u_shape() -> Vec<Vec2> {
    [[0.0, 0.0], [3.0, 0.0], [3.0, 3.0], [2.0, 3.0], [2.0, 1.0], [1.0, 1.0], [1.0, 3.0], [0.0, 3.0]]
        .map(Vec2::from_array)
        .to_vec()
}

/// The pentagram {5/2}: the regular pentagon's vertices (angles 90° + 72°k,
/// radius 1) taken in the order 0, 2, 4, 1, 3, counter-clockwise. It winds
/// twice around the centre (the inner pentagon) and once around each tip.
pub fn pentagram() -> Vec<Vec2> {
    [0, 2, 4, 1, 3]
        .iter()
        .map(|&k| {
            let a = PI / 2.0 + 2.0 * PI * k as Float / 5.0;
            Vec2::new(a.cos(), a.sin())
        })
        .collect()
}

/// The point of the plane where coordinate `axis` is 1 whose next two
/// coordinates (cyclically: y, z across x; z, x across y; x, y across z) are
/// (u, v).
pub fn on_plane(axis: usize, u: Float, v: Float) -> Vec3 {
    let mut p = Vec3::ZERO;
    p[axis] = 1.0;
    p[(axis + 1) % 3] = u;
    p[(axis + 2) % 3] = v;
    p
}

/// The square [0, 2]² placed in 3D with `axis` as its normal axis, at
/// coordinate 1 along it ([`on_plane`]), counter-clockwise seen from +axis.
pub fn square_in_plane(axis: usize) -> Vec<Vec3> {
    square().iter().map(|v| on_plane(axis, v.x, v.y)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_placed_square_keeps_its_corners_and_its_turn() {
        // Across z the next two coordinates are x, y: the square itself at z = 1.
        let at_z: Vec<Vec3> = square().iter().map(|v| v.extend(1.0)).collect();
        assert_eq!(square_in_plane(2), at_z);
        // Across x they are y, z: (0, 2) goes to (1, 0, 2); (y, z) counter-clockwise seen from +x.
        assert_eq!(square_in_plane(0)[3], Vec3::new(1.0, 0.0, 2.0));
        assert_eq!((u_shape().len(), pentagram().len()), (8, 5));
    }
}
