//! Reading TOML scene files, the format of `crates/raylab/SCENES.md`.
//!
//! serde reads the text into the `…Spec` structs of `toml_spec.rs` (unknown
//! keys are errors, every value keeps its byte span through [`Spanned`]);
//! then a `Reader` checks each value and builds the [`Scene`], turning spans
//! into line and column for its errors. Angles are degrees in the file and
//! radians in the `Scene`. Book: §0.5 Scene files.

use std::collections::{BTreeMap, HashMap};
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use toml::Spanned;

use super::checks::{self, show};
use super::files::read_scene;
use super::toml_spec::{
    CameraSpec, LightSpec, MaterialSpec, Num, Nums, ObjectSpec, RenderSpec, SHAPES, ScaleSpec, SceneSpec,
    StepSpec, TextureSpec, shape_keys,
};
use super::{
    Camera, Light, LightKind, MAX_OCTAVES, Material, Mesh, Object, RenderSettings, Scene, SceneError, Shape,
    SolidPattern, Specular, Texture, Transform,
};
use crate::color::{BLACK, Color, WHITE};
use crate::image::Image;
use crate::math::{Float, Mat4, Vec3, radians};

/// Reads the TOML scene file at `path` (format: `crates/raylab/SCENES.md`).
/// Every error names the file, line and column and what was expected.
pub fn load_toml(path: &Path) -> Result<Scene, SceneError> {
    let text = read_scene(path)?;
    parse_toml(&text, path)
}

/// Reads a TOML scene from `text`; `path` names the file in errors, and OBJ
/// files are looked for relative to its folder.
pub fn parse_toml(text: &str, path: &Path) -> Result<Scene, SceneError> {
    let spec: SceneSpec = toml::from_str(text).map_err(|e| {
        let message = super::toml_errors::explain(text, e.span(), e.message());
        match e.span() {
            Some(span) => SceneError::at_offset(path, text, span.start, message),
            None => SceneError::new(path, 0, 0, message),
        }
    })?;
    Reader { text, path, dir: path.parent().unwrap_or(Path::new("")), meshes: HashMap::new() }.scene(spec)
}

/// Builds the scene from the specs, checking every value.
struct Reader<'a> {
    text: &'a str,
    path: &'a Path,
    /// The scene file's folder, where OBJ paths start.
    dir: &'a Path,
    meshes: HashMap<PathBuf, Arc<Mesh>>,
}

/// What an optional key holds, with its span.
fn span_of<T>(v: &Option<Spanned<T>>) -> Option<Range<usize>> {
    v.as_ref().map(Spanned::span)
}

impl Reader<'_> {
    fn error(&self, span: &Range<usize>, message: impl Into<String>) -> SceneError {
        SceneError::at_offset(self.path, self.text, span.start, message)
    }

    /// A check's sentence, located at `span`.
    fn at<T>(&self, span: &Range<usize>, checked: Result<T, String>) -> Result<T, SceneError> {
        checked.map_err(|m| self.error(span, m))
    }

    fn float(&self, x: &Num, key: &str) -> Result<Float, SceneError> {
        checks::finite(*x.get_ref()).ok_or_else(|| {
            self.error(
                &x.span(),
                format!(
                    "{key} must be {}, found {}",
                    checks::finite_words(&[*x.get_ref()]),
                    checks::number(*x.get_ref())
                ),
            )
        })
    }

    fn vec3(&self, v: &Nums, key: &str) -> Result<Vec3, SceneError> {
        let [x, y, z] = v.get_ref()[..] else {
            return Err(self.error(
                &v.span(),
                format!("{key} must be 3 numbers [x, y, z], found {} numbers", v.get_ref().len()),
            ));
        };
        match (checks::finite(x), checks::finite(y), checks::finite(z)) {
            (Some(x), Some(y), Some(z)) => Ok(Vec3::new(x, y, z)),
            _ => {
                let words = checks::finite_words(&[x, y, z]);
                let [x, y, z] = [x, y, z].map(checks::number);
                Err(self.error(&v.span(), format!("{key} must hold {words}, found [{x}, {y}, {z}]")))
            }
        }
    }

    /// A linear RGB triple, every component ≥ 0.
    fn color(&self, v: &Option<Nums>, key: &str, default: Color) -> Result<Color, SceneError> {
        let Some(v) = v else { return Ok(default) };
        let c = self.vec3(v, key)?;
        if c.min_element() < 0.0 {
            return Err(self.error(&v.span(), format!("{key} components must be ≥ 0, found {}", show(c))));
        }
        Ok(c)
    }

    /// A non-zero direction, normalised.
    fn direction(&self, v: &Nums, key: &str) -> Result<Vec3, SceneError> {
        let d = self.vec3(v, key)?;
        self.at(&v.span(), checks::unit(d, key))
    }

    /// A required key of `whole` (a table of kind `kind`).
    fn need<'s, T>(
        &self,
        v: &'s Option<Spanned<T>>,
        key: &str,
        kind: &str,
        whole: &Range<usize>,
    ) -> Result<&'s Spanned<T>, SceneError> {
        v.as_ref().ok_or_else(|| self.error(whole, format!("{kind} needs `{key}`")))
    }

    /// Errors on the first key of `present` not in `allowed`.
    fn only(
        &self,
        kind: &str,
        present: &[(&str, Option<Range<usize>>)],
        allowed: &[&str],
    ) -> Result<(), SceneError> {
        for (key, span) in present {
            if let Some(span) = span
                && !allowed.contains(key)
            {
                let keys = if allowed.is_empty() { "none".to_string() } else { allowed.join(", ") };
                return Err(self.error(span, format!("{key} is not a key of {kind} (its keys: {keys})")));
            }
        }
        Ok(())
    }

    fn scene(mut self, spec: SceneSpec) -> Result<Scene, SceneError> {
        let mut materials = self.materials(spec.materials)?;
        let mut default_material = materials.iter().position(|m| m.name == "default");
        let mut objects = Vec::with_capacity(spec.objects.len());
        for object in &spec.objects {
            objects.push(self.object(object, &mut materials, &mut default_material)?);
        }
        let lights = spec.lights.iter().map(|l| self.light(l)).collect::<Result<_, _>>()?;
        let camera = self.camera(&spec.camera)?;
        let (width, height, background, ambient) = match &spec.image {
            None => (320, 240, BLACK, BLACK),
            Some(image) => (
                self.size(&image.width, "width", 320)?,
                self.size(&image.height, "height", 240)?,
                self.color(&image.background, "background", BLACK)?,
                self.color(&image.ambient, "ambient", BLACK)?,
            ),
        };
        let render = self.render(&spec.render)?;
        let scene = Scene { camera, width, height, background, ambient, lights, materials, objects, render };
        super::radiance::check(&scene, super::radiance::Words::Toml)
            .map_err(|e| SceneError::new(self.path, 0, 0, e))?;
        Ok(scene)
    }

    fn size(&self, v: &Option<Spanned<i64>>, key: &str, default: u32) -> Result<u32, SceneError> {
        let Some(v) = v else { return Ok(default) };
        match *v.get_ref() {
            n @ 1..=16384 => Ok(n as u32),
            n => Err(self.error(&v.span(), format!("{key} must be in 1..=16384 pixels, found {n}"))),
        }
    }

    fn camera(&self, spec: &Spanned<CameraSpec>) -> Result<Camera, SceneError> {
        let (whole, c) = (spec.span(), spec.get_ref());
        let eye = self.vec3(&c.eye, "eye")?;
        let at = self.vec3(&c.at, "at")?;
        let up = match &c.up {
            Some(up) => self.vec3(up, "up")?,
            None => Vec3::Y,
        };
        let view_span = match (&c.up, eye == at) {
            (Some(up), false) => up.span(),
            _ => c.at.span(),
        };
        let view = checks::check_view(eye, at, at - eye, up, checks::ViewWords::Toml);
        let at = self.at(&view_span, view)?.unwrap_or(at);
        let present = [("fovy", span_of(&c.fovy)), ("height", span_of(&c.height))];
        match c.kind.get_ref().as_str() {
            "perspective" => {
                self.only("a perspective camera", &present, &["fovy"])?;
                let fovy = self.need(&c.fovy, "fovy", "a perspective camera", &whole)?;
                let degrees = self.float(fovy, "fovy")?;
                let fovy = checks::field_of_view(degrees, "fovy").map_err(|e| self.error(&fovy.span(), e))?;
                Ok(Camera::Perspective { eye, at, up, fovy })
            }
            "orthographic" => {
                self.only("an orthographic camera", &present, &["height"])?;
                let h = self.need(&c.height, "height", "an orthographic camera", &whole)?;
                let height = self.float(h, "height")?;
                if height <= 0.0 {
                    return Err(self.error(&h.span(), format!("height must be > 0, found {height}")));
                }
                Ok(Camera::Orthographic { eye, at, up, height })
            }
            other => Err(self.error(
                &c.kind.span(),
                format!("unknown camera type `{other}`, expected perspective or orthographic"),
            )),
        }
    }

    fn light(&self, spec: &Spanned<LightSpec>) -> Result<Light, SceneError> {
        let (whole, l) = (spec.span(), spec.get_ref());
        let present = [
            ("direction", span_of(&l.direction)),
            ("position", span_of(&l.position)),
            ("attenuation", span_of(&l.attenuation)),
            ("inner", span_of(&l.inner)),
            ("outer", span_of(&l.outer)),
            ("corner", span_of(&l.corner)),
            ("edge_u", span_of(&l.edge_u)),
            ("edge_v", span_of(&l.edge_v)),
            ("center", span_of(&l.center)),
            ("radius", span_of(&l.radius)),
        ];
        let kind = l.kind.get_ref().as_str();
        let (what, allowed): (&str, &[&str]) = match kind {
            "directional" => ("a directional light", &["direction"]),
            "point" => ("a point light", &["position", "attenuation"]),
            "spot" => ("a spot light", &["position", "direction", "attenuation", "inner", "outer"]),
            "rect" => ("a rect light", &["corner", "edge_u", "edge_v", "attenuation"]),
            "sphere" => ("a sphere light", &["center", "radius", "attenuation"]),
            other => {
                return Err(self.error(
                    &l.kind.span(),
                    format!(
                        "unknown light type `{other}`, expected directional, point, spot, rect or sphere"
                    ),
                ));
            }
        };
        self.only(what, &present, allowed)?;
        let attenuation = match &l.attenuation {
            None => Default::default(),
            Some(a) => {
                let v = self.vec3(a, "attenuation")?;
                self.at(&a.span(), checks::attenuation(v.x, v.y, v.z))?
            }
        };
        let kind = match kind {
            "directional" => LightKind::Directional {
                direction: self
                    .direction(self.need(&l.direction, "direction", what, &whole)?, "direction")?,
            },
            "point" => LightKind::Point {
                position: self.vec3(self.need(&l.position, "position", what, &whole)?, "position")?,
                attenuation,
            },
            "spot" => {
                let inner_spec = self.need(&l.inner, "inner", what, &whole)?;
                let outer_spec = self.need(&l.outer, "outer", what, &whole)?;
                let (inner, outer) = (self.float(inner_spec, "inner")?, self.float(outer_spec, "outer")?);
                if inner < 0.0 {
                    return Err(
                        self.error(&inner_spec.span(), format!("inner must be ≥ 0 degrees, found {inner}"))
                    );
                }
                if !(inner <= outer && outer < 90.0) {
                    return Err(self.error(
                        &outer_spec.span(),
                        format!("outer must satisfy inner ≤ outer < 90 degrees, found inner {inner}, outer {outer}"),
                    ));
                }
                LightKind::Spot {
                    position: self.vec3(self.need(&l.position, "position", what, &whole)?, "position")?,
                    direction: self
                        .direction(self.need(&l.direction, "direction", what, &whole)?, "direction")?,
                    inner: radians(inner),
                    outer: radians(outer),
                    attenuation,
                }
            }
            "rect" => {
                let corner = self.vec3(self.need(&l.corner, "corner", what, &whole)?, "corner")?;
                let u_spec = self.need(&l.edge_u, "edge_u", what, &whole)?;
                let v_spec = self.need(&l.edge_v, "edge_v", what, &whole)?;
                let (edge_u, edge_v) = (self.vec3(u_spec, "edge_u")?, self.vec3(v_spec, "edge_v")?);
                let span = if edge_u == Vec3::ZERO { u_spec.span() } else { v_spec.span() };
                self.at(&span, checks::check_rect(edge_u, edge_v))?;
                LightKind::Rect { corner, edge_u, edge_v, attenuation }
            }
            _ => {
                let center = self.vec3(self.need(&l.center, "center", what, &whole)?, "center")?;
                let r = self.need(&l.radius, "radius", what, &whole)?;
                let radius = self.float(r, "radius")?;
                if radius <= 0.0 {
                    return Err(self.error(&r.span(), format!("radius must be > 0, found {radius}")));
                }
                LightKind::Sphere { center, radius, attenuation }
            }
        };
        Ok(Light { color: self.color(&l.color, "color", WHITE)?, shadows: l.shadows.unwrap_or(true), kind })
    }

    /// The `[render]` table; every key optional.
    fn render(&self, spec: &Option<RenderSpec>) -> Result<RenderSettings, SceneError> {
        let Some(r) = spec else { return Ok(RenderSettings::default()) };
        let max_depth = match &r.depth {
            None => None,
            Some(d) => match *d.get_ref() {
                n @ 0..=64 => Some(n as u32),
                n => return Err(self.error(&d.span(), format!("depth must be in 0..=64, found {n}"))),
            },
        };
        let min_weight = match &r.weight {
            None => None,
            Some(w) => match self.float(w, "weight")? {
                x if (0.0..=1.0).contains(&x) => Some(x),
                x => return Err(self.error(&w.span(), format!("weight must be in [0, 1], found {x}"))),
            },
        };
        let area_samples = match &r.area_samples {
            None => None,
            Some(a) => match *a.get_ref() {
                n @ 1..=4096 => Some(n as u32),
                n => {
                    return Err(self.error(&a.span(), format!("area_samples must be in 1..=4096, found {n}")));
                }
            },
        };
        let samples_per_pixel = match &r.spp {
            None => None,
            Some(a) => match *a.get_ref() {
                n @ 1..=1024 => Some(n as u32),
                n => return Err(self.error(&a.span(), format!("spp must be in 1..=1024, found {n}"))),
            },
        };
        Ok(RenderSettings {
            max_depth,
            min_weight,
            transparent_shadows: r.transparent_shadows,
            area_samples,
            samples_per_pixel,
        })
    }

    /// The named materials, in the order of the file.
    fn materials(&self, specs: BTreeMap<String, Spanned<MaterialSpec>>) -> Result<Vec<Material>, SceneError> {
        let mut specs: Vec<_> = specs.into_iter().collect();
        specs.sort_by_key(|(_, m)| m.span().start);
        let mut materials = Vec::with_capacity(specs.len());
        for (name, spec) in specs {
            let m = spec.get_ref();
            let model = match &m.model {
                None => Specular::default(),
                Some(model) => match model.get_ref().as_str() {
                    "blinn" => Specular::Blinn,
                    "phong" => Specular::Phong,
                    other => {
                        return Err(self.error(
                            &model.span(),
                            format!("unknown specular model `{other}`, expected blinn or phong"),
                        ));
                    }
                },
            };
            let exponent = match &m.exponent {
                None => 1.0,
                Some(e) => match self.float(e, "exponent")? {
                    e if e >= 0.0 => e,
                    x => return Err(self.error(&e.span(), format!("exponent must be ≥ 0, found {x}"))),
                },
            };
            let ior = match &m.ior {
                None => 1.0,
                Some(i) => checks::index_of_refraction(self.float(i, "ior")?, "ior")
                    .map_err(|e| self.error(&i.span(), e))?,
            };
            let mut material = Material {
                diffuse: self.color(&m.diffuse, "diffuse", WHITE)?,
                specular: self.color(&m.specular, "specular", BLACK)?,
                exponent,
                model,
                reflective: self.color(&m.reflective, "reflective", BLACK)?,
                transparent: self.color(&m.transparent, "transparent", BLACK)?,
                ior,
                texture: None,
                name,
            };
            material.texture = m.texture.as_ref().map(|t| self.texture(t, &material)).transpose()?;
            materials.push(material);
        }
        Ok(materials)
    }

    /// The `texture` of `material` (read without it): a uv checkerboard, a
    /// solid one, or an image file (relative to the scene file's folder, read now).
    fn texture(&self, spec: &Spanned<TextureSpec>, material: &Material) -> Result<Texture, SceneError> {
        let (whole, t) = (spec.span(), spec.get_ref());
        let kind = t.kind.get_ref().as_str();
        let allowed: &[&str] = match kind {
            "checker" | "solid_checker" => &["scale", "other"],
            "noise" => &["scale", "other", "octaves"],
            "marble" | "wood" => &["scale", "other", "octaves", "frequency", "amplitude"],
            "image" => &["file"],
            _ => {
                return Err(self.error(
                    &t.kind.span(),
                    format!(
                        "unknown texture type `{kind}`, expected checker, solid_checker, noise, marble, wood or image"
                    ),
                ));
            }
        };
        let present = [
            ("scale", span_of(&t.scale)),
            ("other", span_of(&t.other)),
            ("file", span_of(&t.file)),
            ("octaves", span_of(&t.octaves)),
            ("frequency", span_of(&t.frequency)),
            ("amplitude", span_of(&t.amplitude)),
        ];
        let what = format!("the {kind} texture");
        self.only(&what, &present, allowed)?;
        if kind == "image" {
            let file = self.need(&t.file, "file", &what, &whole)?;
            let path = self.dir.join(file.get_ref());
            let shown = |e: String| self.error(&file.span(), format!("image file `{}`: {e}", file.get_ref()));
            let bytes = super::files::read_limited(&path, super::files::TEXTURE_LIMIT, "the image file")
                .map_err(|e| shown(format!("{}: {e}", path.display())))?;
            let image = Image::decode_png(&bytes, &path).map_err(|e| shown(e.to_string()))?;
            return Ok(Texture::Image { file: path, image: Arc::new(image) });
        }
        let scale = match &t.scale {
            None => 1.0,
            Some(n) => match self.float(n, "scale")? {
                x if x > 0.0 => x,
                x => return Err(self.error(&n.span(), format!("scale must be > 0, found {x}"))),
            },
        };
        let other = self.color(&t.other, "other", BLACK)?;
        if kind == "checker" {
            return Ok(Texture::Checker { scale, other });
        }
        let octaves = match &t.octaves {
            None => 0,
            Some(n) => match u32::try_from(*n.get_ref()) {
                Ok(k) if k <= MAX_OCTAVES => k,
                _ => {
                    let found = n.get_ref();
                    return Err(
                        self.error(&n.span(), format!("octaves must be in 0..={MAX_OCTAVES}, found {found}"))
                    );
                }
            },
        };
        let number = |x: &Option<Num>, key: &str, default: Float| match x {
            None => Ok(default),
            Some(n) => self.float(n, key),
        };
        let (frequency, amplitude) =
            (number(&t.frequency, "frequency", 1.0)?, number(&t.amplitude, "amplitude", 1.0)?);
        let pattern = match kind {
            "solid_checker" => SolidPattern::Checker,
            "noise" => SolidPattern::Noise { octaves },
            "marble" => SolidPattern::Marble { octaves, frequency, amplitude },
            _ => SolidPattern::Wood { octaves, frequency, amplitude },
        };
        Ok(Texture::Solid {
            pattern_from_world: Mat4::from_scale(Vec3::splat(scale)),
            pattern,
            a: Box::new(material.clone()),
            b: Box::new(Material { diffuse: other, ..material.clone() }),
        })
    }

    fn object(
        &mut self,
        spec: &Spanned<ObjectSpec>,
        materials: &mut Vec<Material>,
        default_material: &mut Option<usize>,
    ) -> Result<Object, SceneError> {
        let o = spec.get_ref();
        let material = match &o.material {
            Some(name) => materials.iter().position(|m| m.name == *name.get_ref()).ok_or_else(|| {
                let known: Vec<&str> = materials.iter().map(|m| m.name.as_str()).collect();
                let known = if known.is_empty() { "none".to_string() } else { known.join(", ") };
                self.error(
                    &name.span(),
                    format!("unknown material `{}` (the scene's materials: {known})", name.get_ref()),
                )
            })?,
            None => *default_material.get_or_insert_with(|| {
                materials.push(Material { name: "default".to_string(), ..Material::default() });
                materials.len() - 1
            }),
        };
        let transform = match &o.transform {
            Some(steps) => self.transform(steps)?,
            None => None,
        };
        Ok(Object { shape: self.shape(spec)?, material, transform })
    }

    fn shape(&mut self, spec: &Spanned<ObjectSpec>) -> Result<Shape, SceneError> {
        let (whole, o) = (spec.span(), spec.get_ref());
        let kind = o.kind.get_ref().as_str();
        let Some(allowed) = shape_keys(kind) else {
            return Err(
                self.error(&o.kind.span(), format!("unknown object type `{kind}`, expected {SHAPES}"))
            );
        };
        let present = [
            ("center", span_of(&o.center)),
            ("radius", span_of(&o.radius)),
            ("normal", span_of(&o.normal)),
            ("offset", span_of(&o.offset)),
            ("min", span_of(&o.min)),
            ("max", span_of(&o.max)),
            ("vertices", span_of(&o.vertices)),
            ("normals", span_of(&o.normals)),
            ("file", span_of(&o.file)),
            ("subdivisions", span_of(&o.subdivisions)),
            ("major", span_of(&o.major)),
            ("minor", span_of(&o.minor)),
            ("segments", span_of(&o.segments)),
        ];
        let what = format!("a {kind}");
        self.only(&what, &present, allowed)?;
        Ok(match kind {
            "sphere" => {
                let center = self.vec3(self.need(&o.center, "center", &what, &whole)?, "center")?;
                let r = self.need(&o.radius, "radius", &what, &whole)?;
                let radius = self.float(r, "radius")?;
                if radius <= 0.0 {
                    return Err(self.error(&r.span(), format!("radius must be > 0, found {radius}")));
                }
                Shape::Sphere { center, radius }
            }
            "plane" => {
                let n = self.need(&o.normal, "normal", &what, &whole)?;
                let normal = self.vec3(n, "normal")?;
                let offset = self.float(self.need(&o.offset, "offset", &what, &whole)?, "offset")?;
                let unit = self.at(&n.span(), checks::unit(normal, "normal"))?;
                let offset = offset / normal.length();
                if !offset.is_finite() {
                    return Err(self.error(&n.span(), "normal is too short to divide the offset by"));
                }
                Shape::Plane { normal: unit, offset }
            }
            "box" => {
                let min = self.vec3(self.need(&o.min, "min", &what, &whole)?, "min")?;
                let max_spec = self.need(&o.max, "max", &what, &whole)?;
                let max = self.vec3(max_spec, "max")?;
                if !min.cmple(max).all() {
                    return Err(self.error(
                        &max_spec.span(),
                        format!(
                            "max must be ≥ min in every coordinate, found min {} max {}",
                            show(min),
                            show(max)
                        ),
                    ));
                }
                Shape::Box { min, max }
            }
            "polygon" => {
                let v = self.need(&o.vertices, "vertices", &what, &whole)?;
                let vertices = self.points(v, "vertices")?;
                self.at(&v.span(), checks::check_polygon(&vertices))?;
                Shape::Polygon { vertices }
            }
            "triangle" => {
                let v = self.need(&o.vertices, "vertices", &what, &whole)?;
                let vertices = self.three(v, "vertices")?;
                self.at(&v.span(), checks::check_triangle(vertices))?;
                let normals = match &o.normals {
                    None => None,
                    Some(n) => {
                        let normals = self.three(n, "normals")?;
                        let unit = |i: usize| checks::unit(normals[i], &format!("normal {i}"));
                        Some(self.at(&n.span(), (|| Ok([unit(0)?, unit(1)?, unit(2)?]))())?)
                    }
                };
                Shape::Triangle { vertices, normals }
            }
            "mesh" => {
                let file = self.need(&o.file, "file", &what, &whole)?;
                let mesh = checks::mesh(&mut self.meshes, self.dir, file.get_ref())
                    .map_err(|e| self.error(&file.span(), format!("mesh file `{}`: {e}", file.get_ref())))?;
                Shape::Mesh(mesh)
            }
            "icosphere" => {
                let subdivisions = match &o.subdivisions {
                    None => 2,
                    Some(s) => match *s.get_ref() {
                        n @ 0..=6 => n as u32,
                        n => {
                            return Err(
                                self.error(&s.span(), format!("subdivisions must be in 0..=6, found {n}"))
                            );
                        }
                    },
                };
                Shape::Mesh(Arc::new(Mesh::icosphere(subdivisions)))
            }
            "torus" => {
                let major = o.major.as_ref().map_or(Ok(1.0), |m| self.float(m, "major"))?;
                let minor = o.minor.as_ref().map_or(Ok(0.25), |m| self.float(m, "minor"))?;
                if !(0.0 < minor && minor < major) {
                    let span = span_of(&o.minor).or(span_of(&o.major)).unwrap_or(whole);
                    return Err(self.error(
                        &span,
                        format!("a torus needs 0 < minor < major, found major {major}, minor {minor}"),
                    ));
                }
                let (m, n) = match &o.segments {
                    None => (48, 24),
                    Some(s) => match s.get_ref()[..] {
                        [m @ 3..=1024, n @ 3..=1024] => (m as u32, n as u32),
                        _ => {
                            return Err(self.error(
                                &s.span(),
                                format!(
                                    "segments must be [major, minor] with each in 3..=1024, found {:?}",
                                    s.get_ref()
                                ),
                            ));
                        }
                    },
                };
                Shape::Mesh(Arc::new(Mesh::torus(major, minor, m, n)))
            }
            "cylinder" => Shape::Cylinder,
            _ => Shape::Cone,
        })
    }

    /// A list of points `[[x, y, z], …]`.
    fn points(&self, v: &Spanned<Vec<Nums>>, key: &str) -> Result<Vec<Vec3>, SceneError> {
        v.get_ref().iter().map(|p| self.vec3(p, key)).collect()
    }

    /// Exactly three points.
    fn three(&self, v: &Spanned<Vec<Nums>>, key: &str) -> Result<[Vec3; 3], SceneError> {
        let points = self.points(v, key)?;
        <[Vec3; 3]>::try_from(points).map_err(|p| {
            self.error(&v.span(), format!("{key} must be 3 points [[x, y, z], …], found {}", p.len()))
        })
    }

    /// world_from_object = M₁·M₂·…·Mₙ; `None` for an empty list.
    fn transform(&self, steps: &Spanned<Vec<Spanned<StepSpec>>>) -> Result<Option<Transform>, SceneError> {
        if steps.get_ref().is_empty() {
            return Ok(None);
        }
        let mut world_from_object = Mat4::IDENTITY;
        for step in steps.get_ref() {
            world_from_object *= self.step(step)?;
        }
        Transform::new(world_from_object).map(Some).ok_or_else(|| {
            self.error(
                &steps.span(),
                "the transform is not invertible (the steps multiply to a singular matrix)",
            )
        })
    }

    fn step(&self, spec: &Spanned<StepSpec>) -> Result<Mat4, SceneError> {
        let s = spec.get_ref();
        let present = [
            ("translate", span_of(&s.translate)),
            ("scale", span_of(&s.scale)),
            ("rotate_x", span_of(&s.rotate_x)),
            ("rotate_y", span_of(&s.rotate_y)),
            ("rotate_z", span_of(&s.rotate_z)),
            ("rotate", span_of(&s.rotate)),
            ("matrix", span_of(&s.matrix)),
        ];
        let found: Vec<&str> = present.iter().filter(|(_, s)| s.is_some()).map(|(k, _)| *k).collect();
        if found.len() != 1 {
            return Err(self.error(
                &spec.span(),
                format!(
                    "a transform step holds exactly one of translate, scale, rotate_x, rotate_y, rotate_z, \
                     rotate or matrix, found {}",
                    if found.is_empty() { "none".to_string() } else { found.join(" and ") }
                ),
            ));
        }
        if let Some(t) = &s.translate {
            return Ok(Mat4::from_translation(self.vec3(t, "translate")?));
        }
        if let Some(scale) = &s.scale {
            let factors = match scale.get_ref() {
                ScaleSpec::Uniform(f) => {
                    let f = self.float(&Spanned::new(scale.span(), *f), "scale")?;
                    Vec3::splat(f)
                }
                ScaleSpec::Axes(axes) => self.vec3(&Spanned::new(scale.span(), axes.clone()), "scale")?,
            };
            return self.at(&scale.span(), checks::scale(factors));
        }
        if let Some(angle) = &s.rotate_x {
            return Ok(Mat4::from_rotation_x(radians(self.float(angle, "rotate_x")?)));
        }
        if let Some(angle) = &s.rotate_y {
            return Ok(Mat4::from_rotation_y(radians(self.float(angle, "rotate_y")?)));
        }
        if let Some(angle) = &s.rotate_z {
            return Ok(Mat4::from_rotation_z(radians(self.float(angle, "rotate_z")?)));
        }
        if let Some(r) = &s.rotate {
            let axis = self.direction(&r.get_ref().axis, "axis")?;
            let angle = self.float(&r.get_ref().angle, "angle")?;
            return Ok(Mat4::from_axis_angle(axis, radians(angle)));
        }
        let m = s.matrix.as_ref().expect("exactly one step key is present");
        let numbers = m.get_ref();
        if numbers.len() != 16 {
            let found = numbers.len();
            return Err(
                self.error(&m.span(), format!("matrix must be 16 numbers, row by row, found {found}"))
            );
        }
        let mut rows = [0.0; 16];
        for (row, &x) in rows.iter_mut().zip(numbers) {
            *row = checks::finite(x).ok_or_else(|| {
                self.error(
                    &m.span(),
                    format!("matrix must hold {}, found {x}", checks::finite_words(&[x, x])),
                )
            })?;
        }
        self.at(&m.span(), checks::affine_from_rows(&rows))
    }
}

#[cfg(test)]
#[path = "toml_tests.rs"]
mod tests;
