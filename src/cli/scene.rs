//! `demsweep scene <case>`: print a validation case as a scene file (TOML), the tool that
//! writes the scenes under `sweeps/` (never edited by hand).

use crate::cases::{cantilever, cracked_plate};
use crate::error::Result;

/// Which case.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Case {
    /// Cantilever under a sinusoidal tip load (close-packed, seed §4).
    Cantilever,
    /// Edge-cracked plate, energy criterion, close-packed (seed §5).
    CrackedPlateEnergy,
    /// Edge-cracked plate, toughness criterion, simple cubic (seed §4).
    CrackedPlateToughness,
}

/// Arguments of `demsweep scene`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// The case.
    #[arg(value_enum)]
    pub case: Case,
    /// Refinement level (0 coarsest).
    #[arg(long, default_value_t = 0)]
    pub level: u32,
    /// Cracked plate without its crack.
    #[arg(long)]
    pub uncracked: bool,
}

/// Print the scene.
pub fn run(args: Args) -> Result<()> {
    let scene = match args.case {
        Case::Cantilever => cantilever::scene(args.level)?,
        Case::CrackedPlateEnergy | Case::CrackedPlateToughness => {
            let study = if args.case == Case::CrackedPlateEnergy {
                cracked_plate::Study::EnergyClosePacked
            } else {
                cracked_plate::Study::ToughnessSimpleCubic
            };
            cracked_plate::scene(study, args.level, !args.uncracked, &cracked_plate::Setup::default())
        }
    };
    println!("# Written by `demsweep scene {:?} --level {}{}`: regenerate, do not edit.", args.case, args.level, if args.uncracked { " --uncracked" } else { "" });
    print!("{}", scene.to_toml());
    Ok(())
}
