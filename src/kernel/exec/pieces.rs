//! The contact stage's scatter on the pool, in the one-thread order. The contact list is cut
//! into pieces of whole chunks, and each piece is given a range of elements that it is the
//! first piece to touch ([`plan`]); it adds its forces straight into the sums of its range and
//! keeps every other contribution, in contact order, as a [`Record`], filed by the motion
//! stage's chunk of its element ([`Kept`]). When all pieces are done the records are added
//! piece by piece (in a step by the motion stage, each chunk's records just before it moves that
//! chunk: [`fix_up_chunk`]). An element's sum is then formed from zero in
//! increasing contact order, as the one-thread scatter forms it, so the bits are the same for
//! any number of pieces or threads. An element outside every range (a projectile's element that
//! pieces far apart touch) is made by the fix-up alone, from zero, in the same order.
//!
//! The ranges are disjoint slices of the sums: safe code only, and the compiler knows the
//! pieces' writes alias nothing else. A plan that did not fit the list would change bits (the
//! thread-count tests would see it), never memory safety.
//!
//! Why not a gather: summing each element's forces over its adjacency after the stage reads
//! every force twice through a scattered index, which cost more than the scatter saves.

use crate::kernel::contact::{Contact, ContactForce};
use super::scatter::Sums;

/// Contacts per piece at most by default: 32 chunks (see `Model::scatter_piece_contacts`).
/// Only the first pieces of a span are this long, and they are its own thread's: fewer pieces,
/// fewer contributions through the records.
pub const PIECE: usize = 32 * super::scatter::CHUNK;

/// The pieces for `contacts` contacts on `threads` threads, pieces of `most` contacts at most
/// (at least one chunk). The list is cut into one span of about equal chunks per thread, each
/// taken from its front by its thread and from its back by the others when they are done
/// (`spans`); within a span the pieces shrink towards its back, `most`, …, 8, 4, 2 chunks, so
/// that what the others take first is small. (The level-2 event on two threads, in even pieces
/// of eight chunks that rayon halved between the threads, idled ~6.5 % of its contact stage,
/// the two threads' last pieces ending 0.29–0.30 ms apart per step; in spans, 0.16–0.21 ms.)
/// Pieces of one chunk at the very back were no better: each cut sends a band of the lattice
/// through the records.
///
/// `cuts` gets each piece's first contact and then `contacts`, so piece p is
/// `cuts[p]..cuts[p + 1]`; `spans` gets each span's first piece and then the number of pieces.
/// Every piece is whole chunks (the last may end the list).
pub fn cuts(contacts: usize, threads: usize, most: usize, cuts: &mut Vec<usize>, spans: &mut Vec<usize>) {
    let chunk = super::scatter::CHUNK;
    let most = (most / chunk).max(1);
    let chunks = contacts.div_ceil(chunk);
    let n_spans = threads.clamp(1, chunks.max(1));
    cuts.clear();
    spans.clear();
    let mut sizes = Vec::new();
    for s in 0..n_spans {
        let (from, to) = (chunks * s / n_spans, chunks * (s + 1) / n_spans);
        // From the back: 2, 4, 8, … up to `most`; the front piece takes what is left, or
        // joins the next if it would be less than half of it.
        sizes.clear();
        let (mut left, mut next) = (to - from, most.min(2));
        while left > 0 {
            let size = next.min(left);
            left -= size;
            if size < next.div_ceil(2) && !sizes.is_empty() {
                *sizes.last_mut().expect("not empty") += size;
            } else {
                sizes.push(size);
            }
            next = (2 * next).min(most);
        }
        spans.push(cuts.len());
        let mut at = from;
        for size in sizes.iter().rev() {
            cuts.push(at * chunk);
            at += size;
        }
    }
    spans.push(cuts.len());
    cuts.push(contacts);
}

/// One contribution to an element outside the piece's range, kept for [`fix_up_chunk`].
#[derive(Debug, Clone, Copy)]
pub struct Record {
    /// The element.
    pub e: u32,
    /// What to add: [Fx N, Fy N, T N·m].
    pub add: [f64; 3],
}

/// Elements per chunk of the motion stage (fixed, for deterministic partial sums), by which
/// records are filed.
pub const MOTION_CHUNK: usize = 1024;

/// One piece's records, filed by the motion stage's chunk of their element, each chunk's in
/// contact order (scratch space, kept from step to step).
///
/// Why filed: the records used to be added in a pass of their own after the contact stage, on
/// the pool, each thread reading every record for the ones of its half of the elements (the
/// level-2 penetration event on two threads: ~22 000 records a step, 1.6 % of the two cores'
/// samples under perf, and a fork and join a step). Filed by chunk, each chunk's records are
/// added by the motion stage's job for that chunk, which reads that chunk's sums next anyway.
#[derive(Debug, Clone, Default)]
pub struct Kept {
    by_chunk: Vec<Vec<Record>>,
}

impl Kept {
    /// Empty, with a bucket for each motion chunk of `n_elements` elements.
    fn reset(&mut self, n_elements: usize) {
        self.by_chunk.resize_with(n_elements.div_ceil(MOTION_CHUNK), Vec::new);
        self.by_chunk.iter_mut().for_each(Vec::clear);
    }

    /// The records for elements of motion chunk `k`, in contact order.
    pub fn chunk(&self, k: usize) -> &[Record] {
        &self.by_chunk[k]
    }
}

/// The contact stage's plan on the pool: where the list is cut into pieces, each piece's
/// elements it adds into directly, and the pieces' spans, one per thread. Derived from the
/// contact list and remade whenever the list, the pool or the cap changes; the contact list
/// itself knows nothing of it.
#[derive(Debug, Clone, Default)]
pub struct Plan {
    /// Per piece, the elements it scatters into directly ([`plan`]).
    pub ranges: Vec<std::ops::Range<u32>>,
    /// Where the list is cut ([`cuts`]): piece p is `cuts[p]..cuts[p + 1]`.
    pub cuts: Vec<usize>,
    /// The pieces' spans: span s is pieces `spans[s]..spans[s + 1]`.
    pub spans: Vec<usize>,
    /// The threads and the longest piece, contacts, the plan is made for (None: no plan).
    rule: Option<(usize, usize)>,
    scratch: PlanScratch,
}

impl Plan {
    /// A plan for `threads` threads and pieces of `most` contacts at most, made now unless the
    /// present one already is (on rayon's pool).
    pub fn ensure(&mut self, threads: usize, most: usize, list: &[Contact], n_elements: usize) {
        if self.rule != Some((threads, most)) {
            self.rule = Some((threads, most));
            self.make(list, n_elements, true);
        }
    }

    /// After the list changed: the plan made again, if one is kept (with `pool`, on rayon's
    /// pool).
    pub fn follow(&mut self, list: &[Contact], n_elements: usize, pool: bool) {
        if self.rule.is_some() {
            self.make(list, n_elements, pool);
        }
    }

    /// Drop the plan (a restored state: the next step on the pool makes one).
    pub fn forget(&mut self) {
        self.rule = None;
    }

    fn make(&mut self, list: &[Contact], n_elements: usize, pool: bool) {
        let (threads, most) = self.rule.expect("a rule to plan by");
        cuts(list.len(), threads, most, &mut self.cuts, &mut self.spans);
        plan(list, &self.cuts, n_elements, pool, &mut self.scratch, &mut self.ranges);
    }
}

/// Scratch space of [`plan`]: each element's first piece, and the later half's on the pool.
#[derive(Debug, Clone, Default)]
pub struct PlanScratch {
    first: Vec<u32>,
    later: Vec<u32>,
}

/// For the pieces cut at `cuts` (see [`cuts`]), the range of elements each piece writes
/// straight into, written to `out` (one per piece): elements that piece is the first to touch,
/// the ranges disjoint and increasing. With `pool`, the pieces' first touches are found in two
/// halves on rayon's pool (the same plan: one pass over the list, 0.8 ms a merge serial on
/// the level-2 penetration event).
pub fn plan(list: &[Contact], cuts: &[usize], n_elements: usize, pool: bool, scratch: &mut PlanScratch, out: &mut Vec<std::ops::Range<u32>>) {
    assert_eq!(cuts.last(), Some(&list.len()), "cuts for another list");
    let n_pieces = cuts.len() - 1;
    let PlanScratch { first, later } = scratch;
    let touch = |pieces: std::ops::Range<usize>, first: &mut Vec<u32>| {
        first.clear();
        first.resize(n_elements, u32::MAX);
        for p in pieces {
            for c in &list[cuts[p]..cuts[p + 1]] {
                for e in [c.i, c.j] {
                    let f = &mut first[e as usize];
                    *f = (*f).min(p as u32);
                }
            }
        }
    };
    if pool && n_pieces > 1 {
        let mid = n_pieces / 2;
        rayon::join(|| touch(0..mid, first), || touch(mid..n_pieces, later));
        first.iter_mut().zip(later.iter()).for_each(|(f, &l)| *f = (*f).min(l));
    } else {
        touch(0..n_pieces, first);
    }
    // Each piece's longest run of elements it touches first; elements no contact touches
    // (u32::MAX: held supports, say) join any run, since nothing is added to them.
    out.clear();
    out.resize(n_pieces, 0..0);
    let (mut start, mut cur) = (0, u32::MAX);
    for e in 0..=n_elements {
        let p = first.get(e).copied().unwrap_or(u32::MAX - 1);
        if p == u32::MAX || p == cur {
            continue;
        }
        if let Some(r) = out.get_mut(cur as usize)
            && e - start > r.len()
        {
            *r = start as u32..e as u32;
        }
        (start, cur) = (e, p);
    }
    // Increasing: a range that starts before the previous one ends is dropped (its elements go
    // through the records).
    let mut end = 0;
    for r in out.iter_mut() {
        if r.start < end {
            *r = end..end;
        } else if r.start < r.end {
            end = r.end;
        }
    }
}

/// Split `all` into the slices of `ranges` (disjoint and increasing; what lies between them is
/// left out): the sums into the ranges of a [`plan`], the contact list into pieces.
pub fn split<T>(mut all: &mut [T], ranges: impl Iterator<Item = std::ops::Range<usize>>) -> Vec<&mut [T]> {
    let mut at = 0;
    ranges
        .map(|r| {
            let (_, from_start) = std::mem::take(&mut all).split_at_mut(r.start - at);
            let (mine, rest) = from_start.split_at_mut(r.len());
            (all, at) = (rest, r.end);
            mine
        })
        .collect()
}

/// The pieces of [`cuts`] as ranges, each scaled down by `per` (contacts per item: 1 for the
/// contacts, `scatter::CHUNK` for the per-chunk dissipation), the last rounded up.
pub fn ranges(cuts: &[usize], per: usize) -> impl Iterator<Item = std::ops::Range<usize>> + '_ {
    cuts.windows(2).map(move |w| w[0] / per..w[1].div_ceil(per))
}

/// One piece's side of the scatter: straight into its range, into `records` otherwise.
pub struct PieceSums<'a> {
    /// The sums of the range, element `lo` first.
    sums: &'a mut [[f64; 3]],
    lo: u32,
    records: &'a mut Kept,
    /// The element whose i-contributions are being summed in `acc` (contacts are sorted by i),
    /// and whether it is in the range.
    run_i: u32,
    own_i: bool,
    acc: [f64; 3],
}

impl<'a> PieceSums<'a> {
    /// The piece whose range starts at element `lo`, with its sums; `records` is emptied and
    /// given a bucket per motion chunk of `n_elements` elements.
    pub fn new(sums: &'a mut [[f64; 3]], lo: u32, records: &'a mut Kept, n_elements: usize) -> Self {
        records.reset(n_elements);
        PieceSums { sums, lo, records, run_i: u32::MAX, own_i: false, acc: [0.0; 3] }
    }

    #[inline(always)]
    fn mine(&mut self, e: u32) -> Option<&mut [f64; 3]> {
        self.sums.get_mut(e.wrapping_sub(self.lo) as usize)
    }

    #[inline(always)]
    fn flush(&mut self) {
        if self.own_i {
            let (e, acc) = (self.run_i, self.acc);
            *self.mine(e).expect("in the range") = acc;
        }
    }
}

/// Out of line: the law's loop keeps its registers.
#[cold]
#[inline(never)]
fn keep(records: &mut Kept, e: u32, add: [f64; 3]) {
    records.by_chunk[e as usize / MOTION_CHUNK].push(Record { e, add });
}

impl Sums for PieceSums<'_> {
    #[inline(always)]
    fn add(&mut self, c: &Contact, f: &ContactForce) {
        if c.i != self.run_i {
            self.flush();
            self.run_i = c.i;
            match self.mine(c.i) {
                Some(s) => (self.own_i, self.acc) = (true, *s),
                None => self.own_i = false,
            }
        }
        if self.own_i {
            self.acc[0] += f.fx;
            self.acc[1] += f.fy;
            self.acc[2] += f.ti;
        } else {
            keep(self.records, c.i, [f.fx, f.fy, f.ti]);
        }
        // s − f and s + (−f) are the same IEEE operation: the record carries −f.
        match self.mine(c.j) {
            Some(s) => {
                s[0] -= f.fx;
                s[1] -= f.fy;
                s[2] += f.tj;
            }
            None => keep(self.records, c.j, [-f.fx, -f.fy, f.tj]),
        }
    }

    #[inline(always)]
    fn finish(&mut self) {
        self.flush();
    }
}

/// The records of motion chunk `k` added to its sums `sums` (element `k × CHUNK` first), piece
/// by piece, each in its contact order: what adding every piece's records in turn would add to
/// these elements, in its order, so the same bits (the tests' `fix_up` is that reference).
/// Called by the motion stage's job for the chunk, whichever thread runs it.
#[inline]
pub fn fix_up_chunk(sums: &mut [[f64; 3]], k: usize, records: &[Kept]) {
    let first = k * MOTION_CHUNK;
    for r in records.iter().flat_map(|kept| kept.chunk(k)) {
        add(&mut sums[r.e as usize - first], r);
    }
}

#[inline(always)]
fn add(s: &mut [f64; 3], r: &Record) {
    s[0] += r.add[0];
    s[1] += r.add[1];
    s[2] += r.add[2];
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every piece's records added to the sums, piece by piece, each in its contact order: the
    /// reference for [`fix_up_chunk`]. Indexed: a record for an element that does not exist is
    /// a bug of the plan, and stops here.
    fn fix_up(sums: &mut [[f64; 3]], records: &[Kept]) {
        for r in records.iter().flat_map(|k| k.by_chunk.iter().flatten()) {
            add(&mut sums[r.e as usize], r);
        }
    }

    fn kept_len(k: &Kept) -> usize {
        k.by_chunk.iter().map(Vec::len).sum()
    }
    use super::super::scatter::Serial;

    /// Forces with a wide spread of magnitudes, so that any change of summation order shows in
    /// the bits.
    fn force(k: usize) -> ContactForce {
        let x = (k as f64 * 0.618_033_988_75).fract();
        let scale = [1e-9, 1.0, 1e7, 3e-3][k % 4];
        ContactForce { fx: (x - 0.5) * scale, fy: (0.3 - x) * scale * 1.7, ti: x * scale * 0.1, tj: -x * scale * 0.07 }
    }

    /// A lattice-like list sorted by (i, j), with some far-away partners (a projectile's
    /// elements at the end of the numbering).
    fn list(n: u32) -> Vec<Contact> {
        let mut l = Vec::new();
        for i in 0..n {
            for d in [1, 7, 8] {
                if i + d < n {
                    l.push(Contact::bonded(i, i + d, 0, 1.0));
                }
            }
            if i % 13 == 0 && i + 1 < n - 3 {
                l.push(Contact::frictional(i, n - 1 - i % 3, 0, 1.0));
            }
        }
        l.sort_by_key(|c| (c.i, c.j));
        l.dedup_by_key(|c| (c.i, c.j));
        l
    }

    fn serial(list: &[Contact], n: usize) -> Vec<[f64; 3]> {
        let mut sums = vec![[0.0; 3]; n];
        let mut s = Serial::new(&mut sums);
        for (k, c) in list.iter().enumerate() {
            s.add(c, &force(k));
        }
        s.finish();
        sums
    }

    /// Cuts every `piece` contacts.
    fn even(list: &[Contact], piece: usize) -> Vec<usize> {
        (0..list.len()).step_by(piece).chain([list.len()]).collect()
    }

    fn pieced(list: &[Contact], n: usize, cuts: &[usize], order: &[usize]) -> (Vec<[f64; 3]>, usize) {
        let (mut sums, records) = unfixed(list, n, cuts, order);
        fix_up(&mut sums, &records);
        (sums, records.iter().map(kept_len).sum())
    }

    /// The pieces' sums and records before the fix-up, the pieces run in `order`.
    fn unfixed(list: &[Contact], n: usize, cuts: &[usize], order: &[usize]) -> (Vec<[f64; 3]>, Vec<Kept>) {
        let (mut scratch, mut ranges) = (PlanScratch::default(), Vec::new());
        plan(list, cuts, n, false, &mut scratch, &mut ranges);
        let mut sums = vec![[0.0; 3]; n];
        let mut records = vec![Kept::default(); ranges.len()];
        {
            let own = ranges.iter().map(|r| r.start as usize..r.end as usize);
            let mut mine: Vec<Option<&mut [[f64; 3]]>> = split(&mut sums, own).into_iter().map(Some).collect();
            let mut kept: Vec<Option<&mut Kept>> = records.iter_mut().map(Some).collect();
            // The pieces in any order: as the pool may run them.
            for &p in order {
                let mut s = PieceSums::new(mine[p].take().unwrap(), ranges[p].start, kept[p].take().unwrap(), n);
                for (k, c) in list.iter().enumerate().take(cuts[p + 1]).skip(cuts[p]) {
                    s.add(c, &force(k));
                }
                s.finish();
            }
        }
        (sums, records)
    }

    fn bits(s: &[[f64; 3]]) -> Vec<u64> {
        s.iter().flatten().map(|v| v.to_bits()).collect()
    }

    #[test]
    fn pieces_in_any_order_give_the_one_thread_sums_bit_for_bit() {
        let n = 400;
        let l = list(n as u32);
        let want = serial(&l, n);
        // Even pieces, and pieces shrinking along the list as `cuts` makes them.
        let shrinking: Vec<usize> = [0, 300, 500, 620, 700, 740, 760, 770].into_iter().filter(|&c| c < l.len()).chain([l.len()]).collect();
        assert!(shrinking.len() > 6, "the list is too short for the shrinking pieces");
        for cuts in [1, 5, 64, 333, l.len()].map(|piece| even(&l, piece)).into_iter().chain([shrinking]) {
            let n_pieces = cuts.len() - 1;
            let forward: Vec<usize> = (0..n_pieces).collect();
            let backward: Vec<usize> = (0..n_pieces).rev().collect();
            let (a, kept) = pieced(&l, n, &cuts, &forward);
            let (b, _) = pieced(&l, n, &cuts, &backward);
            let first = cuts[1];
            assert!(bits(&a) == bits(&want), "{n_pieces} pieces, the first of {first}: sums differ from one thread's");
            assert!(bits(&b) == bits(&want), "{n_pieces} pieces, the first of {first}, run backwards: sums differ");
            if n_pieces > 1 {
                assert!(kept > 0, "{n_pieces} pieces: nothing went through the records");
            } else {
                assert_eq!(kept, 0, "one piece owns every element it touches");
            }
        }
    }

    #[test]
    fn the_fix_up_chunk_by_chunk_gives_the_whole_fix_up_bit_for_bit() {
        // Elements over several motion chunks, the last one short: a lattice whose rows are a
        // chunk long and a half, partners far along the numbering.
        let n = 3 * MOTION_CHUNK + MOTION_CHUNK / 3;
        let l = list(n as u32);
        let cuts = even(&l, 700);
        let (sums, records) = unfixed(&l, n, &cuts, &(0..cuts.len() - 1).collect::<Vec<_>>());
        let chunks = n.div_ceil(MOTION_CHUNK);
        for k in 0..chunks {
            let here = records.iter().map(|r| r.chunk(k).len()).sum::<usize>();
            assert!(here > 10, "chunk {k} has only {here} records: too few to test its boundaries");
            assert!(records.iter().flat_map(|r| r.chunk(k)).all(|r| r.e as usize / MOTION_CHUNK == k), "chunk {k} holds another's record");
        }
        let mut want = sums.clone();
        fix_up(&mut want, &records);
        assert!(bits(&want) != bits(&sums), "the records changed nothing");
        let mut got = sums.clone();
        // In any order of the chunks, as the motion stage's threads may take them.
        for k in (0..chunks).rev() {
            let lo = k * MOTION_CHUNK;
            fix_up_chunk(&mut got[lo..(lo + MOTION_CHUNK).min(n)], k, &records);
        }
        assert!(bits(&got) == bits(&want), "chunk by chunk the sums differ from the whole fix-up's");
    }

    /// Piece lengths in chunks, span by span.
    fn chunks_of(contacts: usize, threads: usize, most: usize) -> Vec<Vec<usize>> {
        let chunk = super::super::scatter::CHUNK;
        let (mut c, mut s) = (Vec::new(), Vec::new());
        cuts(contacts, threads, most, &mut c, &mut s);
        assert_eq!((c[0], *c.last().unwrap()), (0, contacts), "the cuts must span the list");
        assert!(c.windows(2).all(|w| w[0] < w[1]), "empty pieces: {c:?}");
        assert!(c[..c.len() - 1].iter().all(|&k| k % chunk == 0), "pieces of whole chunks: {c:?}");
        assert_eq!((s[0], *s.last().unwrap()), (0, c.len() - 1), "the spans must cover the pieces");
        let len = |p: usize| c[p + 1].div_ceil(chunk) - c[p] / chunk;
        s.windows(2).map(|w| (w[0]..w[1]).map(len).collect()).collect()
    }

    #[test]
    fn a_span_per_thread_of_whole_chunks_shrinking_to_two_and_never_above_half_again_the_cap() {
        let chunk = super::super::scatter::CHUNK;
        // The level-2 event on two threads: 166 243 contacts, 82 chunks, two spans of 41.
        assert_eq!(chunks_of(166_243, 2, PIECE), vec![vec![27, 8, 4, 2]; 2]);
        // Under a cap of 16 chunks, as before.
        assert_eq!(chunks_of(166_243, 2, 16 * chunk), vec![vec![11, 16, 8, 4, 2]; 2]);
        // The peers' beam on two threads: 39 726 contacts, 20 chunks.
        assert_eq!(chunks_of(39_726, 2, PIECE), vec![vec![4, 4, 2]; 2]);
        // Spans differ by a chunk at most; small lists: fewer spans than threads; a cap below
        // a chunk still gives a chunk.
        assert_eq!(chunks_of(5 * 2048, 2, PIECE), [vec![2], vec![3]]);
        assert_eq!(chunks_of(9 * 2048, 1, 2 * 2048), [vec![1, 2, 2, 2, 2]]);
        assert_eq!(chunks_of(3_000, 8, PIECE), [vec![1], vec![1]]);
        assert_eq!(chunks_of(1_000, 2, PIECE), [vec![1]]);
        assert!(chunks_of(166_243, 2, 0).iter().flatten().all(|&c| c == 1));
        for threads in [1, 2, 3, 8] {
            for span in chunks_of(166_243, threads, PIECE) {
                let tail = &span[1..];
                assert!(tail.windows(2).all(|w| w[0] >= w[1]) && tail.last() <= Some(&2), "{threads} threads: {span:?}");
                let cap = PIECE / chunk;
                assert!(span.iter().all(|&c| c <= cap + cap / 2), "{threads} threads: {span:?}");
            }
        }
    }

    #[test]
    fn each_range_holds_only_elements_its_piece_touches_first_and_the_ranges_do_not_overlap() {
        let n = 400;
        let l = list(n as u32);
        let (mut scratch, mut ranges) = (PlanScratch::default(), Vec::new());
        plan(&l, &even(&l, 64), n, false, &mut scratch, &mut ranges);
        // On the pool, the same plan.
        for threads in [1, 2, 3] {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
            for cuts in [even(&l, 64), even(&l, 5), even(&l, l.len())] {
                let (mut want, mut got) = (Vec::new(), Vec::new());
                plan(&l, &cuts, n, false, &mut scratch, &mut want);
                pool.install(|| plan(&l, &cuts, n, true, &mut PlanScratch::default(), &mut got));
                assert_eq!(got, want, "{threads} threads, {} pieces: the plan on the pool differs", cuts.len() - 1);
            }
        }
        let mut end = 0;
        for (p, r) in ranges.iter().enumerate() {
            assert!(r.start >= end, "range {p} {r:?} overlaps the one before (ending at {end})");
            end = end.max(r.end);
            let touched_before = |e: u32| l[..p * 64].iter().any(|c| c.i == e || c.j == e);
            for e in r.clone() {
                assert!(!touched_before(e), "element {e} of piece {p}'s range is touched by an earlier piece");
                assert!(l[p * 64..].iter().take(64).any(|c| c.i == e || c.j == e), "element {e} of piece {p}'s range is not its");
            }
        }
        // The lattice's pieces own most of it: only the bands between them and the far
        // partners are left to the fix-up.
        let owned: usize = ranges.iter().map(|r| r.len()).sum();
        assert!(owned > n / 2, "the ranges hold {owned} of {n} elements");
    }
}
