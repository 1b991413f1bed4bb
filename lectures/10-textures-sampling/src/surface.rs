//! Textures in the tracer: the texture coordinates of any hit, the material
//! a texture makes there, and a whole textured, supersampled render of a scene.

use std::borrow::Cow;

use l01_transforms::{Camera, transform_point};
use l08_ray_tree::{SurfaceMaterial, TraceSettings, World};
use l09_acceleration::intersector_for;
use raylab::math::consts::TAU;
use raylab::scene::{Material, Shape, SolidPattern, Texture};
use raylab::stats::RayStats;
use raylab::{Color, Float, Hit, Image, Scene, Vec2, Vec3};

use crate::bilinear::bilinear;
use crate::checker::{checker, checker_3d};
use crate::filter::Filter;
use crate::noise::{fractal_noise, marble, wood};
use crate::patterns::Pattern;
use crate::supersample::render_supersampled;
use crate::uv::{plane_uv, sphere_uv};

/// The texture axes of a plane with unit normal n: u along normalize(ŷ × n)
/// (x̂ when n is vertical), v = n × u. So a floor (n = +y) has u = +x and
/// v = −z (away from a camera on +z), a wall facing +z has u = +x, v = +y:
/// upright textures as seen by the usual camera.
pub fn plane_axes(normal: Vec3) -> (Vec3, Vec3) {
    let u = Vec3::Y.cross(normal).try_normalize().unwrap_or(Vec3::X);
    (u, normal.cross(u))
}

/// The texture coordinates of `hit` on its object of `scene` (`hit.object`),
/// from the hit point in the object's own space p (through its transform):
/// - sphere: [`sphere_uv`] of (p − centre)/radius;
/// - plane n·p = offset: [`plane_uv`] from the point offset·n along
///   [`plane_axes`], one unit per cell;
/// - box: the two coordinates across the face hit (the one p is nearest),
///   each over the box's extent, in [0, 1];
/// - cylinder and cone: u = ½ + atan2(y, x)/2π around the axis, v = z;
/// - triangle: its barycentrics (β, γ), which the hit carries (lecture 03);
///   mesh: the hit's uv, interpolated from the OBJ's texture coordinates
///   (lecture 03); polygon: the hit's uv as its test left it.
///
/// A hit whose object index is not in the scene keeps its uv. Glue: the
/// mappings are the exercises. Book: §10.5 Textures in the tracer.
pub fn surface_uv(scene: &Scene, hit: &Hit) -> Vec2 {
    let Some(object) = scene.objects.get(hit.object) else {
        return hit.uv;
    };
    let p = match &object.transform {
        Some(t) => transform_point(&t.object_from_world, hit.point),
        None => hit.point,
    };
    match &object.shape {
        Shape::Sphere { center, radius } => sphere_uv((p - *center) / *radius),
        Shape::Plane { normal, offset } => {
            let (u_axis, v_axis) = plane_axes(*normal);
            plane_uv(p, *offset * *normal, u_axis, v_axis)
        }
        Shape::Box { min, max } => box_uv(p, *min, *max),
        Shape::Cylinder | Shape::Cone => Vec2::new(0.5 + p.y.atan2(p.x) / TAU, p.z),
        Shape::Triangle { .. } | Shape::Mesh(_) | Shape::Polygon { .. } => hit.uv,
    }
}

/// The coordinates across the face of the box [min, max] nearest to p, each
/// over the box's extent (0 across a flat side).
fn box_uv(p: Vec3, min: Vec3, max: Vec3) -> Vec2 {
    let distance = (p - min).abs().min((max - p).abs());
    let axis = if distance.x <= distance.y && distance.x <= distance.z {
        0
    } else if distance.y <= distance.z {
        1
    } else {
        2
    };
    let along = |k: usize| {
        let extent = max[k] - min[k];
        if extent > 0.0 { (p[k] - min[k]) / extent } else { 0.0 }
    };
    match axis {
        0 => Vec2::new(along(2), along(1)),
        1 => Vec2::new(along(0), along(2)),
        _ => Vec2::new(along(0), along(1)),
    }
}

/// The material of a surface at `hit`, `material` the scene's material the
/// hit names: `material` itself without a texture (borrowed); with one, an
/// untextured copy whose properties are the texture's there:
/// - `Checker { scale, other }`: k_d is [`checker`] at [`surface_uv`],
///   `diffuse` and `other`;
/// - `Image`: k_d is [`bilinear`] at [`surface_uv`];
/// - `Solid { pattern_from_world, pattern, a, b }`: the blend value s of
///   [`solid_value`] at the hit point in pattern space, and every colour
///   (1 − s)·a's + s·b's, a and b each the material at `hit` first (either
///   may be textured); exponent, model and η are a's. Where s is exactly 0
///   or 1 (every hit of a checker), the one material alone: a or b as this
///   function makes it, borrowed when untextured.
///
/// What lecture 08's tracer asks through `World::with_surface`. A copy has
/// no name (no allocation per hit). Glue. Book: §10.5 Textures in the tracer.
pub fn surface_material<'m>(scene: &Scene, hit: &Hit, material: &'m Material) -> Cow<'m, Material> {
    let diffuse = match &material.texture {
        None => return Cow::Borrowed(material),
        Some(Texture::Checker { scale, other }) => {
            checker(surface_uv(scene, hit), *scale, material.diffuse, *other)
        }
        Some(Texture::Image { image, .. }) => bilinear(image, surface_uv(scene, hit)),
        Some(Texture::Solid { pattern_from_world, pattern, a, b }) => {
            let s = solid_value(pattern, transform_point(pattern_from_world, hit.point));
            // All of one material (a checker's every hit): that one alone, borrowed if untextured.
            if s == 0.0 {
                return surface_material(scene, hit, a);
            } else if s == 1.0 {
                return surface_material(scene, hit, b);
            }
            let (a, b) = (surface_material(scene, hit, a), surface_material(scene, hit, b));
            let mix = |x: Color, y: Color| (1.0 - s) * x + s * y;
            return Cow::Owned(Material {
                diffuse: mix(a.diffuse, b.diffuse),
                specular: mix(a.specular, b.specular),
                reflective: mix(a.reflective, b.reflective),
                transparent: mix(a.transparent, b.transparent),
                ..untextured(&a)
            });
        }
    };
    Cow::Owned(Material { diffuse, ..untextured(material) })
}

/// `material`'s properties without its name and texture.
fn untextured(material: &Material) -> Material {
    Material {
        name: String::new(),
        diffuse: material.diffuse,
        specular: material.specular,
        exponent: material.exponent,
        model: material.model,
        reflective: material.reflective,
        transparent: material.transparent,
        ior: material.ior,
        texture: None,
    }
}

/// The blend value s ∈ [0, 1] of a solid `pattern` at p′ (pattern space):
/// - `Checker`: 0 in the unit cube (0, 0, 0) and every other one, 1 in the
///   rest ([`checker_3d`], scale 1);
/// - `Noise { octaves }`: clamp((N + 1)/2, 0, 1), N the [`fractal_noise`];
/// - `Marble { … }`: [`marble`]; `Wood { … }`: [`wood`].
///
/// 6.837's `Noise` maps its noise to a blend as well; the exact map of its
/// handout is not known here, so raylab takes N's usual range [−1, 1] to
/// [0, 1] and clamps the rare values beyond it. Where the pattern has no
/// value, past Float's range (a pattern space scaled by 10³⁸: the phase of
/// a sine or the point itself infinite), the blend is ½, the mean of both
/// materials, never NaN. Glue. Book: §10.3 Solid textures.
pub fn solid_value(pattern: &SolidPattern, p: Vec3) -> Float {
    let s = match *pattern {
        SolidPattern::Checker => checker_3d(p, 1.0, Color::ZERO, Color::ONE).x,
        SolidPattern::Noise { octaves } => ((fractal_noise(p, octaves) + 1.0) / 2.0).clamp(0.0, 1.0),
        SolidPattern::Marble { octaves, frequency, amplitude } => marble(p, octaves, frequency, amplitude),
        SolidPattern::Wood { octaves, frequency, amplitude } => wood(p, octaves, frequency, amplitude),
    };
    if s.is_finite() { s } else { 0.5 }
}

/// `scene` rendered at its own size through its own camera, textured
/// ([`surface_material`]) and supersampled ([`render_supersampled`]), its
/// objects behind the intersector the scene requires (lecture 09's
/// `intersector_for`: a BVH only for many primitives). An error (never a
/// panic) when the camera cannot be built. Book: §10.8 Supersampling.
pub fn render_textured(
    scene: &Scene,
    settings: &TraceSettings,
    spp: u32,
    pattern: Pattern,
    filter: Filter,
    seed: u64,
) -> Result<(Image, RayStats), String> {
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).map_err(|e| e.to_string())?;
    let objects = intersector_for(&scene.objects);
    let surface: SurfaceMaterial = &|hit, material| surface_material(scene, hit, material);
    let world = World::new(scene, objects.as_ref()).with_surface(surface);
    Ok(render_supersampled(&world, &camera, scene.width, scene.height, settings, spp, pattern, filter, seed))
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_abs_diff_eq;
    use l04_quadrics_transforms::BruteForce;
    use raylab::scene::{self, Object, Transform};
    use raylab::{Float, Intersector, Interval, Mat4, Ray, WHITE};

    const EPS: Float = Float::EPSILON;
    const RED: Color = Color::new(1.0, 0.0, 0.0);

    fn object(shape: Shape, transform: Option<Transform>) -> Object {
        Object { shape, material: 0, transform }
    }

    /// A scene of these objects and one material, white ambient light and no lights, so a
    /// pixel's colour is the surface's k_d; the camera looks straight down from y = 5 with
    /// `up` = −z and sees the square x, z ∈ [−1, 1] (orthographic, 2 high) in a 4 × 4 image.
    fn scene_of(objects: Vec<Object>, material: Material) -> Scene {
        Scene {
            camera: scene::Camera::Orthographic {
                eye: Vec3::new(0.0, 5.0, 0.0),
                at: Vec3::ZERO,
                up: -Vec3::Z,
                height: 2.0,
            },
            width: 4,
            height: 4,
            background: Color::ZERO,
            ambient: WHITE,
            lights: vec![],
            materials: vec![material],
            objects,
            render: Default::default(),
        }
    }

    fn hit_of(s: &Scene, ray: Ray) -> Hit {
        BruteForce::new(&s.objects).closest_hit(&ray, Interval::POSITIVE).expect("a hit")
    }

    #[test]
    fn plane_axes_are_upright_for_floors_and_walls() {
        // ŷ × ŷ = 0: the floor falls back to u = x̂, and v = ŷ × x̂ = −ẑ; a wall facing +z:
        // u = ŷ × ẑ = x̂, v = ẑ × x̂ = ŷ. Exact (unit axes, products of 0 and ±1).
        assert_eq!(plane_axes(Vec3::Y), (Vec3::X, -Vec3::Z));
        assert_eq!(plane_axes(Vec3::Z), (Vec3::X, Vec3::Y));
        assert_eq!(plane_axes(-Vec3::Y), (Vec3::X, Vec3::Z));
    }

    #[test]
    fn hits_get_the_uv_of_their_shape() {
        // A sphere of radius 2 at (2, 0, 0), placed by a translation by (0, 3, 0): the ray down
        // −z at (2, 3, ·) hits it at world (2, 3, 2), object (2, 0, 2), on the unit sphere
        // (0, 0, 1): u = ¼, v = ½ (uv.rs). Tolerance 8ε: the transform and the hit round.
        let moved = Transform::new(Mat4::from_translation(Vec3::new(0.0, 3.0, 0.0)));
        let s = scene_of(
            vec![object(Shape::Sphere { center: Vec3::new(2.0, 0.0, 0.0), radius: 2.0 }, moved)],
            Material::default(),
        );
        let hit = hit_of(&s, Ray::new(Vec3::new(2.0, 3.0, 10.0), -Vec3::Z));
        assert_abs_diff_eq!(surface_uv(&s, &hit), Vec2::new(0.25, 0.5), epsilon = 8.0 * EPS);
        // The floor y = −1 (offset −1 along +y): origin (0, −1, 0), u = x, v = −z: the point
        // (0.25, −1, −0.75) has uv (0.25, 0.75), exactly (a vertical ray, exact t).
        let floor =
            scene_of(vec![object(Shape::Plane { normal: Vec3::Y, offset: -1.0 }, None)], Material::default());
        let hit = hit_of(&floor, Ray::new(Vec3::new(0.25, 4.0, -0.75), -Vec3::Y));
        assert_eq!(surface_uv(&floor, &hit), Vec2::new(0.25, 0.75));
        // A box [0, 2] × [0, 1] × [0, 4] hit on its top (y = 1) at x = 0.5, z = 3: (x/2, z/4).
        let cuboid = Shape::Box { min: Vec3::ZERO, max: Vec3::new(2.0, 1.0, 4.0) };
        let boxed = scene_of(vec![object(cuboid, None)], Material::default());
        let hit = hit_of(&boxed, Ray::new(Vec3::new(0.5, 5.0, 3.0), -Vec3::Y));
        assert_eq!(surface_uv(&boxed, &hit), Vec2::new(0.25, 0.75));
    }

    #[test]
    fn each_texture_colours_its_surface() {
        let floor = vec![object(Shape::Plane { normal: Vec3::Y, offset: 0.0 }, None)];
        let material = |texture| Material { diffuse: WHITE, texture: Some(texture), ..Material::default() };
        let down = |x: Float, z: Float| Ray::new(Vec3::new(x, 5.0, z), -Vec3::Y);
        // A uv checker of 2 cells per unit: (0.1, 0, −0.1) is uv (0.1, 0.1), cell (0, 0): white;
        // (0.6, 0, −0.1) is cell (1, 0): red.
        let s = scene_of(floor.clone(), material(Texture::Checker { scale: 2.0, other: RED }));
        let color = |s: &Scene, x, z| surface_material(s, &hit_of(s, down(x, z)), &s.materials[0]).diffuse;
        assert_eq!((color(&s, 0.1, -0.1), color(&s, 0.6, -0.1)), (WHITE, RED));
        // A solid checker of cubes ½ wide (pattern = 2·world), the floor y = 0 lifted to 0.25
        // inside a layer: (0.1, 0.25, 0.1) → (0.2, 0.5, 0.2), cube (0, 0, 0): white;
        // (−0.1, 0.25, 0.1) → cube (−1, 0, 0): red.
        let lifted = vec![object(Shape::Plane { normal: Vec3::Y, offset: 0.25 }, None)];
        let pattern_from_world = Mat4::from_scale(Vec3::splat(2.0));
        let (a, b) =
            (Box::new(material(Texture::Checker { scale: 1.0, other: WHITE })), Box::new(matte(RED)));
        let solid = Texture::Solid { pattern_from_world, pattern: SolidPattern::Checker, a, b };
        let s = scene_of(lifted, material(solid));
        assert_eq!((color(&s, 0.1, 0.1), color(&s, -0.1, 0.1)), (WHITE, RED));
        // An image, 2 × 1: left half black, right half red; uv (0.75, ·) is the centre of the
        // right pixel (x = 0.75·2 − ½ = 1): red exactly; the floor point (0.75, 0, −0.5).
        let image = Image::from_pixels(2, 1, vec![Color::ZERO, RED]);
        let texture = Texture::Image { file: "two.png".into(), image: std::sync::Arc::new(image) };
        let s = scene_of(floor, material(texture));
        assert_eq!(color(&s, 0.75, -0.5), RED);
        // No texture: the material itself, borrowed.
        let plain = Material::default();
        let there = surface_material(&s, &hit_of(&s, down(0.0, 0.0)), &plain);
        assert!(matches!(there, Cow::Borrowed(m) if std::ptr::eq(m, &plain)));
    }

    fn matte(diffuse: Color) -> Material {
        Material { diffuse, ..Material::default() }
    }

    #[test]
    fn a_solid_texture_blends_every_colour_of_its_two_materials() {
        // Marble with no octaves on the floor y = 0: s = (1 + sin(f·x))/2, f = π. At x = ½,
        // s = 1 (b); at x = −½, s = 0 (a); at x = 0, s = ½: every colour halfway, exponent a's.
        use raylab::math::consts::PI;
        let a =
            Material { diffuse: RED, reflective: Color::splat(0.1), exponent: 8.0, ..Material::default() };
        let b = Material {
            diffuse: Color::new(0.0, 0.0, 1.0),
            reflective: Color::splat(0.3),
            exponent: 8.0,
            ..a.clone()
        };
        let pattern = SolidPattern::Marble { octaves: 0, frequency: PI, amplitude: 3.0 };
        let texture = Texture::Solid {
            pattern_from_world: Mat4::IDENTITY,
            pattern,
            a: Box::new(a.clone()),
            b: Box::new(b.clone()),
        };
        let floor = vec![object(Shape::Plane { normal: Vec3::Y, offset: 0.0 }, None)];
        let s = scene_of(floor, Material { texture: Some(texture), ..a.clone() });
        let at = |x: Float| {
            surface_material(&s, &hit_of(&s, Ray::new(Vec3::new(x, 5.0, 0.0), -Vec3::Y)), &s.materials[0])
                .into_owned()
        };
        let (left, right, middle) = (at(-0.5), at(0.5), at(0.0));
        assert_abs_diff_eq!(left.diffuse, RED, epsilon = 4.0 * EPS);
        assert_abs_diff_eq!(right.diffuse, b.diffuse, epsilon = 4.0 * EPS);
        assert_abs_diff_eq!(middle.diffuse, Color::new(0.5, 0.0, 0.5), epsilon = 4.0 * EPS);
        assert_abs_diff_eq!(middle.reflective, Color::splat(0.2), epsilon = 4.0 * EPS);
        assert_eq!((middle.exponent, middle.texture, middle.name), (8.0, None, String::new()));
    }

    #[test]
    fn solid_values_stay_in_zero_one() {
        let patterns = [
            SolidPattern::Checker,
            SolidPattern::Noise { octaves: 8 },
            SolidPattern::Marble { octaves: 5, frequency: 3.0, amplitude: 4.0 },
            SolidPattern::Wood { octaves: 3, frequency: 6.0, amplitude: 2.0 },
        ];
        let mut rng = raylab::random::Rng::new(4);
        for _ in 0..2000 {
            let p = rng.in_cube(10.0);
            for pattern in &patterns {
                let s = solid_value(pattern, p);
                assert!((0.0..=1.0).contains(&s), "{pattern:?} at {p}: {s}");
            }
        }
        assert_eq!(solid_value(&SolidPattern::Checker, Vec3::new(-0.5, 0.5, 0.5)), 1.0);
        // Past Float's range (found by scaling a scene's frequency to 3·10³⁸): ½, not NaN.
        let huge = SolidPattern::Marble { octaves: 2, frequency: Float::MAX, amplitude: 2.0 };
        assert_eq!(solid_value(&huge, Vec3::new(3.0, 0.5, 0.5)), 0.5);
        assert_eq!(solid_value(&SolidPattern::Noise { octaves: 3 }, Vec3::splat(Float::INFINITY)), 0.5);
        assert_eq!(solid_value(&SolidPattern::Noise { octaves: 4 }, Vec3::new(3.0, -2.0, 7.0)), 0.5);
    }

    #[test]
    fn a_textured_render_shows_the_checkerboard() {
        // Looking down at the floor y = 0 through a 4 × 4 image of x, z ∈ [−1, 1] (camera x = +x,
        // camera up = −z): pixel centres at x = −0.75, −0.25, 0.25, 0.75 left to right and
        // z = −0.75, −0.25, 0.25, 0.75 top to bottom. uv = (x, −z), one cell per unit: the top
        // left quadrant is cell (−1, 0), odd: red; top right (0, 0): white; bottom left
        // (−1, −1): white; bottom right (0, −1): red. No lights and white ambient light: each
        // pixel is k_d, exactly (one regular sample, weight 1).
        let floor = vec![object(Shape::Plane { normal: Vec3::Y, offset: 0.0 }, None)];
        let checker = Texture::Checker { scale: 1.0, other: RED };
        let s = scene_of(floor, Material { diffuse: WHITE, texture: Some(checker), ..Material::default() });
        let settings = TraceSettings::default();
        let (image, stats) = render_textured(&s, &settings, 1, Pattern::Regular, Filter::Box, 0).unwrap();
        for y in 0..4 {
            for x in 0..4 {
                let expected = if (x < 2) == (y < 2) { RED } else { WHITE };
                assert_eq!(image.get(x, y), expected, "pixel ({x}, {y})");
            }
        }
        assert_eq!(stats.get(raylab::stats::Counter::PrimaryRays), 16);
    }

    #[test]
    fn the_lecture_scenes_load_and_render_textured() {
        // The textured scenes of scenes/, at 1/10 of their size: finite, non-negative pixels,
        // and the textures change the picture (the same scene without them renders differently).
        for name in ["checkerboard.toml", "solid-checker.toml", "marble-and-wood.toml"] {
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name);
            let mut s = raylab::scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
            (s.width, s.height) = (s.width / 10, s.height / 10);
            let settings =
                TraceSettings { max_depth: s.render.max_depth.unwrap_or(5), ..TraceSettings::default() };
            let (image, _) = render_textured(&s, &settings, 4, Pattern::Stratified, Filter::Tent, 1).unwrap();
            assert_eq!(image.non_finite(), None, "{name}");
            assert!(image.pixels.iter().all(|c| c.min_element() >= 0.0), "{name}");
            let mut plain = s.clone();
            plain.materials.iter_mut().for_each(|m| m.texture = None);
            let (untextured, _) =
                render_textured(&plain, &settings, 4, Pattern::Stratified, Filter::Tent, 1).unwrap();
            assert_ne!(image, untextured, "{name}: the textures show");
        }
    }

    #[test]
    fn the_6837_checkerboard_scene_shows_both_materials() {
        // scene6_13: a red/blue checkerboard of ½-unit cubes on the sphere, which fills the
        // middle of the view. At 40 × 40 the middle 10 × 10 pixels see the sphere: both its
        // colours must be there (red pixels: red > blue; blue pixels: blue > red).
        let Some(path) = raylab::data::shared_data("mit6837/scene6_13_checkerboard.txt", "scene6_13") else {
            return;
        };
        let mut s = raylab::scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        (s.width, s.height) = (40, 40);
        let (image, _) =
            render_textured(&s, &TraceSettings::default(), 1, Pattern::Regular, Filter::Box, 0).unwrap();
        let middle: Vec<Color> =
            (15..25).flat_map(|y| (15..25).map(move |x| (x, y))).map(|(x, y)| image.get(x, y)).collect();
        assert!(middle.iter().any(|c| c.x > c.z) && middle.iter().any(|c| c.z > c.x), "{middle:?}");
    }
}
