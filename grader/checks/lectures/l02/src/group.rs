//! The checks of `group.rs`: the closest hit of a group.

use super::common::*;

pub(super) fn closest_of_three() -> CheckResult {
    let sphere = |z: Float| Object {
        shape: Shape::Sphere { center: Vec3::new(0.0, 0.0, z), radius: 1.0 },
        material: 0,
        transform: None,
    };
    // Listed far, near, middle: the nearest (index 1, z = 0) is hit at t = 4.
    let objects = [sphere(-10.0), sphere(0.0), sphere(-5.0)];
    let case = "spheres at z = −10, 0, −5 (in that order), ray from (0, 0, 5) along −z";
    let r = ray([0.0, 0.0, 5.0], [0.0, 0.0, -1.0]);
    let got =
        crate::judge::student(|| Group::new(&objects).closest_hit(&r, Interval::new(0.0, Float::INFINITY)));
    let show = |h: &Option<Hit>| maybe(h, |h| format!("object {} at t = {}", h.object, num(h.t)));
    let Some(h) = got else {
        return Err(fail(
            case,
            "object 1 at t = 4",
            show(&got),
            "test every object and keep the nearest hit",
        ));
    };
    ensure(
        h.object == 1 && (h.t - 4.0).abs() <= TOL,
        case,
        format!("object 1 at t = 4 (± {TOL:.1e})"),
        show(&got),
        "keep the nearest hit: shrink the range's max to each hit's t, and set hit.object to the index",
    )?;
    Ok("1 case".into())
}
