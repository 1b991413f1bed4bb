//! `grader render SCENE -o OUT.png`: any TOML or MIT 6.837 scene, drawn by a
//! stage (`--stage NN`: what lecture NN's pictures show, with the lectures up
//! to NN only; by default the scene's own lecture's, else the complete tracer
//! of stage 10, with the flags that override its `[render]` table), its AOVs,
//! statistics and the ray tree of one pixel. An exercise not done yet is
//! named, not a panic.

use std::path::PathBuf;

use clap::ValueEnum;
use l06_shadows::ShadowMode;
use l08_ray_tree::TraceSettings;
use l10_textures_sampling::{Filter, Pattern};
use raylab::{Float, Scene};

use crate::lectures::l10::tracer::{self as shade, Aov, Sampling};

#[derive(clap::Args)]
pub struct RenderArgs {
    /// The scene file (`.toml`, or any other name for the 6.837 format).
    scene: PathBuf,
    /// Where to write the image (PNG, or OpenEXR for depth and normal AOVs).
    #[arg(short, long, default_value = "out.png")]
    output: PathBuf,
    /// Image size WxH (overrides the scene's).
    #[arg(long, value_parser = parse_size)]
    size: Option<(u32, u32)>,
    /// Write an arbitrary output variable instead of the shaded image.
    #[arg(long, value_enum)]
    aov: Option<Aov>,
    /// Print ray statistics.
    #[arg(long)]
    stats: bool,
    /// With --stats: print them as JSON.
    #[arg(long, requires = "stats")]
    json: bool,
    /// The deepest level of the ray tree (6.837's -bounces) [default: the scene's `depth`, else 5].
    #[arg(long)]
    depth: Option<u32>,
    /// The smallest contribution a ray may carry to be traced (6.837's -weight) [default: the
    /// scene's `weight`, else 0.01].
    #[arg(long)]
    weight: Option<Float>,
    /// Shadow rays per area light and shaded point, 1 to 4096 [default: the scene's
    /// `area_samples`, else 16].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=4096))]
    samples: Option<u32>,
    /// Eye rays per pixel, 1 to 1024 [default: the scene's `spp`, else 1].
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    spp: Option<u32>,
    /// Where a pixel's eye rays go [default: jittered with more than one, else the centre].
    #[arg(long, value_enum)]
    pattern: Option<PatternArg>,
    /// How a pixel weighs its eye rays [default: box].
    #[arg(long, value_enum)]
    filter: Option<FilterArg>,
    /// Trace no shadow rays.
    #[arg(long)]
    no_shadows: bool,
    /// Transparent objects filter the light by their transparent colour instead of blocking it
    /// [default: the scene's `transparent_shadows`, else off].
    #[arg(long)]
    transparent_shadows: bool,
    /// Split transparent surfaces between reflection and refraction by the exact Fresnel reflectance.
    #[arg(long)]
    fresnel: bool,
    /// Print the ray tree of pixel X,Y (0,0 is the top left).
    #[arg(long, value_parser = parse_pixel)]
    tree: Option<(u32, u32)>,
    /// With --tree: also write that pixel's ray tree in 3D over the scene, an HTML page that
    /// works offline (drag to orbit, shift-drag to pan, the wheel to zoom).
    #[arg(long, requires = "tree")]
    view: Option<PathBuf>,
    /// Render even when the scene asks for more work or memory than the budget
    /// (`RAY_BUDGET` rays, `IMAGE_BUDGET` bytes of image).
    #[arg(long)]
    allow_large: bool,
    /// The stage that draws, 01–10: what lecture NN's pictures show, with the lectures up to NN
    /// only [default: the scene's own lecture's, for a scene of lectures/NN-*/scenes/; else 10,
    /// the complete tracer]. Before 10 the complete tracer's flags (--depth, --spp, …) do not
    /// apply.
    #[arg(long, value_parser = parse_stage)]
    stage: Option<String>,
}

/// A stage, the first's to the final one's.
fn parse_stage(s: &str) -> Result<String, String> {
    match crate::stages::stage(s) {
        Some(stage) => Ok(stage.lecture.to_owned()),
        None => Err(format!("expected a stage from {FIRST_STAGE} to {FINAL_STAGE}, found {s:?}")),
    }
}

/// The stage a scene is drawn by when none is asked for: its lecture's, for a scene of
/// `lectures/NN-*/scenes/` (what that lecture's pictures show, from the week it is done), else
/// the complete tracer's. Chosen by where the scene is, not by what passes: the same command
/// draws the same picture every week, and names what is missing when it cannot.
fn own_stage(scene: &std::path::Path) -> String {
    let path = scene.canonicalize().unwrap_or_else(|_| scene.to_owned());
    let parts: Vec<String> =
        path.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect();
    let lecture = parts.windows(4).rev().find_map(|w| match w {
        [lectures, folder, scenes, _] if lectures == "lectures" && scenes == "scenes" => {
            folder.get(..2).filter(|n| parse_stage(n).is_ok()).map(str::to_owned)
        }
        _ => None,
    });
    lecture.unwrap_or_else(|| FINAL_STAGE.to_owned())
}

use crate::stages::{FINAL_STAGE, FIRST_STAGE};

/// The most rays a render may cast without `--allow-large`: 2·10⁹, minutes of
/// work on a laptop's cores (the lecture scenes cast under 10⁷, the 6.837
/// scenes under 10⁸ at their own sizes).
pub const RAY_BUDGET: f64 = 2e9;

/// The most memory the image of a render may take without `--allow-large`:
/// 1 GiB (a 9,000 × 9,000 image in f32; the 16384 × 16384 the format allows
/// takes 3 GiB).
pub const IMAGE_BUDGET: f64 = (1u64 << 30) as f64;

/// The most rays a render of `scene` may cast, an upper bound: pixels × eye
/// rays per pixel × the nodes of a full ray tree (1 + b + b² + … + b^depth,
/// b = 1 or 2 when some material reflects and/or transmits, 0 when none does)
/// × (1 + the shadow rays of a shaded point: one per light, `area_samples`
/// per area light). An AOV casts the eye rays only.
pub fn ray_bound(scene: &Scene, settings: &TraceSettings, sampling: Sampling, aov: Option<Aov>) -> f64 {
    let eye = scene.width as f64 * scene.height as f64 * sampling.spp as f64;
    if aov.is_some() {
        return eye;
    }
    let reflects = scene.materials.iter().any(|m| m.reflective.max_element() > 0.0);
    let transmits = scene.materials.iter().any(|m| m.transparent.max_element() > 0.0);
    let branching = f64::from(u8::from(reflects) + u8::from(transmits));
    let nodes: f64 = (0..=settings.max_depth.min(64)).map(|k| branching.powi(k as i32)).sum();
    let shadow: f64 = if settings.shadows {
        scene.lights.iter().map(|l| if l.kind.is_area() { settings.area_samples as f64 } else { 1.0 }).sum()
    } else {
        0.0
    };
    eye * nodes * (1.0 + shadow)
}

/// Refuses a render whose ray bound or image size is over budget, saying
/// both figures and what lowers them.
fn within_budget(scene: &Scene, rays: f64) -> Result<(), String> {
    let bytes = scene.width as f64 * scene.height as f64 * size_of::<raylab::Color>() as f64;
    if rays > RAY_BUDGET {
        return Err(format!(
            "this render may cast up to {rays:.1e} rays, more than the {RAY_BUDGET:.0e} allowed by default: \
             lower --size, --spp, --samples or --depth (or the scene's [render] table), or pass --allow-large"
        ));
    }
    if bytes > IMAGE_BUDGET {
        return Err(format!(
            "a {}×{} image takes {:.1} GiB, more than the {:.0} GiB allowed by default: lower --size, or \
             pass --allow-large",
            scene.width,
            scene.height,
            bytes / (1u64 << 30) as f64,
            IMAGE_BUDGET / (1u64 << 30) as f64
        ));
    }
    Ok(())
}

impl RenderArgs {
    /// The scene's own settings ([`shade::scene_settings`]), overridden by the flags given.
    fn settings(&self, scene: &Scene) -> TraceSettings {
        let own = shade::scene_settings(scene);
        TraceSettings {
            max_depth: self.depth.unwrap_or(own.max_depth),
            min_weight: self.weight.unwrap_or(own.min_weight),
            shadows: !self.no_shadows,
            shadow_mode: if self.transparent_shadows { ShadowMode::Transmissive } else { own.shadow_mode },
            area_samples: self.samples.unwrap_or(own.area_samples),
            fresnel: self.fresnel,
        }
    }

    /// The scene's sampling ([`shade::scene_sampling`]), overridden by the flags given.
    fn sampling(&self, scene: &Scene) -> Sampling {
        let own = shade::scene_sampling(scene);
        let spp = self.spp.unwrap_or(own.spp);
        let pattern = match self.pattern {
            Some(PatternArg::Regular) => Pattern::Regular,
            Some(PatternArg::Jittered) => Pattern::Jittered,
            Some(PatternArg::Stratified) => Pattern::Stratified,
            None if spp > 1 => Pattern::Jittered,
            None => Pattern::Regular,
        };
        let filter = match self.filter {
            Some(FilterArg::Box) => Filter::Box,
            Some(FilterArg::Tent) => Filter::Tent,
            None => own.filter,
        };
        Sampling { spp, pattern, filter }
    }
}

/// Sample patterns (lecture 10).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum PatternArg {
    Regular,
    Jittered,
    Stratified,
}

/// Pixel filters (lecture 10).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
enum FilterArg {
    Box,
    Tent,
}

fn parse_pixel(s: &str) -> Result<(u32, u32), String> {
    let (x, y) = s.split_once(',').ok_or_else(|| format!("expected X,Y, e.g. 100,75, found {s:?}"))?;
    let parse = |v: &str| v.trim().parse::<u32>().map_err(|_| format!("expected a pixel index, found {v:?}"));
    Ok((parse(x)?, parse(y)?))
}

pub fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) =
        s.split_once(['x', 'X']).ok_or_else(|| format!("expected WxH, e.g. 320x240, found {s:?}"))?;
    let parse = |v: &str| match v.trim().parse::<u32>() {
        Ok(n) if (1..=16384).contains(&n) => Ok(n),
        _ => Err(format!("expected a size from 1 to 16384, found {v:?}")),
    };
    Ok((parse(w)?, parse(h)?))
}

fn is_png(path: &std::path::Path) -> bool {
    path.extension().is_some_and(|e| e.eq_ignore_ascii_case("png"))
}

/// A depth or normal image made viewable, for a PNG: a normal n shows as the
/// 8-bit colour (n + 1)/2 (the usual normal-map colours), a depth as grey
/// from light (the nearest hit) to dark (the 95th percentile of the depths,
/// so that a plane running to the horizon does not wash out the rest);
/// nothing hit is black either way.
fn viewable(image: &raylab::Image, aov: Aov) -> raylab::Image {
    use raylab::color::srgb_to_linear;
    let mut depths: Vec<Float> =
        image.pixels.iter().map(|c| c.x).filter(|d| *d > 0.0 && d.is_finite()).collect();
    depths.sort_by(Float::total_cmp);
    let near = depths.first().copied().unwrap_or(0.0);
    let far = depths.get(depths.len() * 95 / 100).copied().unwrap_or(1.0);
    let span = (far - near).max(Float::MIN_POSITIVE);
    let pixels = image
        .pixels
        .iter()
        .map(|&c| {
            let shown = match aov {
                _ if c == raylab::Color::ZERO => c,
                Aov::Normal => (c + raylab::Color::ONE) * 0.5,
                _ => raylab::Color::splat(1.0 - 0.85 * ((c.x - near) / span).clamp(0.0, 1.0)),
            };
            // The PNG stores sRGB: encode so that the file holds these values themselves.
            shown.map(srgb_to_linear)
        })
        .collect();
    raylab::Image::from_pixels(image.width, image.height, pixels)
}

/// The exit status of a render stopped by Ctrl-C: 128 + SIGINT, as a shell reports it.
pub const INTERRUPTED: i32 = 130;

/// On Ctrl-C, stops the render at once with a line that says so and that
/// `output` was not written (the image is written only when it is whole), and
/// exits with [`INTERRUPTED`]; the progress bar's line is ended first.
fn stop_on_ctrl_c(output: &std::path::Path) {
    let output = output.display().to_string();
    // Refused only when a handler is set already, which this process never does twice.
    let _ = ctrlc::set_handler(move || {
        eprintln!("\ninterrupted: the render was stopped, {output} not written");
        std::process::exit(INTERRUPTED);
    });
}

/// `grader render`: a `todo!()` met on the way is a message naming the exercise (the panic hook
/// that finds where it stopped is the process's: set here, in the tool's own process, not in
/// [`render_to_file`], which tests call side by side).
pub fn render(args: &RenderArgs) -> Result<(), String> {
    stop_on_ctrl_c(&args.output);
    until_todo(&args.stage(), || render_to_file(args))
}

impl RenderArgs {
    /// The stage asked for, else the scene's own ([`own_stage`]).
    fn stage(&self) -> String {
        self.stage.clone().unwrap_or_else(|| own_stage(&self.scene))
    }
}

/// Loads, checks against the budget, renders and writes: `grader render` but Ctrl-C and the
/// message for a `todo!()`.
pub(crate) fn render_to_file(args: &RenderArgs) -> Result<(), String> {
    let mut scene = raylab::scene::load(&args.scene).map_err(|e| e.to_string())?;
    if let Some((w, h)) = args.size {
        scene.width = w;
        scene.height = h;
    }
    let stage = args.stage();
    if let Some((x, y)) = args.tree.filter(|(x, y)| *x >= scene.width || *y >= scene.height) {
        return Err(format!("pixel ({x}, {y}) is outside the {}×{} image", scene.width, scene.height));
    }
    if stage == FINAL_STAGE { traced(args, &scene) } else { staged(args, &scene, &stage) }
}

/// The complete tracer's render (stage 10), with every flag.
fn traced(args: &RenderArgs, scene: &Scene) -> Result<(), String> {
    let settings = args.settings(scene);
    if !args.allow_large {
        within_budget(scene, ray_bound(scene, &settings, args.sampling(scene), args.aov))?;
    }
    if let Some(pixel) = args.tree {
        let (color, tree) = shade::pixel_tree(scene, pixel, &settings)?;
        println!(
            "pixel ({}, {}): colour ({:.3}, {:.3}, {:.3})\n{tree}",
            pixel.0, pixel.1, color.x, color.y, color.z
        );
        if let Some(file) = &args.view {
            let title =
                format!("the ray tree of pixel ({}, {}) of {}", pixel.0, pixel.1, args.scene.display());
            let mut view = crate::view3d::View::new(scene, &title);
            view.add_tree(scene, "yours", pixel, &crate::lectures::l08::stage::tree_node(&tree));
            std::fs::write(file, view.to_html()?).map_err(|e| format!("{}: {e}", file.display()))?;
        }
    }
    let (image, stats) = shade::render_scene(scene, args.aov, &settings, args.sampling(scene))?;
    write(args, &image, &stats)
}

/// The flags only the complete tracer reads, the first one given.
fn tracer_flag(args: &RenderArgs) -> Option<&'static str> {
    [
        (args.depth.is_some(), "--depth"),
        (args.weight.is_some(), "--weight"),
        (args.samples.is_some(), "--samples"),
        (args.spp.is_some(), "--spp"),
        (args.pattern.is_some(), "--pattern"),
        (args.filter.is_some(), "--filter"),
        (args.no_shadows, "--no-shadows"),
        (args.transparent_shadows, "--transparent-shadows"),
        (args.fresnel, "--fresnel"),
    ]
    .into_iter()
    .find_map(|(given, flag)| given.then_some(flag))
}

/// Stage `stage`'s render of `scene` (before the complete tracer): its picture, an AOV through
/// its intersections, or a pixel's rays as it draws them.
fn staged(args: &RenderArgs, scene: &Scene, stage: &str) -> Result<(), String> {
    if let Some(flag) = tracer_flag(args) {
        return Err(format!(
            "{flag} sets the complete tracer (stage {FINAL_STAGE}); stage {stage} draws as lecture {stage}'s \
             pictures do: leave {flag} out, or add --stage {FINAL_STAGE}"
        ));
    }
    if !args.allow_large {
        let settings = shade::scene_settings(scene);
        within_budget(scene, ray_bound(scene, &settings, shade::scene_sampling(scene), args.aov))?;
    }
    if let Some(pixel) = args.tree {
        let tree = crate::stages::trees(stage, scene, &[pixel])
            .and_then(|mut trees| trees.pop())
            .ok_or_else(|| format!("stage {stage} is not in this build"))?;
        // Stage 08 traces as the complete tracer does, and prints as it prints; the earlier
        // stages' rays have no colour of their own to print.
        match crate::stages::pixel_tree(stage, scene, pixel) {
            Some(traced) => println!("pixel ({}, {}): {traced}", pixel.0, pixel.1),
            None => println!("pixel ({}, {}), stage {stage}:\n{tree}", pixel.0, pixel.1),
        }
        if let Some(file) = &args.view {
            let title = format!(
                "the rays of pixel ({}, {}) of {}, stage {stage}",
                pixel.0,
                pixel.1,
                args.scene.display()
            );
            let mut view = crate::view3d::View::new(scene, &title);
            view.add_tree(scene, "yours", pixel, &tree);
            std::fs::write(file, view.to_html()?).map_err(|e| format!("{}: {e}", file.display()))?;
        }
    }
    let (image, stats) = match args.aov {
        None => {
            let (image, stats) = raylab::stats::measure(|| crate::stages::render(stage, scene));
            (image?, stats)
        }
        Some(aov) => {
            let objects = crate::stages::intersector(stage, scene).ok_or_else(|| {
                format!(
                    "stage {stage} finds no hits (it draws the camera's rays): --aov needs stage 02 or later"
                )
            })?;
            let camera = l01_transforms::Camera::from_scene(&scene.camera, scene.width, scene.height)
                .map_err(|e| e.to_string())?;
            let (w, h, objects) = (scene.width, scene.height, objects.as_ref());
            raylab::stats::measure(|| match aov {
                Aov::Id => l02_ray_casting::object_id_image(&camera, &objects, w, h),
                Aov::Depth => l02_ray_casting::depth_image(&camera, &objects, w, h),
                Aov::Normal => l02_ray_casting::normal_image(&camera, &objects, w, h),
            })
        }
    };
    write(args, &image, &stats)
}

/// Runs a render, turning a `todo!()` of an exercise not done yet into a message that names it
/// and the stages that draw without it: a student renders from week 1 on, and a scene that
/// needs more than the lectures done says so instead of panicking.
fn until_todo(stage: &str, render: impl FnOnce() -> Result<(), String>) -> Result<(), String> {
    use std::sync::{Arc, Mutex};
    let place: Arc<Mutex<String>> = Arc::default();
    let previous = std::panic::take_hook();
    let seen = place.clone();
    std::panic::set_hook(Box::new(move |info| {
        if let (Ok(mut seen), Some(at)) = (seen.lock(), info.location()) {
            *seen = format!("{}:{}", at.file(), at.line());
        }
    }));
    let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(render));
    std::panic::set_hook(previous);
    let payload = match result {
        Ok(rendered) => return rendered,
        Err(payload) => payload,
    };
    let message = payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_default();
    let place = place.lock().map(|p| p.clone()).unwrap_or_default();
    // A stub's panic: "not yet implemented: NN/function: Book §N.M …".
    let todo = message.strip_prefix("not yet implemented: ").and_then(|rest| rest.split(':').next());
    match todo.filter(|id| id.len() > 3 && id.as_bytes()[2] == b'/') {
        Some(id) => {
            let (lecture, function) = id.split_at(2);
            let earlier = if lecture > FIRST_STAGE && lecture <= stage {
                format!(
                    ", or draw it with the stage of a lecture before {lecture} that you have done (--stage NN)"
                )
            } else {
                String::new()
            };
            Err(format!(
                "stage {stage} draws this scene with lecture {lecture}'s `{}`, which is not started yet \
                 (todo!() at {place}): do it first{earlier}",
                &function[1..]
            ))
        }
        None => Err(format!("the render panicked at {place}: {message}")),
    }
}

/// Writes the image (a viewable PNG of an AOV, or its EXR) and prints the statistics asked for.
fn write(args: &RenderArgs, image: &raylab::Image, stats: &raylab::stats::RayStats) -> Result<(), String> {
    let write = match args.aov {
        Some(aov @ (Aov::Depth | Aov::Normal)) if is_png(&args.output) => {
            viewable(image, aov).save_png(&args.output)
        }
        Some(Aov::Depth | Aov::Normal) => image.save_exr(&args.output),
        _ => image.save_png(&args.output),
    };
    write.map_err(|e| e.to_string())?;
    if args.stats {
        if args.json {
            println!("{}", stats.to_json());
        } else {
            print!("{stats}");
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tools::{Tool, Tools};
    use clap::Parser;
    use std::path::Path;

    /// A scene whose `[render]` table sets every key.
    const OWN: &str = "[render]\ndepth = 0\nweight = 0.5\ntransparent_shadows = true\narea_samples = 4\n\
                       [camera]\ntype = \"perspective\"\neye = [0, 0, 5]\nat = [0, 0, 0]\nfovy = 40\n";

    /// The settings `grader render` uses for the scene `text` with the command-line `flags`.
    fn settings(text: &str, flags: &[&str]) -> TraceSettings {
        let scene = raylab::scene::parse_toml(text, Path::new("s.toml")).unwrap_or_else(|e| panic!("{e}"));
        let argv = ["grader", "render", "s.toml"].into_iter().chain(flags.iter().copied());
        let Tool::Render(args) = Tools::try_parse_from(argv).unwrap_or_else(|e| panic!("{e}")).tool else {
            panic!("a render command");
        };
        args.settings(&scene)
    }

    #[test]
    fn the_scene_sets_what_the_flags_leave_and_the_defaults_the_rest() {
        let default = TraceSettings::default();
        let transmissive = ShadowMode::Transmissive;
        // The scene's own table, every key.
        let own = TraceSettings {
            max_depth: 0,
            min_weight: 0.5,
            shadow_mode: transmissive,
            area_samples: 4,
            ..default
        };
        assert_eq!(settings(OWN, &[]), own);
        // Every flag given: the flags win.
        let flags = ["--depth", "3", "--weight", "0.25", "--samples", "9", "--no-shadows", "--fresnel"];
        let expected = TraceSettings {
            max_depth: 3,
            min_weight: 0.25,
            shadows: false,
            shadow_mode: transmissive,
            area_samples: 9,
            fresnel: true,
        };
        assert_eq!(settings(OWN, &flags), expected);
        // One flag: only that one changes.
        assert_eq!(settings(OWN, &["--samples", "64"]), TraceSettings { area_samples: 64, ..own });
        // No table, no flags: the defaults (6.837 files are always so); the flag turns on
        // transparent shadows, there being no flag to turn them off.
        let plain = &OWN[OWN.find("[camera]").unwrap()..];
        assert_eq!(settings(plain, &[]), default);
        assert_eq!(settings(plain, &["--transparent-shadows"]).shadow_mode, transmissive);
    }

    #[test]
    fn the_ray_bound_counts_pixels_eye_rays_tree_nodes_and_shadow_rays() {
        // 32×24 pixels, a point light and a rect light, a mirror: branching 1, depth 5 → 6 nodes.
        let text = "[image]\nwidth = 32\nheight = 24\n\
                    [camera]\ntype = \"perspective\"\neye = [0, 0, 5]\nat = [0, 0, 0]\nfovy = 40\n\
                    [[lights]]\ntype = \"point\"\nposition = [0, 5, 0]\ncolor = [1, 1, 1]\n\
                    [[lights]]\ntype = \"rect\"\ncorner = [0, 5, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]\ncolor = [1, 1, 1]\n\
                    [materials.m]\nreflective = [0.5, 0.5, 0.5]\n";
        let scene = raylab::scene::parse_toml(text, Path::new("s.toml")).unwrap_or_else(|e| panic!("{e}"));
        let one = Sampling { spp: 1, pattern: Pattern::Regular, filter: Filter::Box };
        let settings = TraceSettings { area_samples: 16, ..TraceSettings::default() };
        // 768 pixels × 1 × 6 nodes × (1 + 1 + 16) = 82,944.
        assert_eq!(ray_bound(&scene, &settings, one, None), 82_944.0);
        assert_eq!(ray_bound(&scene, &settings, one, Some(Aov::Depth)), 768.0);
        let no_shadows = TraceSettings { shadows: false, ..settings };
        assert_eq!(ray_bound(&scene, &no_shadows, one, None), 768.0 * 6.0);
        // The case: spp 1024 and 4096 area samples at 32×24: 1.9·10¹⁰ rays, refused.
        let heavy = TraceSettings { area_samples: 4096, ..settings };
        let many = Sampling { spp: 1024, ..one };
        let rays = ray_bound(&scene, &heavy, many, None);
        assert_eq!(rays, 768.0 * 1024.0 * 6.0 * 4098.0);
        let said = within_budget(&scene, rays).unwrap_err();
        assert!(said.contains("1.9e10 rays") && said.contains("--allow-large"), "{said}");
        // 16384 × 16384 pixels: 3 GiB of image in f32 (6 in f64), refused whatever the rays.
        let mut big = scene.clone();
        (big.width, big.height) = (16384, 16384);
        let said = within_budget(&big, 1.0).unwrap_err();
        assert!(said.starts_with("a 16384×16384 image takes"), "{said}");
        // Every lecture scene, and every 6.837 scene that loads, is within budget at its own size.
        let mut paths: Vec<_> =
            crate::scenes::scene_files(None).unwrap().into_iter().map(|f| f.scene).collect();
        let mit = crate::scenes::workspace_root().join("../shared/data/mit6837");
        match std::fs::read_dir(&mit) {
            Ok(entries) => paths.extend(entries.filter_map(|e| e.ok().map(|e| e.path()))),
            Err(_) => println!("SKIPPED the 6.837 scenes' budget: {} is absent", mit.display()),
        }
        let mut checked = 0;
        for path in paths.iter().filter(|p| p.extension().is_some_and(|e| e == "toml" || e == "txt")) {
            let Ok(scene) = raylab::scene::load(path) else { continue };
            let bound =
                ray_bound(&scene, &shade::scene_settings(&scene), shade::scene_sampling(&scene), None);
            assert!(within_budget(&scene, bound).is_ok(), "{}: {bound:e}", path.display());
            checked += 1;
        }
        println!("{checked} scenes within budget");
        assert!(checked >= 45, "{checked} scenes checked");
    }

    #[test]
    fn a_sample_count_outside_1_to_4096_is_refused() {
        for n in ["0", "4097", "-1", "many"] {
            assert!(Tools::try_parse_from(["grader", "render", "s.toml", "--samples", n]).is_err(), "{n}");
        }
        assert!(Tools::try_parse_from(["grader", "render", "s.toml", "--samples", "4096"]).is_ok());
    }
}
