//! What a run drives: a model that steps, saves and restores itself, and reports its ledger.

use serde::{Deserialize, Serialize};

use super::{Bodies, Tally};
use crate::error::Result;

/// Where a model's steps run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum Threading {
    /// On the rayon pool the caller runs in, when the model is large enough (a lone run).
    #[default]
    Pool,
    /// On the calling thread only (a run inside a sweep, which is itself one task of the pool).
    Serial,
}

/// A kernel's model as `crate::run` drives it. Its results may not depend on [`Threading`],
/// on how the steps are batched into `run_steps` calls, or on a checkpoint and restore between
/// them.
pub trait Simulation: Bodies + Send {
    /// Time step, s.
    fn dt_s(&self) -> f64;
    /// Completed steps.
    fn steps(&self) -> u64;
    /// Advance `n` steps. An unstable step or a NaN is an error naming the step and the
    /// element; the state is then unusable (the caller must not write it out).
    fn run_steps(&mut self, n: u64) -> Result<()>;
    /// Where the steps run now.
    fn threading(&self) -> Threading;
    /// Run the next steps here or on the pool.
    fn set_threading(&mut self, threading: Threading);
    /// The evolving state as bytes, restorable into the same scene's model.
    fn checkpoint(&self) -> Vec<u8>;
    /// Continue from [`Simulation::checkpoint`]'s bytes; an error names what does not fit.
    fn restore(&mut self, bytes: &[u8]) -> Result<()>;
    /// Contacts now (bonded or touching).
    fn contact_count(&self) -> u64;
    /// Intact bonds now.
    fn bond_count(&self) -> u64;
    /// What the kernel reports in a run's summary row.
    fn tally(&self) -> Tally;
}
