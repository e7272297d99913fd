//! Putting a polyhedral model together: shapes, bodies of kinds, the laws between kinds, and
//! the time step checked against the stiffest law on the lightest pair.

use std::ops::Range;

use nalgebra::Vector3;

use super::super::body::Body;
use super::super::law::Law;
use super::super::shape::Polyhedron;
use super::state::{Ledger, State};
use super::Model;
use crate::error::{Error, Result};
use crate::simulation::Threading;

/// A body's configuration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Member {
    /// Index of its shape in `Model::shapes`.
    pub shape: usize,
    /// Its kind (which laws it meets others by).
    pub kind: usize,
    /// Held: moved at its own velocity, whatever pushes it (a wall); infinite mass.
    pub held: bool,
}

/// Collects a model's parts.
#[derive(Debug, Clone)]
pub struct ModelBuilder {
    shapes: Vec<Polyhedron>,
    members: Vec<Member>,
    bodies: Vec<Body>,
    laws: Vec<Law>,
    kinds: usize,
    groups: Vec<(String, Range<usize>)>,
    /// Gravity, m/s².
    pub gravity: Vector3<f64>,
    /// Viscous damping rate of eq 6, 1/s.
    pub damping_per_s: f64,
}

impl ModelBuilder {
    /// A builder for bodies of `kinds` kinds, `laws[a × kinds + b]` between kinds a and b (each
    /// law checked, and the table symmetric).
    pub fn new(kinds: usize, laws: Vec<Law>) -> Result<Self> {
        if laws.len() != kinds * kinds {
            return Err(Error::input("laws", format!("{} laws for {kinds} kinds; {} wanted", laws.len(), kinds * kinds)));
        }
        for a in 0..kinds {
            for b in 0..kinds {
                laws[a * kinds + b].check(&format!("laws[{a}][{b}]"))?;
                if laws[a * kinds + b] != laws[b * kinds + a] {
                    return Err(Error::input(format!("laws[{a}][{b}]"), "must equal the law of the pair the other way round"));
                }
            }
        }
        Ok(ModelBuilder { shapes: Vec::new(), members: Vec::new(), bodies: Vec::new(), laws, kinds, groups: Vec::new(), gravity: Vector3::zeros(), damping_per_s: 0.0 })
    }

    /// Adds a shape; its index.
    pub fn shape(&mut self, shape: Polyhedron) -> usize {
        self.shapes.push(shape);
        self.shapes.len() - 1
    }

    /// The shape at `index`.
    pub fn shape_at(&self, index: usize) -> &Polyhedron {
        &self.shapes[index]
    }

    /// Adds a free body of shape `shape` and kind `kind`; its index.
    pub fn body(&mut self, shape: usize, kind: usize, body: Body) -> usize {
        self.members.push(Member { shape, kind, held: false });
        self.bodies.push(body);
        self.bodies.len() - 1
    }

    /// Adds a held body (a wall) of shape `shape` and kind `kind` moving at `velocity` (m/s),
    /// its mass and inertia infinite; its index.
    pub fn held(&mut self, shape: usize, kind: usize, mut body: Body, velocity: Vector3<f64>) -> usize {
        body.mass = f64::INFINITY;
        body.inertia = Vector3::repeat(f64::INFINITY);
        body.velocity = velocity;
        body.spin.momentum = Vector3::zeros();
        self.members.push(Member { shape, kind, held: true });
        self.bodies.push(body);
        self.bodies.len() - 1
    }

    /// Names the bodies added since `start` as group `name`.
    pub fn group(&mut self, name: &str, start: usize) {
        self.groups.push((name.to_string(), start..self.bodies.len()));
    }

    /// Bodies so far.
    pub fn len(&self) -> usize {
        self.bodies.len()
    }

    /// True before any body is added.
    pub fn is_empty(&self) -> bool {
        self.bodies.is_empty()
    }

    /// The stability limit, s: 2/ω with ω² = k (1/m_a + 1/m_b) for each pair of kinds, m the
    /// lightest free body of a kind made lighter by its turning (1/m + r²/J_min, r its bounding
    /// radius), k the linear stiffness (a power law's tangent stiffness at an overlap of 5 % of
    /// the smaller bounding radius).
    pub fn dt_bound_s(&self) -> f64 {
        let mut compliance = vec![0.0f64; self.kinds];
        let mut radius = vec![f64::INFINITY; self.kinds];
        for (m, b) in self.members.iter().zip(&self.bodies) {
            let r = self.shapes[m.shape].radius();
            if !m.held {
                compliance[m.kind] = compliance[m.kind].max(1.0 / b.mass + r * r / b.inertia.min());
            }
            radius[m.kind] = radius[m.kind].min(r);
        }
        let mut omega2 = 0.0f64;
        for a in 0..self.kinds {
            for b in 0..self.kinds {
                let law = &self.laws[a * self.kinds + b];
                let overlap = 0.05 * radius[a].min(radius[b]);
                let k = law.exponent * law.stiffness * if law.exponent > 1.0 { overlap.powf(law.exponent - 1.0) } else { 1.0 };
                omega2 = omega2.max(k * (compliance[a] + compliance[b]));
            }
        }
        2.0 / omega2.sqrt()
    }

    /// The model, stepping at `dt_s` (s); refused above the stability limit.
    pub fn build(self, dt_s: f64) -> Result<Model> {
        let bound = self.dt_bound_s();
        if !(dt_s > 0.0 && dt_s <= bound) {
            return Err(Error::UnstableStep { requested_s: dt_s, bound_s: bound, detail: "2/ω of the stiffest law on the lightest pair of bodies, turning included".into() });
        }
        let n = self.bodies.len();
        Ok(Model {
            initial_m: self.bodies.iter().map(|b| b.position.into()).collect(),
            state: State { bodies: self.bodies, touches: Vec::new(), contact_force_n: vec![[0.0; 3]; n], steps: 0, ledger: Ledger::default(), dissipated_by_kinds: vec![[0.0; 2]; self.kinds * self.kinds + 1] },
            shapes: self.shapes,
            members: self.members,
            laws: self.laws,
            kinds: self.kinds,
            groups: self.groups,
            gravity: self.gravity,
            damping_per_s: self.damping_per_s,
            dt_s,
            dt_bound_s: bound,
            threading: Threading::default(),
        })
    }
}
