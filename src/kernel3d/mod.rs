//! The 3D kernel: bonded spheres with six degrees of freedom and the moment transfer law of
//! seed 004, stepping as the 2D kernel does — contact processing, element motion, contact
//! detection — under the same contract (`crate::simulation`, [`contract`]).
//!
//! On the pool, contacts are evaluated in parallel by fixed chunks and their actions then added
//! to the spheres in contact order, and the spheres move by fixed chunks whose ledger shares are
//! summed in chunk order: a step's bits are the same on any thread count (and on one thread,
//! which takes the same chunks in turn and adds each action as it is made, in the same order).

pub mod build;
pub mod contact;
pub mod contract;
pub mod detect;
pub mod energy;
pub mod integrate;
pub mod law;
pub mod mirror;
pub mod solid;
pub mod stability;
pub mod state;
pub mod stiffness;
pub mod vec3;

pub use build::Builder;

use contact::Contact;
use mirror::Mirrors;
use law::{Class, Dissipation, Pair};
use state::{Spheres, State};
use vec3::{V3, add, dot, sub};

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::kernel::Body;
use crate::kernel::law::rate_field::RateField;
use crate::simulation::Threading;

/// A model of spheres ready to step.
#[derive(Debug, Clone)]
pub struct Model {
    // Configuration, fixed when built.
    /// Sphere constants.
    pub spheres: Spheres,
    /// Contact classes, `kind_i × kinds + kind_j`.
    pub classes: Vec<Class>,
    /// Number of kinds.
    pub kinds: usize,
    /// Bodies, in build order.
    pub bodies: Vec<Body>,
    /// Δt and α.
    pub motion: integrate::Params,
    /// The stability limit the step was taken from, s.
    pub dt_bound_s: f64,
    /// The frequency bound, rad/s.
    pub omega_bound_rad_per_s: f64,
    /// Gap below which pairs are candidates, m.
    pub skin_m: f64,
    /// Where steps run (the result never depends on it).
    pub threading: Threading,
    /// Contacts from which the steps run on the pool.
    pub parallel_min_contacts: usize,
    /// The one radius every sphere has, m, if they share one (each class's springs are then
    /// taken once a step, not once per contact).
    pub uniform_radius_m: Option<f64>,
    /// The symmetry planes: the model is one of `mirrors.copies()` mirror-image parts of the
    /// whole (none: the whole).
    pub mirrors: Mirrors,
    // What stepping changes.
    /// The evolving state.
    pub state: State,
    /// Each contact's action of this step (scratch).
    pub(crate) actions: Vec<law::Action>,
    /// Each contact chunk's dissipation and each sphere chunk's ledger share of this step
    /// (scratch: the step allocates nothing).
    pub(crate) shares: (Vec<Dissipation>, Vec<integrate::Report>),
    /// Each class's springs at the one sphere radius of this step, when all share one (scratch).
    pub(crate) locals: Vec<law::Local>,
    /// The rate part's smoothed velocity field (`kernel::law::rate_field`): its grid is
    /// configuration, its values remade every step from the state (empty: each bond reads its
    /// own pair).
    pub rate_field: RateField<3>,
}

/// What a contact's law reads of the model in a step.
struct View<'a> {
    sp: &'a Spheres,
    pos: &'a [V3],
    vel: &'a [V3],
    spin: &'a [V3],
    classes: &'a [Class],
    locals: &'a [law::Local],
    rate_vel: &'a [V3],
    mirrors: &'a Mirrors,
    dt: f64,
}

impl View<'_> {
    /// Contact `c`'s action, its history advanced and its dissipation added to `diss`. Out of
    /// line: inlined into the contact loop it ran 1.1× slower (block3d, register pressure).
    #[inline(never)]
    fn act(&self, c: &mut Contact, diss: &mut Dissipation) -> law::Action {
        let (i, j) = (c.i as usize, c.j as usize);
        let (r, pos) = (&self.sp.radius_m, self.pos);
        let m = &self.sp.mass_kg;
        let rate = (!self.rate_vel.is_empty()).then(|| [self.rate_vel[i], self.rate_vel[j]]);
        let (pair, rate) = match c.image {
            0 => (Pair { r: [r[i], r[j]], dx_m: sub(pos[j], pos[i]), v: [self.vel[i], self.vel[j]], w: [self.spin[i], self.spin[j]], m: [m[i], m[j]] }, rate),
            k => {
                // j as its image across the planes of k.
                let mi = self.mirrors;
                let pair = Pair {
                    r: [r[i], r[j]],
                    dx_m: sub(mi.point(pos[j], k), pos[i]),
                    v: [self.vel[i], mi.vector(self.vel[j], k)],
                    w: [self.spin[i], mi.axial(self.spin[j], k)],
                    m: [m[i], m[j]],
                };
                (pair, rate.map(|[a, b]| [a, mi.vector(b, k)]))
            }
        };
        let class = &self.classes[c.class as usize];
        let here;
        let k = match self.locals.get(c.class as usize) {
            Some(k) => k,
            None => {
                here = class.at(law::mean_radius_m(pair.r));
                &here
            }
        };
        if c.image != 0 && i == j {
            // A sphere against its own image: half the pair's energy is the mirrored part's.
            let mut own = Dissipation::default();
            let a = law::act_at(c, class, k, &pair, rate, self.dt, &mut own);
            diss.add_scaled(&own, 0.5);
            return a;
        }
        law::act_at(c, class, k, &pair, rate, self.dt, diss)
    }
}

/// Add contact `c`'s action `a` to the force and moment sums of its spheres (an image
/// contact's reaction reflected back onto j; none onto a sphere from its own image, whose
/// reaction acts on the mirrored part).
#[inline(always)]
fn scatter(force: &mut [V3], moment: &mut [V3], c: &Contact, a: &law::Action, mirrors: &Mirrors) {
    let (i, j) = (c.i as usize, c.j as usize);
    force[i] = sub(force[i], a.force_j_n);
    moment[i] = add(moment[i], a.moment_i_nm);
    match c.image {
        0 => {
            force[j] = add(force[j], a.force_j_n);
            moment[j] = add(moment[j], a.moment_j_nm);
        }
        _ if i == j => {}
        k => {
            force[j] = add(force[j], mirrors.vector(a.force_j_n, k));
            moment[j] = add(moment[j], mirrors.axial(a.moment_j_nm, k));
        }
    }
}

/// Contacts, and spheres, per chunk: the unit of work on the pool and of the partial sums.
pub const CHUNK: usize = 1024;

/// Contacts from which a model steps on the pool by default (fewer: fork and join cost more).
pub const PARALLEL_MIN_CONTACTS: usize = 8192;

impl Model {
    /// Simulated time, s.
    pub fn time_s(&self) -> f64 {
        self.state.steps as f64 * self.motion.dt_s
    }

    /// The class of a contact between spheres i and j.
    pub fn class_of(&self, i: u32, j: u32) -> u16 {
        (self.spheres.kind[i as usize] as usize * self.kinds + self.spheres.kind[j as usize] as usize) as u16
    }

    /// Advance `n` steps.
    pub fn run_steps(&mut self, n: u64) -> Result<()> {
        for _ in 0..n {
            self.step()?;
        }
        Ok(())
    }

    /// Advance one step: contact processing, element motion, contact detection.
    pub fn step(&mut self) -> Result<()> {
        self.process_contacts();
        self.move_spheres()?;
        self.detect_contacts();
        self.state.steps += 1;
        Ok(())
    }

    fn parallel(&self) -> bool {
        self.threading == Threading::Pool && self.state.contacts.len() >= self.parallel_min_contacts && rayon::current_num_threads() > 1
    }

    fn process_contacts(&mut self) {
        let parallel = self.parallel();
        let (sp, st) = (&self.spheres, &mut self.state);
        let (classes, dt) = (&self.classes, self.motion.dt_s);
        let n = sp.len();
        // One sphere size: each class's springs are taken once a step, not once per contact.
        let locals = &mut self.locals;
        locals.clear();
        if let Some(r) = self.uniform_radius_m {
            locals.extend(classes.iter().map(|c| c.at(law::mean_radius_m([r, r]))));
        }
        let locals = &*locals;
        self.rate_field.update(&st.pos_m, &st.vel_mps, &sp.mass_kg);
        let mirrors = &self.mirrors;
        let view = View { sp, pos: &st.pos_m, vel: &st.vel_mps, spin: &st.spin_rad_per_s, classes, locals, rate_vel: &self.rate_field.vel_mps, mirrors, dt };
        let one = |c: &mut Contact, diss: &mut Dissipation| view.act(c, diss);
        let parts = &mut self.shares.0;
        parts.resize(st.contacts.len().div_ceil(CHUNK), Dissipation::default());
        st.force_n.clear();
        st.force_n.resize(n, [0.0; 3]);
        st.moment_nm.clear();
        st.moment_nm.resize(n, [0.0; 3]);
        if parallel {
            // Each chunk of contacts: its actions and its dissipation; then the actions added to
            // the spheres in contact order.
            self.actions.resize(st.contacts.len(), law::Action::default());
            let chunk = |((cs, acts), d): ((&mut [Contact], &mut [law::Action]), &mut Dissipation)| {
                let mut diss = Dissipation::default();
                cs.iter_mut().zip(acts).for_each(|(c, a)| *a = one(c, &mut diss));
                *d = diss;
            };
            st.contacts.par_chunks_mut(CHUNK).zip(self.actions.par_chunks_mut(CHUNK)).zip(parts.par_iter_mut()).for_each(chunk);
            for (c, a) in st.contacts.iter().zip(&self.actions) {
                scatter(&mut st.force_n, &mut st.moment_nm, c, a, mirrors);
            }
        } else {
            // One thread: each action added to its spheres as it is made, in contact order (the
            // pool's sums, bit for bit), with no trip through the actions' scratch.
            for (cs, d) in st.contacts.chunks_mut(CHUNK).zip(parts.iter_mut()) {
                let mut diss = Dissipation::default();
                for c in cs.iter_mut() {
                    let a = one(c, &mut diss);
                    scatter(&mut st.force_n, &mut st.moment_nm, c, &a, mirrors);
                }
                *d = diss;
            }
        }
        for d in parts.iter() {
            st.ledger.contacts.add(d);
        }
    }

    fn move_spheres(&mut self) -> Result<()> {
        let parallel = self.parallel();
        let (sp, p) = (&self.spheres, &self.motion);
        let st = &mut self.state;
        let reports = &mut self.shares.1;
        reports.resize(sp.len().div_ceil(CHUNK), integrate::Report::default());
        let one = |(k, ((((pos, vel), spin), (force, moment)), out)): (usize, ((((&mut [V3], &mut [V3]), &mut [V3]), (&[V3], &[V3])), &mut integrate::Report))| {
            *out = integrate::advance(sp, integrate::Rows { base: k * CHUNK, pos, vel, spin, force, moment }, p);
        };
        if parallel {
            st.pos_m
                .par_chunks_mut(CHUNK)
                .zip(st.vel_mps.par_chunks_mut(CHUNK))
                .zip(st.spin_rad_per_s.par_chunks_mut(CHUNK))
                .zip(st.force_n.par_chunks(CHUNK).zip(st.moment_nm.par_chunks(CHUNK)))
                .zip(reports.par_iter_mut())
                .enumerate()
                .for_each(one);
        } else {
            st.pos_m
                .chunks_mut(CHUNK)
                .zip(st.vel_mps.chunks_mut(CHUNK))
                .zip(st.spin_rad_per_s.chunks_mut(CHUNK))
                .zip(st.force_n.chunks(CHUNK).zip(st.moment_nm.chunks(CHUNK)))
                .zip(reports.iter_mut())
                .enumerate()
                .for_each(one);
        }
        let mut bad = (None, None);
        for r in reports.iter() {
            st.ledger.mass_damping_j += r.mass_damping_j;
            st.ledger.local_damping_j += r.local_damping_j;
            st.ledger.radiated_j += r.radiated_j;
            st.ledger.external_j += r.external_j;
            bad = (bad.0.or(r.bad_in), bad.1.or(r.bad_out));
        }
        if let Some(e) = bad.0.or(bad.1) {
            let (pos, v, w) = (st.pos_m[e], st.vel_mps[e], st.spin_rad_per_s[e]);
            return Err(Error::BlowUp {
                step: st.steps,
                time_s: st.steps as f64 * self.motion.dt_s,
                element: e,
                detail: format!(
                    "sphere at {pos:.3?} m, velocity {v:.3?} m/s, spin {w:.3?} rad/s is not finite (time step {:.4e} s; stability bound {:.4e} s)",
                    self.motion.dt_s, self.dt_bound_s
                ),
            });
        }
        Ok(())
    }

    fn detect_contacts(&mut self) {
        let half = 0.5 * self.skin_m;
        let st = &self.state;
        let moved = st.pos_m.iter().zip(&st.searched_at_m).any(|(p, q)| {
            let d = sub(*p, *q);
            dot(d, d) > half * half
        });
        if moved {
            self.search();
        }
    }

    /// Search for candidate pairs now and merge them into the contact list. Two held spheres
    /// make no candidate: their motion is given, no free sphere feels their force, and it would
    /// only stain the supports' reactions (walls of held spheres passing through each other).
    pub fn search(&mut self) {
        let held = &self.spheres.held;
        let mut pairs = self.mirrors.candidates(&self.state.pos_m, &self.spheres.radius_m, self.skin_m, self.parallel());
        pairs.retain(|&(i, j, _)| !(held[i as usize] && held[j as usize]));
        let old = std::mem::take(&mut self.state.contacts);
        let classes = |i: u32, j: u32| self.class_of(i, j);
        let reflect = |p: V3, image: u8| self.mirrors.point(p, image);
        let merged = detect::merge(old, &pairs, &self.state.pos_m, &self.spheres.radius_m, reflect, classes);
        self.state.contacts = merged;
        self.state.searched_at_m = self.state.pos_m.clone();
        self.state.searches += 1;
    }

    /// Kinetic energy (half-step velocities and spins), J.
    pub fn kinetic_energy_j(&self) -> f64 {
        let (sp, st) = (&self.spheres, &self.state);
        (0..sp.len())
            .map(|e| 0.5 * sp.mass_kg[e] * dot(st.vel_mps[e], st.vel_mps[e]) + 0.5 * sp.inertia_kg_m2[e] * dot(st.spin_rad_per_s[e], st.spin_rad_per_s[e]))
            .sum()
    }

    /// Elastic energy in the contacts, J.
    pub fn strain_energy_j(&self) -> f64 {
        self.strain_energy_at_j(&self.state.pos_m)
    }

    /// Intact bonds.
    pub fn intact_bonds(&self) -> usize {
        self.state.contacts.iter().filter(|c| c.bond == contact::Bond::Intact).count()
    }

    /// Displacement of sphere e from where it started, m.
    pub fn displacement_m(&self, e: usize) -> V3 {
        sub(self.state.pos_m[e], self.spheres.initial_m[e])
    }

    /// The contacts (read-only).
    pub fn contacts(&self) -> &[Contact] {
        &self.state.contacts
    }
}
