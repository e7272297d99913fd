//! Stage 1 of a step, contact processing: every contact's force from the current positions and
//! the previous half-step velocities. Each contact writes only its own entry, so the stage runs
//! in parallel chunks with results independent of the thread count; dissipation is summed per
//! fixed-size chunk and the chunk sums are added in chunk order (deterministic).
//!
//! In a step the stage also adds each force to its two elements as it goes (a scatter), which
//! spares the motion stage a gather. On one thread the scatter visits an element's contacts in
//! increasing contact order from zero; on the pool the list is cut into pieces that keep that
//! order (`pieces`): the sums are bitwise the same for any thread count.
//!
//! The loop is compiled once per set of optional law parts (`law::PartSet`). Where the part
//! set allows it, the contacts go four at a time in lanes (`lanes`: AVX where the processor has
//! it), with the same bits: runs of four intact bonds through the bond law's elastic branch
//! ([`groups::bonds`]), any other four of one class through every kind's law at once
//! ([`groups::mixed`]); what neither takes (a bond leaving the elastic branch, classes mixed)
//! one at a time.

use std::ops::Range;

use rayon::prelude::*;

use std::marker::PhantomData;

use super::geometry::{self, Geometry, Separation, separation};
use super::lanes::{self, Lanes};
use super::exec::scatter::{Serial, Sums};
use super::exec::{pieces, spans};
use super::groups;
use super::contact::{Bond, Contact, ContactForce};
use super::law::rate_field::RateField;
use super::law::{self, ContactClass, Dissipation, Extra, Kinematics, PartSet};

pub use super::exec::scatter::CHUNK;

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
    /// Where each force goes besides `force`.
    pub out: Out<'a>,
    /// Store each contact's force in `force` (always done with [`Out::Stored`]).
    pub record: bool,
    /// Take the contacts four at a time where the parts allow ([`groups`]).
    pub four_lanes: bool,
    /// The lanes they go on.
    pub lane_width: lanes::Width,
    /// The rate part's smoothed velocities per element, m/s (`law::rate_field`; empty: none).
    pub rate_vel: &'a [[f64; 2]],
}

/// Where stage 1 puts the forces.
pub enum Out<'a> {
    /// In `force` only, chunks on the pool (a gather sums them).
    Stored,
    /// Also added to their elements' sums [Fx N, Fy N, T N·m] (zero on entry), on this thread.
    Serial(&'a mut [[f64; 3]]),
    /// The same sums, made on the pool by the pieces of a plan.
    Pieces(Pieces<'a>),
}

impl law::PartsVisitor for Stage<'_> {
    type Output = ();
    #[inline(never)]
    fn visit<P: PartSet>(self) {
        let Stage { pos, vel, list, extra, force, classes, dt_s, partial, out, record, four_lanes, lane_width, rate_vel } = self;
        let at = &StepInput { pos, vel, dt_s, classes, rate_vel, width: lane_width };
        let four = four_lanes && lanes_apply::<P>();
        match out {
            Out::Stored if four => parallel::<P, true>(at, list, extra, force, partial),
            Out::Stored => parallel::<P, false>(at, list, extra, force, partial),
            // The loops compiled with and without the per-contact store: no branch per contact
            // on an observable the run does not ask for.
            Out::Serial(sums) => {
                let sums = Serial::new(sums);
                match (record, four) {
                    (true, true) => lanes::run_as(at.width, ScatterFour::<P, true, _> { at, list, extra, force, partial, out: sums, parts: PhantomData }),
                    (false, true) => lanes::run_as(at.width, ScatterFour::<P, false, _> { at, list, extra, force, partial, out: sums, parts: PhantomData }),
                    (true, false) => scatter_alone::<P, true, _>(at, list, extra, force, partial, sums),
                    (false, false) => scatter_alone::<P, false, _>(at, list, extra, force, partial, sums),
                }
            }
            Out::Pieces(pieces) => match (record, four) {
                (true, true) => parallel_scatter::<P, true, true>(at, list, extra, force, partial, pieces),
                (false, true) => parallel_scatter::<P, false, true>(at, list, extra, force, partial, pieces),
                (true, false) => parallel_scatter::<P, true, false>(at, list, extra, force, partial, pieces),
                (false, false) => parallel_scatter::<P, false, false>(at, list, extra, force, partial, pieces),
            },
        }
    }
}

/// True when the part set's laws can take four contacts at once: no part that reads the normal
/// velocity or keeps an extra slot (friction may be on: [`groups::mixed`] carries it).
#[inline(always)]
fn lanes_apply<P: PartSet>() -> bool {
    !P::RATE && !P::COMPACTION && !P::DAMPING
}

/// What every contact of a step reads: the state it starts from, the step and the classes.
struct StepInput<'a> {
    /// Positions [x m, y m, θ rad].
    pos: &'a [[f64; 3]],
    /// Half-step velocities.
    vel: &'a [[f64; 3]],
    /// Δt, s.
    dt_s: f64,
    /// Contact classes.
    classes: &'a [ContactClass],
    /// The rate part's smoothed velocities [vx, vy], m/s, per element (`law::rate_field`);
    /// empty: each bond's rate reads its own pair's velocity.
    rate_vel: &'a [[f64; 2]],
    /// The lanes of the groups of four.
    width: lanes::Width,
}

/// Several threads: each contact's force into `force`, chunk by chunk.
#[inline(never)]
fn parallel<P: PartSet, const FOUR: bool>(at: &StepInput<'_>, list: &mut [Contact], extra: &mut [Extra], force: &mut [ContactForce], partial: &mut [Dissipation]) {
    let run = |((cs, fs), d): ((&mut [Contact], &mut [ContactForce]), &mut Dissipation), xs: &mut [Extra]| {
        *d = Dissipation::default();
        if FOUR {
            return lanes::run_as(at.width, ChunkFour::<P> { at, cs, xs, fs, d, parts: PhantomData });
        }
        each::<P, lanes::Portable, false>(at, cs, xs, d, |k, _, f| fs[k] = *f);
    };
    let chunks = list.par_chunks_mut(CHUNK).zip(force.par_chunks_mut(CHUNK)).zip(partial.par_iter_mut());
    if P::EXTRA {
        chunks.zip(extra.par_chunks_mut(CHUNK)).for_each(|(a, xs)| run(a, xs));
    } else {
        chunks.for_each(|a| run(a, &mut []));
    }
}

/// One chunk of [`parallel`] on lanes, with the groups of four: a task of its own, because the
/// closures of `parallel` are compiled without AVX, where the lanes' intrinsics would be calls.
struct ChunkFour<'a, 'b, P> {
    at: &'b StepInput<'a>,
    cs: &'b mut [Contact],
    xs: &'b mut [Extra],
    fs: &'b mut [ContactForce],
    d: &'b mut Dissipation,
    parts: PhantomData<P>,
}

impl<P: PartSet> lanes::Task for ChunkFour<'_, '_, P> {
    type Output = ();
    #[inline(always)]
    fn run<L: Lanes>(self) {
        let ChunkFour { at, cs, xs, fs, d, .. } = self;
        each::<P, L, true>(at, cs, xs, d, |k, _, f| fs[k] = *f);
    }
}

/// The scatter on the pool ([`Out::Pieces`]): the list cut into pieces in spans, one per thread
/// (`pieces::cuts`), and where each piece adds its forces (`pieces::plan`).
pub struct Pieces<'a> {
    /// The elements' sums [Fx N, Fy N, T N·m], zero on entry.
    pub sums: &'a mut [[f64; 3]],
    /// Each piece's range of elements.
    pub ranges: &'a [Range<u32>],
    /// Where the list is cut: piece p is `cuts[p]..cuts[p + 1]`.
    pub cuts: &'a [usize],
    /// Each thread's span of pieces: span s is pieces `spans[s]..spans[s + 1]`.
    pub spans: &'a [usize],
    /// Each piece's records (scratch space; output: the motion stage adds them,
    /// `pieces::fix_up_chunk`).
    pub records: &'a mut Vec<pieces::Kept>,
}

/// Several threads: the pieces (whole chunks) scatter their forces (`pieces`), each thread
/// taking its span's (`spans`). The sums are whole only once the records are added too
/// (`pieces::fix_up_chunk`, by the motion stage).
#[inline(never)]
fn parallel_scatter<P: PartSet, const RECORD: bool, const FOUR: bool>(
    at: &StepInput<'_>,
    list: &mut [Contact],
    extra: &mut [Extra],
    force: &mut [ContactForce],
    partial: &mut [Dissipation],
    Pieces { sums, ranges, cuts, spans: starts, records }: Pieces<'_>,
) {
    assert!(cuts.iter().rev().skip(1).all(|c| c.is_multiple_of(CHUNK)), "pieces of whole chunks: the dissipation is summed per chunk");
    assert!(cuts.last() == Some(&list.len()) && ranges.len() + 1 == cuts.len(), "a plan for another list");
    records.resize_with(ranges.len(), pieces::Kept::default);
    let n_elements = sums.len();
    let own = ranges.iter().map(|r| r.start as usize..r.end as usize);
    let mine = pieces::split(&mut *sums, own);
    let n = ranges.len();
    let xs: Vec<&mut [Extra]> = if P::EXTRA { pieces::split(extra, pieces::ranges(cuts, 1)) } else { (0..n).map(|_| &mut [][..]).collect() };
    let jobs: Vec<_> = (pieces::split(list, pieces::ranges(cuts, 1)).into_iter())
        .zip(pieces::split(force, pieces::ranges(cuts, 1)))
        .zip(pieces::split(partial, pieces::ranges(cuts, CHUNK)))
        .zip(xs)
        .zip(records.iter_mut().zip(mine).zip(ranges))
        .collect();
    spans::run(jobs, starts, |((((cs, fs), ds), xs), ((rs, s), r))| {
        let out = pieces::PieceSums::new(s, r.start, rs, n_elements);
        if FOUR {
            return lanes::run_as(at.width, ScatterFour::<P, RECORD, _> { at, list: cs, extra: xs, force: fs, partial: ds, out, parts: PhantomData });
        }
        scatter_alone::<P, RECORD, _>(at, cs, xs, fs, ds, out);
    });
}

/// Each contact's force added to its two elements by `out` as it goes (and stored in `force`
/// when `RECORD`), chunk by chunk.
#[inline(always)]
fn scatter<P: PartSet, const RECORD: bool, const FOUR: bool, L: Lanes, S: Sums>(
    at: &StepInput<'_>,
    list: &mut [Contact],
    extra: &mut [Extra],
    force: &mut [ContactForce],
    partial: &mut [Dissipation],
    mut out: S,
) {
    if FOUR {
        // A local copy, which the compiler keeps in registers (the argument lives in the
        // caller's frame, where the running sum is loaded and stored per contact). Not in the
        // scalar loop, which the copy made slower.
        let mut local = out;
        return scatter_into::<P, RECORD, FOUR, L, S>(at, list, extra, force, partial, &mut local);
    }
    scatter_into::<P, RECORD, FOUR, L, S>(at, list, extra, force, partial, &mut out)
}

/// [`scatter`]'s loop, adding through `out`.
#[inline(always)]
fn scatter_into<P: PartSet, const RECORD: bool, const FOUR: bool, L: Lanes, S: Sums>(
    at: &StepInput<'_>,
    list: &mut [Contact],
    extra: &mut [Extra],
    force: &mut [ContactForce],
    partial: &mut [Dissipation],
    out: &mut S,
) {
    let n = list.len();
    for (c, d) in partial.iter_mut().enumerate() {
        let (from, to) = (c * CHUNK, ((c + 1) * CHUNK).min(n));
        let xs = if P::EXTRA { &mut extra[from..to] } else { &mut [] };
        *d = Dissipation::default();
        each::<P, L, FOUR>(at, &mut list[from..to], xs, d, |k, c, f| {
            if RECORD {
                force[from + k] = *f;
            }
            out.add(c, f);
        });
    }
    out.finish();
}

/// [`scatter`] one at a time, as a function of its own: inlined into the pool's closure, where
/// the compiler knows less of what aliases what, the same loop ran slower.
#[inline(never)]
fn scatter_alone<P: PartSet, const RECORD: bool, S: Sums>(
    at: &StepInput<'_>,
    list: &mut [Contact],
    extra: &mut [Extra],
    force: &mut [ContactForce],
    partial: &mut [Dissipation],
    out: S,
) {
    scatter::<P, RECORD, false, lanes::Portable, S>(at, list, extra, force, partial, out)
}

/// [`scatter`] on lanes, with the groups of four.
struct ScatterFour<'a, 'b, P, const RECORD: bool, S> {
    at: &'b StepInput<'a>,
    list: &'b mut [Contact],
    extra: &'b mut [Extra],
    force: &'b mut [ContactForce],
    partial: &'b mut [Dissipation],
    out: S,
    parts: PhantomData<P>,
}

impl<P: PartSet, const RECORD: bool, S: Sums> lanes::Task for ScatterFour<'_, '_, P, RECORD, S> {
    type Output = ();
    #[inline(always)]
    fn run<L: Lanes>(self) {
        let ScatterFour { at, list, extra, force, partial, out, .. } = self;
        scatter::<P, RECORD, true, L, S>(at, list, extra, force, partial, out)
    }
}


/// Every contact of `cs` (extra slots `xs`, empty unless the parts keep them) evaluated, its
/// dissipation added to `d`, and `sink(index in cs, contact, force)` called in contact order.
/// With `FOUR` (in a [`lanes::Task`]), whole groups of four go on lanes `L` through
/// [`groups::bonds`] when they are intact bonds of one class, else through [`groups::mixed`]
/// when they are of one class, one by one when neither takes them (without `FOUR`, `L` is not
/// used).
#[inline(always)]
fn each<P: PartSet, L: Lanes, const FOUR: bool>(at: &StepInput<'_>, cs: &mut [Contact], xs: &mut [Extra], d: &mut Dissipation, mut sink: impl FnMut(usize, &Contact, &ContactForce)) {
    // The velocities cut to the positions' length, so that the compiler can drop checks of a
    // row against both (only for the lanes, see `scatter`).
    let cut = if FOUR { StepInput { vel: &at.vel[..at.pos.len()], ..*at } } else { StepInput { ..*at } };
    let at = &cut;
    let mut scratch = Extra::new(0.0);
    let mut from = 0;
    if FOUR {
        const N: usize = groups::LANES;
        // The geometry of the next eight groups first, then their laws: each group's root and
        // division start a long dependent chain (normal, shear spring, elastic test, forces)
        // that the processor's reorder window could not hide behind the ~350 instructions of
        // the group's law; made eight at a time, the roots and divisions run back to back and
        // the laws find them done: more instructions, less time.
        const AHEAD: usize = 8;
        let zero = L::zero();
        let mut geos = [Geometry { d2_m2: zero, d_m: zero, nx: zero, ny: zero }; AHEAD];
        let mut ahead = 0;
        let mut next = 0;
        while from + N <= cs.len() {
            if next == ahead {
                ahead = ((cs.len() - from) / N).min(AHEAD);
                for (g, geo) in geos.iter_mut().enumerate().take(ahead) {
                    *geo = geometry::of_four(at.pos, (&cs[from + g * N..from + (g + 1) * N]).try_into().unwrap());
                }
                next = 0;
            }
            let geo = &geos[next];
            next += 1;
            let group: &mut [Contact; N] = (&mut cs[from..from + N]).try_into().unwrap();
            let k = &at.classes[group[0].class as usize];
            let done = if groups::eligible(group) {
                match groups::bonds(geo, at.vel, group, k, at.dt_s) {
                    Some(g) => {
                        for (l, c) in group.iter_mut().enumerate() {
                            c.ut_m = g.ut_m[l];
                            sink(from + l, c, &g.force[l]);
                        }
                        // The scalar law books each elastic step's plastic work as 0 + 0, which
                        // leaves the sum as it is: it starts at +0 and is never −0.
                        true
                    }
                    None => false,
                }
            } else if groups::one_class(group) {
                match groups::mixed::<L, P>(geo, at.vel, group, k, at.dt_s, d) {
                    Some(f) => {
                        for (l, c) in group.iter().enumerate() {
                            sink(from + l, c, &f[l]);
                        }
                        true
                    }
                    None => false,
                }
            } else {
                false
            };
            if !done {
                for (l, c) in group.iter_mut().enumerate() {
                    let x = if P::EXTRA { &mut xs[from + l] } else { &mut scratch };
                    let f = one::<P>(at, c, x, d);
                    sink(from + l, c, &f);
                }
            }
            from += N;
        }
    }
    if !(P::RATE || P::DAMPING) {
        for (l, c) in cs.iter_mut().enumerate().skip(from) {
            let x = if P::EXTRA { &mut xs[l] } else { &mut scratch };
            let f = one::<P>(at, c, x, d);
            sink(l, c, &f);
        }
        return;
    }
    // With the parts that lengthen a bond's law most (rate, damping), one at a time in blocks:
    // first each contact's geometry and (for a bond) its rate ratios, then the rest of each
    // law. Such a law is one long dependent chain (root, division, the rate table's lookups,
    // the plateaus, the dashpots, the forces) of more instructions than the processor's
    // reorder window holds, so one contact's chain could not overlap the next's; cut in two,
    // the block's first halves run side by side, and then its second halves. A shorter law
    // pays for the blocks and gains nothing, so it is taken one at a time.
    while from < cs.len() {
        let to = (from + ONE_AHEAD).min(cs.len());
        let mut ahead = [Ahead::Nothing; ONE_AHEAD];
        for (l, a) in (from..to).zip(&mut ahead) {
            let x = if P::EXTRA { &mut xs[l] } else { &mut scratch };
            *a = first_half::<P>(at, &cs[l], x);
        }
        // By reference: an array taken by value is moved into its iterator, a memcpy of the
        // block.
        for (l, a) in (from..to).zip(&ahead) {
            let x = if P::EXTRA { &mut xs[l] } else { &mut scratch };
            let f = second_half::<P>(at, &mut cs[l], x, *a, d);
            sink(l, &cs[l], &f);
        }
        from = to;
    }
}

/// Contacts a block of the one-at-a-time loop takes at once (neither fewer nor more was
/// faster).
const ONE_AHEAD: usize = 8;

/// What the first half of a contact's evaluation leaves for the second.
#[derive(Clone, Copy)]
enum Ahead {
    /// A frictional pair apart with nothing to forget: no force, nothing changes.
    Nothing,
    /// A bond: its kinematics and its rate ratios (its rates already updated).
    Bond(Kinematics, law::rate::Ratios),
    /// Another frictional pair: its separation.
    Frictional(Separation),
}

/// The first half of [`one`]: everything up to the law proper.
#[inline(always)]
fn first_half<P: PartSet>(at: &StepInput<'_>, c: &Contact, x: &mut Extra) -> Ahead {
    let k = &at.classes[c.class as usize];
    let s = separation(at.pos, c);
    if c.bond == Bond::Intact {
        let g = along(at.vel, c, k, geometry::of(s));
        let vn_rate = if P::RATE { RateField::normal_velocity_mps(at.rate_vel, c.i, c.j, [g.nx, g.ny], g.vn_mps) } else { g.vn_mps };
        Ahead::Bond(g, law::bond_ratios::<P>(x, k, vn_rate))
    } else if law::friction::idle(c.ut_m, c.rest_m, k.radius_sum_m, s.d2_m2) {
        Ahead::Nothing
    } else {
        Ahead::Frictional(s)
    }
}

/// The second half of [`one`]: the law, from what [`first_half`] left.
#[inline(always)]
fn second_half<P: PartSet>(at: &StepInput<'_>, c: &mut Contact, x: &mut Extra, a: Ahead, d: &mut Dissipation) -> ContactForce {
    let k = &at.classes[c.class as usize];
    match a {
        Ahead::Nothing => ContactForce::default(),
        Ahead::Bond(g, ratios) => law::bonded_at::<P>(c, x, k, &g, ratios, at.dt_s, d),
        Ahead::Frictional(s) => frictional::<P>(at, c, k, s, d),
    }
}

/// One contact's force, its history updated and its dissipation added to `d`.
#[inline(always)]
fn one<P: PartSet>(at: &StepInput<'_>, c: &mut Contact, x: &mut Extra, d: &mut Dissipation) -> ContactForce {
    let a = first_half::<P>(at, c, x);
    second_half::<P>(at, c, x, a, d)
}

/// A frictional contact, out of line: inlined beside the bond law it made the all-bonded loop
/// more than twice as slow.
#[inline(never)]
fn frictional<P: PartSet>(at: &StepInput<'_>, c: &mut Contact, k: &ContactClass, s: Separation, d: &mut Dissipation) -> ContactForce {
    if law::friction::is_apart(s.d2_m2, c.rest_m) {
        law::friction::apart(c, k, s.d2_m2, d);
        ContactForce::default()
    } else {
        law::friction::touching::<P>(c, k, &along(at.vel, c, k, geometry::of(s)), at.dt_s, d)
    }
}

/// Geometry and relative velocity of a contact at the current state, or, for a frictional pair
/// that does not touch, Err(its squared distance, m²).
#[inline(always)]
pub fn kinematics(pos: &[[f64; 3]], vel: &[[f64; 3]], c: &Contact, k: &ContactClass) -> Result<Kinematics, f64> {
    let s = separation(pos, c);
    if c.bond == Bond::Frictional && law::friction::is_apart(s.d2_m2, c.rest_m) {
        return Err(s.d2_m2);
    }
    Ok(along(vel, c, k, geometry::of(s)))
}

/// Relative velocity of a pair of geometry `g`.
#[inline(always)]
fn along(vel: &[[f64; 3]], c: &Contact, k: &ContactClass, g: Geometry) -> Kinematics {
    let (vi, vj) = (vel[c.i as usize], vel[c.j as usize]);
    geometry::relative(&g, vj[0] - vi[0], vj[1] - vi[1], vi[2], vj[2], k.lever_i, k.lever_j)
}
