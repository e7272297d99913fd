//! Cantilever under a sinusoidal tip load (seed 000 §4, Fig 4.1–4.2, Table 4.1).
//!
//! The seed gives E = 1.2 GPa, ν = 0.3, close-packed meshes of 81 / 729 / 6561 elements (element
//! size ÷3), a tip load at 0.2 ω_n and 10 % of critical damping at that frequency, but not the
//! beam's size. Ours: plane stress, L = 10 m, t = 1 m, ρ = 2000 kg/m³, F = 1 kN, and
//! `27·3ᵏ` columns × `3·3ᵏ` rows of elements of radius R = L/(2·27·3ᵏ), which gives exactly the
//! seed's counts. A close-packed row stands for a strip √3 R high, so the continuum beam the
//! meshes converge to is L × h with h = 3·3ᵏ·√3 R = L√3/18 ≈ 0.962 m (area per element 2√3 R²).
//! Two columns of elements left of x = 0 are fixed (the clamp); the last column shares the load
//! and its mean vertical displacement is the tip deflection.
//!
//! Damping "ξ = 10 % at the forcing frequency" is read as mass-proportional Rayleigh damping,
//! α = 2ξω: with a stiffness-proportional term ξ would grow with frequency to ≫ 1 at the mesh's
//! top frequency. The reference solution uses the same damping (modal ξ_k = α/(2ω_k)).

use crate::analysis::{Beam, CantileverModes, Theory, sdof_natural_rad_per_s, sdof_tip_amplitude_m};
use crate::error::Result;
use crate::kernel::boundary::Profile;
use crate::lattice::Rect;
use crate::material::{Arrangement, Material, Plane};
use crate::kernel::Model;
use crate::run::RunResult;
use crate::scene::{Damping, DampingPoint, FixSpec, General, LoadSpec, OutputSpec, ProbeQuantity, ProbeSpec, Scene, TimeStep};

/// Free length, m.
pub const LENGTH_M: f64 = 10.0;
/// Out-of-plane thickness, m.
pub const THICKNESS_M: f64 = 1.0;
/// Young's modulus, Pa (seed).
pub const MODULUS_PA: f64 = 1.2e9;
/// Poisson's ratio (seed).
pub const POISSON: f64 = 0.3;
/// Density, kg/m³.
pub const DENSITY_KG_PER_M3: f64 = 2000.0;
/// Tip load amplitude, N (small enough that the response is linear: tip/L ≈ 4e-4).
pub const FORCE_N: f64 = 1000.0;
/// Forcing frequency over the fundamental (seed).
pub const FORCING_RATIO: f64 = 0.2;
/// Critical-damping ratio at the forcing frequency (seed).
pub const DAMPING_RATIO: f64 = 0.1;
/// Refinement ratio between levels.
pub const REFINEMENT: f64 = 3.0;

/// Columns of free elements at level k.
pub fn columns(level: u32) -> usize {
    27 * 3usize.pow(level)
}

/// Rows at level k.
pub fn rows(level: u32) -> usize {
    3 * 3usize.pow(level)
}

/// Element radius at level k, m.
pub fn radius_m(level: u32) -> f64 {
    LENGTH_M / (2.0 * columns(level) as f64)
}

/// Depth of the continuum beam the meshes represent, m.
pub fn depth_m() -> f64 {
    rows(0) as f64 * 3f64.sqrt() * radius_m(0)
}

/// The continuum beam.
pub fn beam() -> Beam {
    Beam::rectangular(LENGTH_M, depth_m(), THICKNESS_M, MODULUS_PA, POISSON, DENSITY_KG_PER_M3)
}

/// Analytic references for the steady tip amplitude.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reference {
    /// Timoshenko fundamental, rad/s.
    pub omega1_rad_per_s: f64,
    /// Forcing frequency, rad/s.
    pub forcing_rad_per_s: f64,
    /// Mass-proportional damping α, 1/s.
    pub alpha_per_s: f64,
    /// Timoshenko modal solution, m.
    pub timoshenko_m: f64,
    /// Euler–Bernoulli modal solution, m.
    pub euler_bernoulli_m: f64,
    /// The seed's SDOF model, m.
    pub sdof_m: f64,
    /// SDOF natural frequency 3.52 √(EI/(M L³)), rad/s.
    pub sdof_omega_rad_per_s: f64,
}

/// Compute the references.
pub fn reference() -> Result<Reference> {
    let b = beam();
    let timo = CantileverModes::new(&b, Theory::Timoshenko)?;
    let eb = CantileverModes::new(&b, Theory::EulerBernoulli)?;
    let w1 = timo.fundamental_rad_per_s();
    let w = FORCING_RATIO * w1;
    let alpha = 2.0 * DAMPING_RATIO * w;
    Ok(Reference {
        omega1_rad_per_s: w1,
        forcing_rad_per_s: w,
        alpha_per_s: alpha,
        timoshenko_m: timo.tip_amplitude_m(FORCE_N, w, alpha),
        euler_bernoulli_m: eb.tip_amplitude_m(FORCE_N, w, alpha),
        sdof_m: sdof_tip_amplitude_m(&b, FORCE_N, w, alpha),
        sdof_omega_rad_per_s: sdof_natural_rad_per_s(&b),
    })
}

/// Forcing periods simulated: the transients decay as exp(−αt/2) in every mode (ξ_k ω_k = α/2),
/// i.e. by e⁻¹ every 1/(2π ξ ρ) ≈ 1.6 periods at ξ = 0.1 at the forcing frequency; 24 periods
/// leave e^−15 ≈ 3e-7 of them.
pub const PERIODS: f64 = 24.0;
/// Periods at the end over which the steady amplitude is fitted.
pub const FIT_PERIODS: f64 = 2.0;

/// The scene at refinement level k (0, 1, 2: 81, 729, 6561 free elements).
pub fn scene(level: u32) -> Result<Scene> {
    let r = reference()?;
    let rad = radius_m(level);
    let ny = rows(level);
    let height = 2.0 * rad + (ny - 1) as f64 * 3f64.sqrt() * rad + 0.5 * rad;
    let period = std::f64::consts::TAU / r.forcing_rad_per_s;
    let all = |x0: f64, x1: f64| Rect { x_min_m: x0, x_max_m: x1, y_min_m: -1.0, y_max_m: height + 1.0 };
    let tip = all(LENGTH_M - 2.5 * rad, LENGTH_M + rad);
    Ok(Scene {
        scene: General {
            name: format!("cantilever_l{level}"),
            plane: Plane::Stress,
            thickness_m: THICKNESS_M,
            duration_s: PERIODS * period,
            gravity_mps2: [0.0, 0.0],
        },
        time_step: TimeStep::default(),
        damping: Damping { points: vec![DampingPoint { omega_rad_per_s: r.forcing_rad_per_s, ratio: DAMPING_RATIO }], ..Default::default() },
        material: vec![Material::elastic("beam", MODULUS_PA, POISSON, DENSITY_KG_PER_M3)],
        body: vec![crate::scene::BodySpec {
            shape: None,
            name: "beam".into(),
            material: "beam".into(),
            lattice: Arrangement::ClosePacked,
            element_radius_m: rad,
            rect: Some(Rect { x_min_m: -4.0 * rad, x_max_m: LENGTH_M, y_min_m: 0.0, y_max_m: height }),
            velocity_mps: [0.0, 0.0],
            seed: 0,
            bond_gap_ratio: None,
            region: vec![],
        }],
        crack: vec![],
        fix: vec![FixSpec { name: "clamp".into(), rect: all(-5.0 * rad, -0.5 * rad), velocity_mps: [0.0, 0.0], profile: Profile::Constant, dofs: crate::scene::all_dofs() }],
        load: vec![LoadSpec {
            name: "tip".into(),
            rect: tip,
            force_n: [0.0, FORCE_N],
            profile: Profile::Sine { omega_rad_per_s: r.forcing_rad_per_s },
            servo: None,
        }],
        probe: vec![ProbeSpec { name: "tip_uy_m".into(), quantity: ProbeQuantity::MeanDisplacementYM, rect: Some(tip), load: None }],
        output: OutputSpec { every_steps: 1 },
    })
}

/// Run level k and return (steady tip amplitude m, the run). Probes are recorded about 400
/// times per forcing period.
pub fn run(level: u32) -> Result<(f64, RunResult<Model>)> {
    let r = reference()?;
    let mut built = scene(level)?.build()?;
    let period = std::f64::consts::TAU / r.forcing_rad_per_s;
    built.every_steps = ((period / 400.0 / built.model.dt_s()) as u64).max(1);
    let result = crate::run::run(built, &mut |_| {})?;
    Ok((steady_amplitude_m(&result, r.forcing_rad_per_s), result))
}

/// Fit the steady amplitude over the last [`FIT_PERIODS`] periods of `tip_uy_m`.
pub fn steady_amplitude_m(result: &RunResult<Model>, omega_rad_per_s: f64) -> f64 {
    let t = result.column("time_s").expect("time column");
    let u = result.column("tip_uy_m").expect("tip probe");
    let t_end = *t.last().unwrap();
    let from = t_end - FIT_PERIODS * std::f64::consts::TAU / omega_rad_per_s;
    let k = t.iter().position(|&x| x >= from).unwrap_or(0);
    crate::cases::fit::sinusoid_amplitude(&t[k..], &u[k..], omega_rad_per_s).0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn meshes_have_the_seeds_counts() {
        for (level, n) in [(0, 81), (1, 729)] {
            let built = scene(level).unwrap().build().unwrap();
            let free = (0..built.model.el.len()).filter(|&e| !built.model.el.is_kinematic(e)).count();
            assert_eq!(free, n);
        }
    }
}
