//! `demsweep run <scene.toml> [--set FIELD=VALUE]…`: run one scene, write its summary (and, for
//! a kernel scene, its probe series).

use std::path::PathBuf;

use crate::error::{Error, Result};
use crate::penetration::scene::PenetrationScene;
use crate::penetration::history::History;
use crate::penetration::{Finished, Hooks};
use crate::run::{Checkpointing, RunCheckpoint};
use crate::scene::overrides::Override;
use crate::scene_file::SceneFile;
use crate::simulation::{Built, Simulation};
use crate::table::Table;

/// Arguments of `demsweep run`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Scene file (TOML): a kernel scene, or a penetration scene (`[penetration]`).
    pub scene: PathBuf,
    /// Change one field of the scene, checked like the file itself (dotted path; repeatable),
    /// e.g. `--set projectile.v0_fps=850`.
    #[arg(long = "set", value_name = "FIELD=VALUE")]
    pub set: Vec<String>,
    /// Output folder; the run writes `<out>/<scene name>/summary.csv` (and `series.csv`).
    #[arg(long, default_value = "results/runs")]
    pub out: PathBuf,
    /// No progress bar.
    #[arg(long)]
    pub quiet: bool,
    /// Write `<out>/<scene name>/checkpoint.bin` every N steps (atomically; removed when the
    /// run completes). 0: never. Kernel scenes only.
    #[arg(long, default_value_t = 0, value_name = "N")]
    pub checkpoint_every_steps: u64,
    /// Continue from `<out>/<scene name>/checkpoint.bin` if it exists (a run that was killed);
    /// the tables are then those of a run that never stopped.
    #[arg(long)]
    pub resume: bool,
    /// Write pictures of the run into this folder: PNG frames and a VTK series (penetration
    /// scenes), a VTK series (3D scenes).
    #[arg(long, value_name = "DIR")]
    pub snapshots: Option<PathBuf>,
    /// Simulated time between pictures, ms.
    #[arg(long, default_value_t = 0.25, value_name = "MS")]
    pub snapshot_every_ms: f64,
    /// Penetration scenes: write `<out>/<scene name>/history.csv`, a record every MS of
    /// simulated time (depth, speed and resistance of the projectile; kinetic energy and broken
    /// bonds near the path and far from it; the energy ledger).
    #[arg(long, value_name = "MS")]
    pub history_every_ms: Option<f64>,
}

fn announce<M: Simulation>(name: &str, m: &M, steps: f64) {
    let t = m.tally();
    eprintln!("{name}: {} elements, {} contacts, Δt = {:.4e} s ({}), at most {steps} steps", m.element_count(), m.contact_count(), t.dt_s, t.dt_limit);
}

fn print(summary: &Table, dir: &std::path::Path) {
    for (h, v) in summary.header.iter().zip(&summary.rows[0]) {
        println!("{h:>28} = {v}");
    }
    println!("{:>28} = {}", "written", dir.display());
}

/// Run the scene. No table is written unless the run completes; tables and checkpoints are
/// written atomically.
pub fn run(args: Args) -> Result<()> {
    let overrides: Vec<Override> = args.set.iter().map(|s| Override::parse(s)).collect::<Result<_>>()?;
    match crate::scene_file::load(&args.scene, &overrides)? {
        SceneFile::Kernel(scene) => {
            if args.snapshots.is_some() {
                return Err(Error::input("--snapshots", "pictures are drawn of penetration scenes and 3D scenes"));
            }
            run_kernel(&args, scene.build().map_err(|e| e.in_file(&args.scene))?)
        }
        SceneFile::Kernel3(scene) => run_kernel(&args, scene.build().map_err(|e| e.in_file(&args.scene))?),
        SceneFile::Rockfill(scene) => run_kernel(&args, scene.build().map_err(|e| e.in_file(&args.scene))?),
        SceneFile::Penetration(scene) => run_penetration(&args, scene),
    }
}

/// A penetration scene on the kernel of its dimension.
fn run_penetration(args: &Args, scene: PenetrationScene) -> Result<()> {
    match scene.penetration.dim {
        3 => penetrate(args, scene, crate::penetration::run3),
        _ => penetrate(args, scene, crate::penetration::run),
    }
}

/// Run a penetration scene with `run` on its kernel `M`: its row, and with `--snapshots` PNG
/// frames (a 3D run's section through the impact point) and a VTK series.
fn penetrate<M: Simulation>(args: &Args, scene: PenetrationScene, run: impl FnOnce(&PenetrationScene, Hooks<'_, M>) -> Result<Finished<M>>) -> Result<()> {
    if args.checkpoint_every_steps > 0 || args.resume {
        return Err(Error::input("--checkpoint-every-steps", "checkpoints are for kernel scenes; a penetration run is one event"));
    }
    if !(args.snapshot_every_ms.is_finite() && args.snapshot_every_ms > 0.0) {
        return Err(Error::input("--snapshot-every-ms", format!("must be a number > 0, got {}", args.snapshot_every_ms)));
    }
    let dir = args.out.join(&scene.penetration.name);
    let bar = if args.quiet { indicatif::ProgressBar::hidden() } else { indicatif::ProgressBar::new(1000) };
    let mut tick = |f: f64| bar.set_position((f * 1000.0) as u64);
    let mut pictures = match &args.snapshots {
        Some(d) => Some(crate::picture::Series::new(d, &scene)?),
        None => None,
    };
    if let Some(ms) = args.history_every_ms
        && !(ms.is_finite() && ms > 0.0)
    {
        return Err(Error::input("--history-every-ms", format!("must be a number > 0, got {ms}")));
    }
    let picture_s = if pictures.is_some() { args.snapshot_every_ms * 1e-3 } else { 0.0 };
    // Records come at the finer of the two intervals; a picture at its own.
    let every_s = match args.history_every_ms {
        Some(ms) if picture_s > 0.0 => picture_s.min(ms * 1e-3),
        Some(ms) => ms * 1e-3,
        None => picture_s,
    };
    let mut history = args.history_every_ms.map(|_| History::default());
    let (mut started, mut next_picture_s) = (false, 0.0);
    let mut frame = |m: &M| -> Result<()> {
        if !std::mem::replace(&mut started, true) {
            announce(&scene.penetration.name, m, (scene.penetration.max_time_s / m.dt_s()).ceil());
        }
        match pictures.as_mut() {
            // Half a step's slack: records fall on whole steps.
            Some(p) if m.time_s() >= next_picture_s - 0.5 * m.dt_s() => {
                next_picture_s = m.time_s() + picture_s;
                p.frame(m)
            }
            _ => Ok(()),
        }
    };
    let hooks = Hooks { each_record: Some(&mut frame), record_every_s: every_s, tick: Some(&mut tick), history: history.as_mut(), ..Default::default() };
    let finished = run(&scene, hooks);
    bar.finish_and_clear();
    let finished = finished?;
    if let Some(p) = pictures.as_mut() {
        let last = p.finish(&finished.model)?;
        eprintln!("{} frames; the last is {}", p.frames().len(), last.display());
    }
    if let Some(h) = &history {
        Table::from_rows(&h.rows)?.write_csv(&dir.join("history.csv"))?;
    }
    let summary = Table::from_row(&finished.row)?;
    summary.write_csv(&dir.join("summary.csv"))?;
    print(&summary, &dir);
    Ok(())
}

/// Run a built kernel scene (either kernel); `--snapshots` writes a VTK series.
fn run_kernel<M: Simulation>(args: &Args, built: Built<M>) -> Result<()> {
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
    announce(&built.name, &built.model, (built.duration_s / built.model.dt_s()).ceil());
    let bar = if args.quiet { indicatif::ProgressBar::hidden() } else { indicatif::ProgressBar::new(1000) };
    let mut save = |c: &RunCheckpoint| crate::table::write_atomic(&checkpoint_path, &c.to_bytes());
    let every_steps = args.checkpoint_every_steps;
    let checkpointing = (every_steps > 0).then_some(Checkpointing { every_steps, save: &mut save });
    let mut tick = |f: f64| bar.set_position((f * 1000.0) as u64);
    let mut series = match &args.snapshots {
        Some(d) => Some(crate::picture::vtk::Series::new(d)?),
        None => None,
    };
    let every_s = args.snapshot_every_ms * 1e-3;
    if !(every_s.is_finite() && every_s > 0.0) {
        return Err(Error::input("--snapshot-every-ms", format!("must be a number > 0, got {}", args.snapshot_every_ms)));
    }
    // A frame at each record at least `every_s` after the last (records fall every
    // `[output] every_steps`), and the last state.
    let mut next_s = 0.0;
    let mut frame = |m: &M| -> Result<()> {
        match series.as_mut() {
            Some(s) if m.time_s() >= next_s => {
                next_s = m.time_s() + every_s;
                s.frame(m).map(|_| ())
            }
            _ => Ok(()),
        }
    };
    let observe: Option<crate::run::Observer<'_, M>> = if args.snapshots.is_some() { Some(&mut frame) } else { None };
    let options = crate::run::Options { resume: resume.as_ref(), checkpointing, tick: Some(&mut tick), observe, ..Default::default() };
    let result = crate::run::run_with(built, options).map_err(|e| e.in_file(&checkpoint_path));
    bar.finish_and_clear();
    let result = result?;
    if let Some(s) = series.as_mut() {
        s.frame(&result.model)?;
        eprintln!("{} frames in {}", s.frames().len(), args.snapshots.as_ref().expect("a series has a folder").display());
    }
    let summary = result.summary_table();
    summary.write_csv(&dir.join("summary.csv"))?;
    result.series.write_csv(&dir.join("series.csv"))?;
    if checkpoint_path.exists() {
        std::fs::remove_file(&checkpoint_path).map_err(|e| Error::io(&checkpoint_path, e))?;
    }
    print(&summary, &dir);
    Ok(())
}
