//! `demsweep run <scene.toml>`: run one scene, write its summary and series.

use std::path::PathBuf;

use crate::error::{Error, Result};
use crate::run::{Checkpointing, RunCheckpoint};
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
    /// Write `<out>/<scene name>/checkpoint.bin` every N steps (atomically; removed when the
    /// run completes). 0: never.
    #[arg(long, default_value_t = 0, value_name = "N")]
    pub checkpoint_every_steps: u64,
    /// Continue from `<out>/<scene name>/checkpoint.bin` if it exists (a run that was killed);
    /// the tables are then those of a run that never stopped.
    #[arg(long)]
    pub resume: bool,
}

/// Run the scene. No table is written unless the run completes; tables and checkpoints are
/// written atomically.
pub fn run(args: Args) -> Result<()> {
    let scene = Scene::from_file(&args.scene)?;
    let built = scene.build().map_err(|e| e.in_file(&args.scene))?;
    let dir = args.out.join(&built.name);
    let checkpoint_path = dir.join("checkpoint.bin");
    let resume = match (args.resume, checkpoint_path.exists()) {
        (true, true) => {
            let bytes = std::fs::read(&checkpoint_path).map_err(|e| Error::io(&checkpoint_path, e))?;
            Some(RunCheckpoint::from_bytes(&bytes).map_err(|e| e.in_file(&checkpoint_path))?)
        }
        (true, false) => {
            eprintln!("{}: no checkpoint, starting from the beginning", checkpoint_path.display());
            None
        }
        (false, _) => None,
    };
    let info = built.model.step_info.clone();
    eprintln!(
        "{}: {} elements, {} contacts, Δt = {:.4e} s ({}), {} steps",
        built.name,
        built.model.el.len(),
        built.model.state.contacts.len(),
        info.dt_s,
        info.detail,
        (built.duration_s / info.dt_s).ceil()
    );
    let bar = if args.quiet { indicatif::ProgressBar::hidden() } else { indicatif::ProgressBar::new(1000) };
    let mut save = |c: &RunCheckpoint| crate::table::write_atomic(&checkpoint_path, &c.to_bytes());
    let every_steps = args.checkpoint_every_steps;
    let checkpointing = (every_steps > 0).then_some(Checkpointing { every_steps, save: &mut save });
    let mut tick = |f: f64| bar.set_position((f * 1000.0) as u64);
    let options = crate::run::Options { resume: resume.as_ref(), checkpointing, tick: Some(&mut tick), ..Default::default() };
    let result = crate::run::run_with(built, options).map_err(|e| e.in_file(&checkpoint_path));
    bar.finish_and_clear();
    let result = result?;
    let summary = result.summary_table();
    summary.write_csv(&dir.join("summary.csv"))?;
    result.series.write_csv(&dir.join("series.csv"))?;
    if checkpoint_path.exists() {
        std::fs::remove_file(&checkpoint_path).map_err(|e| Error::io(&checkpoint_path, e))?;
    }
    for (h, v) in summary.header.iter().zip(&summary.rows[0]) {
        println!("{h:>28} = {v}");
    }
    println!("{:>28} = {}", "written", dir.display());
    Ok(())
}
