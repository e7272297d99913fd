//! Stage 1 of a step, contact processing: every contact's force from the current positions and
//! the previous half-step velocities. Each contact writes only its own entry, so the stage runs
//! in parallel chunks with results independent of the thread count; dissipation is summed per
//! fixed-size chunk and the chunk sums are added in chunk order (deterministic).
//!
//! On one thread the stage also adds each force to its two elements as it goes (a scatter),
//! which spares the motion stage its gather. The scatter visits an element's contacts in
//! increasing contact order, the same order as the gather's adjacency, from the same zero: the
//! sums are bitwise the same either way.
//!
//! The loop is compiled once per set of optional law parts (`law::PartSet`).

use rayon::prelude::*;

use super::contacts::{Bond, Contact, ContactForce};
use super::law::{self, ContactClass, Dissipation, Extra, Kinematics, PartSet};

/// Contacts per chunk: fixed, so partial sums do not depend on the number of threads.
pub const CHUNK: usize = 2048;

/// What stage 1 reads and writes.
pub struct Stage<'a> {
    /// Positions [x m, y m, θ rad].
    pub pos: &'a [[f64; 3]],
    /// Half-step velocities.
    pub vel: &'a [[f64; 3]],
    /// Contacts.
    pub list: &'a mut [Contact],
    /// Their extra slots (empty unless the parts need them).
    pub extra: &'a mut [Extra],
    /// Their forces (output).
    pub force: &'a mut [ContactForce],
    /// Contact classes.
    pub classes: &'a [ContactClass],
    /// Δt, s.
    pub dt_s: f64,
    /// One entry per chunk (output).
    pub partial: &'a mut [Dissipation],
    /// With one thread: per-element force sums [Fx N, Fy N, T N·m], zero on entry.
    pub sums: Option<&'a mut [[f64; 3]]>,
    /// Store each contact's force in `force` (always done without `sums`).
    pub record: bool,
}

impl law::PartsVisitor for Stage<'_> {
    type Output = ();
    fn visit<P: PartSet>(self) {
        let Stage { pos, vel, list, extra, force, classes, dt_s, partial, sums, record } = self;
        process::<P>(pos, vel, list, extra, force, classes, dt_s, partial, sums, record)
    }
}

/// One chunk: each contact's force into `fs`, its dissipation into `d`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn chunk<P: PartSet>(at: &StepInput<'_>, cs: &mut [Contact], xs: &mut [Extra], fs: &mut [ContactForce], classes: &[ContactClass], d: &mut Dissipation) {
    *d = Dissipation::default();
    if P::EXTRA {
        for ((c, x), f) in cs.iter_mut().zip(xs.iter_mut()).zip(fs.iter_mut()) {
            *f = one::<P>(at, c, x, classes, d);
        }
    } else {
        let mut scratch = Extra::new(0.0);
        for (c, f) in cs.iter_mut().zip(fs.iter_mut()) {
            *f = one::<P>(at, c, &mut scratch, classes, d);
        }
    }
}

/// What every contact of a step reads: the state it starts from and the step.
struct StepInput<'a> {
    /// Positions [x m, y m, θ rad].
    pos: &'a [[f64; 3]],
    /// Half-step velocities.
    vel: &'a [[f64; 3]],
    /// Δt, s.
    dt_s: f64,
}

/// Compute all contact forces: into `force` without `sums`; with them, summed into the
/// elements, and into `force` too when `record`.
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub fn process<P: PartSet>(
    pos: &[[f64; 3]],
    vel: &[[f64; 3]],
    list: &mut [Contact],
    extra: &mut [Extra],
    force: &mut [ContactForce],
    classes: &[ContactClass],
    dt_s: f64,
    partial: &mut [Dissipation],
    sums: Option<&mut [[f64; 3]]>,
    record: bool,
) {
    // One reference for the frictional path's call, built once: fewer arguments to set up.
    let at = &StepInput { pos, vel, dt_s };
    match sums {
        None => {
            let run = |((cs, fs), d): ((&mut [Contact], &mut [ContactForce]), &mut Dissipation), xs: &mut [Extra]| {
                chunk::<P>(at, cs, xs, fs, classes, d)
            };
            let chunks = list.par_chunks_mut(CHUNK).zip(force.par_chunks_mut(CHUNK)).zip(partial.par_iter_mut());
            if P::EXTRA {
                chunks.zip(extra.par_chunks_mut(CHUNK)).for_each(|(a, xs)| run(a, xs));
            } else {
                chunks.for_each(|a| run(a, &mut []));
            }
        }
        // The serial loop compiled with and without the per-contact store: no branch per
        // contact on an observable the run does not ask for.
        Some(sums) if record => scatter::<P, true>(at, list, extra, force, classes, partial, sums),
        Some(sums) => scatter::<P, false>(at, list, extra, force, classes, partial, sums),
    }
}

/// One thread: each contact's force added to its two elements as it goes (and stored in
/// `force` when `RECORD`).
#[inline(always)]
fn scatter<P: PartSet, const RECORD: bool>(
    at: &StepInput<'_>,
    list: &mut [Contact],
    extra: &mut [Extra],
    force: &mut [ContactForce],
    classes: &[ContactClass],
    partial: &mut [Dissipation],
    sums: &mut [[f64; 3]],
) {
    // Contacts are sorted by i: keep i's running sum in registers while i repeats.
    let mut run_i = u32::MAX;
    let mut acc = [0.0f64; 3];
    let mut scratch = Extra::new(0.0);
    let n = list.len();
    let mut from = 0;
    for d in partial.iter_mut() {
        let to = (from + CHUNK).min(n);
        *d = Dissipation::default();
        for k in from..to {
            let c = &mut list[k];
            let x = if P::EXTRA { &mut extra[k] } else { &mut scratch };
            let cf = one::<P>(at, c, x, classes, d);
            if RECORD {
                force[k] = cf;
            }
            if c.i != run_i {
                if run_i != u32::MAX {
                    sums[run_i as usize] = acc;
                }
                run_i = c.i;
                acc = sums[run_i as usize];
            }
            acc[0] += cf.fx;
            acc[1] += cf.fy;
            acc[2] += cf.ti;
            let s = &mut sums[c.j as usize];
            s[0] -= cf.fx;
            s[1] -= cf.fy;
            s[2] += cf.tj;
        }
        from = to;
    }
    if run_i != u32::MAX {
        sums[run_i as usize] = acc;
    }
}

#[inline(always)]
fn one<P: PartSet>(at: &StepInput<'_>, c: &mut Contact, x: &mut Extra, classes: &[ContactClass], d: &mut Dissipation) -> ContactForce {
    let k = &classes[c.class as usize];
    let s = separation(at.pos, c);
    if c.bond == Bond::Intact {
        law::bonded::<P>(c, x, k, &along(at.vel, c, k, s), at.dt_s, d)
    } else if apart_with_nothing_to_forget(c, k, s) {
        ContactForce::default()
    } else {
        frictional::<P>(at, c, k, s, d)
    }
}

/// A frictional pair that is apart with no shear spring and its rest length back at r_i + r_j:
/// `law::friction::apart` would change nothing. Most contacts of a fractured body are such;
/// checked here, in line, they skip the call.
#[inline(always)]
fn apart_with_nothing_to_forget(c: &Contact, k: &ContactClass, s: Separation) -> bool {
    c.ut_m == 0.0 && c.rest_m == k.radius_sum_m && apart(c, s)
}

/// A frictional pair that does not touch: its centres at least its rest length apart.
#[inline(always)]
fn apart(c: &Contact, s: Separation) -> bool {
    s.d2_m2 >= c.rest_m * c.rest_m
}

/// A frictional contact, out of line: inlined beside the bond law it made the all-bonded loop
/// 2.2× slower (the benchmark block: 25 → 11.5 ns per contact for the contact stage).
#[inline(never)]
fn frictional<P: PartSet>(at: &StepInput<'_>, c: &mut Contact, k: &ContactClass, s: Separation, d: &mut Dissipation) -> ContactForce {
    if apart(c, s) {
        law::friction::apart(c, k, s.d2_m2, d);
        ContactForce::default()
    } else {
        law::friction::touching::<P>(c, k, &along(at.vel, c, k, s), at.dt_s, d)
    }
}

/// Geometry and relative velocity of a contact at the current state, or, for a frictional pair
/// that does not touch, Err(its squared distance, m²).
#[inline(always)]
pub fn kinematics(pos: &[[f64; 3]], vel: &[[f64; 3]], c: &Contact, k: &ContactClass) -> Result<Kinematics, f64> {
    let s = separation(pos, c);
    if c.bond == Bond::Frictional && apart(c, s) {
        return Err(s.d2_m2);
    }
    Ok(along(vel, c, k, s))
}

/// From i's centre to j's: (dx m, dy m) and its square length d2 (m²).
#[derive(Clone, Copy)]
struct Separation {
    dx_m: f64,
    dy_m: f64,
    d2_m2: f64,
}

#[inline(always)]
fn separation(pos: &[[f64; 3]], c: &Contact) -> Separation {
    let (pi, pj) = (pos[c.i as usize], pos[c.j as usize]);
    let (dx_m, dy_m) = (pj[0] - pi[0], pj[1] - pi[1]);
    Separation { dx_m, dy_m, d2_m2: dx_m * dx_m + dy_m * dy_m }
}

/// Geometry and relative velocity of a pair `s` apart.
#[inline(always)]
fn along(vel: &[[f64; 3]], c: &Contact, k: &ContactClass, s: Separation) -> Kinematics {
    let (i, j) = (c.i as usize, c.j as usize);
    let dist = s.d2_m2.sqrt();
    let inv = 1.0 / dist;
    let (nx, ny) = (s.dx_m * inv, s.dy_m * inv);
    let (vi, vj) = (vel[i], vel[j]);
    let (dvx, dvy) = (vj[0] - vi[0], vj[1] - vi[1]);
    let (li, lj) = (dist * k.lever_i, dist * k.lever_j);
    Kinematics { d_m: dist, nx, ny, vn_mps: dvx * nx + dvy * ny, vt_mps: -dvx * ny + dvy * nx - li * vi[2] - lj * vj[2], li_m: li, lj_m: lj }
}
