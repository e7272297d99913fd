//! Running a built scene: a pure function of the scene returning its series and a one-row
//! summary. It prints nothing and writes nothing (the caller decides where tables go, and
//! where checkpoints go: a run hands them to a callback and can resume from one).

use std::time::Instant;

use crate::binary::{Reader, Writer, bad};
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

/// Where a run stands: the model's state ([`crate::kernel::Model::checkpoint`]), the series
/// recorded so far and the initial counts the summary reports.
#[derive(Debug, Clone, PartialEq)]
pub struct RunCheckpoint {
    /// The model's checkpoint bytes.
    pub model: Vec<u8>,
    /// Series rows recorded so far (`time_s` then the probes).
    pub values: Vec<Vec<f64>>,
    /// Contacts at the start of the run.
    pub contacts_initial: u64,
    /// Intact bonds at the start of the run.
    pub bonds_initial: u64,
}

const RUN_MAGIC: &[u8; 8] = b"DEMSWRN\0";

impl RunCheckpoint {
    /// As bytes (bit-exact).
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut w = Writer(Vec::with_capacity(self.model.len() + 64 + 8 * self.values.iter().map(Vec::len).sum::<usize>()));
        w.bytes(RUN_MAGIC);
        w.u64(self.contacts_initial);
        w.u64(self.bonds_initial);
        w.u64(self.values.len() as u64);
        w.u64(self.values.first().map_or(0, Vec::len) as u64);
        self.values.iter().for_each(|r| w.f64s(r));
        w.u64(self.model.len() as u64);
        w.bytes(&self.model);
        w.0
    }

    /// From bytes written by [`RunCheckpoint::to_bytes`].
    pub fn from_bytes(bytes: &[u8]) -> Result<Self> {
        let mut r = Reader::new(bytes);
        if r.take::<8>()? != *RUN_MAGIC {
            return Err(bad("not a demsweep run checkpoint (bad magic bytes)".into()));
        }
        let (contacts_initial, bonds_initial) = (r.u64()?, r.u64()?);
        let rows = r.len("series rows", 8)?;
        let cols = r.len("series columns", 8 * rows.max(1))?;
        let values = (0..rows).map(|_| (0..cols).map(|_| r.f64()).collect::<Result<Vec<_>>>()).collect::<Result<Vec<_>>>()?;
        let n = r.len("model bytes", 1)?;
        let model = r.slice(n)?.to_vec();
        r.finish()?;
        Ok(RunCheckpoint { model, values, contacts_initial, bonds_initial })
    }
}

/// Hand a checkpoint to `save` every `every_steps` steps (never at the last step: the run's
/// tables then say everything).
pub struct Checkpointing<'a> {
    /// Steps between checkpoints.
    pub every_steps: u64,
    /// Stores a checkpoint; an error stops the run with that error.
    pub save: &'a mut dyn FnMut(&RunCheckpoint) -> Result<()>,
}

/// Run to the scene's duration, recording probes every `every_steps` and at the end.
/// `tick(fraction)` is called at each record (for progress display).
pub fn run(built: Built, tick: &mut dyn FnMut(f64)) -> Result<RunResult> {
    run_with(built, None, None, tick)
}

/// [`run`], starting from `resume` (a checkpoint of the same scene) if given, and handing
/// checkpoints to `checkpointing` if given. A resumed run's series and summary are those of
/// the run that never stopped, bit for bit, except the wall time and the speed, which count
/// the resumed part only.
pub fn run_with(
    mut built: Built,
    resume: Option<&RunCheckpoint>,
    mut checkpointing: Option<Checkpointing>,
    tick: &mut dyn FnMut(f64),
) -> Result<RunResult> {
    let m = &mut built.model;
    let steps = (built.duration_s / m.dt_s()).ceil() as u64;
    let record = |m: &crate::kernel::Model, values: &mut Vec<Vec<f64>>| {
        let mut row = vec![m.time_s];
        row.extend(built.probes.iter().map(|p| p.value(m)));
        values.push(row);
    };
    let (bonds0, contacts0, mut values) = match resume {
        Some(c) => {
            m.restore(&c.model)?;
            let width = built.probes.len() + 1;
            if c.values.is_empty() || c.values.iter().any(|r| r.len() != width) || m.steps > steps {
                return Err(bad(format!(
                    "the series ({} rows) or the step ({} of {steps}) does not fit this scene's {width} columns",
                    c.values.len(),
                    m.steps
                )));
            }
            (c.bonds_initial as usize, c.contacts_initial as usize, c.values.clone())
        }
        None => {
            let mut values = Vec::new();
            record(m, &mut values);
            (m.intact_bonds(), m.contacts.len(), values)
        }
    };
    let start = Instant::now();
    let first_step = m.steps;
    for s in m.steps + 1..=steps {
        m.step()?;
        if s % built.every_steps == 0 || s == steps {
            record(m, &mut values);
            tick(s as f64 / steps as f64);
        }
        if let Some(c) = checkpointing.as_mut().filter(|c| c.every_steps > 0 && s % c.every_steps == 0 && s < steps) {
            let snapshot =
                RunCheckpoint { model: m.checkpoint(), values: values.clone(), contacts_initial: contacts0 as u64, bonds_initial: bonds0 as u64 };
            (c.save)(&snapshot)?;
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
        ("plastic_work_j".into(), fmt(l.plastic_j)),
        ("fracture_energy_j".into(), fmt(l.fracture_j)),
        ("energy_residual_j".into(), fmt(l.residual_j(ke, se))),
        ("neighbour_rebuilds".into(), m.rebuilds.to_string()),
        ("wall_s".into(), format!("{wall:.3}")),
        ("element_steps_per_s".into(), format!("{:.4e}", m.el.len() as f64 * (steps - first_step) as f64 / wall.max(1e-9))),
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
