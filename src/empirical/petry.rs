//! Modified Petry (Petry 1910; Amirikian 1950; as in Kennedy 1976), FORMULAS §3.1.
//!
//! ```text
//! X   = 12 K_p A_p log10(1 + V²/215000)      [in]   A_p = W/A [lb/ft²], A = π(D/12)²/4 [ft²]
//! h_p = 2 X,   h_s = 2.2 X
//! ```
//! W lb, D in, V ft/s, K_p ft³/lb. Validity: none stated beyond the test base (DOE-STD-3014:
//! "limited range of test data"). Confidence: Medium (x, h_p), Medium–Low (h_s = 2.2 X).
//! Chained: h_s and h_p follow from x.

use super::Missile;

/// Velocity scale of the Petry log term, ft²/s² (SI: 19 974 m²/s²).
pub const V2_SCALE_FPS2: f64 = 215_000.0;

/// Petry's penetrability coefficient K_p, ft³/lb, for the three concrete classes.
pub mod kp {
    /// Massive plain concrete.
    pub const PLAIN_FT3_PER_LB: f64 = 0.00799;
    /// Normally reinforced concrete.
    pub const NORMAL_RC_FT3_PER_LB: f64 = 0.00426;
    /// Specially reinforced concrete.
    pub const SPECIAL_RC_FT3_PER_LB: f64 = 0.00284;
}

/// Sectional pressure A_p = W/A, lb/ft², A the missile's cross-section in ft².
pub fn sectional_pressure_psf(m: &Missile) -> f64 {
    let d_ft = m.diameter_in / 12.0;
    m.weight_lb / (std::f64::consts::PI * d_ft * d_ft / 4.0)
}

/// Penetration depth X, in, at impact velocity `v_fps` (ft/s), with penetrability `kp_ft3_per_lb`.
pub fn penetration_in(m: &Missile, v_fps: f64, kp_ft3_per_lb: f64) -> f64 {
    12.0 * kp_ft3_per_lb * sectional_pressure_psf(m) * (1.0 + v_fps * v_fps / V2_SCALE_FPS2).log10()
}

/// Perforation thickness h_p = 2 X, in (\[THESIS\], verbatim).
pub fn perforation_in(x_in: f64) -> f64 {
    2.0 * x_in
}

/// Scabbing thickness h_s = 2.2 X, in (recollection, Medium–Low).
pub fn scabbing_in(x_in: f64) -> f64 {
    2.2 * x_in
}
