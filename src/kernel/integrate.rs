//! Stage 2 of a step, element motion: take each element's contact forces as stage 1 summed
//! them (in a fixed order: bitwise the same for any thread count), add loads and gravity, and
//! advance by central differences with the mass-proportional half of Rayleigh
//! damping, C = αM:
//!
//!   v(n+½) = [(1 − αΔt/2) v(n−½) + Δt F(n)/m] / (1 + αΔt/2),   x(n+1) = x(n) + Δt v(n+½).
//!
//! The damping term is centred, which keeps the update explicit (M is diagonal) and leaves the
//! stability limit 2/ω untouched; only the stiffness-proportional half costs stability
//! (see `stability`). The same pass watches for blow-up and measures how far elements moved
//! since the last neighbour rebuild.

use super::contacts::Contacts;
use super::lanes::{self, Lanes, Mask, Real};
use super::state::Elements;

/// Elements per chunk (fixed, for deterministic partial sums; the schedule files its records
/// by it).
pub const CHUNK: usize = super::exec::MOTION_CHUNK;

/// Parameters of the motion stage.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct MotionParams {
    /// Time step Δt, s.
    pub dt_s: f64,
    /// Mass-proportional Rayleigh coefficient α, 1/s.
    pub alpha_per_s: f64,
    /// Gravity [gx, gy], m/s².
    pub gravity_mps2: [f64; 2],
    /// Speed above which the state is declared blown up, m/s (applied to |v| + |ω| r).
    pub speed_limit_mps: f64,
}

/// What one chunk of the motion stage reports.
#[derive(Debug, Clone, Copy)]
pub struct MotionReport {
    /// Energy removed by the mass-proportional damping, J.
    pub mass_damping_j: f64,
    /// Work of loads, gravity and prescribed motions on the model, J.
    pub external_j: f64,
    /// Some element drifted further than its neighbour margin since the last rebuild.
    pub drifted: bool,
    /// First element whose state is non-finite or too fast (usize::MAX: none).
    pub first_bad: usize,
}

impl Default for MotionReport {
    fn default() -> Self {
        MotionReport { mass_damping_j: 0.0, external_j: 0.0, drifted: false, first_bad: usize::MAX }
    }
}

impl MotionReport {
    /// Combine chunk reports (in chunk order).
    pub fn merge(&mut self, o: &MotionReport) {
        self.mass_damping_j += o.mass_damping_j;
        self.external_j += o.external_j;
        self.drifted |= o.drifted;
        self.first_bad = self.first_bad.min(o.first_bad);
    }
}

/// Per-step inputs: forces of load groups per sharing element, velocities of motion groups,
/// and (when mass damping spares rigid motion) each body's rigid-body velocity field.
#[derive(Debug, Clone, Copy)]
pub struct Drive<'a> {
    /// Per load group (index g − 1 for element load g), force per element [N, N].
    pub load_force_n: &'a [[f64; 2]],
    /// Per motion group, velocity [m/s, m/s, rad/s] over this step.
    pub motion_velocity: &'a [[f64; 3]],
    /// Per body, [Vx m/s, Vy m/s, Ω rad/s, cx m, cy m]: velocity of the centre of mass, rigid
    /// angular velocity and centre of mass. Empty: damping acts on absolute velocities.
    pub rigid_frame: &'a [[f64; 5]],
}

/// Rigid-body velocity of each body from its free elements' momenta: V = P/M and
/// Ω = L/J about the centre of mass, written to `out` ([Vx, Vy, Ω, cx, cy] per body).
/// `acc` is scratch space (reused between calls: no allocation in the step loop).
pub fn rigid_frames(el: &Elements, pos: &[[f64; 3]], vel: &[[f64; 3]], bodies: usize, out: &mut Vec<[f64; 5]>, acc: &mut Vec<[f64; 5]>) {
    // Per body: M, Mx, My, Px, Py; then L, J in the first two slots.
    acc.clear();
    acc.resize(bodies, [0.0; 5]);
    for e in 0..el.len() {
        if el.is_kinematic(e) {
            continue;
        }
        let (m, b) = (el.mass[e], el.body[e] as usize);
        let (p, v) = (pos[e], vel[e]);
        let a = &mut acc[b];
        a[0] += m;
        a[1] += m * p[0];
        a[2] += m * p[1];
        a[3] += m * v[0];
        a[4] += m * v[1];
    }
    out.clear();
    out.extend(acc.iter().map(|a| if a[0] > 0.0 { [a[3] / a[0], a[4] / a[0], 0.0, a[1] / a[0], a[2] / a[0]] } else { [0.0; 5] }));
    acc.iter_mut().for_each(|a| *a = [0.0; 5]);
    for e in 0..el.len() {
        if el.is_kinematic(e) {
            continue;
        }
        let b = el.body[e] as usize;
        let f = out[b];
        let (p, v) = (pos[e], vel[e]);
        let (rx, ry) = (p[0] - f[3], p[1] - f[4]);
        let m = el.mass[e];
        acc[b][0] += m * (rx * (v[1] - f[1]) - ry * (v[0] - f[0])) + el.inertia[e] * v[2];
        acc[b][1] += m * (rx * rx + ry * ry) + el.inertia[e];
    }
    for (f, l) in out.iter_mut().zip(acc.iter()) {
        f[2] = if l[1] > 0.0 { l[0] / l[1] } else { 0.0 };
    }
}

/// Generalised force on an element from its contacts' sum `summed`, its load group and
/// gravity, and the external part of it alone: ([Fx N, Fy N, T N·m], [Fx N, Fy N]).
#[inline(always)]
fn total_force<const EXTERNAL: bool>(summed: [f64; 3], mass_kg: f64, load: u16, drive: Drive<'_>, gravity: [f64; 2]) -> ([f64; 3], [f64; 2]) {
    let [fx, fy, tz] = summed;
    if !EXTERNAL {
        return ([fx, fy, tz], [0.0, 0.0]);
    }
    let (mut ex, mut ey) = (mass_kg * gravity[0], mass_kg * gravity[1]);
    if load != 0 {
        let l = drive.load_force_n[load as usize - 1];
        ex += l[0];
        ey += l[1];
    }
    ([fx + ex, fy + ey, tz], [ex, ey])
}

/// Forces of every element for the current contact forces (no motion), as `advance` would see
/// them: the stored forces added to their elements in contact order from zero, as the contact
/// stage's scatter adds them.
pub fn forces_now(el: &Elements, contacts: &Contacts, drive: Drive<'_>, gravity: [f64; 2]) -> Vec<[f64; 3]> {
    use super::exec::Sums;
    let mut sums = vec![[0.0; 3]; el.len()];
    let mut out = super::exec::Serial::new(&mut sums);
    for (c, f) in contacts.list.iter().zip(&contacts.force) {
        out.add(c, f);
    }
    out.finish();
    sums.iter().enumerate().map(|(e, &s)| total_force::<true>(s, el.mass[e], el.load[e], drive, gravity).0).collect()
}

/// What the motion stage of a model has to do, resolved once per step from its parameters
/// (as the contact law's parts are): the mass-proportional damping and the work of external
/// forces cost nothing in a scene without them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MotionParts {
    /// The mass-proportional damping acts relative to each body's rigid motion (only with
    /// `damped`: without damping there is nothing for the frame to serve).
    pub frame: bool,
    /// α > 0.
    pub damped: bool,
    /// Gravity or a load group acts (their work is booked).
    pub external: bool,
}

/// What the motion stage reads and writes in one step.
pub struct Motion<'a> {
    /// Element constants.
    pub el: &'a Elements,
    /// Positions [x m, y m, θ rad] (advanced).
    pub pos: &'a mut [[f64; 3]],
    /// Half-step velocities (advanced).
    pub vel: &'a mut [[f64; 3]],
    /// Total force per element [Fx N, Fy N, T N·m] (output).
    pub force: &'a mut [[f64; 3]],
    /// The contact forces summed per element by stage 1 (zeroed here as they are read, ready
    /// for the next step).
    pub sums: &'a mut [[f64; 3]],
    /// What of stage 1's sums is still to be added, each chunk's just before it is moved
    /// (none on one thread).
    pub pending: super::exec::Pending<'a>,
    /// Positions at the last neighbour update, m.
    pub rebuild_pos: &'a [[f64; 2]],
    /// Neighbour margins, m.
    pub margin_m: &'a [f64],
    /// Loads, prescribed velocities, rigid frames of this step.
    pub drive: Drive<'a>,
    /// Δt, α, gravity, speed limit.
    pub p: MotionParams,
    /// One report per chunk (output).
    pub partial: &'a mut [MotionReport],
    /// On the pool, in spans of chunks, one per thread (`spans`): the chunk each span starts
    /// at, from 0, then the number of chunks. None: on this thread.
    pub spans: Option<&'a [usize]>,
    /// The lanes the free elements go on, four at a time.
    pub lane_width: lanes::Width,
}

/// Advance every element by one step. `parts.frame`: the mass-proportional damping acts on the
/// velocity relative to the element's body's rigid motion (`drive.rigid_frame`), so that a
/// free body can translate and rotate undamped (quasi-static loading by dynamic relaxation).
pub fn advance(parts: MotionParts, m: Motion<'_>) {
    macro_rules! arms {
        ($($f:literal $d:literal $x:literal),*) => {
            match (parts.frame, parts.damped, parts.external) {
                $(($f, $d, $x) => advance_with::<$f, $d, $x>(m),)*
            }
        };
    }
    arms!(false false false, false false true, false true false, false true true, true false false, true false true, true true false, true true true)
}

/// The central-difference update of a velocity component, v(n+½) = c1·v(n−½) + c2·F·(1/m) +
/// c3·v_r (`c3_vr`, m/s), left to right: written once for the general loop (damped or not:
/// undamped, c1 = 1, c2 = Δt, c3·v_r = +0, so the bits are those of the damped form with
/// α = 0) and the free elements, one at a time or in lanes.
#[inline(always)]
fn velocity<R: Real>(c1: R, v: R, c2: R, f: R, inv_m: R, c3_vr: R) -> R {
    c1 * v + c2 * f * inv_m + c3_vr
}

/// x(n+1) = x(n) + Δt·v(n+½).
#[inline(always)]
fn position<R: Real>(x: R, dt: R, v: R) -> R {
    x + dt * v
}

/// |v|² + (|ω| r)² above `limit2` (m²/s²), or not finite (NaN fails every comparison: the
/// negated `<=` catches it); velocity (vx, vy) m/s, spin `w` rad/s, radius m.
#[inline(always)]
fn too_fast<R: Real>(vx: R, vy: R, w: R, radius_m: R, limit2: R) -> R::Mask {
    let spin = w.abs() * radius_m;
    !(vx * vx + vy * vy + spin * spin).le(limit2)
}

/// An element at (x, y) m further than `margin_m` from where it was at the last neighbour
/// update, (rx, ry) m.
#[inline(always)]
fn drifted<R: Real>(x: R, y: R, rx: R, ry: R, margin_m: R) -> R::Mask {
    let (dx, dy) = (x - rx, y - ry);
    (dx * dx + dy * dy).gt(margin_m * margin_m)
}

/// [`too_fast`] of one element's velocity row.
#[inline(always)]
fn row_too_fast(v: [f64; 3], radius_m: f64, limit2: f64) -> bool {
    too_fast(v[0], v[1], v[2], radius_m, limit2)
}

/// A run of free elements with no damping or external force, for [`Free::advance`].
struct Free<'a> {
    /// Δt, s.
    dt_s: f64,
    /// 1/m, 1/m, 1/I per element.
    inv_mass_3: &'a [[f64; 3]],
    /// Contact sums [Fx N, Fy N, T N·m] (zeroed as read).
    sum: &'a mut [[f64; 3]],
    /// Total forces (output).
    force: &'a mut [[f64; 3]],
    /// Half-step velocities [m/s, m/s, rad/s].
    vel: &'a mut [[f64; 3]],
    /// Positions [x m, y m, θ rad].
    pos: &'a mut [[f64; 3]],
    /// Radii, m.
    radius: &'a [f64],
    /// Positions at the last neighbour update [x m, y m].
    refs: &'a [[f64; 2]],
    /// Neighbour margins, m.
    margin: &'a [f64],
    /// Squared speed limit, m²/s².
    limit2: f64,
}

impl Free<'_> {
    /// The update, then its checks: (some element too fast, some drifted past its margin), four
    /// elements at a time on lanes `width`.
    fn advance(self, width: lanes::Width) -> (bool, bool) {
        lanes::run_as(width, self)
    }

    /// [`Free::advance`] in groups of `R::LANES` elements, the update and its checks in one
    /// pass: each group's components are updated as flat arrays (for four elements, twelve
    /// components in three values), and the checks read the new velocities and positions from
    /// the registers, put into lanes by `Real::columns`, instead of a second pass over the rows
    /// one element at a time, which cost more than the update. The same operations in the same
    /// order per component and per element, so the same
    /// bits and the same answers (a NaN is too fast). The last elements (fewer than a group) go
    /// one at a time.
    #[inline(always)]
    fn advance_as<R: Real>(self) -> (bool, bool) {
        let Free { dt_s, inv_mass_3, sum, force, vel, pos, radius, refs, margin, limit2 } = self;
        let n = vel.len();
        let whole = n - n % R::LANES;
        let (sum, sum_tail) = sum.split_at_mut(whole);
        let (force, force_tail) = force[..n].split_at_mut(whole);
        let (vel, vel_tail) = vel.split_at_mut(whole);
        let (pos, pos_tail) = pos[..n].split_at_mut(whole);
        let (inv, radius, refs, margin) = (&inv_mass_3[..n], &radius[..n], &refs[..n], &margin[..n]);
        let (dt, one, zero, limit2_r) = (R::splat(dt_s), R::splat(1.0), R::zero(), R::splat(limit2));
        let (mut bad, mut far) = (zero.gt(zero), zero.gt(zero));
        let w = 3 * R::LANES;
        let groups = sum.as_flattened_mut().chunks_exact_mut(w).zip(force.as_flattened_mut().chunks_exact_mut(w)).zip(vel.as_flattened_mut().chunks_exact_mut(w)).zip(pos.as_flattened_mut().chunks_exact_mut(w));
        let consts = inv[..whole].as_flattened().chunks_exact(w).zip(radius[..whole].chunks_exact(R::LANES)).zip(refs[..whole].chunks_exact(R::LANES)).zip(margin[..whole].chunks_exact(R::LANES));
        for ((((s, f), v), x), (((im, r), g), m)) in groups.zip(consts) {
            // Component k·LANES.. of the group: v = 1·v + Δt·F·(1/m) + 0, x += Δt·v.
            let (mut vn, mut xn) = ([zero; 3], [zero; 3]);
            for k in 0..3 {
                let at = k * R::LANES;
                let fk = R::load(&s[at..]);
                zero.store(&mut s[at..]);
                fk.store(&mut f[at..]);
                vn[k] = velocity(one, R::load(&v[at..]), dt, fk, R::load(&im[at..]), zero);
                vn[k].store(&mut v[at..]);
                xn[k] = position(R::load(&x[at..]), dt, vn[k]);
                xn[k].store(&mut x[at..]);
            }
            let (vx, vy, spin) = R::columns(vn[0], vn[1], vn[2]);
            bad = bad | too_fast(vx, vy, spin, R::load(r), limit2_r);
            let (px, py, _) = R::columns(xn[0], xn[1], xn[2]);
            let (rx, ry) = R::rows_xy(g);
            far = far | drifted(px, py, rx, ry, R::load(m));
        }
        let (mut bad, mut far) = (bad.any(), far.any());
        if whole < n {
            let tail = Free {
                dt_s,
                inv_mass_3: &inv[whole..],
                sum: sum_tail,
                force: force_tail,
                vel: vel_tail,
                pos: pos_tail,
                radius: &radius[whole..],
                refs: &refs[whole..],
                margin: &margin[whole..],
                limit2,
            };
            let (b, d) = tail.advance_as::<f64>();
            bad |= b;
            far |= d;
        }
        (bad, far)
    }
}

impl lanes::Task for Free<'_> {
    type Output = (bool, bool);
    #[inline(always)]
    fn run<L: Lanes>(self) -> (bool, bool) {
        self.advance_as::<L>()
    }
}

/// How many elements from the start of `motion` are free (group 0). Thirty-two at a time while
/// all are (an OR the compiler vectorises), then one by one: element by element, the scan took
/// a tenth of the peers' beam's motion stage.
fn free_run(motion: &[u16]) -> usize {
    const WIDE: usize = 32;
    let wide = motion.chunks_exact(WIDE).take_while(|b| b.iter().fold(0, |a, &g| a | g) == 0).count() * WIDE;
    wide + motion[wide..].iter().position(|&g| g != 0).unwrap_or(motion.len() - wide)
}

fn cut<T>(a: &[T], base: usize, n: usize) -> &[T] {
    &a[base..base + n]
}

fn advance_with<const FRAME: bool, const DAMPED: bool, const EXTERNAL: bool>(m: Motion<'_>) {
    let Motion { el, pos, vel, force, sums, pending, rebuild_pos, margin_m, drive, p, partial, spans, lane_width } = m;
    let half = 0.5 * p.alpha_per_s * p.dt_s;
    let (c1, c2, c3) = ((1.0 - half) / (1.0 + half), p.dt_s / (1.0 + half), 2.0 * half / (1.0 + half));
    let limit2 = p.speed_limit_mps * p.speed_limit_mps;
    let run = |k: usize, ps: &mut [[f64; 3]], vs: &mut [[f64; 3]], fs: &mut [[f64; 3]], ss: &mut [[f64; 3]]| -> MotionReport {
        let mut r = MotionReport::default();
        pending.finish(ss, k);
        // The chunk's slices of every per-element array, all of its length: no bounds checks
        // in the loop.
        let (base, n) = (k * CHUNK, ps.len());
        let (mass, inertia, inv_mass, inv_inertia, radius, margin) = (
            cut(&el.mass, base, n),
            cut(&el.inertia, base, n),
            cut(&el.inv_mass, base, n),
            cut(&el.inv_inertia, base, n),
            cut(&el.radius, base, n),
            cut(margin_m, base, n),
        );
        let (motion, load, body, prescribed, refs) =
            (cut(&el.motion, base, n), cut(&el.load, base, n), cut(&el.body, base, n), cut(&el.prescribed, base, n), cut(rebuild_pos, base, n));
        let (vs, fs) = (&mut vs[..n], &mut fs[..n]);
        let (mut bad, mut drifted) = (false, false);
        // Free elements with no damping or external force: runs of them take the update of the
        // general loop below component by component over flat arrays (it vectorises), then its
        // checks.
        let flat = !DAMPED && !EXTERNAL;
        let mut o = 0;
        while o < n {
            let run = if flat { free_run(&motion[o..]) } else { 0 };
            if run > 0 {
                let (a, b) = (o, o + run);
                let free = Free {
                    dt_s: p.dt_s,
                    inv_mass_3: cut(&el.inv_mass_3, base + a, run),
                    sum: &mut ss[a..b],
                    force: &mut fs[a..b],
                    vel: &mut vs[a..b],
                    pos: &mut ps[a..b],
                    radius: &radius[a..b],
                    refs: &refs[a..b],
                    margin: &margin[a..b],
                    limit2,
                };
                let (b1, d1) = free.advance(lane_width);
                bad |= b1;
                drifted |= d1;
                o = b;
                continue;
            }
            let x = &mut ps[o];
            let ([fx, fy, tz], [ex, ey]) = total_force::<EXTERNAL>(std::mem::take(&mut ss[o]), mass[o], load[o], drive, p.gravity_mps2);
            fs[o] = [fx, fy, tz];
            let v0 = vs[o];
            let v1 = if motion[o] != 0 {
                let w = drive.motion_velocity[motion[o] as usize - 1];
                let mask = prescribed[o];
                // Prescribed dofs take the drive's velocity (the actuator holds the element
                // against everything else acting on it); free dofs move undamped by their force
                // (a roller slides freely).
                let g = [fx * inv_mass[o], fy * inv_mass[o], tz * inv_inertia[o]];
                let mut v1 = [0.0; 3];
                for d in 0..3 {
                    if mask & (1 << d) != 0 {
                        v1[d] = w[d];
                        r.external_j -= [fx, fy, tz][d] * w[d] * p.dt_s;
                    } else {
                        v1[d] = v0[d] + p.dt_s * g[d];
                    }
                }
                v1
            } else if DAMPED {
                // Reference velocity of the damping: zero, or the body's rigid motion here.
                let vr = if FRAME {
                    let g = drive.rigid_frame[body[o] as usize];
                    [g[0] - g[2] * (x[1] - g[4]), g[1] + g[2] * (x[0] - g[3]), g[2]]
                } else {
                    [0.0; 3]
                };
                let v1 = [
                    velocity(c1, v0[0], c2, fx, inv_mass[o], c3 * vr[0]),
                    velocity(c1, v0[1], c2, fy, inv_mass[o], c3 * vr[1]),
                    velocity(c1, v0[2], c2, tz, inv_inertia[o], c3 * vr[2]),
                ];
                let mid = [0.5 * (v0[0] + v1[0]) - vr[0], 0.5 * (v0[1] + v1[1]) - vr[1], 0.5 * (v0[2] + v1[2]) - vr[2]];
                r.mass_damping_j +=
                    p.alpha_per_s * (mass[o] * (mid[0] * mid[0] + mid[1] * mid[1]) + inertia[o] * mid[2] * mid[2]) * p.dt_s;
                v1
            } else {
                // α = 0: c1 = 1, c2 = Δt, c3 = 0, so that the bits are those of the damped form
                // with α = 0.
                [
                    velocity(1.0, v0[0], p.dt_s, fx, inv_mass[o], 0.0),
                    velocity(1.0, v0[1], p.dt_s, fy, inv_mass[o], 0.0),
                    velocity(1.0, v0[2], p.dt_s, tz, inv_inertia[o], 0.0),
                ]
            };
            if EXTERNAL && motion[o] == 0 {
                r.external_j += (ex * v1[0] + ey * v1[1]) * p.dt_s;
            }
            vs[o] = v1;
            *x = std::array::from_fn(|d| position(x[d], p.dt_s, v1[d]));
            bad |= row_too_fast(v1, radius[o], limit2);
            drifted |= self::drifted(x[0], x[1], refs[o][0], refs[o][1], margin[o]);
            o += 1;
        }
        r.drifted = drifted;
        if bad {
            r.first_bad = base + vs.iter().zip(radius).position(|(&v, &r)| row_too_fast(v, r, limit2)).expect("an element was too fast");
        }
        r
    };
    assert_eq!(sums.len(), pos.len(), "the motion stage reads the contact sums stage 1 made");
    let chunks = pos.chunks_mut(CHUNK).zip(vel.chunks_mut(CHUNK)).zip(force.chunks_mut(CHUNK)).zip(partial.iter_mut()).zip(sums.chunks_mut(CHUNK)).enumerate();
    // One chunk as the zip hands it out: its index, positions, velocities, forces, report, sums.
    type Rows<'r> = &'r mut [[f64; 3]];
    type Chunk<'r> = (usize, ((((Rows<'r>, Rows<'r>), Rows<'r>), &'r mut MotionReport), Rows<'r>));
    let one = |(k, ((((ps, vs), fs), out), ss)): Chunk<'_>| *out = run(k, ps, vs, fs, ss);
    super::exec::each_chunk(chunks, spans, one);
}

#[cfg(test)]
mod tests {
    use super::{Free, free_run};
    use crate::kernel::lanes::{self, Width};

    /// Random free rows for [`Free`]: (inverse masses, sums, velocities, positions, radii,
    /// reference positions, margins), with element `special` set so that it sits exactly on
    /// the speed limit (25 m²/s²) and on its margin, or is NaN, infinite or a negative zero
    /// by `kind`.
    type Rows = (Vec<[f64; 3]>, Vec<[f64; 3]>, Vec<[f64; 3]>, Vec<[f64; 3]>, Vec<f64>, Vec<[f64; 2]>, Vec<f64>);

    fn rows(n: usize, seed: u64, special: usize, kind: u64) -> Rows {
        let mut x = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
        let mut r = move |lo: f64, hi: f64| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            lo + (hi - lo) * (x >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut t: Rows = Default::default();
        for e in 0..n {
            t.0.push([r(1.0, 50.0), r(1.0, 50.0), r(1e3, 1e5)]);
            t.1.push([r(-1e3, 1e3), r(-1e3, 1e3), r(-1.0, 1.0)]);
            t.2.push([r(-3.0, 3.0), r(-3.0, 3.0), r(-300.0, 300.0)]);
            let p = [r(-1.0, 1.0), r(-1.0, 1.0), r(-1.0, 1.0)];
            t.3.push(p);
            t.4.push(r(0.005, 0.01));
            t.5.push([p[0] + r(-0.004, 0.004), p[1] + r(-0.004, 0.004)]);
            t.6.push(r(0.001, 0.004));
            if e == special {
                match kind {
                    // On the limit and, after a step of 0.125 s (exact in binary), on the margin:
                    // neither too fast nor drifted.
                    0 => {
                        (t.1[e], t.2[e], t.3[e], t.4[e], t.5[e], t.6[e]) = ([0.0; 3], [3.0, 4.0, 0.0], [3.0, 4.0, 0.5], 0.01, [0.375, 0.5], 5.0);
                    }
                    1 => t.2[e][2] = f64::NAN,
                    2 => t.1[e][0] = f64::INFINITY,
                    _ => t.1[e] = [-0.0; 3],
                }
            }
        }
        t
    }

    /// The four-lane motion of free elements gives bitwise the rows and the same answers as the
    /// one-at-a-time pass, for every count of elements around the groups of four (the last
    /// ones go one at a time), with an element on the speed limit and its margin (neither too
    /// fast nor drifted), a NaN (too fast), an infinite force, negative zeros, and random rows
    /// of which some are too fast or drifted and some not.
    #[test]
    fn four_lane_motion_matches_one_at_a_time() {
        let (mut answers, mut cases) = ([[0usize; 2]; 2], 0);
        for n in 0..=13 {
            for seed in 0..24u64 {
                let (special, kind) = ((seed as usize * 5) % n.max(1), seed % 4);
                let limit2 = if seed % 3 == 0 { 25.0 } else { 9.0 };
                let (inv, sum, vel, pos, radius, refs, margin) = rows(n, seed + 100 * n as u64, special, kind);
                let run = |width: Option<Width>| {
                    let (mut sum, mut force, mut vel, mut pos) = (sum.clone(), vec![[7.0; 3]; n], vel.clone(), pos.clone());
                    let free = Free { dt_s: 1e-3, inv_mass_3: &inv, sum: &mut sum, force: &mut force, vel: &mut vel, pos: &mut pos, radius: &radius, refs: &refs, margin: &margin, limit2 };
                    let flags = match width {
                        Some(w) => lanes::run_as(w, free),
                        None => free.advance_as::<f64>(),
                    };
                    let bits = |a: &[[f64; 3]]| a.iter().flatten().map(|v| v.to_bits()).collect::<Vec<_>>();
                    (flags, [bits(&sum), bits(&force), bits(&vel), bits(&pos)])
                };
                let one = run(None);
                for w in lanes::widths() {
                    assert_eq!(run(Some(w)), one, "{n} elements, seed {seed}, {w:?} lanes");
                }
                answers[0][one.0.0 as usize] += 1;
                answers[1][one.0.1 as usize] += 1;
                cases += 1;
            }
        }
        // Both answers of both checks were met.
        assert!(answers.iter().flatten().all(|&k| k > 0), "answers (too fast, drifted) [no, yes]: {answers:?} of {cases}");
    }

    /// On the limit and on the margin exactly is neither too fast nor drifted, in lanes as one
    /// at a time.
    #[test]
    fn four_lane_motion_on_the_limit_and_margin_is_quiet() {
        for n in [1, 4, 5, 8] {
            for (special, w) in (0..n).flat_map(|s| lanes::widths().into_iter().map(move |w| (s, w))) {
                let (inv, mut sum, mut vel, pos, radius, mut refs, mut margin) = rows(n, 7, special, 0);
                for e in (0..n).filter(|&e| e != special) {
                    (sum[e], vel[e], refs[e], margin[e]) = ([0.0; 3], [0.0; 3], [pos[e][0], pos[e][1]], 1.0);
                }
                let (mut pos, mut force) = (pos, vec![[0.0; 3]; n]);
                let free = Free { dt_s: 0.125, inv_mass_3: &inv, sum: &mut sum, force: &mut force, vel: &mut vel, pos: &mut pos, radius: &radius, refs: &refs, margin: &margin, limit2: 25.0 };
                assert_eq!(lanes::run_as(w, free), (false, false), "{n} elements, the one on the limit at {special}, {w:?} lanes");
                assert_eq!((pos[special], vel[special]), ([3.375, 4.5, 0.5], [3.0, 4.0, 0.0]), "the step as meant");
            }
        }
    }

    /// The wide scan finds the first driven element wherever it lies: before, at and after a
    /// 32-element boundary, in a tail shorter than 32, and nowhere.
    #[test]
    fn free_run_is_the_index_of_the_first_driven_element() {
        for n in [0usize, 1, 31, 32, 33, 64, 95, 200] {
            for at in (0..n).chain([usize::MAX]) {
                let mut motion = vec![0u16; n];
                if at < n {
                    motion[at] = 3;
                    // A second driven element after the first must not move the answer.
                    if at + 40 < n {
                        motion[at + 40] = 1;
                    }
                }
                let want = motion.iter().position(|&g| g != 0).unwrap_or(n);
                assert_eq!(free_run(&motion), want, "n = {n}, first driven at {at}");
            }
        }
    }
}
