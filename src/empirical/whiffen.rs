//! Whiffen (British Road Research Laboratory, 1943), FORMULAS §3.8.
//!
//! ```text
//! x = (870/√σc) (W/D²) (D/c)^0.1 (V/1750)^n,   n = 10.7/σc^0.25     [in; W lb, D in, V ft/s, σc psi, c in]
//! ```
//! c = maximum aggregate size. SI: x/d = (2.61/√fc)(M/d³)(d/c)^0.1 (V/533.4)^n, n = 97.51/fc^0.25.
//! Defines x only. Validity \[LEPP\]: σc 800–10 000 psi, W 0.3–22 000 lb, D 0.5–38 in, D/c 0.5–50,
//! V 0–3700 ft/s (ogival noses, ±15 % scatter). Confidence: High.

use super::{Missile, Target, Validity};

/// Velocity exponent n = 10.7/σc^0.25 (σc psi).
pub fn velocity_exponent(t: &Target) -> f64 {
    10.7 / t.fc_psi.powf(0.25)
}

/// Penetration depth x, in.
pub fn penetration_in(m: &Missile, t: &Target, v_fps: f64) -> f64 {
    870.0 / t.fc_psi.sqrt() * m.weight_lb / (m.diameter_in * m.diameter_in)
        * (m.diameter_in / t.aggregate_in).powf(0.1)
        * (v_fps / 1750.0).powf(velocity_exponent(t))
}

/// Validity against \[LEPP\]'s ranges.
pub fn validity(m: &Missile, t: &Target, v_fps: f64) -> Validity {
    Validity::all([
        Validity::range("σc", t.fc_psi, 800.0, 10_000.0, "psi"),
        Validity::range("W", m.weight_lb, 0.3, 22_000.0, "lb"),
        Validity::range("D", m.diameter_in, 0.5, 38.0, "in"),
        Validity::range("D/c", m.diameter_in / t.aggregate_in, 0.5, 50.0, ""),
        Validity::range("V", v_fps, 0.0, 3700.0, "ft/s"),
    ])
}
