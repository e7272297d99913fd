//! Bechtel (topical report BC-TOP-9A Rev. 2, Sept. 1974, Linderman, Rotz & Yeh) scabbing
//! thickness for solid steel missiles, FORMULAS §3.15.
//!
//! ```text
//! h_s = 15.5 W^0.4 V^0.5 / (√f'c D^0.2)     [in; W lb, V ft/s, f'c psi, D in]
//! ```
//! SI: h_s = 38.98 M^0.4 V^0.5/(fc^0.5 d^0.2). Direct; h_s only. The steel-pipe form
//! (5.42 W^0.4 V^0.65 …, Low confidence) is not used. Validity: none stated.
//! Confidence: Medium.

use super::{Missile, Target};

/// Solid-missile coefficient.
pub const COEFFICIENT: f64 = 15.5;

/// Scabbing thickness h_s, in.
pub fn scabbing_in(m: &Missile, t: &Target, v_fps: f64) -> f64 {
    COEFFICIENT * m.weight_lb.powf(0.4) * v_fps.sqrt() / (t.fc_psi.sqrt() * m.diameter_in.powf(0.2))
}

/// Velocity, ft/s, at which h_s = `h_in` (closed form).
pub fn scabbing_velocity_fps(m: &Missile, t: &Target, h_in: f64) -> f64 {
    (h_in * t.fc_psi.sqrt() * m.diameter_in.powf(0.2) / (COEFFICIENT * m.weight_lb.powf(0.4))).powi(2)
}
