//! Command-line interface: one subcommand per module, each a thin call into the library.

use clap::{Parser, Subcommand};

pub mod ballistic;
pub mod bench;
pub mod calibrate;
pub mod chart;
pub mod converge;
pub mod empirical;
pub mod report;
pub mod run;
pub mod scene;
pub mod sweep;
pub mod timestep;
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
    /// Calibrate a penetration scene's strength factor to a depth at a velocity (the source's
    /// calibration) and write the calibrated scene.
    Calibrate(calibrate::Args),
    /// Run a scene over a grid of field values or a parameter table, in parallel.
    Sweep(sweep::Args),
    /// Scabbing and perforation thresholds of a penetration scene: a velocity sweep, then
    /// bisection of both thresholds, with the empirical formulas beside them.
    Ballistic(ballistic::Args),
    /// A design chart: both thresholds at several target thicknesses (a ballistic sweep each),
    /// drawn as thickness against velocity over the empirical formulas' curves.
    Chart(chart::Args),
    /// Refine a case and report observed orders, the Richardson extrapolate, GCI and cost.
    Converge(converge::Args),
    /// Join the shards of a ballistic sweep (`ballistic --shard i/n`) into one set of tables.
    Merge(ballistic::MergeArgs),
    /// Empirical concrete-impact formulas: penetration, scabbing and perforation thickness.
    Empirical(empirical::Args),
    /// Run a penetration scene and measure its top frequency as it goes: the step against the
    /// measured instability threshold.
    Timestep(timestep::Args),
    /// Write an output folder's `report.html` again from its tables (the sweeps write it).
    Report(report::Args),
}

/// What to do with the runs an output folder holds already: one pair of flags for every command
/// that sweeps.
#[derive(Debug, clap::Args)]
pub struct ReuseArgs {
    /// Remove the folder's old tables first and make every run again.
    #[arg(long, conflicts_with = "reuse_older")]
    pub fresh: bool,
    /// Keep the folder's runs made by another commit of demsweep when this same build made
    /// them (a commit that changed no physics); without it a folder holding another commit's
    /// runs is refused.
    #[arg(long)]
    pub reuse_older: bool,
}

impl ReuseArgs {
    /// The flags as the store takes them.
    pub fn reuse(&self) -> crate::sweep::Reuse {
        match (self.fresh, self.reuse_older) {
            (true, _) => crate::sweep::Reuse::Nothing,
            (false, true) => crate::sweep::Reuse::SameBuild,
            (false, false) => crate::sweep::Reuse::SameCommit,
        }
    }
}

/// Run the parsed command.
pub fn dispatch(cli: Cli) -> crate::error::Result<()> {
    match cli.command {
        Command::Run(args) => run::run(args),
        Command::Bench(args) => bench::run(args),
        Command::Scene(args) => scene::run(args),
        Command::Validate(args) => validate::run(args),
        Command::Empirical(args) => empirical::run(args),
        Command::Calibrate(args) => calibrate::run(args),
        Command::Sweep(args) => sweep::run(args),
        Command::Ballistic(args) => ballistic::run(args),
        Command::Merge(args) => ballistic::merge(args),
        Command::Converge(args) => converge::run(args),
        Command::Chart(args) => chart::run(args),
        Command::Timestep(args) => timestep::run(args),
        Command::Report(args) => report::run(args),
    }
}
