//! Element motion: central differences for the centres and the spins, with mass-proportional
//! damping α centred in time (explicit, no stability cost), as the 2D kernel's update. A
//! sphere's inertia is the same about every axis, so its spin needs no gyroscopic term and no
//! orientation: the laws are incremental.

use super::state::{Ledger, Spheres};
use super::vec3::{V3, add, dot, scale};

/// The step's constants: Δt (s) and α (1/s).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Params {
    /// Time step, s.
    pub dt_s: f64,
    /// Mass-proportional damping α, 1/s.
    pub alpha_per_s: f64,
}

/// The update of one velocity-like vector: v⁺ = c1 v⁻ + c2 a (central differences with the
/// damping centred), and what the step's damping took, per unit mass, (v⁺ + v⁻)/2 · α (v⁺ + v⁻)/2 Δt.
#[inline(always)]
fn update(v: V3, accel: V3, p: &Params) -> (V3, f64) {
    let half = 0.5 * p.alpha_per_s * p.dt_s;
    let (c1, c2) = ((1.0 - half) / (1.0 + half), p.dt_s / (1.0 + half));
    let new = add(scale(c1, v), scale(c2, accel));
    let mid = scale(0.5, add(new, v));
    (new, p.alpha_per_s * dot(mid, mid) * p.dt_s)
}

/// Advance every sphere one step from its contact force and moment sums. Returns the sphere to
/// blame if a state is not finite (the caller names it and the step): the first that came into
/// the step so, else the first that left it so (a NaN spreads to a sphere's neighbours through
/// their contacts within the step; the one it came from is the one to name).
#[allow(clippy::too_many_arguments)]
pub fn advance(s: &Spheres, pos: &mut [V3], vel: &mut [V3], spin: &mut [V3], force: &[V3], moment: &[V3], p: &Params, ledger: &mut Ledger) -> Option<usize> {
    let (mut bad_in, mut bad_out) = (None, None);
    for e in 0..s.len() {
        let before = vel[e];
        if bad_in.is_none() && !(pos[e].iter().chain(&vel[e]).chain(&spin[e]).all(|x| x.is_finite())) {
            bad_in = Some(e);
        }
        if s.held[e] {
            vel[e] = s.prescribed_mps[e];
            spin[e] = [0.0; 3];
        } else {
            let m = s.mass_kg[e];
            let f = add(force[e], s.load_n[e]);
            let (v, damped) = update(vel[e], scale(1.0 / m, f), p);
            let (w, damped_w) = update(spin[e], scale(1.0 / s.inertia_kg_m2[e], add(moment[e], s.load_nm[e])), p);
            ledger.mass_damping_j += m * damped + s.inertia_kg_m2[e] * damped_w;
            // Loads work on the mean of the two half-step velocities.
            ledger.external_j += (dot(s.load_n[e], add(v, before)) + dot(s.load_nm[e], add(w, spin[e]))) * 0.5 * p.dt_s;
            vel[e] = v;
            spin[e] = w;
        }
        if s.held[e] {
            // A prescribed motion works against the contacts that push on it.
            ledger.external_j -= dot(force[e], add(vel[e], before)) * 0.5 * p.dt_s;
        }
        pos[e] = add(pos[e], scale(p.dt_s, vel[e]));
        if bad_out.is_none() && !(pos[e].iter().chain(&vel[e]).chain(&spin[e]).all(|x| x.is_finite())) {
            bad_out = Some(e);
        }
    }
    bad_in.or(bad_out)
}
