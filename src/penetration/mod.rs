//! The product's scene: a concrete target struck by a projectile, run until its outcome is
//! settled. One room for its three parts, in the order data flows through them:
//! * [`scene`]: the scene file's fields (seed 000 §7, Tables 7.1–7.2), checked, and the kernel
//!   scene they build;
//! * [`run`](mod@run): the kernel run with the outcome detector as its stop rule, reported as
//!   one typed row;
//! * [`outcome`] and [`fragments`]: what the run did to the target (depth, scabbing,
//!   perforation, spall) and when it is settled, from positions and bonds; [`history`], the
//!   same and the energies, near the path and far from it, against time.

pub mod fragments;
pub mod history;
pub mod outcome;
pub mod run;
pub mod scene;
pub mod slab;

pub use run::{Finished, Hooks, Row, row, run, run3, run_on};
pub use scene::PenetrationScene;
