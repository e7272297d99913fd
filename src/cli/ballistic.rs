//! `demsweep ballistic --v0 500..1500 [--step 50] [--tol-fps 5] [--scene …]`: the scabbing and
//! perforation thresholds of a penetration scene (`ballistic`), and `demsweep merge`, which
//! joins the shards of one sweep.

use std::path::PathBuf;

use crate::ballistic::{self, Plan, Report, parse_shard};
use crate::error::Result;

/// Arguments of `demsweep ballistic`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Impact velocities, ft/s: START..END (inclusive).
    #[arg(long, default_value = "500..1500")]
    pub v0: String,
    /// Step, ft/s.
    #[arg(long, default_value_t = 50.0)]
    pub step: f64,
    /// Bisect each threshold to this bracket width, ft/s.
    #[arg(long, default_value_t = 5.0)]
    pub tol_fps: f64,
    /// The penetration scene.
    #[arg(long, default_value = "sweeps/penetration.toml")]
    pub scene: PathBuf,
    /// Output folder: runs.csv, runs.parquet, thresholds.csv, ballistic.png, sweep.toml.
    #[arg(long, default_value = "results/ballistic")]
    pub out: PathBuf,
    /// Threads, one run each (0: one per core).
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// Run shard i of n of the grid only (1 ≤ i ≤ n), without bisection: `merge --bisect`
    /// finishes the sweep.
    #[arg(long, value_name = "i/n")]
    pub shard: Option<String>,
    /// Remove the folder's old tables first (a changed scene).
    #[arg(long)]
    pub fresh: bool,
    /// No progress display.
    #[arg(long)]
    pub quiet: bool,
}

/// Arguments of `demsweep merge`.
#[derive(Debug, clap::Args)]
pub struct MergeArgs {
    /// Shard folders (each written by `ballistic --shard i/n`).
    #[arg(required = true)]
    pub dirs: Vec<PathBuf>,
    /// Output folder.
    #[arg(long, default_value = "results/ballistic")]
    pub out: PathBuf,
    /// Then bisect the thresholds and write thresholds.csv (runs the bisection's runs here).
    #[arg(long)]
    pub bisect: bool,
    /// Threads for the bisection.
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// No progress display.
    #[arg(long)]
    pub quiet: bool,
}

fn print(r: &Report, out: &std::path::Path) {
    if r.thresholds.rows.is_empty() {
        println!("{} runs made, {} found done; runs in {}", r.ran, r.skipped, out.display());
        return;
    }
    for name in ["scabbing", "perforation"] {
        let f = if name == "scabbing" { &r.scabbing } else { &r.perforation };
        match f.bracket {
            crate::ballistic::bracket::Bracket::Between { lo_fps, hi_fps } => {
                println!("{name:>12}: {:.1} ft/s (none at {lo_fps}, seen at {hi_fps} ft/s) {}", 0.5 * (lo_fps + hi_fps), f.note(name))
            }
            _ => println!("{name:>12}: {}", f.note(name)),
        }
    }
    for (name, fit) in [("Lambert–Jonas", r.lambert_jonas), ("Recht–Ipson", r.recht_ipson)] {
        if let Some(f) = fit {
            println!("{name:>14}: V_bl = {:.1} ft/s, a = {:.4}, p = {:.3}, rms {:.2} ft/s over {} runs", f.v_bl_fps, f.a, f.p, f.rms_fps, f.points);
        }
    }
    println!("{} runs made, {} found done; tables in {}", r.ran, r.skipped, out.display());
}

/// Run the sweep.
pub fn run(args: Args) -> Result<()> {
    let (v0_min_fps, v0_max_fps) = super::range::parse("--v0", &args.v0)?;
    let shard = args.shard.as_deref().map(parse_shard).transpose()?;
    let plan = Plan {
        scene: args.scene,
        v0_min_fps,
        v0_max_fps,
        step_fps: args.step,
        tol_fps: args.tol_fps,
        out: args.out.clone(),
        threads: args.threads,
        quiet: args.quiet,
        fresh: args.fresh,
        shard,
    };
    let report = ballistic::run(&plan)?;
    print(&report, &args.out);
    Ok(())
}

/// Merge shards.
pub fn merge(args: MergeArgs) -> Result<()> {
    let report = ballistic::merge(&args.dirs, &args.out, args.bisect, args.threads, args.quiet)?;
    print(&report, &args.out);
    Ok(())
}
