//! What a ray is traced through: the scene's description and a way to
//! intersect its objects.

use std::fmt;

use raylab::scene::Material;
use raylab::{Color, Hit, Intersector, Scene};

/// How a surface is coloured at a hit: the diffuse colour k_d (also the
/// ambient kₐ) of `material` at `hit`. Lecture 10 supplies one that reads
/// the material's texture; without one, k_d is `material.diffuse`.
/// Book: §10.5 Textures in the tracer.
pub type SurfaceColor<'a> = &'a (dyn Fn(&Hit, &Material) -> Color + Sync);

/// The scene (lights, materials, background, ambient light) with the
/// [`Intersector`] that finds hits among its objects: lecture 04's
/// `BruteForce` or lecture 09's BVH, so the tracer works with either; and,
/// optionally, a [`SurfaceColor`] that varies k_d over the surfaces (lecture
/// 10's textures), which the tracer asks through [`World::diffuse`].
///
/// `objects` must answer for `scene.objects`: every hit's `material` indexes
/// `scene.materials` (the loaders guarantee it for scenes from files).
/// Book: §8.1 The ray tree.
#[derive(Clone, Copy)]
pub struct World<'a> {
    pub scene: &'a Scene,
    pub objects: &'a dyn Intersector,
    /// `None`: every surface has its material's `diffuse` colour.
    pub surface: Option<SurfaceColor<'a>>,
}

impl<'a> World<'a> {
    pub fn new(scene: &'a Scene, objects: &'a dyn Intersector) -> Self {
        Self { scene, objects, surface: None }
    }

    /// The same world with surfaces coloured by `surface`.
    pub fn with_surface(self, surface: SurfaceColor<'a>) -> Self {
        Self { surface: Some(surface), ..self }
    }

    /// The diffuse colour k_d of `material` at `hit`: the [`SurfaceColor`]'s
    /// answer if the world has one, else `material.diffuse`.
    pub fn diffuse(&self, hit: &Hit, material: &Material) -> Color {
        match self.surface {
            Some(surface) => surface(hit, material),
            None => material.diffuse,
        }
    }
}

impl fmt::Debug for World<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("World")
            .field("objects", &self.scene.objects.len())
            .field("materials", &self.scene.materials.len())
            .field("lights", &self.scene.lights.len())
            .field("surface", &self.surface.is_some())
            .finish_non_exhaustive()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{directional, matte, scene, sphere, v};
    use crate::{TraceSettings, trace, trace_recorded};
    use l04_quadrics_transforms::BruteForce;
    use raylab::{Ray, Vec3};

    #[test]
    fn a_surface_colour_replaces_the_diffuse_colour_everywhere() {
        // A white matte sphere head-on, lit along the view by a white light, ambient 0.1: the
        // hit (0, 0, −4) has N·L = 1, so the colour is k_d·(0.1 + 1) = 1.1·k_d. With a surface
        // colour that answers (0.5, 0.25, 0) for k_d: 1.1·(0.5, 0.25, 0), exactly as a material
        // of that colour gives (the same products), with or without shadow rays, recorded too.
        let s = scene(
            vec![sphere(v(0.0, 0.0, -5.0), 1.0, 0)],
            vec![matte(Color::ONE)],
            vec![directional(Vec3::Z, Color::ONE)],
            Color::ZERO,
            Color::splat(0.1),
        );
        let kd = v(0.5, 0.25, 0.0);
        let mut tinted = s.clone();
        tinted.materials[0].diffuse = kd;
        let objects = BruteForce::new(&s.objects);
        let surface = |_: &Hit, _: &Material| kd;
        let world = World::new(&s, &objects).with_surface(&surface);
        let plain = World::new(&tinted, &objects);
        let ray = Ray::new(Vec3::ZERO, -Vec3::Z);
        for shadows in [true, false] {
            let settings = TraceSettings { shadows, ..TraceSettings::default() };
            let expected = trace(&plain, &ray, 0, 1.0, &settings);
            assert_eq!(trace(&world, &ray, 0, 1.0, &settings), expected);
            assert_eq!(trace_recorded(&world, &ray, &settings).0, expected);
            assert_eq!(expected, Color::splat(1.1) * kd);
        }
        // Without a surface colour, the material's own.
        assert_eq!(
            World::new(&s, &objects)
                .diffuse(&objects.closest_hit(&ray, raylab::Interval::POSITIVE).unwrap(), &s.materials[0]),
            Color::ONE
        );
    }
}
