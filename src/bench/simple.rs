//! The simplest honest kernel, the yardstick of the full law's cost ([6/6]): every bond a
//! linear normal spring and an incremental shear spring, central differences, the forces
//! scattered to the elements on one thread. Nothing else: no plateaus, failure, ledger,
//! blow-up watch, neighbour margins or new contacts. It is built from a model's bonds and
//! state, so it steps the same block from the same start; `tests/simple_kernel.rs` checks that
//! it follows the full kernel's trajectory, which makes the timing comparison one of equal work.

use crate::kernel::contact::Bond;
use crate::kernel::Model;

/// A bond of the simple kernel: its pair, class and the one history it has.
#[derive(Debug, Clone, Copy)]
struct Spring {
    i: u32,
    j: u32,
    class: u16,
    /// Rest length, m (configuration).
    rest_m: f64,
    /// Elastic tangential displacement, m (evolves).
    ut_m: f64,
}

/// Per contact class: Kn N/m, Kt N/m, lever shares of i and j.
#[derive(Debug, Clone, Copy)]
struct Class {
    kn: f64,
    kt: f64,
    lever_i: f64,
    lever_j: f64,
}

/// The simple kernel's model.
#[derive(Debug, Clone)]
pub struct Simple {
    // Configuration.
    classes: Vec<Class>,
    inv_mass: Vec<f64>,
    inv_inertia: Vec<f64>,
    dt_s: f64,
    // What stepping changes.
    springs: Vec<Spring>,
    /// Positions [x m, y m, θ rad].
    pub pos: Vec<[f64; 3]>,
    /// Half-step velocities [m/s, m/s, rad/s].
    pub vel: Vec<[f64; 3]>,
    // Scratch.
    force: Vec<[f64; 3]>,
}

impl Simple {
    /// The simple kernel on `model`'s intact bonds, from its current state and with its Δt.
    /// Every element must be free (the benchmark block has no supports).
    pub fn from_model(model: &Model) -> Simple {
        assert!(model.el.prescribed.iter().all(|&p| p == 0), "the simple kernel steps free elements only");
        let st = &model.state;
        Simple {
            classes: model
                .classes
                .iter()
                .map(|k| Class { kn: k.bond.kn_n_per_m, kt: k.bond.kt_n_per_m, lever_i: k.lever_i, lever_j: k.lever_j })
                .collect(),
            inv_mass: model.el.inv_mass.clone(),
            inv_inertia: model.el.inv_inertia.clone(),
            dt_s: model.dt_s(),
            springs: st
                .contacts
                .list
                .iter()
                .filter(|c| c.bond == Bond::Intact)
                .map(|c| Spring { i: c.i, j: c.j, class: c.class, rest_m: c.rest_m, ut_m: c.ut_m })
                .collect(),
            pos: st.pos.clone(),
            vel: st.vel.clone(),
            force: vec![[0.0; 3]; st.pos.len()],
        }
    }

    /// Bonds stepped.
    pub fn bonds(&self) -> usize {
        self.springs.len()
    }

    /// One step: forces from the positions and half-step velocities, then central differences.
    pub fn step(&mut self) {
        let (pos, vel, dt) = (&self.pos, &self.vel, self.dt_s);
        self.force.iter_mut().for_each(|f| *f = [0.0; 3]);
        for s in &mut self.springs {
            let k = &self.classes[s.class as usize];
            let (i, j) = (s.i as usize, s.j as usize);
            let (dx, dy) = (pos[j][0] - pos[i][0], pos[j][1] - pos[i][1]);
            let d = (dx * dx + dy * dy).sqrt();
            let (nx, ny) = (dx / d, dy / d);
            let (vi, vj) = (vel[i], vel[j]);
            let (dvx, dvy) = (vj[0] - vi[0], vj[1] - vi[1]);
            let (li, lj) = (d * k.lever_i, d * k.lever_j);
            let vt = -dvx * ny + dvy * nx - li * vi[2] - lj * vj[2];
            s.ut_m += vt * dt;
            let (f_n, f_t) = (k.kn * (d - s.rest_m), k.kt * s.ut_m);
            let (fx, fy) = (f_n * nx - f_t * ny, f_n * ny + f_t * nx);
            let fi = &mut self.force[i];
            fi[0] += fx;
            fi[1] += fy;
            fi[2] += li * f_t;
            let fj = &mut self.force[j];
            fj[0] -= fx;
            fj[1] -= fy;
            fj[2] += lj * f_t;
        }
        for e in 0..self.pos.len() {
            let (f, v, x) = (self.force[e], &mut self.vel[e], &mut self.pos[e]);
            let (a, b) = (self.inv_mass[e], self.inv_inertia[e]);
            v[0] += dt * f[0] * a;
            v[1] += dt * f[1] * a;
            v[2] += dt * f[2] * b;
            x[0] += dt * v[0];
            x[1] += dt * v[1];
            x[2] += dt * v[2];
        }
    }
}
