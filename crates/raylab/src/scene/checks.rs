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

/// What numbers must be, in messages, given what was found: "finite
/// numbers" for NaN and ±∞, and "numbers within the range of 32-bit floats
/// (±3.4028235e38)" for values finite in the file but not as a `Float` (1e39
/// in an f32 build; an f64 build has no such value). One number: "a finite
/// number", "a number within …".
pub fn finite_words(found: &[f64]) -> String {
    let (article, plural) = if found.len() == 1 { ("a ", "") } else { ("", "s") };
    if found.iter().all(|x| x.is_finite()) {
        let bits = 8 * size_of::<Float>();
        format!("{article}number{plural} within the range of {bits}-bit floats (±{:e})", Float::MAX)
    } else {
        format!("{article}finite number{plural}")
    }
}

/// A number for messages: shortest round-trip digits, in exponent form when
/// very large or small (`1e39`, not forty digits).
pub fn number(x: f64) -> String {
    digits(x, x)
}

/// `x` in shortest round-trip digits, in exponent form when `magnitude` (x in
/// f64) is 0 < |x| < 10⁻⁴ or |x| ≥ 10¹⁵.
fn digits(x: impl std::fmt::Display + std::fmt::LowerExp, magnitude: f64) -> String {
    if magnitude == 0.0 || !magnitude.is_finite() || (1e-4..1e15).contains(&magnitude.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// [`number`] for a `Float`: its own shortest digits (an f32's `1e-45`, not
/// the `1.401298464324817e-45` of its widening to f64).
pub fn float(x: Float) -> String {
    digits(x, f64::from(x))
}

/// A vector for messages: `[1, 0, -2.5]`, each component as [`float`] writes it
/// (`[0, -1e19, 1e13]`, not forty digits).
pub fn show(v: Vec3) -> String {
    let [x, y, z] = v.to_array().map(float);
    format!("[{x}, {y}, {z}]")
}

/// `v / |v|`, or an error for a zero (or too tiny to normalise) vector.
pub fn unit(v: Vec3, what: &str) -> Result<Vec3, String> {
    v.try_normalize().ok_or_else(|| format!("{what} must be a non-zero vector, found {}", show(v)))
}

/// The words a camera's view is written in: a TOML file's `eye` and `at`, or
/// a 6.837 file's `center` and `direction`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ViewWords {
    Toml,
    Mit6837,
}

/// The camera's view must be defined: a non-zero view direction `view`
/// (TOML: at − eye; 6.837: `direction`), and `up` not parallel to it, tested
/// as |up × d| ≤ 10⁻⁶·|up|·|d| (the sine of the angle between them at most
/// 10⁻⁶, which also catches a zero `up`) on both vectors scaled to a largest
/// component of 1, so that neither a far target (at = [1e20, 0, −5]) nor a
/// tiny direction overflows or underflows the test. Book: §1.4 Look-at.
///
/// Returns the target the scene keeps: `None` for `at` itself, or, when at −
/// eye is too long or too short for its length to be computed in `Float`
/// (its square overflows or underflows) or lost beside eye, a target one
/// step of |eye| (at least 1) along the same direction: a far target is a
/// way of saying "look along this direction".
pub fn check_view(
    eye: Vec3,
    at: Vec3,
    view: Vec3,
    up: Vec3,
    words: ViewWords,
) -> Result<Option<Vec3>, String> {
    let shown = match words {
        ViewWords::Toml => format!("the view direction at − eye = {}", show(view)),
        ViewWords::Mit6837 => format!("direction {}", show(view)),
    };
    if view == Vec3::ZERO {
        return Err(match words {
            ViewWords::Toml => format!("at must differ from eye, both are {}", show(eye)),
            ViewWords::Mit6837 => "direction must be a non-zero vector, found [0, 0, 0]".to_owned(),
        });
    }
    if !view.is_finite() {
        return Err(format!(
            "{shown} is beyond the range of {}-bit floats (±{:e}): only the direction counts, so bring the \
             target closer",
            8 * size_of::<Float>(),
            Float::MAX
        ));
    }
    let scaled = |v: Vec3| v / v.abs().max_element();
    let (d, u) = (scaled(view), scaled(up));
    if up == Vec3::ZERO || !up.is_finite() || u.cross(d).length() <= 1e-6 * u.length() * d.length() {
        return Err(format!(
            "up {} is zero or parallel to {shown}, to within 10⁻⁶ radians: the camera's roll is undefined",
            show(up)
        ));
    }
    let kept = at - eye;
    let length2 = kept.length_squared();
    if kept != Vec3::ZERO && length2.is_finite() && length2 >= Float::MIN_POSITIVE {
        return Ok(None);
    }
    let step = eye.abs().max_element().max(1.0);
    let target = eye + step * d.normalize();
    if target == eye || !target.is_finite() {
        return Err(format!("{shown} is lost beside eye {}: eye is too far from the origin", show(eye)));
    }
    Ok(Some(target))
}

/// A perspective camera's full vertical field of view `key` (`fovy`, 6.837's
/// `angle`) of `degrees`, in radians: in (0, 180) degrees, and not so small
/// that it rounds to 0 radians (5e-324 degrees in f64, 1e-45 in f32).
pub fn field_of_view(degrees: Float, key: &str) -> Result<Float, String> {
    if !(degrees > 0.0 && degrees < 180.0) {
        return Err(format!("{key} must be in (0, 180) degrees, found {}", float(degrees)));
    }
    let radians = crate::math::radians(degrees);
    if radians == 0.0 {
        return Err(format!(
            "{key} must be in (0, 180) degrees, found {}: too small, it is 0 in radians with {}-bit floats",
            float(degrees),
            8 * size_of::<Float>()
        ));
    }
    Ok(radians)
}

/// The indices of refraction a material may have: real materials lie between
/// 1 and about 4 (6.837's scenes use 1 to 4); below 10⁻² or above 10² the
/// refraction formula's η = η_i/η_t and η² lose the refracted direction's
/// digits (an index of 10³⁹ collapses it to zero; one of 10⁻³⁹ makes η
/// infinite in f32; both found by the bad-scenes fuzz test).
pub const IOR_RANGE: std::ops::RangeInclusive<Float> = 0.01..=100.0;

/// A material's index of refraction `key` (`ior`, 6.837's `indexOfRefraction`)
/// within [`IOR_RANGE`].
pub fn index_of_refraction(ior: Float, key: &str) -> Result<Float, String> {
    if IOR_RANGE.contains(&ior) {
        Ok(ior)
    } else {
        Err(format!(
            "{key} must be from {} to {} (real materials: 1 to about 4), found {}",
            IOR_RANGE.start(),
            IOR_RANGE.end(),
            float(ior)
        ))
    }
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
        let toml = |at: Vec3, up: Vec3| check_view(eye, at, at - eye, up, ViewWords::Toml);
        assert!(toml(Vec3::ZERO, Vec3::Z).is_err(), "up parallel to −view");
        assert!(toml(Vec3::ZERO, Vec3::ZERO).is_err(), "zero up");
        assert_eq!(toml(eye, Vec3::Y).unwrap_err(), "at must differ from eye, both are [0, 0, 5]");
        // sin θ = 10⁻³ ≫ 10⁻⁶: accepted although far from perpendicular, and `at` kept.
        assert_eq!(toml(Vec3::ZERO, Vec3::new(1e-3, 0.0, 1.0)), Ok(None));
        // 6.837's words for a zero direction.
        assert_eq!(
            check_view(eye, eye, Vec3::ZERO, Vec3::Y, ViewWords::Mit6837).unwrap_err(),
            "direction must be a non-zero vector, found [0, 0, 0]"
        );
    }

    #[test]
    fn a_far_target_is_a_direction_and_a_tiny_one_too() {
        // |at − eye|² = 10⁴⁰ overflows f32: the target becomes eye + 1·d̂, d̂ ≈ +x (in f64 the
        // square is finite and `at` is kept).
        let (eye, at) = (Vec3::ZERO, Vec3::new(1e20, 0.0, -5.0));
        let kept = check_view(eye, at, at - eye, Vec3::Y, ViewWords::Toml).unwrap();
        assert_eq!(kept.is_some(), size_of::<Float>() == 4);
        assert!((kept.unwrap_or(at).normalize() - Vec3::X).length() < 1e-6, "{kept:?}");
        // A direction of 10⁻³⁰ from an eye at 10: lost beside eye (at = eye) in f32 and f64;
        // the target becomes eye + 10·d̂.
        let (eye, direction) = (Vec3::splat(10.0), Vec3::new(0.0, 0.0, -1e-30));
        let target =
            check_view(eye, eye + direction, direction, Vec3::Y, ViewWords::Mit6837).unwrap().unwrap();
        assert_eq!(target, Vec3::new(10.0, 10.0, 0.0));
        // at − eye beyond the float range: refused, saying so.
        let said =
            check_view(-Vec3::X * Float::MAX, Vec3::X * Float::MAX, Vec3::INFINITY, Vec3::Y, ViewWords::Toml);
        assert!(said.unwrap_err().contains("beyond the range"), "overflow");
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
