//! The 3D kernel under the contract of `crate::simulation`.

use std::ops::Range;

use super::Model;
use super::contact::Bond;
use super::state::State;
use crate::error::{Error, Result};
use crate::simulation::{Bodies, Simulation, Tally, Threading};

const MAGIC: [u8; 8] = *b"DEMS3D\x00\x01";

impl Bodies for Model {
    fn time_s(&self) -> f64 {
        Model::time_s(self)
    }
    fn body(&self, name: &str) -> Option<Range<usize>> {
        self.bodies.iter().find(|b| b.name == name).map(|b| b.elements.clone())
    }
    fn element_count(&self) -> usize {
        self.spheres.len()
    }
    fn initial_m(&self, e: usize) -> [f64; 3] {
        self.spheres.initial_m[e]
    }
    fn position_m(&self, e: usize) -> [f64; 3] {
        self.state.pos_m[e]
    }
    fn velocity_mps(&self, e: usize) -> [f64; 3] {
        self.state.vel_mps[e]
    }
    fn radius_m(&self, e: usize) -> f64 {
        self.spheres.radius_m[e]
    }
    fn mass_kg(&self, e: usize) -> f64 {
        self.spheres.mass_kg[e]
    }
    fn held(&self, e: usize) -> bool {
        self.spheres.anchored(e)
    }
    fn each_bond(&self, f: &mut dyn FnMut(usize, usize)) {
        for c in self.state.contacts.iter().filter(|c| c.bond == Bond::Intact) {
            f(c.i as usize, c.j as usize);
        }
    }
}

impl Simulation for Model {
    fn dt_s(&self) -> f64 {
        self.motion.dt_s
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
        out.extend(postcard::to_stdvec(&self.state).expect("the state serialises"));
        out
    }
    fn restore(&mut self, bytes: &[u8]) -> Result<()> {
        let bad = |m: String| Error::input("checkpoint", m);
        if bytes.len() < MAGIC.len() || bytes[..MAGIC.len()] != MAGIC {
            return Err(bad("not a demsweep 3D checkpoint (bad magic bytes)".into()));
        }
        let state: State = postcard::from_bytes(&bytes[MAGIC.len()..]).map_err(|e| bad(format!("damaged: {e}")))?;
        if state.pos_m.len() != self.spheres.len() {
            return Err(bad(format!("{} spheres in the checkpoint, {} in the scene", state.pos_m.len(), self.spheres.len())));
        }
        self.state = state;
        Ok(())
    }
    fn contact_count(&self) -> u64 {
        self.state.contacts.len() as u64
    }
    fn bond_count(&self) -> u64 {
        self.intact_bonds() as u64
    }
    fn tally(&self) -> Tally {
        let l = &self.state.ledger;
        // Energies of the whole a model with symmetry planes is a part of (`mirror`).
        let c = self.mirrors.copies();
        // The energies at the last whole step, second order in Δt (`kernel3d::energy`).
        let w = self.whole_step();
        let (ke, se) = (c * w.kinetic_j, c * w.strain_j);
        let dissipated_j = c * (w.mass_damping_j + w.local_damping_j + w.radiated_j + l.contacts.total_j());
        // Local damping and what the boundary let out (3D only) are listed after the contacts'
        // mechanisms.
        let mut by_mechanism: Vec<(String, f64)> = l.contacts.terms().into_iter().map(|(k, v)| (k.to_string(), c * v)).collect();
        by_mechanism.push(("local_damping_j".to_string(), c * w.local_damping_j));
        by_mechanism.push(("radiated_j".to_string(), c * w.radiated_j));
        Tally {
            elements: self.spheres.len() as u64,
            bonds_broken: l.bonds_broken(),
            dt_s: self.motion.dt_s,
            dt_bound_s: self.dt_bound_s,
            omega_bound_rad_per_s: self.omega_bound_rad_per_s,
            dt_limit: format!("{:.2} of the contact-by-contact bound over the contacts and the candidates", self.motion.dt_s / self.dt_bound_s),
            kinetic_energy_j: ke,
            strain_energy_j: se,
            external_work_j: c * w.external_j,
            mass_damping_j: c * w.mass_damping_j,
            contacts_j: by_mechanism,
            dissipated_j,
            energy_residual_j: ke + se - (c * (l.initial_j + w.external_j) - dissipated_j),
            energy_in_j: c * (l.initial_j + w.external_j.abs()),
            neighbour_rebuilds: self.state.searches,
            neighbour_local_updates: 0,
        }
    }
}
