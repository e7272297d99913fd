//! Chang (1981) scabbing and perforation thickness, FORMULAS §3.11. Dimensionless; SI here.
//!
//! ```text
//! h_p/d = (u/V)^0.25 (M V²/(d³ fc))^0.5
//! h_s/d = 1.84 (u/V)^0.13 (M V²/(d³ fc))^0.4,     u = 200 ft/s (= 60.96 m/s; SI texts: 61 m/s)
//! ```
//! Direct (not chained on x). Validity (recollection): 16.7 ≤ V ≤ 311.8 m/s, 0.11 ≤ M ≤ 343 kg,
//! 0.0508 ≤ d ≤ 0.3048 m, 22.8 ≤ fc ≤ 45.5 MPa. CRIEPI and NEI 07-13 factors are not applied.
//! Confidence: Medium (recollection only).

use super::{Missile, Target, Validity};
use crate::units;

/// Chang's reference velocity u, ft/s.
pub const U_FPS: f64 = 200.0;

/// Q = M/(d³ fc), s²/m² (so that Q V² is Chang's dimensionless energy term).
pub fn q_s2_per_m2(m: &Missile, t: &Target) -> f64 {
    m.mass_kg() / (m.diameter_m().powi(3) * t.fc_pa())
}

/// Perforation thickness h_p, in.
pub fn perforation_in(m: &Missile, t: &Target, v_fps: f64) -> f64 {
    let energy = q_s2_per_m2(m, t) * units::fps_to_mps(v_fps).powi(2);
    m.diameter_in * (U_FPS / v_fps).powf(0.25) * energy.powf(0.5)
}

/// Scabbing thickness h_s, in.
pub fn scabbing_in(m: &Missile, t: &Target, v_fps: f64) -> f64 {
    let energy = q_s2_per_m2(m, t) * units::fps_to_mps(v_fps).powi(2);
    m.diameter_in * 1.84 * (U_FPS / v_fps).powf(0.13) * energy.powf(0.4)
}

/// Velocity, ft/s, at which h_p = `h_in` (closed form: V^0.75 = (h_p/d)/(u^0.25 Q^0.5)).
pub fn ballistic_limit_fps(m: &Missile, t: &Target, h_in: f64) -> f64 {
    let u = units::fps_to_mps(U_FPS);
    let v = (h_in / m.diameter_in / (u.powf(0.25) * q_s2_per_m2(m, t).sqrt())).powf(1.0 / 0.75);
    units::mps_to_fps(v)
}

/// Velocity, ft/s, at which h_s = `h_in` (closed form: V^0.67 = (h_s/d)/(1.84 u^0.13 Q^0.4)).
pub fn scabbing_velocity_fps(m: &Missile, t: &Target, h_in: f64) -> f64 {
    let u = units::fps_to_mps(U_FPS);
    let v = (h_in / m.diameter_in / (1.84 * u.powf(0.13) * q_s2_per_m2(m, t).powf(0.4))).powf(1.0 / 0.67);
    units::mps_to_fps(v)
}

/// Validity (recollected ranges).
pub fn validity(m: &Missile, t: &Target, v_fps: f64) -> Validity {
    Validity::all([
        Validity::range("V", units::fps_to_mps(v_fps), 16.7, 311.8, "m/s"),
        Validity::range("M", m.mass_kg(), 0.11, 343.0, "kg"),
        Validity::range("d", m.diameter_m(), 0.0508, 0.3048, "m"),
        Validity::range("f'c", t.fc_pa() / 1e6, 22.8, 45.5, "MPa"),
    ])
}
