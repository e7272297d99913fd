//! CEA-EDF (Berriaud et al. 1978; Fiquet & Dacquet 1977) perforation, and its reinforcement
//! extension (Fullard et al. 1991 / UKAEA), FORMULAS §3.10. Dimensionless; evaluated in SI.
//!
//! ```text
//! h_p/d = 0.82 M^0.5 V^0.75 / (ρ_c^0.125 fc^0.375 d^1.5)
//! V_p   = 1.3 ρ_c^(1/6) fc^(1/2) (d h²/M)^(2/3)                        (exact inverse)
//! V_p   = 1.3 ρ_c^(1/6) fc^(1/2) (p h²/(π M))^(2/3) (r + 0.3)^(1/2) [1.2 − 0.6 c_r/h]   (extension)
//! ```
//! The two base forms are exact inverses with 0.82 = 1.3^-0.75 (= 0.82144) rounded, so the
//! forward form here uses 1.3^-0.75: with 0.82 itself the forward and closed-form limits would
//! differ by 0.23 %. In the extension p = π d (perimeter), r = reinforcement % each way each face,
//! c_r = rebar spacing (0.12 ≤ c_r/h ≤ 0.49); at r = 0.7 % and c_r/h = 1/3 it is the base formula.
//! Validity: 20 ≤ V ≤ 200 m/s. Confidence: Medium–High (base), Low (extension).

use super::{Missile, Target, Validity};
use crate::units;

/// The V_p coefficient.
pub const VP_COEFFICIENT: f64 = 1.3;

/// The printed h_p coefficient 0.82 is this value rounded.
pub fn hp_coefficient() -> f64 {
    VP_COEFFICIENT.powf(-0.75)
}

/// Reinforcement of the extension: `r_percent` each way each face, spacing ratio c_r/h.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reinforcement {
    /// r, % each way each face.
    pub r_percent: f64,
    /// c_r/h, rebar spacing over wall thickness.
    pub spacing_over_thickness: f64,
}

impl Reinforcement {
    /// Plain concrete in the extension: r = 0, with c_r/h = 1/3 — the spacing at which the
    /// extension equals the base formula at r = 0.7 %, so only the (r + 0.3)^½ term acts
    /// (V_p × √0.3 = × 0.548, FORMULAS §3.10).
    pub const PLAIN: Reinforcement = Reinforcement { r_percent: 0.0, spacing_over_thickness: 1.0 / 3.0 };

    /// The extension's factor on the base V_p: (r + 0.3)^½ [1.2 − 0.6 c_r/h].
    pub fn velocity_factor(&self) -> f64 {
        (self.r_percent + 0.3).sqrt() * (1.2 - 0.6 * self.spacing_over_thickness)
    }
}

/// Base perforation thickness h_p, in, at `v_fps`.
pub fn perforation_in(m: &Missile, t: &Target, v_fps: f64) -> f64 {
    let d = m.diameter_m();
    let v = units::fps_to_mps(v_fps);
    let hd = hp_coefficient() * m.mass_kg().sqrt() * v.powf(0.75)
        / (t.density_kg_per_m3().powf(0.125) * t.fc_pa().powf(0.375) * d.powf(1.5));
    hd * m.diameter_in
}

/// Base ballistic limit V_p, ft/s, for thickness `h_in` (closed form).
pub fn ballistic_limit_fps(m: &Missile, t: &Target, h_in: f64) -> f64 {
    let h = units::in_to_m(h_in);
    let v = VP_COEFFICIENT
        * t.density_kg_per_m3().powf(1.0 / 6.0)
        * t.fc_pa().sqrt()
        * (m.diameter_m() * h * h / m.mass_kg()).powf(2.0 / 3.0);
    units::mps_to_fps(v)
}

/// Extension h_p, in: the base thickness at the velocity the extension scales to, since
/// V_p,ext(h) = factor × V_p,base(h) and h_p,base ∝ V^0.75.
pub fn extension_perforation_in(m: &Missile, t: &Target, v_fps: f64, reinf: Reinforcement) -> f64 {
    perforation_in(m, t, v_fps / reinf.velocity_factor())
}

/// Extension ballistic limit V_p, ft/s (closed form; with p = π d, p/π = d).
pub fn extension_ballistic_limit_fps(m: &Missile, t: &Target, h_in: f64, reinf: Reinforcement) -> f64 {
    reinf.velocity_factor() * ballistic_limit_fps(m, t, h_in)
}

/// Validity: 20 ≤ V ≤ 200 m/s.
pub fn validity(v_fps: f64) -> Validity {
    Validity::range("V", units::fps_to_mps(v_fps), 20.0, 200.0, "m/s")
}
