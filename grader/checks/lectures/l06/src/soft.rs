//! The checks of `soft.rs`: stratified samples and shade_area_light.

use super::common::*;
use super::shade::{floor_hit, surface};

pub(super) fn stratified_cases(stratified: StratifiedFn) -> CheckResult {
    let mut rng = Rng::new(0x57_7a7a);
    for (n, nx, ny) in [
        (1u32, 1u32, 1u32),
        (2, 2, 1),
        (3, 3, 1),
        (4, 2, 2),
        (5, 5, 1),
        (16, 4, 4),
        (64, 8, 8),
        (4096, 64, 64),
    ] {
        let samples = stratified(n, &mut rng);
        let grid = if nx == ny { format!("the {nx} × {ny} grid") } else { format!("{n} strips") };
        let case = format!("n = {n}: {grid}");
        ensure(
            samples.len() == n as usize,
            &case,
            format!("{n} samples"),
            samples.len(),
            "return exactly n samples: a √n × √n grid when n is a square, else n strips",
        )?;
        let mut seen = vec![false; n as usize];
        for &u in &samples {
            ensure(
                u.cmpge(Vec2::ZERO).all() && u.cmplt(Vec2::ONE).all(),
                &case,
                "every sample in [0, 1)²",
                format!("({}, {})", num(u.x), num(u.y)),
                "u = ((i + ξ₁)/nₓ, (j + ξ₂)/n_y) with ξ in [0, 1), each coordinate at most ONE_MINUS_EPSILON",
            )?;
            // The cell, in f64 (exact for these n).
            let (i, j) = ((wide(u.x) * f64::from(nx)) as usize, (wide(u.y) * f64::from(ny)) as usize);
            let k = j * nx as usize + i;
            ensure(
                !seen[k],
                &case,
                "one sample in each cell",
                format!("two in cell ({i}, {j})"),
                "one uniform sample per cell: u = ((i + ξ₁)/nₓ, (j + ξ₂)/n_y); n strips [i/n, (i+1)/n) × [0, 1) when n is not a square",
            )?;
            seen[k] = true;
        }
    }
    // The order: n = 4 from Rng::new(9), cells (0,0), (1,0), (0,1), (1,1), each from two
    // draws ξ₁ (x) then ξ₂ (y): the first is (ξ₁/2, ξ₂/2), the second ((1 + ξ₃)/2, ξ₄/2).
    // Tolerance 2ε: (i + ξ)/2 and i/2 + ξ/2 may round differently.
    let draws: Vec<Float> = {
        let mut rng = Rng::new(9);
        (0..8).map(|_| rng.next_float()).collect()
    };
    let samples = stratified(4, &mut Rng::new(9));
    let expected = [
        Vec2::new(draws[0] / 2.0, draws[1] / 2.0),
        Vec2::new((1.0 + draws[2]) / 2.0, draws[3] / 2.0),
        Vec2::new(draws[4] / 2.0, (1.0 + draws[5]) / 2.0),
        Vec2::new((1.0 + draws[6]) / 2.0, (1.0 + draws[7]) / 2.0),
    ];
    let show =
        |s: &[Vec2]| s.iter().map(|u| format!("({}, {})", num(u.x), num(u.y))).collect::<Vec<_>>().join(", ");
    ensure(
        samples.len() == 4
            && samples
                .iter()
                .zip(&expected)
                .all(|(a, b)| !(*a - *b).is_nan() && (*a - *b).abs().max_element() <= 2.0 * EPS),
        "n = 4 from Rng::new(9): the order of the samples and of the draws",
        format!("{} (± 2ε each)", show(&expected)),
        show(&samples),
        "row by row (j outer, i inner), each cell drawing ξ₁ for x then ξ₂ for y, from the generator given",
    )?;
    Ok("8 grids and the order".into())
}

/// The expected soft-shadowed light at the floor point `hit` from the white rect
/// light (corner, edge_u, edge_v) with no attenuation, on a white matte surface:
/// (1/n) Σ V(qᵢ)·(N·Lᵢ)⁺, over the points qᵢ of the samples uᵢ, in f64. V is given
/// by `visible(p, q)`.
pub(super) fn area_expected(
    hit: &Hit,
    samples: &[Vec2],
    (corner, edge_u, edge_v): (Vec3, Vec3, Vec3),
    visible: impl Fn([f64; 3], [f64; 3]) -> bool,
) -> f64 {
    let p = wide3(hit.point);
    let n = wide3(hit.normal);
    let sum: f64 = samples
        .iter()
        .map(|u| {
            let q = wide3(corner + u.x * edge_u + u.y * edge_v);
            let to = [q[0] - p[0], q[1] - p[1], q[2] - p[2]];
            let d = (to[0] * to[0] + to[1] * to[1] + to[2] * to[2]).sqrt();
            let cos = (to[0] * n[0] + to[1] * n[1] + to[2] * n[2]) / d;
            if cos > 0.0 && visible(p, q) { cos } else { 0.0 }
        })
        .sum();
    sum / samples.len() as f64
}

pub(super) fn area_cases(area: AreaFn) -> CheckResult {
    let white = Material::default();
    let materials = [Material::default()];
    let rect = |corner, edge_u, edge_v| Light {
        color: WHITE,
        shadows: true,
        kind: LightKind::Rect { corner, edge_u, edge_v, attenuation: Attenuation::default() },
    };
    let panel_geometry = (v(-0.5, 20.0, -0.5), Vec3::X, Vec3::Z);
    let panel = rect(panel_geometry.0, panel_geometry.1, panel_geometry.2);
    let run = |shapes: &[(Shape, usize)], light: &Light, x: Float, n: u32| {
        let (hit, eye) = floor_hit(x, 0.1);
        let s = surface(&white, hit, eye);
        let scene = Scene::new(shapes);
        let settings = ShadowSettings { mode: ShadowMode::Opaque, area_samples: n };
        let (c, stats) = measured(|| area(&scene, &materials, &s, light, settings));
        (c, stats.get(Counter::ShadowRays), hit)
    };
    let samples_at = |hit: &Hit, n: u32| stratified(n, &mut Rng::new(point_seed(hit.point)));
    // A 2 × 2 wall light through the floor at x = 1 (y, z in [−1, 1]): of a 4 × 4 grid the
    // rows below the floor (N·L < 0) add nothing and cast no ray, but count in n.
    let wall = (v(1.0, -1.0, -1.0), 2.0 * Vec3::Z, 2.0 * Vec3::Y);
    let case = "white floor (0, 0, 0.1), a 2 × 2 rect light standing through the floor at x = 1, 16 samples";
    let (c, rays, hit) = run(&[], &rect(wall.0, wall.1, wall.2), 0.0, 16);
    let expected = area_expected(&hit, &samples_at(&hit, 16), wall, |_, _| true) as Float;
    // Sixteen terms below 1, each a few roundings: 16·4ε.
    let tolerance = 64.0 * EPS;
    let cause = if (c.x - 2.0 * expected).abs() <= 1e-4 {
        "divide by n: samples behind the surface count in the average"
    } else if (c.x - 16.0 * expected).abs() <= 1e-3 {
        "average: divide the sum over the samples by n"
    } else if rays < 8 {
        "weight each sample by the visibility of its own shadow ray (one per sample facing the surface)"
    } else if rays > 8 {
        "no shadow ray for a sample behind the surface (N·L ≤ 0)"
    } else {
        "the samples are stratified(n, Rng::new(point_seed(hit.point))), each through sample_light and shade_light"
    };
    ensure(
        crate::check::near3(c, Color::splat(expected), tolerance) && rays == 8,
        case,
        format!("{} (± {tolerance:.1e}) with 8 shadow rays", num(expected)),
        format!("{} with {rays} shadow rays", vec3(c)),
        cause,
    )?;
    // Under an opaque roof y = 10: every sample blocked, n shadow rays, black.
    for n in [1, 5, 16] {
        let case = format!(
            "white floor (0, 0, 0.1) under an opaque roof y = 10, 1 × 1 rect light at 20, {n} samples"
        );
        let (c, rays, _) = run(&[floor(10.0, 0)], &panel, 0.0, n);
        let cause = if c != BLACK {
            "weight each sample by the visibility of its own shadow ray"
        } else {
            "one shadow ray per sample that faces the surface"
        };
        ensure(
            c == BLACK && rays == u64::from(n),
            case,
            format!("(0, 0, 0) with {n} shadow rays"),
            format!("{} with {rays} shadow rays", vec3(c)),
            cause,
        )?;
    }
    // Nothing in the way, and the penumbra of a half plane x < 0 at height 10 (edge x = 0):
    // the ray from p to q crosses height 10 at x = (pₓ + qₓ)/2 (halfway up), blocked where
    // that is < 0. Points whose samples come within 10⁻⁴ of the edge are left out (the
    // checks' own f32 intersection may decide either way there).
    let mut count = 0;
    for (shapes, xs) in [
        (vec![], vec![0.0, 0.3]),
        (vec![(Shape::HalfFloor { height: 10.0 }, 0)], vec![-0.3, -0.1, 0.0, 0.2, 0.37]),
    ] {
        for x in xs {
            for n in [16, 64] {
                let (c, _, hit) = run(&shapes, &panel, x, n);
                let samples = samples_at(&hit, n);
                let edge = |p: [f64; 3], q: [f64; 3]| p[0] + (q[0] - p[0]) * (10.0 - p[1]) / (q[1] - p[1]);
                let p = wide3(hit.point);
                let near_edge = samples.iter().any(|u| {
                    let q = wide3(panel_geometry.0 + u.x * panel_geometry.1 + u.y * panel_geometry.2);
                    edge(p, q).abs() < 1e-4
                });
                if near_edge && !shapes.is_empty() {
                    continue;
                }
                let blocker = !shapes.is_empty();
                let expected =
                    area_expected(&hit, &samples, panel_geometry, |p, q| !blocker || edge(p, q) >= 0.0)
                        as Float;
                let case = format!(
                    "white floor ({}, 0, 0.1), 1 × 1 rect light at 20, {}, {n} samples",
                    num(x),
                    if blocker { "half plane x < 0 at height 10" } else { "nothing in the way" }
                );
                let cause = if (c.x - (n as Float) * expected).abs() <= 1e-3 {
                    "average: divide the sum over the samples by n"
                } else if blocker {
                    "weight each sample by the visibility of its own shadow ray, from its own point of the light"
                } else {
                    "the samples are stratified(n, Rng::new(point_seed(hit.point))), each through sample_light and shade_light"
                };
                // n terms below 1, each a few roundings: n·4ε.
                close3(&case, c, Color::splat(expected), (n as Float) * 4.0 * EPS, cause)?;
                count += 1;
            }
        }
    }
    Ok(format!("{} cases", count + 4))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l05_shading::{sample_light, shade_light};
    use l06_shadows::{ShadowSettings, Surface, point_seed, shade_area_light, stratified, visibility};
    use raylab::random::Rng;
    use raylab::scene::{Light, Material};

    use raylab::{BLACK, Color, Float, Intersector, Vec2, WHITE};

    #[test]
    fn stratified_mistakes_are_caught() {
        // Independent samples.
        caught(
            stratified_cases(|n, rng| {
                (0..n).map(|_| Vec2::new(rng.next_float(), rng.next_float())).collect()
            }),
            "one uniform sample per cell",
        );
        // Column by column.
        caught(
            stratified_cases(|n, rng| {
                let mut s = stratified(n, rng);
                let root = n.isqrt() as usize;
                if root * root == n as usize {
                    let copy = s.clone();
                    for (k, u) in s.iter_mut().enumerate() {
                        *u = copy[(k % root) * root + k / root];
                    }
                }
                s
            }),
            "row by row",
        );
        // The largest square grid for every n.
        caught(
            stratified_cases(|n, rng| {
                let root = n.isqrt();
                let mut s = Vec::new();
                for j in 0..root {
                    for i in 0..root {
                        let x = (i as Float + rng.next_float()) / root as Float;
                        let y = (j as Float + rng.next_float()) / root as Float;
                        s.push(Vec2::new(x, y));
                    }
                }
                s
            }),
            "exactly n samples",
        );
    }

    /// The soft-shadowed light with a chosen slip.
    fn area_with(
        scene: &dyn Intersector,
        materials: &[Material],
        s: &Surface,
        light: &Light,
        settings: ShadowSettings,
        slip: &str,
    ) -> Color {
        let samples = stratified(settings.area_samples, &mut Rng::new(point_seed(s.hit.point)));
        let (mut sum, mut used) = (BLACK, 0);
        for &u in &samples {
            let sample = sample_light(light, s.hit.point, u);
            if s.hit.normal.dot(sample.direction) <= 0.0 && slip != "rays behind" {
                continue;
            }
            used += 1;
            let direct = shade_light(s.material, s.diffuse, s.hit.normal, s.v, &sample);
            let visible = if slip == "no shadows" {
                WHITE
            } else {
                visibility(scene, materials, s, &sample, settings.mode)
            };
            sum += visible * direct;
        }
        match slip {
            "divide by used" => sum / used.max(1) as Float,
            "sum" => sum,
            _ => sum / samples.len() as Float,
        }
    }

    #[test]
    fn shade_area_light_mistakes_are_caught() {
        caught(area_cases(|a, b, c, d, e| area_with(a, b, c, d, e, "divide by used")), "divide by n");
        caught(area_cases(|a, b, c, d, e| area_with(a, b, c, d, e, "sum")), "average");
        caught(
            area_cases(|a, b, c, d, e| area_with(a, b, c, d, e, "no shadows")),
            "visibility of its own shadow ray",
        );
        caught(
            area_cases(|a, b, c, d, e| area_with(a, b, c, d, e, "rays behind")),
            "no shadow ray for a sample behind",
        );
        assert!(area_cases(|a, b, c, d, e| area_with(a, b, c, d, e, "")).is_ok());
        // The same for the reference.
        assert!(area_cases(shade_area_light).is_ok());
    }
}
