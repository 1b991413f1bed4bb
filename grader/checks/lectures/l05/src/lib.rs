//! Lecture 05, shading: Lambert, Phong and Blinn–Phong, the reflection vector,
//! light sources with attenuation and spot cones, area-light samples, and the
//! local shading equation that puts them together.

// Built without its lecture (which does not compile), the crate is its checks' declarations alone.
#![cfg_attr(not(feature = "l05"), allow(unused))]

// The core's modules at the crate's root, where the checks name them (`crate::check::close`).
#[allow(unused_imports)]
use raylab_checks_core::{check, declare_checks, judge, path, remote, rows, stages, trees};

use crate::check::Meta;

declare_checks! {
    "l05", judged;
    Meta::unit(
        "concentric_disk",
        "square rings go to circles of the same half side, the centre and the sides by hand, both branches",
    ) => disk_cases(concentric_disk),
    Meta::unit(
        "sample_light",
        "rect samples at corner + u·edges, ball samples on the silhouette disc, point lights",
    )
    .needs(&["05/illuminate", "05/concentric_disk"]) => sample_light_cases(sample_light),
    Meta::unit("lambert", "(N·L)⁺ head-on, at 60°, grazing and from behind") => lambert_cases(lambert),
    Meta::unit("distance_falloff", "1/(c + l·d + q·d²) at d = 2 by hand; 0, never ∞, at and near d = 0")
        => falloff_cases(distance_falloff),
    Meta::unit(
        "spot_falloff",
        "1 inside, 0 outside, smoothstep of the cosines between, a hard edge when inner = outer",
    ) => spot_cases(spot_falloff),
    Meta::unit(
        "illuminate",
        "directional, point, spot and area lights: L toward the light, d, attenuated intensity",
    )
    .needs(&["05/distance_falloff", "05/spot_falloff"]) => illuminate_cases(illuminate),
    Meta::unit(
        "phong_specular",
        "(R·V)ⁿ: the peak in the mirror direction, (√½)ⁿ seen along N, nothing from behind",
    )
    .needs(&["05/reflect"]) => phong_cases(phong_specular),
    Meta::unit(
        "blinn_specular",
        "(N·H)ⁿ: the peak at H = N, cos(22.5°)ⁿ seen along N, l = −v gives 0, not NaN",
    ) => blinn_cases(blinn_specular),
    Meta::unit("reflect", "r = v − 2(v·n)n at 45°, normal incidence, along the surface, non-unit v")
        => reflect_cases(reflect),
    Meta::unit(
        "shade_light",
        "(k_d(N·L)⁺ + k_s·spec) ⊙ I_L: colours by channel, Phong or Blinn as the material says",
    )
    .needs(&["05/lambert", "05/phong_specular", "05/blinn_specular"]) => shade_light_cases(shade_light),
    Meta::unit(
        "shade_local",
        "ambient plus every light: one light at 60°, two lights, none, from behind, a point light",
    )
    .needs(&["05/illuminate", "05/shade_light", "05/lambert"]) => shade_local_cases(shade_local),
}

#[cfg(feature = "l05")]
mod area_lights;
#[cfg(feature = "l05")]
pub mod common;
#[cfg(feature = "l05")]
mod lambert;
#[cfg(feature = "l05")]
mod lights;
#[cfg(feature = "l05")]
mod phong;
#[cfg(feature = "l05")]
mod reflect;
#[cfg(feature = "l05")]
mod shade;

#[cfg(feature = "l05")]
pub mod stage;

/// What the rows above run: the checks of each of the lecture's files.
#[cfg(feature = "l05")]
mod code {
    pub(super) use super::{
        area_lights::*, common::*, lambert::*, lights::*, phong::*, reflect::*, shade::*,
    };
}

#[cfg(all(test, feature = "l05"))]
mod tests {
    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }
}
