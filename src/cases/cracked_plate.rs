//! Plate with an edge crack under Mode I (seed 000 §4 Fig 4.3, §5 Fig 5.5; SPEC §3).
//!
//! Square plate, width c = height = 0.25 m, edge crack a = 0.03125 m (a/c = 1/8) at mid-height
//! from the left edge, E = 29.7 GPa, ν = 0.3, K_Ic = 1 MPa√m, σ_ult = 3.44 MPa, plane stress
//! (plane strain would give ν* = 0.43 > 1/3, which a close-packed lattice cannot represent).
//! Two studies, as the seed:
//! * energy criterion (eq 5.5–5.9) on close-packed meshes with element diameter a/4, a/8, a/16
//!   (≈ 1 200 / 4 700 / 18 900 elements);
//! * toughness criterion (eq 3.10) on simple cubic meshes 16², 32², 64² with Kn = Kt = E t.
//!
//! Loading (the seed: "the upper boundary moves in the upward direction and the lower boundary
//! moves an equal amount in the downward direction"): by default [`Grips::Rollers`], the top
//! and bottom rows move apart at a constant speed, free to slide sideways. The far-field
//! stress is the grips' reaction over the lattice's net width ([`net_width_m`]); its peak is
//! the stress at unstable crack growth. Two other grips are available for comparison:
//! [`Grips::Clamped`] and [`Grips::UniformTraction`] (whiffle-tree servo grips,
//! [`crate::kernel::boundary::Servo`]: uniform traction with the plate free to rotate, which
//! is what the handbook value, eq 4.3, assumes for a long plate).
//!
//! Neither grip reproduces the handbook value, eq 4.3 (2.61 MPa), and neither should:
//! * eq 4.3 is linear fracture mechanics (LEFM) for a *long* strip under uniform tension.
//!   `scripts/cohesive_sent.py` (plane-stress FE, node release) gives 2.608 MPa for a strip
//!   of height 4c, but 2.489 MPa for this square plate under uniform traction and 3.017 MPa
//!   with its edges driven apart (`results/validation/cracked_plate_continuum.csv`).
//! * With these constants the characteristic length E G_f/σ_ult² ≈ 0.085 m is a third of the
//!   plate, so the plate is far from the small-scale yielding LEFM needs. The same FE with a
//!   rectangular cohesive law on the ligament gives 2.287 MPa under uniform traction and
//!   3.010 MPa with the edges driven apart (the net section's plastic limit σ_ult (1 − a/c)).
//!   The law is the lattice's own crack law: a row of inclined bonds carries σ_ult on its
//!   plateau (eq 5.5–5.6) up to a fixed opening (eq 5.7), and, at two bonds per 2R each
//!   dissipating G_f 2R t, G = 2.07 G_f (4 % of it in shear). The DEM extrapolates to
//!   2.361 MPa (+3.2 %) and 2.972 MPa (−1.3 %). It is a little tougher than the line model
//!   under uniform traction because bonds off the crack line yield too: the ledger's plastic
//!   work is 3.0–3.4 G_f per unit ligament area on the two coarse meshes.
//!
//! Quasi-static loading: the grips open to 3× the uncracked plate's failure strain over
//! [`LOADING_TIME_S`]; mass-proportional damping of [`DAMPING_RATIO`] at the plate's first
//! extensional mode, acting relative to the plate's rigid motion so that a free plate is not
//! held by it. The peak drifts like 1/T (−0.4 % from T to 2T at this setting).
//!
//! The rows within [`PLATEN_ROWS`] of each loaded edge are a "platen": the same material and
//! law, but [`PLATEN_TOUGHNESS_FACTOR`] times the toughness, so its bonds yield exactly like
//! the plate's and flow on their plateau instead of breaking. Without it a uniform-traction
//! grip's corner elements, which hang on a single inclined bond, yield at about half the
//! far-field strength and tear off (a glued platen prevents that in a laboratory). An elastic
//! platen would not do: the plate's shear springs reach their plateau (eq 5.6) before its
//! normal springs, and the stiffness mismatch at an elastic platen's face concentrates stress.

use crate::error::Result;
use crate::kernel::boundary::{Profile, Servo};
use crate::lattice::Rect;
use crate::material::{Arrangement, FailureCriterion, Material, Plane, PoissonPolicy};
use crate::kernel::Model;
use crate::run::RunResult;
use crate::scene::{
    BodySpec, CrackSpec, Damping, Dof, FixSpec, General, LoadSpec, OutputSpec, ProbeQuantity, ProbeSpec,
    RegionSpec, Scene, TimeStep,
};

/// Plate width c, m.
pub const WIDTH_M: f64 = 0.25;
/// Plate height, m.
pub const HEIGHT_M: f64 = 0.25;
/// Crack length a, m.
pub const CRACK_M: f64 = 0.03125;
/// Thickness, m.
pub const THICKNESS_M: f64 = 1.0;
/// E, Pa.
pub const MODULUS_PA: f64 = 29.7e9;
/// ν.
pub const POISSON: f64 = 0.3;
/// σ_ult, Pa.
pub const TENSILE_PA: f64 = 3.44e6;
/// K_Ic, Pa√m.
pub const TOUGHNESS_PA_SQRT_M: f64 = 1.0e6;
/// ρ, kg/m³.
pub const DENSITY_KG_PER_M3: f64 = 2400.0;
/// Refinement ratio between levels.
pub const REFINEMENT: f64 = 2.0;
/// Critical-damping ratio (mass-proportional) at the plate's first extensional mode.
pub const DAMPING_RATIO: f64 = 0.02;
/// Rows at each loaded edge whose bonds do not fail.
pub const PLATEN_ROWS: f64 = 3.0;
/// Toughness of the platen rows relative to the plate (G_f × its square: they never break).
pub const PLATEN_TOUGHNESS_FACTOR: f64 = 100.0;
/// Time over which the grips open to 3× the uncracked plate's failure strain, s.
pub const LOADING_TIME_S: f64 = 0.032;

/// Which of the seed's two studies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Study {
    /// Close-packed, strength + fracture-energy criterion (seed §5).
    EnergyClosePacked,
    /// Simple cubic, fracture-toughness criterion (seed §4).
    ToughnessSimpleCubic,
}

impl Study {
    fn arrangement(self) -> Arrangement {
        match self {
            Study::EnergyClosePacked => Arrangement::ClosePacked,
            Study::ToughnessSimpleCubic => Arrangement::SimpleCubic,
        }
    }

    fn failure(self) -> FailureCriterion {
        match self {
            Study::EnergyClosePacked => FailureCriterion::StrengthEnergy,
            Study::ToughnessSimpleCubic => FailureCriterion::FractureToughness,
        }
    }

    /// Element radius at level k, m.
    pub fn radius_m(self, level: u32) -> f64 {
        let base = match self {
            Study::EnergyClosePacked => CRACK_M / 8.0,
            Study::ToughnessSimpleCubic => WIDTH_M / 32.0,
        };
        base / 2f64.powi(level as i32)
    }
}

/// The handbook value (eq 4.3, corrected as SPEC §3 says), Pa: linear fracture mechanics for a
/// long strip, not this square plate (see the module documentation).
pub fn handbook_pa() -> f64 {
    crate::analysis::sent_critical_stress_pa(TOUGHNESS_PA_SQRT_M, CRACK_M, WIDTH_M)
}

/// The continuum references of this plate (`scripts/cohesive_sent.py`, plane-stress FE; the
/// table `results/validation/cracked_plate_continuum.csv` is compiled in).
const CONTINUUM_CSV: &str = include_str!("../../results/validation/cracked_plate_continuum.csv");

/// Which continuum model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Continuum {
    /// Linear fracture mechanics (node release, Richardson-extrapolated in h).
    Lefm,
    /// The lattice's crack law as a cohesive line: σ_ult up to a fixed opening, G = 2.07 G_f
    /// (finest mesh; converged to four digits).
    Cohesive,
}

/// The continuum reference for the square plate under `grips` (rollers or uniform traction),
/// Pa: what the energy criterion (cohesive) and the toughness criterion (LEFM) should converge
/// to for this plate.
pub fn continuum_pa(grips: Grips, model: Continuum) -> Option<f64> {
    let grips = match grips {
        Grips::UniformTraction => "traction",
        Grips::Rollers => "rollers",
        Grips::Clamped => return None,
    };
    let rows: Vec<Vec<&str>> = CONTINUUM_CSV.lines().skip(1).map(|l| l.split(',').collect()).collect();
    let height = |r: &Vec<&str>| r[1].parse::<f64>().is_ok_and(|h| (h - HEIGHT_M).abs() < 1e-12);
    let pick = |r: &&Vec<&str>| {
        r[0] == grips
            && height(r)
            && match model {
                Continuum::Lefm => r[2] == "lefm" && r[4] == "richardson",
                Continuum::Cohesive => r[2] == "cohesive" && r[3].parse::<f64>().is_ok_and(|g| (g - 2.07).abs() < 1e-9),
            }
    };
    // The cohesive rows come coarse to fine: the last is the finest.
    rows.iter().rfind(pick).and_then(|r| r[6].parse().ok())
}

/// How the top and bottom edges are pulled apart.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Grips {
    /// Whiffle-tree servo grips: uniform traction, rotation free (eq 4.3's uniform tension).
    UniformTraction,
    /// The edge rows move apart at a prescribed speed, free to slide sideways (rollers).
    Rollers,
    /// The edge rows move apart at a prescribed speed and are held sideways (clamped).
    Clamped,
}

/// The free parameters of the set-up (the seed gives none of them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Setup {
    /// Loading of the edges.
    pub grips: Grips,
    /// Plate height, m.
    pub height_m: f64,
    /// Time over which the grips open to 3× the uncracked plate's failure strain, s.
    pub loading_time_s: f64,
    /// Critical-damping ratio (mass-proportional) at the plate's first extensional mode.
    pub damping_ratio: f64,
}

impl Setup {
    /// The default set-up with other grips.
    pub fn with_grips(grips: Grips) -> Setup {
        Setup { grips, ..Setup::default() }
    }
}

impl Default for Setup {
    fn default() -> Self {
        Setup { grips: Grips::Rollers, height_m: HEIGHT_M, loading_time_s: LOADING_TIME_S, damping_ratio: DAMPING_RATIO }
    }
}

/// The scene for a study at level k, with or without the crack.
pub fn scene(study: Study, level: u32, cracked: bool, setup: &Setup) -> Scene {
    let height = setup.height_m;
    let loading_time_s = setup.loading_time_s;
    let r = study.radius_m(level);
    let pitch = match study {
        Study::EnergyClosePacked => 3f64.sqrt() * r,
        Study::ToughnessSimpleCubic => 2.0 * r,
    };
    // Row centres are at r + j·pitch; the crack runs between the two rows around mid-height.
    let j = ((0.5 * height - r) / pitch).floor();
    let crack_y = r + (j + 0.5) * pitch;
    let top_row = r + ((height - 2.0 * r) / pitch + 1e-9).floor() * pitch;
    let band_between = |y0: f64, y1: f64| Rect { x_min_m: -1.0, x_max_m: WIDTH_M + 1.0, y_min_m: y0, y_max_m: y1 };
    // Grip members: the loaded row without its end elements, which hang on a single bond into
    // the plate (a long row's ends) and would carry twice the bond force of the others.
    let band = |y: f64| Rect { x_min_m: 1.5 * r, x_max_m: WIDTH_M - 1.5 * r, y_min_m: y - 0.5 * r, y_max_m: y + 0.5 * r };
    let failure_strain = TENSILE_PA / MODULUS_PA;
    let rate = 3.0 * failure_strain * 0.5 * height / loading_time_s;
    // Machine stiffness: 20 × the stiffness of half the plate, so the grips control displacement.
    let k_machine = 20.0 * MODULUS_PA * THICKNESS_M * WIDTH_M / (0.5 * height);
    // First extensional mode of the free plate between the grips, for critical damping.
    let omega1 = std::f64::consts::PI * (MODULUS_PA / DENSITY_KG_PER_M3).sqrt() / height;
    let full_row = |y: f64| band_between(y - 0.5 * r, y + 0.5 * r);
    let held = |name: &str, y: f64, dir: f64| FixSpec {
        name: name.into(),
        rect: full_row(y),
        velocity_mps: [0.0, dir * rate],
        profile: Profile::Constant,
        dofs: match setup.grips {
            Grips::Clamped => vec![Dof::X, Dof::Y, Dof::Rotation],
            _ => vec![Dof::Y],
        },
    };
    let grip = |name: &str, y: f64, dir: f64| LoadSpec {
        name: name.into(),
        rect: band(y),
        force_n: [0.0, 0.0],
        profile: Profile::Constant,
        servo: Some(Servo { direction: [0.0, dir], rate_mps: rate, stiffness_n_per_m: k_machine, start_s: 0.1 * loading_time_s }),
    };
    Scene {
        scene: General {
            name: format!(
                "cracked_plate_{}_l{level}{}",
                match study {
                    Study::EnergyClosePacked => "energy",
                    Study::ToughnessSimpleCubic => "toughness",
                },
                if cracked { "" } else { "_uncracked" }
            ),
            plane: Plane::Stress,
            thickness_m: THICKNESS_M,
            duration_s: loading_time_s,
            gravity_mps2: [0.0, 0.0],
        },
        time_step: TimeStep::default(),
        damping: Damping { alpha_per_s: Some(2.0 * setup.damping_ratio * omega1), relative_to_rigid_motion: true, ..Default::default() },
        material: vec![
            Material { name: "platen".into(), fracture_toughness_pa_sqrt_m: PLATEN_TOUGHNESS_FACTOR * TOUGHNESS_PA_SQRT_M, ..concrete(study.failure()) },
            concrete(study.failure()),
        ],
        body: vec![BodySpec {
            shape: None,
            name: "plate".into(),
            material: "concrete".into(),
            lattice: study.arrangement(),
            element_radius_m: r,
            rect: Some(Rect { x_min_m: 0.0, x_max_m: WIDTH_M, y_min_m: 0.0, y_max_m: height }),
            velocity_mps: [0.0, 0.0],
            seed: 0,
            bond_gap_ratio: None,
            region: vec![
                RegionSpec { rect: band_between(-1.0, r + (PLATEN_ROWS - 0.5) * pitch), material: "platen".into() },
                RegionSpec { rect: band_between(top_row - (PLATEN_ROWS - 0.5) * pitch, 1.0), material: "platen".into() },
            ],
        }],
        crack: if cracked { vec![CrackSpec { from_m: [-r, crack_y], to_m: [CRACK_M, crack_y] }] } else { vec![] },
        fix: match setup.grips {
            Grips::UniformTraction => vec![],
            Grips::Rollers | Grips::Clamped => vec![held("top", top_row, 1.0), held("bottom", r, -1.0)],
        },
        load: match setup.grips {
            Grips::UniformTraction => vec![grip("top", top_row, 1.0), grip("bottom", r, -1.0)],
            Grips::Rollers | Grips::Clamped => vec![],
        },
        probe: vec![
            match setup.grips {
                Grips::UniformTraction => {
                    ProbeSpec { name: "grip_force_n".into(), quantity: ProbeQuantity::AppliedLoadYN, rect: None, load: Some("top".into()) }
                }
                // The plate pulls the held top row down: its reaction, negated.
                Grips::Rollers | Grips::Clamped => {
                    ProbeSpec { name: "grip_reaction_n".into(), quantity: ProbeQuantity::ForceYN, rect: Some(full_row(top_row)), load: None }
                }
            },
            ProbeSpec { name: "bonds_broken".into(), quantity: ProbeQuantity::BondsBroken, rect: None, load: None },
        ],
        output: OutputSpec { every_steps: 1 },
    }
}

/// The seed's concrete (§4–5) with the given failure criterion, as a scene material.
pub fn concrete(failure: FailureCriterion) -> Material {
    Material {
        name: "concrete".into(),
        density_kg_per_m3: DENSITY_KG_PER_M3,
        youngs_modulus_pa: MODULUS_PA,
        poisson_ratio: POISSON,
        tensile_strength_pa: TENSILE_PA,
        compressive_strength_pa: 10.0 * TENSILE_PA,
        fracture_toughness_pa_sqrt_m: TOUGHNESS_PA_SQRT_M,
        friction_coefficient: 0.5,
        cohesion_n_per_m: 0.0,
        failure,
        poisson_policy: PoissonPolicy::Refuse,
        rate: None,
        compaction: None,
    }
}

/// The same (what the kernel tests build models from).
pub fn material(failure: FailureCriterion) -> Material {
    concrete(failure)
}

/// The width over which the lattice carries a uniaxial load, m: the span of the bonds that a
/// horizontal cut crosses. A close-packed plate alternates rows of n and n − 1 elements, and a
/// cut between two rows crosses 2(n − 1) inclined bonds, each able to carry R t σ_ult of
/// vertical force (eq 5.5–5.6: f_n sin 60° + f_t cos 60°), i.e. a width (n − 1) 2R = c − 2R.
/// A simple cubic plate carries on n columns, width n 2R = c. The far-field stress is the grip
/// force over this width (the nominal c would read the uncracked plate's strength low by the
/// lattice's O(R) edge, 3 % on the coarsest mesh; both vanish with refinement).
pub fn net_width_m(study: Study, level: u32) -> f64 {
    let r = study.radius_m(level);
    let n = ((WIDTH_M - 2.0 * r) / (2.0 * r) + 1e-9).floor() + 1.0;
    match study {
        Study::EnergyClosePacked => (n - 1.0) * 2.0 * r,
        Study::ToughnessSimpleCubic => n * 2.0 * r,
    }
}

/// Peak grip force of a run, N.
pub fn peak_force_n(result: &RunResult<Model>) -> f64 {
    match result.column("grip_force_n") {
        Some(f) => f.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        None => -result.column("grip_reaction_n").expect("grip probe").iter().copied().fold(f64::INFINITY, f64::min),
    }
}

/// One mesh's result.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Peak {
    /// Peak far-field stress on the net width, Pa.
    pub stress_pa: f64,
    /// The same on the nominal width c, Pa.
    pub nominal_stress_pa: f64,
    /// Elements.
    pub elements: usize,
    /// Bonds broken by the end of the run.
    pub bonds_broken: u64,
    /// Steps.
    pub steps: u64,
}

/// Run one mesh.
pub fn run(study: Study, level: u32, cracked: bool, setup: &Setup) -> Result<(Peak, RunResult<Model>)> {
    let built = scene(study, level, cracked, setup).build()?;
    let elements = built.model.el.len();
    let result = crate::run::run(built, &mut |_| {})?;
    let f = peak_force_n(&result);
    let broken = result.column("bonds_broken").and_then(|b| b.last().copied()).unwrap_or(0.0) as u64;
    let steps = result.summary.steps;
    let peak = Peak {
        stress_pa: f / (net_width_m(study, level) * THICKNESS_M),
        nominal_stress_pa: f / (WIDTH_M * THICKNESS_M),
        elements,
        bonds_broken: broken,
        steps,
    };
    Ok((peak, result))
}
