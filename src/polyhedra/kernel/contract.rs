//! The polyhedral kernel under the contract of `crate::simulation`: an element is a body.

use std::ops::Range;

use super::Model;
use crate::error::{Error, Result};
use crate::simulation::{Bodies, Simulation, Tally, Threading};

const MAGIC: [u8; 8] = *b"DEMSPLY\x02";

impl Bodies for Model {
    fn time_s(&self) -> f64 {
        Model::time_s(self)
    }
    fn body(&self, name: &str) -> Option<Range<usize>> {
        self.group(name)
    }
    fn element_count(&self) -> usize {
        self.members.len()
    }
    fn initial_m(&self, e: usize) -> [f64; 3] {
        self.initial_m[e]
    }
    fn position_m(&self, e: usize) -> [f64; 3] {
        self.state.bodies[e].position.into()
    }
    fn velocity_mps(&self, e: usize) -> [f64; 3] {
        self.state.bodies[e].velocity.into()
    }
    /// The bounding sphere's radius, m.
    fn radius_m(&self, e: usize) -> f64 {
        self.shapes[self.members[e].shape].radius()
    }
    fn mass_kg(&self, e: usize) -> f64 {
        self.state.bodies[e].mass
    }
    fn held(&self, e: usize) -> bool {
        self.members[e].held
    }
    fn each_bond(&self, _f: &mut dyn FnMut(usize, usize)) {}
}

impl Simulation for Model {
    fn dt_s(&self) -> f64 {
        self.dt_s
    }
    fn steps(&self) -> u64 {
        self.state.steps
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
        let mut out = MAGIC.to_vec();
        out.extend(self.state.to_bytes());
        out
    }
    fn restore(&mut self, bytes: &[u8]) -> Result<()> {
        if bytes.len() < MAGIC.len() || bytes[..MAGIC.len()] != MAGIC {
            return Err(Error::input("checkpoint", "not a demsweep polyhedra checkpoint (bad magic bytes)"));
        }
        self.state.load(&bytes[MAGIC.len()..]).map_err(|m| Error::input("checkpoint", m))
    }
    fn contact_count(&self) -> u64 {
        self.state.touches.len() as u64
    }
    fn bond_count(&self) -> u64 {
        0
    }
    fn tally(&self) -> Tally {
        let l = &self.state.ledger;
        let dissipated_j = l.damping_j + l.friction_j + l.viscous_j;
        Tally {
            elements: self.members.len() as u64,
            bonds_broken: 0,
            dt_s: self.dt_s,
            dt_bound_s: self.dt_bound_s,
            omega_bound_rad_per_s: 2.0 / self.dt_bound_s,
            dt_limit: format!("{:.3} of 2/ω, the stiffest law on the lightest pair, turning included", self.dt_s / self.dt_bound_s),
            kinetic_energy_j: l.kinetic_j,
            strain_energy_j: l.elastic_j,
            external_work_j: l.external_j,
            mass_damping_j: l.viscous_j,
            contacts_j: vec![("damping_j".into(), l.damping_j), ("friction_j".into(), l.friction_j)],
            dissipated_j,
            energy_residual_j: l.kinetic_j + l.elastic_j - (l.initial_j + l.external_j - dissipated_j),
            energy_in_j: l.initial_j + l.external_j.abs(),
            neighbour_rebuilds: self.state.steps,
            neighbour_local_updates: 0,
        }
    }
}
