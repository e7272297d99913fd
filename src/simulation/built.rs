//! A scene built for a kernel: what a run starts from.

use std::fmt::Debug;
use std::sync::Arc;

/// A quantity a run records as a time series column (a probe of a scene).
pub trait Measure<M>: Debug + Send + Sync {
    /// The column's name, with its unit (`tip_uy_m`).
    fn name(&self) -> &str;
    /// Its value on the model's present state.
    fn value(&self, model: &M) -> f64;
}

/// A built scene, ready to run: the model and what the run records.
#[derive(Debug, Clone)]
pub struct Built<M> {
    /// Scene name.
    pub name: String,
    /// The model.
    pub model: M,
    /// The series' columns after `time_s`.
    pub probes: Vec<Arc<dyn Measure<M>>>,
    /// Simulated time to run (a stop rule's cap), s.
    pub duration_s: f64,
    /// Steps between records.
    pub every_steps: u64,
}
