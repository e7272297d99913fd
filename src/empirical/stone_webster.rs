//! Stone & Webster scabbing thickness, FORMULAS §3.16 (original report attribution not verified).
//!
//! ```text
//! h_s = (W V² / C)^(1/3)       [in; W lb, V ft/s]
//! ```
//! C an empirical coefficient, recalled as ~900–1900 and a function of h/d; both ends are
//! variants. Validity (recollection): h/d ≈ 1.5–3, f'c ≈ 3000–4500 psi. Confidence: Low.

use super::{Missile, Target, Validity};

/// Scabbing thickness h_s, in, with coefficient `c`.
pub fn scabbing_in(m: &Missile, v_fps: f64, c: f64) -> f64 {
    (m.weight_lb * v_fps * v_fps / c).cbrt()
}

/// Velocity, ft/s, at which h_s = `h_in` (closed form V = √(C h³/W)).
pub fn scabbing_velocity_fps(m: &Missile, h_in: f64, c: f64) -> f64 {
    (c * h_in.powi(3) / m.weight_lb).sqrt()
}

/// Validity: the wall's h/d and f'c against the recalled ranges.
pub fn validity(m: &Missile, t: &Target) -> Validity {
    Validity::all([
        Validity::range("h/d", t.thickness_in / m.diameter_in, 1.5, 3.0, ""),
        Validity::range("f'c", t.fc_psi, 3000.0, 4500.0, "psi"),
    ])
}
