//! demsweep: a deterministic 2D bonded-disk discrete element method (DEM) for concrete
//! penetration, scabbing and perforation, with the classical empirical formulas beside it.
//!
//! Data flows one way: scene file → [`scene::Scene`] → [`kernel::Model`] → outcome → tables.
//! Internal units are SI (m, kg, s, N, Pa); customary units appear only at the edges
//! ([`units`]) and every public quantity names its unit.

pub mod analysis;
pub mod broad_phase;
pub mod ballistic;
pub mod bench;
pub mod calibrate;
pub mod cases;
pub mod chart;
pub mod units;
pub mod cli;
pub mod converge;
pub mod error;
pub mod fnv;
pub mod keep;
pub mod empirical;

pub use error::{Error, Result};
pub mod kernel;
pub mod kernel3d;
pub mod lattice;
pub mod packing3d;
pub mod material;
pub mod penetration;
pub mod picture;
pub mod polyhedra;
pub mod provenance;
pub mod report;
pub mod run;
pub mod scene;
pub mod scene3d;
pub mod scene_file;
pub mod shape;
pub mod shape3d;
pub mod simulation;
pub mod sweep;
pub mod table;
