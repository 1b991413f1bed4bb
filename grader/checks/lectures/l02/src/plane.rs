//! The checks of `plane.rs`: hit_plane.

use super::common::*;

pub(super) fn plane_cases() -> CheckResult {
    let all = Interval::new(0.0, Float::INFINITY);
    let show = |h: &Option<Hit>| maybe(h, |h| format!("t = {}, normal {}", num(h.t), vec3(h.normal)));
    // The plane y = 1 (n = +y, offset 1): from y = 5 downwards t = 4.
    let case = "plane y = 1, ray from (0, 5, 0) along (0, −1, 0)";
    let got = hit_plane(&ray([0.0, 5.0, 0.0], [0.0, -1.0, 0.0]), Vec3::Y, 1.0, all);
    let Some(h) = got else {
        return Err(fail(case, "t = 4", show(&got), "t = (offset − n·o)/(n·d)"));
    };
    close(case, h.t, 4.0, TOL, "t = (offset − n·o)/(n·d)")?;
    close3(case, h.normal, Vec3::Y, TOL, "the plane's normal is n")?;
    // From below: t = 6, the normal faces the ray.
    let case = "plane y = 1, ray from (0, −5, 0) along (0, 2, 0)";
    let got = hit_plane(&ray([0.0, -5.0, 0.0], [0.0, 2.0, 0.0]), Vec3::Y, 1.0, all);
    let Some(h) = got else {
        return Err(fail(case, "t = 3", show(&got), "t = (offset − n·o)/(n·d)"));
    };
    close(case, h.t, 3.0, TOL, "t = (offset − n·o)/(n·d), in units of dir")?;
    close3(case, h.normal, -Vec3::Y, TOL, "from below the normal faces the ray: Hit::new flips it")?;
    // Parallel and behind: no hit, and no NaN or infinite t.
    let case = "plane y = 1, ray from (0, 5, 0) along (1, 0, 0): parallel";
    let got = hit_plane(&ray([0.0, 5.0, 0.0], [1.0, 0.0, 0.0]), Vec3::Y, 1.0, all);
    ensure(got.is_none(), case, "None", show(&got), "n·d = 0: the ray is parallel, return None")?;
    let case = "plane y = 1, ray from (0, 5, 0) along (0, 1, 0): pointing away";
    let got = hit_plane(&ray([0.0, 5.0, 0.0], [0.0, 1.0, 0.0]), Vec3::Y, 1.0, all);
    ensure(got.is_none(), case, "None", show(&got), "t < 0 is behind the origin: check the range")?;
    Ok("4 cases".into())
}
