//! The scene description: camera, image, lights, materials and objects, as
//! read from a TOML scene file ([`load`]) or an MIT 6.837 scene file.
//!
//! The description holds data only; the lectures compute with it (cameras in
//! 01, intersections in 02–04, shading in 05–08). Loaders check every value
//! they read, so a `Scene` is always usable: finite numbers, unit normals and
//! directions where promised, invertible transforms, materials that exist.

mod checks;
mod error;
mod files;
mod icosphere;
mod mesh;
mod mit6837;
mod radiance;
mod toml;
mod toml_errors;
mod toml_spec;
#[cfg(test)]
mod topology;
mod torus;

use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::color::Color;
use crate::image::Image;
use crate::math::{Float, Mat4, Vec3};

pub use error::SceneError;
pub use mesh::Mesh;
pub use mit6837::{load_mit6837, parse_mit6837};
pub use toml::{load_toml, parse_toml};

/// Reads a scene file: TOML when the name ends in `.toml`, otherwise the
/// MIT 6.837 format.
pub fn load(path: impl AsRef<Path>) -> Result<Scene, SceneError> {
    let path = path.as_ref();
    if path.extension().is_some_and(|e| e == "toml") { load_toml(path) } else { load_mit6837(path) }
}

/// A whole scene.
#[derive(Clone, Debug)]
pub struct Scene {
    pub camera: Camera,
    /// Image size in pixels (the renderer may override it).
    pub width: u32,
    pub height: u32,
    /// The colour of rays that hit nothing.
    pub background: Color,
    /// The ambient light Iₐ.
    pub ambient: Color,
    pub lights: Vec<Light>,
    pub materials: Vec<Material>,
    pub objects: Vec<Object>,
    /// How the scene asks to be rendered (its `[render]` table); the renderer
    /// fills what is `None` with its defaults and its command line overrides it.
    pub render: RenderSettings,
}

/// A scene's own render settings, the TOML `[render]` table; every field is
/// optional (`None`: the renderer's default). The loaders guarantee the
/// ranges stated. MIT 6.837 files have none: all `None`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RenderSettings {
    /// `depth`: the deepest level of the ray tree (the eye ray is level 0), 0..=64.
    pub max_depth: Option<u32>,
    /// `weight`: the smallest weight a ray of the tree may carry, in [0, 1].
    pub min_weight: Option<Float>,
    /// `transparent_shadows`: transparent blockers filter the light by their
    /// transparent colour (true) or block it (false).
    pub transparent_shadows: Option<bool>,
    /// `area_samples`: shadow rays per area light and shading point, 1..=4096.
    pub area_samples: Option<u32>,
    /// `spp`: eye rays per pixel (supersampling, lecture 10), 1..=1024.
    pub samples_per_pixel: Option<u32>,
}

/// The camera as the scene file describes it. Lecture 01 turns it into a ray
/// generator. `up` need not be perpendicular to the view direction but is
/// never parallel to it, and `eye ≠ at` (the loaders check both).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Camera {
    /// A pinhole camera; `fovy` is the full vertical field of view in radians.
    Perspective { eye: Vec3, at: Vec3, up: Vec3, fovy: Float },
    /// A parallel projection; `height` is the full height of the view in world units.
    Orthographic { eye: Vec3, at: Vec3, up: Vec3, height: Float },
}

/// A light source with its colour (intensity) and whether it casts shadows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    pub color: Color,
    /// False for a light whose shadow rays are never traced.
    pub shadows: bool,
    pub kind: LightKind,
}

/// Where a light's light comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightKind {
    /// Light travelling along the unit vector `direction` (from the light
    /// toward the scene), from infinitely far away.
    Directional { direction: Vec3 },
    /// Light from `position`, dimmed by 1 / (c + l·d + q·d²).
    Point { position: Vec3, attenuation: Attenuation },
    /// A point light restricted to a cone around the unit `direction`:
    /// full inside `inner` (half-angle, radians), falling to zero at `outer`.
    Spot { position: Vec3, direction: Vec3, inner: Float, outer: Float, attenuation: Attenuation },
    /// An area light, the parallelogram corner + a·edge_u + b·edge_v for a, b ∈
    /// [0, 1] (`edge_u`, `edge_v` non-zero and not parallel). Each of its
    /// points emits like a point light of the whole light's colour, dimmed by
    /// `attenuation` with its own distance, to both sides and without a cosine
    /// at the emitter; the shading averages over the points (so from afar it
    /// looks like a point light at its centre, whatever its size).
    Rect { corner: Vec3, edge_u: Vec3, edge_v: Vec3, attenuation: Attenuation },
    /// A spherical area light of `radius` > 0 around `center`, whose points emit
    /// like a rectangle's. Seen from a point it is sampled on its silhouette:
    /// the disc through `center` perpendicular to the direction to the point.
    Sphere { center: Vec3, radius: Float, attenuation: Attenuation },
}

impl LightKind {
    /// A rect or sphere light: sampled by `area_samples` shadow rays.
    pub fn is_area(&self) -> bool {
        matches!(self, Self::Rect { .. } | Self::Sphere { .. })
    }
}

/// Distance attenuation 1 / (constant + linear·d + quadratic·d²) of point,
/// spot and area lights; the default (1, 0, 0) is no attenuation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Attenuation {
    pub constant: Float,
    pub linear: Float,
    pub quadratic: Float,
}

impl Default for Attenuation {
    fn default() -> Self {
        Self { constant: 1.0, linear: 0.0, quadratic: 0.0 }
    }
}

/// Which specular highlight a material uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Specular {
    /// (V·R)ⁿ
    Phong,
    /// (N·H)ⁿ
    #[default]
    Blinn,
}

/// A surface's optical properties (6.837's `PhongMaterial`).
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    pub name: String,
    /// k_d, also the ambient reflectance kₐ.
    pub diffuse: Color,
    /// k_s
    pub specular: Color,
    /// The specular exponent n.
    pub exponent: Float,
    pub model: Specular,
    /// k_r, the weight of the mirror ray.
    pub reflective: Color,
    /// k_t, the weight of the transmitted ray.
    pub transparent: Color,
    /// The index of refraction η of the material (the outside is vacuum, η = 1).
    pub ior: Float,
    /// A texture that varies the material over the surface (`None`: the same everywhere).
    pub texture: Option<Texture>,
}

impl Material {
    /// The untextured materials a surface of this one shows somewhere, and
    /// blends between: itself without a texture, or for a [`Texture::Solid`]
    /// those of its two materials. Every property at any hit lies between
    /// these (each colour channel within their least and greatest).
    pub fn blended(&self) -> Vec<&Material> {
        match &self.texture {
            Some(Texture::Solid { a, b, .. }) => {
                let mut all = a.blended();
                all.extend(b.blended());
                all
            }
            _ => vec![self],
        }
    }
}

/// A texture: what varies a material over its surface. The description is
/// data; lecture 10 evaluates it, and lecture 08's tracer asks for the
/// material at each hit.
#[derive(Clone, Debug, PartialEq)]
pub enum Texture {
    /// A checkerboard in the surface's texture coordinates (u, v): `scale`
    /// cells per unit of u and of v, the cell (0, 0) and every other one of
    /// the material's `diffuse` colour, the rest `other`.
    Checker { scale: Float, other: Color },
    /// A solid texture: a pattern in 3D, p′ = `pattern_from_world`·p (p the
    /// hit point in world space), whose value s ∈ [0, 1] blends two
    /// materials: the surface is `a` where s = 0, `b` where s = 1, and in
    /// between every colour (k_d, k_s, k_r, k_t) is (1 − s)·a's + s·b's; the
    /// two agree on the exponent, the specular model and η (the loaders
    /// refuse others). Either may be textured itself (6.837's logo: a
    /// checkerboard of two woods). The material that holds the texture
    /// carries `a`'s properties. 6.837's `Checkerboard`, `Noise`, `Marble`
    /// and `Wood`; the TOML format's `solid_checker`.
    Solid { pattern_from_world: Mat4, pattern: SolidPattern, a: Box<Material>, b: Box<Material> },
    /// An image of linear colours, read when the scene is loaded, looked up
    /// at the hit's (u, v) with bilinear filtering and wrapping; `file` is
    /// where it was read from.
    Image { file: PathBuf, image: Arc<Image> },
}

/// The most octaves a noise pattern may sum (both formats): octave k scales
/// p′ by 2ᵏ, and past 2²⁴ an f32 coordinate of 1 has no fraction left for the
/// noise to vary over.
pub const MAX_OCTAVES: u32 = 24;

/// The pattern of a [`Texture::Solid`], in pattern space p′ (lecture 10
/// computes s; book §10.3 Solid textures).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SolidPattern {
    /// Unit cubes: s = 0 in the cube (0, 0, 0) and every other one, 1 in the rest.
    Checker,
    /// Fractal noise N(p′), the sum of `octaves` octaves of gradient noise,
    /// mapped to s = clamp((N + 1)/2, 0, 1).
    Noise { octaves: u32 },
    /// Veins: s = (1 + sin(frequency·x′ + amplitude·N(p′)))/2.
    Marble { octaves: u32, frequency: Float, amplitude: Float },
    /// Rings around the y′ axis: s = (1 + sin(frequency·√(x′² + z′²) + amplitude·N(p′)))/2.
    Wood { octaves: u32, frequency: Float, amplitude: Float },
}

impl Default for Material {
    fn default() -> Self {
        Self {
            name: String::new(),
            diffuse: Color::ONE,
            specular: Color::ZERO,
            exponent: 1.0,
            model: Specular::default(),
            reflective: Color::ZERO,
            transparent: Color::ZERO,
            ior: 1.0,
            texture: None,
        }
    }
}

/// A shape placed in the world with a material.
#[derive(Clone, Debug)]
pub struct Object {
    pub shape: Shape,
    /// Index into [`Scene::materials`].
    pub material: usize,
    /// `None`: the shape is given in world coordinates.
    pub transform: Option<Transform>,
}

/// An invertible affine placement of an object, with both directions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    pub world_from_object: Mat4,
    pub object_from_world: Mat4,
}

impl Transform {
    /// The placement `world_from_object`, or `None` when it is not invertible
    /// (a zero scale) or not finite.
    pub fn new(world_from_object: Mat4) -> Option<Self> {
        let det = world_from_object.determinant();
        if !det.is_finite() || det == 0.0 {
            return None;
        }
        let object_from_world = world_from_object.inverse();
        object_from_world.is_finite().then_some(Self { world_from_object, object_from_world })
    }
}

/// The shapes a scene can hold.
#[derive(Clone, Debug)]
pub enum Shape {
    Sphere {
        center: Vec3,
        radius: Float,
    },
    /// The plane n·p = offset, `normal` unit length.
    Plane {
        normal: Vec3,
        offset: Float,
    },
    /// The axis-aligned box min ≤ p ≤ max.
    Box {
        min: Vec3,
        max: Vec3,
    },
    /// A planar polygon, at least three vertices, not all on a line.
    Polygon {
        vertices: Vec<Vec3>,
    },
    /// A triangle, with per-vertex normals when given.
    Triangle {
        vertices: [Vec3; 3],
        normals: Option<[Vec3; 3]>,
    },
    Mesh(Arc<Mesh>),
    /// The canonical capped cylinder x² + y² ≤ 1, 0 ≤ z ≤ 1.
    Cylinder,
    /// The canonical capped cone x² + y² ≤ (1 − z)², 0 ≤ z ≤ 1: base of radius
    /// 1 at z = 0, apex at (0, 0, 1).
    Cone,
}

impl Shape {
    /// The name of the shape's kind as written in a TOML scene.
    pub fn kind(&self) -> &'static str {
        match self {
            Shape::Sphere { .. } => "sphere",
            Shape::Plane { .. } => "plane",
            Shape::Box { .. } => "box",
            Shape::Polygon { .. } => "polygon",
            Shape::Triangle { .. } => "triangle",
            Shape::Mesh(_) => "mesh",
            Shape::Cylinder => "cylinder",
            Shape::Cone => "cone",
        }
    }
}
