//! Colours that overflow: a scene whose values are each finite can still
//! make a pixel's colour infinite once the renderer multiplies and adds them
//! (`background = [3e38, …]` summed over 4 eye rays; a transparent colour of
//! 10¹⁵ raised to the ray tree's depth). The loaders refuse such a scene with
//! the key to blame, its value and the largest value it could have.
//!
//! The bound is an upper bound of what the Whitted tracer computes, in f64:
//! a hit's local colour is at most L = Iₐ·k_d + Σ_lights I·A·(k_d + k_s), A
//! the light's largest distance attenuation (1/constant; 1 where constant is
//! 0, whose growth near the light the shading turns to 0 where it overflows),
//! times `area_samples` for an area light (its samples are summed before the
//! sum is divided by their number);
//! a ray's colour at most max(background, L)·(1 + g + g² + … + g^depth), g
//! the largest k_r + k_t (the Fresnel split keeps the sum); a pixel sums its
//! `spp` eye rays before dividing. Every maximum is over all materials and
//! lights, each colour's largest component. Depth and spp are the scene's
//! `[render]` values, else the renderer's defaults (5 and 1); a render that
//! raises them on its command line is not covered.

use super::{LightKind, Scene, Texture};
use crate::math::Float;

/// `x` in f64 (the identity in an f64 build).
fn wide(x: Float) -> f64 {
    f64::from(x)
}

/// A colour's largest component, in f64.
fn m(c: crate::color::Color) -> f64 {
    wide(c.max_element())
}

/// The renderer's default ray-tree depth (`depth` in SCENES.md).
const DEFAULT_DEPTH: u32 = 5;

/// The renderer's default shadow rays per area light (`area_samples` in SCENES.md).
const DEFAULT_AREA_SAMPLES: u32 = 16;

/// The scene's `area_samples`, else the renderer's default.
fn area_samples(scene: &Scene) -> u32 {
    scene.render.area_samples.unwrap_or(DEFAULT_AREA_SAMPLES)
}

/// One value of the scene the bound depends on.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Value {
    Background,
    Ambient,
    Light(usize),
    Diffuse(usize),
    Specular(usize),
    Reflective(usize),
    Transparent(usize),
}

/// How the format names the values: TOML keys or 6.837's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Words {
    Toml,
    Mit6837,
}

/// The bound, with `value` replaced by `with` (its largest component) when given.
fn bound(scene: &Scene, replaced: Option<(Value, f64)>) -> f64 {
    let get = |value: Value, own: f64| match replaced {
        Some((v, with)) if v == value => with,
        _ => own,
    };
    let materials = scene.materials.iter().enumerate();
    // A solid texture blends materials: the largest of theirs bounds the blend.
    let most = |mat: &super::Material, f: &dyn Fn(&super::Material) -> f64| {
        mat.blended().into_iter().map(f).fold(0.0, f64::max)
    };
    let diffuse = materials
        .clone()
        .map(|(i, mat)| {
            let other = match &mat.texture {
                Some(Texture::Checker { other, .. }) => m(*other),
                Some(Texture::Image { .. }) => 1.0,
                Some(Texture::Solid { .. }) | None => 0.0,
            };
            get(Value::Diffuse(i), most(mat, &|l| m(l.diffuse))).max(other)
        })
        .fold(0.0, f64::max);
    let specular = materials
        .clone()
        .map(|(i, mat)| get(Value::Specular(i), most(mat, &|l| m(l.specular))))
        .fold(0.0, f64::max);
    let branching = materials
        .map(|(i, mat)| {
            get(Value::Reflective(i), most(mat, &|l| m(l.reflective)))
                + get(Value::Transparent(i), most(mat, &|l| m(l.transparent)))
        })
        .fold(0.0, f64::max);
    let area_samples = f64::from(area_samples(scene));
    let lights: f64 = scene
        .lights
        .iter()
        .enumerate()
        .map(|(i, light)| {
            let attenuation = match light.kind {
                LightKind::Directional { .. } => return get(Value::Light(i), m(light.color)),
                LightKind::Point { attenuation, .. }
                | LightKind::Spot { attenuation, .. }
                | LightKind::Rect { attenuation, .. }
                | LightKind::Sphere { attenuation, .. } => attenuation,
            };
            let samples = if light.kind.is_area() { area_samples } else { 1.0 };
            let largest = if attenuation.constant > 0.0 { 1.0 / wide(attenuation.constant) } else { 1.0 };
            get(Value::Light(i), m(light.color)) * largest * samples
        })
        .sum();
    let local = get(Value::Ambient, m(scene.ambient)) * diffuse + lights * (diffuse + specular);
    let depth = scene.render.max_depth.unwrap_or(DEFAULT_DEPTH);
    let tree: f64 = (0..=depth).map(|k| branching.powi(k as i32)).sum();
    let spp = f64::from(scene.render.samples_per_pixel.unwrap_or(1));
    // Nothing lit and a black background: black, however deep the tree (no 0·∞).
    let base = get(Value::Background, m(scene.background)).max(local);
    if base == 0.0 { 0.0 } else { base * tree * spp }
}

/// The name of `value` in the format's words.
fn name(scene: &Scene, value: Value, words: Words) -> String {
    let material = |i: usize| &scene.materials[i].name;
    match (words, value) {
        (Words::Toml, Value::Background) => "image.background".into(),
        (Words::Toml, Value::Ambient) => "image.ambient".into(),
        (Words::Toml, Value::Light(i)) => format!("lights[{i}].color"),
        (Words::Toml, Value::Diffuse(i)) => format!("materials.{}.diffuse", material(i)),
        (Words::Toml, Value::Specular(i)) => format!("materials.{}.specular", material(i)),
        (Words::Toml, Value::Reflective(i)) => format!("materials.{}.reflective", material(i)),
        (Words::Toml, Value::Transparent(i)) => format!("materials.{}.transparent", material(i)),
        (Words::Mit6837, Value::Background) => "the Background's color".into(),
        (Words::Mit6837, Value::Ambient) => "the Background's ambientLight".into(),
        (Words::Mit6837, Value::Light(i)) => format!("the color of light {i}"),
        (Words::Mit6837, Value::Diffuse(i)) => format!("the diffuseColor of material {i}"),
        (Words::Mit6837, Value::Specular(i)) => format!("the specularColor of material {i}"),
        (Words::Mit6837, Value::Reflective(i)) => format!("the reflectiveColor of material {i}"),
        (Words::Mit6837, Value::Transparent(i)) => format!("the transparentColor of material {i}"),
    }
}

/// Refuses a scene whose pixels can overflow `Float`, naming the value to
/// blame (the largest one whose lowering alone brings the bound within
/// range), its value and the largest value it may have.
pub fn check(scene: &Scene, words: Words) -> Result<(), String> {
    let limit = wide(Float::MAX);
    let total = bound(scene, None);
    if total <= limit {
        return Ok(());
    }
    let mut values: Vec<(Value, f64)> =
        vec![(Value::Background, m(scene.background)), (Value::Ambient, m(scene.ambient))];
    values.extend(scene.lights.iter().enumerate().map(|(i, l)| (Value::Light(i), m(l.color))));
    for (i, mat) in scene.materials.iter().enumerate() {
        values.extend([
            (Value::Diffuse(i), m(mat.diffuse)),
            (Value::Specular(i), m(mat.specular)),
            (Value::Reflective(i), m(mat.reflective)),
            (Value::Transparent(i), m(mat.transparent)),
        ]);
    }
    values.sort_by(|a, b| b.1.total_cmp(&a.1));
    let settings = format!(
        "depth {}, spp {}{}",
        scene.render.max_depth.unwrap_or(DEFAULT_DEPTH),
        scene.render.samples_per_pixel.unwrap_or(1),
        if scene.lights.iter().any(|l| l.kind.is_area()) {
            format!(", area_samples {}", area_samples(scene))
        } else {
            String::new()
        }
    );
    let range = format!("the range of {}-bit floats (±{:e})", 8 * size_of::<Float>(), Float::MAX);
    for &(value, own) in &values {
        if bound(scene, Some((value, 0.0))) > limit {
            continue;
        }
        // The largest value that keeps the bound within range, by bisection (the bound grows with it).
        let (mut low, mut high) = (0.0, own);
        for _ in 0..200 {
            let mid = 0.5 * (low + high);
            if bound(scene, Some((value, mid))) <= limit { low = mid } else { high = mid }
        }
        return Err(format!(
            "{} = {:e} (its largest component) can make a pixel's colour {total:.1e} with {settings}, \
             beyond {range}: the largest value it may have here is {low:.3e}",
            name(scene, value, words),
            own as Float
        ));
    }
    // No one value alone: name the largest ones.
    let largest: Vec<String> = values
        .iter()
        .take_while(|(_, own)| *own > 1.0)
        .take(3)
        .map(|&(value, own)| format!("{} = {:e}", name(scene, value, words), own as Float))
        .collect();
    Err(format!(
        "this scene's colours can make a pixel's colour {total:.1e} with {settings}, beyond {range}; lower \
         its largest values together: {}",
        largest.join(", ")
    ))
}
