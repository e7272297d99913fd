//! Torsion of the moment transfer law (seed 004, eqs 21–28, 39–42).
//!
//! The twist at the contact point is half the relative spin about the normal (eq 23), so a
//! shaft of spheres of spacing 2r twisted by φ per sphere carries T = G I_t φ / (2r) when
//! k_t = G I_t / r. Misprint: eq 41 prints k_t = 2 G I_t / R, which with eq 23's half gives
//! G I_t φ / R, twice the shaft's torque for the same twist (half the twist for a torque).
//! `beam_kt` takes the consistent value; `tests/beam3d.rs` checks the shaft against T L/(G I_t).

use crate::kernel::law::tangential::capped_spring;

/// How the twisting moment is capped.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Cap {
    /// Elastic (a bonded beam).
    None,
    /// Mohr–Coulomb over a contact disc of radius r_min (eq 42):
    /// (2/3)(r_min |F_n| tan φ + π r_min³ c).
    MohrCoulomb {
        /// tan φ of the local friction angle.
        tan_phi: f64,
        /// Local cohesion c, Pa.
        cohesion_pa: f64,
    },
}

/// Twisting part parameters (a contact class's; configuration).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Params {
    /// Twisting stiffness over r̄³, Pa (k_t = this × r̄³; a beam's G π / 2, `beam_kt_pa`).
    pub kt_pa: f64,
    /// Its cap.
    pub cap: Cap,
}

/// k_t / r³ of a beam of spheres in a material of shear modulus `g_pa`: G I_t / r with
/// I_t = π r⁴/2 (eq 39) and the factor of eq 41 corrected (module doc), Pa.
pub fn beam_kt_pa(g_pa: f64) -> f64 {
    g_pa * std::f64::consts::PI / 2.0
}

/// The cap of eq 42 (or none), N·m, for the smaller radius `r_min_m` and normal force `f_n_n`.
#[inline]
pub fn limit_nm(cap: Cap, r_min_m: f64, f_n_n: f64) -> f64 {
    match cap {
        Cap::None => f64::INFINITY,
        Cap::MohrCoulomb { tan_phi, cohesion_pa } => {
            2.0 / 3.0 * (r_min_m * f_n_n.abs() * tan_phi + std::f64::consts::PI * r_min_m.powi(3) * cohesion_pa)
        }
    }
}

/// The new twisting moment about the normal (N·m) from the last one, the spins' components
/// along the normal `wa_n`, `wb_n` (rad/s) over `dt_s`, stiffness `kt` (N·m/rad) and `cap`:
/// k_t times half the relative twist (eqs 21–24), capped and reset at the cap (eqs 25–28) — the
/// scalar return map of the 2D shear spring, whose energy booking it shares. Returns (moment,
/// half the dissipated energy J: the moment acts on both spheres).
#[inline]
#[allow(clippy::too_many_arguments)]
pub fn moment(last_nm: f64, wa_n: f64, wb_n: f64, dt_s: f64, kt: f64, cap: Cap, r_min_m: f64, f_n_n: f64) -> (f64, f64) {
    let limit = limit_nm(cap, r_min_m, f_n_n);
    let twist = 0.5 * (wa_n - wb_n) * dt_s;
    // capped_spring works on the spring's elastic displacement (here the angle, moment / k_t).
    let (m, _, w) = capped_spring(last_nm / kt, twist, kt, kt, limit);
    (m, w)
}
