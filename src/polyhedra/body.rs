//! A rigid polyhedral body's motion: translation by central differences (velocity at half
//! steps, seed eq 6 without damping), rotation by the seed's splitting ([`Spin::step`]).

use nalgebra::{UnitQuaternion, Vector3};

use super::rotation::Spin;
use super::shape::Polyhedron;
use super::support::Placed;

/// A rigid body's mass and motion state (its shape kept apart, shared between bodies).
#[derive(Clone, Copy, Debug)]
pub struct Body {
    /// Mass, kg.
    pub mass: f64,
    /// Principal moments of inertia, kg·m², along the shape's body axes.
    pub inertia: Vector3<f64>,
    /// Centroid, m.
    pub position: Vector3<f64>,
    /// Centroid velocity, m/s (at the half step behind `position`).
    pub velocity: Vector3<f64>,
    /// Orientation and body-frame angular momentum.
    pub spin: Spin,
}

impl Body {
    /// A body of `shape` at density `density` (kg/m³), centroid at `position` (m), turned by
    /// `orientation` from the shape's body frame, at rest.
    pub fn new(shape: &Polyhedron, density: f64, position: Vector3<f64>, orientation: UnitQuaternion<f64>) -> Self {
        let spin = Spin { orientation, momentum: Vector3::zeros() };
        Body { mass: density * shape.volume, inertia: shape.principal * density, position, velocity: Vector3::zeros(), spin }
    }

    /// The body's shape placed where the body is.
    pub fn placed<'a>(&self, shape: &'a Polyhedron) -> Placed<'a> {
        Placed { shape, position: self.position, orientation: self.spin.orientation }
    }

    /// Velocity of the body's material point at world point `x` (m), m/s.
    pub fn point_velocity(&self, x: &Vector3<f64>) -> Vector3<f64> {
        self.velocity + self.spin.velocity(&self.inertia).cross(&(x - self.position))
    }

    /// Sets the world angular velocity, rad/s.
    pub fn set_angular_velocity(&mut self, omega: &Vector3<f64>) {
        self.spin.momentum = self.spin.orientation.inverse_transform_vector(omega).component_mul(&self.inertia);
    }

    /// Kinetic energy, J: translation and rotation.
    pub fn kinetic_energy(&self) -> f64 {
        0.5 * self.mass * self.velocity.norm_squared() + self.spin.energy(&self.inertia)
    }

    /// One step of `dt` (s) under the world force `force` (N) and torque `torque` (N·m) about
    /// the centroid.
    pub fn step(&mut self, force: &Vector3<f64>, torque: &Vector3<f64>, dt: f64) {
        self.velocity += force * (dt / self.mass);
        self.position += self.velocity * dt;
        self.spin.step(&self.inertia, torque, dt);
    }
}
