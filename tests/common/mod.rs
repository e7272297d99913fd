//! Shared test helpers: materials and small scenes for the kernel tests; the report's scenario
//! and rounding helpers for the empirical tests.
#![allow(dead_code)]

pub mod golden;
pub mod impact;

use demsweep::empirical::{Formula, Missile, Nose, Target, inverse};
use demsweep::material::{FailureCriterion, Material};

/// The cracked-plate concrete of seed §4–5: E = 29.7 GPa, ν = 0.3, σ_ult = 3.44 MPa,
/// K_Ic = 1 MPa√m.
pub fn plate_concrete(failure: FailureCriterion) -> Material {
    demsweep::cases::cracked_plate::material(failure)
}

/// An elastic material that never breaks.
pub fn elastic(e_pa: f64, nu: f64, rho: f64) -> Material {
    Material { tensile_strength_pa: 1.0, compressive_strength_pa: 1.0, fracture_toughness_pa_sqrt_m: 1.0, ..Material::elastic("elastic", e_pa, nu, rho) }
}

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
