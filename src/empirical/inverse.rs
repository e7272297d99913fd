//! Inverse: the impact velocity at which a formula's h_s (scabbing velocity) or h_p (ballistic
//! limit) equals a given thickness, by bracketing and bisection (FORMULAS §5).
//!
//! Not every formula is monotone (Adeli–Amin's quadratics turn over, Haldar–Hamieh and the
//! Kennedy/Hughes h_p branches jump slightly), so the answer is the *first* velocity at which the
//! thickness is reached: a log-uniform scan over [`SCAN_MIN_MPS`, `SCAN_MAX_MPS`] finds the first
//! sign change, a finer scan of that interval ([`SUB_STEPS`]) the first sign change inside it,
//! then bisection narrows it to the last representable bit. Where a curve tops out (Adeli–Amin's
//! parabolas) the thickness may be reached only in a window narrower than the scan's step, with
//! both neighbouring samples below it: every sampled local maximum is refined by a
//! golden-section search. Where a curve jumps down at a branch join (Kennedy/Degen/Hughes h_p,
//! Haldar–Hamieh x) and recovers within one step, the samples keep rising across the jump and a
//! crossing window before it narrower than the step (0.43 % in velocity) is passed over for the
//! next crossing, at most a few tenths of a per cent later; property tests found both cases.
//! A formula whose curve never reaches the thickness says so ([`Threshold::NotReachable`]).

use super::{Formula, Missile, Quantity, Target, Validity};
use crate::units;

/// Lower end of the scan, m/s.
pub const SCAN_MIN_MPS: f64 = 1.0;
/// Upper end of the scan, m/s.
pub const SCAN_MAX_MPS: f64 = 5000.0;
/// Scan intervals: fine enough (0.43 % per step) that no fold of the fitted curves is jumped.
pub const SCAN_STEPS: usize = 2000;
/// Sub-intervals of the first bracketing scan interval (a crossing closer than 1e-6 relative to
/// a downward jump could still be passed over).
pub const SUB_STEPS: usize = 4096;

/// The answer of an inverse query.
#[derive(Debug, Clone, PartialEq)]
pub enum Threshold {
    /// The velocity, ft/s, and the formula's validity there.
    Velocity {
        /// Impact velocity, ft/s.
        v_fps: f64,
        /// Validity of the formula's inputs at that velocity.
        validity: Validity,
    },
    /// The thickness is already reached at the scan's lowest velocity (e.g. ACE for thin walls,
    /// where x/d ≥ 0.5 at any velocity).
    AnyVelocity,
    /// The curve never reaches the thickness inside the scan (e.g. Adeli–Amin: h_s/d ≤ 5.44).
    NotReachable,
    /// The formula does not define this quantity.
    NotDefined,
}

impl Threshold {
    /// The velocity, ft/s, if there is one.
    pub fn v_fps(&self) -> Option<f64> {
        match self {
            Threshold::Velocity { v_fps, .. } => Some(*v_fps),
            _ => None,
        }
    }

    /// Table cell: the velocity to `decimals`, `not reachable`, `any velocity`, or empty.
    pub fn cell(&self, decimals: usize) -> String {
        match self {
            Threshold::Velocity { v_fps, .. } => format!("{v_fps:.decimals$}"),
            Threshold::AnyVelocity => "any velocity".into(),
            Threshold::NotReachable => "not reachable".into(),
            Threshold::NotDefined => String::new(),
        }
    }
}

/// The first impact velocity at which `f`'s quantity `q` reaches `h_in` (inches).
pub fn velocity_for(f: Formula, q: Quantity, m: &Missile, t: &Target, h_in: f64) -> Threshold {
    if !f.defines(q) {
        return Threshold::NotDefined;
    }
    // Missing values (Adeli–Amin beyond its fit) count as not reached.
    let gap = |v_fps: f64| f.evaluate(q, m, t, v_fps).map_or(-1.0, |h| h - h_in);
    let (lo, hi) = (units::mps_to_fps(SCAN_MIN_MPS), units::mps_to_fps(SCAN_MAX_MPS));
    if gap(lo) >= 0.0 {
        return Threshold::AnyVelocity;
    }
    let ratio = (hi / lo).powf(1.0 / SCAN_STEPS as f64);
    let found = |a: f64, b: f64| {
        let (a, b) = first_sub_bracket(&gap, a, b);
        let v_fps = bisect(&gap, a, b);
        Threshold::Velocity { v_fps, validity: f.validity(q, m, t, v_fps) }
    };
    // Samples x[k-2], x[k-1], x[k] with their gaps; all gaps so far are negative.
    let (mut x2, mut g2) = (lo, gap(lo));
    let (mut x1, mut g1) = (lo, g2);
    for k in 1..=SCAN_STEPS {
        let x = if k == SCAN_STEPS { hi } else { lo * ratio.powi(k as i32) };
        let g = gap(x);
        if g >= 0.0 {
            return found(x1, x);
        }
        // A sampled local maximum below zero may hide a crossing narrower than the scan's
        // step (the top of Adeli–Amin's parabolas, the end of a branch that then jumps down):
        // look for the true maximum between the neighbouring samples.
        if k >= 2 && g1 > g2 && g1 >= g {
            let (xm, gm) = golden_max(&gap, x2, x);
            if gm >= 0.0 {
                return found(x2, xm);
            }
        }
        (x2, g2, x1, g1) = (x1, g1, x, g);
    }
    Threshold::NotReachable
}

/// Scabbing velocity for the target's own thickness.
pub fn scabbing_velocity(f: Formula, m: &Missile, t: &Target) -> Threshold {
    velocity_for(f, Quantity::Scabbing, m, t, t.thickness_in)
}

/// Ballistic limit (perforation velocity) for the target's own thickness.
pub fn ballistic_limit(f: Formula, m: &Missile, t: &Target) -> Threshold {
    velocity_for(f, Quantity::Perforation, m, t, t.thickness_in)
}

/// Golden-section search for the largest gap in [a, b]; returns (velocity, gap). Exact for a
/// unimodal gap; at a downward jump it closes in on the jump's left side.
fn golden_max(gap: &impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> (f64, f64) {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let (mut c, mut d) = (b - r * (b - a), a + r * (b - a));
    let (mut gc, mut gd) = (gap(c), gap(d));
    let mut best = if gc >= gd { (c, gc) } else { (d, gd) };
    for _ in 0..200 {
        if gc >= gd {
            (b, d, gd) = (d, c, gc);
            c = b - r * (b - a);
            gc = gap(c);
        } else {
            (a, c, gc) = (c, d, gd);
            d = a + r * (b - a);
            gd = gap(d);
        }
        for (x, g) in [(c, gc), (d, gd)] {
            if g > best.1 {
                best = (x, g);
            }
        }
        if best.1 >= 0.0 || b - a <= 1e-15 * b {
            break;
        }
    }
    best
}

/// The first of [`SUB_STEPS`] equal sub-intervals of [a, b] (gap(a) < 0 ≤ gap(b)) that
/// brackets a crossing.
fn first_sub_bracket(gap: &impl Fn(f64) -> f64, a: f64, b: f64) -> (f64, f64) {
    let h = (b - a) / SUB_STEPS as f64;
    let mut lo = a;
    for k in 1..SUB_STEPS {
        let x = a + h * k as f64;
        if gap(x) >= 0.0 {
            return (lo, x);
        }
        lo = x;
    }
    (lo, b)
}

/// Narrow `gap(a) < 0 ≤ gap(b)` until a and b are adjacent doubles; returns b, the least
/// velocity found at which the thickness is reached.
fn bisect(gap: &impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    loop {
        let mid = 0.5 * (a + b);
        if mid <= a || mid >= b {
            return b;
        }
        if gap(mid) >= 0.0 { b = mid } else { a = mid }
    }
}
