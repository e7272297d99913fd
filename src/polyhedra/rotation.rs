//! The seed's rotation update (eqs 18–25, after Dullweber, Leimkuhler & McLachlan 1997): a torque
//! kick of the angular momentum, then the free rotor split into rotations about the body axes
//! 1, 2, 3, 2, 1 (half, half, full, half, half step). Each sub-rotation turns the body and
//! counter-turns the body-frame angular momentum, so the world angular momentum is kept exactly
//! (up to rounding) and the scheme is symplectic and time-reversible.

use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// The rotational state of a rigid body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spin {
    /// Orientation: world vector = `orientation` × body vector (eq 16's R(q, v)).
    pub orientation: UnitQuaternion<f64>,
    /// Angular momentum in the body (principal) frame, kg·m²/s.
    pub momentum: Vector3<f64>,
}

impl Spin {
    /// Angular velocity in the body frame, rad/s, for principal moments `inertia` (kg·m²), eq 25.
    pub fn body_velocity(&self, inertia: &Vector3<f64>) -> Vector3<f64> {
        self.momentum.component_div(inertia)
    }

    /// Angular velocity in the world frame, rad/s (eq 24).
    pub fn velocity(&self, inertia: &Vector3<f64>) -> Vector3<f64> {
        self.orientation.transform_vector(&self.body_velocity(inertia))
    }

    /// Angular momentum in the world frame, kg·m²/s.
    pub fn world_momentum(&self) -> Vector3<f64> {
        self.orientation.transform_vector(&self.momentum)
    }

    /// Rotational kinetic energy, J: ½ L̄ · J̄⁻¹ L̄.
    pub fn energy(&self, inertia: &Vector3<f64>) -> f64 {
        0.5 * self.momentum.dot(&self.body_velocity(inertia))
    }

    /// One step of `dt` (s) under the world torque `torque` (N·m), held over the step (eqs 18–25).
    pub fn step(&mut self, inertia: &Vector3<f64>, torque: &Vector3<f64>, dt: f64) {
        // Eqs 18–19: the kick, taken in the body frame of the step's start.
        self.momentum += self.orientation.inverse_transform_vector(torque) * dt;
        // Eq 23: the symmetric sequence of sub-rotations.
        for (axis, fraction) in [(0, 0.5), (1, 0.5), (2, 1.0), (1, 0.5), (0, 0.5)] {
            self.turn(inertia, axis, fraction * dt);
        }
        // Products of unit quaternions drift off the unit sphere by rounding: pull back.
        self.orientation = UnitQuaternion::new_normalize(self.orientation.into_inner());
    }

    /// Eqs 20–22: the free rotation about body axis `axis` for `h` (s), the angle h L̄ᵢ/J̄ᵢ in its
    /// Cayley form (s, c exactly on the unit circle), the body turned and L̄ counter-turned.
    fn turn(&mut self, inertia: &Vector3<f64>, axis: usize, h: f64) {
        let phi = 0.5 * h * self.momentum[axis] / inertia[axis];
        let denominator = 1.0 + 0.25 * phi * phi;
        let mut v = Vector3::zeros();
        v[axis] = phi / denominator;
        let increment = UnitQuaternion::new_unchecked(Quaternion::from_parts((1.0 - 0.25 * phi * phi) / denominator, v));
        self.orientation *= increment;
        self.momentum = increment.inverse_transform_vector(&self.momentum);
    }
}
