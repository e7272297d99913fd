//! `demsweep chart --thickness-in 18,24,30,36 [--v0 …] [--scene …]`: the design chart — both
//! thresholds at each target thickness, over the empirical formulas' curves.

use std::path::PathBuf;

use crate::chart::{self, Plan, THICKNESS_FIELD};
use crate::error::{Error, Result};

/// Arguments of `demsweep chart`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Target thicknesses, in: `T1,T2,…` or `START..END:STEP` (inclusive); at least two.
    #[arg(long, default_value = "18,24,30,36")]
    pub thickness_in: String,
    /// Impact velocities of every thickness's grid, ft/s: START..END (inclusive); choose it to
    /// bracket both thresholds at every thickness (a threshold outside it is reported as not
    /// reached).
    #[arg(long, default_value = "300..2000")]
    pub v0: String,
    /// Grid step, ft/s.
    #[arg(long, default_value_t = 100.0)]
    pub step: f64,
    /// Bisect each packing's thresholds to this bracket width, ft/s.
    #[arg(long, default_value_t = 25.0)]
    pub tol_fps: f64,
    /// The penetration scene; each thickness is it with target.depth_in changed.
    #[arg(long, default_value = "sweeps/penetration.toml")]
    pub scene: PathBuf,
    /// Packings per thickness. Default: 5 on an irregular target, 1 on a regular lattice.
    #[arg(long)]
    pub packings: Option<u32>,
    /// Output folder: chart.csv, chart.png, report.html, and one ballistic folder per thickness
    /// (h<T>in/).
    #[arg(long, default_value = "results/chart")]
    pub out: PathBuf,
    /// Threads, one run each (0: one per core).
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// What to do with the runs the thickness folders hold already.
    #[command(flatten)]
    pub reuse: super::ReuseArgs,
    /// No progress display.
    #[arg(long)]
    pub quiet: bool,
}

/// The thicknesses of `--thickness-in`, in.
pub fn thicknesses(text: &str) -> Result<Vec<f64>> {
    let vary = crate::sweep::Vary::parse(&format!("{THICKNESS_FIELD}={text}")).map_err(|e| match e {
        Error::Input { message, .. } => Error::input("--thickness-in", message.replace(&format!("{THICKNESS_FIELD}="), "")),
        other => other,
    })?;
    vary.values
        .iter()
        .map(|v| v.as_float().or_else(|| v.as_integer().map(|i| i as f64)).ok_or_else(|| Error::input("--thickness-in", format!("`{v}` is not a thickness in inches"))))
        .collect()
}

/// Draw the chart and print its rows.
pub fn run(args: Args) -> Result<()> {
    let started = std::time::SystemTime::now();
    let (v0_min_fps, v0_max_fps) = crate::sweep::range::parse("--v0", &args.v0)?;
    let plan = Plan {
        scene: args.scene.clone(),
        thicknesses_in: thicknesses(&args.thickness_in)?,
        v0_min_fps,
        v0_max_fps,
        step_fps: args.step,
        tol_fps: args.tol_fps,
        packings: match args.packings {
            Some(n) => n,
            None => crate::ballistic::default_packings(&args.scene)?,
        },
        out: args.out.clone(),
        threads: args.threads,
        quiet: args.quiet,
        reuse: args.reuse.reuse(),
    };
    let report = chart::run(&plan)?;
    let show = |x: Option<f64>| x.map_or("—".to_string(), |v| format!("{v:.0}"));
    println!("{:>12} {:>12} {:>10} {:>18} {:>18}", "thickness_in", "threshold", "v_est_fps", "interval_fps", "formulas_band_fps");
    for p in &report.points {
        println!(
            "{:>12} {:>12} {:>10} {:>18} {:>18}",
            p.thickness_in,
            p.threshold,
            show(p.v_est_fps),
            format!("{}–{}", show(p.v_low_fps), show(p.v_high_fps)),
            format!("{}–{}", show(p.band_min_fps), show(p.band_max_fps))
        );
    }
    println!("{} runs made, {} found done; chart in {}", report.ran, report.skipped, args.out.join("chart.png").display());
    crate::provenance::write_manifest(&args.out, started)?;
    println!("report: {}", crate::report::write(&args.out)?.display());
    if report.failed.is_empty() {
        return Ok(());
    }
    let list: Vec<String> = report.failed.iter().map(|(d, id, m)| format!("  {}: {id}: {m}", d.display())).collect();
    Err(Error::input("chart", format!("{} run(s) failed (rows with status failed in their folder's runs.csv; the chart was drawn without them):\n{}", report.failed.len(), list.join("\n"))))
}
