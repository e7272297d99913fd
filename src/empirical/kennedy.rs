//! Kennedy's scabbing and perforation relations on the penetration ratio x/d (Kennedy 1976;
//! DOE-STD-3014-96 eqs C.6-5, C.6-6), FORMULAS §3.4. Used with the Modified-NDRC, ACE and Kar
//! penetration depths; the linear parts are the ACE fits.
//!
//! ```text
//! h_s/d = 7.91 (x/d) − 5.06 (x/d)²     x/d ≤ 0.65           (DOE C.6-6)
//! h_s/d = 2.12 + 1.36 (x/d)            0.65 ≤ x/d ≤ 11.75    (DOE C.6-5)
//! h_p/d = 3.19 (x/d) − 0.718 (x/d)²    x/d ≤ 1.35
//! h_p/d = 1.32 + 1.24 (x/d)            1.35 ≤ x/d ≤ 13.5     (\[THESIS\], verbatim)
//! ```
//! Validity: 3 ≤ h/d ≤ 18 for the linear fits, i.e. x/d ≤ 11.75 (h_s) and x/d ≤ 13.5 (h_p); the
//! quadratics cover the small-penetration end. The branches join to 4 digits (3.004/3.004 at 0.65;
//! 2.998/2.994 at 1.35, a drop of 0.004 d that makes h_p very slightly non-monotone there).
//! Confidence: High (h_p quadratic pinned by continuity only).

use super::Validity;

/// x/d at which h_s switches from the quadratic to the linear fit.
pub const HS_BREAK_XD: f64 = 0.65;
/// Upper end of the h_s linear fit (h_s/d = 18).
pub const HS_MAX_XD: f64 = 11.75;
/// x/d at which h_p switches from the quadratic to the linear fit.
pub const HP_BREAK_XD: f64 = 1.35;
/// Upper end of the h_p linear fit (h_p/d = 18).
pub const HP_MAX_XD: f64 = 13.5;

/// Scabbing ratio h_s/d from the penetration ratio x/d.
pub fn hs_over_d(xd: f64) -> f64 {
    if xd <= HS_BREAK_XD { 7.91 * xd - 5.06 * xd * xd } else { 2.12 + 1.36 * xd }
}

/// Perforation ratio h_p/d from the penetration ratio x/d.
pub fn hp_over_d(xd: f64) -> f64 {
    if xd <= HP_BREAK_XD { 3.19 * xd - 0.718 * xd * xd } else { 1.32 + 1.24 * xd }
}

/// The x/d at which [`hs_over_d`] first reaches `hd` (closed form, FORMULAS §5). Inside the
/// branch gap (3.0037 < h/d < 3.004, never attained) it returns the break point.
pub fn xd_for_hs(hd: f64) -> f64 {
    if hd >= hs_over_d_linear(HS_BREAK_XD) {
        (hd - 2.12) / 1.36
    } else {
        smaller_root(-5.06, 7.91, hd).min(HS_BREAK_XD)
    }
}

/// The x/d at which [`hp_over_d`] first reaches `hd` (closed form, FORMULAS §5). Where the
/// quadratic's value at the break (2.998) exceeds the linear one (2.994), the quadratic is
/// reached first, so the quadratic is tried first.
pub fn xd_for_hp(hd: f64) -> f64 {
    if hd <= hp_over_d(HP_BREAK_XD) {
        smaller_root(-0.718, 3.19, hd)
    } else {
        (hd - 1.32) / 1.24
    }
}

fn hs_over_d_linear(xd: f64) -> f64 {
    2.12 + 1.36 * xd
}

/// Smaller non-negative root of a x² + b x = y (a < 0 < b), i.e. the rising side of the parabola.
pub(crate) fn smaller_root(a: f64, b: f64, y: f64) -> f64 {
    let disc = (b * b + 4.0 * a * y).max(0.0);
    // Stable form of (−b + √disc)/(2a): no cancellation when y is small.
    2.0 * y / (b + disc.sqrt())
}

/// Validity of the h_s relation at `xd`.
pub fn hs_validity(xd: f64) -> Validity {
    Validity::range("x/d (Kennedy h_s)", xd, 0.0, HS_MAX_XD, "")
}

/// Validity of the h_p relation at `xd`.
pub fn hp_validity(xd: f64) -> Validity {
    Validity::range("x/d (Kennedy h_p)", xd, 0.0, HP_MAX_XD, "")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closed_inverses_invert() {
        for hd in [0.1, 1.0, 2.5, 2.99, 3.1, 8.57, 17.0] {
            let xs = xd_for_hs(hd);
            assert!((hs_over_d(xs) - hd).abs() < 1e-12, "h_s {hd}");
            let xp = xd_for_hp(hd);
            assert!((hp_over_d(xp) - hd).abs() < 1e-12, "h_p {hd}");
        }
    }
}
