//! The 2D kernel under the contract of `crate::simulation`: its model as bodies a detector
//! reads (z = 0) and as a simulation a run drives.

use std::ops::Range;

use super::contact::Bond;
use super::{Model, Threading};
use crate::error::Result;
use crate::simulation::{Bodies, Simulation, Tally};

impl Bodies for Model {
    fn time_s(&self) -> f64 {
        Model::time_s(self)
    }

    fn body(&self, name: &str) -> Option<Range<usize>> {
        Model::body(self, name).map(|b| b.elements.clone())
    }

    fn element_count(&self) -> usize {
        self.el.len()
    }

    fn initial_m(&self, e: usize) -> [f64; 3] {
        [self.el.initial[e][0], self.el.initial[e][1], 0.0]
    }

    fn position_m(&self, e: usize) -> [f64; 3] {
        [self.state.pos[e][0], self.state.pos[e][1], 0.0]
    }

    fn velocity_mps(&self, e: usize) -> [f64; 3] {
        [self.state.vel[e][0], self.state.vel[e][1], 0.0]
    }

    fn radius_m(&self, e: usize) -> f64 {
        self.el.radius[e]
    }

    fn mass_kg(&self, e: usize) -> f64 {
        self.el.mass[e]
    }

    fn held(&self, e: usize) -> bool {
        self.el.is_fully_prescribed(e)
    }

    fn each_bond(&self, f: &mut dyn FnMut(usize, usize)) {
        for c in self.state.contacts.list.iter().filter(|c| c.bond == Bond::Intact) {
            f(c.i as usize, c.j as usize);
        }
    }
}

impl Simulation for Model {
    fn dt_s(&self) -> f64 {
        Model::dt_s(self)
    }

    fn steps(&self) -> u64 {
        Model::steps(self)
    }

    fn run_steps(&mut self, n: u64) -> Result<()> {
        Model::run_steps(self, n)
    }

    fn threading(&self) -> Threading {
        self.threading
    }

    fn set_threading(&mut self, threading: Threading) {
        self.threading = threading;
    }

    fn checkpoint(&self) -> Vec<u8> {
        Model::checkpoint(self)
    }

    fn restore(&mut self, bytes: &[u8]) -> Result<()> {
        Model::restore(self, bytes)
    }

    fn contact_count(&self) -> u64 {
        self.state.contacts.len() as u64
    }

    fn bond_count(&self) -> u64 {
        self.intact_bonds() as u64
    }

    fn tally(&self) -> Tally {
        let (info, l) = (&self.step_info, &self.state.ledger);
        let (ke, se) = (self.kinetic_energy_j(), self.strain_energy_j());
        Tally {
            elements: self.el.len() as u64,
            bonds_broken: l.bonds_broken(),
            dt_s: info.dt_s,
            dt_bound_s: info.dt_bound_s,
            omega_bound_rad_per_s: info.omega_bound_rad_per_s,
            dt_limit: info.detail.clone(),
            kinetic_energy_j: ke,
            strain_energy_j: se,
            external_work_j: l.external_j,
            mass_damping_j: l.mass_damping_j,
            contacts_j: l.contacts.terms().into_iter().map(|(k, v)| (k.to_string(), v)).collect(),
            dissipated_j: l.dissipated_j(),
            energy_residual_j: l.residual_j(ke, se),
            energy_in_j: l.initial_j + l.external_j.abs(),
            neighbour_rebuilds: self.state.rebuilds,
            neighbour_local_updates: self.state.local_updates,
        }
    }
}
