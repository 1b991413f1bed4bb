//! Checks on this lecture's scene files (`scenes/*.toml`): they load, hold
//! only spheres, planes and boxes, stay small, show the shadows they are
//! for, and show no acne: every shadow ray from an offset origin agrees with
//! an exact answer computed without any offset.

use std::path::PathBuf;

use l01_transforms::Camera;
use l04_quadrics_transforms::BruteForce;
use l05_shading::{LightSample, illuminate};
use raylab::render::render_image;
use raylab::scene::{self, Scene, Shape};
use raylab::stats::{Counter, measure};
use raylab::{Color, Float, Hit, Image, Intersector, Interval, Ray, Vec3};

use crate::testing::without;
use crate::{
    LIGHT_MARGIN, ShadowSettings, Surface, occluded, offset_origin, offset_origin_fixed_normal,
    offset_origin_fixed_t, shade_with_shadows,
};

const SCENES: [&str; 4] =
    ["sphere-shadow.toml", "coloured-shadows.toml", "shadowless-light.toml", "far-from-origin.toml"];

const F32: bool = size_of::<Float>() == 4;

type Offset = fn(Vec3, Vec3, Vec3, Vec3) -> Vec3;

const METHODS: [(&str, Offset); 3] = [
    ("offset_origin", offset_origin),
    ("fixed_t", offset_origin_fixed_t),
    ("fixed_normal", offset_origin_fixed_normal),
];

pub fn load(name: &str) -> Scene {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes")).join(name);
    scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// The primary hit of every pixel and the origin of its ray (the eye), row-major.
fn primary_hits(scene: &Scene) -> Vec<Option<(Hit, Vec3)>> {
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).expect("a valid camera");
    let shapes = BruteForce::new(&scene.objects);
    let mut hits = Vec::new();
    for y in 0..scene.height {
        for x in 0..scene.width {
            let ray = camera.pixel_ray(x, y, scene.width, scene.height);
            hits.push(shapes.closest_hit(&ray, camera.t_range()).map(|hit| (hit, ray.origin)));
        }
    }
    hits
}

/// One shadow question a render asks: the hit, the origin of the ray that found it, the
/// light's index and its sample there.
struct Query {
    hit: Hit,
    origin: Vec3,
    light: usize,
    sample: LightSample,
}

impl Query {
    /// The shadow ray's origin by `offset`.
    fn from(&self, offset: Offset) -> Vec3 {
        offset(self.hit.point, self.hit.normal, self.sample.direction, self.origin)
    }
}

/// Every shadow question a render asks: one for each pixel's hit and each light with
/// shadows that faces it and sends light there.
fn shadow_queries(scene: &Scene) -> Vec<Query> {
    let mut queries = Vec::new();
    for (hit, origin) in primary_hits(scene).into_iter().flatten() {
        for (light, source) in scene.lights.iter().enumerate() {
            let sample = illuminate(source, hit.point);
            if source.shadows && hit.normal.dot(sample.direction) > 0.0 && sample.intensity != Color::ZERO {
                queries.push(Query { hit, origin, light, sample });
            }
        }
    }
    queries
}

/// The exact answer without any offset: every object is convex, so the surface a ray
/// starts on cannot block it toward a light it faces; leave that object out and start at p.
fn exactly_occluded(scene: &Scene, query: &Query) -> bool {
    let Query { hit, sample, .. } = query;
    occluded(&BruteForce::new(&without(&scene.objects, hit.object)), hit.point, sample)
}

/// The scene rendered with shadows, and the shadow rays it cast.
pub fn render(scene: &Scene, settings: ShadowSettings) -> (Image, u64) {
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).expect("a valid camera");
    let shapes = BruteForce::new(&scene.objects);
    let ((image, _), stats) = measure(|| {
        render_image(scene.width, scene.height, |x, y| {
            let ray = camera.pixel_ray(x, y, scene.width, scene.height);
            let Some(hit) = shapes.closest_hit(&ray, camera.t_range()) else {
                return scene.background;
            };
            let material = &scene.materials[hit.material];
            let v = -ray.dir.normalize();
            let surface = Surface { material, diffuse: material.diffuse, hit, v, origin: ray.origin };
            shade_with_shadows(&shapes, &scene.materials, &surface, &scene.lights, scene.ambient, settings)
        })
    });
    (image, stats.get(Counter::ShadowRays))
}

#[test]
fn every_scene_is_small_and_made_of_spheres_planes_and_boxes() {
    for name in SCENES {
        let scene = load(name);
        assert!(scene.width <= 200 && scene.height <= 150, "{name}: {}×{}", scene.width, scene.height);
        for object in &scene.objects {
            let simple =
                matches!(object.shape, Shape::Sphere { .. } | Shape::Plane { .. } | Shape::Box { .. });
            assert!(simple && object.transform.is_none(), "{name}: {object:?}");
        }
    }
}

/// The blocker a shadow ray from `offset(p, N, L, eye)` finds first, if any.
fn first_blocker(scene: &Scene, offset: Offset, query: &Query) -> Option<usize> {
    let dir = query.sample.direction;
    let range = Interval::new(0.0, query.sample.distance * LIGHT_MARGIN);
    BruteForce::new(&scene.objects).closest_hit(&Ray::new(query.from(offset), dir), range).map(|b| b.object)
}

#[test]
fn no_scene_shows_acne_with_offset_origin_and_the_far_one_does_with_fixed_epsilons() {
    // Acne is a shadow ray blocked by the very object it starts on. Every object here is
    // convex and every light faces the point (N·L > 0), so that never happens in exact
    // arithmetic: with offset_origin it must not happen anywhere, the floor of
    // coloured-shadows near the world origin included (seen from (0, 5, 7): o + t·d
    // cancels, and the offset covers it only because it scales with the eye). Far out in
    // f32 (one ulp of 10⁴ is 0.001, ten times the fixed 10⁻⁴) the naive methods leave the
    // ball, whose hit points round inside it about half the time, in speckles: assert > 20%
    // of its tests.
    for name in SCENES {
        let scene = load(name);
        let queries = shadow_queries(&scene);
        for (method, offset) in METHODS {
            let mut acne = 0;
            let mut ball = (0, 0);
            for query in &queries {
                let own = first_blocker(&scene, offset, query) == Some(query.hit.object);
                acne += own as usize;
                if matches!(scene.objects[query.hit.object].shape, Shape::Sphere { .. }) {
                    ball = (ball.0 + own as usize, ball.1 + 1);
                }
            }
            println!(
                "{name:22} {method:14} {acne:5} self-shadowed of {:5} tests; on the ball {:5} of {:5}",
                queries.len(),
                ball.0,
                ball.1
            );
            if method == "offset_origin" {
                assert_eq!(acne, 0, "{name}: acne with offset_origin");
            } else if name.starts_with("far") && F32 {
                assert!(ball.0 * 5 > ball.1, "{name}, {method}: {} of {} on the ball", ball.0, ball.1);
            }
        }
    }
}

#[test]
fn offset_shadow_rays_agree_with_the_exact_answer() {
    // occluded from offset_origin(p, N, L, eye) against the exact answer (the hit's own object left
    // out, no offset: exact for convex objects). Only tests at a shadow's edge may differ,
    // where an origin moved by δ moves the edge by about δ: δ ≈ 8ε·(|p|₁ + |eye|₁) is 10⁻⁵
    // near the origin (none measured) but 0.06 at 10⁴ in f32, about two pixels of the far scene:
    // measured 122 of 55 000 tests (0.22%), all at the ball's and the box's shadow
    // edges; allow 0.5% there and 0.05% elsewhere.
    for name in SCENES {
        let scene = load(name);
        let shapes = BruteForce::new(&scene.objects);
        let queries = shadow_queries(&scene);
        let differ = queries
            .iter()
            .filter(|query| {
                occluded(&shapes, query.from(offset_origin), &query.sample) != exactly_occluded(&scene, query)
            })
            .count();
        println!("{name:22} {differ} of {} shadow tests differ from the exact answer", queries.len());
        let allowed = if name.starts_with("far") && F32 { queries.len() / 200 } else { queries.len() / 2000 };
        assert!(differ <= allowed, "{name}: {differ} of {}", queries.len());
    }
}

#[test]
fn renders_are_finite_and_cast_one_shadow_ray_per_light_that_needs_one() {
    // Opaque mode casts exactly the shadow rays counted independently by `shadow_queries`:
    // one per pixel hit and light with shadows that faces the point and reaches it.
    for name in SCENES {
        let scene = load(name);
        let (image, rays) = render(&scene, ShadowSettings::default());
        assert_eq!(image.non_finite(), None, "{name}");
        assert_eq!(rays, shadow_queries(&scene).len() as u64, "{name}");
    }
}

#[test]
fn the_fill_light_without_shadows_costs_no_shadow_ray() {
    // shadowless-light: the key light (0) casts shadows, the fill (1) does not. Every shadow
    // ray is the key light's; turning the fill's shadows on adds one per pixel it faces.
    let mut scene = load("shadowless-light.toml");
    assert!(scene.lights[0].shadows && !scene.lights[1].shadows);
    let key_only = shadow_queries(&scene);
    assert!(key_only.iter().all(|query| query.light == 0));
    let (_, rays) = render(&scene, ShadowSettings::default());
    assert_eq!(rays, key_only.len() as u64);
    scene.lights[1].shadows = true;
    let fill_faced = shadow_queries(&scene).iter().filter(|query| query.light == 1).count();
    let (_, rays_both) = render(&scene, ShadowSettings::default());
    assert!(fill_faced > 10_000, "the fill light faces most pixels: {fill_faced}");
    assert_eq!(rays_both, (key_only.len() + fill_faced) as u64);
}

#[test]
fn coloured_shadows_show_every_single_and_double_blocking() {
    // coloured-shadows: on the floor, for each light some points see only that light
    // blocked (the mix of the other two), and for each pair some see just that pair
    // blocked (the third colour): the three shadows overlap as the scene intends.
    let scene = load("coloured-shadows.toml");
    let shapes = BruteForce::new(&scene.objects);
    let mut seen = [[false; 3]; 3];
    for (hit, eye) in primary_hits(&scene).into_iter().flatten() {
        if hit.object != 0 {
            continue;
        }
        let blocked: Vec<bool> = scene
            .lights
            .iter()
            .map(|light| {
                let sample = illuminate(light, hit.point);
                occluded(&shapes, offset_origin(hit.point, hit.normal, sample.direction, eye), &sample)
            })
            .collect();
        let which: Vec<usize> = (0..3).filter(|&i| blocked[i]).collect();
        match which[..] {
            [i] => seen[i][i] = true,
            [i, j] => seen[i][j] = true,
            _ => {}
        }
    }
    for (i, j) in [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)] {
        assert!(seen[i][j], "no floor point with just lights {i} and {j} blocked");
    }
}

/// The scene moved by −`by`: every position, and the planes' offsets (n·p = offset becomes
/// n·p' = offset − n·by). Exact when the coordinates are within a factor 2 of `by`.
fn translated(scene: &Scene, by: Vec3) -> Scene {
    let mut moved = scene.clone();
    let scene::Camera::Perspective { eye, at, .. } = &mut moved.camera else { panic!("perspective") };
    (*eye, *at) = (*eye - by, *at - by);
    for light in &mut moved.lights {
        if let scene::LightKind::Point { position, .. } | scene::LightKind::Spot { position, .. } =
            &mut light.kind
        {
            *position -= by;
        }
    }
    for object in &mut moved.objects {
        match &mut object.shape {
            Shape::Sphere { center, .. } => *center -= by,
            Shape::Plane { normal, offset } => *offset -= normal.dot(by),
            Shape::Box { min, max } => (*min, *max) = (*min - by, *max - by),
            _ => panic!("only spheres, planes and boxes"),
        }
    }
    moved
}

#[test]
fn the_far_scene_looks_like_the_same_scene_at_the_origin() {
    // far-from-origin moved back by (10⁴, 10⁴, 10⁴) (exactly: Sterbenz) is the same scene
    // near the origin. Rendered both ways, the pictures may differ only where the far one's
    // coarser grid (0.001 in f32) moves an edge by a pixel: measured 0.5% of the pixels by
    // more than 0.1 in some channel in f32 (object and shadow outlines), none in f64;
    // allow 2%. Acne would darken half the ball's lit pixels: several percent of the image.
    let far = load("far-from-origin.toml");
    let near = translated(&far, Vec3::splat(1e4));
    let (far_image, _) = render(&far, ShadowSettings::default());
    let (near_image, _) = render(&near, ShadowSettings::default());
    let differ = far_image
        .pixels
        .iter()
        .zip(&near_image.pixels)
        .filter(|(a, b)| (**a - **b).abs().max_element() > 0.1)
        .count();
    println!("far vs near: {differ} of {} pixels differ by more than 0.1", far_image.pixels.len());
    assert!(differ * 50 <= far_image.pixels.len(), "{differ} pixels differ");
}
