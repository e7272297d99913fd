//! The contact stage's scatter on the pool, in the one-thread order. The contact list is cut
//! into pieces of whole chunks, and each piece is given a range of elements that it is the
//! first piece to touch ([`plan`]); it adds its forces straight into the sums of its range and
//! keeps every other contribution, in contact order, as a [`Record`]. When all pieces are done
//! the records are added piece by piece ([`fix_up`]). An element's sum is then formed from zero
//! in increasing contact order, as the one-thread scatter forms it, so the bits are the same for
//! any number of pieces or threads. An element outside every range (a projectile's element that
//! pieces far apart touch) is made by the fix-up alone, from zero, in the same order.
//!
//! The ranges are disjoint slices of the sums: no unsafe code, and the compiler knows the
//! pieces' writes alias nothing else. A plan that did not fit the list would change bits (the
//! thread-count tests would see it), never memory safety.
//!
//! Why not a gather: summing each element's forces over its adjacency after the stage reads
//! every force twice through a scattered index (2.4× the one-thread motion stage on the
//! level-2 penetration event, the largest part of why two threads were 1.52× one).

use super::contacts::{Contact, ContactForce};
use super::forces::Sums;

/// Contacts per piece at most by default: eight chunks (see `Model::scatter_piece_contacts`).
pub const PIECE: usize = 8 * super::forces::CHUNK;

/// Pieces per thread aimed at: enough for the pool to even out pieces of unequal cost (the
/// peers' beam, 39 726 contacts, in pieces of eight chunks made three pieces for two threads
/// and ran 1.2× slower than the chunks of the gather before it).
const PIECES_PER_THREAD: usize = 4;

/// Contacts per piece for `contacts` contacts on `threads` threads, pieces of `most` contacts
/// at most: whole chunks, at least one.
pub fn piece_len(contacts: usize, threads: usize, most: usize) -> usize {
    let chunk = super::forces::CHUNK;
    let chunks = contacts / (PIECES_PER_THREAD * threads.max(1)) / chunk;
    (chunks.max(1) * chunk).min(most.max(chunk))
}

/// One contribution to an element outside the piece's range, kept for [`fix_up`].
#[derive(Debug, Clone, Copy)]
pub struct Record {
    /// The element.
    pub e: u32,
    /// What to add: [Fx N, Fy N, T N·m].
    pub add: [f64; 3],
}

/// For pieces of `piece` contacts (in list order), the range of elements each piece writes
/// straight into, written to `out` (one per piece): elements that piece is the first to touch,
/// the ranges disjoint and increasing. `first` is scratch space.
pub fn plan(list: &[Contact], piece: usize, n_elements: usize, first: &mut Vec<u32>, out: &mut Vec<std::ops::Range<u32>>) {
    first.clear();
    first.resize(n_elements, u32::MAX);
    for (p, cs) in list.chunks(piece).enumerate() {
        for c in cs {
            for e in [c.i, c.j] {
                let f = &mut first[e as usize];
                *f = (*f).min(p as u32);
            }
        }
    }
    // Each piece's longest run of elements it touches first; elements no contact touches
    // (u32::MAX: held supports, say) join any run, since nothing is added to them.
    let n_pieces = list.len().div_ceil(piece);
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

/// Split `sums` into the pieces' ranges of `plan` (the rest is left to the fix-up).
pub fn split<'a>(mut sums: &'a mut [[f64; 3]], plan: &[std::ops::Range<u32>]) -> Vec<&'a mut [[f64; 3]]> {
    let mut at = 0;
    plan.iter()
        .map(|r| {
            let (_, from_start) = std::mem::take(&mut sums).split_at_mut(r.start as usize - at);
            let (mine, rest) = from_start.split_at_mut(r.len());
            (sums, at) = (rest, r.end as usize);
            mine
        })
        .collect()
}

/// One piece's side of the scatter: straight into its range, into `records` otherwise.
pub struct PieceSums<'a> {
    /// The sums of the range, element `lo` first.
    sums: &'a mut [[f64; 3]],
    lo: u32,
    records: &'a mut Vec<Record>,
    /// The element whose i-contributions are being summed in `acc` (contacts are sorted by i),
    /// and whether it is in the range.
    run_i: u32,
    own_i: bool,
    acc: [f64; 3],
}

impl<'a> PieceSums<'a> {
    /// The piece whose range starts at element `lo`, with its sums; `records` is cleared.
    pub fn new(sums: &'a mut [[f64; 3]], lo: u32, records: &'a mut Vec<Record>) -> Self {
        records.clear();
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
fn keep(records: &mut Vec<Record>, e: u32, add: [f64; 3]) {
    records.push(Record { e, add });
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

/// Add every piece's records to the sums, piece by piece, each in its contact order.
pub fn fix_up(sums: &mut [[f64; 3]], records: &[Vec<Record>]) {
    for r in records.iter().flatten() {
        let s = &mut sums[r.e as usize];
        s[0] += r.add[0];
        s[1] += r.add[1];
        s[2] += r.add[2];
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::forces::Serial;

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

    fn pieced(list: &[Contact], n: usize, piece: usize, order: &[usize]) -> (Vec<[f64; 3]>, usize) {
        let (mut first, mut ranges) = (Vec::new(), Vec::new());
        plan(list, piece, n, &mut first, &mut ranges);
        let mut sums = vec![[0.0; 3]; n];
        let mut records = vec![Vec::new(); ranges.len()];
        {
            let mut mine: Vec<Option<&mut [[f64; 3]]>> = split(&mut sums, &ranges).into_iter().map(Some).collect();
            let mut kept: Vec<Option<&mut Vec<Record>>> = records.iter_mut().map(Some).collect();
            // The pieces in any order: as the pool may run them.
            for &p in order {
                let mut s = PieceSums::new(mine[p].take().unwrap(), ranges[p].start, kept[p].take().unwrap());
                for (k, c) in list.iter().enumerate().skip(p * piece).take(piece) {
                    s.add(c, &force(k));
                }
                s.finish();
            }
        }
        fix_up(&mut sums, &records);
        (sums, records.iter().map(Vec::len).sum())
    }

    fn bits(s: &[[f64; 3]]) -> Vec<u64> {
        s.iter().flatten().map(|v| v.to_bits()).collect()
    }

    #[test]
    fn pieces_in_any_order_give_the_one_thread_sums_bit_for_bit() {
        let n = 400;
        let l = list(n as u32);
        let want = serial(&l, n);
        for piece in [1, 5, 64, 333, l.len()] {
            let n_pieces = l.len().div_ceil(piece);
            let forward: Vec<usize> = (0..n_pieces).collect();
            let backward: Vec<usize> = (0..n_pieces).rev().collect();
            let (a, kept) = pieced(&l, n, piece, &forward);
            let (b, _) = pieced(&l, n, piece, &backward);
            assert!(bits(&a) == bits(&want), "pieces of {piece}: sums differ from one thread's");
            assert!(bits(&b) == bits(&want), "pieces of {piece} run backwards: sums differ");
            if n_pieces > 1 {
                assert!(kept > 0, "pieces of {piece}: nothing went through the records");
            } else {
                assert_eq!(kept, 0, "one piece owns every element it touches");
            }
        }
    }

    #[test]
    fn pieces_are_whole_chunks_about_four_per_thread_and_never_above_the_cap() {
        let chunk = crate::kernel::forces::CHUNK;
        // The peers' beam on two threads: 39 726 contacts in pieces of two chunks (ten pieces).
        assert_eq!(piece_len(39_726, 2, PIECE), 2 * chunk);
        // The level-2 event: 166 243 contacts, capped at eight chunks.
        assert_eq!(piece_len(166_243, 2, PIECE), PIECE);
        // Small lists: one chunk; the cap below a chunk still gives a chunk.
        assert_eq!(piece_len(3_000, 8, PIECE), chunk);
        assert_eq!(piece_len(166_243, 2, 0), chunk);
    }

    #[test]
    fn each_range_holds_only_elements_its_piece_touches_first_and_the_ranges_do_not_overlap() {
        let n = 400;
        let l = list(n as u32);
        let (mut first, mut ranges) = (Vec::new(), Vec::new());
        plan(&l, 64, n, &mut first, &mut ranges);
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
