//! What a ray is traced through: the scene's description and a way to
//! intersect its objects.

use std::borrow::Cow;
use std::fmt;

use raylab::scene::Material;
use raylab::{Hit, Intersector, Scene};

/// How a surface looks at a hit: the material there, given the scene's
/// material the hit names (`material`). Lecture 10 supplies one that reads
/// the material's texture (a diffuse colour that varies over the surface, or
/// two materials blended by a solid pattern); without one, the scene's
/// material holds everywhere. Borrowed where nothing varies, so an
/// untextured hit costs no copy. Book: §10.5 Textures in the tracer.
pub type SurfaceMaterial<'a> = &'a (dyn for<'m> Fn(&Hit, &'m Material) -> Cow<'m, Material> + Sync);

/// The scene (lights, materials, background, ambient light) with the
/// [`Intersector`] that finds hits among its objects: lecture 04's
/// `BruteForce` or lecture 09's BVH, so the tracer works with either; and,
/// optionally, a [`SurfaceMaterial`] that varies the materials over the
/// surfaces (lecture 10's textures), which the tracer asks through
/// [`World::material_at`].
///
/// `objects` must answer for `scene.objects`: every hit's `material` indexes
/// `scene.materials` (the loaders guarantee it for scenes from files).
/// Book: §8.1 The ray tree.
#[derive(Clone, Copy)]
pub struct World<'a> {
    pub scene: &'a Scene,
    pub objects: &'a dyn Intersector,
    /// `None`: every surface is its scene material everywhere.
    pub surface: Option<SurfaceMaterial<'a>>,
}

impl<'a> World<'a> {
    pub fn new(scene: &'a Scene, objects: &'a dyn Intersector) -> Self {
        Self { scene, objects, surface: None }
    }

    /// The same world with its surfaces' materials given by `surface`.
    pub fn with_surface(self, surface: SurfaceMaterial<'a>) -> Self {
        Self { surface: Some(surface), ..self }
    }

    /// The material of a surface at `hit`, `material` the scene's material
    /// the hit names: the [`SurfaceMaterial`]'s answer if the world has one,
    /// else `material` itself.
    pub fn material_at<'m>(&self, hit: &Hit, material: &'m Material) -> Cow<'m, Material> {
        match self.surface {
            Some(surface) => surface(hit, material),
            None => Cow::Borrowed(material),
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
    use raylab::{Color, Ray, Vec3};

    #[test]
    fn a_surface_material_replaces_the_scene_material_everywhere() {
        // A white matte sphere head-on, lit along the view by a white light, ambient 0.1: the
        // hit (0, 0, −4) has N·L = 1, so the colour is k_d·(0.1 + 1) = 1.1·k_d. With a surface
        // material of k_d = (0.5, 0.25, 0): 1.1·(0.5, 0.25, 0), exactly as a scene material of
        // that colour gives (the same products), with or without shadow rays, recorded too.
        // Its k_r counts too: a mirror of k_r = ½ facing the empty background (0.2) adds ½·0.2.
        let s = scene(
            vec![sphere(v(0.0, 0.0, -5.0), 1.0, 0)],
            vec![matte(Color::ONE)],
            vec![directional(Vec3::Z, Color::ONE)],
            Color::splat(0.2),
            Color::splat(0.1),
        );
        let kd = v(0.5, 0.25, 0.0);
        let there = Material { diffuse: kd, reflective: Color::splat(0.5), ..s.materials[0].clone() };
        let mut tinted = s.clone();
        tinted.materials[0] = there.clone();
        let objects = BruteForce::new(&s.objects);
        let surface: SurfaceMaterial = &|_, _| Cow::Owned(there.clone());
        let world = World::new(&s, &objects).with_surface(surface);
        let plain = World::new(&tinted, &objects);
        let ray = Ray::new(Vec3::ZERO, -Vec3::Z);
        for shadows in [true, false] {
            let settings = TraceSettings { shadows, ..TraceSettings::default() };
            let expected = trace(&plain, &ray, 0, 1.0, &settings);
            assert_eq!(trace(&world, &ray, 0, 1.0, &settings), expected);
            assert_eq!(trace_recorded(&world, &ray, &settings).0, expected);
            assert_eq!(expected, Color::splat(1.1) * kd + Color::splat(0.5 * 0.2));
        }
        // Without a surface material, the scene's own, borrowed.
        let hit = objects.closest_hit(&ray, raylab::Interval::POSITIVE).unwrap();
        let own = World::new(&s, &objects).material_at(&hit, &s.materials[0]);
        assert!(matches!(own, Cow::Borrowed(m) if std::ptr::eq(m, &s.materials[0])));
    }
}
