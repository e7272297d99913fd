//! Which program made a result: the build id, a hash of the sources a run's result depends on
//! and the locked dependencies (`build.rs`), given to the crate as `DEMSWEEP_BUILD`. A sweep
//! keeps it in every row and reuses a row only under the same id; a checkpoint names it and is
//! refused by another build.

/// The id of this build of demsweep (16 hex digits). Two binaries with the same id compute the
/// same runs; a change to what only reads or draws the runs (the command line, pictures, the
/// formulas, the fits) keeps it.
pub fn build_id() -> &'static str {
    env!("DEMSWEEP_BUILD")
}
