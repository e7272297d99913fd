//! BRL — Ballistic Research Laboratory (1941; Chelapati, Kennedy & Wall 1972), FORMULAS §3.2.
//!
//! ```text
//! X   = (427/√f'c) (W/D^1.8) (V/1000)^1.33      [in; W lb, D in, V ft/s, f'c psi]
//! h_p = 1.3 X
//! h_s = 2 h_p (= 2.6 X)   default: the source report derives BRL scabbing from perforation
//! h_s = 2 X               alternative reading found in secondary summaries
//! ```
//! SI: x/d = (1.33e-3/√fc)(M/d³) d^0.2 V^1.33. Validity: none stated. Confidence: High (x, h_p;
//! verbatim in \[THESIS\]), Low (h_s: no retrieved source states it, hence both variants).

use super::{Missile, Target};

/// BRL coefficient, in·psi^½ / (lb·in^-1.8) with V in units of 1000 ft/s.
pub const COEFFICIENT: f64 = 427.0;
/// Velocity exponent.
pub const VELOCITY_EXPONENT: f64 = 1.33;
/// Diameter exponent.
pub const DIAMETER_EXPONENT: f64 = 1.8;

/// Penetration depth X, in.
pub fn penetration_in(m: &Missile, t: &Target, v_fps: f64) -> f64 {
    COEFFICIENT / t.fc_psi.sqrt() * m.weight_lb / m.diameter_in.powf(DIAMETER_EXPONENT)
        * (v_fps / 1000.0).powf(VELOCITY_EXPONENT)
}

/// Perforation thickness h_p = 1.3 X, in.
pub fn perforation_in(x_in: f64) -> f64 {
    1.3 * x_in
}

/// Scabbing thickness, default reading h_s = 2 h_p, in.
pub fn scabbing_twice_perforation_in(x_in: f64) -> f64 {
    2.0 * perforation_in(x_in)
}

/// Scabbing thickness, alternative reading h_s = 2 X, in.
pub fn scabbing_twice_penetration_in(x_in: f64) -> f64 {
    2.0 * x_in
}
