//! The Pareto front of a trade: the settings that no other setting beats on
//! both time and error.

/// For each point (time, error), whether it is on the Pareto front: no other
/// point is at least as fast and at least as accurate and strictly better in
/// one of the two. Equal points are all on the front; a NaN coordinate is
/// never on it and never dominates. O(n²), for the few points of a sweep.
pub fn pareto_front(points: &[(f64, f64)]) -> Vec<bool> {
    let dominates = |(t1, e1): (f64, f64), (t2, e2): (f64, f64)| t1 <= t2 && e1 <= e2 && (t1 < t2 || e1 < e2);
    points
        .iter()
        .map(|&p| !p.0.is_nan() && !p.1.is_nan() && !points.iter().any(|&q| dominates(q, p)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn front_of_a_hand_made_set() {
        // (1, 9) fastest; (2, 4) and (4, 1) each trade time for error; (3, 5) is beaten by
        // (2, 4) on both; (5, 1) is as accurate as (4, 1) but slower; (2, 4) twice: both stay.
        let points = [(1.0, 9.0), (3.0, 5.0), (2.0, 4.0), (4.0, 1.0), (5.0, 1.0), (2.0, 4.0)];
        assert_eq!(pareto_front(&points), [true, false, true, true, false, true]);
    }

    #[test]
    fn a_nan_point_is_off_the_front_and_beats_nothing() {
        let points = [(f64::NAN, 0.0), (1.0, 1.0), (0.5, f64::NAN)];
        assert_eq!(pareto_front(&points), [false, true, false]);
        assert!(pareto_front(&[]).is_empty());
    }
}
