//! The 3D kernel: bonded spheres with six degrees of freedom and the moment transfer law of
//! seed 004, stepping as the 2D kernel does — contact processing, element motion, contact
//! detection — under the same contract (`crate::simulation`, [`contract`]).
//!
//! Each contact's force and moments are added to its two spheres in contact order, so a step's
//! result is one sum order on any thread count.

pub mod build;
pub mod contact;
pub mod contract;
pub mod detect;
pub mod integrate;
pub mod law;
pub mod stability;
pub mod state;
pub mod stiffness;
pub mod vec3;

pub use build::Builder;

use contact::Contact;
use law::{Class, Dissipation, Pair};
use state::{Spheres, State};
use vec3::{V3, add, dot, norm, sub};

use crate::error::{Error, Result};
use crate::kernel::Body;
use crate::simulation::Threading;

/// A model of spheres ready to step.
#[derive(Debug, Clone)]
pub struct Model {
    // Configuration, fixed when built.
    /// Sphere constants.
    pub spheres: Spheres,
    /// Contact classes, `kind_i × kinds + kind_j`.
    pub classes: Vec<Class>,
    /// Number of kinds.
    pub kinds: usize,
    /// Bodies, in build order.
    pub bodies: Vec<Body>,
    /// Δt and α.
    pub motion: integrate::Params,
    /// The stability limit the step was taken from, s.
    pub dt_bound_s: f64,
    /// The frequency bound, rad/s.
    pub omega_bound_rad_per_s: f64,
    /// Gap below which pairs are candidates, m.
    pub skin_m: f64,
    /// Where steps run (one thread for now: the result never depends on it).
    pub threading: Threading,
    // What stepping changes.
    /// The evolving state.
    pub state: State,
}

impl Model {
    /// Simulated time, s.
    pub fn time_s(&self) -> f64 {
        self.state.steps as f64 * self.motion.dt_s
    }

    /// The class of a contact between spheres i and j.
    pub fn class_of(&self, i: u32, j: u32) -> u16 {
        (self.spheres.kind[i as usize] as usize * self.kinds + self.spheres.kind[j as usize] as usize) as u16
    }

    /// Advance `n` steps.
    pub fn run_steps(&mut self, n: u64) -> Result<()> {
        for _ in 0..n {
            self.step()?;
        }
        Ok(())
    }

    /// Advance one step: contact processing, element motion, contact detection.
    pub fn step(&mut self) -> Result<()> {
        self.process_contacts();
        self.move_spheres()?;
        self.detect_contacts();
        self.state.steps += 1;
        Ok(())
    }

    fn process_contacts(&mut self) {
        let (sp, st) = (&self.spheres, &mut self.state);
        let n = sp.len();
        st.force_n.clear();
        st.force_n.resize(n, [0.0; 3]);
        st.moment_nm.clear();
        st.moment_nm.resize(n, [0.0; 3]);
        let mut diss = Dissipation::default();
        for c in st.contacts.iter_mut() {
            let (i, j) = (c.i as usize, c.j as usize);
            let pair = Pair {
                r: [sp.radius_m[i], sp.radius_m[j]],
                dx_m: sub(st.pos_m[j], st.pos_m[i]),
                v: [st.vel_mps[i], st.vel_mps[j]],
                w: [st.spin_rad_per_s[i], st.spin_rad_per_s[j]],
            };
            let a = law::act(c, &self.classes[c.class as usize], &pair, self.motion.dt_s, &mut diss);
            st.force_n[j] = add(st.force_n[j], a.force_j_n);
            st.force_n[i] = sub(st.force_n[i], a.force_j_n);
            st.moment_nm[i] = add(st.moment_nm[i], a.moment_i_nm);
            st.moment_nm[j] = add(st.moment_nm[j], a.moment_j_nm);
        }
        st.ledger.contacts.add(&diss);
    }

    fn move_spheres(&mut self) -> Result<()> {
        let st = &mut self.state;
        let bad = integrate::advance(&self.spheres, &mut st.pos_m, &mut st.vel_mps, &mut st.spin_rad_per_s, &st.force_n, &st.moment_nm, &self.motion, &mut st.ledger);
        if let Some(e) = bad {
            let (p, v, w) = (st.pos_m[e], st.vel_mps[e], st.spin_rad_per_s[e]);
            return Err(Error::BlowUp {
                step: st.steps,
                time_s: st.steps as f64 * self.motion.dt_s,
                element: e,
                detail: format!(
                    "sphere at {p:.3?} m, velocity {v:.3?} m/s, spin {w:.3?} rad/s is not finite (time step {:.4e} s; stability bound {:.4e} s)",
                    self.motion.dt_s, self.dt_bound_s
                ),
            });
        }
        Ok(())
    }

    fn detect_contacts(&mut self) {
        let half = 0.5 * self.skin_m;
        let st = &self.state;
        let moved = st.pos_m.iter().zip(&st.searched_at_m).any(|(p, q)| norm(sub(*p, *q)) > half);
        if moved {
            self.search();
        }
    }

    /// Search for candidate pairs now and merge them into the contact list.
    pub fn search(&mut self) {
        let pairs = detect::candidates(&self.state.pos_m, &self.spheres.radius_m, self.skin_m);
        let old = std::mem::take(&mut self.state.contacts);
        let classes = |i: u32, j: u32| self.class_of(i, j);
        let merged = detect::merge(old, &pairs, &self.state.pos_m, &self.spheres.radius_m, classes);
        self.state.contacts = merged;
        self.state.searched_at_m = self.state.pos_m.clone();
        self.state.searches += 1;
    }

    /// Kinetic energy (half-step velocities and spins), J.
    pub fn kinetic_energy_j(&self) -> f64 {
        let (sp, st) = (&self.spheres, &self.state);
        (0..sp.len())
            .map(|e| 0.5 * sp.mass_kg[e] * dot(st.vel_mps[e], st.vel_mps[e]) + 0.5 * sp.inertia_kg_m2[e] * dot(st.spin_rad_per_s[e], st.spin_rad_per_s[e]))
            .sum()
    }

    /// Elastic energy in the contacts, J.
    pub fn strain_energy_j(&self) -> f64 {
        let st = &self.state;
        st.contacts
            .iter()
            .map(|c| {
                let (i, j) = (c.i as usize, c.j as usize);
                let r_mean = 0.5 * (self.spheres.radius_m[i] + self.spheres.radius_m[j]);
                law::stored_j(c, &self.classes[c.class as usize], norm(sub(st.pos_m[j], st.pos_m[i])), r_mean)
            })
            .sum()
    }

    /// Intact bonds.
    pub fn intact_bonds(&self) -> usize {
        self.state.contacts.iter().filter(|c| c.bond == contact::Bond::Intact).count()
    }

    /// Displacement of sphere e from where it started, m.
    pub fn displacement_m(&self, e: usize) -> V3 {
        sub(self.state.pos_m[e], self.spheres.initial_m[e])
    }

    /// The contacts (read-only).
    pub fn contacts(&self) -> &[Contact] {
        &self.state.contacts
    }
}
