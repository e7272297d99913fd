//! `demsweep validate <case>`: run a validation case at several refinement levels and write its
//! convergence table (figure, cost, order, Richardson extrapolate, GCI) under `results/validation/`.

use std::path::PathBuf;

use crate::cases::cracked_plate::{self, Continuum, Grips, Study};
use crate::cases::study::{self, Level};
use crate::cases::cantilever;
use crate::error::{Error, Result};
use crate::table::Table;

/// Which study.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Case {
    /// Cantilever tip amplitude, close-packed, 81 / 729 / 6561 elements.
    Cantilever,
    /// Cracked plate: energy criterion (close-packed), toughness criterion (simple cubic) and
    /// the uncracked plate, with the seed's displacement-driven edges (rollers) and with
    /// uniform traction (tables suffixed `_traction`).
    CrackedPlate,
}

/// Arguments of `demsweep validate`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The study.
    #[arg(value_enum)]
    pub case: Case,
    /// Refinement levels (three give the observed order and the extrapolate).
    #[arg(long, value_delimiter = ',', default_values_t = vec![0u32, 1, 2])]
    pub levels: Vec<u32>,
    /// Output folder.
    #[arg(long, default_value = "results/validation")]
    pub out: PathBuf,
}

fn emit(out: &std::path::Path, name: &str, table: &Table) -> Result<()> {
    let path = out.join(format!("{name}.csv"));
    table.write_csv(&path)?;
    println!("{}", path.display());
    println!("{}", String::from_utf8_lossy(&table.to_csv()?));
    Ok(())
}

/// Run the study.
pub fn run(args: Args) -> Result<()> {
    if args.levels.is_empty() || args.levels.iter().any(|&l| l > 4) {
        return Err(Error::input("--levels", format!("give levels from 0 to 4, got {:?}", args.levels)));
    }
    match args.case {
        Case::Cantilever => {
            let r = cantilever::reference()?;
            let levels: Vec<Level> = args
                .levels
                .iter()
                .map(|&l| {
                    study::timed(l, || {
                        let (a, res) = cantilever::run(l)?;
                        Ok((cantilever::columns(l) * cantilever::rows(l), a, res))
                    })
                })
                .collect::<Result<_>>()?;
            let (t, _) = study::table("tip_amplitude_m", r.timoshenko_m, &levels, cantilever::REFINEMENT);
            emit(&args.out, "cantilever", &t)?;
            println!(
                "references: Timoshenko {:.7e} m, Euler–Bernoulli {:.7e} m, SDOF {:.7e} m; ω1 = {:.6} rad/s (SDOF 3.52√(EI/ML³) = {:.6})",
                r.timoshenko_m, r.euler_bernoulli_m, r.sdof_m, r.omega1_rad_per_s, r.sdof_omega_rad_per_s
            );
        }
        Case::CrackedPlate => {
            for (grips, suffix) in [(Grips::Rollers, ""), (Grips::UniformTraction, "_traction")] {
                let setup = cracked_plate::Setup::with_grips(grips);
                // Each study against the continuum reference for the same plate and grips (the
                // decision of [1/5]): the energy criterion converges to a cohesive crack, the
                // brittle toughness criterion to linear fracture mechanics.
                let continuum = |m| cracked_plate::continuum_pa(grips, m).expect("the continuum table covers these grips");
                for (name, study_kind, cracked, reference) in [
                    ("cracked_plate_energy", Study::EnergyClosePacked, true, continuum(Continuum::Cohesive)),
                    ("cracked_plate_toughness", Study::ToughnessSimpleCubic, true, continuum(Continuum::Lefm)),
                    ("cracked_plate_uncracked", Study::EnergyClosePacked, false, cracked_plate::TENSILE_PA),
                ] {
                    let levels: Vec<Level> = args
                        .levels
                        .iter()
                        .map(|&l| {
                            study::timed(l, || {
                                let (p, res) = cracked_plate::run(study_kind, l, cracked, &setup)?;
                                Ok((p.elements, p.stress_pa, res))
                            })
                        })
                        .collect::<Result<_>>()?;
                    let (t, _) = study::table("peak_stress_pa", reference, &levels, cracked_plate::REFINEMENT);
                    emit(&args.out, &format!("{name}{suffix}"), &t)?;
                }
            }
        }
    }
    Ok(())
}
