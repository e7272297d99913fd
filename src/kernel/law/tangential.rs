//! Tangential part: an elastic spring Kt on the incremental tangential displacement, capped by
//! a plastic limit. The same return map serves the bond's shear plateau (limit f_t^crit,
//! eq 5.6) and Coulomb sliding with cohesion (limit −μ Fn + c, eq 2.1).

/// Return map of a tangential spring. `ut_trial` is the elastic displacement after adding this
/// step's increment (m). Returns (force N, new elastic displacement m, dissipated energy J).
#[inline(always)]
pub fn capped_spring(ut_trial: f64, kt: f64, limit_n: f64) -> (f64, f64, f64) {
    let f = kt * ut_trial;
    if f.abs() <= limit_n {
        (f, ut_trial, 0.0)
    } else {
        let capped = limit_n.copysign(f);
        let ut = capped / kt;
        // Work done by the cap on the slip ut_trial − ut.
        (capped, ut, limit_n * (ut_trial - ut).abs())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elastic_below_the_limit_and_capped_above() {
        assert_eq!(capped_spring(1e-3, 1e6, 2e3), (1e3, 1e-3, 0.0));
        let (f, ut, w) = capped_spring(-3e-3, 1e6, 2e3);
        assert_eq!(f, -2e3);
        assert_eq!(ut, -2e-3);
        assert!((w - 2e3 * 1e-3).abs() < 1e-12);
    }

    #[test]
    fn zero_limit_carries_no_force() {
        assert_eq!(capped_spring(5e-4, 1e6, 0.0).0, 0.0);
    }
}
