//! ACE — Army Corps of Engineers (1946), FORMULAS §3.3.
//!
//! ```text
//! X/D = (282/√f'c) (W/D^2.785) (V/1000)^1.5 + 0.5     [W lb, D in, V ft/s, f'c psi]
//! h_p/d = 1.32 + 1.24 x/d    1.35 ≤ x/d ≤ 13.5  (3 ≤ h_p/d ≤ 18)
//! h_s/d = 2.12 + 1.36 x/d    0.65 ≤ x/d ≤ 11.75 (3 ≤ h_s/d ≤ 18)
//! ```
//! Below those ranges Kennedy's quadratic branches apply, so h_s and h_p are
//! [`super::kennedy`]'s relations on the ACE depth. SI: x/d = (3.5e-4/√fc)(M/d³)d^0.215 V^1.5 + 0.5.
//! Since x/d ≥ 0.5 at any V, ACE predicts scabbing at any velocity for h/d < 2.69 and perforation
//! for h/d < 1.42. Sources: SI form and h_p verbatim \[THESIS\]; h_s = DOE C.6-5; 282 = 4·222/π as in
//! TM 5-855-1 \[LEPP\]. Confidence: High.

use super::{Missile, Target};

/// ACE coefficient (same as TM 5-855-1's 4·222/π).
pub const COEFFICIENT: f64 = 282.0;
/// Diameter exponent of the X/D form.
pub const DIAMETER_EXPONENT: f64 = 2.785;
/// Velocity exponent.
pub const VELOCITY_EXPONENT: f64 = 1.5;
/// The constant term of X/D.
pub const OFFSET_XD: f64 = 0.5;

/// Penetration ratio X/D.
pub fn penetration_ratio(m: &Missile, t: &Target, v_fps: f64) -> f64 {
    COEFFICIENT / t.fc_psi.sqrt() * m.weight_lb / m.diameter_in.powf(DIAMETER_EXPONENT)
        * (v_fps / 1000.0).powf(VELOCITY_EXPONENT)
        + OFFSET_XD
}
