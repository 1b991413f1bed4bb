//! What a TOML scene file may hold, as serde reads it (the format of
//! `crates/raylab/SCENES.md`): every table denies unknown keys, every value
//! keeps its byte span ([`Spanned`]) so that the reader in `toml.rs` can say
//! where a bad value stands. Values are checked there, not here.

use std::collections::BTreeMap;
use std::fmt;

use serde::Deserialize;
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use toml::Spanned;

pub type Num = Spanned<f64>;
pub type Nums = Spanned<Vec<f64>>;

/// The whole file.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSpec {
    pub image: Option<ImageSpec>,
    pub camera: Spanned<CameraSpec>,
    #[serde(default)]
    pub lights: Vec<Spanned<LightSpec>>,
    #[serde(default)]
    pub materials: BTreeMap<String, Spanned<MaterialSpec>>,
    #[serde(default)]
    pub objects: Vec<Spanned<ObjectSpec>>,
    pub render: Option<RenderSpec>,
}

/// `[render]`
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RenderSpec {
    pub depth: Option<Spanned<i64>>,
    pub weight: Option<Num>,
    pub transparent_shadows: Option<bool>,
    pub area_samples: Option<Spanned<i64>>,
    pub spp: Option<Spanned<i64>>,
}

/// `[image]`
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ImageSpec {
    pub width: Option<Spanned<i64>>,
    pub height: Option<Spanned<i64>>,
    pub background: Option<Nums>,
    pub ambient: Option<Nums>,
}

/// `[camera]`
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraSpec {
    #[serde(rename = "type")]
    pub kind: Spanned<String>,
    pub eye: Nums,
    pub at: Nums,
    pub up: Option<Nums>,
    pub fovy: Option<Num>,
    pub height: Option<Num>,
}

/// One `[[lights]]` table; which keys a light takes depends on its `type`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LightSpec {
    #[serde(rename = "type")]
    pub kind: Spanned<String>,
    pub direction: Option<Nums>,
    pub position: Option<Nums>,
    pub color: Option<Nums>,
    pub shadows: Option<bool>,
    pub attenuation: Option<Nums>,
    pub inner: Option<Num>,
    pub outer: Option<Num>,
    pub corner: Option<Nums>,
    pub edge_u: Option<Nums>,
    pub edge_v: Option<Nums>,
    pub center: Option<Nums>,
    pub radius: Option<Num>,
}

/// One `[materials.NAME]` table.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    pub diffuse: Option<Nums>,
    pub specular: Option<Nums>,
    pub exponent: Option<Num>,
    pub model: Option<Spanned<String>>,
    pub reflective: Option<Nums>,
    pub transparent: Option<Nums>,
    pub ior: Option<Num>,
    pub texture: Option<Spanned<TextureSpec>>,
}

/// A material's `texture = { type = …, … }`; which keys it takes depends on its `type`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TextureSpec {
    #[serde(rename = "type")]
    pub kind: Spanned<String>,
    pub scale: Option<Num>,
    pub other: Option<Nums>,
    pub file: Option<Spanned<String>>,
    pub octaves: Option<Spanned<i64>>,
    pub frequency: Option<Num>,
    pub amplitude: Option<Num>,
}

/// One `[[objects]]` table; which shape keys it takes depends on its `type`
/// (see [`shape_keys`]).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObjectSpec {
    #[serde(rename = "type")]
    pub kind: Spanned<String>,
    pub material: Option<Spanned<String>>,
    pub transform: Option<Spanned<Vec<Spanned<StepSpec>>>>,
    pub center: Option<Nums>,
    pub radius: Option<Num>,
    pub normal: Option<Nums>,
    pub offset: Option<Num>,
    pub min: Option<Nums>,
    pub max: Option<Nums>,
    pub vertices: Option<Spanned<Vec<Nums>>>,
    pub normals: Option<Spanned<Vec<Nums>>>,
    pub file: Option<Spanned<String>>,
    pub subdivisions: Option<Spanned<i64>>,
    pub major: Option<Num>,
    pub minor: Option<Num>,
    pub segments: Option<Spanned<Vec<i64>>>,
}

/// One step of an object's `transform` list: exactly one key.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StepSpec {
    pub translate: Option<Nums>,
    pub scale: Option<Spanned<ScaleSpec>>,
    pub rotate_x: Option<Num>,
    pub rotate_y: Option<Num>,
    pub rotate_z: Option<Num>,
    pub rotate: Option<Spanned<RotateSpec>>,
    pub matrix: Option<Nums>,
}

/// `{ rotate = { axis = [x, y, z], angle = degrees } }`
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RotateSpec {
    pub axis: Nums,
    pub angle: Num,
}

/// `scale = 2` or `scale = [1, 2, 1]`.
pub enum ScaleSpec {
    Uniform(f64),
    Axes(Vec<f64>),
}

impl<'de> Deserialize<'de> for ScaleSpec {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct ScaleVisitor;
        impl<'de> Visitor<'de> for ScaleVisitor {
            type Value = ScaleSpec;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number or an array of 3 numbers")
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<ScaleSpec, E> {
                Ok(ScaleSpec::Uniform(v as f64))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<ScaleSpec, E> {
                Ok(ScaleSpec::Uniform(v as f64))
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<ScaleSpec, E> {
                Ok(ScaleSpec::Uniform(v))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<ScaleSpec, A::Error> {
                let mut axes = Vec::new();
                while let Some(x) = seq.next_element::<f64>()? {
                    axes.push(x);
                }
                Ok(ScaleSpec::Axes(axes))
            }
        }
        deserializer.deserialize_any(ScaleVisitor)
    }
}

/// The keys a shape may have besides `type`, `material` and `transform`.
pub fn shape_keys(kind: &str) -> Option<&'static [&'static str]> {
    Some(match kind {
        "sphere" => &["center", "radius"],
        "plane" => &["normal", "offset"],
        "box" => &["min", "max"],
        "polygon" => &["vertices"],
        "triangle" => &["vertices", "normals"],
        "mesh" => &["file"],
        "icosphere" => &["subdivisions"],
        "torus" => &["major", "minor", "segments"],
        "cylinder" | "cone" => &[],
        _ => return None,
    })
}

pub const SHAPES: &str = "sphere, plane, box, polygon, triangle, mesh, icosphere, torus, cylinder or cone";
