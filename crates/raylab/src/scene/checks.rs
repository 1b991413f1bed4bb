//! The checks both loaders make on the values they read, so that a [`Scene`]
//! never holds a NaN, a zero normal, a degenerate camera or an unusable
//! polygon. Each check returns what is wrong as a sentence; the loader adds
//! the file, line and column.
//!
//! [`Scene`]: super::Scene

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::{Attenuation, Mesh};
use crate::math::{Float, Mat4, Vec3};

/// `x` as a finite `Float`, or `None` for NaN, ±∞ and values beyond the range
/// of `Float` (1e39 overflows `f32`).
pub fn finite(x: f64) -> Option<Float> {
    let f = x as Float;
    f.is_finite().then_some(f)
}

/// A number for messages: shortest round-trip digits, in exponent form when
/// very large or small (`1e39`, not forty digits).
pub fn number(x: f64) -> String {
    if x == 0.0 || !x.is_finite() || (1e-4..1e15).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// A vector for messages: `[1, 0, -2.5]` (shortest round-trip digits).
pub fn show(v: Vec3) -> String {
    format!("[{}, {}, {}]", v.x, v.y, v.z)
}

/// `v / |v|`, or an error for a zero (or too tiny to normalise) vector.
pub fn unit(v: Vec3, what: &str) -> Result<Vec3, String> {
    v.try_normalize().ok_or_else(|| format!("{what} must be a non-zero vector, found {}", show(v)))
}

/// The camera's view must be defined: `eye ≠ at`, and `up` not parallel to
/// the view direction d = at − eye, tested as |up × d| ≤ 10⁻⁶·|up|·|d| (the
/// sine of the angle between them at most 10⁻⁶, which also catches a zero
/// `up`). Book: §1.4 Look-at.
pub fn check_view(eye: Vec3, at: Vec3, up: Vec3) -> Result<(), String> {
    let view = at - eye;
    if view == Vec3::ZERO {
        return Err(format!("at must differ from eye, both are {}", show(eye)));
    }
    if !view.is_finite() {
        return Err(format!("the view direction at − eye = {} is not finite", show(view)));
    }
    if up.cross(view).length() <= 1e-6 * up.length() * view.length() {
        return Err(format!(
            "up {} is parallel to the view direction at − eye = {} (or zero): the camera's roll is undefined",
            show(up),
            show(view)
        ));
    }
    Ok(())
}

/// How flat a triangle may be: its height over the longest edge at most this
/// (|(b − a)×(c − a)| ≤ 10⁻⁶·L², L the longest edge). Far above the rounding
/// of the cross product (a few ε·L², ε = 1.2·10⁻⁷ in f32).
const COLLINEAR: Float = 1e-6;

/// How far a polygon's vertex may stray from its plane, relative to the
/// polygon's size. Loose enough for the f32 error of the plane's normal in a
/// long thin polygon (aspect up to about 1000:1).
const NON_PLANAR: Float = 1e-4;

/// A triangle must span an area: not all three corners on a line.
pub fn check_triangle(v: [Vec3; 3]) -> Result<(), String> {
    let longest = (v[1] - v[0]).length().max((v[2] - v[1]).length()).max((v[0] - v[2]).length());
    let doubled_area = (v[1] - v[0]).cross(v[2] - v[0]).length();
    if doubled_area.is_nan() || doubled_area <= COLLINEAR * longest * longest {
        return Err(format!(
            "the triangle {}, {}, {} is degenerate: its corners lie on a line",
            show(v[0]),
            show(v[1]),
            show(v[2])
        ));
    }
    Ok(())
}

/// A polygon needs at least three vertices, not all on a line, all in one
/// plane (within 10⁻⁴ of its size), and a non-zero area (a self-crossing
/// figure eight whose halves cancel has none). The plane's normal is
/// Newell's Σ (vᵢ − v₀)×(vᵢ₊₁ − v₀). Book: §3.3 Polygons.
pub fn check_polygon(v: &[Vec3]) -> Result<(), String> {
    if v.len() < 3 {
        return Err(format!("a polygon needs at least 3 vertices, found {}", v.len()));
    }
    // The line through v₀ and the vertex farthest from it.
    let far =
        v.iter().map(|&p| p - v[0]).fold(Vec3::ZERO, |a, d| if d.length() > a.length() { d } else { a });
    let size = far.length();
    let off_line = v.iter().map(|&p| (p - v[0]).cross(far).length() / size).fold(0.0, Float::max);
    if !(size > 0.0 && off_line > COLLINEAR * size) {
        return Err("the polygon's vertices all lie on a line".to_string());
    }
    // Newell's normal.
    let normal: Vec3 = v.windows(2).map(|w| (w[0] - v[0]).cross(w[1] - v[0])).sum();
    let Some(n) = normal.try_normalize().filter(|_| normal.length() > COLLINEAR * size * size) else {
        return Err("the polygon's area is zero (does it cross itself?)".to_string());
    };
    // Every vertex in the plane through v₀.
    if let Some((i, d)) = v
        .iter()
        .map(|&p| n.dot(p - v[0]).abs())
        .enumerate()
        .find(|&(_, d)| d.is_nan() || d > NON_PLANAR * size)
    {
        let d = if d >= 1e-3 { format!("{d:.4}") } else { format!("{d:.1e}") };
        return Err(format!(
            "the polygon is not planar: vertex {i} {} is {d} away from its plane (through vertex 0, \
             with Newell's normal)",
            show(v[i])
        ));
    }
    Ok(())
}

/// Point-light attenuation 1 / (c + l·d + q·d²): every coefficient ≥ 0 and
/// not all zero, so the denominator is positive at every d > 0.
pub fn attenuation(c: Float, l: Float, q: Float) -> Result<Attenuation, String> {
    if c < 0.0 || l < 0.0 || q < 0.0 || c + l + q == 0.0 {
        return Err(format!(
            "attenuation [constant, linear, quadratic] must be ≥ 0 and not all 0, found [{c}, {l}, {q}]"
        ));
    }
    Ok(Attenuation { constant: c, linear: l, quadratic: q })
}

/// A rectangular area light's edges must span a parallelogram: both non-zero
/// and not parallel, tested as |u × v| > 10⁻⁶·|u|·|v| (the sine of the angle
/// between them above 10⁻⁶, as for the camera's `up`).
pub fn check_rect(edge_u: Vec3, edge_v: Vec3) -> Result<(), String> {
    if edge_u == Vec3::ZERO || edge_v == Vec3::ZERO {
        return Err(format!(
            "a rect light's edges must be non-zero, found edge_u {} and edge_v {}",
            show(edge_u),
            show(edge_v)
        ));
    }
    let area = edge_u.cross(edge_v).length();
    if area.is_nan() || area <= 1e-6 * edge_u.length() * edge_v.length() {
        return Err(format!(
            "a rect light's edges must not be parallel, found edge_u {} and edge_v {}",
            show(edge_u),
            show(edge_v)
        ));
    }
    Ok(())
}

/// The matrix with the 16 numbers in row-major order; it must be affine (last
/// row 0 0 0 1) and invertible.
pub fn affine_from_rows(rows: &[Float; 16]) -> Result<Mat4, String> {
    if rows[12..] != [0.0, 0.0, 0.0, 1.0] {
        return Err(format!(
            "the matrix must be affine: its last row must be 0 0 0 1, found {} {} {} {}",
            rows[12], rows[13], rows[14], rows[15]
        ));
    }
    let m = Mat4::from_cols_array(rows).transpose();
    if !(m.determinant() != 0.0) {
        return Err("the matrix is not invertible (its determinant is 0)".to_string());
    }
    Ok(m)
}

/// Scale factors must be non-zero (a zero squashes the object flat and
/// cannot be inverted).
pub fn scale(s: Vec3) -> Result<Mat4, String> {
    if s.x == 0.0 || s.y == 0.0 || s.z == 0.0 {
        return Err(format!("scale factors must be non-zero, found {}", show(s)));
    }
    Ok(Mat4::from_scale(s))
}

/// The OBJ file `file` (relative to the scene file's folder `dir`), loaded
/// once per scene: later objects share the mesh.
pub fn mesh(cache: &mut HashMap<PathBuf, Arc<Mesh>>, dir: &Path, file: &str) -> Result<Arc<Mesh>, String> {
    let path = dir.join(file);
    if let Some(mesh) = cache.get(&path) {
        return Ok(mesh.clone());
    }
    let mesh = Arc::new(Mesh::load_obj(&path)?);
    cache.insert(path, mesh.clone());
    Ok(mesh)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn up_along_the_view_is_rejected_but_a_tilted_up_is_not() {
        let eye = Vec3::new(0.0, 0.0, 5.0);
        assert!(check_view(eye, Vec3::ZERO, Vec3::Z).is_err(), "up parallel to −view");
        assert!(check_view(eye, Vec3::ZERO, Vec3::ZERO).is_err(), "zero up");
        assert!(check_view(eye, eye, Vec3::Y).is_err(), "eye = at");
        // sin θ = 10⁻³ ≫ 10⁻⁶: accepted although far from perpendicular.
        assert!(check_view(eye, Vec3::ZERO, Vec3::new(1e-3, 0.0, 1.0)).is_ok());
    }

    #[test]
    fn degenerate_triangles_and_polygons_are_rejected() {
        let (a, b) = (Vec3::ZERO, Vec3::X);
        assert!(check_triangle([a, b, Vec3::new(2.0, 0.0, 0.0)]).is_err(), "collinear");
        assert!(check_triangle([a, a, a]).is_err(), "a point");
        // Height 10⁻³ over an edge of 1: a thin but honest triangle.
        assert!(check_triangle([a, b, Vec3::new(0.5, 1e-3, 0.0)]).is_ok());
        let square = [a, b, Vec3::new(1.0, 1.0, 0.0), Vec3::Y];
        assert!(check_polygon(&square).is_ok());
        assert!(check_polygon(&square[..2]).is_err(), "two vertices");
        let mut bent = square;
        bent[2].z = 0.1; // 0.1 out of the plane of a unit square
        assert!(check_polygon(&bent).unwrap_err().contains("not planar"));
        let bow_tie = [a, Vec3::new(1.0, 1.0, 0.0), b, Vec3::Y];
        assert!(check_polygon(&bow_tie).unwrap_err().contains("area is zero"));
    }

    #[test]
    fn parallel_or_zero_rect_edges_are_rejected() {
        assert!(check_rect(Vec3::X, Vec3::Z).is_ok());
        assert!(check_rect(Vec3::X, Vec3::new(-2.0, 0.0, 0.0)).unwrap_err().contains("parallel"));
        assert!(check_rect(Vec3::ZERO, Vec3::Z).unwrap_err().contains("non-zero"));
        // sin θ = 10⁻³ ≫ 10⁻⁶: a thin sliver of a light, but a light.
        assert!(check_rect(Vec3::X, Vec3::new(1.0, 1e-3, 0.0)).is_ok());
    }

    #[test]
    fn row_major_matrix_puts_the_translation_in_the_last_column() {
        let rows = [1.0, 0.0, 0.0, 4.0, 0.0, 1.0, 0.0, 5.0, 0.0, 0.0, 1.0, 6.0, 0.0, 0.0, 0.0, 1.0];
        let m = affine_from_rows(&rows).unwrap();
        assert_eq!(m.transform_point3(Vec3::ZERO), Vec3::new(4.0, 5.0, 6.0));
        let mut projective = rows;
        projective[14] = 1.0;
        assert!(affine_from_rows(&projective).is_err());
    }
}
