//! What lecture 09 lends the stages (`stages::Lent`): its choice of a hierarchy where the scene
//! has enough primitives, brute force otherwise (stage 09's intersections, and stage 10's).

use crate::stages::{Finds, Lent};

/// Lends lecture 09's choice of intersector.
pub fn lend(lent: &mut Lent) {
    lent.finders.push((Finds::Hierarchy, |scene| l09_acceleration::intersector_for(&scene.objects)));
}
