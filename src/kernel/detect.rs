//! Broad phase: every pair of elements closer than their radii plus a margin.
//!
//! Sort-based cell grid: elements are sorted by the key of their cell (row-major), and each
//! element looks up the forward half of its 3×3 neighbourhood with binary searches. No grid
//! array is allocated, so elements that fly arbitrarily far away cost nothing extra and are
//! still found (cell coordinates are clamped to i32; the final test is the exact distance, so
//! clamping can only add candidates, never lose a pair). The result is sorted by (i, j) and is
//! a pure function of the positions: deterministic.

/// Reusable buffers for the broad phase (no allocation once warmed up).
#[derive(Debug, Default, Clone)]
pub struct BroadPhase {
    keyed: Vec<(u64, u32)>,
    pairs: Vec<u64>,
}

/// Cell coordinates are clamped to this range, so that a neighbour (±1) never aliases a cell.
const CELL_LIMIT: i64 = i32::MAX as i64 - 2;

fn cell_key(cx: i64, cy: i64) -> u64 {
    let offset = |c: i64| (c - i32::MIN as i64) as u64;
    (offset(cy) << 32) | offset(cx)
}

impl BroadPhase {
    /// All pairs (i < j) with |c_i − c_j| < r_i + r_j + `margin_m`, sorted by (i, j), written
    /// to `out` (cleared first); `centre(e)` gives element e's centre [x m, y m] for e < r.len().
    pub fn pairs(&mut self, centre: impl Fn(usize) -> [f64; 2], r: &[f64], margin_m: f64, out: &mut Vec<(u32, u32)>) {
        out.clear();
        let n = r.len();
        if n < 2 {
            return;
        }
        let r_max = r.iter().copied().fold(0.0, f64::max);
        let cell = 2.0 * r_max + margin_m;
        let inv = 1.0 / cell;
        self.keyed.clear();
        let cell_of = |e: usize| {
            let c = centre(e);
            let clamp = |v: f64| ((v * inv).floor() as i64).clamp(-CELL_LIMIT, CELL_LIMIT);
            (clamp(c[0]), clamp(c[1]))
        };
        self.keyed.extend((0..n).map(|e| {
            let (cx, cy) = cell_of(e);
            (cell_key(cx, cy), e as u32)
        }));
        self.keyed.sort_unstable();
        self.pairs.clear();
        let keys = &self.keyed;
        let lower = |k: u64| keys.partition_point(|&(kk, _)| kk < k);
        let upper = |k: u64| keys.partition_point(|&(kk, _)| kk <= k);
        for s in 0..n {
            let (_, a) = keys[s];
            let a = a as usize;
            let (cx, cy) = cell_of(a);
            let ca = centre(a);
            // Forward half-stencil: rest of own cell and (cx+1, cy), then the three cells above.
            let same_row_end = upper(cell_key(cx + 1, cy));
            let above_start = lower(cell_key(cx - 1, cy + 1));
            let above_end = upper(cell_key(cx + 1, cy + 1));
            for &(_, b) in keys[s + 1..same_row_end].iter().chain(&keys[above_start..above_end]) {
                let b = b as usize;
                let cb = centre(b);
                let (dx, dy) = (cb[0] - ca[0], cb[1] - ca[1]);
                let reach = r[a] + r[b] + margin_m;
                if dx * dx + dy * dy < reach * reach {
                    let (i, j) = if a < b { (a, b) } else { (b, a) };
                    self.pairs.push(((i as u64) << 32) | j as u64);
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

    fn brute(x: &[f64], y: &[f64], r: &[f64], m: f64) -> Vec<(u32, u32)> {
        let mut v = vec![];
        for i in 0..x.len() {
            for j in i + 1..x.len() {
                let reach = r[i] + r[j] + m;
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
        bp.pairs(|e| [x[e], y[e]], &r, 0.002, &mut out);
        assert_eq!(out, brute(&x, &y, &r, 0.002));
        assert!(out.contains(&(3, 7)));
    }
}
