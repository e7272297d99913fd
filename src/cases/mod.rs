//! The validation cases of SPEC §3 as scene generators: each case is an ordinary [`Scene`]
//! (so it can be written out as TOML and run with `demsweep run`) plus the analytic reference
//! and the post-processing that turns a run into the figure the source reports.
//!
//! [`Scene`]: crate::scene::Scene

pub mod cantilever;
pub mod cracked_plate;
pub mod fit;
pub mod seed;
pub mod study;
