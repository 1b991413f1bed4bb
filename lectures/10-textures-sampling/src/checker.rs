//! The checkerboard: the procedural texture of chapter 10, in texture space
//! and as a solid texture in 3D.

use raylab::{Color, Float, Vec2, Vec3};

/// Whether the integer ⌊x⌋ is odd, for any float: ⌊x⌋ saturates to the i64
/// range (NaN gives 0) and the parity is the Euclidean remainder, 0 or 1 even
/// for negative cells. Never panics.
fn odd_cell(x: Float) -> bool {
    (x.floor() as i64).rem_euclid(2) == 1
}

/// A checkerboard in texture space with `scale` cells per unit of u and of v:
/// the cell (i, j) = (⌊u·scale⌋, ⌊v·scale⌋) is coloured `a` when i + j is even
/// and `b` when it is odd. Cells are half-open, [i, i + 1)/scale, so a point
/// on an edge belongs to the cell above and right of it.
///
/// The floor, not truncation toward zero: `(u·scale) as i64` sends both
/// −0.4 and 0.4 to 0, so the two cells either side of u = 0 get the same
/// colour and the board shows a double-width stripe along each axis (the
/// catalogued mistake). The parity is taken per index (⌊u·s⌋ odd xor ⌊v·s⌋
/// odd), so even huge coordinates cannot overflow a sum. `scale` > 0.
/// Book: §10.3 Procedural textures.
pub fn checker(uv: Vec2, scale: Float, a: Color, b: Color) -> Color {
    // SOLUTION BEGIN
    // The cell of uv, and its parity.
    let odd = odd_cell(uv.x * scale) ^ odd_cell(uv.y * scale);
    if odd { b } else { a }
    // SOLUTION END
}

/// A solid (3D) checkerboard: the cube (i, j, k) = (⌊x·s⌋, ⌊y·s⌋, ⌊z·s⌋),
/// s = `scale` cubes per unit of object space, is `a` when i + j + k is even
/// and `b` when odd. Any surface cut through it shows a board, with no (u, v)
/// needed. A surface lying exactly on a cube face (the floor y = 0 with
/// s = 1) flickers between two cubes with the rounding of its hit points:
/// move the board (or the surface) half a cube. Book: §10.3 Solid textures.
pub fn checker_3d(p: Vec3, scale: Float, a: Color, b: Color) -> Color {
    // SOLUTION BEGIN
    // The cube of p, and its parity.
    let odd = odd_cell(p.x * scale) ^ odd_cell(p.y * scale) ^ odd_cell(p.z * scale);
    if odd { b } else { a }
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;

    const A: Color = Color::new(1.0, 1.0, 1.0);
    const B: Color = Color::new(0.0, 0.0, 0.0);

    fn at(u: Float, v: Float) -> Color {
        checker(Vec2::new(u, v), 4.0, A, B)
    }

    #[test]
    fn checker_alternates_across_cell_edges() {
        // Scale 4: edges at multiples of ¼. (0.2, 0.1) is cell (0, 0), even: A; across u = ¼,
        // (0.3, 0.1) is cell (1, 0): B; across v = ¼ from there, (0.3, 0.3) is (1, 1): A.
        assert_eq!((at(0.2, 0.1), at(0.3, 0.1), at(0.3, 0.3), at(0.2, 0.3)), (A, B, A, B));
        // On an edge: u = 0.25 exactly is ⌊1⌋ = 1, the cell to the right (half-open cells).
        assert_eq!(at(0.25, 0.1), B);
    }

    #[test]
    fn checker_uses_the_floor_at_negative_coordinates() {
        // u = −0.1: ⌊−0.4⌋ = −1, odd: B, while u = +0.1 is cell 0: A. Truncation would make
        // both cell 0 and both A (the double stripe). u = −0.3: ⌊−1.2⌋ = −2, even: A again,
        // so the colours keep alternating A, B, A going left from 0. (−0.1, −0.1) is cell
        // (−1, −1), sum −2, even: A. u = −0.25 exactly is cell −1: B.
        assert_eq!((at(0.1, 0.1), at(-0.1, 0.1), at(-0.3, 0.1)), (A, B, A));
        assert_eq!((at(-0.1, -0.1), at(0.1, -0.1), at(-0.25, 0.1)), (A, B, B));
    }

    #[test]
    fn checker_never_panics_on_huge_or_nan_coordinates() {
        // 10³⁰ saturates to i64::MAX (odd); −10³⁰ to i64::MIN (even); NaN to 0 (even).
        assert_eq!(at(1e30, 0.1), B);
        assert_eq!(at(-1e30, 0.1), A);
        assert_eq!(at(Float::NAN, 0.1), A);
    }

    #[test]
    fn solid_checker_alternates_in_all_three_axes() {
        // Scale 1: cube (0, 0, 0) is A; stepping across any one face (to −0.1 in that axis,
        // the cube −1) flips the colour, across two faces flips it back.
        let c = |x: Float, y: Float, z: Float| checker_3d(Vec3::new(x, y, z), 1.0, A, B);
        assert_eq!(c(0.5, 0.5, 0.5), A);
        assert_eq!((c(-0.1, 0.5, 0.5), c(0.5, -0.1, 0.5), c(0.5, 0.5, -0.1)), (B, B, B));
        assert_eq!((c(-0.1, -0.1, 0.5), c(-0.1, -0.1, -0.1)), (A, B));
        // Scale 2: cubes of side ½; (0.6, 0.1, 0.1) is cube (1, 0, 0): B.
        assert_eq!(checker_3d(Vec3::new(0.6, 0.1, 0.1), 2.0, A, B), B);
    }
}
