//! Soft shadows: an area light seen through n shadow rays.
//!
//! A point light is either seen or not: its shadows are hard. An area light
//! (a rect or a sphere, lecture 05's [`sample_light`]) is partly seen from the
//! penumbra, the band where a blocker's edge crosses the light. The shading
//! estimates its light by the average of n samples, each a point of the
//! light with its own shadow ray:
//!
//!   I_L ≈ (1/n) Σᵢ V(qᵢ) ⊙ shade_light(…, sample_light(light, p, uᵢ)).
//!
//! The uᵢ are *stratified*: [0, 1)² is cut into n cells and each gets one
//! uniform sample, so no part of the light is missed and the noise falls
//! faster with n than for independent samples. They are drawn from a
//! generator seeded by the shaded point itself ([`point_seed`]), so a render
//! is the same on every run and for every number of threads.
//! Book: §6.5 Area lights and soft shadows, §6.6 Random numbers that repeat.

use l05_shading::{sample_light, shade_light};
use raylab::random::Rng;
use raylab::scene::{Light, Material};
use raylab::{BLACK, Color, Float, Intersector, Vec2, Vec3};

use crate::shade::{ShadowSettings, Surface, visibility};

/// The largest float below 1 (1 − ε/2): a stratified sample that rounds up
/// to 1 is taken back to it, so every sample stays in [0, 1).
pub const ONE_MINUS_EPSILON: Float = 1.0 - Float::EPSILON / 2.0;

/// n stratified samples of the unit square: when n is a square, the √n × √n
/// grid of cells [i/√n, (i+1)/√n) × [j/√n, (j+1)/√n); otherwise the n strips
/// [i/n, (i+1)/n) × [0, 1). Each cell gets one uniform sample,
///
///   u = ((i + ξ₁)/nₓ, (j + ξ₂)/n_y),  ξ₁, ξ₂ = `rng.next_float()`, in that order,
///
/// row by row (j outer, i inner), each coordinate at most
/// [`ONE_MINUS_EPSILON`]. `n` ≥ 1 (0 is taken as 1). Stratifying cuts the
/// error at a shadow's edge from ~1/√n (independent samples) to ~n^(−3/4):
/// only the cells the edge crosses can be wrong. Book: §6.5 Stratified samples.
pub fn stratified(n: u32, rng: &mut Rng) -> Vec<Vec2> {
    debug_assert!(n >= 1, "stratified: n = 0");
    // SOLUTION BEGIN
    // The grid: √n × √n when n is a square, else n strips.
    let n = n.max(1);
    let root = n.isqrt();
    let (nx, ny) = if root * root == n { (root, root) } else { (n, 1) };
    let mut samples = Vec::with_capacity(n as usize);
    for j in 0..ny {
        for i in 0..nx {
            // One uniform point in cell (i, j), kept below 1.
            let x = (i as Float + rng.next_float()) / nx as Float;
            let y = (j as Float + rng.next_float()) / ny as Float;
            samples.push(Vec2::new(x.min(ONE_MINUS_EPSILON), y.min(ONE_MINUS_EPSILON)));
        }
    }
    samples
    // SOLUTION END
}

/// The side of the cells of [`point_seed`]: 1/256 world units.
pub const SEED_CELL: Float = 1.0 / 256.0;

/// The seed of a shaded point's samples: the cell of the grid of side
/// [`SEED_CELL`] (shifted by half a cell) that holds the point, hashed by
/// SplitMix64 coordinate after coordinate: kᵢ = ⌊pᵢ/cell + ½⌋.
///
/// Why a grid and not the point's own bits: the f32 and f64 builds compute
/// the same hit point a few f32 ulp of the eye's distance apart (10⁻⁶ for
/// the course's scenes), and a floor at y = 0 has y = ±10⁻⁸ or so, whose bits
/// are noise. Cells of 1/256, far below a pixel's footprint (~0.03 here) and
/// far above that error, give both builds the same samples at all but a few
/// points near a cell's edge, so they render the same noise; the half-cell
/// shift keeps round coordinates (0, ½, 1, …) off the edges. The cost: points
/// of one cell share their samples, visible only in scenes far smaller than
/// the cell. Book: §6.6 Random numbers that repeat.
pub fn point_seed(p: Vec3) -> u64 {
    p.to_array().into_iter().fold(0, |seed, c| {
        // The cell's index (saturating for coordinates beyond 2⁶³ cells).
        let k = (c / SEED_CELL + 0.5).floor() as i64;
        Rng::new(seed ^ k as u64).next_u64()
    })
}

/// The light an area light sends to `surface` through the blockers, with
/// soft shadows: the average over n = `settings.area_samples` stratified
/// samples uᵢ ([`stratified`], from `Rng::new(point_seed(p))`),
///
///   (1/n) Σᵢ V(qᵢ) ⊙ shade_light(material, diffuse, N, v, sample_light(light, p, uᵢ)),
///
/// with V by [`visibility`] (`settings.mode`). A sample behind the surface
/// (N·L ≤ 0) or sending nothing adds nothing and casts no shadow ray, but
/// still counts in n. With nothing in the way it is the unshadowed average
/// exactly; deep in the umbra, black. The light's `shadows` flag is the
/// caller's business ([`crate::shade_with_shadows`] lights an area light
/// without shadows as a point light at its centre). `n` ≥ 1 (0 is taken as
/// 1). Book: §6.5 Area lights and soft shadows.
pub fn shade_area_light(
    scene: &dyn Intersector,
    materials: &[Material],
    surface: &Surface,
    light: &Light,
    settings: ShadowSettings,
) -> Color {
    debug_assert!(settings.area_samples >= 1, "shade_area_light: no samples");
    // SOLUTION BEGIN
    let Surface { material, diffuse, hit, v, .. } = *surface;
    // Stratified samples, seeded by the point: the same on every run and thread.
    let samples = stratified(settings.area_samples.max(1), &mut Rng::new(point_seed(hit.point)));
    let mut sum = BLACK;
    for &u in &samples {
        // One point of the light; behind the surface or sending nothing, it adds nothing.
        let sample = sample_light(light, hit.point, u);
        if hit.normal.dot(sample.direction) <= 0.0 {
            continue;
        }
        let direct = shade_light(material, diffuse, hit.normal, v, &sample);
        if direct == BLACK {
            continue;
        }
        // What its shadow ray lets through.
        sum += visibility(scene, materials, surface, &sample, settings.mode) * direct;
    }
    // The average over every sample.
    sum / samples.len() as Float
    // SOLUTION END
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testing::{object, see_through};
    use crate::{ShadowMode, shade_with_shadows};
    use l04_quadrics_transforms::BruteForce;
    use l05_shading::shade_local;
    use raylab::scene::{Attenuation, LightKind, Object, Shape};
    use raylab::stats::{Counter, measure};
    use raylab::{Hit, Ray, WHITE};
    use raylab_testing::v;

    const EPS: Float = Float::EPSILON;
    const AMBIENT: Color = Color::splat(0.1);

    /// A white light of this kind, casting shadows.
    fn white(kind: LightKind) -> Light {
        Light { color: WHITE, shadows: true, kind }
    }

    /// The 1 × 1 square light centred above the origin at H = 20: x, z ∈ [−½, ½].
    fn panel() -> Light {
        let attenuation = Attenuation::default();
        white(LightKind::Rect { corner: v(-0.5, 20.0, -0.5), edge_u: Vec3::X, edge_v: Vec3::Z, attenuation })
    }

    /// A ball light of radius ½ at the same place.
    fn bulb() -> Light {
        white(LightKind::Sphere {
            center: v(0.0, 20.0, 0.0),
            radius: 0.5,
            attenuation: Attenuation::default(),
        })
    }

    /// The half-plane x < 0 at height h = 10 (a flat box, opaque material 0).
    fn half_plane() -> Object {
        object(Shape::Box { min: v(-1000.0, 10.0, -1000.0), max: v(0.0, 10.0, 1000.0) }, 0)
    }

    /// A 10 × 10 slab at height 10 to 10.5 over the origin: it hides the whole light.
    fn roof() -> Object {
        object(Shape::Box { min: v(-5.0, 10.0, -5.0), max: v(5.0, 10.5, 5.0) }, 0)
    }

    /// The settings with `n` samples per area light and opaque blockers.
    fn samples(n: u32) -> ShadowSettings {
        ShadowSettings { mode: ShadowMode::Opaque, area_samples: n }
    }

    /// The floor point (x, 0, z), white and matte, seen from above and in front: the hit,
    /// the direction to the eye and the eye.
    fn floor_hit(x: Float, z: Float) -> (Hit, Vec3, Vec3) {
        let ray = Ray::new(v(x, 3.0, z + 4.0), v(0.0, -3.0, -4.0) / 5.0);
        (Hit::new(&ray, 5.0, Vec3::Y), -ray.dir, ray.origin)
    }

    /// `light`'s soft-shadowed contribution at the floor point (x, 0, z) among `objects`
    /// (material 0 opaque, 1 of k_t = ½), and the shadow rays it cast.
    fn area_at(
        objects: &[Object],
        light: &Light,
        x: Float,
        z: Float,
        settings: ShadowSettings,
    ) -> (Color, u64) {
        let materials = [raylab::scene::Material::default(), see_through(Color::splat(0.5))];
        let (hit, eye, origin) = floor_hit(x, z);
        let surface = Surface { material: &materials[0], diffuse: WHITE, hit, v: eye, origin };
        let (color, stats) =
            measure(|| shade_area_light(&BruteForce::new(objects), &materials, &surface, light, settings));
        (color, stats.get(Counter::ShadowRays))
    }

    /// The whole shading (ambient included) of that floor point, and its shadow rays.
    fn shade_at(
        objects: &[Object],
        lights: &[Light],
        x: Float,
        z: Float,
        settings: ShadowSettings,
    ) -> (Color, u64) {
        let material = raylab::scene::Material::default();
        let (hit, eye, origin) = floor_hit(x, z);
        let surface = Surface { material: &material, diffuse: WHITE, hit, v: eye, origin };
        let scene = BruteForce::new(objects);
        let (color, stats) = measure(|| {
            shade_with_shadows(&scene, std::slice::from_ref(&material), &surface, lights, AMBIENT, settings)
        });
        (color, stats.get(Counter::ShadowRays))
    }

    #[test]
    fn deep_in_the_umbra_only_the_ambient_term_is_left() {
        // The roof hides the whole light from the origin: a ray to any light point (x, z
        // within ½ at height 20) crosses height 10–10.5 within ¼ of the axis, inside the
        // roof. Every sample faces the floor, so n shadow rays, all blocked: k_d·I_a exactly.
        for light in [panel(), bulb()] {
            for n in [1, 5, 16] {
                let (color, rays) = shade_at(&[roof()], &[light], 0.0, 0.0, samples(n));
                assert_eq!((color, rays), (AMBIENT, u64::from(n)), "{:?}, n = {n}", light.kind);
            }
        }
    }

    #[test]
    fn fully_outside_the_penumbra_it_is_exactly_the_unshadowed_average() {
        // At x = 2 every ray to the light passes the half plane's edge x = 0 at height 10 on
        // the far side ((2 + q_x)/2 ≥ ¾ > 0): all samples visible. The result is then the
        // average of shade_light over the same stratified points (seeded by the point),
        // summed in the same order: equal to it but for the division's rounding, and to an
        // empty scene's to the last bit.
        let (hit, eye, _) = floor_hit(2.0, 0.25);
        let material = raylab::scene::Material::default();
        for light in [panel(), bulb()] {
            for n in [1, 4, 7, 64] {
                let (blocked, rays) = area_at(&[half_plane()], &light, 2.0, 0.25, samples(n));
                assert_eq!(blocked, area_at(&[], &light, 2.0, 0.25, samples(n)).0);
                let mut sum = BLACK;
                for u in stratified(n, &mut Rng::new(point_seed(hit.point))) {
                    let sample = sample_light(&light, hit.point, u);
                    sum += shade_light(&material, WHITE, hit.normal, eye, &sample);
                }
                // Σ/n and Σ·(1/n), the book's (1/n)Σ, differ by one rounding at most: two ulps
                // of the average are allowed, and nothing more (a sample lost or counted twice
                // moves it by a whole sample's share, ≥ 1/64 of it here).
                let average = sum / n as Float;
                let ulps = 2.0 * Float::EPSILON;
                let close = (0..3).all(|c| (blocked[c] - average[c]).abs() <= ulps * average[c].abs());
                assert!(
                    close,
                    "{:?}, n = {n}: {blocked:?}, the unshadowed average Σ/n is {average:?} \
                     (Σ/n and Σ·(1/n) are both right; they differ by one rounding, not more)",
                    light.kind
                );
                assert_eq!(rays, u64::from(n));
            }
        }
    }

    #[test]
    fn in_the_penumbra_the_visible_fraction_is_the_one_derived_by_hand() {
        // By hand: the ray from the floor point p = (x₀, 0, z₀) to the light point
        // q = (q_x, 20, q_z) crosses the blocker's height 10 halfway, at x = (x₀ + q_x)/2, and
        // is blocked where that is < 0, i.e. q_x < −x₀. With q_x uniform in [−½, ½] the
        // visible fraction is f = (½ + x₀)/1 = x₀ + ½ for |x₀| ≤ ½, whatever z₀.
        //
        // Measured: the light received over that received with nothing in the way (the same
        // samples, seeded by the point) is Σ Vᵢwᵢ / Σ wᵢ, wᵢ = N·Lᵢ (white light, no
        // attenuation, matte white floor). The wᵢ differ: N·L = 20/|q − p| ≥ 20/√(20² + 1² +
        // ½²) = 0.99844, which moves the ratio from the count Σ Vᵢ/n by at most
        // 2·(1 − 0.99844) < 0.0032. Stratified bound: the 1D edge q_x = −x₀ crosses one
        // column of the √n × √n grid; the other columns are wholly seen or hidden, and the
        // √n samples of that column can miss its share by at most √n/n = 1/√n. So
        // |ratio − f| ≤ 1/√n + 0.0032. Typically much less: the column's count is binomial,
        // of variance √n·t(1 − t) ≤ √n/4, so the RMS error over points is about
        // √(√n/6)/n = 0.41·n^(−3/4) (t(1 − t) averages 1/6 over the column); 50 points
        // estimate it, asserted below 0.75·n^(−3/4), a margin of 1.8 for that estimate.
        let mut rng = Rng::new(0x9e_4b7a);
        for n in [16, 64, 256, 1024] {
            let bound = 1.0 / Float::sqrt(n as Float) + 0.0032;
            let (mut worst, mut sum_sq) = (0.0 as Float, 0.0 as Float);
            for _ in 0..50 {
                let x0 = 0.9 * rng.next_float() - 0.45;
                let z0 = 0.6 * rng.next_float() - 0.3;
                let (shadowed, _) = area_at(&[half_plane()], &panel(), x0, z0, samples(n));
                let (open, _) = area_at(&[], &panel(), x0, z0, samples(n));
                let error = shadowed.x / open.x - (x0 + 0.5);
                assert!(
                    error.abs() <= bound,
                    "n = {n}, x₀ = {x0}: visible {} against {}",
                    shadowed.x / open.x,
                    x0 + 0.5
                );
                worst = worst.max(error.abs());
                sum_sq += error * error;
            }
            let rms = (sum_sq / 50.0).sqrt();
            let typical = 0.75 * (n as Float).powf(-0.75);
            println!("n = {n:4}: visible fraction off by {worst:.4} at most (bound {bound:.4}),");
            println!("          RMS {rms:.4} (bound {typical:.4})");
            assert!(rms <= typical, "n = {n}: RMS {rms}");
        }
    }

    #[test]
    fn samples_behind_the_surface_count_but_cast_no_shadow_ray() {
        // A 2 × 2 vertical light through the floor at x = 1, y and z in [−1, 1], edge_v = 2y:
        // of the 4 × 4 grid the rows j = 0, 1 lie below the floor (y < 0, N·L < 0) and the
        // rows j = 2, 3 above it. Exactly 8 shadow rays. The 8 below still count in n: the
        // result is half of what the 8 upper samples average to.
        let attenuation = Attenuation::default();
        let wall = white(LightKind::Rect {
            corner: v(1.0, -1.0, -1.0),
            edge_u: 2.0 * Vec3::Z,
            edge_v: 2.0 * Vec3::Y,
            attenuation,
        });
        let (color, rays) = area_at(&[], &wall, 0.0, 0.0, samples(16));
        assert_eq!(rays, 8);
        let (hit, eye, _) = floor_hit(0.0, 0.0);
        let material = raylab::scene::Material::default();
        let upper: Color = stratified(16, &mut Rng::new(point_seed(hit.point)))[8..]
            .iter()
            .map(|&u| shade_light(&material, WHITE, hit.normal, eye, &sample_light(&wall, hit.point, u)))
            .sum();
        // Sums of 8 values below 1 in another grouping: 8ε.
        approx::assert_abs_diff_eq!(color, 0.5 * (upper / 8.0), epsilon = 8.0 * EPS);
    }

    #[test]
    fn an_area_light_without_shadows_is_a_point_light_at_its_centre() {
        // shadows = false: lecture 05's shading (illuminate stands the light at its centre),
        // bit for bit, even under the roof, and no shadow ray.
        for light in [panel(), bulb()] {
            let light = Light { shadows: false, ..light };
            let (color, rays) = shade_at(&[roof()], &[light], 0.3, -0.2, samples(16));
            let (hit, eye, _) = floor_hit(0.3, -0.2);
            let material = raylab::scene::Material::default();
            assert_eq!((color, rays), (shade_local(&material, WHITE, &hit, eye, &[light], AMBIENT), 0));
        }
    }

    #[test]
    fn a_transparent_roof_passes_a_quarter_of_every_sample() {
        // The roof of k_t = ½ (material 1) in Transmissive mode: each sample crosses its two
        // faces, ½·½ = ¼ of what it would bring; the sum of quarters is a quarter of the
        // sum up to a rounding per sample: n·ε relative, 64ε for n = 16 (values below 1).
        let glass_roof = object(Shape::Box { min: v(-5.0, 10.0, -5.0), max: v(5.0, 10.5, 5.0) }, 1);
        let settings = ShadowSettings { mode: ShadowMode::Transmissive, area_samples: 16 };
        let (filtered, rays) = area_at(&[glass_roof], &panel(), 0.1, 0.1, settings);
        let (open, _) = area_at(&[], &panel(), 0.1, 0.1, settings);
        approx::assert_abs_diff_eq!(filtered, 0.25 * open, epsilon = 64.0 * EPS);
        assert_eq!(rays, 16 * 3, "three segments per sample: to the roof, through it, on");
    }

    #[test]
    fn a_far_small_area_light_looks_like_a_point_light_at_its_centre() {
        // The panel seen from (0.3, 0, −0.2), 20 below, lights like a point light at its
        // centre to within the spread of N·L over it: 1 − 0.99844 < 0.0016 relative (above).
        let (area, _) = area_at(&[], &panel(), 0.3, -0.2, samples(64));
        let point =
            white(LightKind::Point { position: v(0.0, 20.0, 0.0), attenuation: Attenuation::default() });
        let (hit, eye, _) = floor_hit(0.3, -0.2);
        let material = raylab::scene::Material::default();
        let expected =
            shade_light(&material, WHITE, hit.normal, eye, &l05_shading::illuminate(&point, hit.point));
        approx::assert_relative_eq!(area, expected, max_relative = 0.0016);
    }

    /// The cell (i, j) of the nₓ × n_y grid that holds `u`, in f64 (exact for these n).
    fn cell(u: Vec2, nx: u32, ny: u32) -> (u32, u32) {
        let (x, y) = (f64::from(u.x), f64::from(u.y));
        ((x * f64::from(nx)).floor() as u32, (y * f64::from(ny)).floor() as u32)
    }

    #[test]
    fn each_stratum_holds_exactly_one_sample() {
        // Squares give the √n × √n grid, other n the n strips; every cell exactly once, every
        // sample in [0, 1)².
        let mut rng = Rng::new(0x57_7a7a);
        for (n, nx, ny) in
            [(1, 1, 1), (2, 2, 1), (3, 3, 1), (4, 2, 2), (5, 5, 1), (16, 4, 4), (64, 8, 8), (4096, 64, 64)]
        {
            let samples = stratified(n, &mut rng);
            assert_eq!(samples.len(), n as usize);
            let mut seen = vec![false; n as usize];
            for &u in &samples {
                assert!(u.cmpge(Vec2::ZERO).all() && u.cmplt(Vec2::ONE).all(), "n = {n}: {u}");
                let (i, j) = cell(u, nx, ny);
                assert!(i < nx && j < ny, "n = {n}: {u} outside the grid");
                let k = (j * nx + i) as usize;
                assert!(!seen[k], "n = {n}: cell ({i}, {j}) twice");
                seen[k] = true;
            }
        }
    }

    #[test]
    fn samples_come_row_by_row_from_the_generator_in_order() {
        // n = 4: the cells (0,0), (1,0), (0,1), (1,1), each from two draws ξ₁, ξ₂, so the
        // first sample is (ξ₁/2, ξ₂/2) and the last ((1 + ξ₇)/2, (1 + ξ₈)/2).
        let draws: Vec<Float> = {
            let mut rng = Rng::new(9);
            (0..8).map(|_| rng.next_float()).collect()
        };
        let samples = stratified(4, &mut Rng::new(9));
        assert_eq!(samples[0], Vec2::new(draws[0] / 2.0, draws[1] / 2.0));
        assert_eq!(samples[3], Vec2::new((1.0 + draws[6]) / 2.0, (1.0 + draws[7]) / 2.0));
    }

    #[test]
    fn stratified_means_are_closer_to_the_centre_than_independent_ones() {
        // The mean of n = 64 samples estimates (½, ½). Stratified, each coordinate's mean is off
        // by at most the mean of the cells' errors, |Σ (ξ − ½)/8|/8 ≤ 1/16, and typically
        // by (1/8)·√(1/12)/8 = 0.0045; independent samples by √(1/12)/8 = 0.036. Over 200
        // seeds the stratified RMS error is several times smaller.
        let (mut strat, mut indep) = (0.0f64, 0.0f64);
        for seed in 0..200 {
            let mut rng = Rng::new(seed);
            let mean = stratified(64, &mut rng).iter().sum::<Vec2>() / 64.0;
            strat += f64::from((mean - Vec2::splat(0.5)).length_squared());
            let mean = (0..64).map(|_| Vec2::new(rng.next_float(), rng.next_float())).sum::<Vec2>() / 64.0;
            indep += f64::from((mean - Vec2::splat(0.5)).length_squared());
        }
        let (strat, indep) = ((strat / 200.0).sqrt(), (indep / 200.0).sqrt());
        println!("RMS error of the mean of 64 samples: stratified {strat:.4}, independent {indep:.4}");
        assert!(strat * 4.0 < indep, "stratified {strat}, independent {indep}");
    }

    #[test]
    fn the_seed_is_the_cell_of_the_point() {
        // Cells of 1/256 shifted by half: (0, 0, 0) and points within 1/512 of it share a
        // cell, so a floor point at y = ±10⁻⁸ (rounding) seeds like y = 0, and −0 like +0.
        let p = Vec3::new(0.25, 0.0, 3.0);
        assert_eq!(point_seed(p), point_seed(Vec3::new(0.25, -0.0, 3.0)));
        assert_eq!(point_seed(p), point_seed(Vec3::new(0.25 + 1e-6, 1e-8, 3.0 - 1e-6)));
        // Points a pixel apart (10⁻² here, 2.56 cells) get different seeds, and so do permuted
        // coordinates.
        assert_ne!(point_seed(p), point_seed(p + Vec3::new(0.01, 0.0, 0.0)));
        assert_ne!(point_seed(p), point_seed(Vec3::new(3.0, 0.0, 0.25)));
        // An error of 10⁻⁶ (the f32/f64 difference of a hit point here) moves a coordinate into
        // the next cell with probability 10⁻⁶·256 = 0.026%: of 1000 random points moved so along
        // every axis, expect 0.8 (three axes), allow 5.
        let mut rng = Rng::new(3);
        let moved = (0..1000)
            .filter(|_| {
                let p =
                    Vec3::new(rng.next_float(), rng.next_float(), rng.next_float()) * 8.0 - Vec3::splat(4.0);
                point_seed(p) != point_seed(p + Vec3::splat(1e-6))
            })
            .count();
        assert!(moved <= 5, "{moved} of 1000 seeds changed");
        // Huge coordinates saturate instead of overflowing.
        assert_eq!(point_seed(Vec3::splat(Float::MAX)), point_seed(Vec3::splat(Float::MAX / 2.0)));
    }
}
