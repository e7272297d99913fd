//! Modified NDRC (NDRC 1946; modified form as given by Kennedy 1976), FORMULAS §3.4.
//!
//! ```text
//! G = K N (W/D) (V/(1000 D))^1.8,   K = 180/√f'c      [W lb, D in, V ft/s, f'c psi]
//! x/d = 2 √G     G ≤ 1
//! x/d = G + 1    G > 1
//! ```
//! SI: G = 3.8e-5 N M/(d √fc) (V/d)^1.8. h_s and h_p follow from x/d through Kennedy's relations
//! ([`super::kennedy`]); DOE's design factors (1.1 h_s, 1.2 h_p) are not applied. Validity: that
//! of the Kennedy relations. Sources: G and x/d verbatim \[THESIS\]. Confidence: High.

use super::{Missile, Target};

/// NDRC coefficient (K = 180/√f'c).
pub const COEFFICIENT: f64 = 180.0;
/// Velocity exponent of G.
pub const VELOCITY_EXPONENT: f64 = 1.8;

/// The NDRC impact function G for a missile with Young's-modulus ratio `modulus_ratio` = E/E_s
/// raised to Kar's 1.25 (pass 1 for plain NDRC and steel missiles).
pub fn g_function(m: &Missile, t: &Target, v_fps: f64, modulus_ratio: f64) -> f64 {
    COEFFICIENT / t.fc_psi.sqrt()
        * m.nose.ndrc_factor()
        * modulus_ratio.powf(1.25)
        * m.weight_lb
        / m.diameter_in
        * (v_fps / (1000.0 * m.diameter_in)).powf(VELOCITY_EXPONENT)
}

/// Penetration ratio x/d from G.
pub fn xd_from_g(g: f64) -> f64 {
    if g <= 1.0 { 2.0 * g.sqrt() } else { g + 1.0 }
}

/// G from the penetration ratio x/d (inverse of [`xd_from_g`], FORMULAS §5).
pub fn g_from_xd(xd: f64) -> f64 {
    if xd <= 2.0 { (xd / 2.0).powi(2) } else { xd - 1.0 }
}

/// Velocity, ft/s, at which G reaches `g` (closed form, FORMULAS §5), for E/E_s = `modulus_ratio`.
pub fn velocity_for_g_fps(m: &Missile, t: &Target, g: f64, modulus_ratio: f64) -> f64 {
    let per_v = g_function(m, t, 1000.0 * m.diameter_in, modulus_ratio);
    1000.0 * m.diameter_in * (g / per_v).powf(1.0 / VELOCITY_EXPONENT)
}

/// Penetration ratio x/d of the Modified NDRC formula (steel missile).
pub fn penetration_ratio(m: &Missile, t: &Target, v_fps: f64) -> f64 {
    xd_from_g(g_function(m, t, v_fps, 1.0))
}
