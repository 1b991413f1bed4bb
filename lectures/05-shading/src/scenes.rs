//! Checks on this lecture's scene files (`scenes/*.toml`): they load, stay
//! small, hold only spheres, planes and boxes, shade to finite non-negative
//! colours, and each shows what it is for — checked against numbers derived
//! by hand from the scene's description where there are any.

use std::path::PathBuf;

use l01_transforms::Camera;
use l04_quadrics_transforms::BruteForce;
use raylab::render::render_map;
use raylab::scene::{self, Attenuation, Light, LightKind, Material, Scene, Shape, Specular};
use raylab::{BLACK, Color, Float, Hit, Intersector, Vec3};

use crate::{illuminate, shade_local};

const SCENES: [&str; 5] =
    ["phong-exponents.toml", "blinn-vs-phong.toml", "coloured-lights.toml", "attenuation.toml", "spot.toml"];

fn load(name: &str) -> Scene {
    let path = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/scenes")).join(name);
    scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

/// Every pixel's closest hit and the unit direction from it to the eye, row-major at the scene's size.
fn primary_hits(scene: &Scene) -> Vec<Option<(Hit, Vec3)>> {
    let camera = Camera::from_scene(&scene.camera, scene.width, scene.height).expect("a valid camera");
    let world = BruteForce::new(&scene.objects);
    let (w, h) = (scene.width, scene.height);
    let (hits, _) = render_map(w, h, |x, y| {
        let ray = camera.pixel_ray(x, y, w, h);
        world.closest_hit(&ray, camera.t_range()).map(|hit| (hit, -ray.dir.normalize()))
    });
    hits
}

/// The local shading of a hit with the given lights, the surface colour being the material's k_d.
fn shade(scene: &Scene, hit: &Hit, v: Vec3, lights: &[Light]) -> Color {
    let material = &scene.materials[hit.material];
    shade_local(material, material.diffuse, hit, v, lights, scene.ambient)
}

/// The specular part of a hit's shading: the shading minus that of the same material without k_s.
fn specular_part(scene: &Scene, hit: &Hit, v: Vec3) -> Color {
    let material = &scene.materials[hit.material];
    let matte = Material { specular: BLACK, ..material.clone() };
    shade(scene, hit, v, &scene.lights)
        - shade_local(&matte, matte.diffuse, hit, v, &scene.lights, scene.ambient)
}

fn sphere_center(scene: &Scene, object: usize) -> Vec3 {
    match scene.objects[object].shape {
        Shape::Sphere { center, .. } => center,
        ref other => panic!("object {object} is a {}", other.kind()),
    }
}

#[test]
fn every_scene_is_small_and_made_of_spheres_planes_and_boxes() {
    for name in SCENES {
        let scene = load(name);
        assert!(scene.width <= 200 && scene.height <= 150, "{name}: {}×{}", scene.width, scene.height);
        assert!(!scene.lights.is_empty(), "{name}: no lights");
        for object in &scene.objects {
            let kind = object.shape.kind();
            assert!(matches!(kind, "sphere" | "plane" | "box"), "{name}: a {kind}");
            assert!(object.transform.is_none(), "{name}: a transform");
        }
    }
}

#[test]
fn every_scene_shades_finite_and_non_negative_and_lights_every_object() {
    // Every object has a pixel brighter than its ambient term k_d·I_a by 0.05 in some
    // channel: some light reaches it.
    for name in SCENES {
        let scene = load(name);
        let mut lit = vec![false; scene.objects.len()];
        for (hit, v) in primary_hits(&scene).into_iter().flatten() {
            let c = shade(&scene, &hit, v, &scene.lights);
            assert!(c.is_finite() && c.min_element() >= 0.0, "{name}: {c} at {}", hit.point);
            let ambient = scene.materials[hit.material].diffuse * scene.ambient;
            lit[hit.object] |= (c - ambient).max_element() > 0.05;
        }
        for (i, lit) in lit.iter().enumerate() {
            assert!(lit, "{name}: object {i} is never lit");
        }
    }
}

#[test]
fn phong_exponents_shrink_the_highlight_but_not_move_it() {
    // Spheres left to right with Phong exponents 2…200 (increasing). Under an
    // orthographic camera and a directional light every sphere sees the same
    // geometry, so the highlight (pixels whose specular part exceeds 0.05) must
    // shrink strictly with n, and its brightest pixel sit at the same place
    // relative to each sphere's centre (within one pixel: 3/60 world units).
    let scene = load("phong-exponents.toml");
    let mut spheres: Vec<usize> = (0..scene.objects.len()).collect();
    spheres.sort_by(|&a, &b| sphere_center(&scene, a).x.total_cmp(&sphere_center(&scene, b).x));
    let materials: Vec<_> = spheres.iter().map(|&i| &scene.materials[scene.objects[i].material]).collect();
    assert!(materials.iter().all(|m| m.model == Specular::Phong));
    assert_eq!(materials.first().unwrap().exponent, 2.0);
    assert_eq!(materials.last().unwrap().exponent, 200.0);
    assert!(materials.windows(2).all(|w| w[0].exponent < w[1].exponent), "exponents increase");

    let mut area = vec![0usize; spheres.len()];
    let mut peak = vec![(0.0, Vec3::ZERO); spheres.len()];
    for (hit, v) in primary_hits(&scene).into_iter().flatten() {
        let k = spheres.iter().position(|&i| i == hit.object).unwrap();
        let s = specular_part(&scene, &hit, v).max_element();
        area[k] += usize::from(s > 0.05);
        if s > peak[k].0 {
            peak[k] = (s, hit.point - sphere_center(&scene, hit.object));
        }
    }
    assert!(area.windows(2).all(|w| w[0] > w[1]), "highlight areas {area:?}");
    assert!(area[4] > 0, "the sharpest highlight is still seen");
    for (s, offset) in &peak {
        assert!((offset.truncate() - peak[0].1.truncate()).length() <= 0.05 + 1e-3, "peak {s} at {offset}");
    }
}

#[test]
fn blinn_is_wider_than_phong_with_the_peak_in_the_same_place() {
    // Same k_d, k_s and exponent; the spheres are 3 world units = 100 pixels apart, so
    // pixel (x, y) on the Phong sphere and (x + 100, y) on the Blinn one see the same
    // geometry (up to rounding) and differ by the model alone. Both lobes peak where
    // the normal bisects L and V (then R = V and H = N): the brightest pixels sit at
    // the same place on both spheres, within a pixel (3/100 world units). By hand, a
    // normal δ off that peak gives N·H = cos δ in every direction, but R·V = cos 2δ
    // in the plane of incidence and about cos(2δ·cos φ) across it (φ = 35.8°, half
    // the angle between L and V here): Blinn's highlight covers about 4·cos φ = 3.2
    // times Phong's area at the same n; at least 2× is asserted.
    let scene = load("blinn-vs-phong.toml");
    let (phong, blinn) =
        (&scene.materials[scene.objects[0].material], &scene.materials[scene.objects[1].material]);
    assert_eq!((phong.model, blinn.model), (Specular::Phong, Specular::Blinn));
    assert_eq!(
        (phong.exponent, phong.specular, phong.diffuse),
        (blinn.exponent, blinn.specular, blinn.diffuse)
    );
    assert_eq!(sphere_center(&scene, 1) - sphere_center(&scene, 0), Vec3::new(3.0, 0.0, 0.0));

    let hits = primary_hits(&scene);
    let w = scene.width as usize;
    let (mut areas, mut peaks, mut pairs) = ([0usize; 2], [(0.0, Vec3::ZERO); 2], 0);
    for (i, left) in hits.iter().enumerate() {
        let Some((hit_p, v_p)) = left.filter(|(h, _)| h.object == 0) else { continue };
        let Some((hit_b, v_b)) = hits[i + w / 2].filter(|(h, _)| h.object == 1) else { continue };
        pairs += 1;
        for (k, (hit, v)) in [(hit_p, v_p), (hit_b, v_b)].into_iter().enumerate() {
            let s = specular_part(&scene, &hit, v).max_element();
            areas[k] += usize::from(s > 0.05);
            if s > peaks[k].0 {
                peaks[k] = (s, hit.point - sphere_center(&scene, hit.object));
            }
        }
    }
    assert!(pairs > 1000, "only {pairs} pixel pairs");
    assert!(areas[0] > 0 && areas[1] > 2 * areas[0], "areas: Phong {}, Blinn {}", areas[0], areas[1]);
    let apart = (peaks[0].1.truncate() - peaks[1].1.truncate()).length();
    assert!(apart <= 0.03 + 1e-3, "peaks {peaks:?} are {apart} apart");
}

#[test]
fn coloured_lights_add_channel_by_channel() {
    // The sphere is white and each light has a single channel, so each channel of the
    // picture is exactly (adding exact zeros) what its light alone gives. Where two
    // lights reach, their colours mix: some pixel is yellow, cyan and magenta (both
    // channels above 0.2).
    let scene = load("coloured-lights.toml");
    assert_eq!(scene.lights.len(), 3);
    let hits = primary_hits(&scene);
    let mut mixed = [false; 3];
    for (hit, v) in hits.iter().flatten() {
        let all = shade(&scene, hit, *v, &scene.lights);
        for (k, light) in scene.lights.iter().enumerate() {
            assert_eq!(light.color[k], 1.0);
            let alone = shade(&scene, hit, *v, std::slice::from_ref(light));
            assert_eq!(all[k], alone[k], "channel {k} at {}", hit.point);
        }
        for (k, (a, b)) in [(0, 1), (1, 2), (0, 2)].into_iter().enumerate() {
            mixed[k] |= all[a] > 0.2 && all[b] > 0.2;
        }
    }
    assert_eq!(mixed, [true; 3], "yellow, cyan, magenta");
}

#[test]
fn attenuation_gives_one_over_d_d2_d3_on_the_floor() {
    // The three lights hang h = 1 above the white floor (k_d = 1, no ambient): at a
    // floor point at distance d from a light, cos θ = h/d = 1/d, times the
    // attenuation 1 (constant, red), 1/d (linear, green) or 1/d² (quadratic, blue):
    // red = 1/d, green = 1/d², blue = 1/d³, by hand. Compared in f64 from each pixel's
    // floor point; the f32 pipeline (a normalisation, a dot product, a division) is
    // within 32ε of values ≤ 1. Each channel is brightest in the pixel column nearest
    // its light (the closed form decreases with d).
    let scene = load("attenuation.toml");
    let expected_lights = [
        (Vec3::new(-3.0, 1.0, 0.0), (1.0, 0.0, 0.0)),
        (Vec3::new(0.0, 1.0, 0.0), (0.0, 1.0, 0.0)),
        (Vec3::new(3.0, 1.0, 0.0), (0.0, 0.0, 1.0)),
    ];
    for (k, (light, (position, (c, l, q)))) in scene.lights.iter().zip(expected_lights).enumerate() {
        let attenuation = Attenuation { constant: c, linear: l, quadratic: q };
        assert_eq!(light.kind, LightKind::Point { position, attenuation }, "light {k}");
        assert_eq!(light.color, Color::from_array(std::array::from_fn(|i| if i == k { 1.0 } else { 0.0 })));
    }
    assert_eq!(scene.ambient, BLACK);

    let hits = primary_hits(&scene);
    let mut brightest = [(0.0, Vec3::ZERO); 3];
    for (hit, v) in hits.iter().map(|h| h.expect("the floor fills the view")) {
        let c = shade(&scene, &hit, v, &scene.lights);
        let p = hit.point.to_array().map(f64::from);
        for (k, (position, _)) in expected_lights.iter().enumerate() {
            let d = (0..3).map(|i| (f64::from(position[i]) - p[i]).powi(2)).sum::<f64>().sqrt();
            let expected = 1.0 / d.powi(k as i32 + 1);
            let got = f64::from(c[k]);
            assert!((got - expected).abs() <= 32.0 * f64::from(Float::EPSILON), "channel {k} at {p:?}");
            if c[k] > brightest[k].0 {
                brightest[k] = (c[k], hit.point);
            }
        }
    }
    // One pixel is 5/100 world units wide: the brightest is within half a pixel in x.
    for (k, (position, _)) in expected_lights.iter().enumerate() {
        assert!((brightest[k].1.x - position.x).abs() <= 0.025 + 1e-4, "channel {k}: {:?}", brightest[k]);
    }
}

#[test]
fn the_hard_spot_has_a_sharp_rim_and_the_soft_one_a_band() {
    // Both spots hang 3 above the floor. Hard (inner = outer = 25°): every floor
    // pixel gets all or nothing of it, all exactly inside radius 3·tan 25° = 1.399
    // (by hand; pixels within 0.01 of the rim are not judged). Soft (10°–35°): full
    // inside 3·tan 10° = 0.529, nothing beyond 3·tan 35° = 2.101, and the smoothstep
    // band between covers many pixels. The box's top (y = 0.8, 2.2 below the light)
    // is cut by the hard cone at radius 2.2·tan 25° = 1.026: part lit, part not.
    let scene = load("spot.toml");
    let (hard, soft) = (scene.lights[0], scene.lights[1]);
    let fraction = |light: &Light, p: Vec3| {
        let i = illuminate(light, p).intensity;
        (i / light.color).max_element()
    };
    // The distance of a point from the spot's (vertical) axis.
    let axis_distance = |light: &Light, p: Vec3| match light.kind {
        LightKind::Spot { position, .. } => Vec3::new(p.x - position.x, 0.0, p.z - position.z).length(),
        _ => panic!("a spot light"),
    };
    let (mut band, mut box_lit, mut box_dark) = (0, false, false);
    for (hit, _) in primary_hits(&scene).into_iter().flatten() {
        let p = hit.point;
        let (f_hard, f_soft) = (fraction(&hard, p), fraction(&soft, p));
        assert!(f_hard == 0.0 || f_hard == 1.0, "hard spot: {f_hard} at {p}");
        if hit.object == 0 {
            let r = axis_distance(&hard, p);
            if (r - 1.399).abs() > 0.01 {
                assert_eq!(f_hard == 1.0, r < 1.399, "hard spot at r = {r}");
            }
            let r = axis_distance(&soft, p);
            if r < 0.529 - 0.01 {
                assert_eq!(f_soft, 1.0, "soft spot at r = {r}");
            } else if r > 2.101 + 0.01 {
                assert_eq!(f_soft, 0.0, "soft spot at r = {r}");
            }
            band += usize::from(f_soft > 0.0 && f_soft < 1.0);
        } else if (p.y - 0.8).abs() < 1e-4 {
            box_lit |= f_hard == 1.0;
            box_dark |= f_hard == 0.0;
        }
    }
    assert!(band > 500, "only {band} pixels in the soft band");
    assert!(box_lit && box_dark, "the hard rim crosses the box top");
}
