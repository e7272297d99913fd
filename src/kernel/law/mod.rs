//! The contact law, composed of small parts (LAMMPS GRANULAR style): normal ⊕ tangential ⊕
//! damping ⊕ failure. A contact class carries every parameter; which optional parts run is a
//! compile-time choice made once per step from the scene (`Parts`), so a part a scene leaves
//! off is not even a branch in the contact loop.

pub mod damping;
pub mod failure;
pub mod normal;
pub mod tangential;

use super::contacts::{Bond, Contact, ContactForce};
use crate::material::Strength;

/// Parameters of one kind of contact (a pair of element kinds).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactClass {
    /// Normal stiffness Kn, N/m.
    pub kn_n_per_m: f64,
    /// Tangential stiffness Kt, N/m.
    pub kt_n_per_m: f64,
    /// Bond strength (plateaus and breaking opening).
    pub strength: Strength,
    /// Coulomb friction coefficient μ of frictional contacts.
    pub friction: f64,
    /// Cohesion c of frictional contacts, N.
    pub cohesion_n: f64,
    /// Share of the centre distance from i's centre to the contact point: r_i/(r_i + r_j).
    pub lever_i: f64,
    /// Share for j: r_j/(r_i + r_j).
    pub lever_j: f64,
    /// Normal dashpot β·Kn, N·s/m (0 without stiffness-proportional damping).
    pub dashpot_n_s_per_m: f64,
    /// Tangential dashpot β·Kt, N·s/m.
    pub dashpot_t_s_per_m: f64,
}

/// Energy a contact dissipated in one step, J, and whether its bond broke.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Dissipation {
    /// Plastic work on the bond plateaus (normal and shear), J.
    pub plastic_j: f64,
    /// Elastic energy released by bonds breaking, J.
    pub fracture_j: f64,
    /// Coulomb sliding, J.
    pub friction_j: f64,
    /// Contact dashpots, J.
    pub damping_j: f64,
    /// Bonds broken.
    pub broken: u32,
}

impl Dissipation {
    /// Add another step's or chunk's dissipation.
    #[inline(always)]
    pub fn add(&mut self, o: &Dissipation) {
        self.plastic_j += o.plastic_j;
        self.fracture_j += o.fracture_j;
        self.friction_j += o.friction_j;
        self.damping_j += o.damping_j;
        self.broken += o.broken;
    }
}

/// Kinematics of a contact at the current configuration.
#[derive(Debug, Clone, Copy)]
pub struct Kinematics {
    /// Centre distance d, m.
    pub d_m: f64,
    /// Unit normal from i to j.
    pub nx: f64,
    /// Unit normal y.
    pub ny: f64,
    /// Relative normal velocity of j w.r.t. i (> 0 separating), m/s.
    pub vn_mps: f64,
    /// Relative tangential velocity of the contact points (j w.r.t. i along t = (−ny, nx)), m/s.
    pub vt_mps: f64,
    /// Lever arm of i, m.
    pub li_m: f64,
    /// Lever arm of j, m.
    pub lj_m: f64,
}

/// Evaluate one touching or bonded contact: update its history and return its force.
/// `DAMP` switches the dashpot part on.
#[inline(always)]
pub fn interact<const DAMP: bool>(c: &mut Contact, k: &ContactClass, g: &Kinematics, dt_s: f64, diss: &mut Dissipation) -> ContactForce {
    let opening = g.d_m - c.d0;
    let slip = g.vt_mps * dt_s;
    let (mut f_n, mut f_t);
    if c.bond == Bond::Intact {
        let (f, w) = normal::bonded(opening, &mut c.dp, k.kn_n_per_m, k.strength.normal_force_n);
        let (ft, ut, ws) = tangential::capped_spring(c.ut, slip, k.kt_n_per_m, k.strength.shear_force_n);
        diss.plastic_j += w + ws;
        if failure::breaks(c.dp, k.strength.plastic_opening_at_break_m) {
            diss.fracture_j += failure::released_energy_j(f, ft, k.kn_n_per_m, k.kt_n_per_m);
            diss.broken += 1;
            c.bond = Bond::Frictional;
            c.dp = 0.0;
            c.ut = 0.0;
            // Breaking needs tension beyond the plateau (opening > δ_p ≥ 0): the pair is apart,
            // and a frictional contact that is apart carries nothing.
            return ContactForce::default();
        }
        c.ut = ut;
        f_n = f;
        f_t = ft;
        if DAMP {
            let (dn, dt) = damping::dashpot(k, g.vn_mps, g.vt_mps);
            f_n += dn;
            f_t += dt;
            diss.damping_j += (dn * g.vn_mps + dt * g.vt_mps) * dt_s;
        }
        return force(g, f_n, f_t);
    }
    frictional::<DAMP>(c, k, g, opening, slip, dt_s, diss)
}

#[inline(always)]
fn frictional<const DAMP: bool>(
    c: &mut Contact,
    k: &ContactClass,
    g: &Kinematics,
    opening: f64,
    slip: f64,
    dt_s: f64,
    diss: &mut Dissipation,
) -> ContactForce {
    let mut f_n = normal::frictional(opening, k.kn_n_per_m);
    let limit = k.friction * (-f_n) + k.cohesion_n;
    let (mut f_t, ut, w) = tangential::capped_spring(c.ut, slip, k.kt_n_per_m, limit);
    c.ut = ut;
    diss.friction_j += w;
    if DAMP {
        // A frictional contact never pulls, and a sliding one has no tangential dashpot.
        let (dn, dt) = damping::dashpot(k, g.vn_mps, g.vt_mps);
        let fn_damped = (f_n + dn).min(0.0);
        diss.damping_j += (fn_damped - f_n) * g.vn_mps * dt_s;
        f_n = fn_damped;
        if w == 0.0 {
            f_t += dt;
            diss.damping_j += dt * g.vt_mps * dt_s;
        }
    }
    force(g, f_n, f_t)
}

/// Cartesian force on i and the torques, from the normal (tension positive) and tangential force.
#[inline(always)]
fn force(g: &Kinematics, f_n: f64, f_t: f64) -> ContactForce {
    ContactForce {
        fx: f_n * g.nx - f_t * g.ny,
        fy: f_n * g.ny + f_t * g.nx,
        ti: g.li_m * f_t,
        tj: g.lj_m * f_t,
    }
}
