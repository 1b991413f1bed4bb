//! What one measurement says: a row of a pair's table (a variant, on a case,
//! in a precision: its time and its errors), and the report of one run.

use serde::{Deserialize, Serialize};

use super::timing::Timing;

/// The trades measured, each a table of the report (and a plot for the
/// render sweeps).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Pair {
    Sphere,
    Triangle,
    Box,
    Offset,
    Refraction,
    GlassSphere,
    Scale,
    LookAt,
    Spp,
    Depth,
    Weight,
    Bvh,
}

impl Pair {
    /// Every pair, in the order of the report.
    pub const ALL: [Pair; 12] = [
        Pair::Sphere,
        Pair::Triangle,
        Pair::Box,
        Pair::Offset,
        Pair::Refraction,
        Pair::GlassSphere,
        Pair::Scale,
        Pair::LookAt,
        Pair::Spp,
        Pair::Depth,
        Pair::Weight,
        Pair::Bvh,
    ];

    /// The name of the pair in file names and JSON.
    pub fn key(self) -> &'static str {
        match self {
            Pair::Sphere => "sphere",
            Pair::Triangle => "triangle",
            Pair::Box => "box",
            Pair::Offset => "offset",
            Pair::Refraction => "refraction",
            Pair::GlassSphere => "glass_sphere",
            Pair::Scale => "scale",
            Pair::LookAt => "look_at",
            Pair::Spp => "spp",
            Pair::Depth => "depth",
            Pair::Weight => "weight",
            Pair::Bvh => "bvh",
        }
    }

    /// The table's title.
    pub fn title(self) -> &'static str {
        match self {
            Pair::Sphere => "Ray–sphere: algebraic vs geometric vs stable (lecture 02)",
            Pair::Triangle => "Ray–triangle: Cramer vs Möller–Trumbore vs watertight (lecture 03)",
            Pair::Box => "Ray–box: six planes vs textbook slabs vs slabs with 1 + 2γ₃ (lecture 03)",
            Pair::Offset => {
                "Shadow-ray origins: scaled offset vs fixed ε on t vs fixed ε along n (lecture 06)"
            }
            Pair::Refraction => {
                "Refraction: lecture 07's refract vs strict TIR test vs Snell through the sines"
            }
            Pair::GlassSphere => {
                "Refracted rays through a glass sphere of radius 1e-5: scaled offset vs fixed ε (lectures 06, 07)"
            }
            Pair::Scale => {
                "Non-uniform scale to 1e-3 : 1e3: (M⁻¹)ᵀ vs M for normals, world t vs renormalised direction \
                 (lecture 04)"
            }
            Pair::LookAt => "Look-at: lecture 01's look_at vs plain Gram–Schmidt without the parallel test",
            Pair::Spp => "Samples per pixel (lecture 10)",
            Pair::Depth => "Ray-tree depth (lecture 08)",
            Pair::Weight => "Ray-tree weight cut-off (lecture 08)",
            Pair::Bvh => "BVH vs brute force (lectures 09 and 04)",
        }
    }

    /// What the table measures and against which ground truth.
    pub fn about(self) -> &'static str {
        match self {
            Pair::Sphere => {
                "A sphere of radius 1 at distance D along random directions, rays from the unit ball around \
                 the world origin aimed at random points of the disc of radius 1.5 around the centre. Ground \
                 truth: the roots in f64 polished by Newton steps on a double-double residual. Wrong hit/miss \
                 over all rays (rays within 10⁻⁹ of the silhouette in the reference are left out), and over \
                 the rays whose line passes farther than ε·D from the silhouette (nearer, rounding o − c \
                 alone can tip the verdict in any method); |Δt| in ulp of t over rays passing within 0.5 of \
                 the centre. Fails: wrong hit/miss clear of the silhouette > 0.2 % or max |Δt| > 4 ulp."
            }
            Pair::Triangle => {
                "Rays from inside closed meshes aimed exactly at every vertex and at three points of every \
                 edge; each must hit some triangle (brute force over the mesh). A leak is a ray that hits \
                 none. Time: one ray–triangle test. Fails: any leak."
            }
            Pair::Box => {
                "Integer coordinates / 16 (exact in f32 and f64), boxes flat along an axis one time in \
                 eight; rays with zero direction components (+0 or −0) and origins on slab planes; rays \
                 aimed exactly at faces, edges and corners (direction scaled by an odd 3–999, so the target is met \
                 at an inexact t); generic rays. Ground truth: exact rational arithmetic. slabs_textbook is \
                 the slab test without the 1 + 2γ₃ widening, dividing by d. Fails: a false miss or a NaN."
            }
            Pair::Offset => {
                "A sphere of radius r seen from cameras 2–10 r away; from each hit a shadow ray toward a \
                 directional light. Acne: on the lit side (N·L > 0) the sphere cannot shadow itself, so any \
                 hit is a self-hit. Leaks (radius 10⁻⁴ only): on the dark side (N·L < −0.05) the ray must \
                 enter the ball; a ray that finds nothing is a light leak. Time: offset plus shadow ray. \
                 Fails: any acne, or leaks above 1 %."
            }
            Pair::Refraction => {
                "Unit i onto unit n, η = η_i/η_t. Critical angle: random planes and azimuths, θ_c ± 0.001° \
                 for η = 1.33, 1.5, 2.4 (|sin²θ_t − 1| ≥ 3·10⁻⁵, far beyond rounding). Normal incidence: \
                 i = −n for random unit n (rounding leaves |i·n| a few ε either side of 1), η from 1/2.4 to \
                 2.4. Ground truth: Snell's law in f64 on the rounded i and n. sin²θ_t rounds to 1: \
                 cos θ_i = k/64 and η where (η·η)(1 − cos²θ_i) is exactly 1 in the precision (lecture 07's \
                 construction, six axis orientations): θ_t = 90°, no transmitted ray, so a returned ray along \
                 the surface (t·n ≥ 0) is wrong. strict_tir: no clamp of cos θ_i, TIR only when sin²θ_t > 1; \
                 via_sines: sin θ_i = √(1 − cos²θ_i) unclamped, TIR when η·sin θ_i > 1. Time: one call. \
                 Fails: any NaN, wrong TIR decision or t·n ≥ 0, or an angle error above 1.7·10⁻³ rad (0.1°)."
            }
            Pair::GlassSphere => {
                "A glass sphere (ior 1.5) of radius r = 10⁻⁵ at the origin, eyes at random directions and \
                 distances (2–10 r, or 0.1), rays aimed within 0.95 r of the centre. Entry by lecture 02's \
                 stable sphere, lecture 07's interface and refract; then the refracted ray starts at each \
                 variant's origin (lecture 06) and lecture 02's sphere finds the exit. Ground truth: the same \
                 path in f64 (the exit is the end of the chord). Wrong: no hit from inside, or an exit more \
                 than 0.1 r from the truth. The fixed 10⁻⁴ is ten radii: it jumps past the sphere (t) or \
                 out of it (normal). Time: offset plus exit ray. Fails: any wrong exit."
            }
            Pair::Scale => {
                "The unit sphere placed by S(1e-3, 1, 1e3), alone, rotated, or moved to (5, −2, 300), and by \
                 the milder S(0.5, 1, 2). Normals: at random points, lecture 04's normal_to_world ((M⁻¹)ᵀ from \
                 the inverse) against M·n normalised; truth: the cofactor matrix of M (∝ (M⁻¹)ᵀ) in f64 with \
                 error-free products. Hits: rays from 2–4 object radii aimed within 0.5 of the centre (in \
                 object space), lecture 04's hit_transformed (lecture 02's sphere in object space) against the \
                 same with the object-space direction renormalised (whose t is in object units); truth: the \
                 root in f64 on the rounded ray and matrix. Time: one normal, or one hit. Fails: a normal more \
                 than 10⁻⁴ rad off, a miss, or a relative t error above 10⁻² (the object-space origin carries \
                 ε·|M⁻¹|·|M's translation|: 6·10⁻⁴ in f32 at (5, −2, 300) with the 1e-3 axis)."
            }
            Pair::LookAt => {
                "Cameras whose up is exactly parallel to the view (views along the axes with up ± that axis, \
                 random views with up a multiple of the view, zero up); up within δ = 10⁻³ … 3·10⁻⁶ rad of \
                 the view (half the views within 10⁻² of −z, half random); and views near −z with up +y (eye 10⁻²–10⁻⁸ off the z axis). A camera \
                 refused (Err) is right for a parallel up. Orthonormality error of a returned basis: the \
                 largest of ||u|−1|, ||v|−1|, ||w|−1|, |u·v|, |v·w|, |w·u|, |u×v − w| and |w − ŵ| (ŵ the f64 \
                 unit eye − at). gram_schmidt: w, u = up × w, v = w × u, normalised, no parallel test. Time: \
                 one call. Fails: a NaN basis, or an orthonormality error above 10⁻⁶."
            }
            Pair::Spp => {
                "Lecture 10's checker-aliasing scene, jittered samples, box filter. Error: mean FLIP against \
                 the converged reference (many more jittered samples per pixel). Time: one render, both cores."
            }
            Pair::Depth => {
                "Lecture 08's Whitted scene, weight cut-off 0 (only the depth stops the tree). Error: mean \
                 FLIP against depth 16, weight 0."
            }
            Pair::Weight => {
                "Lecture 08's Whitted scene, depth 16 (only the weight stops the tree). Error: mean FLIP \
                 against depth 16, weight 0."
            }
            Pair::Bvh => {
                "The same render with lecture 09's BVH (built in every run) and with lecture 04's brute \
                 force: time, and the pixels that differ (none: the answers are the same, bit for bit)."
            }
        }
    }

    /// The unit of the time column.
    pub fn time_unit(self) -> &'static str {
        match self {
            Pair::Sphere | Pair::Triangle | Pair::Box | Pair::Offset => "ns/test",
            Pair::Refraction | Pair::GlassSphere | Pair::Scale | Pair::LookAt => "ns/call",
            Pair::Spp | Pair::Depth | Pair::Weight | Pair::Bvh => "ms/render",
        }
    }

    /// True for the render sweeps that are plotted (error against time).
    pub fn plotted(self) -> bool {
        matches!(self, Pair::Spp | Pair::Depth | Pair::Weight)
    }
}

/// One variant on one case in one precision.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Row {
    pub pair: Pair,
    /// The conditions, e.g. `D = 1e5`, `icosphere(3)`.
    pub case: String,
    /// The method or setting, e.g. `algebraic`, `spp 16`.
    pub variant: String,
    /// `f32` or `f64`.
    pub precision: String,
    /// Per test or per render, in the pair's [`Pair::time_unit`].
    pub time: Timing,
    /// The errors, each with its name and unit in the name (`wrong hit/miss %`).
    pub metrics: Vec<(String, f64)>,
    /// The row shows a failure by the pair's stated criterion.
    pub fails: bool,
    /// On the Pareto front of its plot (the render sweeps only).
    pub pareto: bool,
}

impl Row {
    /// The value of metric `name`, if the row has it.
    pub fn metric(&self, name: &str) -> Option<f64> {
        self.metrics.iter().find(|(n, _)| n == name).map(|&(_, v)| v)
    }
}

/// Everything one precision measured: the rows and the machine's noise.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Report {
    pub precision: String,
    /// The fixed loop of [`super::timing::machine_noise`], ns per iteration.
    pub noise: Timing,
    pub rows: Vec<Row>,
}

/// The name of the precision this binary was built with.
pub fn own_precision() -> &'static str {
    if size_of::<raylab::Float>() == 8 { "f64" } else { "f32" }
}
