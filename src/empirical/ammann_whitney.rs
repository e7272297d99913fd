//! Ammann & Whitney: penetration of high-velocity explosively generated fragments,
//! FORMULAS §3.7.
//!
//! ```text
//! X = (282/√f'c) N (W/D^1.785) (V/1000)^1.8      [in; W lb, D in, V ft/s, f'c psi]
//! ```
//! SI (derived): x/d = 6.30e-5 (N/√fc)(M/d³) d^0.215 V^1.8. Defines x only. Validity: none stated.
//! Confidence: **Low** — the form is recalled by analogy with ACE, and a recalled SI coefficient
//! "6 × 10⁻⁴" would be 10× larger. Not used for acceptance tests.

use super::{Missile, Target};

/// Penetration depth X, in.
pub fn penetration_in(m: &Missile, t: &Target, v_fps: f64) -> f64 {
    282.0 / t.fc_psi.sqrt() * m.nose.ndrc_factor() * m.weight_lb / m.diameter_in.powf(1.785)
        * (v_fps / 1000.0).powf(1.8)
}
