//! Ray trees as data: the form the blessed files (`S.trees.json`) and a student's code hold the
//! trees of the report's grid of pixels in, the grid itself, and the tree's text. A leaf: the 3D
//! view (`view3d`) draws these, the stages make them.

use raylab::{Float, Vec3};
use serde::{Deserialize, Serialize};

/// The trees of the grid's pixels ([`grid`], row by row), as blessed: `S.trees.json` beside the
/// snapshot `S.png`, `S.final.trees.json` beside `S.final.png`.
#[derive(Debug, PartialEq, Serialize, Deserialize)]
pub struct GridTrees {
    pub grid: u32,
    pub width: u32,
    pub height: u32,
    pub trees: Vec<TreeNode>,
}

/// A ray tree as data, its numbers as the text tree prints them (three decimals): what the
/// blessed files hold and what a student's code sends for the report, ~75 bytes a ray in JSON.
/// From stage 08 on, lecture 08's `RayTree` of the pixel; before, the rays the stage draws it
/// with (`stages::grid_trees`). It prints as `RayTree` does.
///
/// A student's NaN or infinite number is written as JSON's `null` (serde_json's way) and read
/// back as NaN, so that such a tree still reaches the report (`nullable`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TreeNode {
    pub(crate) k: Kind,
    #[serde(deserialize_with = "nullable::triple")]
    pub(crate) o: [f64; 3],
    #[serde(deserialize_with = "nullable::triple")]
    pub(crate) d: [f64; 3],
    #[serde(deserialize_with = "nullable::number")]
    pub(crate) w: f64,
    /// The object hit (a shadow ray's blocker) and the ray's t.
    #[serde(default, skip_serializing_if = "Option::is_none", deserialize_with = "nullable::hit")]
    pub(crate) h: Option<(usize, f64)>,
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub(crate) c: Vec<TreeNode>,
}

/// Numbers that may be `null` in JSON (a NaN or infinity written by serde_json), read as NaN.
mod nullable {
    use serde::{Deserialize, Deserializer};

    pub fn number<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        Ok(Option::<f64>::deserialize(d)?.unwrap_or(f64::NAN))
    }

    pub fn triple<'de, D: Deserializer<'de>>(d: D) -> Result<[f64; 3], D::Error> {
        Ok(<[Option<f64>; 3]>::deserialize(d)?.map(|x| x.unwrap_or(f64::NAN)))
    }

    pub fn hit<'de, D: Deserializer<'de>>(d: D) -> Result<Option<(usize, f64)>, D::Error> {
        Ok(Option::<(usize, Option<f64>)>::deserialize(d)?.map(|(object, t)| (object, t.unwrap_or(f64::NAN))))
    }
}

/// A ray's kind in a [`TreeNode`], one letter in JSON.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Kind {
    #[serde(rename = "e")]
    Eye,
    #[serde(rename = "s")]
    Shadow,
    #[serde(rename = "r")]
    Reflected,
    #[serde(rename = "t")]
    Transmitted,
}

impl TreeNode {
    /// A ray and the rays it spawned, its numbers rounded as the text prints them (a zero
    /// unsigned: the text never shows its sign), so that it prints the same again.
    pub fn new(
        kind: Kind,
        origin: Vec3,
        dir: Vec3,
        weight: Float,
        hit: Option<(usize, Float)>,
        children: Vec<TreeNode>,
    ) -> Self {
        let printed = |x: Float| format!("{x:.3}").parse::<f64>().map_or(f64::NAN, |x| x + 0.0);
        let v = |v: Vec3| [printed(v.x), printed(v.y), printed(v.z)];
        TreeNode {
            k: kind,
            o: v(origin),
            d: v(dir),
            w: printed(weight),
            h: hit.map(|(object, t)| (object, printed(t))),
            c: children,
        }
    }

    fn write(&self, f: &mut std::fmt::Formatter<'_>, indent: usize) -> std::fmt::Result {
        let kind = match self.k {
            Kind::Eye => "eye",
            Kind::Shadow => "shadow",
            Kind::Reflected => "reflected",
            Kind::Transmitted => "transmitted",
        };
        let fixed = |x: f64| {
            let s = format!("{x:.3}");
            if s == "-0.000" { "0.000".to_owned() } else { s }
        };
        let triple = |v: [f64; 3]| format!("({}, {}, {})", fixed(v[0]), fixed(v[1]), fixed(v[2]));
        write!(
            f,
            "{:indent$}{kind} from {} dir {} weight {}: ",
            "",
            triple(self.o),
            triple(self.d),
            fixed(self.w)
        )?;
        match (self.k, self.h) {
            (Kind::Shadow, Some((object, t))) => writeln!(f, "blocked by #{object} at t = {}", fixed(t))?,
            (Kind::Shadow, None) => writeln!(f, "reaches the light")?,
            (_, Some((object, t))) => writeln!(f, "hits #{object} at t = {}", fixed(t))?,
            (_, None) => writeln!(f, "misses")?,
        }
        self.c.iter().try_for_each(|c| c.write(f, indent + 2))
    }
}

/// As lecture 08's `RayTree` prints (`view3d::tests::a_tree_as_data_prints_as_the_tree`).
impl std::fmt::Display for TreeNode {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        self.write(f, 0)
    }
}

/// The grid of pixels whose trees the report holds: one pixel, the centre of each `GRID` × `GRID`
/// block (a click in the report picks its block's; the view opens at a grid pixel that differs,
/// `images::view_pixel`).
pub const GRID: u32 = 16;

/// The grid pixel of the block `pixel` lies in.
pub fn nearest((x, y): (u32, u32), width: u32, height: u32) -> (u32, u32) {
    let centre = |v: u32, n: u32| ((v / GRID) * GRID + GRID / 2).min(n.saturating_sub(1));
    (centre(x, width), centre(y, height))
}

/// The grid's pixels of a `width` × `height` image, row by row.
pub fn grid(width: u32, height: u32) -> Vec<(u32, u32)> {
    let along = |n: u32| (0..n.div_ceil(GRID)).map(move |k| (k * GRID + GRID / 2).min(n - 1));
    along(height).flat_map(|y| along(width).map(move |x| (x, y))).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grid holds the centre of each 16 × 16 block, the last block's clamped into the image;
    /// `nearest` finds the centre of the block a pixel lies in.
    #[test]
    fn the_grid_is_each_block_s_centre_and_nearest_finds_its_block() {
        let pixels = grid(200, 150);
        // 200 / 16 = 12.5 → 13 columns, 150 / 16 = 9.4 → 10 rows.
        assert_eq!(pixels.len(), 13 * 10);
        assert_eq!(pixels[0], (8, 8));
        assert_eq!(pixels[1], (24, 8));
        assert_eq!(pixels[12], (199, 8));
        assert_eq!(pixels[13], (8, 24));
        assert_eq!(*pixels.last().unwrap(), (199, 149));
        assert_eq!(nearest((150, 70), 200, 150), (152, 72));
        assert_eq!(nearest((0, 0), 200, 150), (8, 8));
        assert_eq!(nearest((199, 149), 200, 150), (199, 149));
        assert_eq!(grid(1, 1), vec![(0, 0)]);
        for &(x, y) in &pixels {
            assert_eq!(nearest((x, y), 200, 150), (x, y), "a grid pixel is its own block's");
        }
    }
}
