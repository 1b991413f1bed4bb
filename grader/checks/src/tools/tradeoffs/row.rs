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
    Spp,
    Depth,
    Weight,
    Bvh,
}

impl Pair {
    /// Every pair, in the order of the report.
    pub const ALL: [Pair; 8] = [
        Pair::Sphere,
        Pair::Triangle,
        Pair::Box,
        Pair::Offset,
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
