//! What a model is made of, by how it changes: [`Elements`] holds each element's constants
//! (fixed when the model is built), [`State`] everything a step changes. A checkpoint is the
//! [`State`], serialised as it is (`checkpoint`).
//!
//! Elements are rigid disks with two translations and one rotation, per unit of the model's
//! out-of-plane thickness (mass and inertia already include it). Structure of arrays, with the
//! three components of position, velocity and force kept together (`[x, y, θ]`): the contact
//! loop reads both elements' position and velocity at random-ish indices, and one 24-byte group
//! is one cache access instead of three.

use serde::{Deserialize, Serialize};

use super::contacts::Contacts;
use super::ledger::Ledger;

/// Per-element constants. Index `e` addresses the same element in every array.
#[derive(Debug, Clone, Default, PartialEq, Serialize, Deserialize)]
pub struct Elements {
    /// Radius, m.
    pub radius: Vec<f64>,
    /// Mass, kg.
    pub mass: Vec<f64>,
    /// Rotational inertia about the centre, kg·m².
    pub inertia: Vec<f64>,
    /// 1/mass, 1/kg.
    pub inv_mass: Vec<f64>,
    /// 1/inertia, 1/(kg·m²).
    pub inv_inertia: Vec<f64>,
    /// [1/mass 1/kg, 1/mass 1/kg, 1/inertia 1/(kg·m²)]: the inverse of each component of an
    /// `[x, y, θ]` triple, so that a free element's update runs over the components as one
    /// flat array (`integrate`).
    pub inv_mass_3: Vec<[f64; 3]>,
    /// Prescribed degrees of freedom: bit 0 x, bit 1 y, bit 2 rotation (0: free element).
    pub prescribed: Vec<u8>,
    /// Kind (material × radius) index: selects the contact class of new contacts.
    pub kind: Vec<u16>,
    /// Body index (bonds never cross bodies).
    pub body: Vec<u16>,
    /// Motion group: 0 free, g > 0 kinematic, driven by motion group g − 1.
    pub motion: Vec<u16>,
    /// Load group: 0 none, g > 0 receives its share of load group g − 1.
    pub load: Vec<u16>,
    /// Initial [x, y] of the centre, m (for displacements).
    pub initial: Vec<[f64; 2]>,
    /// Initial velocity [vx m/s, vy m/s, ω rad/s] at t = 0.
    pub initial_velocity: Vec<[f64; 3]>,
}

impl Elements {
    /// Number of elements.
    pub fn len(&self) -> usize {
        self.radius.len()
    }

    /// True when there are no elements.
    pub fn is_empty(&self) -> bool {
        self.radius.is_empty()
    }

    /// Append one free element at `centre_m` moving with `velocity`.
    #[allow(clippy::too_many_arguments)]
    pub fn push(&mut self, centre_m: [f64; 2], velocity: [f64; 3], radius_m: f64, mass_kg: f64, inertia_kg_m2: f64, kind: u16, body: u16) {
        self.radius.push(radius_m);
        self.mass.push(mass_kg);
        self.inertia.push(inertia_kg_m2);
        self.inv_mass.push(1.0 / mass_kg);
        self.inv_inertia.push(1.0 / inertia_kg_m2);
        self.inv_mass_3.push([1.0 / mass_kg, 1.0 / mass_kg, 1.0 / inertia_kg_m2]);
        self.kind.push(kind);
        self.body.push(body);
        self.motion.push(0);
        self.prescribed.push(0);
        self.load.push(0);
        self.initial.push(centre_m);
        self.initial_velocity.push(velocity);
    }

    /// Drive element `e` by motion group `group` (0-based) in the dofs of `mask` (bit 0 x,
    /// bit 1 y, bit 2 rotation); the other dofs stay free.
    pub fn set_kinematic(&mut self, e: usize, group: usize, mask: u8) {
        self.motion[e] = group as u16 + 1;
        self.prescribed[e] = mask;
    }

    /// True when some dof of element `e` moves by prescription.
    pub fn is_kinematic(&self, e: usize) -> bool {
        self.motion[e] != 0
    }

    /// True when every dof of element `e` is prescribed.
    pub fn is_fully_prescribed(&self, e: usize) -> bool {
        self.prescribed[e] == 0b111
    }

    /// Whether a contact between elements i and j can matter: not when both are fully
    /// prescribed (their relative motion is given, and no free element feels the force).
    pub fn can_interact(&self, i: usize, j: usize) -> bool {
        !(self.is_fully_prescribed(i) && self.is_fully_prescribed(j))
    }

    /// [1/√m, 1/√m, 1/√I] with 0 in the prescribed dofs: the scaling of the free dofs'
    /// mass-normalised stiffness.
    pub fn free_inv_sqrt_mass(&self, e: usize) -> [f64; 3] {
        let p = self.prescribed[e];
        let f = |bit: u8, inv: f64| if p & bit != 0 { 0.0 } else { inv.sqrt() };
        [f(1, self.inv_mass[e]), f(2, self.inv_mass[e]), f(4, self.inv_inertia[e])]
    }
}

/// Everything a step changes.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct State {
    /// Centre and rotation [x m, y m, θ rad (counter-clockwise)] per element.
    pub pos: Vec<[f64; 3]>,
    /// Velocity at the half step t − Δt/2: [vx m/s, vy m/s, ω rad/s] per element.
    pub vel: Vec<[f64; 3]>,
    /// Total generalised force of the last step (contacts + loads + gravity): [Fx N, Fy N, T N·m].
    pub force: Vec<[f64; 3]>,
    /// Contacts with their history and last forces.
    pub contacts: Contacts,
    /// Element centres at the last neighbour rebuild [x m, y m] (they decide the next one).
    pub rebuild_pos: Vec<[f64; 2]>,
    /// Each element's neighbour margin since the last rebuild, m: a pair is a candidate while
    /// its gap is below the sum of the two margins, and an element that drifts further than
    /// its own margin triggers a rebuild.
    pub margin_m: Vec<f64>,
    /// Energy ledger.
    pub ledger: Ledger<super::law::Dissipation>,
    /// Completed steps.
    pub steps: u64,
    /// Full neighbour rebuilds so far.
    pub rebuilds: u64,
    /// Local neighbour updates so far (see `neighbours`).
    pub local_updates: u64,
}

impl State {
    /// Kinetic energy of the free degrees of freedom, J (velocities at the half step). A
    /// prescribed dof's motion is given, not part of the energy balance: what it does to the
    /// model is the external work of its actuator.
    pub fn kinetic_energy_j(&self, el: &Elements) -> f64 {
        (0..el.len())
            .map(|e| {
                let (v, p) = (self.vel[e], el.prescribed[e]);
                let free = |bit: u8| if p & bit == 0 { 1.0 } else { 0.0 };
                0.5 * el.mass[e] * (free(1) * v[0] * v[0] + free(2) * v[1] * v[1]) + 0.5 * el.inertia[e] * free(4) * v[2] * v[2]
            })
            .sum()
    }

    /// Displacement of element `e` from its initial position, [m, m].
    pub fn displacement_m(&self, el: &Elements, e: usize) -> [f64; 2] {
        [self.pos[e][0] - el.initial[e][0], self.pos[e][1] - el.initial[e][1]]
    }
}
