//! Rolling resistance of the moment transfer law (seed 004, eqs 1–20).
//!
//! The incremental rolling displacement (eq 10) is the mean of where the two material points
//! that met at the old contact point C are now, seen from the new contact point C':
//! dU_r = ½ [r_A (n − n′) + r_B (n′ − n) + Δt (r_A ω_A − r_B ω_B) × n].
//! Misprint: eq 9 prints C′M_B = r_B((n′ − n) + Δt ω_B ∧ n); with eq 7 (C_B M_B = −r_B Δt ω_B ∧ n)
//! the sign of the spin term is minus, as used here (with the printed sign, two spheres spinning
//! oppositely — the seed's own example of pure rolling — would give dU_r = 0).
//! The rolling angle increment is n′ × dU_r / r (r the mean radius of eq 1): eqs 11–12 give
//! |dU_r|/r along n′ × dU_r, the same while dU_r lies in the contact plane, as it does to first
//! order in Δt; its part along n′ (second order: the pair turning as a rigid body leaves
//! one) eqs 11–12 would turn into a rolling of its full size about a direction set by rounding,
//! and eq 14 drops the normal component anyway. For equal spheres the increment is half the
//! relative spin normal to n, so k_r = E I_f / r (eq 38) gives a beam's bending moment
//! E I θ / (2r) over the spacing 2r.

use super::super::vec3::{V3, cross, scale, sub};
use super::capped::capped;

/// Rolling part parameters (a contact class's; configuration).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Params {
    /// Rolling stiffness over r̄³, Pa (k_r = this × r̄³: eq 31's k_s r² for granular media,
    /// eq 38's E π r³/4 for a beam).
    pub kr_pa: f64,
    /// Elastic limit η of eq 16 (∞: no cap).
    pub eta: f64,
}

/// The rolling angle increment dθ_r (rad, eqs 10–12) of spheres A (radius `ra_m`, spin
/// `wa_rad_per_s`) and B over a step `dt_s` in which the normal turned from `n_old` to `n`.
#[inline]
pub fn increment(ra_m: f64, rb_m: f64, n_old: V3, n: V3, wa_rad_per_s: V3, wb_rad_per_s: V3, dt_s: f64) -> V3 {
    increment_per(ra_m, rb_m, 1.0 / (0.5 * (ra_m + rb_m)), n_old, n, wa_rad_per_s, wb_rad_per_s, dt_s)
}

/// [`increment`] given 1/r̄ (1/m, `Local::per_r_mean`): a division fewer per contact.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn increment_per(ra_m: f64, rb_m: f64, per_r: f64, n_old: V3, n: V3, wa_rad_per_s: V3, wb_rad_per_s: V3, dt_s: f64) -> V3 {
    let dn = sub(n_old, n);
    let spin = cross(sub(scale(ra_m * dt_s, wa_rad_per_s), scale(rb_m * dt_s, wb_rad_per_s)), n_old);
    let du = scale(0.5, [
        (ra_m - rb_m) * dn[0] + spin[0],
        (ra_m - rb_m) * dn[1] + spin[1],
        (ra_m - rb_m) * dn[2] + spin[2],
    ]);
    scale(per_r, cross(n, du))
}

/// The new rolling moment (N·m, in the plane normal to `n`) from the last one carried into that
/// plane, the angle increment `d_theta`, the stiffness `kr` (N·m/rad) and the normal force
/// `f_n_n` (N): elastic k_r θ_r (eq 15) capped at η r |F_n| (eq 16) with θ_r reset to the cap
/// (eqs 17–20). Returns (moment, the cap's share of the moments' work: half the dissipated
/// energy, J).
#[inline]
pub fn moment(last_nm: V3, d_theta: V3, kr: f64, eta: f64, mean_radius_m: f64, f_n_n: f64) -> (V3, f64) {
    // η = ∞ is no cap, also at F_n = 0 (where ∞ × 0 would be NaN).
    let limit = if eta.is_finite() { eta * mean_radius_m * f_n_n.abs() } else { f64::INFINITY };
    capped(last_nm, d_theta, kr, limit)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel3d::vec3::norm;

    const X: V3 = [1.0, 0.0, 0.0];

    #[test]
    fn opposite_spins_roll_and_a_common_spin_does_not() {
        let dt = 1e-3;
        let w = [0.0, 0.0, 2.0];
        // Opposite spins about z (the seed's pure rolling): half the relative spin, about z.
        let d = increment(0.1, 0.1, X, X, w, scale(-1.0, w), dt);
        assert!((d[2] - 2.0 * dt).abs() < 1e-15 && d[0] == 0.0 && d[1] == 0.0, "{d:?}");
        // The pair turning together as a rigid body (the normal turns with it): no rolling,
        // also for unequal radii (the radius difference's terms cancel in the contact plane).
        let n = [1.0, 2.0 * dt, 0.0];
        let d = norm(increment(0.1, 0.05, X, scale(1.0 / norm(n), n), w, w, dt));
        assert!(d < 1e-12 * 2.0 * dt, "{d} rad against {} of opposite spins", 2.0 * dt);
    }

    #[test]
    fn the_moment_is_capped_at_eta_r_fn() {
        let (m, w) = moment([0.0; 3], [0.0, 1.0, 0.0], 100.0, 0.5, 0.1, -40.0);
        assert!((m[1] - 2.0).abs() < 1e-12 && w > 0.0, "{m:?} {w}");
    }
}
