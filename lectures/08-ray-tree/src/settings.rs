//! What the tracer is allowed to spend: how deep the ray tree grows, how
//! faint a branch may get, and which of the course's options it uses.

use l06_shadows::ShadowMode;
use raylab::Float;

/// The knobs of the recursive tracer ([`crate::trace`]).
///
/// Both stopping rules of the ray tree are here: a ray of depth `max_depth`
/// spawns no children (the eye ray has depth 0, so at most `max_depth`
/// bounces), and a child whose weight (the product of the k_r or k_t maxima
/// along its branch) would fall below `min_weight` is not spawned, since it
/// could change the pixel by less than that. 6.837's ray tracer calls them
/// `-bounces` and `-weight`. `shadows = false` shades with lecture 05's
/// `shade_local` (no shadow ray at all); `shadow_mode` picks what
/// transparent blockers do and `area_samples` how many shadow rays an area
/// light gets per shaded point (lecture 06); `fresnel` lets the exact Fresnel
/// reflectance split a transparent surface's k_t between the mirror and the
/// transmitted ray. Book: §8.3 Stopping the recursion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TraceSettings {
    /// The deepest ray that may still spawn children is at depth `max_depth − 1`.
    pub max_depth: u32,
    /// Children lighter than this are not spawned (0: only the depth stops).
    pub min_weight: Float,
    /// Trace shadow rays (lecture 06) or shade every light as unblocked (lecture 05).
    pub shadows: bool,
    /// Transparent blockers block, or filter by their k_t.
    pub shadow_mode: ShadowMode,
    /// Shadow rays per area light and shaded point (≥ 1), for soft shadows.
    pub area_samples: u32,
    /// Split k_t by the Fresnel reflectance R: k_r + R·k_t to the mirror ray, (1 − R)·k_t through.
    pub fresnel: bool,
}

impl Default for TraceSettings {
    /// Depth 5, weight 0.01 (6.837's `-bounces 5 -weight 0.01`), opaque shadows, 16 samples per
    /// area light (lecture 06's default), no Fresnel.
    fn default() -> Self {
        Self {
            max_depth: 5,
            min_weight: 0.01,
            shadows: true,
            shadow_mode: ShadowMode::Opaque,
            area_samples: 16,
            fresnel: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_the_6837_flags() {
        let s = TraceSettings::default();
        assert_eq!((s.max_depth, s.min_weight, s.shadows, s.fresnel), (5, 0.01, true, false));
        assert_eq!((s.shadow_mode, s.area_samples), (ShadowMode::Opaque, 16));
        assert_eq!(s.area_samples, l06_shadows::ShadowSettings::default().area_samples);
    }
}
