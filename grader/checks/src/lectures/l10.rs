//! Lecture 10, textures and sampling: texture coordinates of spheres, planes and triangles,
//! checkerboards, bilinear image lookup, sampling patterns, filters and supersampling.

use crate::check::Meta;

declare_checks! {
    "l10";
    Meta::unit(
        "sphere_uv",
        "poles, the equator's axis points, the inverse of longitude and latitude, points off the sphere",
    ) => sphere_cases(sphere_uv),
    Meta::unit("plane_uv", "perpendicular and skew axes, and a point off the plane, by hand")
        => plane_cases(plane_uv),
    Meta::unit("triangle_uv", "the vertices' uvs at the corners, their mean at the centroid and on an edge")
        => triangle_cases(triangle_uv),
    Meta::unit(
        "checker",
        "alternation across cell edges, the floor at negative coordinates, half-open cells",
    ) => checker_cases(checker),
    Meta::unit("checker_3d", "a solid board alternating across each face of a cube, at two scales")
        => checker_3d_cases(checker_3d),
    Meta::unit(
        "bilinear",
        "pixel centres, halfway means, wrapping edges and tiles, v upward, on a 4 × 2 image",
    ) => bilinear_cases(bilinear),
    Meta::unit("filter_weight", "box and tent by hand, their rims, NaN, and both integrating to 1")
        => filter_cases(filter_weight),
    Meta::unit(
        "sample_offsets",
        "regular centres by hand; one jittered sample per cell; multi-jittered n-rooks; non-square counts",
    ) => sampling_cases(sample_offsets),
    Meta::unit(
        "render_supersampled",
        "one regular sample is 08's render; one primary ray per sample; a pixel under an edge converges to \
         its coverage, box and tent weighted",
    )
    .needs(&[
        "01/PerspectiveCamera::generate_ray",
        "01/OrthographicCamera::generate_ray",
        "02/hit_sphere_stable",
        "02/hit_plane",
        "03/hit_triangle",
        "08/trace_ray",
        "08/render",
        "10/sample_offsets",
        "10/filter_weight",
    ]) => supersampling_cases(render_supersampled),
}

#[cfg(feature = "l10")]
// Widening `Float` to f64 for exact comparisons is a cast in f32 builds and none in f64 ones.
#[allow(clippy::unnecessary_cast)]
mod code {
    use std::collections::HashSet;

    pub(super) use l01_transforms::Camera;
    pub(super) use l04_quadrics_transforms::BruteForce;
    pub(super) use l08_ray_tree::{TraceSettings, World};
    pub(super) use l10_textures_sampling::{
        Filter, Pattern, bilinear, checker, checker_3d, filter_weight, plane_uv, render_supersampled,
        sample_offsets, sphere_uv, triangle_uv,
    };
    use raylab::math::consts::{PI, TAU};
    use raylab::random::Rng;
    use raylab::scene::{self, Light, LightKind, Material, Object, Shape};
    use raylab::stats::{Counter, RayStats};
    use raylab::{Color, Float, Image, Scene, Vec2, Vec3};

    use crate::check::{CheckResult, Failure, ensure, fail, num, vec3};

    pub(super) type SphereUvFn = fn(Vec3) -> Vec2;
    pub(super) type PlaneUvFn = fn(Vec3, Vec3, Vec3, Vec3) -> Vec2;
    pub(super) type TriangleUvFn = fn(&[Vec2; 3], Float, Float) -> Vec2;
    pub(super) type CheckerFn = fn(Vec2, Float, Color, Color) -> Color;
    pub(super) type Checker3dFn = fn(Vec3, Float, Color, Color) -> Color;
    pub(super) type BilinearFn = fn(&Image, Vec2) -> Color;
    pub(super) type FilterFn = fn(Filter, Vec2) -> Float;
    pub(super) type SamplesFn = fn(Pattern, u32, &mut Rng) -> Vec<Vec2>;
    pub(super) type SupersampleFn =
        fn(&World, &Camera, u32, u32, &TraceSettings, u32, Pattern, Filter, u64) -> (Image, RayStats);

    const EPS: Float = Float::EPSILON;

    fn v3(x: Float, y: Float, z: Float) -> Vec3 {
        Vec3::new(x, y, z)
    }

    fn uv(u: Float, v: Float) -> Vec2 {
        Vec2::new(u, v)
    }

    fn show2(p: Vec2) -> String {
        format!("({}, {})", num(p.x), num(p.y))
    }

    fn near2(a: Vec2, b: Vec2, tolerance: Float) -> bool {
        (a - b).abs().max_element() <= tolerance
    }

    fn same_uv(case: &str, got: Vec2, expected: Vec2, tolerance: Float, cause: &str) -> Result<(), Failure> {
        let shown = if tolerance == 0.0 {
            format!("{} exactly", show2(expected))
        } else {
            format!("{} (± {tolerance:.1e})", show2(expected))
        };
        ensure(near2(got, expected, tolerance), case, shown, show2(got), cause)
    }

    const SPHERE_UV: &str = "u = ½ + atan2(−z, x)/2π, v = ½ + atan2(y, √(x² + z²))/π";

    pub(super) fn sphere_cases(sphere_uv: SphereUvFn) -> CheckResult {
        // Poles: atan2(±1, 0) = ±π/2, v = ½ ± ½ exactly; any u in [0, 1] there.
        for (p, v, name) in
            [(Vec3::Y, 1.0, "north pole (0, 1, 0)"), (v3(0.0, -1.0, 0.0), 0.0, "south pole (0, −1, 0)")]
        {
            let got = sphere_uv(p);
            let cause = if (got.y - (1.0 - v)).abs() <= 2.0 * EPS {
                "v grows upward: 0 at the south pole (−y), 1 at the north pole"
            } else {
                SPHERE_UV
            };
            ensure(
                (got.y - v).abs() <= 2.0 * EPS && (0.0..=1.0).contains(&got.x),
                format!("the {name}"),
                format!("v = {v} (± 2ε = {:.1e}), u in [0, 1]", 2.0 * EPS),
                show2(got),
                cause,
            )?;
        }
        // The equator (v = ½): longitude atan2(−z, x): +x → u = ½, +z → ¼, −z → ¾, −x → 0 (z = +0).
        // Two roundings (atan2, the sum): 2ε; allowed 4ε.
        for (p, u, name) in [
            (Vec3::X, 0.5, "+x"),
            (Vec3::Z, 0.25, "+z"),
            (-Vec3::Z, 0.75, "−z"),
            (v3(-1.0, 0.0, 0.0), 0.0, "−x (z = +0)"),
        ] {
            let got = sphere_uv(p);
            let case = format!("the equator's point {name}, {}", vec3(p));
            let cause = if (got.x - (1.0 - u)).abs() <= 4.0 * EPS && u != 0.5 {
                "seen from outside u grows to the right: atan2(−z, x), so +z (facing the viewer) is u = ¼"
            } else if (got.x - (u + 0.5).rem_euclid(1.0)).abs() <= 4.0 * EPS {
                "the seam is at −x: u = ½ + atan2(−z, x)/2π puts +x at u = ½"
            } else {
                SPHERE_UV
            };
            same_uv(&case, got, uv(u, 0.5), 4.0 * EPS, cause)?;
        }
        // A pole one ulp outside the sphere (a rounded hit point): acos(−y) is NaN there.
        let outside = v3(0.0, -(1.0 as Float).next_up(), 0.0);
        let got = sphere_uv(outside);
        ensure(
            got.is_finite() && got.y.abs() <= 2.0 * EPS,
            "the south pole one ulp outside the sphere, (0, −1 − ε, 0)",
            format!("v = 0 (± 2ε = {:.1e}), finite", 2.0 * EPS),
            show2(got),
            "use atan2(y, √(x² + z²)) for the latitude, not acos(y): a point a rounding off the sphere makes \
             acos (or asin) NaN",
        )?;
        // The inverse map, written from the definition: φ = 2π(u − ½), λ = π(v − ½),
        // p = (cos λ cos φ, sin λ, −cos λ sin φ); every (u, v) of a 9 × 9 grid comes back, at
        // radius 1, 3 and 1/7 (only the direction counts). sin, cos, atan2 and the products, a
        // few ulp each: 8ε; allowed 16ε.
        for i in 1..10 {
            for j in 1..10 {
                let (u, v) = (i as Float / 10.0, j as Float / 10.0);
                let (phi, lambda) = (TAU * (u - 0.5), PI * (v - 0.5));
                let p = v3(lambda.cos() * phi.cos(), lambda.sin(), -lambda.cos() * phi.sin());
                for s in [1.0, 3.0, 1.0 / 7.0] {
                    let case = format!("the point {} (radius {})", vec3(s * p), num(s));
                    let got = sphere_uv(s * p);
                    let cause = if s != 1.0 && near2(sphere_uv(p), uv(u, v), 16.0 * EPS) {
                        "only the direction of p matters: a point at radius 3 has the uv of p/3 (atan2 of \
                         ratios, or normalise p first)"
                    } else {
                        SPHERE_UV
                    };
                    same_uv(&case, got, uv(u, v), 16.0 * EPS, cause)?;
                }
            }
        }
        Ok("6 axis points, 243 grid points, a point off the sphere".into())
    }

    pub(super) fn plane_cases(plane_uv: PlaneUvFn) -> CheckResult {
        // Origin (1, 2, 3), perpendicular axes a = (2, 0, 0), b = (0, 0, −3): p = o + u·a + v·b by
        // construction, exact in floats.
        let (o, a, b) = (v3(1.0, 2.0, 3.0), v3(2.0, 0.0, 0.0), v3(0.0, 0.0, -3.0));
        let cause = "(u, v) with p = origin + u·a + v·b: for perpendicular axes u = d·a/|a|², v = d·b/|b|²";
        for (p, expected, name) in [
            (o, uv(0.0, 0.0), "the origin"),
            (o + a, uv(1.0, 0.0), "origin + a"),
            (o + b, uv(0.0, 1.0), "origin + b"),
            (o - 0.5 * a + 2.0 * b, uv(-0.5, 2.0), "origin − ½a + 2b"),
        ] {
            let got = plane_uv(p, o, a, b);
            let case = format!("plane through (1, 2, 3), axes a = (2, 0, 0), b = (0, 0, −3): {name}");
            let cause = if near2(got, expected * uv(2.0, 3.0), 4.0 * EPS) {
                "divide by the axis's squared length: the axes' lengths set the tile's size"
            } else {
                cause
            };
            same_uv(&case, got, expected, 4.0 * EPS, cause)?;
        }
        // 5 units off the plane along its normal: projected back.
        let got = plane_uv(o + a + 5.0 * Vec3::Y, o, a, b);
        same_uv(
            "plane through (1, 2, 3), axes (2, 0, 0), (0, 0, −3): 5 above origin + a",
            got,
            uv(1.0, 0.0),
            4.0 * EPS,
            "a point off the plane is projected along the normal: use dot products with the axes",
        )?;
        // Skew axes a = (1, 0, 0), b = (1, 1, 0): p = o + 2a + 3b = o + (5, 3, 0). Each axis
        // alone would give u = 5; the 2 × 2 solve gives (2, 3). Gram matrix [1 1; 1 2], det 1.
        let (o, a, b) = (v3(-1.0, 0.5, 2.0), Vec3::X, v3(1.0, 1.0, 0.0));
        let got = plane_uv(o + 2.0 * a + 3.0 * b, o, a, b);
        same_uv(
            "skew axes a = (1, 0, 0), b = (1, 1, 0), the point origin + 2a + 3b",
            got,
            uv(2.0, 3.0),
            8.0 * EPS,
            "for axes that are not perpendicular solve the 2 × 2 normal equations (Cramer): projecting on each \
             axis alone is wrong",
        )?;
        Ok("6 points".into())
    }

    pub(super) fn triangle_cases(triangle_uv: TriangleUvFn) -> CheckResult {
        let uvs = [uv(0.0, 0.0), uv(1.0, 0.25), uv(0.5, 1.0)];
        let cause = "uv = (1 − β − γ)·uv₀ + β·uv₁ + γ·uv₂: β weighs vertex 1 and γ vertex 2";
        // The vertices: weights 1 and 0, exact. The centroid: the mean (0.5, 5/12), 4ε. The edge
        // b–c midpoint (β = γ = ½): the mean of uv₁ and uv₂, exact.
        let third = 1.0 / 3.0;
        for (beta, gamma, expected, tolerance, name) in [
            (0.0, 0.0, uvs[0], 0.0, "vertex a (β = γ = 0)"),
            (1.0, 0.0, uvs[1], 0.0, "vertex b (β = 1)"),
            (0.0, 1.0, uvs[2], 0.0, "vertex c (γ = 1)"),
            (third, third, uv(0.5, 5.0 / 12.0), 4.0 * EPS, "the centroid (β = γ = ⅓)"),
            (0.5, 0.5, uv(0.75, 0.625), 0.0, "the midpoint of b–c (β = γ = ½)"),
        ] {
            let case = format!("vertex uvs (0, 0), (1, 0.25), (0.5, 1): {name}");
            same_uv(&case, triangle_uv(&uvs, beta, gamma), expected, tolerance, cause)?;
        }
        Ok("5 points".into())
    }

    const A: Color = Color::new(1.0, 1.0, 1.0);
    const B: Color = Color::new(0.0, 0.0, 0.0);

    fn name(c: Color) -> &'static str {
        if c == A {
            "a"
        } else if c == B {
            "b"
        } else {
            "neither a nor b"
        }
    }

    pub(super) fn checker_cases(checker: CheckerFn) -> CheckResult {
        // Scale 4: edges at multiples of ¼; cell (⌊4u⌋, ⌊4v⌋), a when the sum is even.
        for (u, v, expected, why) in [
            (0.2, 0.1, A, "cell (0, 0)"),
            (0.3, 0.1, B, "cell (1, 0)"),
            (0.3, 0.3, A, "cell (1, 1)"),
            (0.2, 0.3, B, "cell (0, 1)"),
            (0.25, 0.1, B, "on the edge u = ¼: the cell to the right, (1, 0)"),
            (0.6, 0.9, B, "cell (2, 3)"),
            (-0.1, 0.1, B, "⌊−0.4⌋ = −1: cell (−1, 0)"),
            (-0.3, 0.1, A, "⌊−1.2⌋ = −2: cell (−2, 0)"),
            (-0.1, -0.1, A, "cell (−1, −1)"),
            (0.1, -0.1, B, "cell (0, −1)"),
            (-0.25, 0.1, B, "on the edge u = −¼: cell (−1, 0)"),
        ] {
            let got = checker(uv(u, v), 4.0, A, B);
            let case = format!("checker of scale 4 at (u, v) = ({u}, {v}), {why}");
            // The colour truncation toward zero would give, to name that mistake.
            let truncated = if ((u * 4.0) as i64 + (v * 4.0) as i64).rem_euclid(2) == 1 { B } else { A };
            let cause = if got == truncated && truncated != expected {
                "use the floor, not truncation toward zero: (−0.4) as i64 is 0, so the cells either side of 0 \
                 get one colour (a double-width stripe)"
            } else if checker(uv(0.2, 0.1), 4.0, A, B) == B {
                "the cell (0, 0) and every cell with an even i + j is a"
            } else {
                "the cell is (⌊u·scale⌋, ⌊v·scale⌋); a when i + j is even, b when odd"
            };
            ensure(got == expected, case, name(expected), name(got), cause)?;
        }
        // Far and NaN coordinates: any of the two colours, never a panic (an overflowing sum).
        for (u, what) in [(1e30, "10³⁰"), (-1e30, "−10³⁰"), (Float::NAN, "NaN")] {
            let got = checker(uv(u, 0.1), 4.0, A, B);
            ensure(
                got == A || got == B,
                format!("checker of scale 4 at u = {what}"),
                "a or b",
                name(got),
                "never anything but a or b, whatever the coordinates",
            )?;
        }
        Ok("11 points, 3 far ones".into())
    }

    pub(super) fn checker_3d_cases(checker_3d: Checker3dFn) -> CheckResult {
        // Scale 1: cube (0, 0, 0) is a; across any one face (to −0.1 in that axis, cube −1) b;
        // across two faces a again, across three b; the positive neighbours first, where truncation
        // and the floor agree. Scale 2: cubes of side ½.
        for (p, scale, expected, why) in [
            (v3(0.5, 0.5, 0.5), 1.0, A, "cube (0, 0, 0)"),
            (v3(1.5, 0.5, 0.5), 1.0, B, "cube (1, 0, 0)"),
            (v3(0.5, 1.5, 0.5), 1.0, B, "cube (0, 1, 0)"),
            (v3(0.5, 0.5, 1.5), 1.0, B, "cube (0, 0, 1)"),
            (v3(-0.1, 0.5, 0.5), 1.0, B, "cube (−1, 0, 0)"),
            (v3(0.5, -0.1, 0.5), 1.0, B, "cube (0, −1, 0)"),
            (v3(0.5, 0.5, -0.1), 1.0, B, "cube (0, 0, −1)"),
            (v3(-0.1, -0.1, 0.5), 1.0, A, "cube (−1, −1, 0)"),
            (v3(-0.1, -0.1, -0.1), 1.0, B, "cube (−1, −1, −1)"),
            (v3(1.5, 2.5, 0.5), 1.0, B, "cube (1, 2, 0)"),
            (v3(0.6, 0.1, 0.1), 2.0, B, "scale 2: cube (1, 0, 0)"),
            (v3(0.6, 0.6, 0.1), 2.0, A, "scale 2: cube (1, 1, 0)"),
        ] {
            let got = checker_3d(p, scale, A, B);
            let case = format!("solid checker of scale {scale} at {}, {why}", vec3(p));
            let q = p * scale;
            let truncated = if (q.x as i64 + q.y as i64 + q.z as i64).rem_euclid(2) == 1 { B } else { A };
            let cause = if got == truncated && truncated != expected {
                "use the floor, not truncation toward zero: −0.1 is in cube −1, not 0"
            } else if scale != 1.0 {
                "the cube is (⌊x·scale⌋, ⌊y·scale⌋, ⌊z·scale⌋)"
            } else {
                "a when i + j + k is even (all three coordinates), b when odd"
            };
            ensure(got == expected, case, name(expected), name(got), cause)?;
        }
        Ok("12 points".into())
    }

    /// A 4 × 2 image whose pixel (i, j) is (i, j, 1): every value, every mean of two or four of
    /// them (multiples of ¼), and the centres u = (i + ½)/4, v = 1 − (j + ½)/2 are exact.
    fn ramp() -> Image {
        let pixels = (0..2).flat_map(|j| (0..4).map(move |i| v3(i as Float, j as Float, 1.0))).collect();
        Image::from_pixels(4, 2, pixels)
    }

    pub(super) fn bilinear_cases(bilinear: BilinearFn) -> CheckResult {
        let image = ramp();
        let centre = |i: u32, j: u32| uv((i as Float + 0.5) / 4.0, 1.0 - (j as Float + 0.5) / 2.0);
        // Pixel centres: fx = fy = 0 exactly, the pixel itself.
        for j in 0..2 {
            for i in 0..4 {
                let got = bilinear(&image, centre(i, j));
                let expected = image.get(i, j);
                if got == expected {
                    continue;
                }
                let case = format!(
                    "4 × 2 image, pixel (i, j) = (i, j, 1): the centre of pixel ({i}, {j}), uv {}",
                    show2(centre(i, j))
                );
                let cause = if got.y == 1.0 - expected.y && got.x == expected.x {
                    "v grows upward: row 0 (the top) is at v = 1 − ½/h, so y = (1 − v)·h − ½"
                } else if (got.x - expected.x).abs() == 0.5 {
                    "pixel centres are at (i + ½)/w: x = u·w − ½ (and y = (1 − v)·h − ½)"
                } else {
                    "x = u·w − ½, y = (1 − v)·h − ½; blend the four pixels around (x, y) by their fractions"
                };
                return Err(fail(case, vec3(expected), vec3(got), cause));
            }
        }
        // Halfway between centres: the means, exact. Between (1, 0) and (2, 0): u = ½, v = ¾;
        // rows 0 and 1 of column 3: u = ⅞, v = ½; among four: (½, ½); a quarter of the way from
        // (0, 0) to (1, 0): x = 0.25.
        let blend = "blend along x by fx = x − ⌊x⌋, then along y by fy: (1 − f)·left + f·right";
        for (p, expected, what) in [
            (uv(0.5, 0.75), v3(1.5, 0.0, 1.0), "halfway between pixels (1, 0) and (2, 0)"),
            (uv(0.875, 0.5), v3(3.0, 0.5, 1.0), "halfway between pixels (3, 0) and (3, 1)"),
            (uv(0.5, 0.5), v3(1.5, 0.5, 1.0), "amid pixels (1, 0), (2, 0), (1, 1), (2, 1)"),
            (uv(0.1875, 0.75), v3(0.25, 0.0, 1.0), "a quarter of the way from pixel (0, 0) to (1, 0)"),
        ] {
            let got = bilinear(&image, p);
            let case = format!("4 × 2 image, pixel (i, j) = (i, j, 1): uv {}, {what}", show2(p));
            ensure(got == expected, case, vec3(expected), vec3(got), blend)?;
        }
        // Wrapping: u = 0 is x = −½, between the last column (3) and the first: red 1.5; v = 0 and
        // v = 1 lie between the last row and the first: green ½; whole tiles away (negative ones
        // too) the same colours, exact for these dyadic values.
        let wrap = "the image repeats: take columns mod w and rows mod h with rem_euclid (−1 is the last), \
                    after reducing u and v mod 1";
        for (p, expected, what) in [
            (uv(0.0, 0.75), v3(1.5, 0.0, 1.0), "u = 0: between the last column and the first"),
            (uv(1.0, 0.75), v3(1.5, 0.0, 1.0), "u = 1: between the last column and the first"),
            (uv(0.125, 1.0), v3(0.0, 0.5, 1.0), "v = 1: between the last row and the first"),
            (uv(0.125, 0.0), v3(0.0, 0.5, 1.0), "v = 0: between the last row and the first"),
            (uv(0.0, 0.0), v3(1.5, 0.5, 1.0), "the corner (0, 0): all four corner pixels"),
            (
                centre(3, 1) + uv(3.0, -2.0),
                v3(3.0, 1.0, 1.0),
                "the centre of pixel (3, 1) three tiles right, two down",
            ),
            (
                centre(2, 0) - uv(1.0, 5.0),
                v3(2.0, 0.0, 1.0),
                "the centre of pixel (2, 0) one tile left, five up",
            ),
        ] {
            let got = bilinear(&image, p);
            let case = format!("4 × 2 image, pixel (i, j) = (i, j, 1): uv {}, {what}", show2(p));
            ensure(got == expected, case, vec3(expected), vec3(got), wrap)?;
        }
        // An empty image: black, no panic.
        let got = bilinear(&Image::new(0, 5), uv(0.3, 0.3));
        ensure(
            got == Color::ZERO,
            "an empty 0 × 5 image at (0.3, 0.3)",
            vec3(Color::ZERO),
            vec3(got),
            "an empty image gives black",
        )?;
        Ok("8 centres, 4 blends, 7 wrapped points, an empty image".into())
    }

    pub(super) fn filter_cases(filter_weight: FilterFn) -> CheckResult {
        let w = |f: Filter, x: Float, y: Float| filter_weight(f, uv(x, y));
        // Box: 1 on [−½, ½)², closed below and open above, 0 outside.
        for (x, y, expected, what) in [
            (0.0, 0.0, 1.0, "the centre"),
            (-0.5, 0.2, 1.0, "the lower edge x = −½ (closed)"),
            (0.2, -0.5, 1.0, "the lower edge y = −½ (closed)"),
            (0.5, 0.0, 0.0, "the upper edge x = ½ (open)"),
            (0.0, -0.7, 0.0, "outside, y = −0.7"),
            (0.49, 0.49, 1.0, "inside a corner"),
        ] {
            let got = w(Filter::Box, x, y);
            let cause = if x == 0.5 {
                "the box is half-open, −½ ≤ x < ½: neighbouring pixels' boxes must not overlap"
            } else {
                "the box weighs 1 inside the pixel, −½ ≤ x, y < ½, and 0 outside"
            };
            ensure(
                got == expected,
                format!("box filter at ({x}, {y}), {what}"),
                num(expected),
                num(got),
                cause,
            )?;
        }
        // Tent: (1 − |x|)(1 − |y|) clamped at 0 per factor; exact for these dyadic values.
        for (x, y, expected, what) in [
            (0.0, 0.0, 1.0, "the centre"),
            (0.5, -0.25, 0.375, "(1 − ½)(1 − ¼)"),
            (1.0, 0.0, 0.0, "the rim x = 1"),
            (-3.0, 0.5, 0.0, "beyond the rim, x = −3"),
            (-3.0, -3.0, 0.0, "beyond the rim in both, (−3, −3)"),
        ] {
            let got = w(Filter::Tent, x, y);
            let cause = if (got - 0.25).abs() <= EPS && x == 0.5 {
                "the tent is a product of two triangles, (1 − |x|)(1 − |y|), not 1 − |x| − |y|"
            } else if got != 0.0 && x.abs() >= 1.0 {
                "clamp each factor at 0 before multiplying, max(0, 1 − |x|)·max(0, 1 − |y|): beyond the rim \
                 (1 − |x|) is negative, and two negatives make a positive"
            } else {
                "tent: max(0, 1 − |x|)·max(0, 1 − |y|)"
            };
            ensure(
                got == expected,
                format!("tent filter at ({x}, {y}), {what}"),
                num(expected),
                num(got),
                cause,
            )?;
        }
        // NaN offsets weigh 0 (never NaN).
        for f in [Filter::Box, Filter::Tent] {
            let got = w(f, Float::NAN, 0.0);
            ensure(
                got == 0.0,
                format!("{f:?} filter at (NaN, 0)"),
                "0",
                num(got),
                "a NaN offset weighs 0: range tests are false for NaN, and max(NaN, 0) = 0",
            )?;
        }
        // Both integrate to 1: the midpoint rule on [−1, 1]² with 200 × 200 cells of side 0.01,
        // whose edges fall on ±½, 0 and ±1, where the box jumps and the tent bends, so each cell
        // is integrated exactly; what is left is rounding, ≤ 4ε of Float summed in f64. Allowed
        // 10⁻⁵, far below the error of a wrong filter (one row of cells is 0.01).
        let n = 200u32;
        let h = 2.0 / f64::from(n);
        for f in [Filter::Box, Filter::Tent] {
            let mut integral = 0.0f64;
            for i in 0..n {
                for j in 0..n {
                    let x = -1.0 + (f64::from(i) + 0.5) * h;
                    let y = -1.0 + (f64::from(j) + 0.5) * h;
                    integral += filter_weight(f, uv(x as Float, y as Float)) as f64 * h * h;
                }
            }
            ensure(
                (integral - 1.0).abs() <= 1e-5,
                format!("the {f:?} filter integrated over [−1, 1]² by the midpoint rule"),
                "1 (± 1e-5)",
                format!("{integral:.6}"),
                "a filter integrates to 1: box of side 1 and height 1; tent of half-width 1 and height 1",
            )?;
        }
        Ok("11 points, NaN, 2 integrals".into())
    }

    /// The grid cell of each sample in a cols × rows grid, by floor: exact for power-of-two grids.
    fn cells(samples: &[Vec2], cols: u32, rows: u32) -> HashSet<(i64, i64)> {
        samples
            .iter()
            .map(|p| ((p.x * cols as Float).floor() as i64, (p.y * rows as Float).floor() as i64))
            .collect()
    }

    fn show_samples(samples: &[Vec2]) -> String {
        let shown: Vec<String> = samples.iter().take(6).map(|p| show2(*p)).collect();
        let more =
            if samples.len() > 6 { format!(", … ({} in all)", samples.len()) } else { String::new() };
        format!("[{}{more}]", shown.join(", "))
    }

    pub(super) fn sampling_cases(sample_offsets: SamplesFn) -> CheckResult {
        // Regular, n = 4: the centres of the 2 × 2 cells, row by row; n = 1: the pixel centre.
        let mut rng = Rng::new(1);
        let expected: Vec<Vec2> =
            [(0.25, 0.25), (0.75, 0.25), (0.25, 0.75), (0.75, 0.75)].map(|(x, y)| uv(x, y)).to_vec();
        let got = sample_offsets(Pattern::Regular, 4, &mut rng);
        let cause = if got.len() == 4 && got.iter().zip(&expected).all(|(g, e)| *g == *e - Vec2::splat(0.25))
        {
            "the cells' centres, ((i + ½)/cols, (j + ½)/rows), not their corners"
        } else {
            "regular samples are the cells' centres ((i + ½)/cols, (j + ½)/rows), listed row by row (j outer, i inner)"
        };
        ensure(
            got == expected,
            "regular pattern, n = 4",
            show_samples(&expected),
            show_samples(&got),
            cause,
        )?;
        let got = sample_offsets(Pattern::Regular, 1, &mut rng);
        ensure(
            got == [Vec2::splat(0.5)],
            "regular pattern, n = 1",
            "[(0.5000, 0.5000)]",
            show_samples(&got),
            "one regular sample is the centre of the pixel",
        )?;
        ensure(
            rng == Rng::new(1),
            "regular patterns of 4 and 1 samples",
            "no random number drawn",
            "the generator advanced",
            "the regular pattern draws nothing from the generator",
        )?;
        // Every pattern: n samples in [0, 1)², one in each cell of the k × k grid (power-of-two
        // sizes: the cells by floor are exact). Multi-jittered also puts one in each of the n
        // columns [m/n, (m+1)/n) and each of the n rows.
        for pattern in [Pattern::Regular, Pattern::Jittered, Pattern::Stratified] {
            let mut rng = Rng::new(3);
            for n in [1u32, 4, 16, 64] {
                let k = n.isqrt();
                for _ in 0..10 {
                    let samples = sample_offsets(pattern, n, &mut rng);
                    let case = format!("{pattern:?} pattern, n = {n}");
                    ensure(
                        samples.len() == n as usize,
                        &case,
                        format!("{n} samples"),
                        samples.len(),
                        "n samples, one per cell",
                    )?;
                    let inside =
                        samples.iter().all(|p| (0.0..1.0).contains(&p.x) && (0.0..1.0).contains(&p.y));
                    ensure(
                        inside,
                        &case,
                        "every sample in [0, 1)²",
                        show_samples(&samples),
                        "keep each coordinate in its stratum with in_stratum(i, count, ξ): (i + ξ)/count can round up to \
                         the next one",
                    )?;
                    let occupied = cells(&samples, k, k).len();
                    ensure(
                        occupied == n as usize,
                        &case,
                        format!("one sample in each of the {k} × {k} cells"),
                        format!("{occupied} cells occupied: {}", show_samples(&samples)),
                        "one sample per cell: x = (i + ξ₁)/cols, y = (j + ξ₂)/rows for cell (i, j), not anywhere in \
                         the square",
                    )?;
                    if pattern == Pattern::Stratified {
                        let fine = cells(&samples, n, n);
                        let columns: HashSet<i64> = fine.iter().map(|c| c.0).collect();
                        let rows: HashSet<i64> = fine.iter().map(|c| c.1).collect();
                        ensure(
                            columns.len() == n as usize && rows.len() == n as usize,
                            &case,
                            format!("one sample in each of the {n} columns and {n} rows [m/n, (m+1)/n)"),
                            format!("{} columns and {} rows occupied", columns.len(), rows.len()),
                            "multi-jittered: cell (i, j) takes fine column i·rows + s and fine row j·cols + t, with s \
                             and t shuffled within each cell column and row (n-rooks)",
                        )?;
                    }
                    if pattern == Pattern::Regular {
                        break;
                    }
                }
            }
        }
        // Non-square counts on their cols × rows grid (cols ≥ rows), listed row by row: sample
        // k in cell (k mod cols, k div cols). 6 = 3 × 2, 8 = 4 × 2, 12 = 4 × 3, 7 = 7 × 1.
        let mut rng = Rng::new(4);
        for n in [6u32, 8, 12, 7] {
            let (cols, rows) = match n {
                6 => (3, 2),
                8 => (4, 2),
                12 => (4, 3),
                _ => (7, 1),
            };
            for pattern in [Pattern::Regular, Pattern::Jittered, Pattern::Stratified] {
                let samples = sample_offsets(pattern, n, &mut rng);
                let case = format!("{pattern:?} pattern, n = {n} ({cols} columns × {rows} rows)");
                ensure(
                    samples.len() == n as usize,
                    &case,
                    format!("{n} samples"),
                    samples.len(),
                    "n samples for any n",
                )?;
                for (k, p) in samples.iter().enumerate() {
                    let (i, j) = (k as u32 % cols, k as u32 / cols);
                    let ok = i as Float / cols as Float <= p.x
                        && p.x < (i + 1) as Float / cols as Float
                        && j as Float / rows as Float <= p.y
                        && p.y < (j + 1) as Float / rows as Float;
                    ensure(
                        ok,
                        &case,
                        format!("sample {k} in cell ({i}, {j}) of the {cols} × {rows} grid"),
                        show2(*p),
                        "n samples on grid(n): rows = the largest divisor of n not above √n, cols = n/rows, listed \
                         row by row",
                    )?;
                }
            }
        }
        // n = 0: nothing; the same generator state: the same samples.
        for pattern in [Pattern::Regular, Pattern::Jittered, Pattern::Stratified] {
            let got = sample_offsets(pattern, 0, &mut Rng::new(1));
            ensure(
                got.is_empty(),
                format!("{pattern:?} pattern, n = 0"),
                "no samples",
                show_samples(&got),
                "n = 0 gives no samples",
            )?;
            let (a, b) = (
                sample_offsets(pattern, 16, &mut Rng::new(99)),
                sample_offsets(pattern, 16, &mut Rng::new(99)),
            );
            ensure(
                a == b,
                format!("{pattern:?} pattern, n = 16, twice from Rng::new(99)"),
                show_samples(&a),
                show_samples(&b),
                "draw only from the rng given: the same state gives the same samples",
            )?;
        }
        Ok("3 patterns at 1, 4, 16, 64 and 4 non-square counts".into())
    }

    fn scene_of(camera: scene::Camera, size: (u32, u32), objects: Vec<Object>, lights: Vec<Light>) -> Scene {
        Scene {
            camera,
            width: size.0,
            height: size.1,
            background: Color::ZERO,
            ambient: Color::ONE,
            lights,
            materials: vec![Material { diffuse: Color::ONE, ..Material::default() }],
            objects,
            render: Default::default(),
        }
    }

    /// The white half-plane y < slope·x + intercept (z = 0) on black, seen by an orthographic
    /// camera from +z with a view 2 units high: the image is the square [−1, 1]², a 1 × 1 image
    /// one pixel of 2 × 2 units. No lights, white ambient: a sample is 1 on the half-plane and 0
    /// off it. The half-plane is a triangle reaching 100 units along the edge and 1000 below,
    /// covering everything below the edge in [−2, 2]² (the tent's reach).
    fn half_plane(slope: Float, intercept: Float) -> Scene {
        let edge = |x: Float| v3(x, slope * x + intercept, 0.0);
        let triangle =
            Shape::Triangle { vertices: [edge(-100.0), edge(100.0), v3(0.0, -1000.0, 0.0)], normals: None };
        let camera =
            scene::Camera::Orthographic { eye: v3(0.0, 0.0, 5.0), at: Vec3::ZERO, up: Vec3::Y, height: 2.0 };
        scene_of(camera, (1, 1), vec![Object { shape: triangle, material: 0, transform: None }], vec![])
    }

    /// Two lit spheres over a floor, 12 × 8, seen in perspective.
    fn spheres() -> Scene {
        let sphere = |x: Float, r: Float| Object {
            shape: Shape::Sphere { center: v3(x, 0.0, 0.0), radius: r },
            material: 0,
            transform: None,
        };
        let floor =
            Object { shape: Shape::Plane { normal: Vec3::Y, offset: -1.0 }, material: 0, transform: None };
        let light = Light {
            color: Color::splat(0.8),
            shadows: true,
            kind: LightKind::Directional { direction: v3(-1.0, -2.0, -1.0).normalize() },
        };
        let camera =
            scene::Camera::Perspective { eye: v3(0.0, 1.0, 6.0), at: Vec3::ZERO, up: Vec3::Y, fovy: 0.7 };
        let mut s = scene_of(camera, (12, 8), vec![sphere(-1.0, 0.9), sphere(1.2, 0.6), floor], vec![light]);
        s.ambient = Color::splat(0.1);
        s.background = Color::new(0.2, 0.3, 0.5);
        s
    }

    /// `render` of `s` at its own size through its own camera, brute force, default settings.
    fn rendered(
        render: SupersampleFn,
        s: &Scene,
        spp: u32,
        pattern: Pattern,
        filter: Filter,
        seed: u64,
    ) -> (Image, RayStats) {
        let camera =
            Camera::from_scene(&s.camera, s.width, s.height).expect("the check scenes have valid cameras");
        let objects = BruteForce::new(&s.objects);
        let world = World::new(s, &objects);
        render(&world, &camera, s.width, s.height, &TraceSettings::default(), spp, pattern, filter, seed)
    }

    /// The value a pixel of [`half_plane`] takes with the k × k regular samples and `filter`,
    /// computed here: offset d = (2u − 1)·r in pixels (r = ½ for the box, 1 for the tent), the sample at world (2dₓ, −2d_y) (the
    /// pixel is 2 units wide, y up in the world and down in pixels), covered when
    /// y < slope·x + intercept, weighted by the filter written out again (in f64).
    fn expected_coverage(k: u32, filter: Filter, r: f64, slope: f64, intercept: f64) -> (f64, f64) {
        let (mut covered, mut total, mut largest) = (0.0, 0.0, 0.0f64);
        for j in 0..k {
            for i in 0..k {
                let u = ((f64::from(i) + 0.5) / f64::from(k), (f64::from(j) + 0.5) / f64::from(k));
                let d = ((2.0 * u.0 - 1.0) * r, (2.0 * u.1 - 1.0) * r);
                let w = match filter {
                    Filter::Box => {
                        f64::from(u8::from((-0.5..0.5).contains(&d.0) && (-0.5..0.5).contains(&d.1)))
                    }
                    Filter::Tent => (1.0 - d.0.abs()).max(0.0) * (1.0 - d.1.abs()).max(0.0),
                };
                let (x, y) = (2.0 * d.0, -2.0 * d.1);
                if y < slope * x + intercept {
                    covered += w;
                }
                total += w;
                largest = largest.max(w);
            }
        }
        (covered / total, largest / total)
    }

    pub(super) fn supersampling_cases(render: SupersampleFn) -> CheckResult {
        // One regular sample: the pixel centre (d = 0), weight 1: 08's render bit for bit.
        let s = spheres();
        let camera = Camera::from_scene(&s.camera, s.width, s.height).expect("a valid camera");
        let objects = BruteForce::new(&s.objects);
        let world = World::new(&s, &objects);
        let (expected, _) =
            l08_ray_tree::render(&world, &camera, s.width, s.height, &TraceSettings::default());
        for filter in [Filter::Box, Filter::Tent] {
            let (image, stats) = rendered(render, &s, 1, Pattern::Regular, filter, 5);
            let case =
                format!("two spheres over a floor, 12 × 8, 1 regular sample per pixel, {filter:?} filter");
            if let Some(k) =
                (0..expected.pixels.len()).find(|&k| image.pixels.get(k) != Some(&expected.pixels[k]))
            {
                let (x, y) = (k as u32 % s.width, k as u32 / s.width);
                let got = image.pixels.get(k).map_or("no such pixel".to_owned(), |c| vec3(*c));
                return Err(fail(
                    format!("{case}: pixel ({x}, {y})"),
                    vec3(expected.pixels[k]),
                    got,
                    "one regular sample is at the pixel centre, d = (2u − 1)·r = 0, through the screen point \
                     sx = (2(x + ½ + dₓ) − w)/w, sy = (h − 2(y + ½ + d_y))/h, traced at depth 0, weight 1: 08's \
                     render exactly",
                ));
            }
            let primary = stats.get(Counter::PrimaryRays);
            ensure(
                primary == u64::from(s.width * s.height),
                &case,
                format!("{} primary rays", s.width * s.height),
                primary,
                "count one Counter::PrimaryRays per sample",
            )?;
        }
        // Rays: 12 × 8 pixels × 9 samples; spp = 0 is taken as 1.
        for (spp, rays) in [(9u32, 96 * 9), (0, 96)] {
            let (image, stats) = rendered(render, &s, spp, Pattern::Jittered, Filter::Box, 1);
            let primary = stats.get(Counter::PrimaryRays);
            let cause = if spp == 0 {
                "spp = 0 is taken as 1: one sample per pixel"
            } else {
                "count one Counter::PrimaryRays per sample: spp eye rays per pixel"
            };
            ensure(
                primary == rays && image.non_finite().is_none(),
                format!("two spheres over a floor, 12 × 8, {spp} jittered samples per pixel"),
                format!("{rays} primary rays, finite pixels"),
                format!(
                    "{primary} primary rays{}",
                    if image.non_finite().is_some() { ", NaN pixels" } else { "" }
                ),
                cause,
            )?;
        }
        // The same seed gives the same image.
        let a = rendered(render, &s, 4, Pattern::Stratified, Filter::Tent, 42);
        let b = rendered(render, &s, 4, Pattern::Stratified, Filter::Tent, 42);
        ensure(
            a.0 == b.0,
            "two spheres over a floor, 4 multi-jittered samples, seed 42, rendered twice",
            "the same image",
            "different images",
            "each pixel draws from its own pixel_rng(seed, x, y), never from a shared stream",
        )?;
        // One pixel under the edge y = 0.3x + 0.2 (world units, the pixel is [−1, 1]²), 32 × 32
        // regular samples: the box and the tent weighted coverage, computed here sample by
        // sample. A sample within rounding of the edge may fall either way: one sample's weight
        // over the total, plus a margin of 10⁻⁴ for the sums.
        for filter in [Filter::Box, Filter::Tent] {
            let radius = if filter == Filter::Box { 0.5 } else { 1.0 };
            let (expected, one) = expected_coverage(32, filter, radius, 0.3, 0.2);
            let tolerance = one + 1e-4;
            let (image, _) = rendered(render, &half_plane(0.3, 0.2), 1024, Pattern::Regular, filter, 7);
            let got = image.get(0, 0).x as f64;
            let case = format!(
                "one pixel (the square [−1, 1]²) under the edge y = 0.3x + 0.2, 32 × 32 regular samples, {filter:?} filter"
            );
            let cause = if filter == Filter::Tent && (got - expected / 4.0).abs() <= 0.05 {
                "divide by the sum of the weights Σ w(dₖ), not by the number of samples"
            } else if filter == Filter::Tent
                && (got - expected_coverage(32, filter, 0.5, 0.3, 0.2).0).abs() <= tolerance
            {
                "weight each sample by filter_weight(filter, d) and spread the samples over the filter's support, \
                 d = (2u − 1)·filter.radius()"
            } else {
                "the samples cover [−r, r)² around the centre, d = (2u − 1)·r, r = filter.radius(); the pixel is \
                 Σ w(dₖ)·cₖ / Σ w(dₖ)"
            };
            ensure(
                (got - expected).abs() <= tolerance,
                case,
                format!("{expected:.5} (± {tolerance:.1e})"),
                format!("{got:.5}"),
                cause,
            )?;
        }
        Ok("1-sample renders as 08's, ray counts, a repeatable seed, box and tent coverage".into())
    }
}

#[cfg(all(test, feature = "l10"))]
#[allow(clippy::unnecessary_cast)] // as in `code`
mod tests {
    use super::code::*;
    use crate::check::testing::caught;
    pub(super) use l01_transforms::Camera;
    pub(super) use l08_ray_tree::{TraceSettings, World, trace};
    pub(super) use l10_textures_sampling::{Filter, Pattern, grid, in_stratum, pixel_rng, sample_offsets};
    use raylab::math::consts::{PI, TAU};
    use raylab::random::Rng;
    use raylab::render::render_image;
    use raylab::stats::{Counter, RayStats, count};
    use raylab::{BLACK, Color, Float, Image, Vec2, Vec3};

    #[test]
    fn every_declared_check_passes_on_the_reference() {
        crate::check::testing::every_check_passes(super::CHECKS, super::run);
    }

    #[test]
    fn planted_uv_mistakes_are_caught() {
        // Mirrored longitude, v from the north pole, acos for the latitude, not scale-free.
        caught(
            sphere_cases(|p| {
                Vec2::new(0.5 + p.z.atan2(p.x) / TAU, 0.5 + p.y.atan2((p.x * p.x + p.z * p.z).sqrt()) / PI)
            }),
            "seen from outside",
        );
        caught(
            sphere_cases(|p| {
                Vec2::new(0.5 + (-p.z).atan2(p.x) / TAU, 0.5 - p.y.atan2((p.x * p.x + p.z * p.z).sqrt()) / PI)
            }),
            "v grows upward",
        );
        caught(sphere_cases(|p| Vec2::new(0.5 + (-p.z).atan2(p.x) / TAU, 1.0 - p.y.acos() / PI)), "not acos");
        caught(
            sphere_cases(|p| {
                Vec2::new(0.5 + (-p.z).atan2(p.x) / TAU, 0.5 + p.y.clamp(-1.0, 1.0).asin() / PI)
            }),
            "only the direction",
        );
        // Each axis alone; no division by the squared length.
        caught(
            plane_cases(|p, o, a, b| Vec2::new((p - o).dot(a) / a.dot(a), (p - o).dot(b) / b.dot(b))),
            "normal equations",
        );
        caught(
            plane_cases(|p, o, a, b| Vec2::new((p - o).dot(a.normalize()), (p - o).dot(b.normalize()))),
            "squared length",
        );
        // Weights rotated.
        caught(
            triangle_cases(|uvs, b, g| b * uvs[0] + g * uvs[1] + (1.0 - b - g) * uvs[2]),
            "β weighs vertex 1",
        );
    }

    #[test]
    fn planted_checker_mistakes_are_caught() {
        fn truncated(p: Vec2, s: Float, a: Color, b: Color) -> Color {
            if ((p.x * s) as i64 + (p.y * s) as i64).rem_euclid(2) == 1 { b } else { a }
        }
        caught(checker_cases(truncated), "not truncation");
        fn swapped(p: Vec2, s: Float, a: Color, b: Color) -> Color {
            if ((p.x * s).floor() as i64 + (p.y * s).floor() as i64).rem_euclid(2) == 1 { a } else { b }
        }
        caught(checker_cases(swapped), "even i + j is a");
        fn truncated_3d(p: Vec3, s: Float, a: Color, b: Color) -> Color {
            let q = p * s;
            if (q.x as i64 + q.y as i64 + q.z as i64).rem_euclid(2) == 1 { b } else { a }
        }
        caught(checker_3d_cases(truncated_3d), "not truncation");
        fn two_axes(p: Vec3, s: Float, a: Color, b: Color) -> Color {
            if ((p.x * s).floor() as i64 + (p.y * s).floor() as i64).rem_euclid(2) == 1 { b } else { a }
        }
        caught(checker_3d_cases(two_axes), "all three");
    }

    /// The reference lookup with a slip: 1 = v not flipped, 2 = no half-pixel shift in x, 3 = clamped
    /// instead of wrapped.
    fn lookup(slip: u8, image: &Image, uv: Vec2) -> Color {
        let (w, h) = (image.width, image.height);
        if w == 0 || h == 0 {
            return BLACK;
        }
        let shift = if slip == 2 { 0.0 } else { 0.5 };
        let x = uv.x.rem_euclid(1.0) * w as Float - shift;
        let v = uv.y.rem_euclid(1.0);
        let y = if slip == 1 { v } else { 1.0 - v } * h as Float - 0.5;
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let column = |i: i64| {
            if slip == 3 { i.clamp(0, i64::from(w) - 1) as u32 } else { i.rem_euclid(i64::from(w)) as u32 }
        };
        let row = |j: i64| {
            if slip == 3 { j.clamp(0, i64::from(h) - 1) as u32 } else { j.rem_euclid(i64::from(h)) as u32 }
        };
        let (i, j) = (x0 as i64, y0 as i64);
        let top = (1.0 - fx) * image.get(column(i), row(j)) + fx * image.get(column(i + 1), row(j));
        let bottom =
            (1.0 - fx) * image.get(column(i), row(j + 1)) + fx * image.get(column(i + 1), row(j + 1));
        (1.0 - fy) * top + fy * bottom
    }

    #[test]
    fn planted_bilinear_mistakes_are_caught() {
        assert!(bilinear_cases(|i, uv| lookup(0, i, uv)).is_ok());
        caught(bilinear_cases(|i, uv| lookup(1, i, uv)), "v grows upward");
        caught(bilinear_cases(|i, uv| lookup(2, i, uv)), "(i + ½)/w");
        caught(bilinear_cases(|i, uv| lookup(3, i, uv)), "the image repeats");
    }

    #[test]
    fn planted_filter_mistakes_are_caught() {
        fn box_closed(f: Filter, d: Vec2) -> Float {
            match f {
                Filter::Box => Float::from(u8::from(d.x.abs() <= 0.5 && d.y.abs() <= 0.5)),
                Filter::Tent => (1.0 - d.x.abs()).max(0.0) * (1.0 - d.y.abs()).max(0.0),
            }
        }
        caught(filter_cases(box_closed), "half-open");
        fn unclamped(f: Filter, d: Vec2) -> Float {
            match f {
                Filter::Box => {
                    Float::from(u8::from((-0.5..0.5).contains(&d.x) && (-0.5..0.5).contains(&d.y)))
                }
                Filter::Tent => (1.0 - d.x.abs()) * (1.0 - d.y.abs()),
            }
        }
        caught(filter_cases(unclamped), "clamp each factor");
        fn pyramid(f: Filter, d: Vec2) -> Float {
            match f {
                Filter::Box => {
                    Float::from(u8::from((-0.5..0.5).contains(&d.x) && (-0.5..0.5).contains(&d.y)))
                }
                Filter::Tent => (1.0 - d.x.abs() - d.y.abs()).max(0.0),
            }
        }
        caught(filter_cases(pyramid), "product of two triangles");
    }

    /// The reference patterns with a slip: 1 = regular at the cells' corners, 2 = jittered
    /// anywhere in the square, 3 = multi-jittered without the shuffles' n-rooks (plain jitter).
    fn samples(slip: u8, pattern: Pattern, n: u32, rng: &mut Rng) -> Vec<Vec2> {
        let (cols, rows) = grid(n);
        match (pattern, slip) {
            (Pattern::Regular, 1) => (0..n)
                .map(|k| Vec2::new((k % cols) as Float / cols as Float, (k / cols) as Float / rows as Float))
                .collect(),
            (Pattern::Jittered, 2) => (0..n).map(|_| Vec2::new(rng.next_float(), rng.next_float())).collect(),
            (Pattern::Stratified, 3) => (0..n)
                .map(|k| {
                    let (i, j) = (k % cols, k / cols);
                    Vec2::new(in_stratum(i, cols, rng.next_float()), in_stratum(j, rows, rng.next_float()))
                })
                .collect(),
            _ => sample_offsets(pattern, n, rng),
        }
    }

    #[test]
    fn planted_sampling_mistakes_are_caught() {
        caught(sampling_cases(|p, n, r| samples(1, p, n, r)), "not their corners");
        caught(sampling_cases(|p, n, r| samples(2, p, n, r)), "one sample per cell");
        caught(sampling_cases(|p, n, r| samples(3, p, n, r)), "n-rooks");
    }

    /// The reference supersampler with a slip: 1 = divided by the number of samples, 2 = the
    /// offsets not spread over the filter's radius (d = u − ½ for every filter), 3 = primary
    /// rays not counted.
    #[allow(clippy::too_many_arguments)]
    fn supersample(
        slip: u8,
        world: &World,
        camera: &Camera,
        width: u32,
        height: u32,
        settings: &TraceSettings,
        spp: u32,
        pattern: Pattern,
        filter: Filter,
        seed: u64,
    ) -> (Image, RayStats) {
        let (w, h) = (width as Float, height as Float);
        render_image(width, height, |x, y| {
            let offsets = sample_offsets(pattern, spp.max(1), &mut pixel_rng(seed, x, y));
            let (mut weighted, mut total) = (BLACK, 0.0);
            for u in &offsets {
                let radius = if slip == 2 { 0.5 } else { filter.radius() };
                let d = (2.0 * *u - Vec2::ONE) * radius;
                let sx = (2.0 * (x as Float + 0.5 + d.x) - w) / w;
                let sy = (h - 2.0 * (y as Float + 0.5 + d.y)) / h;
                if slip != 3 {
                    count(Counter::PrimaryRays);
                }
                let c = trace(world, &camera.generate_ray(sx, sy), 0, 1.0, settings);
                let weight = l10_textures_sampling::filter_weight(filter, d);
                weighted += weight * c;
                total += weight;
            }
            if slip == 1 { weighted / offsets.len() as Float } else { weighted / total }
        })
    }

    macro_rules! supersample_slips {
        ($($name:ident => $slip:expr),* $(,)?) => {
            $(#[allow(clippy::too_many_arguments)]
            fn $name(
                world: &World, camera: &Camera, w: u32, h: u32, s: &TraceSettings,
                spp: u32, pattern: Pattern, filter: Filter, seed: u64,
            ) -> (Image, RayStats) {
                supersample($slip, world, camera, w, h, s, spp, pattern, filter, seed)
            })*
        };
    }

    supersample_slips! { by_count => 1, unspread => 2, uncounted => 3 }

    #[test]
    fn planted_supersampling_mistakes_are_caught() {
        caught(supersampling_cases(by_count), "sum of the weights");
        caught(supersampling_cases(unspread), "filter's support");
        caught(supersampling_cases(uncounted), "per sample");
    }
}
