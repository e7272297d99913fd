//! What the polyhedra tests share: a seeded generator, random convex polyhedra and poses.
#![allow(dead_code)]

use demsweep::polyhedra::Polyhedron;
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// A 64-bit permuted congruential generator (PCG-XSH-RR's state step with a xorshift output),
/// seeded, so every test draws the same shapes on every machine.
pub struct Draw(pub u64);

impl Draw {
    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        let mut x = self.0;
        x ^= x >> 33;
        x = x.wrapping_mul(0xff51_afd7_ed55_8ccd);
        x ^= x >> 33;
        (x >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn between(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// A point uniform in the ball of radius `r`.
    pub fn in_ball(&mut self, r: f64) -> Vector3<f64> {
        loop {
            let p = Vector3::new(self.between(-1.0, 1.0), self.between(-1.0, 1.0), self.between(-1.0, 1.0));
            if p.norm_squared() <= 1.0 {
                return p * r;
            }
        }
    }

    /// A random orientation (uniform over rotations: a normalised point of the 4-ball).
    pub fn orientation(&mut self) -> UnitQuaternion<f64> {
        loop {
            let q = Quaternion::new(self.between(-1.0, 1.0), self.between(-1.0, 1.0), self.between(-1.0, 1.0), self.between(-1.0, 1.0));
            let n = q.norm();
            if n > 0.1 && n <= 1.0 {
                return UnitQuaternion::from_quaternion(q);
            }
        }
    }

    /// The hull of `count` points in the ball of radius `r` (m), as a rock-like convex cell.
    pub fn polyhedron(&mut self, count: usize, r: f64) -> Polyhedron {
        let points: Vec<Vector3<f64>> = (0..count).map(|_| self.in_ball(r)).collect();
        Polyhedron::from_points(&points, 1e-12 * r).unwrap()
    }
}
