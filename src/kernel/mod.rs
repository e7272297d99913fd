//! The DEM kernel. A step is the source's three stages (seed 000 §2):
//!
//! 1. **contact processing** (`forces`): every contact's force from the current positions;
//! 2. **element motion** (`integrate`): gather forces, central-difference update, blow-up watch;
//! 3. **contact detection** (`detect`): when any element has drifted more than half the
//!    neighbour skin since the last rebuild, rebuild the candidate pairs, keeping bonds and
//!    touching frictional contacts with their history and dropping separated ones.

pub mod boundary;
pub mod checkpoint;
pub mod build;
pub mod contacts;
pub mod detect;
pub mod energy;
pub mod forces;
pub mod integrate;
pub mod law;
pub mod stability;
pub mod state;

use boundary::{LoadGroup, MotionGroup};
use contacts::{Bond, Contact, Contacts};
use detect::BroadPhase;
use energy::Ledger;
use integrate::{Drive, MotionParams, MotionReport};
use law::{ContactClass, Dissipation};
use state::Elements;

use crate::error::{Error, Result};

pub use build::{ModelBuilder, StepChoice};

/// Contacts below which a model steps on one thread (rayon's fork–join costs more than the
/// work). Results do not depend on it: chunking, not threading, fixes the summation order.
pub const PARALLEL_MIN_CONTACTS: usize = 16_384;

/// The contact class between element kinds a and b (classes are built for every ordered pair).
pub(crate) fn class_index(a: usize, b: usize, kinds: usize) -> u16 {
    (a * kinds + b) as u16
}

/// How the time step was chosen.
#[derive(Debug, Clone, PartialEq)]
pub struct StepInfo {
    /// Bound on the top frequency used, rad/s.
    pub omega_bound_rad_per_s: f64,
    /// Damping ratio at that frequency from the stiffness-proportional term.
    pub xi_at_bound: f64,
    /// Stability limit from the bound, s.
    pub dt_bound_s: f64,
    /// Safety factor applied (1 when the scene fixed the step).
    pub safety: f64,
    /// Step used, s.
    pub dt_s: f64,
    /// What limited the step and how the bound was obtained.
    pub detail: String,
}

/// A model ready to step.
#[derive(Debug, Clone)]
pub struct Model {
    /// Elements.
    pub el: Elements,
    /// Contacts.
    pub contacts: Contacts,
    /// Contact classes.
    pub classes: Vec<ContactClass>,
    kinds: usize,
    /// Prescribed-motion groups.
    pub motions: Vec<MotionGroup>,
    /// Load groups.
    pub loads: Vec<LoadGroup>,
    /// Motion-stage parameters (Δt, α, gravity, speed limit).
    pub motion: MotionParams,
    /// Stiffness-proportional damping present (dashpot part on).
    damped: bool,
    /// Neighbour skin, m.
    pub skin_m: f64,
    rebuild_pos: Vec<[f64; 2]>,
    broad: BroadPhase,
    pairs: Vec<(u32, u32)>,
    diss_partial: Vec<Dissipation>,
    motion_partial: Vec<MotionReport>,
    load_now: Vec<[f64; 2]>,
    motion_now: Vec<[f64; 3]>,
    frame_now: Vec<[f64; 5]>,
    frame_scratch: Vec<[f64; 5]>,
    /// Per-element contact force sums of stage 1 when it runs on one thread (else empty).
    contact_sums: Vec<[f64; 3]>,
    /// Mass-proportional damping spares each body's rigid motion (see `integrate::advance`).
    pub damp_relative_to_rigid: bool,
    bodies: usize,
    /// Energy ledger.
    pub ledger: Ledger,
    /// Simulated time, s.
    pub time_s: f64,
    /// Completed steps.
    pub steps: u64,
    /// Neighbour rebuilds so far.
    pub rebuilds: u64,
    /// Time-step choice.
    pub step_info: StepInfo,
    /// Contacts from which the stages run on rayon's pool (see [`PARALLEL_MIN_CONTACTS`]).
    pub parallel_min_contacts: usize,
}

impl Model {
    /// Time step, s.
    pub fn dt_s(&self) -> f64 {
        self.motion.dt_s
    }

    /// Advance one step. On blow-up the error names the step and the element; the state is
    /// then unusable (the caller must not write it out).
    pub fn step(&mut self) -> Result<()> {
        self.process_contacts();
        let drift2_m2 = self.move_elements()?;
        self.detect_contacts(drift2_m2);
        self.steps += 1;
        self.time_s = self.steps as f64 * self.motion.dt_s;
        Ok(())
    }

    /// Advance `n` steps.
    pub fn run_steps(&mut self, n: u64) -> Result<()> {
        for _ in 0..n {
            self.step()?;
        }
        Ok(())
    }

    fn parallel(&self) -> bool {
        self.contacts.len() >= self.parallel_min_contacts && rayon::current_num_threads() > 1
    }

    fn process_contacts(&mut self) {
        let parallel = self.parallel();
        let n_chunks = self.contacts.len().div_ceil(forces::CHUNK);
        self.diss_partial.resize(n_chunks, Dissipation::default());
        self.contact_sums.clear();
        if !parallel {
            self.contact_sums.resize(self.el.len(), [0.0; 3]);
        }
        let sums = if parallel { None } else { Some(&mut self.contact_sums[..]) };
        let Contacts { list, force, .. } = &mut self.contacts;
        let (el, classes, dt, diss) = (&self.el, &self.classes[..], self.motion.dt_s, &mut self.diss_partial[..]);
        if self.damped {
            forces::process::<true>(el, list, force, classes, dt, diss, sums);
        } else {
            forces::process::<false>(el, list, force, classes, dt, diss, sums);
        }
        let mut total = Dissipation::default();
        for d in &self.diss_partial {
            total.add(d);
        }
        let l = &mut self.ledger;
        l.plastic_j += total.plastic_j;
        l.fracture_j += total.fracture_j;
        l.friction_j += total.friction_j;
        l.contact_damping_j += total.damping_j;
        l.bonds_broken += total.broken as u64;
    }

    /// Returns the largest squared drift since the last neighbour rebuild, m².
    fn move_elements(&mut self) -> Result<f64> {
        self.update_drive();
        let parallel = self.parallel();
        let n_chunks = self.el.len().div_ceil(integrate::CHUNK);
        self.motion_partial.resize(n_chunks, MotionReport::default());
        let drive = Drive { load_force_n: &self.load_now, motion_velocity: &self.motion_now, rigid_frame: &self.frame_now };
        let (el, c, rp, p, part) = (&mut self.el, &self.contacts, &self.rebuild_pos, self.motion, &mut self.motion_partial);
        let sums = &self.contact_sums[..];
        if self.damp_relative_to_rigid {
            integrate::advance::<true>(el, c, sums, rp, drive, p, part, parallel);
        } else {
            integrate::advance::<false>(el, c, sums, rp, drive, p, part, parallel);
        }
        let mut total = MotionReport::default();
        for r in &self.motion_partial {
            total.merge(r);
        }
        if total.first_bad != usize::MAX {
            let e = total.first_bad;
            let v = self.el.vel[e];
            return Err(Error::BlowUp {
                step: self.steps,
                time_s: self.time_s,
                element: e,
                detail: format!(
                    "velocity ({:.3e}, {:.3e}) m/s, spin {:.3e} rad/s exceeds the speed limit {:.3e} m/s or is not finite \
                     (time step {:.4e} s; stability bound {:.4e} s)",
                    v[0], v[1], v[2], self.motion.speed_limit_mps, self.motion.dt_s, self.step_info.dt_bound_s
                ),
            });
        }
        self.ledger.mass_damping_j += total.mass_damping_j;
        self.ledger.external_j += total.external_j;
        Ok(total.max_drift2_m2)
    }

    /// Loads at t, prescribed velocities at t + Δt/2 (the midpoint rule moves a kinematic
    /// element exactly along a prescribed velocity that is linear over the step).
    fn update_drive(&mut self) {
        let (t, half) = (self.time_s, self.time_s + 0.5 * self.motion.dt_s);
        self.load_now.clear();
        let el = &self.el;
        self.load_now.extend(self.loads.iter().map(|g| {
            let n = g.members.len().max(1) as f64;
            match g.servo {
                None => {
                    let s = g.profile.at(t) / n;
                    [g.force_n[0] * s, g.force_n[1] * s]
                }
                Some(servo) => {
                    let [dx, dy] = servo.direction;
                    let mean: f64 = g.members.iter().map(|&e| {
                        let u = el.displacement_m(e as usize);
                        u[0] * dx + u[1] * dy
                    }).sum::<f64>() / n;
                    let f = servo.stiffness_n_per_m * (servo.target_m(t) - mean) / n;
                    [f * dx, f * dy]
                }
            }
        }));
        self.motion_now.clear();
        self.motion_now.extend(self.motions.iter().map(|g| {
            let s = g.profile.at(half);
            [g.velocity[0] * s, g.velocity[1] * s, g.velocity[2] * s]
        }));
        if self.damp_relative_to_rigid {
            integrate::rigid_frames(&self.el, self.bodies, &mut self.frame_now, &mut self.frame_scratch);
        }
    }

    /// Put the free elements' velocities half a step back, v(−Δt/2) = v(0) − (Δt/2) a(0), so
    /// that the given initial velocities are the ones at t = 0 and central differences start
    /// at second order (a free fall is then exact). Contact history is not touched.
    pub(crate) fn prime(&mut self) {
        self.update_drive();
        let mut probe = self.contacts.clone();
        let n_chunks = probe.len().div_ceil(forces::CHUNK);
        let mut partial = vec![Dissipation::default(); n_chunks];
        let Contacts { list, force, .. } = &mut probe;
        forces::process::<false>(&self.el, list, force, &self.classes, 0.0, &mut partial, None);
        let drive = Drive { load_force_n: &self.load_now, motion_velocity: &self.motion_now, rigid_frame: &self.frame_now };
        let f = integrate::forces_now(&self.el, &probe, drive, self.motion.gravity_mps2);
        let h = 0.5 * self.motion.dt_s;
        for (e, fe) in f.iter().enumerate() {
            let inv = [self.el.inv_mass[e], self.el.inv_mass[e], self.el.inv_inertia[e]];
            for d in 0..3 {
                if self.el.prescribed[e] & (1 << d) == 0 {
                    self.el.vel[e][d] -= h * fe[d] * inv[d];
                }
            }
        }
    }

    /// New pairs can only come within reach once some element has moved half the skin: until
    /// then the candidate list is complete (each contact checks touching itself every step).
    fn detect_contacts(&mut self, drift2_m2: f64) {
        if drift2_m2 > 0.25 * self.skin_m * self.skin_m {
            self.rebuild_neighbours();
        }
    }

    /// Rebuild the candidate pairs from the current positions (broad phase + merge).
    pub fn rebuild_neighbours(&mut self) {
        let n = self.el.len();
        let pos = &self.el.pos;
        self.broad.pairs(|e| [pos[e][0], pos[e][1]], &self.el.radius, self.skin_m, &mut self.pairs);
        let el = &self.el;
        let kinds = self.kinds;
        let touching = |c: &Contact| {
            let (pi, pj) = (el.pos[c.i as usize], el.pos[c.j as usize]);
            (pj[0] - pi[0]).powi(2) + (pj[1] - pi[1]).powi(2) < c.d0 * c.d0
        };
        let fresh = |i: u32, j: u32| {
            let (a, b) = (el.kind[i as usize] as usize, el.kind[j as usize] as usize);
            Contact::frictional(i, j, class_index(a, b, kinds), el.radius[i as usize] + el.radius[j as usize])
        };
        let admit = |i: u32, j: u32| el.can_interact(i as usize, j as usize);
        self.contacts.merge_candidates(&self.pairs, touching, fresh, admit, n);
        self.rebuild_pos.clear();
        self.rebuild_pos.extend(self.el.pos.iter().map(|p| [p[0], p[1]]));
        self.rebuilds += 1;
    }

    /// Elastic energy in the contacts, J.
    pub fn strain_energy_j(&self) -> f64 {
        energy::strain_energy_j(&self.el, &self.contacts.list, &self.classes, self.motion.dt_s)
    }

    /// Energy balance residual, J (see `energy::Ledger::residual_j`).
    pub fn energy_residual_j(&self) -> f64 {
        self.ledger.residual_j(self.el.kinetic_energy_j(), self.strain_energy_j())
    }

    /// Number of intact bonds.
    pub fn intact_bonds(&self) -> usize {
        self.contacts.list.iter().filter(|c| c.bond == Bond::Intact).count()
    }

    /// Total force a load group applied in the last step, [N, N].
    pub fn applied_load_n(&self, group: usize) -> [f64; 2] {
        let n = self.loads[group].members.len() as f64;
        [self.load_now[group][0] * n, self.load_now[group][1] * n]
    }

    /// Sum of the forces on a set of elements in the last step, [N, N].
    pub fn force_on(&self, elements: &[usize]) -> [f64; 2] {
        elements.iter().fold([0.0, 0.0], |a, &e| [a[0] + self.el.force[e][0], a[1] + self.el.force[e][1]])
    }

    /// Mean displacement of a set of elements from their initial positions, [m, m].
    pub fn mean_displacement_m(&self, elements: &[usize]) -> [f64; 2] {
        let s = elements.iter().fold([0.0, 0.0], |a, &e| {
            let d = self.el.displacement_m(e);
            [a[0] + d[0], a[1] + d[1]]
        });
        let n = elements.len().max(1) as f64;
        [s[0] / n, s[1] / n]
    }
}
