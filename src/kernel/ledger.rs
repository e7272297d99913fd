//! The energy ledger: work and dissipation accumulated since the start of a run, per
//! mechanism (the contacts' listed once, in `law::Dissipation`). `energy` computes the strain
//! energy it is balanced against.

use serde::{Deserialize, Serialize};

use super::law::Dissipation;

/// Accumulated work and dissipation since the start of the run, J.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct Ledger {
    /// Kinetic + strain energy at the start, J.
    pub initial_j: f64,
    /// Work of loads, gravity and prescribed motions on the model, J.
    pub external_j: f64,
    /// Mass-proportional Rayleigh damping, J.
    pub mass_damping_j: f64,
    /// What the contacts dissipated, by mechanism, and the bonds broken.
    pub contacts: Dissipation,
}

impl Ledger {
    /// Everything dissipated, J.
    pub fn dissipated_j(&self) -> f64 {
        self.mass_damping_j + self.contacts.total_j()
    }

    /// Balance error given the present kinetic and strain energy, J (0 for a perfect ledger).
    pub fn residual_j(&self, kinetic_j: f64, strain_j: f64) -> f64 {
        kinetic_j + strain_j - (self.initial_j + self.external_j - self.dissipated_j())
    }

    /// Bonds broken so far.
    pub fn bonds_broken(&self) -> u64 {
        self.contacts.broken
    }
}
