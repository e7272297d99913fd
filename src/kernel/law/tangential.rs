//! Tangential part: an elastic spring Kt on the incremental tangential displacement, capped by
//! a plastic limit. The same return map serves the bond's shear plateau (limit f_t^crit,
//! eq 5.6) and Coulomb sliding with cohesion (limit −μ Fn + c, eq 2.1).

use crate::kernel::lanes::{Mask, Real};

/// Return map of a tangential spring: elastic displacement `ut_prev` (m, the force of the last
/// step is `kt_last`·ut_prev) plus this step's relative tangential displacement `increment_m`,
/// stiffness `kt`, capped at `limit_n`. Returns (force N, new elastic displacement m,
/// dissipated energy J).
///
/// The dissipation is the slip times the mean of the last and the new force: the trapezoidal
/// work of the step less the change of the spring's energy, which is what central differences
/// take out of the kinetic energy (it changes by F_n·(Δx_{n−½} + Δx_{n+½})/2, so a force is
/// weighted by both ends of each step). Booking the new force alone misses the work of a force
/// that falls during the step, as the cap −μ Fn does while an impact unloads: in the 250 m/s
/// impact of `tests/energy_ledger.rs` it left 14 % of the friction out of the ledger.
#[inline(always)]
pub fn capped_spring<R: Real>(ut_prev: R, increment_m: R, kt: R, kt_last: R, limit_n: R) -> (R, R, R) {
    let (ut_trial, f, holds) = trial(ut_prev, increment_m, kt, limit_n);
    holds.when((f, ut_trial, R::zero()), #[inline(always)] || {
        let capped = limit_n.copysign(f);
        let ut = capped / kt;
        (capped, ut, R::splat(0.5) * (kt_last * ut_prev + capped) * (ut_trial - ut))
    })
}

/// The elastic trial of [`capped_spring`]: (u_t m, force N, where |force| ≤ `limit_n` and the
/// spring keeps it).
#[inline(always)]
pub fn trial<R: Real>(ut_prev: R, increment_m: R, kt: R, limit_n: R) -> (R, R, R::Mask) {
    let ut_trial = ut_prev + increment_m;
    let f = kt * ut_trial;
    (ut_trial, f, f.abs().le(limit_n))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elastic_below_the_limit_and_capped_above() {
        assert_eq!(capped_spring(0.0, 1e-3, 1e6, 1e6, 2e3), (1e3, 1e-3, 0.0));
        // Sliding on at the cap: the slip times the (constant) force.
        let (f, ut, w) = capped_spring(-2e-3, -1e-3, 1e6, 1e6, 2e3);
        assert_eq!((f, ut), (-2e3, -2e-3));
        assert!((w - 2e3 * 1e-3).abs() < 1e-12);
    }

    #[test]
    fn a_force_that_flips_within_the_step_is_weighted_by_both_ends() {
        // From the cap one way to the cap the other: the mean force is zero, and so is the work
        // central differences remove.
        let (f, ut, w) = capped_spring(2e-3, -5e-3, 1e6, 1e6, 2e3);
        assert_eq!((f, ut), (-2e3, -2e-3));
        assert_eq!(w, 0.0);
        // Reaching the cap from below: the mean of the last and the capped force on the slip.
        let (_, _, w) = capped_spring(1e-3, 2e-3, 1e6, 1e6, 2e3);
        assert!((w - 1.5e3 * 1e-3).abs() < 1e-12, "{w}");
    }

    #[test]
    fn zero_limit_carries_no_force() {
        assert_eq!(capped_spring(0.0, 5e-4, 1e6, 1e6, 0.0).0, 0.0);
    }
}
