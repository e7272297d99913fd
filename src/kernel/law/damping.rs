//! Damping part: the stiffness-proportional half of Rayleigh damping, C = αM + βK, lives in the
//! contacts as dashpots β·Kn and β·Kt on the relative velocity of the previous half step (the
//! mass-proportional half lives in the integrator). Lagging the velocity keeps the update
//! explicit; its price is the (√(1+ξ²) − ξ) factor of the stability bound (`stability`).
//! The dashpots use the static springs (a rate-enhanced modulus does not change the damping).

use serde::{Deserialize, Serialize};

use super::Springs;

/// Dashpot coefficients of a contact class, N·s/m.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Params {
    /// β·Kn of a bond.
    pub bond_n: f64,
    /// β·Kt of a bond.
    pub bond_t: f64,
    /// β·Kn of a frictional contact.
    pub contact_n: f64,
    /// β·Kt of a frictional contact.
    pub contact_t: f64,
}

impl Params {
    /// β times the springs.
    pub fn new(beta_s: f64, bond: Springs, contact: Springs) -> Params {
        Params {
            bond_n: beta_s * bond.kn_n_per_m,
            bond_t: beta_s * bond.kt_n_per_m,
            contact_n: beta_s * contact.kn_n_per_m,
            contact_t: beta_s * contact.kt_n_per_m,
        }
    }
}

/// Dashpot forces (normal N, tension positive; tangential N) for the relative velocities.
/// The energy they dissipate over a step is force × velocity × Δt (≥ 0).
#[inline(always)]
pub fn dashpot(coef_n: f64, coef_t: f64, vn_mps: f64, vt_mps: f64) -> (f64, f64) {
    (coef_n * vn_mps, coef_t * vt_mps)
}
