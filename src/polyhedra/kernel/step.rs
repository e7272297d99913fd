//! One step of the polyhedral model: the broad phase, each candidate pair's contact and law
//! (in parallel, each reading only the step's start and its own spring), the pushes added in
//! pair order, then each body moved (in parallel) and its ledger shares added in body order.

use nalgebra::Vector3;
use rayon::prelude::*;

use super::super::body::Body;
use super::super::law::Act;
use super::super::pair::{Push, interact_act};
use super::Model;
use super::broad::{Aabb, pairs};
use super::state::Touch;
use crate::error::{Error, Result};
use crate::simulation::Threading;

/// What moving one body adds to the ledger, J.
#[derive(Clone, Copy, Default)]
struct Share {
    kinetic: f64,
    viscous: f64,
    gravity: f64,
    held: f64,
}

impl Model {
    /// Advance `n` steps.
    pub fn run_steps(&mut self, n: u64) -> Result<()> {
        for _ in 0..n {
            self.step()?;
        }
        Ok(())
    }

    /// Simulated time, s.
    pub fn time_s(&self) -> f64 {
        self.state.steps as f64 * self.dt_s
    }

    /// Each candidate pair's contact: its push, the law's energies and the spring carried on.
    fn contacts(&self, candidates: &[(u32, u32)]) -> Vec<Option<(Push, Act, [f64; 3])>> {
        let (bodies, old, dt) = (&self.state.bodies, &self.state.touches, self.dt_s);
        let work = |&(i, j): &(u32, u32)| {
            let mut shear = old.binary_search_by(|t| (t.i, t.j).cmp(&(i, j))).map_or(Vector3::zeros(), |k| Vector3::from(old[k].shear));
            let (i, j) = (i as usize, j as usize);
            let (a, b) = ((&bodies[i], &self.shapes[self.members[i].shape]), (&bodies[j], &self.shapes[self.members[j].shape]));
            interact_act(self.law(i, j), a, b, &mut shear, dt).map(|(p, act)| (p, act, shear.into()))
        };
        match self.threading {
            Threading::Pool => candidates.par_iter().map(work).collect(),
            Threading::Serial => candidates.iter().map(work).collect(),
        }
    }

    /// One step.
    fn step(&mut self) -> Result<()> {
        let placed = |k: usize| self.state.bodies[k].placed(&self.shapes[self.members[k].shape]);
        let boxes: Vec<Aabb> = match self.threading {
            Threading::Pool => (0..self.members.len()).into_par_iter().map(|k| Aabb::of(&placed(k))).collect(),
            Threading::Serial => (0..self.members.len()).map(|k| Aabb::of(&placed(k))).collect(),
        };
        let candidates = pairs(&boxes, |i, j| self.members[i].held && self.members[j].held);
        let found = self.contacts(&candidates);
        let n = self.members.len();
        let (mut force, mut torque) = (vec![Vector3::zeros(); n], vec![Vector3::zeros(); n]);
        let (mut touches, mut elastic) = (Vec::new(), 0.0);
        let (ledger, split) = (&mut self.state.ledger, &mut self.state.dissipated_by_kinds);
        for (&(i, j), r) in candidates.iter().zip(found) {
            let Some((p, act, shear)) = r else { continue };
            let (i, j) = (i as usize, j as usize);
            let (a, b) = (&self.members[i], &self.members[j]);
            let class = if a.held || b.held { self.kinds * self.kinds } else { a.kind.min(b.kind) * self.kinds + a.kind.max(b.kind) };
            split[class][0] += act.damping_j;
            split[class][1] += act.friction_j;
            force[i] += p.force_a;
            torque[i] += p.torque_a;
            force[j] += p.force_b;
            torque[j] += p.torque_b;
            elastic += act.elastic_j;
            ledger.damping_j += act.damping_j;
            ledger.friction_j += act.friction_j;
            touches.push(Touch { i: i as u32, j: j as u32, shear });
        }
        let (dt, gravity, c) = (self.dt_s, self.gravity, self.damping_per_s);
        let members = &self.members;
        let advance = |(k, b): (usize, &mut Body)| -> Share { advance(b, members[k].held, &force[k], &torque[k], &gravity, c, dt) };
        let shares: Vec<Share> = match self.threading {
            Threading::Pool => self.state.bodies.par_iter_mut().enumerate().map(advance).collect(),
            Threading::Serial => self.state.bodies.iter_mut().enumerate().map(advance).collect(),
        };
        let ledger = &mut self.state.ledger;
        // Gravity's work of the last step's move brings the external work up to x_n.
        let (mut kinetic, mut gravity_ahead) = (0.0, 0.0);
        for s in &shares {
            kinetic += s.kinetic;
            ledger.viscous_j += s.viscous;
            ledger.held_work_j += s.held;
            ledger.external_j += s.held;
            gravity_ahead += s.gravity;
        }
        ledger.external_j += std::mem::replace(&mut ledger.gravity_ahead_j, gravity_ahead);
        ledger.kinetic_j = kinetic;
        ledger.elastic_j = elastic;
        if self.state.steps == 0 {
            ledger.initial_j = kinetic + elastic;
        }
        self.state.touches = touches;
        self.state.contact_force_n = force.iter().map(|f| (*f).into()).collect();
        self.state.steps += 1;
        if let Some(k) = self.state.bodies.iter().position(|b| !(b.position.iter().chain(b.velocity.iter()).all(|x| x.is_finite()))) {
            return Err(Error::BlowUp { step: self.state.steps, time_s: self.time_s(), element: k, detail: "a position or velocity is not finite".into() });
        }
        Ok(())
    }
}

/// Moves one body over the step under its contact force and torque (N, N·m), gravity (m/s²)
/// and the viscous rate `c` (1/s); a held body moves at its own velocity. Its ledger shares.
fn advance(b: &mut Body, held: bool, force: &Vector3<f64>, torque: &Vector3<f64>, gravity: &Vector3<f64>, c: f64, dt: f64) -> Share {
    if held {
        b.position += b.velocity * dt;
        // What the held body's motion does to the rest: their push on it is `force`.
        return Share { held: -force.dot(&b.velocity) * dt, ..Share::default() };
    }
    let (v0, l0, inertia) = (b.velocity, b.spin.momentum, b.inertia);
    let viscous_torque = -b.spin.world_momentum() * c;
    let total = force + gravity * b.mass - v0 * (c * b.mass);
    let total_torque = torque + viscous_torque;
    // The body-frame momentum after the kick, before the free rotation (`Spin::step`).
    let kicked = l0 + b.spin.orientation.inverse_transform_vector(&total_torque) * dt;
    b.step(&total, &total_torque, dt);
    let v1 = b.velocity;
    // Whole-step energies from the two half-step velocities: ½ m v⁻·v⁺, ½ Σ L⁻ᵢ L⁺ᵢ / Jᵢ.
    let rotational = 0.5 * l0.component_mul(&kicked).component_div(&inertia).sum();
    let spin_mean = (l0 + kicked).component_div(&inertia) * 0.5;
    Share {
        kinetic: 0.5 * b.mass * v0.dot(&v1) + rotational,
        viscous: c * (b.mass * v0.dot(&((v0 + v1) * 0.5)) + l0.dot(&spin_mean)) * dt,
        gravity: b.mass * gravity.dot(&v1) * dt,
        held: 0.0,
    }
}
