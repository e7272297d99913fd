//! Command-line interface: one subcommand per module, each a thin call into the library.

use clap::{Parser, Subcommand};

pub mod bench;
pub mod empirical;
pub mod range;
pub mod run;
pub mod scene;
pub mod validate;

/// demsweep: deterministic 2D DEM of concrete impact, with the empirical formulas beside it.
#[derive(Debug, Parser)]
#[command(name = "demsweep", version, about, long_about = None)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

/// Subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Run one scene file and write its summary and time series.
    Run(run::Args),
    /// Run a validation case at several refinements and write its convergence table.
    Validate(validate::Args),
    /// Print a validation case as a scene file (TOML).
    Scene(scene::Args),
    /// Measure the kernel's speed (ns per contact-step, element-steps per second).
    Bench(bench::Args),
    /// Empirical concrete-impact formulas: penetration, scabbing and perforation thickness.
    Empirical(empirical::Args),
}

/// Run the parsed command.
pub fn dispatch(cli: Cli) -> crate::error::Result<()> {
    match cli.command {
        Command::Run(args) => run::run(args),
        Command::Bench(args) => bench::run(args),
        Command::Scene(args) => scene::run(args),
        Command::Validate(args) => validate::run(args),
        Command::Empirical(args) => empirical::run(args),
    }
}
