//! Compaction part: densification of a bond in compression (seed 000 §6, eq 6.11, Fig 6.1).
//!
//! The bond's normal spring is linear in compression up to the critical compressive force
//! (f_n^crit)_c = (R t f'c)/(2(1−ν*)) (√3 − ν*/√3) (eq 6.11: eq 5.5 with f'c for σ_ult; on a
//! simple cubic lattice f'c 2R t, as the tensile plateau there), rate-enhanced by the
//! compressive ratio of the rate part. Beyond it the bond is plastic: its rest length d0* (the
//! zero-force distance, `Contact::rest_m`) moves in, so that the force follows the yield line
//! f_c + K_c p, where p = L0 − d0* is the plastic compaction and K_c the compaction stiffness,
//! until p reaches the full-compaction strain × L0; from there the spring is linear with the
//! initial Kn again (the seed: "until d0* reaches the element radius R ... it will continue to
//! have a normal stiffness equal to the initial stiffness Kn"). Unloading follows Kn from the
//! moved rest length, so the compaction is permanent: a compacted bond that later opens in
//! tension measures its opening from d0*.
//!
//! The seed gives neither free parameter ("chosen somewhat arbitrarily"). The defaults are the
//! seed's own description: the branch is perfectly plastic ("the contact normal force will
//! behave in a plastic manner", K_c = 0), and full compaction is reached when d0* = R for two
//! equal elements, a strain of 0.5.
//!
//! The work along the yield line is booked as compaction work; the elastic part stays strain
//! energy.

use serde::{Deserialize, Serialize};

use crate::error::Result;
use crate::material::{Arrangement, CompactionSpec, Material, Plane};


/// Per contact class.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Params {
    /// Compaction acts on this class's bonds (both materials have it).
    pub enabled: bool,
    /// Static critical compressive force (eq 6.11), N.
    pub critical_force_n: f64,
    /// Slope of the yield line K_c, N/m.
    pub stiffness_n_per_m: f64,
    /// Plastic strain at full compaction.
    pub full_strain: f64,
}

/// Critical compressive force of one material's bond (eq 6.11), N.
pub fn critical_force_n(m: &Material, plane: Plane, arrangement: Arrangement, radius_m: f64, thickness_m: f64) -> Result<f64> {
    let fc = m.compressive_strength_pa;
    Ok(match arrangement {
        Arrangement::SimpleCubic => fc * 2.0 * radius_m * thickness_m,
        _ => {
            let nu = m.lattice_poisson(plane, arrangement)?;
            radius_m * thickness_m * fc / (2.0 * (1.0 - nu)) * (3f64.sqrt() - nu / 3f64.sqrt())
        }
    })
}

impl Params {
    /// Parameters between two materials (on when both compact): the weaker critical force,
    /// the softer yield line and the smaller full-compaction strain.
    /// Each side is a material's compaction law (if any) and its bond's critical force, N.
    pub fn between(a: (Option<CompactionSpec>, f64), b: (Option<CompactionSpec>, f64), kn_n_per_m: f64) -> Params {
        let ((Some(ca), fa), (Some(cb), fb)) = (a, b) else { return Params::default() };
        Params {
            enabled: true,
            critical_force_n: fa.min(fb),
            stiffness_n_per_m: ca.stiffness_ratio.min(cb.stiffness_ratio) * kn_n_per_m,
            full_strain: ca.full_strain.min(cb.full_strain),
        }
    }

    /// Return map of a bond in compression. `force_n` is the trial normal force (< 0 in
    /// compression) with stiffness `kn` = (now, in the last step), `step_m` the change of the
    /// bond's length over this step; `rest_m` the rest length, moved in by the plastic compaction; `length0_m` the
    /// initial length; `strength_ratio` the dynamic factor of the critical force. Returns the
    /// force and the work along the yield line, J: the compaction times the mean of the last
    /// step's force and the new one (`normal::bonded`), so that a yield line that moves (the
    /// rate-enhanced critical force decaying, hardening) is booked as central differences
    /// see it.
    #[inline(always)]
    pub fn compress(&self, force_n: f64, step_m: f64, (kn, kn_last): (f64, f64), rest_m: &mut f64, length0_m: f64, strength_ratio: f64) -> (f64, f64) {
        let p = length0_m - *rest_m;
        let room = self.full_strain * length0_m - p;
        let limit = self.critical_force_n * strength_ratio + self.stiffness_n_per_m * p.max(0.0);
        if -force_n <= limit || room <= 0.0 {
            return (force_n, 0.0);
        }
        let dp = ((-force_n - limit) / (kn + self.stiffness_n_per_m)).min(room);
        *rest_m -= dp;
        let (last, new) = (kn_last * (force_n / kn - step_m), force_n + kn * dp);
        (new, -0.5 * (last + new) * dp)
    }
}
