//! Damping part: the stiffness-proportional half of Rayleigh damping, C = αM + βK, lives in the
//! contacts as dashpots β·Kn and β·Kt on the relative velocity of the previous half step (the
//! mass-proportional half lives in the integrator). Lagging the velocity keeps the update
//! explicit; its price is the (√(1+ξ²) − ξ) factor of the stability bound (`stability`).

use super::ContactClass;

/// Dashpot forces (normal N, tension positive; tangential N) for the relative velocities.
/// The energy they dissipate over a step is force × velocity × Δt (≥ 0).
#[inline(always)]
pub fn dashpot(k: &ContactClass, vn_mps: f64, vt_mps: f64) -> (f64, f64) {
    (k.dashpot_n_s_per_m * vn_mps, k.dashpot_t_s_per_m * vt_mps)
}
