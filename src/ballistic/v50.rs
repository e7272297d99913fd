//! V50 estimation from binary outcomes (e.g. "the projectile perforated")
//! of runs at impact velocities, as ballistic testing reports it
//! (MIL-STD-662F, NIJ): a logistic curve P(v) = 1 / (1 + exp(-(v - μ)/s))
//! fitted by Firth's penalised maximum likelihood (Firth 1993, Biometrika
//! 80:27; Heinze & Schemper 2002, Stat Med 21:2409), with μ = V50 and a
//! profile penalised-likelihood interval for μ.
//!
//! Firth's penalty (½ log det of the Fisher information) keeps the estimate
//! finite when outcomes are completely separated, which pooled runs of
//! deterministic packings often are; ordinary ML is also reported where it
//! exists, for comparison.

/// The confidence level the sweeps report, as ballistic testing does: 90 %.
pub const LEVEL: f64 = 0.90;

/// A fitted V50 with its profile penalised-likelihood interval.
#[derive(Debug, Clone, PartialEq)]
pub struct V50 {
    /// Firth (penalised ML) estimate of the V50, μ, in ft/s.
    pub v50_fps: f64,
    /// Logistic spread s = 1/slope in ft/s; negative if the outcome becomes
    /// less likely with velocity.
    pub scale_fps: f64,
    /// Lower end of the profile penalised-likelihood interval in ft/s, `None`
    /// if the interval is unbounded below (not closed within 10× the data's
    /// velocity range of the estimate).
    pub lower_fps: Option<f64>,
    /// Upper end of the interval in ft/s, `None` if unbounded above.
    pub upper_fps: Option<f64>,
    /// Pooled outcomes are completely separated: every "false" velocity lies
    /// strictly below every "true" one (or strictly above all of them).
    pub separated: bool,
    /// Number of runs used (runs with a non-finite velocity are dropped).
    pub n: usize,
    /// Number of those runs whose outcome happened.
    pub n_true: usize,
    /// Ordinary ML estimate of the V50 in ft/s; `None` when it does not
    /// exist (complete or quasi-complete separation: no overlap of outcomes).
    pub mle_v50_fps: Option<f64>,
}

/// Fits the logistic V50 model to `runs` = (impact velocity in ft/s, outcome
/// happened) and forms a `level` (e.g. 0.90) profile penalised-likelihood
/// interval for the V50.
///
/// Runs with a non-finite velocity are ignored. Returns `None` if fewer than
/// 2 runs remain, all outcomes are equal, all velocities are equal, `level`
/// is not in (0, 1), or the fit fails numerically.
pub fn fit(runs: &[(f64, bool)], level: f64) -> Option<V50> {
    if !(level > 0.0 && level < 1.0) {
        return None;
    }
    let clean: Vec<(f64, bool)> = runs.iter().copied().filter(|r| r.0.is_finite()).collect();
    let n = clean.len();
    let n_true = clean.iter().filter(|r| r.1).count();
    if n < 2 || n_true == 0 || n_true == n {
        return None;
    }
    let (mean, sd) = mean_sd(&clean)?;
    let data = Grouped::new(&clean, mean, sd);
    let overlap = Overlap::of(&clean);

    let (a, b) = firth_fit(&data)?;
    let mu_x = -a / b;
    if !mu_x.is_finite() {
        return None;
    }
    // The joint optimum and the profile at μ̂ should agree; take the larger so
    // rounding can never put μ̂ itself outside the interval.
    let (prof_at_hat, _) = profile(&data, mu_x, b.abs());
    let l_max = penalised(&data, a, b).max(prof_at_hat);
    let crit = chi2_1_quantile(level);
    let range_x = data.range();
    let lower = endpoint(&data, mu_x, b.abs(), l_max, crit, -range_x);
    let upper = endpoint(&data, mu_x, b.abs(), l_max, crit, range_x);

    let to_fps = |x: f64| mean + sd * x;
    let mle_v50_fps = if overlap.overlapping() {
        mle_fit(&data).map(|(ma, mb)| to_fps(-ma / mb)).filter(|v| v.is_finite())
    } else {
        None
    };
    Some(V50 {
        v50_fps: to_fps(mu_x),
        scale_fps: sd / b,
        lower_fps: lower.map(to_fps),
        upper_fps: upper.map(to_fps),
        separated: overlap.separated(),
        n,
        n_true,
        mle_v50_fps,
    })
}

/// The χ² quantile with 1 degree of freedom at probability `level`, as
/// z² with z = Φ⁻¹((1 + level)/2); 2.705543454095404 at 0.90.
pub fn chi2_1_quantile(level: f64) -> f64 {
    let z = normal_quantile(0.5 * (1.0 + level));
    z * z
}

/// The standard normal quantile Φ⁻¹(p) by Wichura's AS241 (PPND16, about
/// 1e-16 relative); NaN outside (0, 1).
#[allow(clippy::excessive_precision)] // coefficients as published by Wichura
pub fn normal_quantile(p: f64) -> f64 {
    if !(p > 0.0 && p < 1.0) {
        return f64::NAN;
    }
    let q = p - 0.5;
    if q.abs() <= 0.425 {
        let r = 0.180625 - q * q;
        let num = poly(
            r,
            &[
                3.3871328727963666080e0, 1.3314166789178437745e2, 1.9715909503065514427e3,
                1.3731693765509461125e4, 4.5921953931549871457e4, 6.7265770927008700853e4,
                3.3430575583588128105e4, 2.5090809287301226727e3,
            ],
        );
        let den = poly(
            r,
            &[
                1.0, 4.2313330701600911252e1, 6.8718700749205790830e2, 5.3941960214247511077e3,
                2.1213794301586595867e4, 3.9307895800092710610e4, 2.8729085735721942674e4,
                5.2264952788528545610e3,
            ],
        );
        return q * num / den;
    }
    let tail = if q < 0.0 { p } else { 1.0 - p };
    let mut r = (-tail.ln()).sqrt();
    let z = if r <= 5.0 {
        r -= 1.6;
        poly(
            r,
            &[
                1.42343711074968357734e0, 4.63033784615654529590e0, 5.76949722146069140550e0,
                3.64784832476320460504e0, 1.27045825245236838258e0, 2.41780725177450611770e-1,
                2.27238449892691845833e-2, 7.74545014278341407640e-4,
            ],
        ) / poly(
            r,
            &[
                1.0, 2.05319162663775882187e0, 1.67638483018380384940e0, 6.89767334985100004550e-1,
                1.48103976427480074590e-1, 1.51986665636164571966e-2, 5.47593808499534494600e-4,
                1.05075007164441684324e-9,
            ],
        )
    } else {
        r -= 5.0;
        poly(
            r,
            &[
                6.65790464350110377720e0, 5.46378491116411436990e0, 1.78482653991729133580e0,
                2.96560571828504891230e-1, 2.65321895265761230930e-2, 1.24266094738807843860e-3,
                2.71155556874348757815e-5, 2.01033439929228813265e-7,
            ],
        ) / poly(
            r,
            &[
                1.0, 5.99832206555887937690e-1, 1.36929880922735805310e-1, 1.48753612908506148525e-2,
                7.86869131145613259100e-4, 1.84631831751005468180e-5, 1.42151175831644588870e-7,
                2.04426310338993978564e-15,
            ],
        )
    };
    if q < 0.0 { -z } else { z }
}

/// Horner evaluation of c[0] + c[1] r + c[2] r² + ….
fn poly(r: f64, c: &[f64]) -> f64 {
    c.iter().rev().fold(0.0, |acc, &ci| acc * r + ci)
}

// ---------------------------------------------------------------- data ----

/// Mean and (population) standard deviation of the velocities; `None` if
/// they are all equal, when no slope can be estimated.
fn mean_sd(runs: &[(f64, bool)]) -> Option<(f64, f64)> {
    let n = runs.len() as f64;
    let mean = runs.iter().map(|r| r.0).sum::<f64>() / n;
    let var = runs.iter().map(|r| (r.0 - mean).powi(2)).sum::<f64>() / n;
    let sd = var.sqrt();
    (sd > 0.0 && sd.is_finite()).then_some((mean, sd))
}

/// Runs grouped by velocity as binomial counts on the scaled velocity
/// x = (v − mean)/sd; grouping makes each likelihood evaluation cheaper
/// (several packings share the same velocities) without changing it.
struct Grouped {
    x: Vec<f64>,
    trials: Vec<f64>,
    trues: Vec<f64>,
}

impl Grouped {
    fn new(runs: &[(f64, bool)], mean: f64, sd: f64) -> Self {
        let mut sorted = runs.to_vec();
        sorted.sort_by(|p, q| p.0.total_cmp(&q.0));
        let mut g = Grouped { x: Vec::new(), trials: Vec::new(), trues: Vec::new() };
        let mut last = f64::NAN;
        for (v, hit) in sorted {
            if v != last {
                g.x.push((v - mean) / sd);
                g.trials.push(0.0);
                g.trues.push(0.0);
                last = v;
            }
            let i = g.x.len() - 1;
            g.trials[i] += 1.0;
            g.trues[i] += if hit { 1.0 } else { 0.0 };
        }
        g
    }

    /// Spread of the scaled velocities (they are sorted).
    fn range(&self) -> f64 {
        self.x[self.x.len() - 1] - self.x[0]
    }
}

/// Extremes of the velocities of each outcome, to classify separation.
struct Overlap {
    max_false: f64,
    min_false: f64,
    max_true: f64,
    min_true: f64,
}

impl Overlap {
    fn of(runs: &[(f64, bool)]) -> Self {
        let mut o = Overlap {
            max_false: f64::NEG_INFINITY,
            min_false: f64::INFINITY,
            max_true: f64::NEG_INFINITY,
            min_true: f64::INFINITY,
        };
        for &(v, hit) in runs {
            if hit {
                o.max_true = o.max_true.max(v);
                o.min_true = o.min_true.min(v);
            } else {
                o.max_false = o.max_false.max(v);
                o.min_false = o.min_false.min(v);
            }
        }
        o
    }

    /// Complete separation, in either direction.
    fn separated(&self) -> bool {
        self.max_false < self.min_true || self.max_true < self.min_false
    }

    /// True overlap in both directions: exactly when the ordinary MLE exists
    /// (no complete or quasi-complete separation).
    fn overlapping(&self) -> bool {
        self.max_false > self.min_true && self.max_true > self.min_false
    }
}

// ------------------------------------------------------------ numerics ----

/// log(1 + e^t) without overflow or loss of precision for large |t|.
fn softplus(t: f64) -> f64 {
    if t > 0.0 { t + (-t).exp().ln_1p() } else { t.exp().ln_1p() }
}

/// (p, p(1 − p)) at linear predictor `eta`, both without overflow.
fn prob_weight(eta: f64) -> (f64, f64) {
    let e = (-eta.abs()).exp();
    let d = 1.0 + e;
    let p = if eta >= 0.0 { 1.0 / d } else { e / d };
    (p, e / (d * d))
}

/// Weighted sums of the Fisher information I = XᵀWX for X = [1, x]: total
/// weight, weighted mean of x and weighted sum of squares about it,
/// accumulated with West's update so det I = s0·ss never cancels.
#[derive(Default)]
struct Info {
    s0: f64,
    mean: f64,
    ss: f64,
}

impl Info {
    fn add(&mut self, x: f64, w: f64) {
        if w <= 0.0 {
            return;
        }
        self.s0 += w;
        let delta = x - self.mean;
        self.mean += w / self.s0 * delta;
        self.ss += w * delta * (x - self.mean);
    }

    fn det(&self) -> f64 {
        self.s0 * self.ss
    }

    /// I⁻¹ as (i00, i01, i11); `None` if I is singular.
    fn inverse(&self) -> Option<(f64, f64, f64)> {
        let det = self.det();
        if !(det > 0.0 && det.is_finite()) {
            return None;
        }
        let s1 = self.s0 * self.mean;
        let s2 = self.ss + self.s0 * self.mean * self.mean;
        Some((s2 / det, -s1 / det, self.s0 / det))
    }
}

/// Ordinary log-likelihood and Fisher information at (a, b).
fn loglik_info(d: &Grouped, a: f64, b: f64) -> (f64, Info) {
    let mut ll = 0.0;
    let mut info = Info::default();
    for i in 0..d.x.len() {
        let eta = a + b * d.x[i];
        ll += d.trues[i] * eta - d.trials[i] * softplus(eta);
        info.add(d.x[i], d.trials[i] * prob_weight(eta).1);
    }
    (ll, info)
}

/// Firth's penalised log-likelihood ℓ + ½ log det I; −∞ where I is
/// numerically singular (only at absurdly steep slopes).
fn penalised(d: &Grouped, a: f64, b: f64) -> f64 {
    let (ll, info) = loglik_info(d, a, b);
    let det = info.det();
    if det > 0.0 { ll + 0.5 * det.ln() } else { f64::NEG_INFINITY }
}

/// Scoring step I⁻¹U at (a, b); with `firth` the score is Heinze &
/// Schemper's modified one, Σ (y − m p + h(½ − p)) X, which is exactly the
/// gradient of the penalised log-likelihood for the logistic model.
fn scoring_step(d: &Grouped, a: f64, b: f64, firth: bool) -> Option<(f64, f64)> {
    let (_, info) = loglik_info(d, a, b);
    let (i00, i01, i11) = info.inverse()?;
    let (mut ua, mut ub) = (0.0, 0.0);
    for i in 0..d.x.len() {
        let x = d.x[i];
        let (p, w) = prob_weight(a + b * x);
        let mut r = d.trues[i] - d.trials[i] * p;
        if firth {
            let leverage = d.trials[i] * w * (i00 + 2.0 * i01 * x + i11 * x * x);
            r += leverage * (0.5 - p);
        }
        ua += r;
        ub += r * x;
    }
    Some((i00 * ua + i01 * ub, i01 * ua + i11 * ub))
}

/// Maximises `objective` by scoring steps with step-halving; the steps are
/// capped so a flat start cannot jump to a numerically singular slope.
fn newton(
    d: &Grouped,
    firth: bool,
    objective: impl Fn(f64, f64) -> f64,
) -> Option<(f64, f64)> {
    const MAX_STEP: f64 = 5.0;
    let kbar = d.trues.iter().sum::<f64>() / d.trials.iter().sum::<f64>();
    let (mut a, mut b) = ((kbar / (1.0 - kbar)).ln(), 0.0);
    let mut cur = objective(a, b);
    for _ in 0..500 {
        let (da, db) = scoring_step(d, a, b, firth)?;
        let size = da.abs().max(db.abs());
        if !size.is_finite() {
            return None;
        }
        if size < 1e-12 * (1.0 + a.abs().max(b.abs())) {
            return Some((a, b));
        }
        let mut t = (MAX_STEP / size).min(1.0);
        // Accept a step that does not lower the objective beyond rounding.
        let slack = 1e-13 * (1.0 + cur.abs());
        loop {
            let cand = objective(a + t * da, b + t * db);
            if cand >= cur - slack {
                a += t * da;
                b += t * db;
                cur = cand.max(cur);
                break;
            }
            t *= 0.5;
            if t < 1e-12 {
                return Some((a, b)); // no ascent possible: at the optimum to rounding
            }
        }
    }
    None
}

/// Firth's penalised ML estimate of (a, b) on the scaled velocity.
fn firth_fit(d: &Grouped) -> Option<(f64, f64)> {
    newton(d, true, |a, b| penalised(d, a, b)).filter(|&(_, b)| b != 0.0)
}

/// Ordinary ML estimate of (a, b); call only when the outcomes overlap.
fn mle_fit(d: &Grouped) -> Option<(f64, f64)> {
    newton(d, false, |a, b| loglik_info(d, a, b).0).filter(|&(_, b)| b != 0.0)
}

// ------------------------------------------------------------- profile ----

/// ℓ*_prof(μ) = max over b of ℓ*(−b μ, b) with μ on the scaled axis, and the
/// maximising b. A log-spaced grid over both signs of b (around `b_ref`, the
/// size of the Firth slope) finds the best cell, grown outward if the best
/// point is at an end, then Brent refines within it: the function need not
/// be concave and can peak at b ≤ 0 when μ is far outside the data.
fn profile(d: &Grouped, mu: f64, b_ref: f64) -> (f64, f64) {
    let f = |b: f64| penalised(d, -b * mu, b);
    let b_ref = if b_ref > 0.0 && b_ref.is_finite() { b_ref } else { 1.0 };
    let mut grid: Vec<f64> = (-12..=8).rev().map(|k| -b_ref * 2f64.powi(k)).collect();
    grid.push(0.0);
    grid.extend((-12..=8).map(|k| b_ref * 2f64.powi(k)));
    let vals: Vec<f64> = grid.iter().map(|&b| f(b)).collect();
    let best = argmax(&vals);
    let last = grid.len() - 1;
    let (lo, hi, b0, f0) = if best == 0 || best == last {
        grow_outward(&f, grid[best], vals[best])
    } else {
        (grid[best - 1], grid[best + 1], grid[best], vals[best])
    };
    let (b, fb) = brent_max(&f, lo, hi, b0, f0);
    if fb >= f0 { (fb, b) } else { (f0, b0) }
}

/// Index of the largest value (NaN and −∞ never win).
fn argmax(vals: &[f64]) -> usize {
    let mut best = 0;
    for (i, &v) in vals.iter().enumerate() {
        if v > vals[best] || vals[best].is_nan() {
            best = i;
        }
    }
    best
}

/// Doubles b from an end of the grid while f keeps rising; returns a bracket
/// (lo, hi) around the best point found, and that point with its value.
fn grow_outward(f: &impl Fn(f64) -> f64, b_end: f64, f_end: f64) -> (f64, f64, f64, f64) {
    let (mut prev, mut b, mut fb) = (b_end * 0.5, b_end, f_end);
    for _ in 0..200 {
        let next = 2.0 * b;
        let fnext = f(next);
        #[allow(clippy::neg_cmp_op_on_partial_ord)] // a NaN value must stop the growth too
        if !(fnext > fb) {
            let (lo, hi) = if prev < next { (prev, next) } else { (next, prev) };
            return (lo, hi, b, fb);
        }
        prev = b;
        b = next;
        fb = fnext;
    }
    let (lo, hi) = if prev < b { (prev, b) } else { (b, prev) };
    (lo, hi, b, fb)
}

/// Brent's minimiser (golden section + parabolic steps) applied to −f on
/// [lo, hi], starting from the interior point `x0` with value `f0`.
fn brent_max(f: &impl Fn(f64) -> f64, lo: f64, hi: f64, x0: f64, f0: f64) -> (f64, f64) {
    const CGOLD: f64 = 0.381_966_011_250_105;
    const REL: f64 = 3e-8; // ≈ √ε: finer x cannot change f at the maximum
    let g = |x: f64| {
        let v = -f(x);
        if v.is_nan() { f64::INFINITY } else { v }
    };
    let (mut a, mut b) = (lo, hi);
    let (mut x, mut w, mut v) = (x0, x0, x0);
    let (mut fx, mut fw, mut fv) = (-f0, -f0, -f0);
    let (mut d, mut e): (f64, f64) = (0.0, 0.0);
    for _ in 0..200 {
        let xm = 0.5 * (a + b);
        let tol1 = REL * x.abs() + 1e-14;
        let tol2 = 2.0 * tol1;
        if (x - xm).abs() <= tol2 - 0.5 * (b - a) {
            break;
        }
        let mut golden = true;
        if e.abs() > tol1 {
            let r = (x - w) * (fx - fv);
            let mut q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            }
            q = q.abs();
            let etemp = e;
            if p.abs() < (0.5 * q * etemp).abs() && p > q * (a - x) && p < q * (b - x) {
                e = d;
                d = p / q;
                let u = x + d;
                if u - a < tol2 || b - u < tol2 {
                    d = tol1.copysign(xm - x);
                }
                golden = false;
            }
        }
        if golden {
            e = if x >= xm { a - x } else { b - x };
            d = CGOLD * e;
        }
        let u = if d.abs() >= tol1 { x + d } else { x + tol1.copysign(d) };
        let fu = g(u);
        if fu <= fx {
            if u >= x { a = x } else { b = x }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x { a = u } else { b = u }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    (x, -fx)
}

/// One end of the interval on the scaled axis: scans from μ̂ in the
/// direction of `step0` (sign) with steps growing from |step0|/20 until the
/// profile deviance exceeds `crit`, then solves for the crossing. `None` if
/// not reached within 10 × |step0| (10 × the data's range) of μ̂.
fn endpoint(d: &Grouped, mu_hat: f64, b_ref: f64, l_max: f64, crit: f64, step0: f64) -> Option<f64> {
    let excess = |mu: f64| 2.0 * (l_max - profile(d, mu, b_ref).0) - crit;
    let limit = 10.0 * step0.abs();
    let mut step = step0 / 20.0;
    let (mut prev, mut f_prev) = (mu_hat, -crit);
    loop {
        let cur = prev + step;
        if (cur - mu_hat).abs() > limit {
            return None;
        }
        let f_cur = excess(cur);
        if f_cur > 0.0 {
            return Some(brent_root(&excess, prev, cur, f_prev, f_cur));
        }
        (prev, f_prev) = (cur, f_cur);
        step *= 1.25; // reach 10× the range in ~18 steps
    }
}

/// Brent's root finder (bisection + inverse quadratic interpolation) on a
/// bracket with f(a)·f(b) ≤ 0.
fn brent_root(f: &impl Fn(f64) -> f64, a0: f64, b0: f64, fa0: f64, fb0: f64) -> f64 {
    const TOL: f64 = 1e-11;
    let (mut a, mut b, mut fa, mut fb) = (a0, b0, fa0, fb0);
    let (mut c, mut fc) = (b, fb);
    let (mut d, mut e) = (b - a, b - a);
    for _ in 0..200 {
        if (fb > 0.0) == (fc > 0.0) {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, b, c) = (b, c, b);
            (fa, fb, fc) = (fb, fc, fb);
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * TOL;
        let xm = 0.5 * (c - b);
        if xm.abs() <= tol1 || fb == 0.0 {
            return b;
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q);
            if a == c {
                p = 2.0 * xm * s;
                q = 1.0 - s;
            } else {
                let qq = fa / fc;
                let r = fb / fc;
                p = s * (2.0 * xm * qq * (qq - r) - (b - a) * (r - 1.0));
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
            }
            if p > 0.0 {
                q = -q;
            }
            p = p.abs();
            let min1 = 3.0 * xm * q - (tol1 * q).abs();
            let min2 = (e * q).abs();
            if 2.0 * p < min1.min(min2) {
                e = d;
                d = p / q;
            } else {
                d = xm;
                e = d;
            }
        } else {
            d = xm;
            e = d;
        }
        (a, fa) = (b, fb);
        b += if d.abs() > tol1 { d } else { tol1.copysign(xm) };
        fb = f(b);
    }
    b
}

// --------------------------------------------------------------- tests ----

#[cfg(test)]
mod tests {
    use super::*;

    const V: [f64; 9] = [800.0, 850.0, 900.0, 950.0, 1000.0, 1050.0, 1100.0, 1150.0, 1200.0];

    fn rel_close(got: f64, want: f64, tol: f64) -> bool {
        (got - want).abs() <= tol * want.abs()
    }

    fn assert_rel(name: &str, got: f64, want: f64) {
        assert!(rel_close(got, want, 1e-6), "{name}: got {got:.12}, want {want:.12}");
    }

    /// The overlapping two-packing data set of crosscheck.py.
    fn overlap_runs() -> Vec<(f64, bool)> {
        let p1 = [0, 0, 0, 1, 0, 1, 0, 1, 1];
        let p2 = [0, 0, 1, 0, 1, 1, 1, 1, 1];
        let mut runs: Vec<(f64, bool)> = V.iter().zip(p1).map(|(&v, y)| (v, y == 1)).collect();
        runs.extend(V.iter().zip(p2).map(|(&v, y)| (v, y == 1)));
        runs
    }

    fn separated_runs() -> Vec<(f64, bool)> {
        V.iter().map(|&v| (v, v >= 1000.0)).collect()
    }

    #[test]
    fn normal_quantile_matches_reference_values() {
        // Reference values: the brief, and Python's statistics.NormalDist.inv_cdf.
        let cases = [
            (0.95, 1.6448536269514722),
            (0.975, 1.959963984540054),
            (0.5, 0.0),
            (0.6, 0.2533471031357998),
            (0.9, 1.2815515655446008),
            (0.99, 2.3263478740408408),
            (1e-3, -3.090232306167813),
            (1e-10, -6.361340902404056),
            (1.0 - 1e-7, 5.199337582290662),
        ];
        for (p, z) in cases {
            let got = normal_quantile(p);
            assert!((got - z).abs() <= 1e-9 * (1.0 + z.abs()), "p={p}: {got} vs {z}");
        }
        assert!((chi2_1_quantile(0.90) - 2.705543454095404).abs() < 1e-12);
        assert!((normal_quantile(0.5 * (1.0 + 0.90)) - 1.6448536269514722).abs() < 1e-12);
        assert!((normal_quantile(0.5 * (1.0 + 0.95)) - 1.959963984540054).abs() < 1e-12);
        assert!(normal_quantile(0.0).is_nan() && normal_quantile(f64::NAN).is_nan());
    }

    /// Numbers from /tmp/v50/crosscheck.py: an independent Firth fit
    /// (per-observation Newton with Heinze & Schemper's modified score, numpy),
    /// a brute-force profile scan + brentq for the interval, and statsmodels'
    /// Logit for the ordinary MLE.
    #[test]
    fn crosscheck_against_python() {
        let r = fit(&overlap_runs(), 0.90).expect("fit");
        assert_rel("v50", r.v50_fps, 972.931211740906);
        assert_rel("scale", r.scale_fps, 84.968229146041);
        assert_rel("lower", r.lower_fps.expect("lower"), 869.263817462903);
        assert_rel("upper", r.upper_fps.expect("upper"), 1060.563746642579);
        assert_rel("mle", r.mle_v50_fps.expect("mle"), 973.084732663474);
        assert!(!r.separated);
        assert_eq!((r.n, r.n_true), (18, 10));

        let s = fit(&separated_runs(), 0.90).expect("fit");
        assert_rel("sep v50", s.v50_fps, 975.925096121161);
        assert_rel("sep scale", s.scale_fps, 50.127400722400);
        assert_rel("sep lower", s.lower_fps.expect("lower"), 872.416942873953);
        assert_rel("sep upper", s.upper_fps.expect("upper"), 1071.847818585872);
    }

    #[test]
    fn complete_separation_gives_finite_estimate_and_interval() {
        let r = fit(&separated_runs(), 0.90).expect("fit");
        assert!(r.separated);
        assert!(r.mle_v50_fps.is_none());
        assert!(r.v50_fps > 950.0 && r.v50_fps < 1000.0, "{}", r.v50_fps);
        let (lo, hi) = (r.lower_fps.expect("lower"), r.upper_fps.expect("upper"));
        assert!(lo.is_finite() && hi.is_finite());
        assert!(lo < r.v50_fps && r.v50_fps < hi);
        assert!(lo < 950.0 && hi > 1000.0, "[{lo}, {hi}]");
    }

    #[test]
    fn quasi_separation_is_not_complete_but_has_no_mle() {
        // A tie at 1000 ft/s: outcomes touch but do not overlap.
        let mut runs = separated_runs();
        runs.push((1000.0, false));
        let r = fit(&runs, 0.90).expect("fit");
        assert!(!r.separated);
        assert!(r.mle_v50_fps.is_none());
        assert!(r.v50_fps > 950.0 && r.v50_fps < 1050.0);
    }

    #[test]
    fn shift_of_velocities_shifts_results() {
        for runs in [overlap_runs(), separated_runs()] {
            let shifted: Vec<(f64, bool)> = runs.iter().map(|&(v, y)| (v + 100.0, y)).collect();
            let (a, b) = (fit(&runs, 0.9).expect("fit"), fit(&shifted, 0.9).expect("fit"));
            let near = |x: f64, y: f64| (x + 100.0 - y).abs() < 1e-6;
            assert!(near(a.v50_fps, b.v50_fps));
            assert!(near(a.lower_fps.expect("lo"), b.lower_fps.expect("lo")));
            assert!(near(a.upper_fps.expect("hi"), b.upper_fps.expect("hi")));
            assert!((a.scale_fps - b.scale_fps).abs() < 1e-6);
            assert_eq!(a.separated, b.separated);
        }
    }

    #[test]
    fn degenerate_inputs_give_none() {
        assert!(fit(&[], 0.9).is_none());
        assert!(fit(&[(1000.0, true)], 0.9).is_none());
        let all_true: Vec<(f64, bool)> = V.iter().map(|&v| (v, true)).collect();
        let all_false: Vec<(f64, bool)> = V.iter().map(|&v| (v, false)).collect();
        assert!(fit(&all_true, 0.9).is_none());
        assert!(fit(&all_false, 0.9).is_none());
        // Non-finite velocities are dropped, leaving too little.
        assert!(fit(&[(f64::NAN, true), (900.0, false)], 0.9).is_none());
        assert!(fit(&[(f64::INFINITY, true), (900.0, false), (f64::NAN, true)], 0.9).is_none());
        // Both outcomes but one velocity: no slope.
        assert!(fit(&[(900.0, true), (900.0, false)], 0.9).is_none());
        assert!(fit(&overlap_runs(), f64::NAN).is_none());
        // NaNs mixed into good data are ignored, not fatal.
        let mut runs = overlap_runs();
        runs.push((f64::NAN, true));
        assert_eq!(fit(&runs, 0.9).expect("fit").n, 18);
    }

    #[test]
    fn weak_data_gives_unbounded_interval_not_panic() {
        // Five runs, reversed separation: the data hardly locate the V50.
        let runs = [(900.0, true), (1000.0, false), (950.0, true), (1050.0, false), (980.0, true)];
        let r = fit(&runs, 0.9).expect("fit");
        assert!(r.v50_fps.is_finite());
        assert!(r.scale_fps < 0.0, "outcome falls with velocity");
        println!("weak data: {r:?}");
    }

    #[test]
    fn tiny_separation_gap_is_handled() {
        // Steep step: the Firth slope is large on the scaled axis.
        let mut runs: Vec<(f64, bool)> = V.iter().map(|&v| (v, v >= 1000.0)).collect();
        runs.push((999.9, false));
        let r = fit(&runs, 0.9).expect("fit");
        assert!(r.separated);
        assert!(r.v50_fps > 950.0 && r.v50_fps < 1050.0, "{r:?}");
        let (lo, hi) = (r.lower_fps.expect("lo"), r.upper_fps.expect("hi"));
        assert!(lo < r.v50_fps && r.v50_fps < hi);
        println!("tiny gap: {r:?}");
    }

    /// Coverage of the true V50 over `reps` synthetic data sets: 5 packings ×
    /// 500..=1500 step 50, Bernoulli draws from a logistic(1000, s).
    fn coverage(scale_fps: f64, seed: u64, reps: usize) -> (usize, usize, usize) {
        const TRUE_V50: f64 = 1000.0;
        let mut rng = crate::lattice::SplitMix64(seed);
        let (mut covered, mut separated, mut unbounded) = (0, 0, 0);
        let start = std::time::Instant::now();
        for _ in 0..reps {
            let mut runs = Vec::with_capacity(105);
            for _packing in 0..5 {
                for k in 0..=20 {
                    let v = 500.0 + 50.0 * k as f64;
                    let p = 1.0 / (1.0 + (-(v - TRUE_V50) / scale_fps).exp());
                    runs.push((v, rng.unit() < p));
                }
            }
            let r = fit(&runs, 0.90).expect("fit");
            let lo_ok = r.lower_fps.is_none_or(|l| l <= TRUE_V50);
            let hi_ok = r.upper_fps.is_none_or(|u| u >= TRUE_V50);
            covered += usize::from(lo_ok && hi_ok);
            separated += usize::from(r.separated);
            unbounded += usize::from(r.lower_fps.is_none() || r.upper_fps.is_none());
        }
        let per_fit = start.elapsed().as_secs_f64() * 1e3 / reps as f64;
        println!(
            "s = {scale_fps} ft/s: covered {covered}/{reps}, separated {separated}, \
             unbounded {unbounded}, {per_fit:.2} ms per fit"
        );
        (covered, separated, unbounded)
    }

    #[test]
    fn coverage_of_90_percent_interval_s40() {
        let (covered, _, _) = coverage(40.0, 0x5EED_0040, 200);
        assert!((170..=190).contains(&covered), "coverage {covered}/200");
    }

    #[test]
    fn coverage_of_90_percent_interval_s20() {
        // Closer to separation. The brief asked to assert this only if it
        // honestly landed in the band; the first run (design unchanged) gave
        // 186/200, so it is asserted.
        let (covered, _, _) = coverage(20.0, 0x5EED_0020, 200);
        assert!((170..=190).contains(&covered), "coverage {covered}/200");
    }

    /// Diagnostic, not part of the suite: coverage over 2000 repetitions with
    /// other seeds, to see where the 200-rep counts sit. Run with --ignored.
    #[test]
    #[ignore]
    fn coverage_diagnostic_2000() {
        coverage(40.0, 0xD1A6_0040, 2000);
        coverage(20.0, 0xD1A6_0020, 2000);
        coverage(10.0, 0xD1A6_0010, 2000);
    }
}
