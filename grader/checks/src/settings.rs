//! What a scene's `[render]` table asks of the shading and the tracer, with the lectures'
//! defaults for what it does not say (6.837 files say nothing): the stages that shade and the
//! complete tracer both draw with these.

use raylab::Scene;

/// The shadow settings `scene` asks for: its `[render]` table's
/// `transparent_shadows` and `area_samples`, lecture 06's defaults for what it
/// does not say. Stage 06 shades with them; the tracer's settings take them.
#[cfg(feature = "l06")]
pub fn shadow_settings(scene: &Scene) -> l06_shadows::ShadowSettings {
    use l06_shadows::{ShadowMode, ShadowSettings};
    let defaults = ShadowSettings::default();
    ShadowSettings {
        mode: match scene.render.transparent_shadows {
            Some(true) => ShadowMode::Transmissive,
            Some(false) => ShadowMode::Opaque,
            None => defaults.mode,
        },
        area_samples: scene.render.area_samples.unwrap_or(defaults.area_samples),
    }
}

/// The tracer's settings for `scene`: what its `[render]` table says, and
/// [`l08_ray_tree::TraceSettings::default`] for what it does not (6.837 files
/// say nothing); the shadow settings are [`shadow_settings`]'s.
#[cfg(feature = "l08")]
pub fn scene_settings(scene: &Scene) -> l08_ray_tree::TraceSettings {
    let (own, default) = (scene.render, l08_ray_tree::TraceSettings::default());
    let shadows = shadow_settings(scene);
    l08_ray_tree::TraceSettings {
        max_depth: own.max_depth.unwrap_or(default.max_depth),
        min_weight: own.min_weight.unwrap_or(default.min_weight),
        shadow_mode: shadows.mode,
        area_samples: shadows.area_samples,
        ..default
    }
}
