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

/// Reusable buffers for the broad phase (no allocation once warmed up).
#[derive(Debug, Default, Clone)]
pub struct BroadPhase {
    keyed: Vec<(u64, u32)>,
    pairs: Vec<u64>,
    wide: Vec<u32>,
}

/// Cell coordinates are clamped to this range, so that a neighbour (±k) never aliases a cell.
const CELL_LIMIT: i64 = i32::MAX as i64 - 1024;

fn cell_key(cx: i64, cy: i64) -> u64 {
    let offset = |c: i64| (c - i32::MIN as i64) as u64;
    (offset(cy) << 32) | offset(cx)
}

impl BroadPhase {
    /// All pairs (i < j) with |c_i − c_j| < r_i + r_j + m_i + m_j, sorted by (i, j), written to
    /// `out` (cleared first); `centre(e)` gives element e's centre [x m, y m] for e < r.len(),
    /// `margin(e)` its margin, m.
    pub fn pairs(&mut self, centre: impl Fn(usize) -> [f64; 2], r: &[f64], margin: impl Fn(usize) -> f64, out: &mut Vec<(u32, u32)>) {
        out.clear();
        let n = r.len();
        if n < 2 {
            return;
        }
        // Cells are sized for the usual reach: the largest radius plus the smallest margin
        // (most elements have it).
        let r_max = r.iter().copied().fold(0.0, f64::max);
        let m_min = (0..n).map(&margin).fold(f64::INFINITY, f64::min);
        let usual = r_max + m_min;
        let cell = 2.0 * usual;
        let inv = 1.0 / cell;
        let clamp = |v: f64| ((v * inv).floor() as i64).clamp(-CELL_LIMIT, CELL_LIMIT);
        let cell_of = |c: [f64; 2]| (clamp(c[0]), clamp(c[1]));
        self.keyed.clear();
        self.wide.clear();
        for e in 0..n {
            let (cx, cy) = cell_of(centre(e));
            self.keyed.push((cell_key(cx, cy), e as u32));
            if r[e] + margin(e) > usual {
                self.wide.push(e as u32);
            }
        }
        self.keyed.sort_unstable();
        self.pairs.clear();
        let keys = &self.keyed;
        let lower = |k: u64| keys.partition_point(|&(kk, _)| kk < k);
        let upper = |k: u64| keys.partition_point(|&(kk, _)| kk <= k);
        let is_wide = |e: usize| r[e] + margin(e) > usual;
        let test = |a: usize, b: usize, ca: [f64; 2], pairs: &mut Vec<u64>| {
            let cb = centre(b);
            let (dx, dy) = (cb[0] - ca[0], cb[1] - ca[1]);
            let reach = (r[a] + r[b]) + (margin(a) + margin(b));
            if dx * dx + dy * dy < reach * reach {
                let (i, j) = if a < b { (a, b) } else { (b, a) };
                pairs.push(((i as u64) << 32) | j as u64);
            }
        };
        // Usual–usual pairs: forward half-stencil (rest of own cell and (cx+1, cy), then the
        // three cells above); two usual reaches never exceed one cell.
        for s in 0..n {
            let (_, a) = keys[s];
            let a = a as usize;
            if is_wide(a) {
                continue;
            }
            let ca = centre(a);
            let (cx, cy) = cell_of(ca);
            let same_row_end = upper(cell_key(cx + 1, cy));
            let above_start = lower(cell_key(cx - 1, cy + 1));
            let above_end = upper(cell_key(cx + 1, cy + 1));
            for &(_, b) in keys[s + 1..same_row_end].iter().chain(&keys[above_start..above_end]) {
                if !is_wide(b as usize) {
                    test(a, b as usize, ca, &mut self.pairs);
                }
            }
        }
        // Wide elements: every cell within their reach plus the widest one; a pair of two wide
        // elements is taken once, from the smaller index.
        let widest = self.wide.iter().map(|&e| r[e as usize] + margin(e as usize)).fold(usual, f64::max);
        for &a in &self.wide {
            let a = a as usize;
            let ca = centre(a);
            let (cx, cy) = cell_of(ca);
            let k = ((r[a] + margin(a) + widest) * inv).ceil() as i64;
            for y in cy - k..=cy + k {
                let (from, to) = (lower(cell_key(cx - k, y)), upper(cell_key(cx + k, y)));
                for &(_, b) in &keys[from..to] {
                    let b = b as usize;
                    if b != a && (!is_wide(b) || a < b) {
                        test(a, b, ca, &mut self.pairs);
                    }
                }
            }
        }
        self.pairs.sort_unstable();
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

    #[test]
    fn matches_brute_force_including_far_away_elements() {
        let mut s = 12345u64;
        let mut rnd = || {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (s >> 11) as f64 / (1u64 << 53) as f64
        };
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
        bp.pairs(|e| [x[e], y[e]], &r, |_| 0.001, &mut out);
        assert_eq!(out, brute(&x, &y, &r, |_| 0.001));
        assert!(out.contains(&(3, 7)));
        // Per-element margins, some elements reaching several cells further than the rest.
        let m = |e: usize| if e % 17 == 0 { 0.03 + 0.001 * (e % 5) as f64 } else { 0.0005 + 0.0001 * (e % 3) as f64 };
        bp.pairs(|e| [x[e], y[e]], &r, m, &mut out);
        assert_eq!(out, brute(&x, &y, &r, m));
    }
}
