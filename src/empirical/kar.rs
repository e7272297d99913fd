//! Kar (1978): NDRC with a missile-modulus factor and an aggregate term, FORMULAS §3.6.
//!
//! ```text
//! G = 180/√f'c · N (E/E_s)^1.25 (W/D) (V/(1000 D))^1.8,   x/d from G as NDRC
//! β (h_s − a)/d = Kennedy h_s/d(x/d),   β (h_p − a)/d = Kennedy h_p/d(x/d),   β = (E/E_s)^0.2
//! ```
//! E the missile's Young's modulus, E_s that of mild steel (`super::inputs`
//! `MILD_STEEL_MODULUS_PSI`), a half the maximum aggregate size. For a steel missile x is NDRC's
//! and h = a + d·f(x/d). Validity: that of the Kennedy relations. Confidence: Medium–Low (the
//! half-aggregate a and both exponents are recollection).

use super::MILD_STEEL_MODULUS_PSI;
use super::{Missile, Target, kennedy, ndrc};

/// Modulus ratio E/E_s.
pub fn modulus_ratio(m: &Missile) -> f64 {
    m.modulus_psi / MILD_STEEL_MODULUS_PSI
}

/// β = (E/E_s)^0.2.
pub fn beta(m: &Missile) -> f64 {
    modulus_ratio(m).powf(0.2)
}

/// Kar's aggregate term a = half the maximum aggregate size, in.
pub fn aggregate_term_in(t: &Target) -> f64 {
    t.aggregate_in / 2.0
}

/// Penetration ratio x/d.
pub fn penetration_ratio(m: &Missile, t: &Target, v_fps: f64) -> f64 {
    ndrc::xd_from_g(ndrc::g_function(m, t, v_fps, modulus_ratio(m)))
}

/// Scabbing thickness h_s, in, from the penetration ratio.
pub fn scabbing_in(m: &Missile, t: &Target, xd: f64) -> f64 {
    aggregate_term_in(t) + m.diameter_in * kennedy::hs_over_d(xd) / beta(m)
}

/// Perforation thickness h_p, in, from the penetration ratio.
pub fn perforation_in(m: &Missile, t: &Target, xd: f64) -> f64 {
    aggregate_term_in(t) + m.diameter_in * kennedy::hp_over_d(xd) / beta(m)
}

/// The Kennedy ratio h/d that a Kar thickness `h_in` corresponds to: β (h − a)/d.
pub fn kennedy_ratio(m: &Missile, t: &Target, h_in: f64) -> f64 {
    beta(m) * (h_in - aggregate_term_in(t)) / m.diameter_in
}
