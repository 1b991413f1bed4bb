//! What lecture 04 lends the stages (`stages::Lent`): its brute force over every shape,
//! transforms included, which stages 04 to 08 find their hits with.

use crate::stages::{Finds, Lent};

/// Lends lecture 04's brute force.
pub fn lend(lent: &mut Lent) {
    lent.finders.push((Finds::BruteForce, |scene| {
        Box::new(l04_quadrics_transforms::BruteForce::new(&scene.objects))
    }));
}
