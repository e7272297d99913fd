//! A timing prototype, not part of demsweep ([6/6], README "The one-thread beam on this
//! machine"): what the bond lanes would gain if a group's four contacts were four consecutive
//! elements of a lattice row and their four neighbours in one direction, so that positions,
//! velocities and sums are read and written as whole rows instead of gathered element by
//! element. Run by `scripts/row_groups_prototype.sh`.
//!
//! One all-bonded close-packed block (no breakage, undamped, a random initial velocity field),
//! the bond law's elastic branch (normal spring, incremental shear spring, the plateau tests)
//! on four AVX lanes written out here as `kernel::groups` takes it, central differences. Variants:
//! - `gathered`: demsweep's way — the (i, j)-sorted list in groups of four consecutive
//!   contacts, rows gathered by index, the sums added contact by contact with i's running sum
//!   held (`forces::Serial`);
//! - `gathered-ahead`: the same with the geometry made eight groups ahead (`forces::each`);
//! - `rows`: the bonds of a row and a direction (east, up-left, up-right) four at a time, their
//!   history in columns by direction, rows loaded and added three vectors at a time;
//! - `rows-scalar-sums`: `rows` with the sums added lane by lane (what the contiguous loads
//!   alone give);
//! - `rows-then-list`: demsweep's bits kept the simple way — the forces by rows with the history
//!   left in the list, each stored at its contact's place, then the sums added in the list's
//!   order as `gathered` adds them.
//! `rows` adds each element's forces in another order than the list's, so its positions agree
//! with `gathered`'s to rounding, not bitwise (printed; the lane-by-lane sums happen to keep the
//! list's order on this lattice: an element's first two terms, its j parts from the row below,
//! commute). What neither has of demsweep's kernel (other contact kinds, the
//! dissipation ledger, the motion stage's checks) costs the same in both.
use std::arch::x86_64::*;
use std::time::Instant;

/// Element radius, m.
const RAD_M: f64 = 1e-3;
/// Bond springs, N/m.
const KN_N_PER_M: f64 = 1e8;
const KT_N_PER_M: f64 = KN_N_PER_M / 3.0;
/// Time step, s (about a third of the stability bound).
const DT_S: f64 = 2e-7;
const LEVER: f64 = 0.5;
/// Plateaus out of reach and no plastic opening allowed: every group stays elastic.
const PLATEAU_N: f64 = 1e30;

#[derive(Clone, Copy)]
struct Contact {
    i: u32,
    j: u32,
    class: u16,
    bond: u8,
    rest_m: f64,
    ut_m: f64,
    dp_m: f64,
}

#[derive(Clone)]
struct State {
    pos: Vec<[f64; 3]>,
    vel: Vec<[f64; 3]>,
    sums: Vec<[f64; 3]>,
    inv_mass: Vec<[f64; 3]>,
}

/// Rows of `cols` elements, odd rows shifted by a radius; element (r, c) is r·cols + c.
struct Lattice {
    cols: usize,
    rows: usize,
}

impl Lattice {
    /// Row r's bonds in direction d (0 east, 1 up-left, 2 up-right): (j − i, first column,
    /// end column).
    fn run(&self, r: usize, d: usize) -> Option<(usize, usize, usize)> {
        let c = self.cols;
        match d {
            0 => Some((1, 0, c - 1)),
            _ if r + 1 >= self.rows => None,
            1 => Some(if r % 2 == 0 { (c - 1, 1, c) } else { (c, 0, c) }),
            _ => Some(if r % 2 == 0 { (c, 0, c) } else { (c + 1, 0, c - 1) }),
        }
    }

    /// Every row's runs of bonds in row order, directions in turn: (direction, j − i, the run's
    /// first i, its number of bonds).
    fn runs(&self) -> impl Iterator<Item = (usize, usize, usize, usize)> + '_ {
        (0..self.rows).flat_map(move |r| (0..3).filter_map(move |d| self.run(r, d).map(|(off, c0, c1)| (d, off, r * self.cols + c0, c1 - c0))))
    }
}

/// Force `f` = (fx, fy, ti, tj) added to i and j: (fx, fy, ti) and (−fx, −fy, tj).
fn add_pair(sums: &mut [[f64; 3]], i: usize, j: usize, f: [f64; 4]) {
    let si = &mut sums[i];
    si[0] += f[0];
    si[1] += f[1];
    si[2] += f[2];
    let sj = &mut sums[j];
    sj[0] -= f[0];
    sj[1] -= f[1];
    sj[2] += f[3];
}

fn uniform(s: &mut u64) -> f64 {
    *s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
    ((*s >> 11) as f64) / ((1u64 << 53) as f64) - 0.5
}

/// The block and its bond list sorted by (i, j).
fn build(l: &Lattice) -> (State, Vec<Contact>) {
    let n = l.cols * l.rows;
    let (mut pos, mut vel) = (vec![[0.0; 3]; n], vec![[0.0; 3]; n]);
    let mut seed = 12345u64;
    for r in 0..l.rows {
        for c in 0..l.cols {
            let e = r * l.cols + c;
            pos[e] = [2.0 * RAD_M * c as f64 + if r % 2 == 1 { RAD_M } else { 0.0 }, 3f64.sqrt() * RAD_M * r as f64, 0.0];
            vel[e] = [0.1 * uniform(&mut seed), 0.1 * uniform(&mut seed), 10.0 * uniform(&mut seed)];
        }
    }
    let m = 2400.0 * std::f64::consts::PI * RAD_M * RAD_M * 1e-2;
    let inv_mass = vec![[1.0 / m, 1.0 / m, 1.0 / (0.5 * m * RAD_M * RAD_M)]; n];
    let mut list = Vec::new();
    for r in 0..l.rows {
        for c in 0..l.cols {
            let e = r * l.cols + c;
            let mut js: Vec<usize> = (0..3).filter_map(|d| l.run(r, d).filter(|&(_, c0, c1)| (c0..c1).contains(&c)).map(|(off, _, _)| e + off)).collect();
            js.sort();
            list.extend(js.into_iter().map(|j| Contact { i: e as u32, j: j as u32, class: 0, bond: 0, rest_m: 2.0 * RAD_M, ut_m: 0.0, dp_m: 0.0 }));
        }
    }
    (State { pos, vel, sums: vec![[0.0; 3]; n], inv_mass }, list)
}

/// Central differences over the flat components, the sums zeroed as read (`integrate`).
fn motion(st: &mut State) {
    let n = st.pos.len() * 3;
    let (s, v, x, im) = (st.sums.as_flattened_mut(), st.vel.as_flattened_mut(), st.pos.as_flattened_mut(), st.inv_mass.as_flattened());
    let (s, v, x, im) = (&mut s[..n], &mut v[..n], &mut x[..n], &im[..n]);
    for q in 0..n {
        let f = std::mem::take(&mut s[q]);
        let vn = v[q] + DT_S * f * im[q] + 0.0;
        v[q] = vn;
        x[q] += DT_S * vn;
    }
}

/// One bond, scalar (the rows' tails, the list's tail).
fn one(pi: [f64; 3], pj: [f64; 3], vi: [f64; 3], vj: [f64; 3], rest_m: f64, ut_m: f64, dp_m: f64) -> ([f64; 4], f64) {
    let (dx, dy) = (pj[0] - pi[0], pj[1] - pi[1]);
    let d = (dx * dx + dy * dy).sqrt();
    let inv = 1.0 / d;
    let (nx, ny) = (dx * inv, dy * inv);
    let (dvx, dvy) = (vj[0] - vi[0], vj[1] - vi[1]);
    let (li, lj) = (d * LEVER, d * LEVER);
    let vt = -dvx * ny + dvy * nx - li * vi[2] - lj * vj[2];
    let f_n = KN_N_PER_M * (d - rest_m - dp_m);
    let ut = ut_m + vt * DT_S;
    let f_t = KT_N_PER_M * ut;
    ([f_n * nx - f_t * ny, f_n * ny + f_t * nx, li * f_t, lj * f_t], ut)
}

/// Four bonds' geometry: [d, nx, ny].
#[inline(always)]
unsafe fn geometry(xi: __m256d, yi: __m256d, xj: __m256d, yj: __m256d) -> [__m256d; 3] {
    unsafe {
        let (dx, dy) = (_mm256_sub_pd(xj, xi), _mm256_sub_pd(yj, yi));
        let d = _mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)));
        let inv = _mm256_div_pd(_mm256_set1_pd(1.0), d);
        [d, _mm256_mul_pd(dx, inv), _mm256_mul_pd(dy, inv)]
    }
}

/// Four bonds' forces (fx, fy, ti, tj), new shear springs, and whether all stayed elastic.
struct Lanes {
    f: [__m256d; 4],
    ut: __m256d,
    elastic: bool,
}

/// The elastic branch at geometry `g`, velocities (vx, vy, ω) of i and j, history (rest, ut, dp).
#[inline(always)]
unsafe fn law(g: [__m256d; 3], vi: (__m256d, __m256d, __m256d), vj: (__m256d, __m256d, __m256d), rest: __m256d, ut: __m256d, dp: __m256d) -> Lanes {
    unsafe {
        let splat = _mm256_set1_pd;
        let [d, nx, ny] = g;
        let (dvx, dvy) = (_mm256_sub_pd(vj.0, vi.0), _mm256_sub_pd(vj.1, vi.1));
        let (li, lj) = (_mm256_mul_pd(d, splat(LEVER)), _mm256_mul_pd(d, splat(LEVER)));
        let neg_dvx = _mm256_xor_pd(dvx, splat(-0.0));
        let vt = _mm256_sub_pd(_mm256_sub_pd(_mm256_add_pd(_mm256_mul_pd(neg_dvx, ny), _mm256_mul_pd(dvy, nx)), _mm256_mul_pd(li, vi.2)), _mm256_mul_pd(lj, vj.2));
        let f_n = _mm256_mul_pd(splat(KN_N_PER_M), _mm256_sub_pd(_mm256_sub_pd(d, rest), dp));
        let ut = _mm256_add_pd(ut, _mm256_mul_pd(vt, splat(DT_S)));
        let f_t = _mm256_mul_pd(splat(KT_N_PER_M), ut);
        let below = _mm256_cmp_pd::<_CMP_LE_OQ>(f_n, splat(PLATEAU_N));
        let capped = _mm256_cmp_pd::<_CMP_LE_OQ>(_mm256_andnot_pd(splat(-0.0), f_t), splat(PLATEAU_N));
        let holds = _mm256_cmp_pd::<_CMP_NGT_UQ>(dp, splat(0.0));
        let el = _mm256_and_pd(_mm256_and_pd(below, capped), holds);
        let fx = _mm256_sub_pd(_mm256_mul_pd(f_n, nx), _mm256_mul_pd(f_t, ny));
        let fy = _mm256_add_pd(_mm256_mul_pd(f_n, ny), _mm256_mul_pd(f_t, nx));
        Lanes { f: [fx, fy, _mm256_mul_pd(li, f_t), _mm256_mul_pd(lj, f_t)], ut, elastic: _mm256_testc_pd(el, _mm256_castsi256_pd(_mm256_set1_epi64x(-1))) != 0 }
    }
}

#[inline(always)]
unsafe fn out(v: __m256d) -> [f64; 4] {
    let mut a = [0.0; 4];
    unsafe { _mm256_storeu_pd(a.as_mut_ptr(), v) };
    a
}

/// The first two components of four rows, by index (`geometry::xy`).
#[inline(always)]
unsafe fn xy(a: &[[f64; 3]], rows: [usize; 4]) -> (__m256d, __m256d) {
    unsafe {
        let pair = |r: usize| _mm_loadu_pd(a[r].as_ptr());
        let ac = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(pair(rows[0])), pair(rows[2]));
        let bd = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(pair(rows[1])), pair(rows[3]));
        (_mm256_unpacklo_pd(ac, bd), _mm256_unpackhi_pd(ac, bd))
    }
}

macro_rules! lanes {
    ($g:expr, |$c:ident| $e:expr) => {
        _mm256_set_pd({ let $c = &$g[3]; $e }, { let $c = &$g[2]; $e }, { let $c = &$g[1]; $e }, { let $c = &$g[0]; $e })
    };
}

/// i's running sum held while i repeats, j's added in memory (`forces::Serial`).
struct Serial {
    run_i: u32,
    acc: [f64; 3],
}

impl Serial {
    #[inline(always)]
    fn add(&mut self, sums: &mut [[f64; 3]], i: u32, j: u32, f: [f64; 4]) {
        if i != self.run_i {
            if self.run_i != u32::MAX {
                sums[self.run_i as usize] = self.acc;
            }
            self.run_i = i;
            self.acc = sums[i as usize];
        }
        self.acc[0] += f[0];
        self.acc[1] += f[1];
        self.acc[2] += f[2];
        let s = &mut sums[j as usize];
        s[0] -= f[0];
        s[1] -= f[1];
        s[2] += f[3];
    }
}

/// The contact stage demsweep's way; `AHEAD`: the geometry eight groups ahead. Returns the
/// groups that left the elastic branch (none here).
#[target_feature(enable = "avx")]
unsafe fn gathered<const AHEAD: bool>(st: &mut State, list: &mut [Contact]) -> usize {
    let (pos, vel, sums) = (&st.pos[..], &st.vel[..st.pos.len()], &mut st.sums[..]);
    let mut serial = Serial { run_i: u32::MAX, acc: [0.0; 3] };
    let mut left = 0;
    let whole = list.len() / 4 * 4;
    let mut geos = [[_mm256_setzero_pd(); 3]; 8];
    let (mut next, mut ahead) = (0, 0);
    let mut from = 0;
    while from < whole {
        let geo = if AHEAD {
            if next == ahead {
                ahead = ((whole - from) / 4).min(8);
                for (q, g) in geos.iter_mut().enumerate().take(ahead) {
                    let c: &[Contact; 4] = (&list[from + 4 * q..from + 4 * q + 4]).try_into().unwrap();
                    let ((xi, yi), (xj, yj)) = unsafe { (xy(pos, c.map(|c| c.i as usize)), xy(pos, c.map(|c| c.j as usize))) };
                    *g = unsafe { geometry(xi, yi, xj, yj) };
                }
                next = 0;
            }
            next += 1;
            geos[next - 1]
        } else {
            let c: &[Contact; 4] = (&list[from..from + 4]).try_into().unwrap();
            let ((xi, yi), (xj, yj)) = unsafe { (xy(pos, c.map(|c| c.i as usize)), xy(pos, c.map(|c| c.j as usize))) };
            unsafe { geometry(xi, yi, xj, yj) }
        };
        let g: &mut [Contact; 4] = (&mut list[from..from + 4]).try_into().unwrap();
        from += 4;
        let k0 = g[0].class;
        if ((g[1].class ^ k0) | (g[2].class ^ k0) | (g[3].class ^ k0)) != 0 || (g[0].bond | g[1].bond | g[2].bond | g[3].bond) != 0 {
            left += 1;
            continue;
        }
        unsafe {
            let (vxi, vyi) = xy(vel, g.map(|c| c.i as usize));
            let (vxj, vyj) = xy(vel, g.map(|c| c.j as usize));
            let (wi, wj) = (lanes!(g, |c| vel[c.i as usize][2]), lanes!(g, |c| vel[c.j as usize][2]));
            let o = law(geo, (vxi, vyi, wi), (vxj, vyj, wj), lanes!(g, |c| c.rest_m), lanes!(g, |c| c.ut_m), lanes!(g, |c| c.dp_m));
            if !o.elastic {
                left += 1;
                continue;
            }
            let ([fx, fy, ti, tj], ut) = (o.f.map(|v| out(v)), out(o.ut));
            for (l, c) in g.iter_mut().enumerate() {
                c.ut_m = ut[l];
                serial.add(sums, c.i, c.j, [fx[l], fy[l], ti[l], tj[l]]);
            }
        }
    }
    for c in &mut list[whole..] {
        let (i, j) = (c.i as usize, c.j as usize);
        let (f, ut) = one(pos[i], pos[j], vel[i], vel[j], c.rest_m, c.ut_m, c.dp_m);
        c.ut_m = ut;
        serial.add(sums, c.i, c.j, f);
    }
    if serial.run_i != u32::MAX {
        sums[serial.run_i as usize] = serial.acc;
    }
    left
}

/// Four `[x, y, θ]` rows from three vectors of their twelve components, in lanes
/// (`integrate::columns`).
#[inline(always)]
unsafe fn columns(a: __m256d, b: __m256d, c: __m256d) -> (__m256d, __m256d, __m256d) {
    unsafe {
        let xy = _mm256_permute2f128_pd::<0x30>(a, b);
        let tx = _mm256_permute2f128_pd::<0x21>(a, c);
        let yt = _mm256_permute2f128_pd::<0x30>(b, c);
        (_mm256_blend_pd::<0b1010>(xy, tx), _mm256_shuffle_pd::<0b0101>(xy, yt), _mm256_blend_pd::<0b1010>(tx, yt))
    }
}

/// The inverse of [`columns`]: lanes (x, y, θ) back to three vectors of four rows.
#[inline(always)]
unsafe fn rows(x: __m256d, y: __m256d, t: __m256d) -> [__m256d; 3] {
    unsafe {
        let xy_lo = _mm256_unpacklo_pd(x, y);
        let tx = _mm256_blend_pd::<0b1010>(t, x);
        let yt = _mm256_shuffle_pd::<0b1111>(y, t);
        [_mm256_permute2f128_pd::<0x20>(xy_lo, tx), _mm256_permute2f128_pd::<0x30>(yt, xy_lo), _mm256_permute2f128_pd::<0x31>(tx, yt)]
    }
}

#[inline(always)]
unsafe fn load_rows(a: &[[f64; 3]], r: usize) -> (__m256d, __m256d, __m256d) {
    let p = a[r..r + 4].as_flattened().as_ptr();
    unsafe { columns(_mm256_loadu_pd(p), _mm256_loadu_pd(p.add(4)), _mm256_loadu_pd(p.add(8))) }
}

#[inline(always)]
unsafe fn add_rows(a: &mut [[f64; 3]], r: usize, v: [__m256d; 3]) {
    let p = a[r..r + 4].as_flattened_mut().as_mut_ptr();
    for (k, v) in v.into_iter().enumerate() {
        unsafe { _mm256_storeu_pd(p.add(4 * k), _mm256_add_pd(_mm256_loadu_pd(p.add(4 * k)), v)) };
    }
}

/// Bond history by direction, indexed by i (columns).
#[derive(Clone)]
struct History {
    rest_m: [Vec<f64>; 3],
    ut_m: [Vec<f64>; 3],
    dp_m: [Vec<f64>; 3],
}

/// The contact stage by rows and directions; `VECTOR_SUMS`: the sums added as whole rows, else
/// lane by lane.
#[target_feature(enable = "avx")]
unsafe fn by_rows<const VECTOR_SUMS: bool>(st: &mut State, l: &Lattice, h: &mut History) -> usize {
    let mut left = 0;
    let neg = _mm256_set1_pd(-0.0);
    for (d, off, first, n) in l.runs() {
        let whole = first + n / 4 * 4;
        for i in (first..whole).step_by(4) {
            let j = i + off;
            unsafe {
                let (xi, yi, _) = load_rows(&st.pos, i);
                let (xj, yj, _) = load_rows(&st.pos, j);
                let (vi, vj) = (load_rows(&st.vel, i), load_rows(&st.vel, j));
                let (rest, dp, ut) = (&h.rest_m[d][i..i + 4], &h.dp_m[d][i..i + 4], &mut h.ut_m[d][i..i + 4]);
                let o = law(geometry(xi, yi, xj, yj), vi, vj, _mm256_loadu_pd(rest.as_ptr()), _mm256_loadu_pd(ut.as_ptr()), _mm256_loadu_pd(dp.as_ptr()));
                if !o.elastic {
                    left += 1;
                    continue;
                }
                _mm256_storeu_pd(ut.as_mut_ptr(), o.ut);
                let [fx, fy, ti, tj] = o.f;
                if VECTOR_SUMS {
                    add_rows(&mut st.sums, i, rows(fx, fy, ti));
                    add_rows(&mut st.sums, j, rows(_mm256_xor_pd(fx, neg), _mm256_xor_pd(fy, neg), tj));
                } else {
                    let (fx, fy, ti, tj) = (out(fx), out(fy), out(ti), out(tj));
                    for q in 0..4 {
                        add_pair(&mut st.sums, i + q, j + q, [fx[q], fy[q], ti[q], tj[q]]);
                    }
                }
            }
        }
        for i in whole..first + n {
            let (f, ut) = one(st.pos[i], st.pos[i + off], st.vel[i], st.vel[i + off], h.rest_m[d][i], h.ut_m[d][i], h.dp_m[d][i]);
            h.ut_m[d][i] = ut;
            add_pair(&mut st.sums, i, i + off, f);
        }
    }
    left
}

/// The contact stage in two passes that keep demsweep's bits: the forces by rows and directions
/// (history read from and written to the list, each force stored at its contact's place), then
/// the sums in the list's order as [`gathered`] adds them. `slot[d][i]`: the list index of i's
/// bond in direction d.
#[target_feature(enable = "avx")]
unsafe fn rows_then_list(st: &mut State, l: &Lattice, list: &mut [Contact], slot: &[Vec<u32>; 3], buf: &mut [[f64; 4]]) -> usize {
    let mut left = 0;
    for (d, off, first, n) in l.runs() {
        let whole = first + n / 4 * 4;
        for i in (first..whole).step_by(4) {
            let j = i + off;
            let k: [usize; 4] = std::array::from_fn(|q| slot[d][i + q] as usize);
            let g = k.map(|k| list[k]);
            unsafe {
                let (xi, yi, _) = load_rows(&st.pos, i);
                let (xj, yj, _) = load_rows(&st.pos, j);
                let (vi, vj) = (load_rows(&st.vel, i), load_rows(&st.vel, j));
                let o = law(geometry(xi, yi, xj, yj), vi, vj, lanes!(g, |c| c.rest_m), lanes!(g, |c| c.ut_m), lanes!(g, |c| c.dp_m));
                if !o.elastic {
                    left += 1;
                    continue;
                }
                let ([fx, fy, ti, tj], ut) = (o.f.map(|v| out(v)), out(o.ut));
                for q in 0..4 {
                    list[k[q]].ut_m = ut[q];
                    buf[k[q]] = [fx[q], fy[q], ti[q], tj[q]];
                }
            }
        }
        for i in whole..first + n {
            let k = slot[d][i] as usize;
            let b = &mut list[k];
            let (f, ut) = one(st.pos[i], st.pos[i + off], st.vel[i], st.vel[i + off], b.rest_m, b.ut_m, b.dp_m);
            b.ut_m = ut;
            buf[k] = f;
        }
    }
    let sums = &mut st.sums[..];
    let mut serial = Serial { run_i: u32::MAX, acc: [0.0; 3] };
    for (c, f) in list.iter().zip(&*buf) {
        serial.add(sums, c.i, c.j, *f);
    }
    if serial.run_i != u32::MAX {
        sums[serial.run_i as usize] = serial.acc;
    }
    left
}

const VARIANTS: [&str; 5] = ["gathered", "gathered-ahead", "rows", "rows-scalar-sums", "rows-then-list"];

/// What the two-pass variant needs besides the list: each bond's place, and the forces.
struct Places {
    slot: [Vec<u32>; 3],
    buf: Vec<[f64; 4]>,
}

/// One step of variant `v` (contact stage, then motion); the groups that left the lanes.
fn step(v: usize, st: &mut State, list: &mut [Contact], l: &Lattice, h: &mut History, p: &mut Places) -> usize {
    // SAFETY: `main` checked that the processor has AVX.
    let left = unsafe {
        match v {
            0 => gathered::<false>(st, list),
            1 => gathered::<true>(st, list),
            2 => by_rows::<true>(st, l, h),
            3 => by_rows::<false>(st, l, h),
            _ => rows_then_list(st, l, list, &p.slot, &mut p.buf),
        }
    };
    motion(st);
    left
}

fn main() {
    assert!(is_x86_feature_detected!("avx"), "the prototype needs AVX");
    let arg = |k: usize, default: usize| std::env::args().nth(k).map(|s| s.parse().expect("a count")).unwrap_or(default);
    let (cols, rows_n, steps, rounds) = (arg(1, 120), arg(2, 100), arg(3, 500), arg(4, 7));
    let l = Lattice { cols, rows: rows_n };
    let (st0, list0) = build(&l);
    let n = st0.pos.len();
    let h0 = History { rest_m: std::array::from_fn(|_| vec![2.0 * RAD_M; n]), ut_m: std::array::from_fn(|_| vec![0.0; n]), dp_m: std::array::from_fn(|_| vec![0.0; n]) };
    let mut slot: [Vec<u32>; 3] = std::array::from_fn(|_| vec![u32::MAX; n]);
    for (k, c) in list0.iter().enumerate() {
        let (i, r) = (c.i as usize, c.i as usize / l.cols);
        let d = (0..3).find(|&d| l.run(r, d).is_some_and(|(off, _, _)| c.j as usize == i + off)).expect("a lattice bond");
        slot[d][i] = k as u32;
    }
    let mut places = Places { slot, buf: vec![[0.0; 4]; list0.len()] };
    let mut runs: Vec<(State, Vec<Contact>, History)> = VARIANTS.iter().map(|_| (st0.clone(), list0.clone(), h0.clone())).collect();
    // The variants against the first after 200 steps: the same motion to rounding.
    for (v, (st, list, h)) in runs.iter_mut().enumerate() {
        for _ in 0..200 {
            assert_eq!(step(v, st, list, &l, h, &mut places), 0, "{}: a group left the elastic branch", VARIANTS[v]);
        }
    }
    let moved = runs[0].0.pos.iter().zip(&st0.pos).map(|(p, q)| (p[0] - q[0]).abs().max((p[1] - q[1]).abs())).fold(0.0, f64::max);
    for v in 1..VARIANTS.len() {
        let diff = runs[v].0.pos.iter().zip(&runs[0].0.pos).map(|(p, q)| (p[0] - q[0]).abs().max((p[1] - q[1]).abs())).fold(0.0, f64::max);
        // Rounding of the positions themselves (up to the block's size) is the scale.
        let size = st0.pos.iter().map(|p| p[0].abs().max(p[1].abs())).fold(0.0, f64::max);
        assert!(diff < 64.0 * f64::EPSILON * size, "{} drifted from {} by {diff:e} m", VARIANTS[v], VARIANTS[0]);
        println!("{:>17}: positions within {diff:.1e} m of {}'s after 200 steps (largest displacement {moved:.2e} m)", VARIANTS[v], VARIANTS[0]);
    }
    println!("{n} elements, {} bonds; {rounds} rounds of {steps} steps, the variants in turn in each round", list0.len());
    let mut ns = vec![vec![]; VARIANTS.len()];
    for _ in 0..rounds {
        for (v, (st, list, h)) in runs.iter_mut().enumerate() {
            let t = Instant::now();
            for _ in 0..steps {
                step(v, st, list, &l, h, &mut places);
            }
            ns[v].push(t.elapsed().as_secs_f64() / (steps * list0.len()) as f64 * 1e9);
        }
    }
    let median = |mut a: Vec<f64>| {
        a.sort_by(|x, y| x.partial_cmp(y).unwrap());
        a[a.len() / 2]
    };
    println!("{:>17} {:>16} {:>20}", "variant", "ns/contact-step", "time / gathered's");
    for v in 0..VARIANTS.len() {
        let ratio = median(ns[v].iter().zip(&ns[0]).map(|(a, b)| a / b).collect());
        println!("{:>17} {:>16.2} {:>20.3}", VARIANTS[v], median(ns[v].clone()), ratio);
    }
}
