//! The exercises on a picture's path at one pixel: each function of a student's lecture that a
//! stage's picture depends on there, called by the check in the order a mistake spreads (the
//! sampling before the eye ray, a light's falloff before the light, Lambert before one light's
//! shading, one light's before the sum), with what it returned. When a picture differs and its
//! geometry matches, the judge compares the student's calls at a differing pixel of the report's
//! grid with the reference's, blessed beside the snapshot (`S.calls.json`, `S.final.calls.json`),
//! and the first call that differs names the exercise (`images::check_image`).
//!
//! Stages 05, 06, 07, 08 and 10 have calls; the others' pictures are explained by their geometry
//! (02–04, 09) or their rays (01). Each call's inputs are the student's own earlier values, so the
//! calls agree up to the first exercise that is wrong, and that one is named, not what it feeds.

use serde::{Deserialize, Serialize};

/// One call on the path: the exercise (`05/lambert`), where on the path (`light 1`), and what it
/// returned as numbers (a vector's components, a colour's channels, a flag as 0 or 1), rounded to
/// six significant digits (the blessed file's precision). A number that is not finite is NaN
/// (JSON's `null` in the blessed file): a comparison takes every such number as equal to any
/// other (an infinite distance, a directional light's, and a NaN alike).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Call(pub String, pub String, pub Vec<f64>);

fn numbers<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Vec<f64>, D::Error> {
    Ok(Vec::<Option<f64>>::deserialize(d)?.into_iter().map(|x| x.unwrap_or(f64::NAN)).collect())
}

/// The calls at the report's grid of pixels ([`crate::trees::grid`], row by row), as blessed:
/// each distinct (exercise, where) once in `labels`, each call as its label's index and values.
#[derive(Debug, Serialize, Deserialize)]
pub struct GridCalls {
    pub grid: u32,
    pub width: u32,
    pub height: u32,
    labels: Vec<(String, String)>,
    calls: Vec<Vec<(usize, Values)>>,
}

/// A call's numbers, NaN read back from `null`.
#[derive(Debug, Serialize, Deserialize)]
struct Values(#[serde(deserialize_with = "numbers")] Vec<f64>);

impl GridCalls {
    /// The calls of each grid pixel of a `width × height` picture, in grid order.
    pub fn new(width: u32, height: u32, pixels: Vec<Vec<Call>>) -> Self {
        let mut labels: Vec<(String, String)> = Vec::new();
        let mut calls = Vec::new();
        for pixel in pixels {
            let mut indexed = Vec::new();
            for Call(exercise, at, values) in pixel {
                let label = (exercise, at);
                let index = labels.iter().position(|l| *l == label).unwrap_or_else(|| {
                    labels.push(label);
                    labels.len() - 1
                });
                indexed.push((index, Values(values)));
            }
            calls.push(indexed);
        }
        Self { grid: crate::trees::GRID, width, height, labels, calls }
    }

    /// The calls of the `index`th grid pixel; `None` past the grid or where a label is missing.
    pub fn pixel(&self, index: usize) -> Option<Vec<Call>> {
        let calls = self.calls.get(index)?;
        calls
            .iter()
            .map(|(label, values)| {
                let (exercise, at) = self.labels.get(*label)?;
                Some(Call(exercise.clone(), at.clone(), values.0.clone()))
            })
            .collect()
    }
}

/// At most this many characters of a label, and numbers of a value, of the student's process
/// are shown in a cause.
const SHOWN_CHARS: usize = 80;
const SHOWN_NUMBERS: usize = 16;

/// A value is off when it differs by more than this, relative to the larger of 1 and the
/// reference's value: six printed digits keep 10⁻⁵, the f32 and f64 builds agree to ~10⁻⁵ on the
/// lecture scenes at the grid's pixels, and the catalogued mistakes are off by 10⁻² or more.
pub const TOLERANCE: f64 = 1e-3;

/// The shadow ray's offset is compared in units of ε·(|p|₁ + |o|₁) (the book's rule: 8 along
/// the normal) to within one unit: the f32 origin is rounded to half an ulp of each coordinate,
/// up to ½ unit, and f64's ε is f32's / 2²⁹, so only a unit of the precision it runs in is
/// the same in both; a fixed 10⁻⁴ offset, the wrong side or none are 8 units off or more.
const OFFSET_TOLERANCE: f64 = 1.0;

/// Whether `yours` differs from the reference's `expected` in a call of `exercise`.
fn off(exercise: &str, expected: f64, yours: f64) -> bool {
    match (expected.is_finite(), yours.is_finite()) {
        (true, true) if exercise == "06/offset_origin" => (yours - expected).abs() > OFFSET_TOLERANCE,
        (true, true) => (yours - expected).abs() > TOLERANCE * expected.abs().max(1.0),
        (e, y) => e != y,
    }
}

/// Where the student's `yours` first leaves the reference's `expected`: the exercise, and the
/// sentence that says how. `None` when every call agrees.
///
/// `yours` comes from the student's process: what it says is shown cut short (a label to
/// [`SHOWN_CHARS`] characters, values to the first [`SHOWN_NUMBERS`]), so that a forged value
/// cannot fill the verdict's text.
pub fn first_difference(expected: &[Call], yours: &[Call]) -> Option<(String, String)> {
    let show = |values: &[f64]| {
        let shown: Vec<String> = values.iter().take(SHOWN_NUMBERS).map(|v| format!("{v}")).collect();
        let more = if values.len() > SHOWN_NUMBERS { ", …" } else { "" };
        format!("({}{more})", shown.join(", "))
    };
    let cut = |text: &str| -> String {
        let mut cut: String = text.chars().take(SHOWN_CHARS).collect();
        if cut.len() < text.len() {
            cut.push('…');
        }
        cut
    };
    for (i, e) in expected.iter().enumerate() {
        let Some(y) = yours.get(i) else {
            return Some((e.0.clone(), format!("your path ends before {} ({})", e.0, e.1)));
        };
        if y.0 == PANICKED {
            return Some((e.0.clone(), format!("{} ({}) panics: {}", e.0, e.1, cut(&y.1))));
        }
        if (&e.0, &e.1) != (&y.0, &y.1) {
            return Some((
                e.0.clone(),
                format!(
                    "the reference's path calls {} ({}) where yours calls {} ({})",
                    e.0,
                    e.1,
                    cut(&y.0),
                    cut(&y.1)
                ),
            ));
        }
        if e.2.len() != y.2.len() || e.2.iter().zip(&y.2).any(|(a, b)| off(&e.0, *a, *b)) {
            return Some((
                e.0.clone(),
                format!(
                    "{} ({}) returns {} where the reference's returns {}",
                    e.0,
                    e.1,
                    show(&y.2),
                    show(&e.2)
                ),
            ));
        }
    }
    None
}

/// The calls `walk` makes into a trail (a stage's, at one pixel: `stages::calls`); `None` where
/// it makes none.
///
/// A call that panics (an exercise not started, or a bug) ends the calls there, recorded as a
/// call of [`PANICKED`] with the panic's message: it is caught, and not the check's outcome (the
/// panic hook lets it pass, [`probing`]), since the calls only explain a picture already failed.
pub fn record(walk: impl FnOnce(&mut Trail) -> Option<()>) -> Option<Vec<Call>> {
    let mut trail = Trail::default();
    PROBING.set(true);
    let walked = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| walk(&mut trail)));
    PROBING.set(false);
    match walked {
        Ok(walked) => walked.map(|()| trail.0),
        Err(payload) => {
            let message = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_owned())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "a panic without a message".to_owned());
            trail.0.push(Call(PANICKED.to_owned(), message, Vec::new()));
            Some(trail.0)
        }
    }
}

/// The exercise of the call that records a panic on the path: its `at` is the panic's message.
pub const PANICKED: &str = "panicked";

thread_local! {
    static PROBING: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Whether this thread is making the calls on a picture's path: a panic now is caught there and
/// is not the check's outcome (`main`'s panic hook asks).
pub fn probing() -> bool {
    PROBING.get()
}

/// Rounds to six significant digits, as the blessed files hold them (`+ 0.0`: no negative zero).
fn rounded(x: f64) -> f64 {
    if x.is_finite() { format!("{x:.5e}").parse::<f64>().map_or(x, |r| r + 0.0) } else { f64::NAN }
}

/// What a call returns, as numbers.
pub trait Numbers {
    fn numbers(&self) -> Vec<f64>;
}

impl Numbers for raylab::Float {
    fn numbers(&self) -> Vec<f64> {
        vec![f64::from(*self)]
    }
}

impl Numbers for raylab::Vec3 {
    fn numbers(&self) -> Vec<f64> {
        self.to_array().iter().flat_map(Numbers::numbers).collect()
    }
}

impl Numbers for raylab::Vec2 {
    fn numbers(&self) -> Vec<f64> {
        self.to_array().iter().flat_map(Numbers::numbers).collect()
    }
}

impl Numbers for bool {
    fn numbers(&self) -> Vec<f64> {
        vec![if *self { 1.0 } else { 0.0 }]
    }
}

impl<T: Numbers> Numbers for [T] {
    fn numbers(&self) -> Vec<f64> {
        self.iter().flat_map(Numbers::numbers).collect()
    }
}

/// `None` as no numbers at all: a refraction with none differs from one with a direction by its
/// length.
impl<T: Numbers> Numbers for Option<T> {
    fn numbers(&self) -> Vec<f64> {
        self.as_ref().map(Numbers::numbers).unwrap_or_default()
    }
}

/// The calls as they are made, in order.
#[derive(Default)]
pub struct Trail(Vec<Call>);

impl Trail {
    /// Records a call of `exercise` (`05/lambert`), made `at` (`light 0`), that returned `value`.
    pub fn push(&mut self, exercise: &str, at: impl Into<String>, value: &(impl Numbers + ?Sized)) {
        let values = value.numbers().into_iter().map(rounded).collect();
        self.0.push(Call(exercise.to_owned(), at.into(), values));
    }
}

/// At most this many samples of a pattern are recorded: enough to show their order and place.
pub const SAMPLES_SHOWN: usize = 8;

#[cfg(test)]
mod tests {
    use super::*;

    fn call(exercise: &str, at: &str, values: &[f64]) -> Call {
        Call(exercise.into(), at.into(), values.to_vec())
    }

    #[test]
    fn the_first_call_that_differs_is_named_not_what_it_feeds() {
        let expected = [
            call("05/illuminate", "light 0", &[0.0, 1.0, 0.0, 2.0, 1.0, 1.0, 1.0]),
            call("05/lambert", "light 0", &[0.5]),
            call("05/shade_light", "light 0", &[0.25, 0.25, 0.25]),
        ];
        assert_eq!(first_difference(&expected, &expected), None);
        // Lambert off by 0.1: named, though shade_light differs too.
        let mut yours = expected.to_vec();
        yours[1].2 = vec![0.4];
        yours[2].2 = vec![0.2, 0.2, 0.2];
        let (exercise, how) = first_difference(&expected, &yours).unwrap();
        assert_eq!(exercise, "05/lambert");
        assert_eq!(how, "05/lambert (light 0) returns (0.4) where the reference's returns (0.5)");
        // Within the tolerance, relative to the larger of 1 and the value: 2 + 1.9·10⁻³ agrees,
        // 2 + 2.1·10⁻³ does not; 0.5 + 0.9·10⁻³ agrees, 0.5 + 1.1·10⁻³ does not.
        let mut near = expected.to_vec();
        near[0].2[3] = 2.0019;
        near[1].2 = vec![0.5009];
        assert_eq!(first_difference(&expected, &near), None);
        near[0].2[3] = 2.0021;
        assert_eq!(first_difference(&expected, &near).unwrap().0, "05/illuminate");
        near[0].2[3] = 2.0;
        near[1].2 = vec![0.5011];
        assert_eq!(first_difference(&expected, &near).unwrap().0, "05/lambert");
    }

    #[test]
    fn numbers_that_are_not_finite_agree_with_each_other_only() {
        let expected = [call("05/illuminate", "light 0", &[f64::NAN])];
        assert_eq!(first_difference(&expected, &[call("05/illuminate", "light 0", &[f64::NAN])]), None);
        let finite = [call("05/illuminate", "light 0", &[1e30])];
        assert!(first_difference(&expected, &finite).is_some());
        assert!(first_difference(&finite, &expected).is_some());
        // An infinity is rounded to NaN, as the blessed file holds it.
        assert!(rounded(f64::INFINITY).is_nan());
    }

    #[test]
    fn a_path_that_leaves_the_reference_s_or_ends_early_is_named_where_it_leaves() {
        let expected = [
            call("07/mirror_direction", "the mirror ray", &[0.0, 1.0, 0.0]),
            call("08/trace_ray", "c", &[1.0]),
        ];
        let other = [call("07/interface", "the surface crossed", &[1.0]), call("08/trace_ray", "c", &[1.0])];
        let (exercise, how) = first_difference(&expected, &other).unwrap();
        assert_eq!(exercise, "07/mirror_direction");
        assert!(how.contains("where yours calls 07/interface"), "{how}");
        // A forged label is shown cut short.
        let forged = [call(&"x".repeat(500), "c", &[1.0]), call("08/trace_ray", "c", &[1.0])];
        let (_, how) = first_difference(&expected, &forged).unwrap();
        assert!(how.len() < 300 && how.contains(&format!("{}…", "x".repeat(80))), "{how}");
        let (exercise, how) = first_difference(&expected, &expected[..1]).unwrap();
        assert_eq!(exercise, "08/trace_ray");
        assert!(how.starts_with("your path ends before 08/trace_ray"), "{how}");
        // A call that panicked is named as the reference's call at its place.
        let panicked =
            [expected[0].clone(), call(PANICKED, "not yet implemented: 08/trace_ray: Book §8.2", &[])];
        let (exercise, how) = first_difference(&expected, &panicked).unwrap();
        assert_eq!(exercise, "08/trace_ray");
        assert_eq!(how, "08/trace_ray (c) panics: not yet implemented: 08/trace_ray: Book §8.2");
        // A refraction with no direction against one with a direction: the lengths differ.
        let none = [call("07/refract", "t", &[])];
        assert!(first_difference(&[call("07/refract", "t", &[0.0, 0.0, -1.0])], &none).is_some());
    }

    #[test]
    fn six_significant_digits_and_no_negative_zero() {
        assert_eq!(rounded(0.123_456_789), 0.123_457);
        assert_eq!(rounded(-123_456.789), -123_457.0);
        assert_eq!(rounded(-0.0).to_bits(), 0.0f64.to_bits());
    }
}
