//! Normal part: bonded (tension and compression, tensile plateau, Fig 2.3 and Fig 5.4a) and
//! frictional (compression only, Fig 2.4a).

use crate::kernel::lanes::Real;

/// Bonded normal spring with a tensile plateau at `plateau_n` (∞ for no yield) and plastic
/// opening history `dp` (m). `opening_m` = d − d0 (> 0 in tension), `step_m` its change over
/// this step, `kn_last` the stiffness the spring had in the last step. Unloading from the plateau follows the initial slope (seed §5). Returns (normal
/// force N, tension positive; plastic work of this step J). Updates `dp`.
///
/// The work is the plastic opening times the mean of the last step's force and the new one,
/// as for the tangential cap (`tangential::capped_spring`): that is what central differences
/// take out of the kinetic energy, also when the plateau itself moves during the step (a
/// rate-enhanced plateau decaying with the held rate).
#[inline(always)]
pub fn bonded(opening_m: f64, step_m: f64, dp: &mut f64, kn: f64, kn_last: f64, plateau_n: f64) -> (f64, f64) {
    let (f, below) = elastic(opening_m, *dp, kn, plateau_n);
    if below {
        (f, 0.0)
    } else {
        let dp_new = opening_m - plateau_n / kn;
        let last = kn_last * (opening_m - step_m - *dp);
        let work = 0.5 * (last + plateau_n) * (dp_new - *dp);
        *dp = dp_new;
        (plateau_n, work)
    }
}

/// The bonded normal spring's elastic branch: the force Kn (opening − δ_p), N (tension
/// positive), and where it stays at or below the plateau `plateau_n` (N), where [`bonded`] keeps
/// it.
#[inline(always)]
pub fn elastic<R: Real>(opening_m: R, dp_m: R, kn: R, plateau_n: R) -> (R, R::Mask) {
    let f = kn * (opening_m - dp_m);
    (f, f.le(plateau_n))
}

/// Frictional normal spring: compression only, N. `opening_m` = d − d0 < 0 when touching.
#[inline(always)]
pub fn frictional<R: Real>(opening_m: R, kn: R) -> R {
    kn * opening_m.min(R::zero())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plateau_then_unloading_at_initial_slope() {
        let (kn, cap) = (1e6, 10.0);
        let mut dp = 0.0;
        assert_eq!(bonded(5e-6, 5e-6, &mut dp, kn, kn, cap), (5.0, 0.0));
        // From 5 µm (5 N) to 30 µm: the plateau at 10 N is reached half-way through the
        // elastic part; the work is the plastic opening (20 µm) times the mean of 5 N and 10 N.
        let (f, w) = bonded(30e-6, 25e-6, &mut dp, kn, kn, cap);
        assert_eq!(f, 10.0);
        assert!((dp - 20e-6).abs() < 1e-18 && (w - 7.5 * 20e-6).abs() < 1e-15, "{w}");
        // On along the plateau: the plateau times the opening.
        let (_, w) = bonded(32e-6, 2e-6, &mut dp, kn, kn, cap);
        assert!((w - 10.0 * 2e-6).abs() < 1e-15);
        // Unload by 4 µm: force drops by Kn × 4 µm.
        let (f, w) = bonded(28e-6, -4e-6, &mut dp, kn, kn, cap);
        assert!((f - 6.0).abs() < 1e-9 && w == 0.0);
        // The plateau falls to 4 N at a fixed configuration: the energy the spring gives up,
        // (6² − 4²)/(2 Kn), is the work.
        let (f, w) = bonded(28e-6, 0.0, &mut dp, kn, kn, 4.0);
        assert!((f - 4.0).abs() < 1e-12 && (w - (36.0 - 16.0) / (2.0 * kn)).abs() < 1e-15, "{w}");
        // Compression is linear and unlimited.
        assert!((bonded(-1e-3, -1e-3, &mut dp, kn, kn, cap).0 + kn * (1e-3 + dp)).abs() < 1e-6);
    }

    #[test]
    fn frictional_pushes_only() {
        assert_eq!(frictional(1e-3, 1e6), 0.0);
        assert_eq!(frictional(-1e-3, 1e6), -1e3);
    }
}
