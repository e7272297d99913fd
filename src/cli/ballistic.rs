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
    /// Step, ft/s. 100 by default: with five packings the V50 pools every run's outcome, and
    /// the packings' spread (50–100 ft/s) is wider than a finer grid would resolve.
    #[arg(long, default_value_t = 100.0)]
    pub step: f64,
    /// Bisect each packing's thresholds to this bracket width, ft/s.
    #[arg(long, default_value_t = 25.0)]
    pub tol_fps: f64,
    /// The penetration scene.
    #[arg(long, default_value = "sweeps/penetration.toml")]
    pub scene: PathBuf,
    /// Output folder: runs.csv, runs.parquet, thresholds.csv, ballistic.png, sweep.toml,
    /// pictures/, report.html.
    #[arg(long, default_value = "results/ballistic")]
    pub out: PathBuf,
    /// Threads, one run each (0: one per core).
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// Run shard i of n of the grid only (1 ≤ i ≤ n), without bisection: `merge --bisect`
    /// finishes the sweep.
    #[arg(long, value_name = "i/n")]
    pub shard: Option<String>,
    /// Packings to sweep (target seeds from the scene's on); each gets the grid and its own
    /// bisections, and the thresholds are reported as V50s with 90 % intervals. Default: 5 for
    /// an irregular target, 1 (its one packing) for a regular lattice.
    #[arg(long)]
    pub packings: Option<u32>,
    /// What to do with the runs the folder holds already.
    #[command(flatten)]
    pub reuse: super::ReuseArgs,
    /// No progress display.
    #[arg(long)]
    pub quiet: bool,
    /// Do not make again the first packing's first scabbing and first perforation runs to draw
    /// them for the report (`<out>/pictures/`; two more runs).
    #[arg(long)]
    pub no_pictures: bool,
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
    /// Merge shards of another commit (or of several) when one build made them all; without
    /// it, shards of several commits, or (with --bisect) of another commit than this program's,
    /// are refused.
    #[arg(long)]
    pub reuse_older: bool,
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
    // With several packings each has its own bisection (printed below), not one pooled.
    for name in ["scabbing", "perforation"].into_iter().filter(|_| r.packings.is_empty()) {
        let f = if name == "scabbing" { &r.scabbing } else { &r.perforation };
        match f.bracket {
            crate::ballistic::bracket::Bracket::Between { lo_fps, hi_fps } => {
                println!("{name:>12}: {:.1} ft/s (none at {lo_fps}, seen at {hi_fps} ft/s) {}", 0.5 * (lo_fps + hi_fps), f.note(name))
            }
            _ => println!("{name:>12}: {}", f.note(name)),
        }
    }
    if let Some((scab, perf)) = &r.v50 {
        for (name, v) in [("scabbing V50", scab), ("perforation V50", perf)] {
            match v {
                Some(v) => println!(
                    "{name:>16}: {:.1} ft/s, 90 % interval {} – {} ft/s ({} packings{})",
                    v.v50_fps,
                    v.lower_fps.map_or("unbounded".into(), |x| format!("{x:.1}")),
                    v.upper_fps.map_or("unbounded".into(), |x| format!("{x:.1}")),
                    r.packings.len(),
                    if v.separated { "; outcomes separate completely: Firth's penalised likelihood" } else { "" }
                ),
                None => println!("{name:>16}: every run had the same outcome"),
            }
        }
        for p in &r.packings {
            let est = |f: &crate::ballistic::bracket::Finding| f.estimate_fps().map_or_else(|| "not bracketed".to_string(), |v| format!("{v:.1}"));
            println!("{:>16}: scabbing {}, perforation {} ft/s", format!("seed {}", p.seed), est(&p.scabbing), est(&p.perforation));
        }
    }
    for (name, fit) in [("Lambert–Jonas", r.lambert_jonas), ("Recht–Ipson", r.recht_ipson)] {
        if let Some(f) = fit {
            println!("{name:>14}: V_bl = {:.1} ft/s, a = {:.4}, p = {:.3}, rms {:.2} ft/s over {} runs", f.v_bl_fps, f.a, f.p, f.rms_fps, f.points);
        }
    }
    println!("{} runs made, {} found done; tables in {}", r.ran, r.skipped, out.display());
}

/// After the tables and the report are written: an error listing the failed runs, if any.
fn failures(r: &Report) -> Result<()> {
    if r.failed.is_empty() {
        return Ok(());
    }
    let list: Vec<String> = r.failed.iter().map(|(id, m)| format!("  {id}: {m}")).collect();
    Err(crate::error::Error::input(
        "ballistic",
        format!(
            "{} run(s) failed (rows with status failed in runs.csv; the thresholds were drawn without them, and a bisection that needed one stopped at the bracket it had; a rerun retries them):\n{}",
            r.failed.len(),
            list.join("\n")
        ),
    ))
}

/// Run the sweep.
pub fn run(args: Args) -> Result<()> {
    let started = std::time::SystemTime::now();
    let (v0_min_fps, v0_max_fps) = crate::sweep::range::parse("--v0", &args.v0)?;
    let shard = args.shard.as_deref().map(parse_shard).transpose()?;
    let plan = Plan {
        scene: args.scene.clone(),
        v0_min_fps,
        v0_max_fps,
        step_fps: args.step,
        tol_fps: args.tol_fps,
        out: args.out.clone(),
        threads: args.threads,
        quiet: args.quiet,
        reuse: args.reuse.reuse(),
        shard,
        packings: match args.packings {
            Some(n) => n,
            None => ballistic::default_packings(&args.scene)?,
        },
    };
    let report = ballistic::run(&plan)?;
    print(&report, &args.out);
    // A shard has no thresholds to picture; the merge of the shards is what a user reads.
    if shard.is_none() && !args.no_pictures {
        let runs = crate::table::Table::read_csv(&crate::sweep::store::Store::csv_path(&args.out))?;
        for p in ballistic::pictures::draw(&args.scene, &runs, &args.out)? {
            println!("picture: {}", p.display());
        }
    }
    crate::provenance::write_manifest(&args.out, started)?;
    println!("report: {}", crate::report::write(&args.out)?.display());
    failures(&report)
}

/// Merge shards.
pub fn merge(args: MergeArgs) -> Result<()> {
    let started = std::time::SystemTime::now();
    let report = ballistic::merge(&args.dirs, &args.out, args.bisect, args.reuse_older, args.threads, args.quiet)?;
    print(&report, &args.out);
    crate::provenance::write_manifest(&args.out, started)?;
    println!("report: {}", crate::report::write(&args.out)?.display());
    failures(&report)
}
