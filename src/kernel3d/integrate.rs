//! Element motion: central differences for the centres and the spins, with mass-proportional
//! damping α centred in time (explicit, no stability cost), as the 2D kernel's update, local
//! damping λ per sphere (`local`, a material's own damping), and a viscous boundary: dashpots
//! from boundary spheres to what lies beyond the model, centred in time as α is (`with_dashpot`).
//! A
//! sphere's inertia is the same about every axis, so its spin needs no gyroscopic term and no
//! orientation: the laws are incremental.

use super::state::Spheres;
use super::vec3::{V3, add, dot, scale, sub};

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

/// [`update`] for a sphere on a dashpot to the ground of `c_per_s` = c/m (1/s) along x, y, z on
/// top of α: each axis damped at its own rate, centred in time (unconditionally stable). Returns
/// the new velocity, the mass damping's work per unit mass and the dashpot's. Lysmer &
/// Kuhlemeyer (1969): a dashpot ρ c_p A normal to a face and ρ c_s A across it takes a plane
/// wave arriving square to the face out of the model whole, at every frequency.
#[inline(always)]
fn with_dashpot(v: V3, accel: V3, p: &Params, c_per_s: V3) -> (V3, f64, f64) {
    let new: V3 = [0, 1, 2].map(|k| {
        let half = 0.5 * (p.alpha_per_s + c_per_s[k]) * p.dt_s;
        (1.0 - half) / (1.0 + half) * v[k] + p.dt_s / (1.0 + half) * accel[k]
    });
    let mid = scale(0.5, add(new, v));
    let radiated = (c_per_s[0] * mid[0] * mid[0] + c_per_s[1] * mid[1] * mid[1] + c_per_s[2] * mid[2] * mid[2]) * p.dt_s;
    (new, p.alpha_per_s * dot(mid, mid) * p.dt_s, radiated)
}

/// [`with_dashpot`] undone: the half-step velocity before an update that gave `v` from `accel`.
#[inline(always)]
pub fn before_dashpot(v: V3, accel: V3, p: &Params, c_per_s: V3) -> V3 {
    [0, 1, 2].map(|k| {
        let half = 0.5 * (p.alpha_per_s + c_per_s[k]) * p.dt_s;
        (v[k] - p.dt_s / (1.0 + half) * accel[k]) * (1.0 + half) / (1.0 - half)
    })
}

/// Local (non-viscous) damping of a force (or moment) `f` on a sphere moving at `v`: each
/// component less λ|fᵢ| along vᵢ (Cundall's local damping, as PFC's and YADE's
/// NewtonIntegrator apply it). It opposes motion in proportion to the force that drives it, so a
/// sphere in free flight or in steady motion loses nothing (a loose fragment is not dragged; a
/// bonded cluster flying off, only as much as its own vibration pushes on it). A linear
/// oscillator loses the fraction 4λ of its energy a cycle (the amplitude falls by
/// (1 − λ)/(1 + λ) a cycle), as with a viscous damper at ζ = λ/π, whatever its frequency.
#[inline(always)]
pub fn local(f: V3, v: V3, lambda: f64) -> V3 {
    let sign = |x: f64| if x > 0.0 { 1.0 } else if x < 0.0 { -1.0 } else { 0.0 };
    [0, 1, 2].map(|i| f[i] - lambda * f[i].abs() * sign(v[i]))
}

/// The whole-step velocity the local damping reads, m/s (or rad/s): the half-step one plus half
/// the step's undamped change, as YADE's (the sign of the motion the force meets).
#[inline(always)]
pub fn whole_step_velocity(v_half: V3, accel: V3, p: &Params) -> V3 {
    add(v_half, scale(0.5 * p.dt_s, accel))
}

/// What one chunk's update adds to the ledger and where it saw a non-finite state.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Report {
    /// Mass-proportional damping, J.
    pub mass_damping_j: f64,
    /// Local damping, J.
    pub local_damping_j: f64,
    /// Carried out through the dashpots of a viscous boundary, J.
    pub radiated_j: f64,
    /// Work of loads and prescribed motions, J.
    pub external_j: f64,
    /// The first sphere that came into the step non-finite.
    pub bad_in: Option<usize>,
    /// The first sphere that left it non-finite.
    pub bad_out: Option<usize>,
}

/// One chunk's rows of the per-sphere arrays, from sphere `base` on.
pub struct Rows<'a> {
    /// The chunk's first sphere.
    pub base: usize,
    /// Centres, m (advanced).
    pub pos: &'a mut [V3],
    /// Half-step velocities, m/s (advanced).
    pub vel: &'a mut [V3],
    /// Half-step spins, rad/s (advanced).
    pub spin: &'a mut [V3],
    /// Contact force sums, N.
    pub force: &'a [V3],
    /// Contact moment sums, N·m.
    pub moment: &'a [V3],
}

/// Advance a chunk of spheres one step from their contact force and moment sums.
pub fn advance(s: &Spheres, rows: Rows<'_>, p: &Params) -> Report {
    // A model that damps no sphere locally, or has no dashpot, gets a loop without that test
    // per sphere.
    match (s.local_damping.is_empty(), s.dashpot_kg_per_s.is_empty()) {
        (true, true) => advance_as::<false, false>(s, rows, p),
        (false, true) => advance_as::<true, false>(s, rows, p),
        (true, false) => advance_as::<false, true>(s, rows, p),
        (false, false) => advance_as::<true, true>(s, rows, p),
    }
}

/// [`advance`], with local damping read per sphere (`LOCAL`) or absent, and dashpots
/// (`DASHPOT`) or none.
fn advance_as<const LOCAL: bool, const DASHPOT: bool>(s: &Spheres, rows: Rows<'_>, p: &Params) -> Report {
    let Rows { base, pos, vel, spin, force, moment } = rows;
    let mut r = Report::default();
    // x·0 is 0 for every finite x and NaN for ±∞ and NaN: one sum tells, with no branch per value.
    let zero = |v: V3| v[0] * 0.0 + v[1] * 0.0 + v[2] * 0.0;
    let finite = |a: V3, b: V3, c: V3| zero(a) + zero(b) + zero(c) == 0.0;
    for k in 0..pos.len() {
        let e = base + k;
        let before = vel[k];
        if r.bad_in.is_none() && !finite(pos[k], vel[k], spin[k]) {
            r.bad_in = Some(e);
        }
        if s.held[e] {
            vel[k] = s.prescribed_mps[e];
            spin[k] = [0.0; 3];
            // A prescribed motion works against the contacts that push on it.
            r.external_j -= dot(force[k], add(vel[k], before)) * 0.5 * p.dt_s;
        } else {
            let (m, i) = (s.mass_kg[e], s.inertia_kg_m2[e]);
            let (mut f, mut t) = (add(force[k], s.load_n[e]), add(moment[k], s.load_nm[e]));
            let lambda = if LOCAL { s.local_damping[e] } else { 0.0 };
            let (f_in, t_in) = (f, t);
            if LOCAL && lambda > 0.0 {
                f = local(f, whole_step_velocity(vel[k], scale(1.0 / m, f), p), lambda);
                t = local(t, whole_step_velocity(spin[k], scale(1.0 / i, t), p), lambda);
            }
            let c = if DASHPOT { s.dashpot_kg_per_s[e] } else { [0.0; 3] };
            let (v, damped) = if DASHPOT && c != [0.0; 3] {
                let (v, damped, radiated) = with_dashpot(vel[k], scale(1.0 / m, f), p, scale(1.0 / m, c));
                r.radiated_j += m * radiated;
                (v, damped)
            } else {
                update(vel[k], scale(1.0 / m, f), p)
            };
            let (w, damped_w) = update(spin[k], scale(1.0 / i, t), p);
            r.mass_damping_j += m * damped + i * damped_w;
            if LOCAL && lambda > 0.0 {
                // The damping force's work over the step, on the mean of the half-step velocities.
                let mid = |a: V3, b: V3| scale(0.5, add(a, b));
                r.local_damping_j -= (dot(sub(f, f_in), mid(v, before)) + dot(sub(t, t_in), mid(w, spin[k]))) * p.dt_s;
            }
            // Loads work on the mean of the two half-step velocities.
            r.external_j += (dot(s.load_n[e], add(v, before)) + dot(s.load_nm[e], add(w, spin[k]))) * 0.5 * p.dt_s;
            vel[k] = v;
            spin[k] = w;
        }
        pos[k] = add(pos[k], scale(p.dt_s, vel[k]));
        if r.bad_out.is_none() && !finite(pos[k], vel[k], spin[k]) {
            r.bad_out = Some(e);
        }
    }
    r
}
