//! What lecture 05 lends the stages (`stages::Lent`): stage 05's local shading, every light
//! unblocked, and the calls on its pictures' path ([`walk`]), which the later shading stages
//! (06, 07, 08, 10) extend through [`Walk`].
//!
//! The calls are the student's own functions at one pixel, made in the order a mistake spreads
//! (the `path` module): the eye ray, its hit, each light's falloffs, the light seen from the
//! point, the cosines and the light's shading, then the sum.

use std::borrow::Cow;

use l05_shading::{
    LightSample, blinn_specular, distance_falloff, illuminate, lambert, phong_specular, reflect, shade_light,
    shade_local, spot_falloff,
};
use raylab::scene::{LightKind, Material, Shape, Specular};
use raylab::{Color, Hit, Intersector, Interval, Ray, Scene, Vec3};

use crate::path::Trail;
use crate::stages::{self, Drawer, Draws, Lent};

/// Lends stage 05's drawing.
pub fn lend(lent: &mut Lent) {
    let shade = |scene: &Scene, _: &dyn Intersector, ray: &Ray, hit: &Hit| local(scene, ray, hit);
    let calls =
        |stage: &str, scene: &Scene, pixel, trail: &mut Trail| walk(&Local, stage, scene, pixel, trail);
    lent.drawers.push((Draws::Local, Drawer::Shades { shade, sky_rays: None, calls }));
}

/// Stage 05's colour of a hit: 05's `shade_local` with the material's own colour, V = −d/|d|.
pub fn local(scene: &Scene, ray: &Ray, hit: &Hit) -> Color {
    let Some(material) = scene.materials.get(hit.material) else { return scene.background };
    shade_local(material, material.diffuse, hit, -ray.dir.normalize(), &scene.lights, scene.ambient)
}

/// The eye ray's hit, where a light's calls are made: the scene, the intersector its shadow rays
/// ask, the ray, its hit and the (textured) material there.
#[derive(Clone, Copy)]
pub struct AtHit<'a> {
    pub scene: &'a Scene,
    pub objects: &'a dyn Intersector,
    pub ray: &'a Ray,
    pub hit: &'a Hit,
    pub material: &'a Material,
}

/// What a shading stage adds to stage 05's calls; each method's default is stage 05's.
pub trait Walk {
    /// Before the eye ray (10: the pixel's samples).
    fn sampling(&self, _trail: &mut Trail, _scene: &Scene, _pixel: (u32, u32)) {}

    /// The material at the hit, its calls made (10: the textured one).
    fn material<'m>(
        &self,
        _trail: &mut Trail,
        _scene: &Scene,
        _hit: &Hit,
        material: &'m Material,
    ) -> Cow<'m, Material> {
        Cow::Borrowed(material)
    }

    /// How the lights' calls are made: 05's, every light unblocked, or 06's shadow rays (06, 08, 10).
    fn lights(&self) -> &dyn Lights {
        &Unblocked
    }

    /// After the sum (07 on: the mirror and refracted directions; 08 on: the trace).
    fn after(&self, _trail: &mut Trail, _at: &AtHit) {}
}

/// How a stage's lights are shaded, as calls: each method's default is stage 05's.
pub trait Lights {
    /// Light `index`'s calls made in full, where this stage makes them its own way (06 on: an
    /// area light with shadows); `false` where the point light's calls below are made.
    fn area_light(&self, _trail: &mut Trail, _at: &AtHit, _index: usize) -> bool {
        false
    }

    /// After light `index`'s shading `direct` (06 on: its shadow ray).
    fn shadow_ray(
        &self,
        _trail: &mut Trail,
        _at: &AtHit,
        _index: usize,
        _sample: &LightSample,
        _direct: Color,
    ) {
    }

    /// The sum over the lights: 05's `shade_local`.
    fn sum(&self, trail: &mut Trail, at: &AtHit) {
        let AtHit { scene, ray, hit, material, .. } = *at;
        let v = -ray.dir.normalize();
        let local = shade_local(material, material.diffuse, hit, v, &scene.lights, scene.ambient);
        trail.push("05/shade_local", "the sum: ambient plus every light", &local);
    }
}

/// Stage 05's lights: every one unblocked.
struct Unblocked;

impl Lights for Unblocked {}

/// Stage 05's calls: the defaults.
struct Local;

impl Walk for Local {}

/// The calls of stage `stage` at `(x, y)`, made into `trail` as `walk` says.
pub fn walk(
    walk: &dyn Walk,
    stage: &str,
    scene: &Scene,
    (x, y): (u32, u32),
    trail: &mut Trail,
) -> Option<()> {
    walk.sampling(trail, scene, (x, y));
    let camera = l01_transforms::Camera::from_scene(&scene.camera, scene.width, scene.height).ok()?;
    let ray = camera.pixel_ray(x, y, scene.width, scene.height);
    let eye = match scene.camera {
        raylab::scene::Camera::Perspective { .. } => "01/PerspectiveCamera::generate_ray",
        raylab::scene::Camera::Orthographic { .. } => "01/OrthographicCamera::generate_ray",
    };
    trail.push(eye, "the eye ray's origin and unit direction", &[ray.origin, ray.dir.normalize()][..]);
    // Stage 10 finds hits through lecture 09's choice of hierarchy, the others with 04's brute force.
    let objects = stages::intersector(stage, scene)?;
    let Some(hit) = objects.closest_hit(&ray, Interval::POSITIVE) else {
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
    let material = walk.material(trail, scene, &hit, scene.materials.get(hit.material)?);
    let at = AtHit { scene, objects: objects.as_ref(), ray: &ray, hit: &hit, material: &material };
    let lights = walk.lights();
    for index in 0..scene.lights.len() {
        if !lights.area_light(trail, &at, index) {
            one_light(lights, trail, &at, index);
        }
    }
    lights.sum(trail, &at);
    walk.after(trail, &at);
    Some(())
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
/// cosines, its shading, and what the stage adds after it (06 on: its shadow ray).
fn one_light(lights: &dyn Lights, trail: &mut Trail, at_hit: &AtHit, index: usize) {
    let AtHit { scene, ray, hit, material, .. } = *at_hit;
    let light = &scene.lights[index];
    let at = format!("light {index}");
    let (p, n, v) = (hit.point, hit.normal, -ray.dir.normalize());
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
    trail.push("05/shade_light", at, &direct);
    lights.shadow_ray(trail, at_hit, index, &sample, direct);
}

/// A light sample's numbers: direction, distance, intensity.
pub fn light_numbers(sample: &LightSample) -> [raylab::Float; 7] {
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
