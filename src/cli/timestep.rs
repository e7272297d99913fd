//! `demsweep timestep <scene.toml>`: how close the scene's step is to its instability
//! threshold. The run goes as `demsweep run` would; at every record the assembled mesh's top
//! frequency is measured (Lanczos on M^-½ K M^-½ of the contacts that carry stiffness then, at
//! their present moduli: a Ritz value, never above the truth), and Δt is set beside the
//! measured threshold 2/ω of central differences (undamped) and the build's rigorous bound.

use std::path::PathBuf;

use serde::Serialize;

use crate::error::{Error, Result};
use crate::kernel::{Model, stability};
use crate::scene::overrides::Override;
use crate::scene_file::SceneFile;
use crate::table::Table;

/// Arguments of `demsweep timestep`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// A penetration scene file (TOML).
    pub scene: PathBuf,
    /// Change one field of the scene (as `demsweep run --set`).
    #[arg(long = "set", value_name = "FIELD=VALUE")]
    pub set: Vec<String>,
    /// Simulated time between measurements, ms.
    #[arg(long, default_value_t = 0.5, value_name = "MS")]
    pub every_ms: f64,
    /// Lanczos iterations per measurement.
    #[arg(long, default_value_t = 120)]
    pub iterations: usize,
    /// Write the table here (CSV).
    #[arg(long, default_value = "results/timestep/timestep.csv")]
    pub out: PathBuf,
}

/// One measurement.
#[derive(Debug, Clone, Serialize)]
struct Row {
    time_ms: f64,
    step: u64,
    contacts: usize,
    omega_measured_rad_per_s: f64,
    omega_bound_rad_per_s: f64,
    dt_s: f64,
    /// 2/ω_measured, s.
    dt_threshold_s: f64,
    /// Δt / (2/ω_measured).
    dt_over_threshold: f64,
}

fn measure(m: &Model, iterations: usize) -> Row {
    let st = &m.state;
    let omega = stability::lanczos_top(&m.el, &st.pos, &st.contacts, &m.classes, iterations);
    let threshold = 2.0 / omega;
    Row {
        time_ms: m.time_s() * 1e3,
        step: m.steps(),
        contacts: st.contacts.len(),
        omega_measured_rad_per_s: omega,
        omega_bound_rad_per_s: m.step_info.omega_bound_rad_per_s,
        dt_s: m.dt_s(),
        dt_threshold_s: threshold,
        dt_over_threshold: m.dt_s() / threshold,
    }
}

/// Run the scene and measure.
pub fn run(args: Args) -> Result<()> {
    let overrides: Vec<Override> = args.set.iter().map(|s| Override::parse(s)).collect::<Result<_>>()?;
    let scene = match crate::scene_file::load(&args.scene, &overrides)? {
        SceneFile::Penetration(s) => s,
        SceneFile::Kernel(_) | SceneFile::Kernel3(_) | SceneFile::Rockfill(_) => return Err(Error::input("scene", "timestep takes a penetration scene")),
    };
    if !(args.every_ms.is_finite() && args.every_ms > 0.0) {
        return Err(Error::input("--every-ms", format!("must be a number > 0, got {}", args.every_ms)));
    }
    if args.iterations < 10 {
        return Err(Error::input("--iterations", format!("must be ≥ 10, got {}", args.iterations)));
    }
    let mut rows = Vec::new();
    let mut record = |m: &Model| {
        rows.push(measure(m, args.iterations));
        Ok(())
    };
    let hooks = crate::penetration::Hooks { each_record: Some(&mut record), record_every_s: args.every_ms * 1e-3, ..Default::default() };
    let finished = crate::penetration::run(&scene, hooks)?;
    rows.push(measure(&finished.model, args.iterations));
    let info = &finished.model.step_info;
    println!("{}: Δt = {:.4e} s ({}), bound 2/ω = {:.4e} s", scene.penetration.name, info.dt_s, info.detail, info.dt_bound_s);
    println!("{:>8} {:>7} {:>8} {:>14} {:>14} {:>10}", "t_ms", "step", "contacts", "ω_meas rad/s", "2/ω_meas s", "Δt/(2/ω)");
    for r in &rows {
        println!("{:>8.3} {:>7} {:>8} {:>14.6e} {:>14.6e} {:>10.4}", r.time_ms, r.step, r.contacts, r.omega_measured_rad_per_s, r.dt_threshold_s, r.dt_over_threshold);
    }
    let worst = rows.iter().map(|r| r.dt_over_threshold).fold(0.0, f64::max);
    println!("highest Δt / measured threshold over the run: {worst:.4} (ω_meas / ω_bound ≤ {:.4})", worst / info.safety);
    Table::from_rows(&rows)?.write_csv(&args.out)?;
    println!("written {}", args.out.display());
    Ok(())
}
