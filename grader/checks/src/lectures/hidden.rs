// INSTRUCTOR ONLY: left out of the handout; `grader grade --submission` turns these checks on.
//! Hidden checks: the same exercises at inputs the students have not seen,
//! so that a solution fitted to the visible checks' numbers does not pass.
//! Gradescope shows them after the grades are published.

use super::Lecture;
use crate::check::Meta;

const L02: &[Meta] = &[Meta::unit(
    "hit_sphere_stable",
    "an off-axis ray at an off-centre sphere of radius 0.5, both roots ahead",
)
.named_hidden("hidden-off-axis")];

const L07: &[Meta] =
    &[Meta::unit("refract", "refraction into glass at 30° and back out, against Snell's law by hand")
        .named_hidden("hidden-snell-both-ways")];

pub fn lectures() -> Vec<Lecture> {
    vec![
        Lecture { number: "02", checks: L02, run: run_if!("l02", run02), hidden: true },
        Lecture { number: "07", checks: L07, run: run_if!("l07", run07), hidden: true },
    ]
}

/// A hidden lecture's runner when its feature is on.
macro_rules! run_if {
    ($feature:literal, $run:ident) => {{
        #[cfg(feature = $feature)]
        let run: Option<fn(&str) -> Option<crate::check::CheckResult>> = Some($run);
        #[cfg(not(feature = $feature))]
        let run: Option<fn(&str) -> Option<crate::check::CheckResult>> = None;
        run
    }};
}
use run_if;

#[cfg(feature = "l02")]
fn run02(name: &str) -> Option<crate::check::CheckResult> {
    use crate::check::{close, fail};
    use l02_ray_casting::hit_sphere_stable;
    use raylab::{Float, Interval, Ray, Vec3};
    if name != "hit_sphere_stable/hidden-off-axis" {
        return None;
    }
    // Sphere r = 0.5 at (1, 2, −3); the ray from (1, 2.3, 2) along −z passes 0.3 from the
    // centre: half chord √(0.25 − 0.09) = 0.4, so t = 5 − 0.4 = 4.6 (and 5.4).
    let case = "sphere r = 0.5 at (1, 2, −3), ray from (1, 2.3, 2) along (0, 0, −1)";
    let ray = Ray::new(Vec3::new(1.0, 2.3, 2.0), Vec3::new(0.0, 0.0, -1.0));
    let got = hit_sphere_stable(&ray, Vec3::new(1.0, 2.0, -3.0), 0.5, Interval::new(0.0, Float::INFINITY));
    let Some(hit) = got else {
        return Some(Err(fail(
            case,
            "t = 4.6",
            "None",
            "the ray passes 0.3 from the centre, inside r = 0.5",
        )));
    };
    // 4.6 is not exact in binary: a few ulp of 5.
    let tolerance = 64.0 * Float::EPSILON * 5.0;
    Some(close(case, hit.t, 4.6, tolerance, "the nearer root of the quadratic").map(|()| "1 case".into()))
}

#[cfg(feature = "l07")]
fn run07(name: &str) -> Option<crate::check::CheckResult> {
    use crate::check::{close3, fail};
    use l07_reflection_refraction::refract;
    use raylab::{Float, Vec3};
    if name != "refract/hidden-snell-both-ways" {
        return None;
    }
    // i at 30° to the normal n = +y, going down: i = (sin 30°, −cos 30°, 0). Into glass
    // (η = 1/1.5): sin θt = sin 30° / 1.5 = 1/3, cos θt = √(8/9), t = (1/3, −√(8/9), 0).
    let (s, c) = (0.5 as Float, (0.75 as Float).sqrt());
    let i = Vec3::new(s, -c, 0.0);
    let expected = Vec3::new(1.0 / 3.0, -(8.0 as Float / 9.0).sqrt(), 0.0);
    let case = "i at 30° from the normal (0, 1, 0), air to glass (η = 1/1.5)";
    let Some(t) = refract(i, Vec3::Y, 1.0 / 1.5) else {
        return Some(Err(fail(
            case,
            "a refracted ray",
            "None",
            "no total internal reflection going into glass",
        )));
    };
    let tolerance = 16.0 * Float::EPSILON;
    if let Err(e) = close3(case, t, expected, tolerance, "t = η i + (η cos θi − cos θt) n") {
        return Some(Err(e));
    }
    // And back out along the reversed ray: the original direction, reversed (reciprocity).
    let case = "the refracted ray reversed, glass to air (η = 1.5), normal (0, −1, 0) facing it";
    let Some(back) = refract(-t, -Vec3::Y, 1.5) else {
        return Some(Err(fail(
            case,
            "a refracted ray",
            "None",
            "below the critical angle there is a refracted ray",
        )));
    };
    Some(close3(case, back, -i, tolerance, "Snell's law is reversible").map(|()| "2 cases".into()))
}
