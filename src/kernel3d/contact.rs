//! One contact between two spheres: who, whether bonded, and its history (what evolves).

use serde::{Deserialize, Serialize};

use super::vec3::V3;
pub use crate::kernel::contact::Bond;
pub use crate::kernel::law::Extra;

/// A contact's record. Everything here evolves except `i`, `j`, `class` and `image`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Contact {
    /// First sphere (i < j).
    pub i: u32,
    /// Second sphere.
    pub j: u32,
    /// Contact class (`class_index` of the two kinds).
    pub class: u16,
    /// Which symmetry planes j is seen through (`mirror::Mirrors`, a bit per plane; 0: j
    /// itself, and i < j; else i ≤ j).
    pub image: u8,
    /// Bonded, or frictional after failure or for a new contact.
    pub bond: Bond,
    /// Rest length d0, m (the centre distance when the bond formed; r_i + r_j for a new one).
    pub rest_m: f64,
    /// The unit normal from i to j at the last step (the frame the history lives in).
    pub normal: V3,
    /// Shear spring: the tangential force, N, in the plane normal to `normal`.
    pub shear_n: V3,
    /// Plastic opening of the bond's tensile plateau, m (seed 000 §5).
    pub plastic_opening_m: f64,
    /// The rolling moment k_r θ_r, N·m (seed 004 eq 15, capped by eq 16), in the contact plane.
    pub rolling_nm: V3,
    /// The twisting moment k_t ω_M about the normal, N·m (eq 24, capped by eq 25/42).
    pub twisting_nm: f64,
    /// A bond's rate and compaction state (the 2D kernel's record), where its class has either
    /// part; none for frictional contacts, which have neither.
    pub extra: Option<Box<Extra>>,
}

impl Contact {
    /// A fresh contact of `class` between i < j at rest length `rest_m` along `normal`.
    pub fn new(i: u32, j: u32, class: u16, bond: Bond, rest_m: f64, normal: V3) -> Contact {
        Contact { i, j, class, image: 0, bond, rest_m, normal, shear_n: [0.0; 3], plastic_opening_m: 0.0, rolling_nm: [0.0; 3], twisting_nm: 0.0, extra: None }
    }

    /// Forget the history of a contact that let go (a bond broke, or a frictional contact came
    /// apart) at centre distance `d_m`: its rest length returns towards touching, r_i + r_j, but
    /// never past the present distance, so a pair a compacted bond held closer than touching
    /// (`kernel::law::compaction`) is left apart, not thrown out of an overlap it did not have.
    pub fn forget(&mut self, radius_sum_m: f64, d_m: f64) {
        self.shear_n = [0.0; 3];
        self.rolling_nm = [0.0; 3];
        self.twisting_nm = 0.0;
        self.rest_m = radius_sum_m.min(self.rest_m.max(d_m));
    }
}
