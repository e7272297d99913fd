//! `demsweep converge --mesh 3 [--case cantilever|cracked-plate|penetration] [--ratio 2]`.

use std::path::PathBuf;

use crate::converge::{self, Case, Class, Plan};
use crate::error::Result;

/// Arguments of `demsweep converge`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Number of refinement levels, from level 0.
    #[arg(long, default_value_t = 3)]
    pub mesh: u32,
    /// The case.
    #[arg(long, value_enum, default_value = "penetration")]
    pub case: Case,
    /// Element-size ratio between levels (each case has its own: cantilever 3, the others 2).
    #[arg(long)]
    pub ratio: Option<f64>,
    /// Penetration: the scene.
    #[arg(long, default_value = "sweeps/penetration.toml")]
    pub scene: PathBuf,
    /// Penetration: impact velocity, ft/s.
    #[arg(long, default_value_t = 500.0)]
    pub v0: f64,
    /// Penetration: packings per level (target seeds from the scene's on), each level's depth
    /// their mean (1: the scene's own packing). More than one needs an irregular target.
    #[arg(long, default_value_t = 1)]
    pub packings: u32,
    /// Output folder.
    #[arg(long, default_value = "results/converge")]
    pub out: PathBuf,
    /// Threads (penetration levels run in parallel, one thread each).
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// No progress display.
    #[arg(long)]
    pub quiet: bool,
    /// What to do with the runs the folder holds already.
    #[command(flatten)]
    pub reuse: super::ReuseArgs,
}

/// Run the study and print its tables.
pub fn run(args: Args) -> Result<()> {
    let started = std::time::SystemTime::now();
    let plan = Plan {
        case: args.case,
        mesh: args.mesh,
        ratio: args.ratio.unwrap_or(args.case.ratio()),
        scene: args.scene,
        v0_fps: args.v0,
        packings: args.packings,
        out: args.out.clone(),
        threads: args.threads,
        quiet: args.quiet,
        reuse: args.reuse.reuse(),
    };
    let report = converge::run(&plan)?;
    let (levels, summary) = converge::tables(&report);
    print!("{}", String::from_utf8_lossy(&levels.to_csv()?));
    print!("{}", String::from_utf8_lossy(&summary.to_csv()?));
    match &report.class {
        Class::None(why) => println!("no observed order: {why}"),
        Class::OutcomeChanges(why) => println!("no observed order: the levels end in different outcomes ({why})"),
        _ => {}
    }
    println!("tables in {}", args.out.display());
    crate::provenance::write_manifest(&args.out, started)?;
    println!("report: {}", crate::report::write(&args.out)?.display());
    Ok(())
}
