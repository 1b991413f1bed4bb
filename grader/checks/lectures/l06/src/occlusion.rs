//! The checks of `occlusion.rs`: occluded and transmittance.

use super::common::*;

pub(super) fn occluded_cases(occluded: OccludedFn) -> CheckResult {
    let light = toward_point(Vec3::ZERO, v(0.0, 5.0, 0.0));
    let cases = [
        (
            "unit sphere at (0, 2, 0) between the origin and a light at (0, 5, 0)",
            v(0.0, 2.0, 0.0),
            true,
            "a blocker between the point and the light shadows it: any hit with 0 < s < distance",
        ),
        (
            "unit sphere at (1.5, 2, 0), beside the ray to a light at (0, 5, 0)",
            v(1.5, 2.0, 0.0),
            false,
            "the shadow ray runs from the point along L = sample.direction",
        ),
        (
            "unit sphere at (0, 8, 0), beyond a light at (0, 5, 0)",
            v(0.0, 8.0, 0.0),
            false,
            "blockers beyond the light do not count: the range ends at sample.distance",
        ),
        (
            "unit sphere at (0, −3, 0), behind the point, light at (0, 5, 0)",
            v(0.0, -3.0, 0.0),
            false,
            "blockers behind the point do not count: the range starts at 0 (from is already offset)",
        ),
        (
            "unit sphere at (0, 6, 0) whose surface touches the light at (0, 5, 0)",
            v(0.0, 6.0, 0.0),
            false,
            "the range ends short of the light: distance·(1 − 4ε) (LIGHT_MARGIN)",
        ),
    ];
    for (case, center, expected, cause) in cases {
        let scene = Scene::new(&[(Shape::Sphere { center, radius: 1.0 }, 0)]);
        let got = occluded(&scene, Vec3::ZERO, &light);
        ensure(got == expected, case, expected, got, cause)?;
    }
    // A directional light (distance ∞): blocked by a sphere 1000 away on the ray.
    let case = "unit sphere at (0, 1000, 0), directional light straight up";
    let scene = Scene::new(&[sphere(0.0, 1000.0, 0.0, 1.0, 0)]);
    let got = occluded(&scene, Vec3::ZERO, &toward(Vec3::Y));
    ensure(got, case, true, got, "a directional light (distance ∞) is blocked by anything along the ray")?;
    // One any-hit query, no closest hit, one shadow ray counted.
    let case = "unit sphere at (0, 2, 0), directional light straight up: the queries asked";
    let scene = Scene::new(&[sphere(0.0, 2.0, 0.0, 1.0, 0)]);
    // The queries are the student's code's doing: counted in the same value.
    let ((any, closest), stats) = measured(|| {
        occluded(&scene, Vec3::ZERO, &toward(Vec3::Y));
        (scene.any_calls.load(Ordering::Relaxed), scene.closest_calls.load(Ordering::Relaxed))
    });
    ensure(
        any == 1 && closest == 0,
        case,
        "1 any_hit, 0 closest_hit",
        format!("{any} any_hit, {closest} closest_hit"),
        "a shadow ray needs any hit, not the closest: ask scene.any_hit once (it may stop at the first blocker)",
    )?;
    let rays = stats.get(Counter::ShadowRays);
    ensure(
        rays == 1,
        case,
        "1 shadow ray counted",
        rays,
        "count one Counter::ShadowRays per shadow ray (the statistics show what the scene required)",
    )?;
    Ok("8 cases".into())
}

/// Light from (0, 10, 0) to the origin through `shapes`: the filter and the segments.
pub(super) fn through(
    transmittance: TransmittanceFn,
    shapes: &[(Shape, usize)],
    materials: &[Material],
) -> (Color, u64) {
    let scene = Scene::new(shapes);
    let sample = toward_point(Vec3::ZERO, v(0.0, 10.0, 0.0));
    let (t, stats) = measured(|| transmittance(&scene, materials, Vec3::ZERO, &sample));
    (t, stats.get(Counter::ShadowRays))
}

/// A case of the walk: what, the shapes, their materials, the filter and the segments.
pub(super) type TransmittanceCase = (&'static str, Vec<(Shape, usize)>, Vec<Material>, Color, u64);

pub(super) fn transmittance_cases(transmittance: TransmittanceFn) -> CheckResult {
    let half = see_through(Color::splat(0.5));
    let show = |(c, n): (Color, u64)| format!("{} after {n} segments", vec3(c));
    // Each surface crossing filters by k_t: products of powers of two, exact.
    let cases: [TransmittanceCase; 8] = [
        (
            "a sphere of k_t = ½ at (0, 4, 0), light at (0, 10, 0)",
            vec![sphere(0.0, 4.0, 0.0, 1.0, 0)],
            vec![half.clone()],
            Color::splat(0.25),
            3,
        ),
        (
            "a plane y = 4 of k_t = ½, light at (0, 10, 0)",
            vec![floor(4.0, 0)],
            vec![half.clone()],
            Color::splat(0.5),
            2,
        ),
        (
            "a sphere of k_t = (1, ½, ¼) at (0, 3, 0) and a plane y = 6 of k_t = (½, 1, 1)",
            vec![sphere(0.0, 3.0, 0.0, 1.0, 0), floor(6.0, 1)],
            vec![see_through(v(1.0, 0.5, 0.25)), see_through(v(0.5, 1.0, 1.0))],
            v(0.5, 0.25, 0.0625),
            4,
        ),
        ("nothing in the way", vec![], vec![half.clone()], WHITE, 1),
        (
            "an opaque sphere at (0, 3, 0), a transparent plane y = 6 beyond",
            vec![sphere(0.0, 3.0, 0.0, 1.0, 0), floor(6.0, 1)],
            vec![Material::default(), half.clone()],
            BLACK,
            1,
        ),
        (
            "a plane y = 4 of k_t = ½, an opaque sphere at (0, 12, 0) beyond the light at 10",
            vec![floor(4.0, 0), sphere(0.0, 12.0, 0.0, 1.0, 1)],
            vec![half.clone(), Material::default()],
            Color::splat(0.5),
            2,
        ),
        // Found by mutation testing: remaining /= hit.t passed (the far plane is 6 beyond the
        // first, the range 10/2 = 5 instead of 8).
        (
            "planes y = 2 and y = 8 of k_t = ½, light at (0, 10, 0)",
            vec![floor(2.0, 0), floor(8.0, 0)],
            vec![half.clone()],
            Color::splat(0.25),
            3,
        ),
        // Found by mutation testing: a range of distance / LIGHT_MARGIN passed.
        (
            "a plane y = 10 of k_t = ½ through the light at (0, 10, 0)",
            vec![floor(10.0, 0)],
            vec![half.clone()],
            WHITE,
            1,
        ),
    ];
    for (case, shapes, materials, expected, segments) in cases {
        let got = through(transmittance, &shapes, &materials);
        let cause = if case.starts_with("planes") && got.0 == Color::splat(0.5) {
            "after each blocker the light is nearer by the t travelled: remaining −= hit.t"
        } else if expected == BLACK && got.0 == BLACK && got.1 > segments {
            "an opaque blocker (k_t = 0) ends the walk: stop at black, no more segments"
        } else if got.0 == 2.0 * expected && expected != BLACK {
            "each surface crossing filters by k_t: a sphere is crossed twice, in and out"
        } else if got.0 == BLACK && got.1 >= 60 {
            "start the next segment past the blocker: offset_origin(hit.point, hit.normal, dir, origin)"
        } else if got.0 == BLACK && expected != BLACK && shapes.len() == 2 {
            "after each blocker the light is nearer by the t travelled: shrink the range (remaining −= hit.t)"
        } else if got.0 == expected {
            "count one Counter::ShadowRays per segment: to each blocker, and on to the light"
        } else if case.contains("through the light") {
            "the range ends short of the light: distance·(1 − 4ε) (LIGHT_MARGIN), so a surface the light \
             sits on does not filter it"
        } else if expected == BLACK {
            "an opaque blocker (k_t = 0) blocks: stop the walk at black"
        } else {
            "T = Π k_t over the surfaces crossed between the point and the light, by channel"
        };
        ensure(got == (expected, segments), case, show((expected, segments)), show(got), cause)?;
    }
    // A material index with no material is opaque.
    let case = "a sphere at (0, 3, 0) whose material index 7 has no material";
    let got = through(transmittance, &[sphere(0.0, 3.0, 0.0, 1.0, 7)], std::slice::from_ref(&half));
    ensure(
        got.0 == BLACK,
        case,
        "(0, 0, 0)",
        show(got),
        "a material index with no material counts as opaque",
    )?;
    // Twenty fully transparent spheres along the ray, the light beyond at 100: white after
    // 2·20 + 1 segments, and the walk ends.
    let case = "20 spheres of k_t = 1 along the ray, light at (0, 100, 0)";
    let shapes: Vec<(Shape, usize)> =
        (0..20).map(|i| sphere(0.0, 2.0 + 2.5 * i as Float, 0.0, 1.0, 0)).collect();
    let scene = Scene::new(&shapes);
    let sample = toward_point(Vec3::ZERO, v(0.0, 100.0, 0.0));
    let (t, stats) = measured(|| transmittance(&scene, &[see_through(WHITE)], Vec3::ZERO, &sample));
    let got = (t, stats.get(Counter::ShadowRays));
    ensure(
        got == (WHITE, 41),
        case,
        show((WHITE, 41)),
        show(got),
        "walk through every surface up to the light",
    )?;
    Ok("10 cases".into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::testing::caught;
    use l05_shading::LightSample;
    use l06_shadows::{LIGHT_MARGIN, offset_origin};

    use raylab::scene::Material;
    use raylab::stats::{Counter, count};
    use raylab::{BLACK, Color, Float, Intersector, Interval, Ray, Vec3, WHITE};

    #[test]
    fn occluded_mistakes_are_caught() {
        // The closest hit asked, where any hit would do.
        caught(
            occluded_cases(|scene, from, s| {
                count(Counter::ShadowRays);
                scene
                    .closest_hit(&Ray::new(from, s.direction), Interval::new(0.0, s.distance * LIGHT_MARGIN))
                    .is_some()
            }),
            "any hit, not the closest",
        );
        // No end at the light.
        caught(
            occluded_cases(|scene, from, s| {
                count(Counter::ShadowRays);
                scene.any_hit(&Ray::new(from, s.direction), Interval::POSITIVE)
            }),
            "beyond the light",
        );
        // A range open behind the point.
        caught(
            occluded_cases(|scene, from, s| {
                count(Counter::ShadowRays);
                scene.any_hit(&Ray::new(from, s.direction), Interval::new(Float::NEG_INFINITY, s.distance))
            }),
            "behind the point",
        );
        // Not counted.
        caught(
            occluded_cases(|scene, from, s| {
                scene.any_hit(&Ray::new(from, s.direction), Interval::new(0.0, s.distance * LIGHT_MARGIN))
            }),
            "count one",
        );
    }

    /// The reference walk with a chosen slip.
    fn walk(
        scene: &dyn Intersector,
        materials: &[Material],
        from: Vec3,
        s: &LightSample,
        slip: &str,
    ) -> Color {
        let mut origin = from;
        let mut remaining = s.distance * LIGHT_MARGIN;
        let mut filtered = WHITE;
        for _ in 0..64 {
            count(Counter::ShadowRays);
            let Some(hit) = scene.closest_hit(&Ray::new(origin, s.direction), Interval::new(0.0, remaining))
            else {
                return filtered;
            };
            let kt = materials.get(hit.material).map_or(BLACK, |m| m.transparent);
            if slip != "once per object" || hit.front_face {
                filtered *= kt;
            }
            if filtered == BLACK && slip != "no stop" {
                return BLACK;
            }
            origin = if slip == "no offset" {
                hit.point
            } else {
                offset_origin(hit.point, hit.normal, s.direction, origin)
            };
            if slip != "light not nearer" {
                remaining -= hit.t;
            }
        }
        BLACK
    }

    #[test]
    fn transmittance_mistakes_are_caught() {
        caught(transmittance_cases(|sc, m, f, s| walk(sc, m, f, s, "once per object")), "crossed twice");
        caught(transmittance_cases(|sc, m, f, s| walk(sc, m, f, s, "light not nearer")), "light is nearer");
        caught(transmittance_cases(|sc, m, f, s| walk(sc, m, f, s, "no stop")), "ends the walk");
        assert!(transmittance_cases(|sc, m, f, s| walk(sc, m, f, s, "")).is_ok());
    }
}
