//! One contact's record: which pair, its class, its history, and the force it gives. What the
//! law reads and writes; the list of them is `contacts`.

use serde::{Deserialize, Serialize};

/// State of a contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[repr(u8)]
pub enum Bond {
    /// Bonded: tension and compression, shear spring, failure law.
    Intact = 0,
    /// Frictional: compression only, Coulomb (eq 2.1). New contacts and broken bonds.
    Frictional = 1,
}

/// One contact: which pair, its class, and its history (what evolves). Geometry is recomputed
/// every step.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Contact {
    /// First element (i < j).
    pub i: u32,
    /// Second element.
    pub j: u32,
    /// Contact class (stiffness, strength, friction), see `law::ContactClass`.
    pub class: u16,
    /// Bonded or frictional.
    pub bond: Bond,
    /// Rest length d0*, m: the distance at which the normal spring carries no force. A bond
    /// starts at its initial distance and compaction moves it in; a new pair starts at
    /// r_i + r_j. A frictional contact touches while the distance is below it.
    pub rest_m: f64,
    /// Elastic tangential displacement u_t, m (shear force = Kt u_t).
    pub ut_m: f64,
    /// Plastic normal opening δ_p of a bond's tension plateau, m.
    pub dp_m: f64,
}

impl Contact {
    /// A bond between i and j at rest distance `rest_m`.
    pub fn bonded(i: u32, j: u32, class: u16, rest_m: f64) -> Contact {
        Contact { i, j, class, bond: Bond::Intact, rest_m, ut_m: 0.0, dp_m: 0.0 }
    }

    /// A new frictional contact, touching once the distance drops below `rest_m` (r_i + r_j).
    pub fn frictional(i: u32, j: u32, class: u16, rest_m: f64) -> Contact {
        Contact { i, j, class, bond: Bond::Frictional, rest_m, ut_m: 0.0, dp_m: 0.0 }
    }

    /// The pair as one sortable key.
    pub(crate) fn key(&self) -> u64 {
        ((self.i as u64) << 32) | self.j as u64
    }
}

/// Force of one contact in the current step: (fx, fy) acts on i, −(fx, fy) on j.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct ContactForce {
    /// Force on i, x, N.
    pub fx: f64,
    /// Force on i, y, N.
    pub fy: f64,
    /// Torque on i, N·m.
    pub ti: f64,
    /// Torque on j, N·m.
    pub tj: f64,
}
