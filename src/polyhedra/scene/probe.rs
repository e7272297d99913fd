//! What a rockfill run records of the projectile, as series columns.

use super::super::kernel::Model;
use crate::simulation::Measure;

/// A quantity of the projectile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Quantity {
    /// Speed, m/s (its final value is the residual velocity).
    Speed,
    /// Velocity along the line of fire (+x), m/s.
    AlongPath,
    /// Resistance: the rocks' push against the motion, −F·v/|v|, N.
    Resistance,
    /// Deflection: angle of the velocity from the line of fire, degrees.
    Deflection,
    /// Yaw: angle of the projectile's axis from the line of fire, degrees.
    Yaw,
    /// The nose's distance along the line of fire from the layer's face, m.
    NoseX,
    /// The time, s, once the whole projectile is past the far face, NaN before: the series'
    /// least value is the exit time, to within a record interval.
    ExitTime,
}

/// A probe on the projectile (`body`), with the far face of the layer at x = `far_face_m` (m).
#[derive(Debug, Clone)]
pub struct Probe {
    /// What it reads.
    pub quantity: Quantity,
    /// The projectile's body index.
    pub body: usize,
    /// The layer's far face, m.
    pub far_face_m: f64,
}

impl Measure<Model> for Probe {
    fn name(&self) -> &str {
        match self.quantity {
            Quantity::Speed => "projectile_speed_mps",
            Quantity::AlongPath => "projectile_vx_mps",
            Quantity::Resistance => "resistance_n",
            Quantity::Deflection => "deflection_deg",
            Quantity::Yaw => "yaw_deg",
            Quantity::NoseX => "nose_x_m",
            Quantity::ExitTime => "exit_time_s",
        }
    }

    fn value(&self, m: &Model) -> f64 {
        let b = &m.state.bodies[self.body];
        let shape = &m.shapes[m.members[self.body].shape];
        let v = b.velocity;
        let extent = |sign: f64| shape.vertices.iter().map(|p| sign * b.placed(shape).world(p).x).fold(f64::NEG_INFINITY, f64::max) * sign;
        match self.quantity {
            Quantity::Speed => v.norm(),
            Quantity::AlongPath => v.x,
            Quantity::Resistance => -nalgebra::Vector3::from(m.state.contact_force_n[self.body]).dot(&v) / v.norm(),
            Quantity::Deflection => (v.x / v.norm()).clamp(-1.0, 1.0).acos().to_degrees(),
            // The axis is the body frame's first principal axis (least moment).
            Quantity::Yaw => b.spin.orientation.transform_vector(&nalgebra::Vector3::x()).x.abs().clamp(0.0, 1.0).acos().to_degrees(),
            Quantity::NoseX => extent(1.0),
            Quantity::ExitTime => {
                if extent(-1.0) > self.far_face_m {
                    m.time_s()
                } else {
                    f64::NAN
                }
            }
        }
    }
}
