//! The ledger's energies at a whole step, second order in Δt. The state holds half-step
//! velocities v_{N−½} beside the centres x_N, and the contacts' history as of step N−1 (the last
//! forces made); ½ m v_{N−½}² beside the strain at x_N is off by about ½ Δt F·v, first order
//! (on impact3d a small share: 0.300 → 0.291 %; the break booking, `law::act`, was the rest). At step N−1
//! everything is known to second order: the velocity is the mean of v_{N−3/2} (undone from
//! v_{N−½} by the last forces) and v_{N−½}, the centres are x_N − Δt v_{N−½}, the contacts'
//! history is that step's, and of the last update's external work and damping (each centred on
//! step N−1) half belongs before it.

use super::Model;
use super::{integrate, law};
use super::vec3::{V3, add, dot, norm, scale, sub};

/// The energies of the ledger at the last whole step whose forces are known, J.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct WholeStep {
    /// Kinetic energy, J.
    pub kinetic_j: f64,
    /// Strain energy, J.
    pub strain_j: f64,
    /// Work of loads and prescribed motions up to that step, J.
    pub external_j: f64,
    /// Mass-proportional damping up to that step, J.
    pub mass_damping_j: f64,
    /// Local damping up to that step, J.
    pub local_damping_j: f64,
    /// Carried out through the viscous boundary up to that step, J.
    pub radiated_j: f64,
}

impl Model {
    /// The ledger's energies at step N−1 (module doc); before the first step, the present ones.
    pub fn whole_step(&self) -> WholeStep {
        let (sp, st, p) = (&self.spheres, &self.state, &self.motion);
        let l = &st.ledger;
        if st.steps == 0 || st.force_n.len() != sp.len() {
            let (kinetic_j, strain_j) = (self.kinetic_energy_j(), self.strain_energy_j());
            return WholeStep { kinetic_j, strain_j, external_j: l.external_j, mass_damping_j: l.mass_damping_j, local_damping_j: l.local_damping_j, radiated_j: l.radiated_j };
        }
        // The update's constants (integrate::update): v⁺ = c1 v⁻ + c2 a.
        let half = 0.5 * p.alpha_per_s * p.dt_s;
        let (c1, c2) = ((1.0 - half) / (1.0 + half), p.dt_s / (1.0 + half));
        let undo = |v: V3, a: V3| scale(1.0 / c1, sub(v, scale(c2, a)));
        let (mut kinetic_j, mut external_last_j, mut damping_last_j, mut local_last_j, mut radiated_last_j) = (0.0, 0.0, 0.0, 0.0, 0.0);
        let mut before = Vec::with_capacity(sp.len());
        for e in 0..sp.len() {
            let (v, w, f) = (st.vel_mps[e], st.spin_rad_per_s[e], st.force_n[e]);
            before.push(sub(st.pos_m[e], scale(p.dt_s, v)));
            if sp.held[e] {
                external_last_j -= dot(f, v) * p.dt_s;
                kinetic_j += 0.5 * sp.mass_kg[e] * dot(v, v);
                continue;
            }
            let (m, i) = (sp.mass_kg[e], sp.inertia_kg_m2[e]);
            let (mut f, mut t) = (add(f, sp.load_n[e]), add(st.moment_nm[e], sp.load_nm[e]));
            let (f_in, t_in) = (f, t);
            let lambda = sp.local_damping_of(e);
            if lambda > 0.0 {
                // The motion the damping met, from the new half-step side (the old one is what
                // is being undone): the same sign but where a component turned within the step.
                let (a, b) = (scale(1.0 / m, f), scale(1.0 / i, t));
                f = integrate::local(f, integrate::whole_step_velocity(v, scale(-1.0, a), p), lambda);
                t = integrate::local(t, integrate::whole_step_velocity(w, scale(-1.0, b), p), lambda);
            }
            let c = scale(1.0 / m, sp.dashpot_of(e));
            let v_old = if c == [0.0; 3] { undo(v, scale(1.0 / m, f)) } else { integrate::before_dashpot(v, scale(1.0 / m, f), p, c) };
            let w_old = undo(w, scale(1.0 / i, t));
            let (v_mid, w_mid) = (scale(0.5, add(v, v_old)), scale(0.5, add(w, w_old)));
            local_last_j -= (dot(sub(f, f_in), v_mid) + dot(sub(t, t_in), w_mid)) * p.dt_s;
            kinetic_j += 0.5 * m * dot(v_mid, v_mid) + 0.5 * i * dot(w_mid, w_mid);
            damping_last_j += p.alpha_per_s * (m * dot(v_mid, v_mid) + i * dot(w_mid, w_mid)) * p.dt_s;
            radiated_last_j += m * (c[0] * v_mid[0] * v_mid[0] + c[1] * v_mid[1] * v_mid[1] + c[2] * v_mid[2] * v_mid[2]) * p.dt_s;
            external_last_j += (dot(sp.load_n[e], v_mid) + dot(sp.load_nm[e], w_mid)) * p.dt_s;
        }
        WholeStep {
            kinetic_j,
            strain_j: self.strain_energy_at_j(&before),
            external_j: l.external_j - 0.5 * external_last_j,
            mass_damping_j: l.mass_damping_j - 0.5 * damping_last_j,
            local_damping_j: l.local_damping_j - 0.5 * local_last_j,
            radiated_j: l.radiated_j - 0.5 * radiated_last_j,
        }
    }

    /// Elastic energy in the contacts with the spheres' centres at `pos_m` (m), J.
    pub fn strain_energy_at_j(&self, pos_m: &[V3]) -> f64 {
        let r = &self.spheres.radius_m;
        self.state
            .contacts
            .iter()
            .map(|c| {
                let (i, j) = (c.i as usize, c.j as usize);
                let d = norm(sub(self.mirrors.point(pos_m[j], c.image), pos_m[i]));
                super::mirror::Mirrors::weight(c.i, c.j, c.image) * law::stored_j(c, &self.classes[c.class as usize], d, law::mean_radius_m([r[i], r[j]]))
            })
            .sum()
    }
}
