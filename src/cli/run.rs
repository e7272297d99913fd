//! `demsweep run <scene.toml>`: run one scene, write its summary and series.

use std::path::PathBuf;

use crate::error::Result;
use crate::scene::Scene;

/// Arguments of `demsweep run`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Scene file (TOML).
    pub scene: PathBuf,
    /// Output folder; the run writes `<out>/<scene name>/summary.csv` and `series.csv`.
    #[arg(long, default_value = "results/runs")]
    pub out: PathBuf,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
}

/// Run the scene. Nothing is written unless the run completes; tables are written atomically.
pub fn run(args: Args) -> Result<()> {
    let scene = Scene::from_file(&args.scene)?;
    let built = scene.build().map_err(|e| e.in_file(&args.scene))?;
    let info = built.model.step_info.clone();
    eprintln!(
        "{}: {} elements, {} contacts, Δt = {:.4e} s ({}), {} steps",
        built.name,
        built.model.el.len(),
        built.model.contacts.len(),
        info.dt_s,
        info.detail,
        (built.duration_s / info.dt_s).ceil()
    );
    let bar = if args.quiet { indicatif::ProgressBar::hidden() } else { indicatif::ProgressBar::new(1000) };
    let result = crate::run::run(built, &mut |f| bar.set_position((f * 1000.0) as u64));
    bar.finish_and_clear();
    let result = result?;
    let dir = args.out.join(&result.name);
    result.summary.write_csv(&dir.join("summary.csv"))?;
    result.series.write_csv(&dir.join("series.csv"))?;
    let row = &result.summary.rows[0];
    for (h, v) in result.summary.header.iter().zip(row) {
        println!("{h:>28} = {v}");
    }
    println!("{:>28} = {}", "written", dir.display());
    Ok(())
}
