//! Running a built scene: a pure function of the scene returning its series and a one-row
//! summary. It prints nothing and writes nothing (the caller decides where tables go).

use std::time::Instant;

use crate::error::Result;
use crate::scene::Built;
use crate::table::Table;

/// The outcome of one run.
#[derive(Debug, Clone)]
pub struct RunResult {
    /// Scene name.
    pub name: String,
    /// Probe time series: `time_s` then one column per probe.
    pub series: Table,
    /// One row: counts, time step, energies, probe extremes, cost.
    pub summary: Table,
    /// Probe values as numbers, row-major like `series`.
    pub values: Vec<Vec<f64>>,
}

impl RunResult {
    /// The values of one series column (`time_s` or a probe name).
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let k = self.series.column(name)?;
        Some(self.values.iter().map(|r| r[k]).collect())
    }
}

fn fmt(v: f64) -> String {
    format!("{v:.9e}")
}

/// Run to the scene's duration, recording probes every `every_steps` and at the end.
/// `tick(fraction)` is called at each record (for progress display).
pub fn run(mut built: Built, tick: &mut dyn FnMut(f64)) -> Result<RunResult> {
    let m = &mut built.model;
    let steps = (built.duration_s / m.dt_s()).ceil() as u64;
    let bonds0 = m.intact_bonds();
    let contacts0 = m.contacts.len();
    let mut values = Vec::new();
    let record = |m: &crate::kernel::Model, values: &mut Vec<Vec<f64>>| {
        let mut row = vec![m.time_s];
        row.extend(built.probes.iter().map(|p| p.value(m)));
        values.push(row);
    };
    record(m, &mut values);
    let start = Instant::now();
    for s in 1..=steps {
        m.step()?;
        if s % built.every_steps == 0 || s == steps {
            record(m, &mut values);
            tick(s as f64 / steps as f64);
        }
    }
    let wall = start.elapsed().as_secs_f64();
    let mut header = vec!["time_s".to_string()];
    header.extend(built.probes.iter().map(|p| p.name.clone()));
    let series = Table { header, rows: values.iter().map(|r| r.iter().map(|&v| fmt(v)).collect()).collect() };
    let info = &m.step_info;
    let l = &m.ledger;
    let (ke, se) = (m.el.kinetic_energy_j(), m.strain_energy_j());
    let mut cols: Vec<(String, String)> = vec![
        ("scene".into(), built.name.clone()),
        ("elements".into(), m.el.len().to_string()),
        ("contacts_initial".into(), contacts0.to_string()),
        ("bonds_initial".into(), bonds0.to_string()),
        ("bonds_broken".into(), l.bonds_broken.to_string()),
        ("steps".into(), steps.to_string()),
        ("dt_s".into(), fmt(info.dt_s)),
        ("dt_bound_s".into(), fmt(info.dt_bound_s)),
        ("omega_bound_rad_per_s".into(), fmt(info.omega_bound_rad_per_s)),
        ("time_s".into(), fmt(m.time_s)),
        ("kinetic_energy_j".into(), fmt(ke)),
        ("strain_energy_j".into(), fmt(se)),
        ("external_work_j".into(), fmt(l.external_j)),
        ("dissipated_j".into(), fmt(l.dissipated_j())),
        ("energy_residual_j".into(), fmt(l.residual_j(ke, se))),
        ("neighbour_rebuilds".into(), m.rebuilds.to_string()),
        ("wall_s".into(), format!("{wall:.3}")),
        ("element_steps_per_s".into(), format!("{:.4e}", m.el.len() as f64 * steps as f64 / wall.max(1e-9))),
    ];
    for (k, p) in built.probes.iter().enumerate() {
        let col: Vec<f64> = values.iter().map(|r| r[k + 1]).collect();
        let (lo, hi) = col.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
        cols.push((format!("{}_final", p.name), fmt(*col.last().unwrap())));
        cols.push((format!("{}_min", p.name), fmt(lo)));
        cols.push((format!("{}_max", p.name), fmt(hi)));
    }
    let summary = Table { header: cols.iter().map(|c| c.0.clone()).collect(), rows: vec![cols.into_iter().map(|c| c.1).collect()] };
    Ok(RunResult { name: built.name, series, summary, values })
}
