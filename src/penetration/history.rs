//! A penetration run's history (`run --history-every-ms`): at each record, where the projectile
//! is and what resists it, and where the target's energy and damage are, near the path and far
//! from it. What the summary row reports at the end, against time: to read where the impact's
//! energy went and when the bonds far from the path broke.

use serde::Serialize;

use super::fragments;
use super::outcome::{Detector, FAR_CALIBRES};
use crate::run::Columns;
use crate::simulation::Simulation;
use crate::units::{KG_PER_LB, M_PER_IN, mps_to_fps};

/// Newtons in a kip (1000 lbf).
const N_PER_KIP: f64 = 4448.221615260501;

/// One record of a run's history.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HistoryRow {
    /// Time, ms.
    pub time_ms: f64,
    /// Depth of the nose below the original front face, in.
    pub depth_in: f64,
    /// The projectile's centre's speed along the impact axis, ft/s (> 0 going in).
    pub v_axial_fps: f64,
    /// The mean force resisting the projectile along its axis since the last record, kip: its
    /// loss of axial momentum over the interval.
    pub resistance_kip: f64,
    /// Kinetic energy of the target's elements within `FAR_CALIBRES` of the axis, J.
    pub near_kinetic_j: f64,
    /// Kinetic energy of the target's elements beyond it, J.
    pub far_kinetic_j: f64,
    /// ... of those still attached to the supports (the slab's vibration away from the path,
    /// without the debris flying over it), J.
    pub far_attached_kinetic_j: f64,
    /// Front-face ejecta: the target's elements above the original front face moving out of
    /// the slab, their mass, lb.
    pub ejecta_lb: f64,
    /// ... their kinetic energy, J.
    pub ejecta_kinetic_j: f64,
    /// ... their momentum out of the slab along the axis, N·s (> 0 out).
    pub ejecta_momentum_n_s: f64,
    /// The whole target's momentum along the impact axis, N·s (> 0 going in): with the
    /// projectile's loss and the supports' impulse it closes the momentum balance.
    pub target_momentum_n_s: f64,
    /// Target bonds broken within `FAR_CALIBRES` of the axis.
    pub near_bonds_broken: u64,
    /// Target bonds broken beyond `FAR_CALIBRES` of the axis.
    pub far_bonds_broken: u64,
    /// The ledger: kinetic and strain energy, and what was dissipated by mechanism, J.
    pub kinetic_j: f64,
    /// Strain energy, J.
    pub strain_j: f64,
    /// Dissipated by mechanism (the kernel's columns), J.
    pub ledger: Columns,
}

/// The recorder.
#[derive(Debug, Clone, Default)]
pub struct History {
    /// The records so far.
    pub rows: Vec<HistoryRow>,
    /// Target bonds at the start (near, far).
    bonds_initial: Option<(u64, u64)>,
    /// The last record's time (s) and the projectile's axial momentum (kg·m/s).
    last: Option<(f64, f64)>,
}

impl History {
    /// Take a record of `m`, laid out as `detector` reads it.
    pub fn record<M: Simulation>(&mut self, m: &M, detector: &Detector) {
        let (target, projectile) = (detector.target(), detector.projectile());
        let axis = detector.layout.axis;
        let (mut mass, mut p_axial, mut lowest) = (0.0, 0.0, f64::INFINITY);
        for e in projectile {
            let (v, me) = (m.velocity_mps(e), m.mass_kg(e));
            mass += me;
            p_axial += me * (v[0] * axis[0] + v[1] * axis[1] + v[2] * axis[2]);
            lowest = lowest.min(m.position_m(e)[1] - m.radius_m(e));
        }
        let far_m = FAR_CALIBRES * detector.layout.projectile_width_m;
        let (frags, of) = fragments::fragments(m, target.clone(), |_| (false, false));
        let (mut near_k, mut far_k, mut far_attached_k) = (0.0, 0.0, 0.0);
        let (mut ejecta_kg, mut ejecta_k, mut ejecta_p, mut target_p) = (0.0, 0.0, 0.0, 0.0);
        for e in target.clone() {
            let (v, me) = (m.velocity_mps(e), m.mass_kg(e));
            let k = 0.5 * me * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            let v_in = v[0] * axis[0] + v[1] * axis[1] + v[2] * axis[2];
            target_p += me * v_in;
            if m.position_m(e)[1] - m.radius_m(e) > detector.layout.front_y_m && v_in < 0.0 {
                (ejecta_kg, ejecta_k, ejecta_p) = (ejecta_kg + me, ejecta_k + k, ejecta_p - me * v_in);
            }
            if detector.from_axis_m(m.initial_m(e)) > far_m {
                far_k += k;
                if frags[of[e - target.start] as usize].supported {
                    far_attached_k += k;
                }
            } else {
                near_k += k;
            }
        }
        let (near, far) = detector.bonds_near_far(m);
        let (near0, far0) = *self.bonds_initial.get_or_insert((near, far));
        // Momenta, masses and energies of the whole (`Layout::copies`).
        let c = detector.layout.copies();
        let (p_axial, ejecta_kg, ejecta_k, ejecta_p, target_p) = (c * p_axial, c * ejecta_kg, c * ejecta_k, c * ejecta_p, c * target_p);
        let (mass, near_k, far_k, far_attached_k) = (c * mass, c * near_k, c * far_k, c * far_attached_k);
        let t = m.time_s();
        let resistance = match self.last {
            Some((t0, p0)) if t > t0 => (p0 - p_axial) / (t - t0),
            _ => 0.0,
        };
        self.last = Some((t, p_axial));
        let tally = m.tally();
        self.rows.push(HistoryRow {
            time_ms: t * 1e3,
            depth_in: (detector.layout.front_y_m - lowest) / M_PER_IN,
            v_axial_fps: mps_to_fps(p_axial / mass),
            resistance_kip: resistance / N_PER_KIP,
            near_kinetic_j: near_k,
            far_kinetic_j: far_k,
            far_attached_kinetic_j: far_attached_k,
            ejecta_lb: ejecta_kg / KG_PER_LB,
            ejecta_kinetic_j: ejecta_k,
            ejecta_momentum_n_s: ejecta_p,
            target_momentum_n_s: target_p,
            near_bonds_broken: near0.saturating_sub(near),
            far_bonds_broken: far0.saturating_sub(far),
            kinetic_j: tally.kinetic_energy_j,
            strain_j: tally.strain_energy_j,
            ledger: Columns(tally.contacts_j.into_iter().chain([("mass_damping_j".to_string(), tally.mass_damping_j)]).collect()),
        });
    }
}
