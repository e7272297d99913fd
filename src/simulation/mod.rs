//! The contract between a kernel and everything above it. A kernel (the 2D bonded disks of
//! `crate::kernel`; [3/5]'s 3D spheres next) is plugged in by implementing two traits, and the
//! layers above — the run loop (`crate::run`), the penetration outcome, sweeps, the ballistic
//! search, the convergence study and the calibration — name nothing else of it:
//!
//! 1. **Build**: a scene description becomes a [`Built`]: the model, what to record
//!    ([`Measure`]), how long to run and how often to record. Which kernel a scene builds is the
//!    scene's business (`crate::scene` builds the 2D kernel; `crate::penetration::run` picks the
//!    kernel of a penetration scene).
//! 2. **Run until settled**: [`Simulation`] steps the model (`run_steps`), on the thread or pool
//!    it is told ([`Threading`]), and saves and restores its whole state bit for bit
//!    (`checkpoint`/`restore`). `crate::run` drives it and asks a stop rule every few steps.
//! 3. **The summary row**: [`Simulation::tally`] is what the kernel puts in a run's row —
//!    counts, the time step and why, the energy ledger ([`Tally`]).
//! 4. **What detectors read**: [`Bodies`] — each element's position, velocity, radius and
//!    mass, which are held in place, and which bonds hold, in three components (a 2D kernel's
//!    z is 0). Outcome detectors, fragments and stop rules read only this.
//!
//! Promises a kernel keeps: SI units throughout; results bit for bit the same on any thread
//! count and after any restore; an unstable step or a NaN is an `Err` naming the step and the
//! element, never a panic or a silently wrong state.

mod bodies;
mod built;
mod model;
mod tally;

pub use bodies::Bodies;
pub use built::{Built, Measure};
pub use model::{Simulation, Threading};
pub use tally::Tally;
