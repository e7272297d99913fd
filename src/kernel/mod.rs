//! The DEM kernel. A step is the source's three stages (seed 000 §2):
//!
//! 1. **contact processing** (`forces`): every contact's force from the current positions,
//!    added to its two elements (`pieces` on the pool);
//! 2. **element motion** (`integrate`): summed forces, central-difference update, blow-up watch;
//! 3. **contact detection** (`crate::broad_phase`, `neighbours`): when an element has drifted further than
//!    its neighbour margin since the last rebuild, rebuild the candidate pairs, keeping bonds
//!    and frictional contacts with their history.
//!
//! A [`Model`]'s fields say how they change: configuration fixed when it is built (elements'
//! constants, contact classes, the enabled law parts, boundary groups, the time step), the
//! [`State`] that stepping changes (what a checkpoint holds), and scratch buffers.

pub mod boundary;
pub mod build;
pub mod checkpoint;
pub mod contact;
pub mod contacts;
pub mod energy;
pub mod exec;
pub mod forces;
pub mod geometry;
pub mod groups;
pub mod integrate;
pub mod lanes;
pub mod law;
pub mod ledger;
pub mod neighbours;
pub mod stability;
pub mod contract;
pub mod state;

use std::ops::Range;

use serde::{Deserialize, Serialize};

use boundary::{LoadGroup, MotionGroup};
use contact::Bond;
use integrate::{Drive, MotionParams, MotionReport};
use law::{ContactClass, Dissipation, Parts};
pub use state::{Elements, State};

use crate::error::{Error, Result};

pub use build::{ModelBuilder, StepChoice};
pub use crate::simulation::Threading;

/// Contacts below which a model steps on one thread (rayon's fork–join costs more than the
/// work). Results do not depend on it: chunking, not threading, fixes the summation order.
pub const PARALLEL_MIN_CONTACTS: usize = 16_384;

/// The contact class between element kinds a and b (classes are built for every ordered pair).
pub(crate) fn class_index(a: usize, b: usize, kinds: usize) -> u16 {
    (a * kinds + b) as u16
}

/// How the time step was chosen.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
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

/// A body: a named range of elements (a lattice, a projectile).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Body {
    /// Name from the scene.
    pub name: String,
    /// Its elements.
    pub elements: Range<usize>,
}

#[derive(Debug, Clone, Default)]
struct Scratch {
    broad: crate::broad_phase::BroadPhase,
    pairs: Vec<(u32, u32)>,
    diss_partial: Vec<Dissipation>,
    motion_partial: Vec<MotionReport>,
    load_now: Vec<[f64; 2]>,
    motion_now: Vec<[f64; 3]>,
    frame_now: Vec<[f64; 5]>,
    frame_scratch: Vec<[f64; 5]>,
    /// Per-element contact force sums of stage 1: zero between steps (the motion stage zeroes
    /// each entry as it reads it, sparing a pass that clears them).
    contact_sums: Vec<[f64; 3]>,
    /// The pieces' records of the scatter on the pool (`pieces`): made by the contact stage,
    /// added to `contact_sums` by the motion stage.
    records: Vec<exec::pieces::Kept>,
    /// The contact stage's plan on the pool, kept up with the contact list.
    plan: exec::pieces::Plan,
    movers: Vec<u32>,
    is_mover: Vec<bool>,
    /// The motion stage's spans of chunks on the pool (`integrate::Motion::spans`).
    motion_spans: Vec<usize>,
}

/// A model ready to step.
#[derive(Debug, Clone)]
pub struct Model {
    // Configuration, fixed when built.
    /// Element constants.
    pub el: Elements,
    /// Contact classes, `class_index(kind_i, kind_j)`.
    pub classes: Vec<ContactClass>,
    /// Optional law parts on.
    pub parts: Parts,
    kinds: usize,
    /// Bodies, in scene order.
    pub bodies: Vec<Body>,
    /// Prescribed-motion groups.
    pub motions: Vec<MotionGroup>,
    /// Load groups.
    pub loads: Vec<LoadGroup>,
    /// Motion-stage parameters (Δt, α, gravity, speed limit).
    pub motion: MotionParams,
    /// Neighbour search settings.
    pub neighbours: neighbours::Settings,
    /// Mass-proportional damping spares each body's rigid motion (see `integrate::advance`).
    pub damp_relative_to_rigid: bool,
    /// Time-step choice.
    pub step_info: StepInfo,
    /// Where steps run.
    pub threading: Threading,
    /// Contacts from which the stages run on rayon's pool (see [`PARALLEL_MIN_CONTACTS`]).
    pub parallel_min_contacts: usize,
    /// Keep each contact's force of the last step in `state.contacts.force` (an observable: the
    /// virial stress, a single contact's law). The contact stage adds each force to its two
    /// elements as it goes and, without this, stores no copy (the copy was 1.3 MB written per
    /// step on the peers' beam, about a tenth of its step).
    pub record_contact_forces: bool,
    /// Contacts per piece of the contact stage's scatter on the pool at most (`pieces`; a
    /// multiple of `forces::CHUNK`; only the front pieces of each thread's span are this long,
    /// the others shrink to two chunks at its back, see `exec::pieces::cuts`). The bits do not depend
    /// on it; smaller pieces balance the threads better and send more contributions through the
    /// serial fix-up.
    pub scatter_piece_contacts: usize,
    /// Take the contacts four at a time where the law parts allow (`groups`, on the widest
    /// `lanes` the processor has; the same bits as one at a time). Off only to measure what it
    /// gains.
    pub four_lanes: bool,
    /// The lanes of the four-at-a-time paths, contacts and free elements alike: the widest the
    /// processor has (`lanes::widest`); the portable ones to check them in whole runs (the
    /// same bits).
    pub lane_width: lanes::Width,
    /// The rate part's smoothed velocity field (`law::rate_field`): its grid is configuration,
    /// its values are remade from the state at every step.
    pub rate_field: law::rate_field::RateField<2>,
    // What stepping changes.
    /// The evolving state.
    pub state: State,
    scratch: Scratch,
}

impl Model {
    /// Time step, s.
    pub fn dt_s(&self) -> f64 {
        self.motion.dt_s
    }

    /// Simulated time, s.
    pub fn time_s(&self) -> f64 {
        self.state.steps as f64 * self.motion.dt_s
    }

    /// Completed steps.
    pub fn steps(&self) -> u64 {
        self.state.steps
    }

    /// The body named `name`.
    pub fn body(&self, name: &str) -> Option<&Body> {
        self.bodies.iter().find(|b| b.name == name)
    }

    /// Advance one step. On blow-up the error names the step and the element; the state is
    /// then unusable (the caller must not write it out).
    pub fn step(&mut self) -> Result<()> {
        let parallel = self.parallel();
        self.process_contacts(parallel);
        let drifted = self.move_elements(parallel)?;
        self.detect_contacts(drifted);
        self.state.steps += 1;
        Ok(())
    }

    /// Advance `n` steps. On the pool, from a thread outside it, the steps run on one of its
    /// workers: one entry into the pool for all of them, not two per step, and the same worker
    /// starts every parallel stage, so each stage's pieces tend to stay on the cores that had
    /// them the step before; the other workers look for work meanwhile instead of sleeping
    /// between the stages (`awake`). (Inside the pool — a sweep's run, or one that borrows a
    /// lender's cores — the other workers have other work.)
    pub fn run_steps(&mut self, n: u64) -> Result<()> {
        if n > 1 && self.parallel() && rayon::current_thread_index().is_none() {
            return exec::awake::while_running(|| self.steps_here(n));
        }
        self.steps_here(n)
    }

    fn steps_here(&mut self, n: u64) -> Result<()> {
        for _ in 0..n {
            self.step()?;
        }
        Ok(())
    }

    fn parallel(&self) -> bool {
        self.threading == Threading::Pool
            && self.state.contacts.len() >= self.parallel_min_contacts
            && rayon::current_num_threads() > 1
    }

    fn process_contacts(&mut self, parallel: bool) {
        let s = &mut self.scratch;
        let n_chunks = self.state.contacts.len().div_ceil(forces::CHUNK);
        s.diss_partial.resize(n_chunks, Dissipation::default());
        let n = self.el.len();
        if s.contact_sums.len() != n {
            s.contact_sums = vec![[0.0; 3]; n];
        }
        let st = &mut self.state;
        self.rate_field.update(&st.pos, &st.vel, &self.el.mass);
        // On the pool: the plan made again if the pool or the cap changed (one thread needs
        // none).
        let rule = (rayon::current_num_threads(), self.scatter_piece_contacts);
        if parallel {
            s.plan.ensure(rule.0, rule.1, &st.contacts.list, n);
        }
        let contacts::Contacts { list, extra, force, .. } = &mut st.contacts;
        let sums = &mut s.contact_sums[..];
        let out = if parallel {
            forces::Out::Pieces(forces::Pieces { sums, ranges: &s.plan.ranges, cuts: &s.plan.cuts, spans: &s.plan.spans, records: &mut s.records })
        } else {
            forces::Out::Serial(sums)
        };
        let stage = forces::Stage {
            pos: &st.pos,
            vel: &st.vel,
            list,
            extra,
            force,
            classes: &self.classes,
            dt_s: self.motion.dt_s,
            partial: &mut s.diss_partial,
            out,
            record: self.record_contact_forces,
            four_lanes: self.four_lanes,
            lane_width: self.lane_width,
            rate_vel: &self.rate_field.vel_mps,
        };
        self.parts.dispatch(stage);
        for d in &s.diss_partial {
            st.ledger.contacts.add(d);
        }
    }

    /// Returns whether some element drifted past its neighbour margin.
    fn move_elements(&mut self, parallel: bool) -> Result<bool> {
        self.update_drive();
        let parts = self.motion_parts();
        let s = &mut self.scratch;
        let n_chunks = self.el.len().div_ceil(integrate::CHUNK);
        s.motion_partial.resize(n_chunks, MotionReport::default());
        let drive = Drive { load_force_n: &s.load_now, motion_velocity: &s.motion_now, rigid_frame: &s.frame_now };
        let st = &mut self.state;
        // On the pool, each thread moves the elements its span of the contact stage added into
        // (to the nearest chunk), and the next contact stage finds them in its cache. Stealing
        // still evens out the rest (`spans`).
        let spans = parallel.then(|| {
            // Span s's elements begin where its first piece's range does.
            let plan = &s.plan;
            let chunk_of = |e: u32| ((e as usize + integrate::CHUNK / 2) / integrate::CHUNK).min(n_chunks);
            let later_spans = plan.spans.iter().take(plan.spans.len().saturating_sub(1)).skip(1);
            s.motion_spans.clear();
            s.motion_spans.push(0);
            s.motion_spans.extend(later_spans.map(|&p| chunk_of(plan.ranges[p].start)));
            s.motion_spans.push(n_chunks);
            &s.motion_spans[..]
        });
        let (el, p) = (&self.el, self.motion);
        let motion = integrate::Motion {
            el,
            pos: &mut st.pos,
            vel: &mut st.vel,
            force: &mut st.force,
            sums: &mut s.contact_sums[..],
            // Only the step's contact stage on the pool made records.
            pending: if parallel { exec::Pending::of(&s.records) } else { exec::Pending::NONE },
            rebuild_pos: &st.rebuild_pos,
            margin_m: &st.margin_m,
            drive,
            p,
            partial: &mut s.motion_partial,
            spans,
            lane_width: self.lane_width,
        };
        integrate::advance(parts, motion);
        let mut total = MotionReport::default();
        for r in &s.motion_partial {
            total.merge(r);
        }
        if total.first_bad != usize::MAX {
            let e = total.first_bad;
            let v = st.vel[e];
            return Err(Error::BlowUp {
                step: st.steps,
                time_s: self.time_s(),
                element: e,
                detail: format!(
                    "velocity ({:.3e}, {:.3e}) m/s, spin {:.3e} rad/s exceeds the speed limit {:.3e} m/s or is not finite \
                     (time step {:.4e} s; stability bound {:.4e} s)",
                    v[0], v[1], v[2], self.motion.speed_limit_mps, self.motion.dt_s, self.step_info.dt_bound_s
                ),
            });
        }
        st.ledger.mass_damping_j += total.mass_damping_j;
        st.ledger.external_j += total.external_j;
        Ok(total.drifted)
    }

    /// What the motion stage does for this model (fixed when built).
    fn motion_parts(&self) -> integrate::MotionParts {
        let p = &self.motion;
        let damped = p.alpha_per_s != 0.0;
        integrate::MotionParts {
            frame: damped && self.damp_relative_to_rigid,
            damped,
            external: p.gravity_mps2 != [0.0, 0.0] || !self.loads.is_empty(),
        }
    }

    /// Loads at t, prescribed velocities at t + Δt/2 (the midpoint rule moves a kinematic
    /// element exactly along a prescribed velocity that is linear over the step).
    fn update_drive(&mut self) {
        let (t, half) = (self.time_s(), self.time_s() + 0.5 * self.motion.dt_s);
        let frame = self.motion_parts().frame;
        let s = &mut self.scratch;
        let (el, st) = (&self.el, &self.state);
        s.load_now.clear();
        s.load_now.extend(self.loads.iter().map(|g| {
            let n = g.members.len().max(1) as f64;
            match g.servo {
                None => {
                    let f = g.profile.at(t) / n;
                    [g.force_n[0] * f, g.force_n[1] * f]
                }
                Some(servo) => {
                    let [dx, dy] = servo.direction;
                    let mean: f64 = g
                        .members
                        .iter()
                        .map(|&e| {
                            let u = st.displacement_m(el, e as usize);
                            u[0] * dx + u[1] * dy
                        })
                        .sum::<f64>()
                        / n;
                    let f = servo.stiffness_n_per_m * (servo.target_m(t) - mean) / n;
                    [f * dx, f * dy]
                }
            }
        }));
        s.motion_now.clear();
        s.motion_now.extend(self.motions.iter().map(|g| {
            let f = g.profile.at(half);
            [g.velocity[0] * f, g.velocity[1] * f, g.velocity[2] * f]
        }));
        if frame {
            integrate::rigid_frames(el, &st.pos, &st.vel, self.bodies.len(), &mut s.frame_now, &mut s.frame_scratch);
        }
    }

    /// Put the free elements' velocities half a step back, v(−Δt/2) = v(0) − (Δt/2) a(0), so
    /// that the given initial velocities are the ones at t = 0 and central differences start
    /// at second order (a free fall is then exact). Contact history is not touched.
    pub(crate) fn prime(&mut self) {
        self.update_drive();
        let mut probe = self.state.contacts.clone();
        let n_chunks = probe.len().div_ceil(forces::CHUNK);
        let mut partial = vec![Dissipation::default(); n_chunks];
        let contacts::Contacts { list, extra, force, .. } = &mut probe;
        let stage = forces::Stage {
            pos: &self.state.pos,
            vel: &self.state.vel,
            list,
            extra,
            force,
            classes: &self.classes,
            dt_s: 0.0,
            partial: &mut partial,
            out: forces::Out::Stored,
            record: true,
            four_lanes: self.four_lanes,
            lane_width: self.lane_width,
            rate_vel: &self.rate_field.vel_mps,
        };
        Parts { damping: false, ..self.parts }.dispatch(stage);
        let s = &self.scratch;
        let drive = Drive { load_force_n: &s.load_now, motion_velocity: &s.motion_now, rigid_frame: &s.frame_now };
        let f = integrate::forces_now(&self.el, &probe, drive, self.motion.gravity_mps2);
        let h = 0.5 * self.motion.dt_s;
        for (e, fe) in f.iter().enumerate() {
            let inv = [self.el.inv_mass[e], self.el.inv_mass[e], self.el.inv_inertia[e]];
            for d in 0..3 {
                if self.el.prescribed[e] & (1 << d) == 0 {
                    self.state.vel[e][d] -= h * fe[d] * inv[d];
                }
            }
        }
    }

    /// New pairs can only come within reach once some element has moved past its margin: until
    /// then the candidate list is complete (each contact checks touching itself every step).
    /// A few such elements get a local update, many a full rebuild. The update takes every
    /// element past half its margin along, so the ones about to trigger the next update do not.
    fn detect_contacts(&mut self, drifted: bool) {
        if !drifted {
            return;
        }
        let (st, s) = (&self.state, &mut self.scratch);
        s.movers.clear();
        s.movers.extend((0..self.el.len() as u32).filter(|&e| {
            let (p, g, m) = (st.pos[e as usize], st.rebuild_pos[e as usize], st.margin_m[e as usize]);
            (p[0] - g[0]).powi(2) + (p[1] - g[1]).powi(2) > 0.25 * m * m
        }));
        if self.neighbours.local(s.movers.len(), self.el.len()) {
            self.update_neighbours();
        } else {
            self.rebuild_neighbours();
        }
    }

    /// The local update: new margins and reference positions for the movers, their pairs looked
    /// for again, everything else kept.
    fn update_neighbours(&mut self) {
        let pool = self.parallel();
        let (st, s) = (&mut self.state, &mut self.scratch);
        s.is_mover.clear();
        s.is_mover.resize(self.el.len(), false);
        for &a in &s.movers {
            let a = a as usize;
            s.is_mover[a] = true;
            st.rebuild_pos[a] = [st.pos[a][0], st.pos[a][1]];
            st.margin_m[a] = self.neighbours.margin_m(&self.el, a, st.vel[a], st.force[a], self.motion.dt_s);
        }
        let (r, margin, refs) = (&self.el.radius, &st.margin_m, &st.rebuild_pos);
        let widest = r.iter().zip(margin).map(|(r, m)| r + m).fold(0.0, f64::max);
        s.broad.requery(&s.movers, &s.is_mover, |e| refs[e], r, |e| margin[e], widest, pool, &mut s.pairs);
        let is_mover = &s.is_mover;
        let covered = |i: u32, j: u32| is_mover[i as usize] || is_mover[j as usize];
        Self::merge(&self.el, &self.classes, self.kinds, &st.pos, &s.pairs, covered, self.record_contact_forces, pool, &mut st.contacts, &mut s.plan, &mut st.ledger);
        st.local_updates += 1;
    }

    /// Rebuild the candidate pairs from the current positions (margins, broad phase, merge).
    pub fn rebuild_neighbours(&mut self) {
        let pool = self.parallel();
        let (st, s) = (&mut self.state, &mut self.scratch);
        self.neighbours.margins(&self.el, &st.vel, &st.force, self.motion.dt_s, &mut st.margin_m);
        let (pos, margin) = (&st.pos, &st.margin_m);
        let usual = self.neighbours.usual_reach_m(self.el.radius.iter().copied().fold(0.0, f64::max));
        s.broad.pairs(|e| [pos[e][0], pos[e][1]], &self.el.radius, |e| margin[e], Some(usual), pool, &mut s.pairs);
        Self::merge(&self.el, &self.classes, self.kinds, &st.pos, &s.pairs, |_, _| true, self.record_contact_forces, pool, &mut st.contacts, &mut s.plan, &mut st.ledger);
        st.rebuild_pos.clear();
        st.rebuild_pos.extend(st.pos.iter().map(|p| [p[0], p[1]]));
        st.rebuilds += 1;
    }

    /// Bodies must not start inside each other: a pair of elements of two bodies closer than
    /// r_i + r_j at the start is refused, naming both bodies and elements.
    fn refuse_overlapping_bodies(&self) -> Result<()> {
        let (el, st) = (&self.el, &self.state);
        for c in st.contacts.list.iter().filter(|c| c.bond == Bond::Frictional) {
            let (i, j) = (c.i as usize, c.j as usize);
            let (bi, bj) = (el.body[i] as usize, el.body[j] as usize);
            if bi == bj {
                continue;
            }
            let (p, q) = (st.pos[i], st.pos[j]);
            let d = (q[0] - p[0]).hypot(q[1] - p[1]);
            let sum = el.radius[i] + el.radius[j];
            if d < sum * (1.0 - 1e-9) {
                let name = |b: usize| self.bodies.get(b).map_or("?", |x| x.name.as_str()).to_string();
                return Err(Error::input(
                    "body",
                    format!(
                        "bodies {:?} and {:?} overlap at the start: element {i} at ({:.6}, {:.6}) m and element {j} at ({:.6}, {:.6}) m \
                         are {d:.6e} m apart, less than r_i + r_j = {sum:.6e} m; move one of them (a projectile's standoff must be ≥ 0)",
                        name(bi),
                        name(bj),
                        p[0],
                        p[1],
                        q[0],
                        q[1]
                    ),
                ));
            }
        }
        Ok(())
    }

    /// Merge the candidate `pairs` (complete for the `covered` pairs) into the contacts (with
    /// `pool`, on rayon's pool); with `record` (`Model::record_contact_forces`) their stored
    /// forces, no longer those of the list's entries, are zeroed.
    #[allow(clippy::too_many_arguments)]
    fn merge(
        el: &Elements,
        classes: &[ContactClass],
        kinds: usize,
        pos: &[[f64; 3]],
        pairs: &[(u32, u32)],
        covered: impl Fn(u32, u32) -> bool + Sync,
        record: bool,
        pool: bool,
        contacts: &mut contacts::Contacts,
        plan: &mut exec::pieces::Plan,
        ledger: &mut ledger::Ledger<Dissipation>,
    ) {
        let touching = |c: &contact::Contact| {
            let (pi, pj) = (pos[c.i as usize], pos[c.j as usize]);
            (pj[0] - pi[0]).powi(2) + (pj[1] - pi[1]).powi(2) < c.rest_m * c.rest_m
        };
        let class_of = |i: u32, j: u32| class_index(el.kind[i as usize] as usize, el.kind[j as usize] as usize, kinds);
        let fresh = |i: u32, j: u32| {
            let class = class_of(i, j);
            contact::Contact::frictional(i, j, class, classes[class as usize].radius_sum_m)
        };
        let fresh_extra = |i: u32, j: u32| law::Extra::new(classes[class_of(i, j) as usize].radius_sum_m);
        let admit = |i: u32, j: u32| el.can_interact(i as usize, j as usize);
        let release = |c: &contact::Contact| 0.5 * classes[c.class as usize].contact.springs.kt_n_per_m * c.ut_m * c.ut_m;
        let mut released = Dissipation::default();
        contacts.merge_candidates(pairs, covered, touching, fresh, fresh_extra, admit, release, &mut released, pool);
        plan.follow(&contacts.list, el.len(), pool);
        if record {
            contacts.force.fill(contact::ContactForce::default());
        }
        ledger.contacts.add(&released);
    }

    /// Kinetic energy, J (velocities at the half step).
    pub fn kinetic_energy_j(&self) -> f64 {
        self.state.kinetic_energy_j(&self.el)
    }

    /// Elastic energy in the contacts, J.
    pub fn strain_energy_j(&self) -> f64 {
        let st = &self.state;
        energy::strain_energy_j(&self.el, &st.pos, &st.vel, &st.contacts, &self.classes, self.parts, self.motion.dt_s)
    }

    /// Energy balance residual, J (see `ledger::Ledger::residual_j`).
    pub fn energy_residual_j(&self) -> f64 {
        self.state.ledger.residual_j(self.kinetic_energy_j(), self.strain_energy_j())
    }

    /// Number of intact bonds.
    pub fn intact_bonds(&self) -> usize {
        self.state.contacts.list.iter().filter(|c| c.bond == Bond::Intact).count()
    }

    /// Total force a load group applied in the last step, [N, N].
    pub fn applied_load_n(&self, group: usize) -> [f64; 2] {
        let n = self.loads[group].members.len() as f64;
        [self.scratch.load_now[group][0] * n, self.scratch.load_now[group][1] * n]
    }

    /// Sum of the forces on a set of elements in the last step, [N, N].
    pub fn force_on(&self, elements: &[usize]) -> [f64; 2] {
        let f = &self.state.force;
        elements.iter().fold([0.0, 0.0], |a, &e| [a[0] + f[e][0], a[1] + f[e][1]])
    }

    /// Displacement of element `e` from its initial position, [m, m].
    pub fn displacement_m(&self, e: usize) -> [f64; 2] {
        self.state.displacement_m(&self.el, e)
    }

    /// Mean displacement of a set of elements from their initial positions, [m, m].
    pub fn mean_displacement_m(&self, elements: &[usize]) -> [f64; 2] {
        let s = elements.iter().fold([0.0, 0.0], |a, &e| {
            let d = self.displacement_m(e);
            [a[0] + d[0], a[1] + d[1]]
        });
        let n = elements.len().max(1) as f64;
        [s[0] / n, s[1] / n]
    }
}
