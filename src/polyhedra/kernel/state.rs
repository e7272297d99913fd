//! What stepping changes: the bodies' motion, the touching pairs with their tangential springs,
//! the energy ledger; and its bytes for a checkpoint (floats as their bits, so a restored run
//! continues bit for bit).

use nalgebra::{Quaternion, UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};

use super::super::body::Body;

/// A pair in contact at the last step, with its tangential spring carried to the next.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Touch {
    /// Lower body index.
    pub i: u32,
    /// Higher body index.
    pub j: u32,
    /// Tangential spring stretch, m (world).
    pub shear: [f64; 3],
}

/// The energy ledger, J. At step n: kinetic and elastic at the whole step n, the rest summed
/// over the steps so far.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Ledger {
    /// Kinetic + elastic energy at the first step, J.
    pub initial_j: f64,
    /// Kinetic energy at the last whole step (½ m v⁻·v⁺ and its rotational counterpart), J.
    pub kinetic_j: f64,
    /// Elastic energy of the contacts' springs at the last step, J.
    pub elastic_j: f64,
    /// Work of gravity (m g·(x − x₀), exact) and of the held bodies' motion, J.
    pub external_j: f64,
    /// Work of the held bodies' prescribed motion so far, J (a part of `external_j`).
    pub held_work_j: f64,
    /// Dissipated by the contacts' dashpots, J.
    pub damping_j: f64,
    /// Dissipated by sliding (the Coulomb cap), J.
    pub friction_j: f64,
    /// Dissipated by the viscous damping of eq 6 (packing only), J.
    pub viscous_j: f64,
    /// Gravity's work over the last step's move x_n → x_(n+1), J: added at the next step.
    pub gravity_ahead_j: f64,
}

/// The evolving state of a polyhedral model.
#[derive(Clone, Debug)]
pub struct State {
    /// The bodies (mass and inertia are configuration; motion is state).
    pub bodies: Vec<Body>,
    /// Pairs touching at the last step, sorted by (i, j).
    pub touches: Vec<Touch>,
    /// Each body's contact force of the last step, N (the projectile's resistance).
    pub contact_force_n: Vec<[f64; 3]>,
    /// Completed steps.
    pub steps: u64,
    /// The ledger.
    pub ledger: Ledger,
    /// The ledger's contact losses split by the pair's kinds: [dashpot, sliding] (J) at
    /// `a × kinds + b` (a ≤ b) for two free bodies of kinds a and b, and at `kinds²` for a
    /// pair with a held body (a wall).
    pub dissipated_by_kinds: Vec<[f64; 2]>,
}

impl State {
    /// [dashpot, sliding] losses so far (J) between free bodies of kinds `a` and `b` of
    /// `kinds`, or (`None`) between a free body and a held one.
    pub fn dissipated_between(&self, kinds: usize, pair: Option<(usize, usize)>) -> [f64; 2] {
        self.dissipated_by_kinds[pair.map_or(kinds * kinds, |(a, b)| a.min(b) * kinds + a.max(b))]
    }
}

/// One body's motion as saved.
#[derive(Serialize, Deserialize)]
struct Motion {
    x: [f64; 3],
    v: [f64; 3],
    q: [f64; 4],
    l: [f64; 3],
}

/// The state as saved.
#[derive(Serialize, Deserialize)]
struct Saved {
    motion: Vec<Motion>,
    touches: Vec<Touch>,
    contact_force_n: Vec<[f64; 3]>,
    steps: u64,
    ledger: Ledger,
    dissipated_by_kinds: Vec<[f64; 2]>,
}

impl State {
    /// The state as bytes (postcard; floats bit-exact).
    pub fn to_bytes(&self) -> Vec<u8> {
        let motion = self
            .bodies
            .iter()
            .map(|b| {
                let q = b.spin.orientation.into_inner();
                Motion { x: b.position.into(), v: b.velocity.into(), q: [q.w, q.i, q.j, q.k], l: b.spin.momentum.into() }
            })
            .collect();
        let saved = Saved { motion, touches: self.touches.clone(), contact_force_n: self.contact_force_n.clone(), steps: self.steps, ledger: self.ledger, dissipated_by_kinds: self.dissipated_by_kinds.clone() };
        postcard::to_stdvec(&saved).expect("the state serialises")
    }

    /// Restores the motion from [`State::to_bytes`] onto these bodies (whose masses stay);
    /// an error says what does not fit.
    pub fn load(&mut self, bytes: &[u8]) -> Result<(), String> {
        let saved: Saved = postcard::from_bytes(bytes).map_err(|e| format!("damaged: {e}"))?;
        if saved.motion.len() != self.bodies.len() || saved.contact_force_n.len() != self.bodies.len() {
            return Err(format!("{} bodies in the checkpoint, {} in the scene", saved.motion.len(), self.bodies.len()));
        }
        if saved.dissipated_by_kinds.len() != self.dissipated_by_kinds.len() {
            return Err(format!("{} kinds' losses in the checkpoint, {} in the scene", saved.dissipated_by_kinds.len(), self.dissipated_by_kinds.len()));
        }
        if saved.touches.iter().any(|t| t.i >= t.j || t.j as usize >= self.bodies.len()) {
            return Err("a contact names a body the scene has not".into());
        }
        for (b, m) in self.bodies.iter_mut().zip(&saved.motion) {
            b.position = Vector3::from(m.x);
            b.velocity = Vector3::from(m.v);
            b.spin.orientation = UnitQuaternion::new_unchecked(Quaternion::new(m.q[0], m.q[1], m.q[2], m.q[3]));
            b.spin.momentum = Vector3::from(m.l);
        }
        self.touches = saved.touches;
        self.contact_force_n = saved.contact_force_n;
        self.steps = saved.steps;
        self.ledger = saved.ledger;
        self.dissipated_by_kinds = saved.dissipated_by_kinds;
        Ok(())
    }
}
