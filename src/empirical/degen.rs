//! Degen (1980) perforation thickness, chained on the Modified-NDRC depth; FORMULAS §3.5,
//! DOE-STD-3014-96 eqs C.6-13, C.6-14 (verbatim).
//!
//! ```text
//! h_p/d = 2.2 (x/d) − 0.3 (x/d)²    x/d ≤ 1.52                      (C.6-14)
//! h_p/d = 0.69 + 1.29 (x/d)         2.65 ≤ h_p/d ≤ 18 (x/d ≥ 1.52)   (C.6-13)
//! ```
//! Test-base validity (recollection): 25 ≤ V ≤ 311.8 m/s, 28.4 ≤ f'c ≤ 43.1 MPa; and h_p/d ≤ 18.
//! The branches join at 2.651 (the quadratic is 8e-5 d above the line: a negligible drop).
//! DOE's design factor 1.2 h_p is not applied. Confidence: High (equations), Medium (ranges).

use super::Validity;
use super::kennedy::smaller_root;

/// x/d at which the quadratic hands over to the line.
pub const BREAK_XD: f64 = 1.52;
/// Upper end of the linear fit (h_p/d = 18).
pub const MAX_HD: f64 = 18.0;

/// Perforation ratio h_p/d from the NDRC penetration ratio x/d.
pub fn hp_over_d(xd: f64) -> f64 {
    if xd <= BREAK_XD { 2.2 * xd - 0.3 * xd * xd } else { 0.69 + 1.29 * xd }
}

/// The x/d at which [`hp_over_d`] first reaches `hd` (closed form, FORMULAS §5).
pub fn xd_for_hp(hd: f64) -> f64 {
    if hd <= hp_over_d(BREAK_XD) { smaller_root(-0.3, 2.2, hd) } else { (hd - 0.69) / 1.29 }
}

/// Validity of Degen's test base at impact velocity `v_mps` (m/s), strength `fc_mpa` (MPa) and
/// predicted ratio `hd`.
pub fn validity(v_mps: f64, fc_mpa: f64, hd: f64) -> Validity {
    Validity::all([
        Validity::range("V", v_mps, 25.0, 311.8, "m/s"),
        Validity::range("f'c", fc_mpa, 28.4, 43.1, "MPa"),
        Validity::range("h_p/d", hd, 0.0, MAX_HD, ""),
    ])
}
