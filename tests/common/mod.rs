//! Shared by the empirical integration tests: the report's scenario and rounding helpers.
#![allow(dead_code)]

use demsweep::empirical::{Formula, Missile, Nose, Target, inverse};

/// The report's missile with `nose`.
pub fn missile(nose: Nose) -> Missile {
    Missile::report(nose)
}

/// The report's 30 in wall.
pub fn target() -> Target {
    Target::report()
}

/// `x` rounded to `decimals` decimals, as FORMULAS.md prints it.
pub fn round(x: f64, decimals: i32) -> f64 {
    let s = 10f64.powi(decimals);
    (x * s).round() / s
}

/// The scabbing velocity, ft/s, for the scenario; panics if there is none.
pub fn v_scab(f: Formula, nose: Nose) -> f64 {
    inverse::scabbing_velocity(f, &missile(nose), &target()).v_fps().expect("a scabbing velocity")
}

/// The ballistic limit, ft/s, for the scenario; panics if there is none.
pub fn v_perf(f: Formula, nose: Nose) -> f64 {
    inverse::ballistic_limit(f, &missile(nose), &target()).v_fps().expect("a ballistic limit")
}
