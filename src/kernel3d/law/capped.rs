//! An elastic–plastic vector spring held as its force (or moment): the shear spring of a
//! contact and its rolling moment are both this, in the contact plane.

use super::super::vec3::{V3, add, dot, norm, scale, sub};

/// Add `k · increment` to the carried value `last` (same units as the result: N or N·m) and
/// cap its length at `limit` (∞: elastic). Returns (new value, dissipated energy J): the slip
/// (trial − new)/k times the mean of the last and the new value, as the 2D return map books it
/// (`kernel::law::tangential::capped_spring`), which is what central differences take out of
/// the kinetic energy.
#[inline]
pub fn capped(last: V3, increment: V3, k: f64, limit: f64) -> (V3, f64) {
    capped_from(last, last, increment, k, limit)
}

/// [`capped`] for a spring whose stiffness changed since the last step (the rate part's secant
/// modulus): `base` is the spring's value at the new stiffness before the increment (it keeps its
/// zero), `last` the value it had, whose mean with the new one books the slip.
#[inline(always)]
pub fn capped_from(last: V3, base: V3, increment: V3, k: f64, limit: f64) -> (V3, f64) {
    let trial = add(base, scale(k, increment));
    // No cap: elastic whatever its length, which then needs no root (the same bits).
    if limit == f64::INFINITY {
        return (trial, 0.0);
    }
    let size = norm(trial);
    if size <= limit {
        return (trial, 0.0);
    }
    let new = scale(limit / size, trial);
    let slip = scale(1.0 / k, sub(trial, new));
    (new, dot(slip, scale(0.5, add(last, new))).abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn below_the_limit_the_spring_is_elastic_and_dissipates_nothing() {
        let (f, w) = capped([1.0, 0.0, 0.0], [0.0, 2.0, 0.0], 3.0, 100.0);
        assert_eq!((f, w), ([1.0, 6.0, 0.0], 0.0));
    }

    #[test]
    fn past_the_limit_the_value_is_capped_along_the_trial_and_the_slip_dissipates() {
        // From rest, a trial of 10 along x capped at 4: slip (10 − 4)/k = 3 m at mean force 2 N.
        let (f, w) = capped([0.0; 3], [5.0, 0.0, 0.0], 2.0, 4.0);
        assert_eq!(f, [4.0, 0.0, 0.0]);
        assert!((w - 6.0).abs() < 1e-12, "{w}");
    }
}
