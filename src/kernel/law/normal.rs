//! Normal part: bonded (tension and compression, tensile plateau, Fig 2.3 and Fig 5.4a) and
//! frictional (compression only, Fig 2.4a).

/// Bonded normal spring with a tensile plateau at `plateau_n` (∞ for no yield) and plastic
/// opening history `dp` (m). `opening_m` = d − d0 (> 0 in tension). Unloading from the plateau
/// follows the initial slope (seed §5). Returns (normal force N, tension positive; plastic work
/// of this step J). Updates `dp`.
#[inline(always)]
pub fn bonded(opening_m: f64, dp: &mut f64, kn: f64, plateau_n: f64) -> (f64, f64) {
    let f = kn * (opening_m - *dp);
    if f <= plateau_n {
        (f, 0.0)
    } else {
        let dp_new = opening_m - plateau_n / kn;
        let work = plateau_n * (dp_new - *dp);
        *dp = dp_new;
        (plateau_n, work)
    }
}

/// Frictional normal spring: compression only. `opening_m` = d − d0 < 0 when touching.
#[inline(always)]
pub fn frictional(opening_m: f64, kn: f64) -> f64 {
    kn * opening_m.min(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plateau_then_unloading_at_initial_slope() {
        let (kn, cap) = (1e6, 10.0);
        let mut dp = 0.0;
        assert_eq!(bonded(5e-6, &mut dp, kn, cap), (5.0, 0.0));
        let (f, w) = bonded(30e-6, &mut dp, kn, cap);
        assert_eq!(f, 10.0);
        assert!((dp - 20e-6).abs() < 1e-18 && (w - 10.0 * 20e-6).abs() < 1e-15);
        // Unload by 4 µm: force drops by Kn × 4 µm.
        let (f, w) = bonded(26e-6, &mut dp, kn, cap);
        assert!((f - 6.0).abs() < 1e-9 && w == 0.0);
        // Compression is linear and unlimited.
        assert!((bonded(-1e-3, &mut dp, kn, cap).0 + kn * (1e-3 + 20e-6)).abs() < 1e-6);
    }

    #[test]
    fn frictional_pushes_only() {
        assert_eq!(frictional(1e-3, 1e6), 0.0);
        assert_eq!(frictional(-1e-3, 1e6), -1e3);
    }
}
