// INSTRUCTOR ONLY: left out of the handout; `grader grade --submission` turns these checks on.
//! Hidden checks: the same exercises at inputs the students have not seen,
//! so that a solution fitted to the visible checks' numbers does not pass.
//! Gradescope shows them after the grades are published.

use super::{Lecture, built};

pub fn lectures() -> Vec<Lecture> {
    vec![
        Lecture { number: "01", checks: h01::CHECKS, run: built!("l01", h01::run), lend: None, hidden: true },
        Lecture { number: "02", checks: h02::CHECKS, run: built!("l02", h02::run), lend: None, hidden: true },
        Lecture { number: "03", checks: h03::CHECKS, run: built!("l03", h03::run), lend: None, hidden: true },
        Lecture { number: "05", checks: h05::CHECKS, run: built!("l05", h05::run), lend: None, hidden: true },
        Lecture { number: "07", checks: h07::CHECKS, run: built!("l07", h07::run), lend: None, hidden: true },
        Lecture { number: "09", checks: h09::CHECKS, run: built!("l09", h09::run), lend: None, hidden: true },
    ]
}

mod h01 {
    use crate::check::Meta;

    raylab_checks_core::declare_checks! {
        "l01", judged;
        Meta::unit("rotate_z", "a quarter turn about z takes x to y, counter-clockwise seen from +z")
        .named_hidden("hidden-quarter-turn") => hidden(),
    }

    #[cfg(feature = "l01")]
    mod code {
        pub(super) fn hidden() -> crate::check::CheckResult {
            use crate::check::close3;
            use crate::lectures::l01::common::{rotate_z, transform_vector};
            use raylab::{Float, Vec3};
            // R_z(90°) = [[0, −1, 0], [1, 0, 0], [0, 0, 1]]: x ↦ y and y ↦ −x; cos 90° rounds to ~6e-8 in f32.
            let r = rotate_z::call(std::f64::consts::FRAC_PI_2 as Float);
            let case = "rotate_z(π/2) applied to the vectors x and y";
            let tolerance = 4.0 * Float::EPSILON;
            let cause =
                "R_z(θ) = [[cos θ, −sin θ, 0], [sin θ, cos θ, 0], [0, 0, 1]]: counter-clockwise seen from +z";
            close3(case, transform_vector::call(&r, Vec3::X), Vec3::Y, tolerance, cause)?;
            close3(case, transform_vector::call(&r, Vec3::Y), -Vec3::X, tolerance, cause)
                .map(|()| "2 cases".into())
        }
    }
}

mod h02 {
    use crate::check::Meta;

    raylab_checks_core::declare_checks! {
            "l02", judged;
            Meta::unit(
        "hit_sphere_stable",
        "an off-axis ray at an off-centre sphere of radius 0.5, both roots ahead",
    )
    .named_hidden("hidden-off-axis") => hidden(),
        }

    #[cfg(feature = "l02")]
    mod code {
        pub(super) fn hidden() -> crate::check::CheckResult {
            use crate::check::{close, fail};
            use crate::lectures::l02::common::hit_sphere_stable;
            use raylab::{Float, Interval, Ray, Vec3};
            // Sphere r = 0.5 at (1, 2, −3); the ray from (1, 2.3, 2) along −z passes 0.3 from the
            // centre: half chord √(0.25 − 0.09) = 0.4, so t = 5 − 0.4 = 4.6 (and 5.4).
            let case = "sphere r = 0.5 at (1, 2, −3), ray from (1, 2.3, 2) along (0, 0, −1)";
            let ray = Ray::new(Vec3::new(1.0, 2.3, 2.0), Vec3::new(0.0, 0.0, -1.0));
            let got = hit_sphere_stable::call(
                &ray,
                Vec3::new(1.0, 2.0, -3.0),
                0.5,
                Interval::new(0.0, Float::INFINITY),
            );
            let Some(hit) = got else {
                return Err(fail(
                    case,
                    "t = 4.6",
                    "None",
                    "the ray passes 0.3 from the centre, inside r = 0.5",
                ));
            };
            // 4.6 is not exact in binary: a few ulp of 5.
            let tolerance = 64.0 * Float::EPSILON * 5.0;
            close(case, hit.t, 4.6, tolerance, "the nearer root of the quadratic").map(|()| "1 case".into())
        }
    }
}

mod h03 {
    use crate::check::Meta;

    raylab_checks_core::declare_checks! {
        "l03", judged;
        Meta::unit("hit_slabs", "a ray along +z through an off-origin box: enter and exit t by hand")
        .named_hidden("hidden-off-origin-box") => hidden(),
    }

    #[cfg(feature = "l03")]
    mod code {
        pub(super) fn hidden() -> crate::check::CheckResult {
            use crate::check::{close, fail};
            use crate::lectures::l03::common::hit_slabs;
            use raylab::{Float, Interval, Ray, Vec3};
            // Box [−1, 2] × [0, 3] × [1, 4]; ray from (0.5, 1, −10) along (0, 0, 2): x and y stay inside,
            // z enters at (1 + 10)/2 = 5.5 and leaves at (4 + 10)/2 = 7.
            let case = "box [−1, 2] × [0, 3] × [1, 4], ray from (0.5, 1, −10) along (0, 0, 2)";
            let ray = Ray::new(Vec3::new(0.5, 1.0, -10.0), Vec3::new(0.0, 0.0, 2.0));
            let got = hit_slabs::call(
                &ray,
                Vec3::new(-1.0, 0.0, 1.0),
                Vec3::new(2.0, 3.0, 4.0),
                Interval::new(0.0, Float::INFINITY),
            );
            let Some((enter, exit)) = got else {
                return Err(fail(
                    case,
                    "(5.5, 7)",
                    "None",
                    "x and y stay inside their slabs; only z limits t",
                ));
            };
            // The exit may be widened by 1 + 2γ₃ (a few ulp of 7).
            let tolerance = 16.0 * Float::EPSILON * 7.0;
            let cause = "t = (slab − o)/d per axis, in units of dir; enter = max of the nears, exit = min of the fars";
            close(case, enter, 5.5, tolerance, cause)?;
            close(case, exit, 7.0, tolerance, cause).map(|()| "1 case".into())
        }
    }
}

mod h05 {
    use crate::check::Meta;

    raylab_checks_core::declare_checks! {
        "l05", judged;
        Meta::unit("lambert", "a 3-4-5 direction to the light, and the same light behind the surface")
        .named_hidden("hidden-3-4-5") => hidden(),
    }

    #[cfg(feature = "l05")]
    mod code {
        pub(super) fn hidden() -> crate::check::CheckResult {
            use crate::check::close;
            use crate::lectures::l05::common::lambert;
            use raylab::{Float, Vec3};
            // n = z, l = (0, 0.6, 0.8): cos θ = 0.8; the light mirrored behind the surface gives 0, not −0.8.
            let n = Vec3::Z;
            let case = "n = (0, 0, 1), l = (0, 0.6, 0.8)";
            let tolerance = 4.0 * Float::EPSILON;
            close(case, lambert::call(n, Vec3::new(0.0, 0.6, 0.8)), 0.8, tolerance, "max(n·l, 0)")?;
            let case = "n = (0, 0, 1), l = (0, 0.6, −0.8): the light behind the surface";
            let got = lambert::call(n, Vec3::new(0.0, 0.6, -0.8));
            close(case, got, 0.0, 0.0, "max(n·l, 0): no negative light").map(|()| "2 cases".into())
        }
    }
}

mod h07 {
    use crate::check::Meta;

    raylab_checks_core::declare_checks! {
        "l07", judged;
        Meta::unit("refract", "refraction into glass at 30° and back out, against Snell's law by hand")
        .named_hidden("hidden-snell-both-ways") => hidden(),
    }

    #[cfg(feature = "l07")]
    mod code {
        pub(super) fn hidden() -> crate::check::CheckResult {
            use crate::check::{close3, fail};
            use crate::lectures::l07::common::refract;
            use raylab::{Float, Vec3};
            // i at 30° to the normal n = +y, going down: i = (sin 30°, −cos 30°, 0). Into glass
            // (η = 1/1.5): sin θt = sin 30° / 1.5 = 1/3, cos θt = √(8/9), t = (1/3, −√(8/9), 0).
            let (s, c) = (0.5 as Float, (0.75 as Float).sqrt());
            let i = Vec3::new(s, -c, 0.0);
            let expected = Vec3::new(1.0 / 3.0, -(8.0 as Float / 9.0).sqrt(), 0.0);
            let case = "i at 30° from the normal (0, 1, 0), air to glass (η = 1/1.5)";
            let Some(t) = refract::call(i, Vec3::Y, 1.0 / 1.5) else {
                return Err(fail(
                    case,
                    "a refracted ray",
                    "None",
                    "no total internal reflection going into glass",
                ));
            };
            let tolerance = 16.0 * Float::EPSILON;
            close3(case, t, expected, tolerance, "t = η i + (η cos θi − cos θt) n")?;
            // And back out along the reversed ray: the original direction, reversed (reciprocity).
            let case = "the refracted ray reversed, glass to air (η = 1.5), normal (0, −1, 0) facing it";
            let Some(back) = refract::call(-t, -Vec3::Y, 1.5) else {
                return Err(fail(
                    case,
                    "a refracted ray",
                    "None",
                    "below the critical angle there is a refracted ray",
                ));
            };
            close3(case, back, -i, tolerance, "Snell's law is reversible").map(|()| "2 cases".into())
        }
    }
}

mod h09 {
    use crate::check::Meta;

    raylab_checks_core::declare_checks! {
        "l09", judged;
        Meta::unit("Aabb::surface_area", "a 1 × 2 × 3 box away from the origin: 22 by hand")
    .named_hidden("hidden-1-2-3-box") => hidden(),
    }

    #[cfg(feature = "l09")]
    mod code {
        pub(super) fn hidden() -> crate::check::CheckResult {
            use crate::check::close;
            use crate::lectures::l09::common::aabb_surface_area;
            use raylab::{Float, Vec3};
            // 2(1·2 + 2·3 + 3·1) = 22, wherever the box is.
            let (min, max) = (Vec3::new(4.0, -1.0, 10.0), Vec3::new(5.0, 1.0, 13.0));
            let case = "the box [4, 5] × [−1, 1] × [10, 13]";
            let got = aabb_surface_area::call(min, max);
            close(case, got, 22.0, 8.0 * Float::EPSILON * 22.0, "2(dx·dy + dy·dz + dz·dx)")
                .map(|()| "1 case".into())
        }
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn every_hidden_check_passes_on_the_reference() {
        for lecture in super::lectures() {
            if let Some(run) = lecture.run {
                crate::check::testing::every_check_passes(lecture.checks, run);
            }
        }
    }
}
