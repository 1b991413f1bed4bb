//! The calls themselves: each stage's exercises at one pixel, made with the student's code in the
//! order a mistake spreads (see the parent module).

use std::borrow::Cow;

use l05_shading::{
    LightSample, blinn_specular, distance_falloff, illuminate, lambert, phong_specular, reflect, shade_light,
    shade_local, spot_falloff,
};
use raylab::scene::{LightKind, Material, Shape, Specular};
use raylab::{Hit, Interval, Ray, Scene, Vec3};

use super::Trail;
use crate::stages::{self, Draws};

/// The calls of stage `stage` at `(x, y)`, made into `trail`; `None` at a stage whose pictures
/// are not shaded (no calls).
pub fn calls(stage: &str, scene: &Scene, (x, y): (u32, u32), trail: &mut Trail) -> Option<()> {
    let draws = stages::stage(stage)?.draws;
    if !draws.shades() {
        return None;
    }
    #[cfg(feature = "complete")]
    if draws == Draws::Complete {
        sampling(trail, scene, (x, y));
    }
    let camera = l01_transforms::Camera::from_scene(&scene.camera, scene.width, scene.height).ok()?;
    let ray = camera.pixel_ray(x, y, scene.width, scene.height);
    let eye = match scene.camera {
        raylab::scene::Camera::Perspective { .. } => "01/PerspectiveCamera::generate_ray",
        raylab::scene::Camera::Orthographic { .. } => "01/OrthographicCamera::generate_ray",
    };
    trail.push(eye, "the eye ray's origin and unit direction", &[ray.origin, ray.dir.normalize()][..]);
    // Stage 10 finds hits through lecture 09's choice of hierarchy, the others with 04's brute force.
    let objects = stages::intersector(stage, scene)?;
    let found = objects.closest_hit(&ray, Interval::POSITIVE);
    let Some(hit) = found else {
        trail.push("02/closest_hit", "the eye ray: a miss", &false);
        return Some(());
    };
    trail.push(
        hit_exercise(scene, hit.object),
        "the eye ray's hit: distance, normal, front face, object, material",
        &[
            hit.t * ray.dir.length(),
            hit.normal.x,
            hit.normal.y,
            hit.normal.z,
            if hit.front_face { 1.0 } else { 0.0 },
            hit.object as raylab::Float,
            hit.material as raylab::Float,
        ][..],
    );
    let material = scene.materials.get(hit.material)?;
    #[cfg(feature = "complete")]
    let material: Cow<Material> = if draws == Draws::Complete {
        textures(trail, scene, &hit, material);
        l10_textures_sampling::surface_material(scene, &hit, material)
    } else {
        Cow::Borrowed(material)
    };
    #[cfg(not(feature = "complete"))]
    let material: Cow<Material> = Cow::Borrowed(material);
    let v = -ray.dir.normalize();
    for i in 0..scene.lights.len() {
        let at_hit = AtHit { scene, objects: objects.as_ref(), ray: &ray, hit: &hit, material: &material };
        one_light(trail, draws, &at_hit, i);
    }
    if !draws.shadows() {
        let local = shade_local(&material, material.diffuse, &hit, v, &scene.lights, scene.ambient);
        trail.push("05/shade_local", "the sum: ambient plus every light", &local);
    } else {
        #[cfg(feature = "l06")]
        {
            let surface = surface(&material, &hit, &ray);
            let color = l06_shadows::shade_with_shadows(
                objects.as_ref(),
                &scene.materials,
                &surface,
                &scene.lights,
                scene.ambient,
                crate::settings::shadow_settings(scene),
            );
            trail.push("06/shade_with_shadows", "the sum: ambient plus every light's visible share", &color);
        }
    }
    #[cfg(feature = "l07")]
    if draws.mirrors() {
        directions(trail, draws, scene, &ray, &hit, &material);
    }
    #[cfg(feature = "l08")]
    if draws.traces() {
        trace(trail, draws, scene, objects.as_ref(), &ray);
    }
    Some(())
}

/// The eye ray's hit, where a light's calls are made: the scene, the intersector its shadow rays
/// ask, the ray, its hit and the (textured) material there.
#[derive(Clone, Copy)]
struct AtHit<'a> {
    scene: &'a Scene,
    objects: &'a dyn raylab::Intersector,
    ray: &'a Ray,
    hit: &'a Hit,
    material: &'a Material,
}

/// The intersection exercise of object `index`: its transform's, or its shape's.
fn hit_exercise(scene: &Scene, index: usize) -> &'static str {
    let Some(object) = scene.objects.get(index) else { return "02/closest_hit" };
    if object.transform.is_some() {
        return "04/hit_transformed";
    }
    match object.shape {
        Shape::Sphere { .. } => "02/hit_sphere_stable",
        Shape::Plane { .. } => "02/hit_plane",
        Shape::Box { .. } => "03/hit_box",
        Shape::Polygon { .. } => "03/hit_polygon",
        Shape::Triangle { .. } => "03/hit_triangle",
        Shape::Mesh(_) => "03/hit_mesh",
        Shape::Cylinder => "04/hit_cylinder",
        Shape::Cone => "04/hit_cone",
    }
}

/// Light `index`'s calls at the hit: its falloffs, the light seen from the point, the
/// cosines, its shading, and from stage 06 on its shadow ray (or an area light's samples).
#[allow(unused_variables)]
fn one_light(trail: &mut Trail, draws: Draws, at_hit: &AtHit, index: usize) {
    let AtHit { scene, objects, ray, hit, material } = *at_hit;
    let light = &scene.lights[index];
    let at = format!("light {index}");
    let (p, n, v) = (hit.point, hit.normal, -ray.dir.normalize());
    #[cfg(feature = "l06")]
    if draws.shadows() && light.shadows && light.kind.is_area() {
        area_light(trail, at_hit, index);
        return;
    }
    let position = match light.kind {
        LightKind::Point { position, .. } | LightKind::Spot { position, .. } => Some(position),
        _ => None,
    };
    if let (Some(position), LightKind::Point { attenuation, .. } | LightKind::Spot { attenuation, .. }) =
        (position, light.kind)
    {
        trail.push(
            "05/distance_falloff",
            at.clone(),
            &distance_falloff(attenuation, (position - p).length()),
        );
    }
    if let LightKind::Spot { position, direction, inner, outer, .. } = light.kind
        && let Some(l) = (position - p).try_normalize()
    {
        trail.push("05/spot_falloff", at.clone(), &spot_falloff(-l.dot(direction), inner, outer));
    }
    let sample = illuminate(light, p);
    trail.push("05/illuminate", format!("{at}: direction, distance, intensity"), &light_numbers(&sample)[..]);
    cosines(trail, &at, material, n, v, sample.direction);
    let direct = shade_light(material, material.diffuse, n, v, &sample);
    trail.push("05/shade_light", at.clone(), &direct);
    #[cfg(feature = "l06")]
    if draws.shadows() && light.shadows && n.dot(sample.direction) > 0.0 && direct != raylab::BLACK {
        // The offset from the surface in units of ε·(|p|₁ + |o|₁), the same in f32 and f64
        // (the book's rule is 8 along the normal, on the light's side).
        let from = l06_shadows::offset_origin(p, n, sample.direction, ray.origin);
        let unit = raylab::Float::EPSILON * (p.abs().element_sum() + ray.origin.abs().element_sum());
        let offset = (from - p) / if unit > 0.0 { unit } else { 1.0 };
        trail.push(
            "06/offset_origin",
            format!("{at}: the shadow ray's origin − p, in units of ε·(|p|₁ + |o|₁)"),
            &offset,
        );
        let surface = surface(material, hit, ray);
        let mode = crate::settings::shadow_settings(scene).mode;
        let seen = l06_shadows::visibility(objects, &scene.materials, &surface, &sample, mode);
        trail.push("06/visibility", format!("{at}: what its shadow ray lets through"), &seen);
    }
}

/// Lecture 06's view of the surface at the eye ray's hit, with the material there.
#[cfg(feature = "l06")]
fn surface<'a>(material: &'a Material, hit: &Hit, ray: &Ray) -> l06_shadows::Surface<'a> {
    let v = -ray.dir.normalize();
    l06_shadows::Surface { material, diffuse: material.diffuse, hit: *hit, v, origin: ray.origin }
}

/// A light sample's numbers: direction, distance, intensity.
fn light_numbers(sample: &LightSample) -> [raylab::Float; 7] {
    let (d, i) = (sample.direction, sample.intensity);
    [d.x, d.y, d.z, sample.distance, i.x, i.y, i.z]
}

/// The diffuse and specular cosines toward `l`: Lambert, then Phong's (with its mirror
/// vector) or Blinn's, as the material's model says.
fn cosines(trail: &mut Trail, at: &str, material: &Material, n: Vec3, v: Vec3, l: Vec3) {
    trail.push("05/lambert", at, &lambert(n, l));
    match material.model {
        Specular::Phong => {
            trail.push("05/reflect", format!("{at}: R = reflect(−L, N)"), &reflect(-l, n));
            trail.push("05/phong_specular", at, &phong_specular(n, l, v, material.exponent));
        }
        Specular::Blinn => trail.push("05/blinn_specular", at, &blinn_specular(n, l, v, material.exponent)),
    }
}

/// An area light with shadows (stages 06, 08, 10): its first samples in order, the first
/// sample's light and cosines, and its average.
#[cfg(feature = "l06")]
fn area_light(trail: &mut Trail, at_hit: &AtHit, index: usize) {
    let AtHit { scene, objects, ray, hit, material } = *at_hit;
    use l06_shadows::{point_seed, shade_area_light, stratified};
    let (light, at) = (&scene.lights[index], format!("light {index}"));
    let settings = crate::settings::shadow_settings(scene);
    let samples =
        stratified(settings.area_samples.max(1), &mut raylab::random::Rng::new(point_seed(hit.point)));
    let shown = &samples[..samples.len().min(super::SAMPLES_SHOWN)];
    trail.push("06/stratified", format!("{at}: the first samples, in order"), shown);
    if let Some(&u) = samples.first() {
        if let LightKind::Sphere { .. } = light.kind {
            trail.push(
                "05/concentric_disk",
                format!("{at}: the first sample"),
                &l05_shading::concentric_disk(u),
            );
        }
        let sample = l05_shading::sample_light(light, hit.point, u);
        trail.push("05/sample_light", format!("{at}: the first sample"), &light_numbers(&sample)[..]);
    }
    let color = shade_area_light(objects, &scene.materials, &surface(material, hit, ray), light, settings);
    trail.push("06/shade_area_light", at, &color);
}

/// The mirror and refracted directions at the hit (stages 07, 08, 10), and the Fresnel
/// reflectance where the tracer's settings ask for it.
#[cfg(feature = "l07")]
fn directions(trail: &mut Trail, draws: Draws, scene: &Scene, ray: &Ray, hit: &Hit, material: &Material) {
    use l07_reflection_refraction::{fresnel_dielectric, interface, mirror_direction, refract};
    let d = ray.dir.normalize();
    if material.reflective != raylab::BLACK {
        trail.push("07/mirror_direction", "the mirror ray", &mirror_direction(d, hit.normal));
    }
    if material.transparent != raylab::BLACK {
        let crossing = interface(hit, material.ior);
        let values =
            [crossing.normal.x, crossing.normal.y, crossing.normal.z, crossing.eta_i, crossing.eta_t];
        trail.push("07/interface", "the surface crossed: normal, η_i, η_t", &values[..]);
        trail.push(
            "07/refract",
            "the refracted ray (no numbers: total internal reflection)",
            &refract(d, crossing.normal, crossing.eta_ratio()),
        );
        #[cfg(feature = "l08")]
        if draws.traces() && crate::settings::scene_settings(scene).fresnel {
            let cos_i = -d.dot(crossing.normal);
            let r = fresnel_dielectric(cos_i, crossing.eta_i, crossing.eta_t);
            trail.push("07/fresnel_dielectric", "the reflected share", &r);
        }
    }
}

/// The colour lecture 08's `trace` gives the pixel's centre ray (stages 08 and 10: at 10 with
/// the textures and the hierarchy), then the pixel's own value: the last on the path.
#[cfg(feature = "l08")]
fn trace(trail: &mut Trail, draws: Draws, scene: &Scene, objects: &dyn raylab::Intersector, ray: &Ray) {
    let settings = crate::settings::scene_settings(scene);
    #[allow(unused_mut)]
    let mut world = l08_ray_tree::World::new(scene, objects);
    #[cfg(feature = "complete")]
    let surface: l08_ray_tree::SurfaceMaterial =
        &|hit, material| l10_textures_sampling::surface_material(scene, hit, material);
    #[cfg(feature = "complete")]
    if draws == Draws::Complete {
        world = world.with_surface(surface);
    }
    let color = l08_ray_tree::trace(&world, ray, 0, 1.0, &settings);
    trail.push("08/trace_ray", "the colour of the pixel's centre ray, traced", &color);
}

/// Stage 10's samples of the pixel, where the scene asks for more than one: their offsets in
/// order (the pixel's own generator) and their filter weights.
#[cfg(feature = "complete")]
fn sampling(trail: &mut Trail, scene: &Scene, (x, y): (u32, u32)) {
    use l10_textures_sampling::{filter_weight, pixel_rng, sample_offsets};
    let sampling = crate::tracer::scene_sampling(scene);
    if sampling.spp <= 1 {
        return;
    }
    let mut rng = pixel_rng(crate::tracer::SAMPLING_SEED, x, y);
    let offsets = sample_offsets(sampling.pattern, sampling.spp, &mut rng);
    let shown = &offsets[..offsets.len().min(super::SAMPLES_SHOWN)];
    trail.push("10/sample_offsets", "the pixel's first samples, in order", shown);
    let radius = sampling.filter.radius();
    let weights: Vec<raylab::Float> = shown
        .iter()
        .map(|u| filter_weight(sampling.filter, (2.0 * *u - raylab::Vec2::ONE) * radius))
        .collect();
    trail.push("10/filter_weight", "the first samples' weights", &weights[..]);
}

/// The hit's texture (stage 10): the surface's uv where an exercise maps it, then the
/// texture's value, through the blend of a solid pattern's two materials.
#[cfg(feature = "complete")]
fn textures(trail: &mut Trail, scene: &Scene, hit: &Hit, material: &Material) {
    use l10_textures_sampling as l10;
    use raylab::scene::{SolidPattern, Texture};
    let uv = || {
        let uv = l10::surface_uv(scene, hit);
        let exercise = scene.objects.get(hit.object).and_then(|o| match o.shape {
            Shape::Sphere { .. } => Some("10/sphere_uv"),
            Shape::Plane { .. } => Some("10/plane_uv"),
            _ => None,
        });
        (uv, exercise)
    };
    match &material.texture {
        None => {}
        Some(Texture::Checker { scale, other }) => {
            let (uv, exercise) = uv();
            if let Some(exercise) = exercise {
                trail.push(exercise, "the hit's uv", &uv);
            }
            trail.push(
                "10/checker",
                "the checker's colour",
                &l10::checker(uv, *scale, material.diffuse, *other),
            );
        }
        Some(Texture::Image { image, .. }) => {
            let (uv, exercise) = uv();
            if let Some(exercise) = exercise {
                trail.push(exercise, "the hit's uv", &uv);
            }
            trail.push("10/bilinear", "the image's colour", &l10::bilinear(image, uv));
        }
        Some(Texture::Solid { pattern_from_world, pattern, a, b }) => {
            let q = l01_transforms::transform_point(pattern_from_world, hit.point);
            let octaves = match *pattern {
                SolidPattern::Noise { octaves }
                | SolidPattern::Marble { octaves, .. }
                | SolidPattern::Wood { octaves, .. } => Some(octaves),
                SolidPattern::Checker => None,
            };
            if let Some(octaves) = octaves {
                trail.push("10/noise", "noise at the pattern's point", &l10::noise(q));
                trail.push("10/fractal_noise", format!("{octaves} octaves"), &l10::fractal_noise(q, octaves));
            }
            let (exercise, value) = match *pattern {
                SolidPattern::Checker => ("10/checker_3d", l10::checker_3d(q, 1.0, Vec3::ZERO, Vec3::ONE).x),
                SolidPattern::Noise { .. } => ("10/fractal_noise", l10::solid_value(pattern, q)),
                SolidPattern::Marble { octaves, frequency, amplitude } => {
                    ("10/marble", l10::marble(q, octaves, frequency, amplitude))
                }
                SolidPattern::Wood { octaves, frequency, amplitude } => {
                    ("10/wood", l10::wood(q, octaves, frequency, amplitude))
                }
            };
            trail.push(exercise, "the pattern's blend of its two materials", &value);
            // The two materials' own textures, as the blend takes them.
            for inner in [a, b] {
                textures(trail, scene, hit, inner);
            }
        }
    }
}
