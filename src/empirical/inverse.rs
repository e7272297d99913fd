//! Inverse: the impact velocity at which a formula's h_s (scabbing velocity) or h_p (ballistic
//! limit) equals a given thickness, by bracketing and bisection (FORMULAS §5).
//!
//! Not every formula is monotone (Adeli–Amin's quadratics turn over, Haldar–Hamieh and the
//! Kennedy/Hughes h_p branches jump slightly), so the answer is the *first* velocity at which the
//! thickness is reached: a log-uniform scan over [`SCAN_MIN_MPS`, `SCAN_MAX_MPS`] finds the first
//! sign change, then bisection narrows it to the last representable bit. A formula whose curve
//! never reaches the thickness in the scan says so ([`Threshold::NotReachable`]).

use super::{Formula, Missile, Quantity, Target, Validity};
use crate::units;

/// Lower end of the scan, m/s.
pub const SCAN_MIN_MPS: f64 = 1.0;
/// Upper end of the scan, m/s.
pub const SCAN_MAX_MPS: f64 = 5000.0;
/// Scan intervals: fine enough (0.43 % per step) that no fold of the fitted curves is jumped.
pub const SCAN_STEPS: usize = 2000;

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
    let mut a = lo;
    for k in 1..=SCAN_STEPS {
        let b = if k == SCAN_STEPS { hi } else { lo * ratio.powi(k as i32) };
        if gap(b) >= 0.0 {
            let v_fps = bisect(&gap, a, b);
            return Threshold::Velocity { v_fps, validity: f.validity(q, m, t, v_fps) };
        }
        a = b;
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
