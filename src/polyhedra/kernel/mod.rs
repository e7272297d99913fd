//! The polyhedral kernel under the contract of `crate::simulation`: rigid convex polyhedra
//! stepped by central differences (translation) and the seed's splitting (rotation), touching
//! through the Minkowski contact law of `super::law`. A step: the broad phase over bounding
//! boxes ([`broad`]), each candidate pair's narrow phase and law on its own (in parallel on the
//! pool), their pushes added to the bodies in pair order, then each body moved.
//!
//! Bits do not depend on the pool: pairs are listed sorted, each pair's work reads only the
//! state at the step's start and its own spring, and every sum runs in pair or body order.

pub mod broad;
pub mod build;
pub mod contract;
pub mod state;
pub mod step;

use std::ops::Range;

use nalgebra::Vector3;

pub use build::{Member, ModelBuilder};
pub use state::{Ledger, State, Touch};

use super::law::Law;
use super::shape::Polyhedron;
use crate::simulation::Threading;

/// A model of polyhedra ready to step.
#[derive(Debug, Clone)]
pub struct Model {
    // Configuration, fixed when built.
    /// Shapes, shared by bodies (a body names its shape by index).
    pub shapes: Vec<Polyhedron>,
    /// Each body's shape, kind and whether it is held.
    pub members: Vec<Member>,
    /// Laws between kinds, `kind_a × kinds + kind_b` (symmetric).
    pub laws: Vec<Law>,
    /// Number of kinds.
    pub kinds: usize,
    /// Named groups of bodies (`target`, `projectile`, `walls`), contiguous.
    pub groups: Vec<(String, Range<usize>)>,
    /// Gravity, m/s² (may be changed between steps, e.g. to tilt a test's slope).
    pub gravity: Vector3<f64>,
    /// Viscous damping rate c/m of eq 6 on the free bodies' translation and rotation, 1/s
    /// (zero for a physical run; a packing settles with it).
    pub damping_per_s: f64,
    /// Time step, s.
    pub dt_s: f64,
    /// Stability limit the step is compared with (2/ω for the stiffest law on the lightest pair), s.
    pub dt_bound_s: f64,
    /// Where the steps run (the bits never depend on it).
    pub threading: Threading,
    /// Where each body started, m.
    pub initial_m: Vec<[f64; 3]>,
    // What stepping changes.
    /// The evolving state.
    pub state: State,
}

impl Model {
    /// The law between bodies `i` and `j`.
    pub fn law(&self, i: usize, j: usize) -> &Law {
        &self.laws[self.members[i].kind * self.kinds + self.members[j].kind]
    }

    /// The bodies of group `name`.
    pub fn group(&self, name: &str) -> Option<Range<usize>> {
        self.groups.iter().find(|g| g.0 == name).map(|g| g.1.clone())
    }
}
