//! Hughes (1984), FORMULAS §3.14. Dimensionless; SI here.
//!
//! ```text
//! I_h = M V²/(d³ f_t),   S = 1 + 12.3 ln(1 + 0.03 I_h)
//! x/d = 0.19 N_h I_h / S
//! h_p/d = 3.6 x/d  (x/d < 0.7);   1.58 x/d + 1.4  (x/d ≥ 0.7)
//! h_s/d = 5.0 x/d  (x/d < 0.7);   1.74 x/d + 2.3  (x/d ≥ 0.7)
//! ```
//! f_t the concrete tensile strength: the report's value, or the modulus of rupture
//! 0.63 √σc (MPa) that \[LEPP\] specifies. Branches join at x/d = 0.7 as 2.520/2.506 (h_p: a small
//! drop) and 3.500/3.518 (h_s). Validity: I_h ≤ 3500 (test range 40–3500 \[LEPP\]; "I < 40
//! corresponds to h/d < 3.5 and x/d < 0.7"). Confidence: High (x), Medium–High (h_s, h_p).

use super::{Missile, Target, Validity};
use crate::units;

/// x/d at which the h_s and h_p relations change branch.
pub const BREAK_XD: f64 = 0.7;
/// Upper end of the test base.
pub const MAX_I: f64 = 3500.0;

/// Modulus of rupture σ_t = 0.63 √σc (MPa), returned in psi.
pub fn modulus_of_rupture_psi(t: &Target) -> f64 {
    let fc_mpa = t.fc_pa() / 1e6;
    units::pa_to_psi(0.63 * fc_mpa.sqrt() * 1e6)
}

/// Hughes impact factor I_h = M V²/(d³ f_t) with f_t = `ft_psi`.
pub fn impact_factor(m: &Missile, v_fps: f64, ft_psi: f64) -> f64 {
    let v = units::fps_to_mps(v_fps);
    m.mass_kg() * v * v / (m.diameter_m().powi(3) * units::psi_to_pa(ft_psi))
}

/// Penetration ratio x/d from I_h and the nose factor N_h.
pub fn xd_from_impact(i: f64, nose_factor: f64) -> f64 {
    let s = 1.0 + 12.3 * (0.03 * i).ln_1p();
    0.19 * nose_factor * i / s
}

/// Scabbing ratio h_s/d.
pub fn hs_over_d(xd: f64) -> f64 {
    if xd < BREAK_XD { 5.0 * xd } else { 1.74 * xd + 2.3 }
}

/// Perforation ratio h_p/d.
pub fn hp_over_d(xd: f64) -> f64 {
    if xd < BREAK_XD { 3.6 * xd } else { 1.58 * xd + 1.4 }
}

/// Validity: I_h ≤ 3500.
pub fn validity(i: f64) -> Validity {
    Validity::range("I_h", i, 0.0, MAX_I, "")
}
