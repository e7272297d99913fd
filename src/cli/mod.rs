//! Command-line interface: one subcommand per module, each a thin call into the library.

use clap::{Parser, Subcommand};

pub mod empirical;
pub mod range;

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
    /// Empirical concrete-impact formulas: penetration, scabbing and perforation thickness.
    Empirical(empirical::Args),
}

/// Run the parsed command.
pub fn dispatch(cli: Cli) -> crate::error::Result<()> {
    match cli.command {
        Command::Empirical(args) => empirical::run(args),
    }
}
