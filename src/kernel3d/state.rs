//! The spheres' constants (configuration) and the state a step changes.

use serde::{Deserialize, Serialize};

use super::contact::Contact;
use super::law::Dissipation;
use super::vec3::V3;

/// Per-sphere constants, fixed when the model is built.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Spheres {
    /// Radius, m.
    pub radius_m: Vec<f64>,
    /// Mass, kg.
    pub mass_kg: Vec<f64>,
    /// Moment of inertia about any axis through the centre, kg·m².
    pub inertia_kg_m2: Vec<f64>,
    /// Kind (material), indexing the contact classes.
    pub kind: Vec<u16>,
    /// Where each started, m.
    pub initial_m: Vec<V3>,
    /// Held: translation at `prescribed_mps`, no spin (a support or a driven grip).
    pub held: Vec<bool>,
    /// Velocity of a held sphere, m/s.
    pub prescribed_mps: Vec<V3>,
    /// Constant external force, N.
    pub load_n: Vec<V3>,
    /// Constant external moment, N·m.
    pub load_nm: Vec<V3>,
    /// Local damping coefficient λ (dimensionless, `integrate`), one per sphere, 0 for an
    /// undamped one; empty when the model damps none (the step then never reads it).
    #[serde(default)]
    pub local_damping: Vec<f64>,
    /// Viscous boundary: the coefficient of each sphere's dashpot to what lies beyond the model
    /// along x, y and z, kg/s (`integrate`; Lysmer & Kuhlemeyer's ρ c A); empty when no sphere
    /// has one (the step then never reads it).
    #[serde(default)]
    pub dashpot_kg_per_s: Vec<V3>,
}

impl Spheres {
    /// Number of spheres.
    pub fn len(&self) -> usize {
        self.radius_m.len()
    }

    /// True when there are none.
    pub fn is_empty(&self) -> bool {
        self.radius_m.is_empty()
    }

    /// Sphere e's local damping coefficient λ (0 where the model damps none).
    pub fn local_damping_of(&self, e: usize) -> f64 {
        self.local_damping.get(e).copied().unwrap_or(0.0)
    }

    /// Sphere e's dashpot coefficients along x, y, z, kg/s (zero where it has none).
    pub fn dashpot_of(&self, e: usize) -> V3 {
        self.dashpot_kg_per_s.get(e).copied().unwrap_or([0.0; 3])
    }

    /// Sphere e ends on what lies beyond the model: held, or on a dashpot to it (a support for
    /// the outcome's fragments).
    pub fn anchored(&self, e: usize) -> bool {
        self.held[e] || self.dashpot_of(e) != [0.0; 3]
    }
}

/// The energy ledger of the 3D contacts' mechanisms (the 2D kernel's, `kernel::ledger`).
pub type Ledger = crate::kernel::ledger::Ledger<Dissipation>;

/// What a step changes (what a checkpoint holds).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct State {
    /// Centres, m.
    pub pos_m: Vec<V3>,
    /// Half-step velocities, m/s.
    pub vel_mps: Vec<V3>,
    /// Half-step spins, rad/s.
    pub spin_rad_per_s: Vec<V3>,
    /// Contact force sums of the last step (held spheres: the reaction), N.
    pub force_n: Vec<V3>,
    /// Contact moment sums of the last step, N·m.
    pub moment_nm: Vec<V3>,
    /// Contacts, sorted by (i, j).
    pub contacts: Vec<Contact>,
    /// Centres at the last neighbour search, m.
    pub searched_at_m: Vec<V3>,
    /// Completed steps.
    pub steps: u64,
    /// Neighbour searches.
    pub searches: u64,
    /// The energy ledger.
    pub ledger: Ledger,
}
