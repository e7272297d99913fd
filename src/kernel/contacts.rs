//! Contact arrays: one entry per pair that is bonded or may touch before the next neighbour
//! rebuild, sorted by (i, j); the optional parts' state beside it; and the per-contact force
//! output. How the contact stage runs over them on the pool is `exec::pieces::Plan`'s.

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::law::{Dissipation, Extra};

use super::contact::{Bond, Contact, ContactForce};

/// The contact list with its optional state and its forces.
#[derive(Debug, Clone, Default, Serialize, Deserialize)]
pub struct Contacts {
    /// Contacts sorted by (i, j).
    pub list: Vec<Contact>,
    /// The optional parts' state, parallel to `list` (empty when no part needs it).
    pub extra: Vec<Extra>,
    /// Forces of the last step, parallel to `list`: written only with
    /// `Model::record_contact_forces` (else never written: zero), and zeroed at a merge then
    /// (`Model::merge`), until the next step writes them.
    pub force: Vec<ContactForce>,
    #[serde(skip)]
    merged: Vec<Contact>,
    #[serde(skip)]
    merged_extra: Vec<Extra>,
    /// Scratch of a merge on the pool: its parts after the first.
    #[serde(skip)]
    parts: Vec<MergePart>,
}

impl Contacts {
    /// A contact set from a list and its extra slots (empty or parallel); the forces are sized
    /// by [`Contacts::refresh`] or a merge.
    pub fn from_list(list: Vec<Contact>, extra: Vec<Extra>) -> Self {
        debug_assert!(extra.is_empty() || extra.len() == list.len());
        Contacts { list, extra, ..Default::default() }
    }

    /// Number of contacts.
    pub fn len(&self) -> usize {
        self.list.len()
    }

    /// True when there are none.
    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// After the list changed: the forces sized to it (new entries zero; the others are left
    /// as they are, since a run that does not record them never writes them).
    pub fn refresh(&mut self) {
        self.force.resize(self.list.len(), ContactForce::default());
    }

    /// Replace the list by the union of the contacts worth keeping and the broad phase's
    /// candidate `pairs` (sorted by (i, j)), which are all the candidates among the pairs for
    /// which `covered(i, j)` (every pair after a full search, the movers' after a local one;
    /// the contacts of the other pairs are kept as they are). Kept with their history: intact bonds (always) and
    /// frictional contacts that are still candidates or still touch (`touching(c)`; a candidate
    /// that is apart is kept too: the contact loop lets it forget, so the physics does not
    /// depend on when lists are rebuilt). Any other frictional contact is dropped; what its shear spring
    /// still held is booked in `released` as friction. Candidates not already present become
    /// `fresh(i, j)` contacts when `admit(i, j)` (pairs that can never interact, such as two
    /// fixed supports, are left out); `fresh_extra(i, j)` gives their extra slot.
    ///
    /// With `pool`, the list is merged in one part per thread of rayon's pool, each a range of
    /// first elements i, side by side; the parts after the first are then appended, on the pool.
    /// The result, and the order in which what is dropped is booked, are the one-part merge's.
    /// (The level-2 penetration event: 127 merges of ~168 000 contacts, each copying the list
    /// and its extra slots, 13 MB; one part took 2.7 ms a merge, serial, while the other core
    /// waited.)
    #[allow(clippy::too_many_arguments)]
    pub fn merge_candidates(
        &mut self,
        pairs: &[(u32, u32)],
        covered: impl Fn(u32, u32) -> bool + Sync,
        touching: impl Fn(&Contact) -> bool + Sync,
        fresh: impl Fn(u32, u32) -> Contact + Sync,
        fresh_extra: impl Fn(u32, u32) -> Extra + Sync,
        admit: impl Fn(u32, u32) -> bool + Sync,
        release_j: impl Fn(&Contact) -> f64 + Sync,
        released: &mut Dissipation,
        pool: bool,
    ) {
        let Contacts { list: old, extra, merged, merged_extra, parts, .. } = self;
        let with_extra = !extra.is_empty();
        let kept = |c: &Contact| c.bond == Bond::Intact || !covered(c.i, c.j) || touching(c);
        let n_parts = if pool { rayon::current_num_threads().clamp(1, old.len().div_ceil(MERGE_PART_MIN).max(1)) } else { 1 };
        // Where part t starts in the list and in the candidates: at the first contact of the
        // element i that the t-th of n_parts equal shares of the list starts in.
        let starts: Vec<(usize, usize)> = (0..=n_parts)
            .map(|t| match t {
                0 => (0, 0),
                t if t == n_parts => (old.len(), pairs.len()),
                t => {
                    let i0 = old[old.len() * t / n_parts].i;
                    (old.partition_point(|c| c.i < i0), pairs.partition_point(|&(i, _)| i < i0))
                }
            })
            .collect();
        let part = |t: usize, list: &mut Vec<Contact>, xs: &mut Vec<Extra>, released: &mut dyn FnMut(&Contact)| {
            let (o, p) = (starts[t].0..starts[t + 1].0, starts[t].1..starts[t + 1].1);
            let xo = if with_extra { &extra[o.clone()] } else { &[][..] };
            list.clear();
            xs.clear();
            merge_part(&old[o], xo, &pairs[p], with_extra, &kept, &fresh, &fresh_extra, &admit, released, list, xs);
        };
        parts.resize_with(n_parts - 1, MergePart::default);
        let mut book = |c: &Contact| released.friction_j += release_j(c);
        if n_parts == 1 {
            // Not through a scope, which from outside the pool would hand the merge to it.
            part(0, merged, merged_extra, &mut book);
        } else {
            rayon::scope(|s| {
                for (t, w) in parts.iter_mut().enumerate() {
                    let part = &part;
                    let release_j = &release_j;
                    s.spawn(move |_| {
                        w.released_j.clear();
                        part(t + 1, &mut w.list, &mut w.extra, &mut |c: &Contact| w.released_j.push(release_j(c)));
                    });
                }
                part(0, merged, merged_extra, &mut book);
            });
        }
        // The later parts in order, as one part would have made and booked them.
        for w in parts.iter() {
            merged.par_extend(w.list.par_iter().copied());
            merged_extra.par_extend(w.extra.par_iter().copied());
            for r in &w.released_j {
                released.friction_j += r;
            }
        }
        std::mem::swap(&mut self.list, &mut self.merged);
        std::mem::swap(&mut self.extra, &mut self.merged_extra);
        self.refresh();
    }
}

/// Contacts below which a merge is not split into parts.
const MERGE_PART_MIN: usize = 8192;

/// A later part of a merge on the pool (scratch space).
#[derive(Debug, Clone, Default)]
struct MergePart {
    list: Vec<Contact>,
    extra: Vec<Extra>,
    /// What the dropped contacts' shear springs held, in their order, J.
    released_j: Vec<f64>,
}

/// [`Contacts::merge_candidates`] for the contacts `old` (with their extra slots `extra`, empty
/// unless `with_extra`) and the candidates `pairs` of one range of first elements: the kept
/// contacts and the fresh ones appended to `list` and `xs` in (i, j) order, each dropped one
/// handed to `dropped` in its order.
#[allow(clippy::too_many_arguments)]
fn merge_part(
    old: &[Contact],
    extra: &[Extra],
    pairs: &[(u32, u32)],
    with_extra: bool,
    kept: &impl Fn(&Contact) -> bool,
    fresh: &impl Fn(u32, u32) -> Contact,
    fresh_extra: &impl Fn(u32, u32) -> Extra,
    admit: &impl Fn(u32, u32) -> bool,
    dropped: &mut dyn FnMut(&Contact),
    list: &mut Vec<Contact>,
    xs: &mut Vec<Extra>,
) {
    let (mut a, mut b) = (0usize, 0usize);
    loop {
        // Candidates already in the list, as many in a row as the list has them (after a
        // full search nearly every contact is one): kept with their history, copied whole.
        let same = pairs[b..].iter().zip(&old[a..]).take_while(|&(&(i, j), c)| c.i == i && c.j == j).count();
        list.extend_from_slice(&old[a..a + same]);
        if with_extra {
            xs.extend_from_slice(&extra[a..a + same]);
        }
        (a, b) = (a + same, b + same);
        let kb = pairs.get(b).map_or(u64::MAX, |&(i, j)| ((i as u64) << 32) | j as u64);
        // The old contacts before the candidate: kept as they are, in runs copied whole, or
        // dropped.
        loop {
            let run = a + old[a..].iter().position(|c| c.key() >= kb || !kept(c)).unwrap_or(old.len() - a);
            list.extend_from_slice(&old[a..run]);
            if with_extra {
                xs.extend_from_slice(&extra[a..run]);
            }
            a = run;
            match old.get(a) {
                Some(c) if c.key() < kb => {
                    if c.ut_m != 0.0 {
                        dropped(c);
                    }
                    a += 1;
                }
                _ => break,
            }
        }
        let Some(&(i, j)) = pairs.get(b) else { break };
        if old.get(a).is_some_and(|c| c.key() == kb) {
            // A candidate already in the list: the run above takes it, with any after it.
            continue;
        }
        if admit(i, j) {
            list.push(fresh(i, j));
            if with_extra {
                xs.push(fresh_extra(i, j));
            }
        }
        b += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn merge_keeps_bonds_and_candidates_with_history_and_books_what_is_dropped() {
        let mut f = Contact::frictional(0, 3, 0, 1.0);
        f.ut_m = 0.5;
        let mut gone = Contact::frictional(2, 3, 0, 1.0);
        gone.ut_m = 0.25;
        let mut c = Contacts::from_list(vec![Contact::bonded(0, 1, 0, 1.0), f, gone], vec![]);
        let mut released = Dissipation::default();
        // (2,3) is no longer a candidate: dropped, its spring booked. (1,2) new. (0,3) kept.
        c.merge_candidates(
            &[(0, 3), (1, 2)],
            |_, _| true,
            |_| false,
            |i, j| Contact::frictional(i, j, 7, 2.0),
            |_, _| Extra::new(0.0),
            |_, _| true,
            |k| k.ut_m * 2.0,
            &mut released,
            false,
        );
        let keys: Vec<_> = c.list.iter().map(|k| (k.i, k.j, k.class)).collect();
        assert_eq!(keys, vec![(0, 1, 0), (0, 3, 0), (1, 2, 7)]);
        assert_eq!(c.list[1].ut_m, 0.5);
        assert_eq!(c.force.len(), 3);
        assert_eq!(released.friction_j, 0.5);
    }

    /// The merge as first written, one contact at a time: the reference for the merge in runs.
    #[allow(clippy::too_many_arguments)]
    fn merged_one_by_one(
        old: &[Contact],
        extra: &[Extra],
        pairs: &[(u32, u32)],
        covered: impl Fn(u32, u32) -> bool,
        touching: impl Fn(&Contact) -> bool,
        fresh: impl Fn(u32, u32) -> Contact,
        fresh_extra: impl Fn(u32, u32) -> Extra,
        admit: impl Fn(u32, u32) -> bool,
        release_j: impl Fn(&Contact) -> f64,
        released: &mut Dissipation,
    ) -> (Vec<Contact>, Vec<Extra>) {
        let (mut list, mut xs) = (vec![], vec![]);
        let with_extra = !extra.is_empty();
        let (mut a, mut b) = (0usize, 0usize);
        while a < old.len() || b < pairs.len() {
            let ka = old.get(a).map_or(u64::MAX, Contact::key);
            let kb = pairs.get(b).map_or(u64::MAX, |&(i, j)| ((i as u64) << 32) | j as u64);
            if ka <= kb {
                let c = old[a];
                if c.bond == Bond::Intact || ka == kb || !covered(c.i, c.j) || touching(&c) {
                    list.push(c);
                    if with_extra {
                        xs.push(extra[a]);
                    }
                } else if c.ut_m != 0.0 {
                    released.friction_j += release_j(&c);
                }
                a += 1;
                b += (ka == kb) as usize;
            } else {
                let (i, j) = pairs[b];
                if admit(i, j) {
                    list.push(fresh(i, j));
                    if with_extra {
                        xs.push(fresh_extra(i, j));
                    }
                }
                b += 1;
            }
        }
        (list, xs)
    }

    /// A merge to make: old contacts and their extra slots, candidates, which elements moved
    /// and whether the search was full.
    struct Case {
        old: Vec<Contact>,
        extra: Vec<Extra>,
        pairs: Vec<(u32, u32)>,
        movers: Vec<bool>,
        full: bool,
    }

    /// A random merge: old contacts over `n` elements (some bonded, some with a shear spring
    /// whose release spans many magnitudes, so that the booking order shows in the bits), their
    /// extra slots, candidates (some of them old pairs: few, as after a local update, or
    /// nearly all, in long runs, as after a full search).
    fn random_case(rnd: &mut impl FnMut(u64) -> u64, n: u32, keys: u64, others: u64, round: usize) -> Case {
        // Mostly near partners (a lattice's), some anywhere.
        let pair = |rnd: &mut dyn FnMut(u64) -> u64| {
            let i = rnd(n as u64) as u32;
            let j = if rnd(4) == 0 { rnd(n as u64) as u32 } else { i + 1 + rnd(40) as u32 };
            (i, j)
        };
        let mut old_keys: Vec<(u32, u32)> = (0..keys).map(|_| pair(rnd)).filter(|&(i, j)| i < j && j < n).collect();
        old_keys.sort_unstable();
        old_keys.dedup();
        let old: Vec<Contact> = old_keys
            .iter()
            .map(|&(i, j)| {
                let mut c = if rnd(3) == 0 { Contact::bonded(i, j, 0, 1.0) } else { Contact::frictional(i, j, 0, 1.0) };
                c.ut_m = if rnd(2) == 0 { 0.0 } else { 0.1 * (i + j) as f64 * [1e-9, 1.0, 1e7][rnd(3) as usize] };
                c
            })
            .collect();
        let extra: Vec<Extra> = old_keys.iter().map(|&(i, j)| Extra::new((i * 100 + j) as f64)).collect();
        let mut pairs: Vec<(u32, u32)> = (0..others).map(|_| pair(rnd)).filter(|&(i, j)| i < j && j < n).collect();
        let share = if round.is_multiple_of(2) { 2 } else { 7 };
        pairs.extend(old_keys.iter().filter(|_| rnd(8) < share));
        pairs.sort_unstable();
        pairs.dedup();
        let movers: Vec<bool> = (0..n).map(|_| rnd(3) == 0).collect();
        Case { old, extra, pairs, movers, full: round.is_multiple_of(3) }
    }

    /// `merge_candidates` on the case against the one-by-one reference, bit for bit.
    fn merge_matches_reference(case: &Case, pool: bool, what: &str) {
        let Case { old, extra, pairs, movers, full } = case;
        let covered = |i: u32, j: u32| *full || movers[i as usize] || movers[j as usize];
        let touching = |c: &Contact| (c.i * 7 + c.j).is_multiple_of(3);
        let fresh = |i: u32, j: u32| Contact::frictional(i, j, 1, 2.0);
        let fresh_extra = |i: u32, _| Extra::new(i as f64);
        let admit = |i: u32, j: u32| !(i + j).is_multiple_of(5);
        let release = |k: &Contact| k.ut_m * 0.5;
        let mut want = Dissipation::default();
        let (list, xs) = merged_one_by_one(old, extra, pairs, covered, touching, fresh, fresh_extra, admit, release, &mut want);
        let mut c = Contacts::from_list(old.clone(), extra.clone());
        let mut got = Dissipation::default();
        c.merge_candidates(pairs, covered, touching, fresh, fresh_extra, admit, release, &mut got, pool);
        assert!(c.list == list, "{what}: the lists differ");
        assert!(c.extra == xs, "{what}: the extra slots differ");
        assert_eq!(got.friction_j.to_bits(), want.friction_j.to_bits(), "{what}: the released energy differs");
        assert_eq!(c.force.len(), list.len());
    }

    fn rng(seed: u64) -> impl FnMut(u64) -> u64 {
        let mut s = seed;
        move |m: u64| {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (s >> 33) % m
        }
    }

    #[test]
    fn merge_in_runs_is_the_merge_one_contact_at_a_time() {
        let mut rnd = rng(99);
        for round in 0..200 {
            let (n, keys, others) = (2 + rnd(40) as u32, rnd(120), rnd(60));
            let case = random_case(&mut rnd, n, keys, others, round);
            merge_matches_reference(&case, false, &format!("round {round}"));
        }
    }

    #[test]
    fn merge_in_parts_on_the_pool_is_the_merge_one_contact_at_a_time() {
        let mut rnd = rng(7);
        for round in 0..6 {
            // Lists long enough to be cut into parts (MERGE_PART_MIN).
            let case = random_case(&mut rnd, 20_000, 60_000, 30_000, round);
            assert!(case.old.len() > 3 * MERGE_PART_MIN, "round {round}: too few contacts for three parts");
            for threads in [1, 2, 3] {
                let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
                pool.install(|| merge_matches_reference(&case, true, &format!("round {round}, {threads} threads")));
            }
        }
    }
}
