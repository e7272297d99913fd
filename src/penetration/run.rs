//! A penetration run: the scene of `penetration::scene`, run until its outcome is settled
//! (`outcome::Detector` as the stop rule), reported as one typed row. The only place that picks
//! the kernel a penetration scene runs on ([`run`] on the 2D kernel, [`run3`] on the 3D one,
//! [`row`] by the scene's `dim`); the rest ([`run_on`]) reads the model through
//! `crate::simulation` and works for any kernel.

use serde::Serialize;

use crate::penetration::scene::PenetrationScene;
use crate::error::Result;
use crate::kernel::Model;
use crate::penetration::history::History;
use crate::penetration::outcome::{Detector, Outcome};
use crate::penetration::scene::Layout;
use crate::run::{self, RunSummary};
use crate::simulation::{Built, Simulation, Threading};
use crate::units::M_PER_IN;

/// The summary row of a penetration run (`summary.csv`; what sweeps tabulate): the inputs a
/// sweep varies, the outcome, then the run's own summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    /// Impact speed, ft/s.
    pub v0_fps: f64,
    /// Obliquity, degrees.
    pub angle_deg: f64,
    /// Refinement level.
    pub level: u32,
    /// The calibration factor.
    pub strength_factor: f64,
    /// The slice thickness of the mapping, in (empty in 3D: no slice).
    pub thickness_in: Option<f64>,
    /// The outcome.
    pub outcome: Outcome,
    /// The run.
    pub run: RunSummary,
}

/// A finished penetration run on a model `M`.
#[derive(Debug, Clone)]
pub struct Finished<M> {
    /// Its row.
    pub row: Row,
    /// The model at the end.
    pub model: M,
    /// The detector with its record.
    pub detector: Detector,
}

/// Hooks a caller may give a run of a model `M`.
pub struct Hooks<'a, M> {
    /// Where the steps run.
    pub threading: Threading,
    /// Idle cores to borrow (see [`run::Options::lend`]).
    pub lend: Option<&'a dyn run::Lend>,
    /// Called at every record with the model (pictures).
    pub each_record: Option<run::Observer<'a, M>>,
    /// Simulated time between records, s (0: only the start and the end).
    pub record_every_s: f64,
    /// Progress, the fraction of the time cap done.
    pub tick: Option<&'a mut dyn FnMut(f64)>,
    /// Where to keep the run's history, a record at every record time (`history`).
    pub history: Option<&'a mut History>,
}

impl<M> Default for Hooks<'_, M> {
    fn default() -> Self {
        Hooks { threading: Threading::default(), lend: None, each_record: None, record_every_s: 0.0, tick: None, history: None }
    }
}

/// Run a 2D scene to its settled outcome on the 2D kernel.
pub fn run(scene: &PenetrationScene, hooks: Hooks<'_, Model>) -> Result<Finished<Model>> {
    let (kernel, layout) = scene.to_scene()?;
    run_on(scene, kernel.build()?, layout, hooks)
}

/// Run a 3D scene (`penetration.dim = 3`) to its settled outcome on the 3D kernel.
pub fn run3(scene: &PenetrationScene, hooks: Hooks<'_, crate::kernel3d::Model>) -> Result<Finished<crate::kernel3d::Model>> {
    let (built, layout) = scene.build3()?;
    run_on(scene, built, layout, hooks)
}

/// The row of a run of the scene on the kernel of its dimension, on `threading`, borrowing
/// `lend`'s idle cores.
pub fn row(scene: &PenetrationScene, threading: Threading, lend: Option<&dyn run::Lend>) -> Result<Row> {
    Ok(match scene.penetration.dim {
        3 => run3(scene, Hooks { threading, lend, ..Default::default() })?.row,
        _ => run(scene, Hooks { threading, lend, ..Default::default() })?.row,
    })
}

/// Run `built`, the scene's model on some kernel laid out as `layout`, to its settled outcome.
pub fn run_on<M: Simulation>(scene: &PenetrationScene, mut built: Built<M>, layout: Layout, hooks: Hooks<'_, M>) -> Result<Finished<M>> {
    built.every_steps = if hooks.record_every_s > 0.0 { ((hooks.record_every_s / built.model.dt_s()).round() as u64).max(1) } else { u64::MAX };
    let mut detector = Detector::new(&built.model, layout.clone(), scene.outcome.clone())?;
    let (mut on, mut tick, mut history) = (hooks.each_record, hooks.tick, hooks.history);
    // The history reads the model as the detector does (its own copy: the detector is the
    // run's stop rule meanwhile).
    let geometry = history.is_some().then(|| detector.clone());
    let recording = on.is_some() || geometry.is_some();
    let mut record = |m: &M| -> Result<()> {
        if let (Some(h), Some(g)) = (history.as_deref_mut(), &geometry) {
            h.record(m, g);
        }
        match on.as_mut() {
            Some(f) => f(m),
            None => Ok(()),
        }
    };
    if recording {
        record(&built.model)?;
    }
    let result = {
        // Reborrowed for the run (the callbacks' trait objects shortened to the run's borrow).
        let observe = recording.then_some(&mut record as run::Observer<'_, M>);
        let tick = tick.as_mut().map(|f| &mut **f as &mut dyn FnMut(f64));
        let options = run::Options { threading: hooks.threading, lend: hooks.lend, stop: Some(&mut detector), tick, observe, ..Default::default() };
        run::run_with(built, options)?
    };
    let outcome = detector.outcome(&result.model);
    let row = Row {
        v0_fps: scene.projectile.v0_fps,
        angle_deg: scene.projectile.angle_deg,
        level: scene.penetration.level,
        strength_factor: scene.concrete.strength_factor,
        thickness_in: (layout.thickness_m.is_finite()).then(|| layout.thickness_m / M_PER_IN),
        outcome,
        run: result.summary,
    };
    Ok(Finished { row, model: result.model, detector })
}
