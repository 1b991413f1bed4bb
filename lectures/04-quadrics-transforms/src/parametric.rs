//! Normals of parametric surfaces.

use raylab::Vec3;

/// The unit normal of a parametric surface s(α, β) from its two partial
/// derivatives: n = (∂s/∂α × ∂s/∂β) / |∂s/∂α × ∂s/∂β|.
///
/// The order of the factors sets the side: swapping α and β flips n. For the
/// sphere s(θ, φ) = (sin θ cos φ, sin θ sin φ, cos θ) the cross product is
/// sin θ · s, the outward radial direction. At a singular point (the
/// partials parallel or one of them zero, as at a sphere's poles) the normal
/// is undefined and the zero vector is returned instead of NaN.
/// Book: §4.7 Normals of parametric surfaces.
pub fn parametric_normal(ds_dalpha: Vec3, ds_dbeta: Vec3) -> Vec3 {
    // SOLUTION BEGIN
    ds_dalpha.cross(ds_dbeta).normalize_or_zero()
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::EPS;
    use crate::{hit_cone, hit_cylinder, normal_to_world};
    use approx::assert_abs_diff_eq;
    use raylab::{Float, Interval, Mat4, Ray};

    /// The unit sphere s(θ, φ) = (sin θ cos φ, sin θ sin φ, cos θ) and its partials.
    fn sphere(theta: Float, phi: Float) -> (Vec3, Vec3, Vec3) {
        let (st, ct, sp, cp) = (theta.sin(), theta.cos(), phi.sin(), phi.cos());
        (Vec3::new(st * cp, st * sp, ct), Vec3::new(ct * cp, ct * sp, -st), Vec3::new(-st * sp, st * cp, 0.0))
    }

    fn grid() -> impl Iterator<Item = (Float, Float)> {
        (1..30).flat_map(|i| (0..36).map(move |j| (i as Float * 0.1, j as Float * 0.175)))
    }

    #[test]
    fn sphere_normal_is_the_radial_direction() {
        // ∂s/∂θ × ∂s/∂φ = sin θ · s: outward, radial. |s| = 1 up to rounding, so 16ε.
        for (theta, phi) in grid() {
            let (s, ds_dtheta, ds_dphi) = sphere(theta, phi);
            assert_abs_diff_eq!(parametric_normal(ds_dtheta, ds_dphi), s, epsilon = 16.0 * EPS);
            // The order of the parameters picks the side.
            assert_abs_diff_eq!(parametric_normal(ds_dphi, ds_dtheta), -s, epsilon = 16.0 * EPS);
        }
    }

    #[test]
    fn a_pole_gives_zero_not_nan() {
        // At θ = 0 the φ-partial vanishes: the parametrisation is singular there.
        let (_, ds_dtheta, ds_dphi) = sphere(0.0, 1.0);
        assert_eq!(parametric_normal(ds_dtheta, ds_dphi), Vec3::ZERO);
    }

    #[test]
    fn ellipsoid_three_ways_agree() {
        // s(θ, φ) = (a sin θ cos φ, b sin θ sin φ, c cos θ): its parametric normal, the
        // gradient (x/a², y/b², z/c²) and (A⁻¹)ᵀ applied to the unit sphere's normal
        // with A = S(a, b, c) are one direction. 64ε: a few roundings, times the axis
        // ratio 4.
        let semi = Vec3::new(2.0, 0.5, 1.0);
        let object_from_world = Mat4::from_scale(semi.recip());
        for (theta, phi) in grid() {
            let (unit, ds_dtheta, ds_dphi) = sphere(theta, phi);
            let parametric = parametric_normal(ds_dtheta * semi, ds_dphi * semi);
            let gradient = (unit * semi / (semi * semi)).normalize();
            assert_abs_diff_eq!(parametric, gradient, epsilon = 64.0 * EPS);
            assert_abs_diff_eq!(normal_to_world(unit, &object_from_world), gradient, epsilon = 64.0 * EPS);
        }
    }

    #[test]
    fn cylinder_and_cone_parametrisations_match_their_hit_normals() {
        // Cylinder s(φ, z) = (cos φ, sin φ, z): ∂φ × ∂z = (cos φ, sin φ, 0).
        // Cone s(φ, z) = ((1 − z) cos φ, (1 − z) sin φ, z): ∂φ × ∂z = (1 − z)(cos φ, sin φ, 1).
        // Shoot at s from one unit out along that normal; 64ε covers both computations.
        for (i, j) in (1..10).flat_map(|i| (0..12).map(move |j| (i, j))) {
            let (z, phi) = (i as Float * 0.1, j as Float * 0.5);
            let (sp, cp) = phi.sin_cos();
            let cases = [
                (
                    Vec3::new(cp, sp, z),
                    Vec3::new(-sp, cp, 0.0),
                    Vec3::Z,
                    hit_cylinder as fn(&Ray, Interval) -> _,
                ),
                (
                    Vec3::new((1.0 - z) * cp, (1.0 - z) * sp, z),
                    Vec3::new(-(1.0 - z) * sp, (1.0 - z) * cp, 0.0),
                    Vec3::new(-cp, -sp, 1.0),
                    hit_cone,
                ),
            ];
            for (s, ds_dphi, ds_dz, hit) in cases {
                let n = parametric_normal(ds_dphi, ds_dz);
                let h = hit(&Ray::new(s + n, -n), Interval::POSITIVE).expect("aimed at the surface");
                assert_abs_diff_eq!(h.normal, n, epsilon = 64.0 * EPS);
            }
        }
    }
}
