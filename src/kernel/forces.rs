//! Stage 1 of a step, contact processing: every contact's force from the current positions and
//! the previous half-step velocities. Each contact writes only its own entry, so the stage runs
//! in parallel chunks with results independent of the thread count; dissipation is summed per
//! fixed-size chunk and the chunk sums are added in chunk order (deterministic).
//!
//! On one thread the stage also adds each force to its two elements as it goes (a scatter),
//! which spares the motion stage its gather. The scatter visits an element's contacts in
//! increasing contact order, the same order as the gather's adjacency, from the same zero: the
//! sums are bitwise the same either way.

use rayon::prelude::*;

use super::contacts::{Bond, Contact, ContactForce};
use super::law::{self, ContactClass, Dissipation, Kinematics};
use super::state::Elements;

/// Contacts per chunk: fixed, so partial sums do not depend on the number of threads.
pub const CHUNK: usize = 2048;

/// Compute all contact forces. `partial` must hold one entry per chunk. With `sums` (one
/// thread), each force is also added to its elements' sums [Fx N, Fy N, T N·m], which must
/// come in zeroed.
#[allow(clippy::too_many_arguments)]
pub fn process<const DAMP: bool>(
    el: &Elements,
    list: &mut [Contact],
    force: &mut [ContactForce],
    classes: &[ContactClass],
    dt_s: f64,
    partial: &mut [Dissipation],
    sums: Option<&mut [[f64; 3]]>,
) {
    match sums {
        None => {
            let run = |((cs, fs), d): ((&mut [Contact], &mut [ContactForce]), &mut Dissipation)| {
                *d = Dissipation::default();
                for (c, f) in cs.iter_mut().zip(fs.iter_mut()) {
                    *f = one::<DAMP>(el, c, classes, dt_s, d);
                }
            };
            list.par_chunks_mut(CHUNK).zip(force.par_chunks_mut(CHUNK)).zip(partial.par_iter_mut()).for_each(run);
        }
        Some(sums) => {
            // Contacts are sorted by i: keep i's running sum in registers while i repeats.
            let mut run_i = u32::MAX;
            let mut acc = [0.0f64; 3];
            for ((cs, fs), d) in list.chunks_mut(CHUNK).zip(force.chunks_mut(CHUNK)).zip(partial.iter_mut()) {
                *d = Dissipation::default();
                for (c, f) in cs.iter_mut().zip(fs.iter_mut()) {
                    let cf = one::<DAMP>(el, c, classes, dt_s, d);
                    *f = cf;
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
            }
            if run_i != u32::MAX {
                sums[run_i as usize] = acc;
            }
        }
    }
}

#[inline(always)]
fn one<const DAMP: bool>(el: &Elements, c: &mut Contact, classes: &[ContactClass], dt_s: f64, d: &mut Dissipation) -> ContactForce {
    let k = &classes[c.class as usize];
    match kinematics(el, c, k) {
        Some(g) => law::interact::<DAMP>(c, k, &g, dt_s, d),
        None => {
            // Separation releases what the shear spring still held.
            if c.ut != 0.0 {
                d.friction_j += 0.5 * k.kt_n_per_m * c.ut * c.ut;
                c.ut = 0.0;
            }
            ContactForce::default()
        }
    }
}

/// Geometry and relative velocity of a contact at the current state, or None for a
/// frictional pair that does not touch.
#[inline(always)]
pub fn kinematics(el: &Elements, c: &Contact, k: &ContactClass) -> Option<Kinematics> {
    let (i, j) = (c.i as usize, c.j as usize);
    let (pi, pj) = (el.pos[i], el.pos[j]);
    let (dx, dy) = (pj[0] - pi[0], pj[1] - pi[1]);
    let d2 = dx * dx + dy * dy;
    if c.bond == Bond::Frictional && d2 >= c.d0 * c.d0 {
        return None;
    }
    let dist = d2.sqrt();
    let inv = 1.0 / dist;
    let (nx, ny) = (dx * inv, dy * inv);
    let (vi, vj) = (el.vel[i], el.vel[j]);
    let (dvx, dvy) = (vj[0] - vi[0], vj[1] - vi[1]);
    let (li, lj) = (dist * k.lever_i, dist * k.lever_j);
    Some(Kinematics {
        d_m: dist,
        nx,
        ny,
        vn_mps: dvx * nx + dvy * ny,
        vt_mps: -dvx * ny + dvy * nx - li * vi[2] - lj * vj[2],
        li_m: li,
        lj_m: lj,
    })
}
