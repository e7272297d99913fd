//! Running a built scene: a pure function of the scene returning its series and a typed
//! summary row. It prints nothing and writes nothing (the caller decides where tables go, and
//! where checkpoints go: a run hands them to a callback and can resume from one).
//!
//! A run ends at the scene's duration, or earlier when a [`StopRule`] says its outcome is
//! settled (the duration is then the hard cap, and hitting it is reported). Its threading is
//! explicit ([`Options::threading`]): a lone run uses the rayon pool it is called from, a run
//! inside a sweep steps on its own thread.

use std::time::Instant;

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::simulation::{Bodies, Built, Simulation, Threading};
use crate::table::Table;

/// The run's one-row summary: counts, time step, energies by mechanism, probe extremes, cost.
/// Serialises to a table row (`table::Table::from_row`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RunSummary {
    /// Scene name.
    pub scene: String,
    /// Elements.
    pub elements: u64,
    /// Contacts at the start.
    pub contacts_initial: u64,
    /// Intact bonds at the start.
    pub bonds_initial: u64,
    /// Bonds broken.
    pub bonds_broken: u64,
    /// Steps taken.
    pub steps: u64,
    /// Time step, s.
    pub dt_s: f64,
    /// Stability limit of the frequency bound, s.
    pub dt_bound_s: f64,
    /// The frequency bound, rad/s.
    pub omega_bound_rad_per_s: f64,
    /// What sets the step: the safety factor and which contacts give the frequency bound.
    pub dt_limit: String,
    /// Simulated time, s.
    pub simulated_s: f64,
    /// Why the run ended: `duration` (the scene's duration, no stop rule), the stop rule's
    /// reason, or `time_cap` (a stop rule never settled within the duration).
    pub end_reason: String,
    /// Kinetic energy at the end, J.
    pub kinetic_energy_j: f64,
    /// Strain energy at the end, J.
    pub strain_energy_j: f64,
    /// Work of loads, gravity and prescribed motions, J.
    pub external_work_j: f64,
    /// Mass-proportional damping, J.
    pub mass_damping_j: f64,
    /// What the contacts dissipated, by mechanism (`law::Dissipation`), and in 3D the local
    /// damping (`local_damping_j`), J.
    pub contacts: Columns,
    /// Everything dissipated, J.
    pub dissipated_j: f64,
    /// Energy balance residual, J.
    pub energy_residual_j: f64,
    /// The residual over the energy put in (initial + |external|): the ledger's closure.
    pub energy_error: f64,
    /// Full neighbour rebuilds.
    pub neighbour_rebuilds: u64,
    /// Local neighbour updates.
    pub neighbour_local_updates: u64,
    /// Wall time of the stepping loop, s (of the resumed part, after a resume).
    pub wall_s: f64,
    /// Element-steps per second of wall time.
    pub element_steps_per_s: f64,
    /// Per probe: `<name>_final`, `<name>_min`, `<name>_max`.
    pub probes: Columns,
}

/// Named values that become columns of a row (a map when serialised).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Columns(pub Vec<(String, f64)>);

impl Serialize for Columns {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            m.serialize_entry(k, v)?;
        }
        m.end()
    }
}

impl Columns {
    /// The value of column `name`.
    pub fn get(&self, name: &str) -> Option<f64> {
        self.0.iter().find(|(k, _)| k == name).map(|p| p.1)
    }
}

/// The outcome of one run of a model `M` (a kernel's, `crate::simulation`).
#[derive(Debug, Clone)]
pub struct RunResult<M> {
    /// Scene name.
    pub name: String,
    /// Probe time series: `time_s` then one column per probe.
    pub series: Table,
    /// The summary row.
    pub summary: RunSummary,
    /// Probe values as numbers, row-major like `series`.
    pub values: Vec<Vec<f64>>,
    /// The model at the end.
    pub model: M,
}

impl<M> RunResult<M> {
    /// The values of one series column (`time_s` or a probe name).
    pub fn column(&self, name: &str) -> Option<Vec<f64>> {
        let k = self.series.column(name)?;
        Some(self.values.iter().map(|r| r[k]).collect())
    }

    /// The summary as a one-row table.
    pub fn summary_table(&self) -> Table {
        Table::from_row(&self.summary).expect("a run summary is a flat row")
    }
}

fn fmt(v: f64) -> String {
    format!("{v:.9e}")
}

/// Decides when a run's outcome is settled, looking at the model every few steps. Its own
/// state travels in the run's checkpoints, so a resumed run decides as one that never stopped.
pub trait StopRule {
    /// Steps between looks.
    fn every_steps(&self) -> u64;
    /// Look at the model's bodies: `Some(reason)` ends the run.
    fn check(&mut self, model: &dyn Bodies) -> Option<String>;
    /// The rule's state as bytes.
    fn save(&self) -> Vec<u8>;
    /// Restore the state from [`StopRule::save`]'s bytes.
    fn load(&mut self, bytes: &[u8]) -> Result<()>;
}

/// Where a run stands: the model's state ([`Simulation::checkpoint`]), the series
/// recorded so far, the stop rule's state and the initial counts the summary reports.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunCheckpoint {
    /// The model's checkpoint bytes.
    pub model: Vec<u8>,
    /// Series rows recorded so far (`time_s` then the probes).
    pub values: Vec<Vec<f64>>,
    /// The stop rule's state (empty without one).
    pub stop: Vec<u8>,
    /// Contacts at the start of the run.
    pub contacts_initial: u64,
    /// Intact bonds at the start of the run.
    pub bonds_initial: u64,
}

const RUN_MAGIC: [u8; 8] = *b"DEMSWRN\x02";

impl RunCheckpoint {
    /// As bytes (bit-exact).
    pub fn to_bytes(&self) -> Vec<u8> {
        let mut out = RUN_MAGIC.to_vec();
        out.extend(postcard::to_stdvec(self).expect("a run checkpoint serialises"));
        out
    }

    /// From bytes written by [`RunCheckpoint::to_bytes`].
    pub fn from_bytes(bytes: &[u8]) -> Result<Self> {
        let bad = |m: String| Error::input("checkpoint", m);
        if bytes.len() < RUN_MAGIC.len() || bytes[..RUN_MAGIC.len()] != RUN_MAGIC {
            return Err(bad("not a demsweep run checkpoint (bad magic bytes or another format version)".into()));
        }
        let (c, rest) = postcard::take_from_bytes::<RunCheckpoint>(&bytes[RUN_MAGIC.len()..]).map_err(|e| match e {
            postcard::Error::DeserializeUnexpectedEnd => bad("truncated: the bytes end before the checkpoint does".into()),
            other => bad(format!("damaged: {other}")),
        })?;
        if !rest.is_empty() {
            return Err(bad(format!("{} bytes after the end of the checkpoint", rest.len())));
        }
        Ok(c)
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

/// Called with the model at each record; an error stops the run.
pub type Observer<'a, M> = &'a mut dyn FnMut(&M) -> Result<()>;

/// Cores a run may borrow while they are idle (a sweep's, `sweep::share`).
pub trait Lend: Sync {
    /// True when a core has nothing to do.
    fn spare(&self) -> bool;
    /// The pool to step on while a core is spare.
    fn pool(&self) -> &rayon::ThreadPool;
    /// False once nobody needs the run (a guess an outcome has ruled out): it ends at the next
    /// look with [`Error::Abandoned`], its core free for a run that is needed.
    fn wanted(&self) -> bool {
        true
    }
}

/// Steps between two looks at [`Lend::spare`] and [`Lend::wanted`] (an atomic load or two).
pub const LEND_POLL_STEPS: u64 = 10;

/// How to run a model `M`.
pub struct Options<'a, M> {
    /// Where the steps run.
    pub threading: Threading,
    /// Idle cores to borrow: while one is spare the run steps on [`Lend::pool`] (the kernel's
    /// results do not depend on it), otherwise as `threading` says.
    pub lend: Option<&'a dyn Lend>,
    /// Continue from this checkpoint of the same scene.
    pub resume: Option<&'a RunCheckpoint>,
    /// Hand out checkpoints.
    pub checkpointing: Option<Checkpointing<'a>>,
    /// End the run when its outcome is settled.
    pub stop: Option<&'a mut dyn StopRule>,
    /// Called with the fraction of the duration done, at each record (progress display).
    pub tick: Option<&'a mut dyn FnMut(f64)>,
    /// Called with the model at each record (pictures); an error stops the run.
    pub observe: Option<Observer<'a, M>>,
}

impl<M> Default for Options<'_, M> {
    fn default() -> Self {
        Options { threading: Threading::default(), lend: None, resume: None, checkpointing: None, stop: None, tick: None, observe: None }
    }
}

/// Run to the scene's duration, recording probes every `every_steps` and at the end.
/// `tick(fraction)` is called at each record (for progress display).
pub fn run<M: Simulation>(built: Built<M>, tick: &mut dyn FnMut(f64)) -> Result<RunResult<M>> {
    run_with(built, Options { tick: Some(tick), ..Default::default() })
}

/// [`run`] with [`Options`]. A resumed run's series and summary are those of the run that
/// never stopped, bit for bit, except the wall time and the speed, which count the resumed
/// part only.
pub fn run_with<M: Simulation>(mut built: Built<M>, mut opts: Options<'_, M>) -> Result<RunResult<M>> {
    let m = &mut built.model;
    m.set_threading(opts.threading);
    let cap = (built.duration_s / m.dt_s()).ceil() as u64;
    let record = |m: &M, values: &mut Vec<Vec<f64>>| {
        let mut row = vec![m.time_s()];
        row.extend(built.probes.iter().map(|p| p.value(m)));
        values.push(row);
    };
    let (bonds0, contacts0, mut values) = match opts.resume {
        Some(c) => {
            m.restore(&c.model)?;
            let width = built.probes.len() + 1;
            if c.values.is_empty() || c.values.iter().any(|r| r.len() != width) || m.steps() > cap {
                return Err(Error::input(
                    "checkpoint",
                    format!("the series ({} rows) or the step ({} of {cap}) does not fit this scene's {width} columns", c.values.len(), m.steps()),
                ));
            }
            if let Some(stop) = opts.stop.as_deref_mut() {
                stop.load(&c.stop)?;
            }
            (c.bonds_initial, c.contacts_initial, c.values.clone())
        }
        None => {
            let mut values = Vec::new();
            record(m, &mut values);
            (m.bond_count(), m.contact_count(), values)
        }
    };
    let start = Instant::now();
    let first_step = m.steps();
    let mut end_reason = if opts.stop.is_some() { "time_cap".to_string() } else { "duration".to_string() };
    let own = opts.threading;
    // The lender's pool while a core is spare (looked at every LEND_POLL_STEPS steps).
    let mut borrowed: Option<&rayon::ThreadPool> = None;
    let mut s = m.steps();
    while s < cap {
        if let Some(l) = opts.lend
            && s.is_multiple_of(LEND_POLL_STEPS)
        {
            if !l.wanted() {
                return Err(Error::Abandoned { step: s });
            }
            borrowed = l.spare().then(|| l.pool());
            m.set_threading(if borrowed.is_some() { Threading::Pool } else { own });
        }
        // The steps up to the next one after which something is looked at, in one go: on the
        // pool, one entry into it for all of them (`Simulation::run_steps`).
        let next = [
            Some(cap),
            Some(built.every_steps),
            opts.stop.as_deref().map(|r| r.every_steps().max(1)),
            opts.checkpointing.as_ref().map(|c| c.every_steps).filter(|&e| e > 0),
            opts.lend.map(|_| LEND_POLL_STEPS),
        ]
        .into_iter()
        .flatten()
        .map(|every| (s / every + 1) * every)
        .fold(cap, u64::min);
        match borrowed {
            Some(pool) => pool.install(|| m.run_steps(next - s))?,
            None => m.run_steps(next - s)?,
        }
        s = next;
        let settled = match opts.stop.as_deref_mut() {
            Some(stop) if s.is_multiple_of(stop.every_steps().max(1)) => stop.check(&*m),
            _ => None,
        };
        let last = s == cap || settled.is_some();
        if s.is_multiple_of(built.every_steps) || last {
            record(m, &mut values);
            if let Some(t) = opts.tick.as_deref_mut() {
                t(s as f64 / cap as f64);
            }
            if let Some(f) = opts.observe.as_deref_mut() {
                f(m)?;
            }
        }
        if let Some(reason) = settled {
            end_reason = reason;
            break;
        }
        if let Some(c) = opts.checkpointing.as_mut().filter(|c| c.every_steps > 0 && s.is_multiple_of(c.every_steps) && s < cap) {
            let snapshot = RunCheckpoint {
                model: m.checkpoint(),
                values: values.clone(),
                stop: opts.stop.as_deref().map_or_else(Vec::new, |r| r.save()),
                contacts_initial: contacts0,
                bonds_initial: bonds0,
            };
            (c.save)(&snapshot)?;
        }
    }
    // The model handed back steps where the caller said, not where the last borrow left it.
    m.set_threading(own);
    let wall = start.elapsed().as_secs_f64();
    let mut header = vec!["time_s".to_string()];
    header.extend(built.probes.iter().map(|p| p.name().to_string()));
    let series = Table { header, rows: values.iter().map(|r| r.iter().map(|&v| fmt(v)).collect()).collect() };
    let t = m.tally();
    let mut probes = Vec::new();
    for (k, p) in built.probes.iter().enumerate() {
        let col: Vec<f64> = values.iter().map(|r| r[k + 1]).collect();
        let (lo, hi) = col.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
        probes.push((format!("{}_final", p.name()), *col.last().unwrap()));
        probes.push((format!("{}_min", p.name()), lo));
        probes.push((format!("{}_max", p.name()), hi));
    }
    let summary = RunSummary {
        scene: built.name.clone(),
        elements: t.elements,
        contacts_initial: contacts0,
        bonds_initial: bonds0,
        bonds_broken: t.bonds_broken,
        steps: m.steps(),
        dt_s: t.dt_s,
        dt_bound_s: t.dt_bound_s,
        omega_bound_rad_per_s: t.omega_bound_rad_per_s,
        dt_limit: t.dt_limit,
        simulated_s: m.time_s(),
        end_reason,
        kinetic_energy_j: t.kinetic_energy_j,
        strain_energy_j: t.strain_energy_j,
        external_work_j: t.external_work_j,
        mass_damping_j: t.mass_damping_j,
        contacts: Columns(t.contacts_j),
        dissipated_j: t.dissipated_j,
        energy_residual_j: t.energy_residual_j,
        energy_error: t.energy_residual_j / t.energy_in_j.max(f64::MIN_POSITIVE),
        neighbour_rebuilds: t.neighbour_rebuilds,
        neighbour_local_updates: t.neighbour_local_updates,
        wall_s: (wall * 1e3).round() / 1e3,
        element_steps_per_s: t.elements as f64 * (m.steps() - first_step) as f64 / wall.max(1e-9),
        probes: Columns(probes),
    };
    Ok(RunResult { name: built.name, series, summary, values, model: built.model })
}
