//! Lecture 07, reflection and refraction: the mirror ray, Snell's law and total
//! internal reflection, the two media at a hit, exact Fresnel and Schlick.

// Built without its lecture (which does not compile), the crate is its checks' declarations alone.
#![cfg_attr(not(feature = "l07"), allow(unused))]

// The core's modules at the crate's root, where the checks name them (`crate::check::close`).
#[allow(unused_imports)]
use raylab_checks_core::{check, declare_checks, judge, path, remote, rows, stages, trees};

use crate::check::Meta;

declare_checks! {
    "l07", judged;
    Meta::unit(
        "schlick",
        "R₀ at normal incidence, (1 − cos θ)⁵ from air, cos θ_t from inside glass, R = 1 under TIR",
    ) => schlick_cases(schlick),
    Meta::unit(
        "fresnel_dielectric",
        "0.04 at normal incidence, the closed form at 45°, Brewster's angle, TIR, and the f64 sine/tangent form",
    ) => fresnel_cases(fresnel_dielectric),
    Meta::unit("mirror_direction", "mirror rays by hand: 3-4-5, 45°, normal incidence, non-unit directions")
        .needs(&["05/reflect"]) => mirror_cases(mirror_direction),
    Meta::unit(
        "interface",
        "entering and leaving a sphere: the normal facing the ray and which index is which",
    ) => interface_cases(interface),
    Meta::unit("refract", "Snell by hand at 30°, normal incidence, η = 1, TIR, and a sweep against f64")
        => refract_cases(refract),
    Meta::extreme(
        "refract",
        "critical-angle",
        "θ_c ± 0.001° and normal incidence: finite, None exactly when sin²θ_t ≥ 1, even when it rounds to 1",
    ) => critical_angle(refract),
    Meta::extreme(
        "refract",
        "tiny-glass-sphere",
        "a glass bead of radius 10⁻⁵: each refracted ray finds the far side and leaves where f64 says",
    )
    .needs(&["02/hit_sphere_stable", "07/interface"]) => tiny_glass_sphere(refract, interface),
}

#[cfg(feature = "l07")]
pub mod common;
#[cfg(feature = "l07")]
mod fresnel;
#[cfg(feature = "l07")]
mod mirror;
#[cfg(feature = "l07")]
mod refract;

#[cfg(feature = "l07")]
pub mod stage;

/// What the rows above run: the checks of each of the lecture's files.
#[cfg(feature = "l07")]
mod code {
    pub(super) use super::{common::*, fresnel::*, mirror::*, refract::*};
}

#[cfg(all(test, feature = "l07"))]
mod tests {
    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }
}
