//! Energy bookkeeping, per mechanism. The balance
//!
//!   kinetic + strain = initial (kinetic + strain) + external work − dissipated
//!
//! closes to O(Δt²) (central differences carry velocities at half steps); `Ledger::residual_j`
//! is what a test or a run summary checks.

use super::contacts::{Bond, Contact};
use super::forces;
use super::law::{self, ContactClass, Dissipation};
use super::state::Elements;

/// Accumulated work and dissipation since the start of the run, J.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Ledger {
    /// Work of loads, gravity and prescribed motions on the model, J.
    pub external_j: f64,
    /// Mass-proportional Rayleigh damping, J.
    pub mass_damping_j: f64,
    /// Contact dashpots (stiffness-proportional Rayleigh damping), J.
    pub contact_damping_j: f64,
    /// Coulomb sliding, J.
    pub friction_j: f64,
    /// Plastic work on bond plateaus, J.
    pub plastic_j: f64,
    /// Elastic energy released by breaking bonds, J.
    pub fracture_j: f64,
    /// Bonds broken.
    pub bonds_broken: u64,
    /// Kinetic + strain energy at the start, J.
    pub initial_j: f64,
}

impl Ledger {
    /// Everything dissipated, J.
    pub fn dissipated_j(&self) -> f64 {
        self.mass_damping_j + self.contact_damping_j + self.friction_j + self.plastic_j + self.fracture_j
    }

    /// Balance error given the present kinetic and strain energy, J (0 for a perfect ledger).
    pub fn residual_j(&self, kinetic_j: f64, strain_j: f64) -> f64 {
        kinetic_j + strain_j - (self.initial_j + self.external_j - self.dissipated_j())
    }
}

/// Elastic energy stored in the contacts' springs at the current positions, J.
///
/// The tangential springs' history lags the positions by one step (this step's slip is added
/// when the contacts are processed), so the energy is taken from the state the next contact
/// processing would produce: each contact is evaluated on a copy with the law itself.
pub fn strain_energy_j(el: &Elements, list: &[Contact], classes: &[ContactClass], dt_s: f64) -> f64 {
    let mut sum = 0.0;
    let mut scratch = Dissipation::default();
    for c in list {
        let k = &classes[c.class as usize];
        let Some(g) = forces::kinematics(el, c, k) else { continue };
        let mut probe = *c;
        law::interact::<false>(&mut probe, k, &g, dt_s, &mut scratch);
        let stretch = match probe.bond {
            Bond::Intact => g.d_m - probe.d0 - probe.dp,
            Bond::Frictional if g.d_m < probe.d0 => g.d_m - probe.d0,
            Bond::Frictional => continue,
        };
        sum += 0.5 * k.kn_n_per_m * stretch * stretch + 0.5 * k.kt_n_per_m * probe.ut * probe.ut;
    }
    sum
}
