//! Sweeps: one scene run over a grid of field values (`--vary FIELD=START..END:STEP`) or over a
//! parameter table (one column per dotted scene field, as yade-batch reads its tables). Each run
//! is one rayon task on one thread ([`engine`]); each finished run goes to one writer thread,
//! which keeps the runs table ([`store`]) on disk, atomically, in a fixed order. `ballistic` and
//! `converge` plan their runs and hand them to the same engine.
//!
//! Every row names its inputs: `run_id` (the overrides that made it, e.g.
//! `projectile.v0_fps=850`), `scene_hash` (a hash of the whole base scene as read, defaults
//! included, and of the crate version), `build` (the program that made it, [`crate::provenance::build_id`])
//! and `level`; a row can be traced to the exact run and the exact code.

pub mod engine;
pub mod hash;
pub mod job;
pub mod parquet;
pub mod plan;
pub mod progress;
pub mod range;
pub mod share;
pub mod store;

pub use engine::{Engine, Finished};
pub use job::{Job, Row, run_job};
pub use plan::{Vary, grid, from_table};
pub use store::{Reuse, Store};
