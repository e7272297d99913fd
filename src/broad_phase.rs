//! Broad phase: every pair of elements whose gap is below the sum of their margins.
//!
//! Sort-based cell grid: elements are sorted by the key of their cell (row-major), and each
//! element looks up the forward half of its 3×3 neighbourhood with binary searches. No grid
//! array is allocated, so elements that fly arbitrarily far away cost nothing extra and are
//! still found (cell coordinates are clamped to i32; the final test is the exact distance, so
//! clamping can only add candidates, never lose a pair). The result is sorted by (i, j) and is
//! a pure function of the positions and margins: deterministic.
//!
//! Margins differ per element (a fast element gets a wide one, so that it does not trigger a
//! rebuild every step): the cells are sized for the usual reach r + m, and the few elements that
//! reach further search the rings of cells their reach needs.

use rayon::prelude::*;

/// Reusable buffers for the broad phase (no allocation once warmed up).
#[derive(Debug, Default, Clone)]
pub struct BroadPhase {
    keyed: Vec<(u64, u32)>,
    /// Scratch: the movers' new keys, and `keyed` merged with them.
    moved: Vec<(u64, u32)>,
    merged: Vec<(u64, u32)>,
    pairs: Vec<u64>,
    wide: Vec<u32>,
    /// Scratch: whether each element is wide (its reach r + m above the usual one).
    is_wide: Vec<bool>,
    count: Vec<u32>,
    fill: Vec<u32>,
    /// 1 / cell size of the last full search, 1/m.
    inv_cell: f64,
}

/// Elements per block of the full search on the pool.
const BLOCK: usize = 4096;

/// Movers per block of a local search on the pool.
const MOVERS_BLOCK: usize = 256;

/// Wide elements per block of the full search on the pool.
const WIDE_BLOCK: usize = 512;

/// Cell coordinates are clamped to this range, so that a neighbour (±k) never aliases a cell.
const CELL_LIMIT: i64 = i32::MAX as i64 - 1024;

/// [`each_around`] cuts the square to the disc for centres within this many cells of the
/// origin (a kilometre for millimetre cells); a cell coordinate's rounding there is below
/// 1e-9 cells.
const DISC_CELLS: f64 = 1e6;

/// How much wider than the reach [`each_around`]'s disc is, cells: far above the rounding of a
/// centre's cell coordinate within [`DISC_CELLS`] and of the reach test.
const DISC_SLACK_CELLS: f64 = 1e-6;

/// The cell of a centre `c` [x m, y m] for cells of 1/`inv` m, its coordinates clamped.
fn cell_of(c: [f64; 2], inv: f64) -> (i64, i64) {
    let clamp = |v: f64| ((v * inv).floor() as i64).clamp(-CELL_LIMIT, CELL_LIMIT);
    (clamp(c[0]), clamp(c[1]))
}

fn cell_key(cx: i64, cy: i64) -> u64 {
    let offset = |c: i64| (c - i32::MIN as i64) as u64;
    (offset(cy) << 32) | offset(cx)
}

/// Pushes the pair of a (centre `ca`) and b, smaller index first, packed as (i << 32) | j,
/// when their centres are closer than r_a + r_b + m_a + m_b.
#[inline(always)]
fn reach_test(a: usize, b: usize, ca: [f64; 2], centre: &impl Fn(usize) -> [f64; 2], r: &[f64], margin: &impl Fn(usize) -> f64, pairs: &mut Vec<u64>) {
    let cb = centre(b);
    let (dx, dy) = (cb[0] - ca[0], cb[1] - ca[1]);
    let reach = (r[a] + r[b]) + (margin(a) + margin(b));
    if dx * dx + dy * dy < reach * reach {
        let (i, j) = if a < b { (a, b) } else { (b, a) };
        pairs.push(((i as u64) << 32) | j as u64);
    }
}

/// `find(items, out)` over `0..n`: in one go, or with `pool` in blocks of `block` items on
/// rayon's pool, their finds appended to `out` in block order (the same list either way).
fn in_blocks(pool: bool, n: usize, block: usize, out: &mut Vec<u64>, find: impl Fn(std::ops::Range<usize>, &mut Vec<u64>) + Sync) {
    if !pool {
        return find(0..n, out);
    }
    let found: Vec<Vec<u64>> = (0..n.div_ceil(block))
        .into_par_iter()
        .map(|b| {
            let mut v = Vec::new();
            find(b * block..((b + 1) * block).min(n), &mut v);
            v
        })
        .collect();
    found.iter().for_each(|v| out.extend_from_slice(v));
}

/// Calls `each(b)` for every element b keyed in a cell (of 1/`inv` m) the disc of radius
/// `reach_m` about the centre `ca` [x m, y m] may overlap — the caller's reach bound, within
/// which every partner its test can take lies —, row by row: the square of cells within
/// ⌈reach⌉ of the centre's cell, each row cut to the columns the disc reaches in it (on average
/// 14 of the square's 25 cells for a reach of 1.5 cells, 18 for 1.8). The elements of the other
/// cells, which the reach test would only turn away, are not visited.
#[inline(always)]
fn each_around(keys: &[(u64, u32)], ca: [f64; 2], inv: f64, reach_m: f64, mut each: impl FnMut(usize)) {
    // In cell units: the centre's cell, the centre and the reach.
    let ((cx, cy), t, reach) = (cell_of(ca, inv), [ca[0] * inv, ca[1] * inv], reach_m * inv);
    let k = reach.ceil() as i64;
    // The slack (in cells) covers the rounding of the centres' cell coordinates and of the
    // reach test, so that no pair the test takes is cut; far out (fragments that flew away,
    // where cells may be clamped and a cell coordinate's rounding grows) the whole square, as
    // for a reach that is not a number (whose square is the own cell, as it always was).
    let disc = reach.is_finite() && t[0].abs().max(t[1].abs()) < DISC_CELLS;
    let s = reach + DISC_SLACK_CELLS;
    for y in cy - k..=cy + k {
        let (mut x0, mut x1) = (cx - k, cx + k);
        if disc {
            let dy = (y as f64 - t[1]).max(t[1] - (y + 1) as f64).max(0.0);
            if dy >= s {
                continue;
            }
            let w = (s * s - dy * dy).sqrt();
            x0 = x0.max((t[0] - w).floor() as i64);
            x1 = x1.min((t[0] + w).floor() as i64);
        }
        let (lo, hi) = (cell_key(x0, y), cell_key(x1, y));
        let from = keys.partition_point(|&(kk, _)| kk < lo);
        let to = keys.partition_point(|&(kk, _)| kk <= hi);
        for &(_, b) in &keys[from..to] {
            each(b as usize);
        }
    }
}

fn cell_coords(key: u64) -> (i64, i64) {
    ((key & 0xffff_ffff) as i64 + i32::MIN as i64, (key >> 32) as i64 + i32::MIN as i64)
}

impl BroadPhase {
    /// All pairs (i < j) with |c_i − c_j| < r_i + r_j + m_i + m_j, sorted by (i, j), written to
    /// `out` (cleared first); `centre(e)` gives element e's centre [x m, y m] for e < r.len(),
    /// `margin(e)` its margin, m. Cells are sized for the reach r + m of most elements
    /// (`usual_reach_m`; None: the largest radius plus the smallest margin). With `pool`, the
    /// search runs in blocks on rayon's pool; the result is the same.
    #[allow(clippy::too_many_arguments)]
    pub fn pairs(
        &mut self,
        centre: impl Fn(usize) -> [f64; 2] + Sync,
        r: &[f64],
        margin: impl Fn(usize) -> f64 + Sync,
        usual_reach_m: Option<f64>,
        pool: bool,
        out: &mut Vec<(u32, u32)>,
    ) {
        out.clear();
        let n = r.len();
        if n < 2 {
            return;
        }
        // Cells are sized for the usual reach: the largest radius plus the smallest margin
        // (most elements have it).
        let usual = usual_reach_m.unwrap_or_else(|| {
            let r_max = r.iter().copied().fold(0.0, f64::max);
            r_max + (0..n).map(&margin).fold(f64::INFINITY, f64::min)
        });
        let cell = 2.0 * usual;
        let inv = 1.0 / cell;
        self.inv_cell = inv;
        // Key the elements in the order of the last call: elements move little between
        // rebuilds, so the keys come nearly sorted and the (adaptive, stable) sort is cheap.
        // (key, element) pairs are distinct, so the order is the same whatever the sort.
        if self.keyed.len() != n {
            self.keyed.clear();
            self.keyed.extend((0..n as u32).map(|e| (0, e)));
        }
        self.wide.clear();
        let key = |k: &mut (u64, u32)| {
            let (cx, cy) = cell_of(centre(k.1 as usize), inv);
            k.0 = cell_key(cx, cy);
        };
        if pool {
            self.keyed.par_iter_mut().for_each(key);
            self.keyed.par_sort();
        } else {
            self.keyed.iter_mut().for_each(key);
            self.keyed.sort();
        }
        // Whether an element is wide is asked of every pair the usual pass looks at: once per
        // element here, a flag, instead of its reach again at each pair.
        self.is_wide.clear();
        self.is_wide.extend((0..n).map(|e| r[e] + margin(e) > usual));
        self.wide.extend((0..n as u32).filter(|&e| self.is_wide[e as usize]));
        self.pairs.clear();
        let keys = &self.keyed;
        let lower = |k: u64| keys.partition_point(|&(kk, _)| kk < k);
        let flags = &self.is_wide;
        let is_wide = |e: usize| flags[e];
        let test = |a: usize, b: usize, ca: [f64; 2], pairs: &mut Vec<u64>| reach_test(a, b, ca, &centre, r, &margin, pairs);
        // Usual–usual pairs: forward half-stencil (rest of own cell and (cx+1, cy), then the
        // three cells above); two usual reaches never exceed one cell. The elements come in
        // key order, so the stencil's bounds only move forward: three pointers, no search
        // (a block's first element finds them by binary search).
        let usual_block = |block: std::ops::Range<usize>, pairs: &mut Vec<u64>| {
            let (mut same_end, mut above_start, mut above_end) = (block.start, 0usize, 0usize);
            if block.start < n {
                let (cx, cy) = cell_coords(keys[block.start].0);
                above_start = lower(cell_key(cx - 1, cy + 1));
            }
            for s in block {
                let (key, a) = keys[s];
                let a = a as usize;
                let (cx, cy) = cell_coords(key);
                let (k_same, k_lo, k_hi) = (cell_key(cx + 1, cy), cell_key(cx - 1, cy + 1), cell_key(cx + 1, cy + 1));
                while same_end < n && keys[same_end].0 <= k_same {
                    same_end += 1;
                }
                while above_start < n && keys[above_start].0 < k_lo {
                    above_start += 1;
                }
                above_end = above_end.max(above_start);
                while above_end < n && keys[above_end].0 <= k_hi {
                    above_end += 1;
                }
                if is_wide(a) {
                    continue;
                }
                let ca = centre(a);
                for &(_, b) in keys[s + 1..same_end].iter().chain(&keys[above_start..above_end]) {
                    if !is_wide(b as usize) {
                        test(a, b as usize, ca, pairs);
                    }
                }
            }
        };
        in_blocks(pool, n, BLOCK, &mut self.pairs, usual_block);
        // Wide elements: every cell within their reach plus the widest one; a pair of two wide
        // elements is taken once, from the smaller index. In blocks on the pool too: in an
        // impact they can be a third of the elements or more (anything set moving faster than
        // half its skin over the margin's look-ahead), each testing the cells of a 5 × 5 block
        // its reach disc overlaps, and this loop was then most of a full search.
        let widest = self.wide.iter().map(|&e| r[e as usize] + margin(e as usize)).fold(usual, f64::max);
        let wide_block = |wide: &[u32], pairs: &mut Vec<u64>| {
            for &a in wide {
                let a = a as usize;
                let ca = centre(a);
                each_around(keys, ca, inv, r[a] + margin(a) + widest, |b| {
                    if b != a && (!is_wide(b) || a < b) {
                        test(a, b, ca, pairs);
                    }
                });
            }
        };
        let wide = &self.wide;
        in_blocks(pool, wide.len(), WIDE_BLOCK, &mut self.pairs, |b, pairs| wide_block(&wide[b], pairs));
        // Sort by (i, j): a counting sort on i, then each i's few partners in place.
        self.count.clear();
        self.count.resize(n + 1, 0);
        for &p in &self.pairs {
            self.count[(p >> 32) as usize + 1] += 1;
        }
        for e in 0..n {
            self.count[e + 1] += self.count[e];
        }
        out.resize(self.pairs.len(), (0, 0));
        self.fill.clear();
        self.fill.extend_from_slice(&self.count[..n]);
        for &p in &self.pairs {
            let i = (p >> 32) as usize;
            out[self.fill[i] as usize] = (i as u32, p as u32);
            self.fill[i] += 1;
        }
        if pool {
            out.par_chunk_by_mut(|a, b| a.0 == b.0).for_each(<[(u32, u32)]>::sort_unstable);
        } else {
            for e in 0..n {
                out[self.count[e] as usize..self.count[e + 1] as usize].sort_unstable();
            }
        }
    }
    /// After a full [`BroadPhase::pairs`]: the elements `movers` (flagged in `is_mover`) have
    /// new centres (and margins); re-key them, and write to `out` every pair (i < j, sorted)
    /// that involves a mover and satisfies the same reach test, where `widest_m` bounds r + m
    /// of every element. Pairs between two other elements are not looked at. With `pool`, the
    /// movers are searched in blocks on rayon's pool; the result is the same.
    #[allow(clippy::too_many_arguments)]
    pub fn requery(
        &mut self,
        movers: &[u32],
        is_mover: &[bool],
        centre: impl Fn(usize) -> [f64; 2] + Sync,
        r: &[f64],
        margin: impl Fn(usize) -> f64 + Sync,
        widest_m: f64,
        pool: bool,
        out: &mut Vec<(u32, u32)>,
    ) {
        out.clear();
        let inv = self.inv_cell;
        // The others keep their keys and their order: the movers' new keys, sorted apart, are
        // merged in (the (key, element) pairs are distinct, so the order is the full sort's).
        self.moved.clear();
        self.moved.extend(movers.iter().map(|&e| {
            let (cx, cy) = cell_of(centre(e as usize), inv);
            (cell_key(cx, cy), e)
        }));
        self.moved.sort_unstable();
        self.merged.clear();
        let mut moved = self.moved.iter().peekable();
        for &k in self.keyed.iter().filter(|k| !is_mover[k.1 as usize]) {
            while let Some(&m) = moved.next_if(|&&m| m < k) {
                self.merged.push(m);
            }
            self.merged.push(k);
        }
        self.merged.extend(moved);
        std::mem::swap(&mut self.keyed, &mut self.merged);
        let keys = &self.keyed;
        let search = |movers: &[u32], pairs: &mut Vec<u64>| {
            for &a in movers {
                let a = a as usize;
                let ca = centre(a);
                each_around(keys, ca, inv, r[a] + margin(a) + widest_m, |b| {
                    if b != a {
                        reach_test(a, b, ca, &centre, r, &margin, pairs);
                    }
                });
            }
        };
        self.pairs.clear();
        in_blocks(pool, movers.len(), MOVERS_BLOCK, &mut self.pairs, |b, pairs| search(&movers[b], pairs));
        if pool {
            self.pairs.par_sort_unstable();
        } else {
            self.pairs.sort_unstable();
        }
        self.pairs.dedup();
        out.extend(self.pairs.iter().map(|&p| ((p >> 32) as u32, p as u32)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn brute(x: &[f64], y: &[f64], r: &[f64], m: impl Fn(usize) -> f64) -> Vec<(u32, u32)> {
        let mut v = vec![];
        for i in 0..x.len() {
            for j in i + 1..x.len() {
                let reach = r[i] + r[j] + m(i) + m(j);
                if (x[j] - x[i]).powi(2) + (y[j] - y[i]).powi(2) < reach * reach {
                    v.push((i as u32, j as u32));
                }
            }
        }
        v
    }

    /// Uniform numbers in [0, 1) from `seed` (a linear congruential generator).
    fn uniform(seed: u64) -> impl FnMut() -> f64 {
        let mut s = seed;
        move || {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    #[test]
    fn matches_brute_force_including_far_away_elements_and_after_a_local_update() {
        let mut rnd = uniform(12345);
        let n = 400;
        let mut x: Vec<f64> = (0..n).map(|_| rnd() * 0.5 - 0.25).collect();
        let mut y: Vec<f64> = (0..n).map(|_| rnd() * 0.5).collect();
        let r: Vec<f64> = (0..n).map(|_| 0.005 + 0.01 * rnd()).collect();
        // Fragments that flew far away, one pair of them still touching, and negative coordinates.
        x[3] = 1e9;
        y[3] = -4e8;
        x[7] = 1e9 + 0.01;
        y[7] = -4e8;
        x[11] = -3e12;
        let mut bp = BroadPhase::default();
        let mut out = vec![];
        bp.pairs(|e| [x[e], y[e]], &r, |_| 0.001, None, false, &mut out);
        assert_eq!(out, brute(&x, &y, &r, |_| 0.001));
        assert!(out.contains(&(3, 7)));
        // Per-element margins, some elements reaching several cells further than the rest.
        let m = |e: usize| if e.is_multiple_of(17) { 0.03 + 0.001 * (e % 5) as f64 } else { 0.0005 + 0.0001 * (e % 3) as f64 };
        bp.pairs(|e| [x[e], y[e]], &r, m, None, false, &mut out);
        assert_eq!(out, brute(&x, &y, &r, m));
        bp.pairs(|e| [x[e], y[e]], &r, m, Some(0.012), false, &mut out);
        assert_eq!(out, brute(&x, &y, &r, m));
        // Move some elements (far, and a little) and requery them alone: with the pairs of the
        // others from before, the union is the full search at the new positions.
        let movers: Vec<u32> = (0..n as u32).filter(|e| e % 7 == 3).collect();
        let mut is_mover = vec![false; n];
        movers.iter().for_each(|&e| is_mover[e as usize] = true);
        for &e in &movers {
            x[e as usize] += 0.003 * (e % 5) as f64 - 0.006;
            y[e as usize] -= 0.002 * (e % 3) as f64;
        }
        x[3] = 5.0;
        let widest = (0..n).map(|e| r[e] + m(e)).fold(0.0, f64::max);
        let mut moved = vec![];
        bp.requery(&movers, &is_mover, |e| [x[e], y[e]], &r, m, widest, false, &mut moved);
        let mut union: Vec<(u32, u32)> = out.iter().copied().filter(|&(i, j)| !is_mover[i as usize] && !is_mover[j as usize]).chain(moved).collect();
        union.sort_unstable();
        assert_eq!(union, brute(&x, &y, &r, m));
    }

    #[test]
    fn the_disc_cut_keeps_pairs_at_the_edge_of_reach() {
        // A wide element with a ring of wide partners just inside their reach (and a second
        // ring just outside), for centres all over a cell: the pairs the cells' disc keeps
        // (`each_around`) are every pair the reach test takes, in the full search and in the
        // movers' search. Two far anchors with the smallest margin set the usual reach.
        let (r, wide_m, usual_m) = (0.004, 0.011, 0.0005);
        let reach = 2.0 * (r + wide_m);
        let angles = 64;
        let mut rnd = uniform(99);
        for _ in 0..24 {
            let (cx, cy) = (0.3 + 0.05 * rnd(), -0.2 + 0.05 * rnd());
            let (mut x, mut y) = (vec![cx, 50.0, 60.0], vec![cy, 50.0, 60.0]);
            for (k, f) in (0..2 * angles).map(|k| (k, if k < angles { 1.0 - 1e-9 } else { 1.0 + 1e-9 })) {
                let phi = std::f64::consts::TAU * (k % angles) as f64 / angles as f64 + 0.013;
                x.push(cx + f * reach * phi.cos());
                y.push(cy + f * reach * phi.sin());
            }
            let n = x.len();
            let rs = vec![r; n];
            let m = |e: usize| if e == 1 || e == 2 { usual_m } else { wide_m };
            let mut bp = BroadPhase::default();
            let mut out = vec![];
            bp.pairs(|e| [x[e], y[e]], &rs, m, None, false, &mut out);
            let expected = brute(&x, &y, &rs, m);
            assert_eq!(out, expected);
            assert!((1..=angles as u32 + 2).all(|j| j < 3 || out.contains(&(0, j))), "the inner ring is found");
            let mut moved = vec![];
            let mut is_mover = vec![false; n];
            is_mover[0] = true;
            bp.requery(&[0], &is_mover, |e| [x[e], y[e]], &rs, m, r + wide_m, false, &mut moved);
            assert_eq!(moved, expected.iter().copied().filter(|&(i, _)| i == 0).collect::<Vec<_>>());
        }
    }

    #[test]
    fn regression_a_reach_that_is_not_a_number_visits_the_own_cell_as_before_the_disc_cut() {
        // Cut to a disc of NaN radius, a row's columns came out reversed (from the own column
        // to column 0): the own cell was lost, and with elements keyed between the two the key
        // slice panicked. The square alone visits the own cell, as it did before the cut.
        let mut keys: Vec<(u64, u32)> = [(5, 7, 0u32), (5, 7, 1), (6, 7, 2), (-3, 7, 3), (2, 7, 4)].iter().map(|&(x, y, e)| (cell_key(x, y), e)).collect();
        keys.sort();
        let mut seen = vec![];
        each_around(&keys, [5.5, 7.5], 1.0, f64::NAN, |b| seen.push(b));
        assert_eq!(seen, vec![0, 1]);
        seen.clear();
        each_around(&keys, [5.5, 7.5], 1.0, 0.4, |b| seen.push(b));
        assert_eq!(seen, vec![0, 1], "a reach within the own cell: the own cell, not the square's (6, 7)");
    }

    #[test]
    fn the_pool_finds_the_same_pairs_across_block_edges() {
        // Several blocks of the full search and of the movers' search, on two threads.
        let mut rnd = uniform(777);
        let n = 3 * BLOCK + 123;
        let (mut x, mut y): (Vec<f64>, Vec<f64>) = (0..n).map(|_| (rnd() * 1.2, rnd() * 1.2)).unzip();
        let r: Vec<f64> = (0..n).map(|_| 0.004 + 0.004 * rnd()).collect();
        // Wide elements enough for several blocks of their own search too.
        let m = |e: usize| if e.is_multiple_of(5) { 0.02 } else { 0.001 };
        assert!(n / 5 > 3 * WIDE_BLOCK);
        let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build().unwrap();
        let (mut serial, mut on_pool) = (BroadPhase::default(), BroadPhase::default());
        let (mut a, mut b) = (vec![], vec![]);
        serial.pairs(|e| [x[e], y[e]], &r, m, None, false, &mut a);
        pool.install(|| on_pool.pairs(|e| [x[e], y[e]], &r, m, None, true, &mut b));
        assert_eq!(a, b);
        assert_eq!(a, brute(&x, &y, &r, m));
        let movers: Vec<u32> = (0..n as u32).filter(|e| e % 5 == 1).collect();
        assert!(movers.len() > 3 * MOVERS_BLOCK);
        let mut is_mover = vec![false; n];
        movers.iter().for_each(|&e| is_mover[e as usize] = true);
        for &e in &movers {
            x[e as usize] += 0.01 * rnd() - 0.005;
            y[e as usize] += 0.01 * rnd() - 0.005;
        }
        let widest = (0..n).map(|e| r[e] + m(e)).fold(0.0, f64::max);
        serial.requery(&movers, &is_mover, |e| [x[e], y[e]], &r, m, widest, false, &mut a);
        pool.install(|| on_pool.requery(&movers, &is_mover, |e| [x[e], y[e]], &r, m, widest, true, &mut b));
        assert_eq!(a, b);
        assert_eq!(serial.keyed, on_pool.keyed);
        // The movers' keys merged in are the full sort of every element's key.
        let mut resorted = serial.keyed.clone();
        resorted.sort();
        assert_eq!(serial.keyed, resorted);
        let brute_all = brute(&x, &y, &r, m);
        let moved: Vec<_> = brute_all.iter().copied().filter(|&(i, j)| is_mover[i as usize] || is_mover[j as usize]).collect();
        assert_eq!(a, moved);
    }
}
