//! The bounding box of every shape, in its own coordinates and placed in the
//! world by its object's transform.

use raylab::math::gamma;
use raylab::scene::{Object, Shape};
use raylab::{Float, Mat4, Vec3};

use crate::aabb::Aabb;

/// The box around a sphere: c − r ≤ p ≤ c + r on every axis, each end
/// rounded outward by one step (`next_down`, `next_up`): the sum c ± r rounds
/// by at most half a step, so the box holds the exact sphere.
///
/// `radius` must not be negative. Book: §9.3 Bounding the shapes.
pub fn sphere_bounds(center: Vec3, radius: Float) -> Aabb {
    debug_assert!(radius >= 0.0, "a sphere's radius must not be negative, found {radius}");
    // SOLUTION BEGIN
    let r = Vec3::splat(radius);
    Aabb::new((center - r).map(Float::next_down), (center + r).map(Float::next_up))
    // SOLUTION END
}

/// The box around the triangle (a, b, c): the componentwise min and max of
/// its corners (exact: no arithmetic). A triangle in an axis plane gives a
/// flat box. Book: §9.3 Bounding the shapes.
pub fn triangle_bounds(vertices: &[Vec3; 3]) -> Aabb {
    // SOLUTION BEGIN
    let [a, b, c] = *vertices;
    Aabb::new(a.min(b).min(c), a.max(b).max(c))
    // SOLUTION END
}

/// The box around the image of the finite box `local` under the affine map
/// `world_from_object`.
///
/// An affine map takes a box to a parallelepiped, the convex hull of the
/// images of the box's 8 corners, so the box around those 8 points holds it.
/// Each world corner M·p is computed with rounding: three products summed in
/// order, then the translation, so each term is rounded at most four times,
/// and the result moved by ±e once more: the corner is widened by
/// e = γ₅·(|M|·|p| + |t|) per component, |M| the matrix of absolute values
/// (pbrt §6.8.5, with one more rounding for glam's order of summation).
///
/// `local` must be finite; `world_from_object` affine.
/// Book: §9.3 Bounding transformed objects.
pub fn transform_bounds(local: &Aabb, world_from_object: &Mat4) -> Aabb {
    debug_assert!(local.is_finite(), "only a finite box can be transformed, found {local:?}");
    // SOLUTION BEGIN
    let abs = world_from_object.abs();
    let mut world = Aabb::EMPTY;
    for corner in 0..8 {
        // Corner i takes the max end on axis k when bit k of i is set.
        let pick = |axis: usize| if corner & (1 << axis) == 0 { local.min[axis] } else { local.max[axis] };
        let p = Vec3::new(pick(0), pick(1), pick(2));

        // Its image, widened by the rounding error of the transform.
        let image = world_from_object.transform_point3(p);
        let error = gamma(5) * abs.transform_point3(p.abs());
        world = world.union_point(image - error).union_point(image + error);
    }
    world
    // SOLUTION END
}

/// The box around `shape` in its own coordinates: spheres by
/// [`sphere_bounds`], triangles by [`triangle_bounds`], boxes are their own
/// bounds, polygons and meshes the box of their vertices, the canonical
/// cylinder and cone [−1, 1] × [−1, 1] × [0, 1]. A plane is unbounded:
/// [`Aabb::INFINITE`] (the BVH keeps such objects out of its tree and tests
/// them on every ray). A mesh without vertices gives [`Aabb::EMPTY`].
/// Glue: the exercises are the cases it calls. Book: §9.3 Bounding the shapes.
pub fn bounds(shape: &Shape) -> Aabb {
    match shape {
        Shape::Sphere { center, radius } => sphere_bounds(*center, *radius),
        Shape::Plane { .. } => Aabb::INFINITE,
        Shape::Box { min, max } => Aabb::new(*min, *max),
        Shape::Polygon { vertices } => vertices.iter().fold(Aabb::EMPTY, |b, &p| b.union_point(p)),
        Shape::Triangle { vertices, .. } => triangle_bounds(vertices),
        Shape::Mesh(mesh) => {
            let (min, max) = mesh.bounds();
            Aabb::new(min, max)
        }
        Shape::Cylinder | Shape::Cone => Aabb::new(Vec3::new(-1.0, -1.0, 0.0), Vec3::ONE),
    }
}

/// The box around `object` in world coordinates: [`bounds`] of its shape,
/// taken through its transform by [`transform_bounds`] when it has one. An
/// unbounded shape stays [`Aabb::INFINITE`] and an empty one
/// [`Aabb::EMPTY`] under any transform; a transform so large that the box
/// overflows gives a box that is not finite (the BVH then treats the object
/// as unbounded). Glue. Book: §9.3 Bounding transformed objects.
pub fn object_bounds(object: &Object) -> Aabb {
    let local = bounds(&object.shape);
    match &object.transform {
        None => local,
        Some(_) if local.is_empty() => Aabb::EMPTY,
        Some(_) if !local.is_finite() => Aabb::INFINITE,
        Some(transform) => transform_bounds(&local, &transform.world_from_object),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{Rng, d3, mat_f64};
    use raylab::scene::{Mesh, Transform};
    use raylab_testing::wide;
    use std::sync::Arc;

    fn placed(shape: Shape, world_from_object: Option<Mat4>) -> Object {
        Object { shape, material: 0, transform: world_from_object.map(|m| Transform::new(m).unwrap()) }
    }

    #[test]
    fn bounds_of_each_shape_by_hand() {
        // A sphere at (1, −2, 3) of radius 0.5: [0.5, 1.5] × [−2.5, −1.5] × [2.5, 3.5], exact
        // sums, each end then one step outward.
        let b = sphere_bounds(Vec3::new(1.0, -2.0, 3.0), 0.5);
        assert_eq!(b.min, Vec3::new(0.5, -2.5, 2.5).map(Float::next_down));
        assert_eq!(b.max, Vec3::new(1.5, -1.5, 3.5).map(Float::next_up));
        let (lo, hi) = (Vec3::new(-1.0, 0.0, 2.0), Vec3::new(1.0, 0.0, 5.0));
        assert_eq!(bounds(&Shape::Box { min: lo, max: hi }), Aabb::new(lo, hi));
        let tri = [Vec3::new(0.0, 1.0, 2.0), Vec3::new(-1.0, 4.0, 2.0), Vec3::new(3.0, 0.5, 2.0)];
        // Flat in z: the triangle lies in z = 2.
        let expected = Aabb::new(Vec3::new(-1.0, 0.5, 2.0), Vec3::new(3.0, 4.0, 2.0));
        assert_eq!(bounds(&Shape::Triangle { vertices: tri, normals: None }), expected);
        assert_eq!(bounds(&Shape::Polygon { vertices: tri.to_vec() }), expected);
        let canonical = Aabb::new(Vec3::new(-1.0, -1.0, 0.0), Vec3::ONE);
        assert_eq!(bounds(&Shape::Cylinder), canonical);
        assert_eq!(bounds(&Shape::Cone), canonical);
        assert_eq!(bounds(&Shape::Plane { normal: Vec3::Y, offset: 1.0 }), Aabb::INFINITE);
        // The unit icosphere's vertices include (±1, 0, 0)-like extremes only up to rounding;
        // its box is that of its positions, within the unit cube ±4ε.
        let ico = bounds(&Shape::Mesh(Arc::new(Mesh::icosphere(1))));
        assert!(ico.min.cmpge(Vec3::splat(-1.0 - 4.0 * Float::EPSILON)).all());
        assert!(ico.max.cmple(Vec3::splat(1.0 + 4.0 * Float::EPSILON)).all());
        assert_eq!(bounds(&Shape::Mesh(Arc::new(Mesh::default()))), Aabb::EMPTY);
    }

    #[test]
    fn rotated_cube_bounds_by_hand() {
        // The cube [−1, 1]³ turned 45° about z: its corners (±1, ±1) reach x, y = ±√2;
        // z stays ±1. Tolerance: the widening γ₅(|M||p| + |t|) ≤ γ₅·2 per component, plus
        // the rotation's own rounding of sin and cos (ε each): 16ε covers both.
        let cube = placed(
            Shape::Box { min: -Vec3::ONE, max: Vec3::ONE },
            Some(Mat4::from_rotation_z(0.25 * raylab::math::consts::PI)),
        );
        let b = object_bounds(&cube);
        let s = (2.0 as Float).sqrt();
        let tol = 16.0 * Float::EPSILON;
        approx::assert_abs_diff_eq!(b.max, Vec3::new(s, s, 1.0), epsilon = tol);
        approx::assert_abs_diff_eq!(b.min, -Vec3::new(s, s, 1.0), epsilon = tol);
        assert!(b.max.x >= s && b.max.z >= 1.0, "widened outward: {b:?}");
        // A translation moves the box; a plane stays unbounded, an empty mesh empty.
        let moved = placed(
            Shape::Sphere { center: Vec3::ZERO, radius: 1.0 },
            Some(Mat4::from_translation(Vec3::new(10.0, 0.0, 0.0))),
        );
        approx::assert_abs_diff_eq!(
            object_bounds(&moved).min,
            Vec3::new(9.0, -1.0, -1.0),
            epsilon = 32.0 * Float::EPSILON
        );
        let plane = placed(Shape::Plane { normal: Vec3::Y, offset: 0.0 }, Some(Mat4::from_rotation_x(0.3)));
        assert_eq!(object_bounds(&plane), Aabb::INFINITE);
        let empty = placed(Shape::Mesh(Arc::new(Mesh::default())), Some(Mat4::from_scale(Vec3::splat(2.0))));
        assert_eq!(object_bounds(&empty), Aabb::EMPTY);
    }

    /// `n` points on the surface of `shape` in its own coordinates, computed in
    /// f64 from the shape's `Float` parameters (an independent construction).
    fn surface_points(shape: &Shape, rng: &mut Rng, n: usize) -> Vec<[f64; 3]> {
        let lerp3 = |p: [f64; 3], q: [f64; 3], r: [f64; 3], b: f64, c: f64| -> [f64; 3] {
            std::array::from_fn(|i| (1.0 - b - c) * p[i] + b * q[i] + c * r[i])
        };
        (0..n)
            .map(|_| match shape {
                Shape::Sphere { center, radius } => {
                    let (c, u) = (d3(*center), rng.unit_f64());
                    std::array::from_fn(|i| c[i] + wide(*radius) * u[i])
                }
                Shape::Box { min, max } => {
                    // A random point on a random face: one coordinate at its min or max.
                    let (lo, hi) = (d3(*min), d3(*max));
                    let face = rng.below(6) as usize;
                    std::array::from_fn(|i| {
                        if i == face % 3 {
                            if face < 3 { lo[i] } else { hi[i] }
                        } else {
                            lo[i] + (hi[i] - lo[i]) * rng.f64()
                        }
                    })
                }
                Shape::Triangle { vertices, .. } => {
                    let (b, c) = rng.barycentric();
                    lerp3(d3(vertices[0]), d3(vertices[1]), d3(vertices[2]), b, c)
                }
                Shape::Polygon { vertices } => {
                    // Points of the fan triangles (v₀, vᵢ, vᵢ₊₁): inside the convex hull.
                    let i = 1 + rng.below(vertices.len() as u64 - 2) as usize;
                    let (b, c) = rng.barycentric();
                    lerp3(d3(vertices[0]), d3(vertices[i]), d3(vertices[i + 1]), b, c)
                }
                Shape::Mesh(mesh) => {
                    let [a, b, c] = mesh.triangle(rng.below(mesh.triangles.len() as u64) as usize);
                    let (u, v) = rng.barycentric();
                    lerp3(d3(a), d3(b), d3(c), u, v)
                }
                Shape::Cylinder | Shape::Cone => {
                    // The side or a cap (z = 0, z = 1 for the cylinder), radius 1 − z for the cone.
                    let phi = std::f64::consts::TAU * rng.f64();
                    let cone = matches!(shape, Shape::Cone);
                    let (z, on_side) = match rng.below(3) {
                        0 => (rng.f64(), true),
                        1 => (0.0, false),
                        _ => (1.0, false),
                    };
                    let rim = if cone { 1.0 - z } else { 1.0 };
                    let r = if on_side { rim } else { rim * rng.f64().sqrt() };
                    [r * phi.cos(), r * phi.sin(), z]
                }
                Shape::Plane { normal, offset } => {
                    // offset·n plus a far point of the plane.
                    let n = d3(*normal);
                    let t = rng.unit_f64();
                    let tangent =
                        [n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]];
                    std::array::from_fn(|i| wide(*offset) * n[i] + 1e6 * tangent[i])
                }
            })
            .collect()
    }

    /// Whether the f64 point `p` is in `b`, allowing `8·ε_f64·scale` for the f64
    /// rounding of the sample itself, `scale` the size of the terms it was summed from
    /// (in an f32 build that is far below an f32 step, so the box must hold the exact
    /// surface).
    fn holds(b: &Aabb, p: [f64; 3], scale: f64) -> bool {
        let slack = 8.0 * f64::EPSILON * scale;
        (0..3).all(|i| wide(b.min[i]) - slack <= p[i] && p[i] <= wide(b.max[i]) + slack)
    }

    #[test]
    fn bounds_contain_random_surface_points_of_every_shape() {
        // 10⁴ points on each shape, plain and placed by an awkward transform (non-uniform
        // scale, rotation, far translation); the points are taken to the world in f64.
        let mesh = Arc::new(Mesh::torus(1.3, 0.4, 24, 12));
        let shapes = vec![
            Shape::Sphere { center: Vec3::new(0.1, -3.7, 1e3), radius: 0.3 },
            Shape::Plane { normal: Vec3::new(0.6, 0.0, 0.8), offset: 2.0 },
            Shape::Box { min: Vec3::new(-1.0, 0.25, 3.0), max: Vec3::new(0.7, 0.25, 3.9) },
            Shape::Polygon {
                vertices: vec![
                    Vec3::new(0.0, 0.0, 1.0),
                    Vec3::new(2.0, 0.1, 1.3),
                    Vec3::new(1.7, 1.9, 1.6),
                    Vec3::new(-0.3, 1.1, 1.2),
                ],
            },
            Shape::Triangle {
                vertices: [Vec3::new(0.3, 0.1, -7.0), Vec3::new(-1.1, 2.2, 0.4), Vec3::new(5.0, -0.7, 0.1)],
                normals: None,
            },
            Shape::Mesh(mesh),
            Shape::Cylinder,
            Shape::Cone,
        ];
        let world_from_object = Mat4::from_translation(Vec3::new(-40.0, 7.0, 300.0))
            * Mat4::from_axis_angle(Vec3::new(1.0, 2.0, -0.5).normalize(), 0.9)
            * Mat4::from_scale(Vec3::new(3.0, 0.01, 70.0));
        let m = mat_f64(&world_from_object);
        let mut rng = Rng::new(21);
        for shape in shapes {
            let points = surface_points(&shape, &mut rng, 10_000);
            let plain = object_bounds(&placed(shape.clone(), None));
            let moved = object_bounds(&placed(shape.clone(), Some(world_from_object)));
            // The size of the coordinates the samples are made of (∞ for the plane, whose
            // box is unbounded anyway), and of the terms of their images.
            let scale = d3(plain.min).iter().chain(&d3(plain.max)).fold(1.0f64, |s, x| s.max(x.abs()));
            let world_scale = (0..3)
                .map(|i| (0..3).map(|j| m[i][j].abs() * scale).sum::<f64>() + m[i][3].abs())
                .fold(0.0f64, f64::max);
            for p in points {
                assert!(holds(&plain, p, scale), "{} {p:?} is outside {plain:?}", shape.kind());
                let q: [f64; 3] =
                    std::array::from_fn(|i| m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3]);
                assert!(holds(&moved, q, world_scale), "placed {} {q:?} is outside {moved:?}", shape.kind());
            }
        }
    }
}
