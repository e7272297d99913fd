//! What the polyhedra tests share: a seeded generator, random convex polyhedra and poses.
#![allow(dead_code)]

use demsweep::polyhedra::Polyhedron;
use nalgebra::{Matrix3, Quaternion, UnitQuaternion, Vector3};

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

/// Volume, first moment and second moment ∫x xᵀ dV by the divergence theorem: with x·n = d on a
/// planar face, V = Σ d A/3, ∫x dV = Σ d ∫x dA/4, ∫x xᵀ dV = Σ d ∫x xᵀ dA/5 (div(x_p x_q x) =
/// 5 x_p x_q); a face's quadratic integral exactly by the three edge midpoints of each triangle.
pub fn by_divergence(vertices: &[Vector3<f64>], faces: &[Vec<usize>]) -> (f64, Vector3<f64>, Matrix3<f64>) {
    // About the first corner, not the library's vertex mean, so rounding differs too.
    let o = vertices[0];
    let (mut v, mut first, mut second) = (0.0, Vector3::zeros(), Matrix3::zeros());
    for f in faces {
        let x: Vec<Vector3<f64>> = f.iter().map(|&k| vertices[k] - o).collect();
        let n = (1..x.len() - 1).map(|k| (x[k] - x[0]).cross(&(x[k + 1] - x[0]))).sum::<Vector3<f64>>().normalize();
        let d = n.dot(&x[0]);
        for k in 1..x.len() - 1 {
            let (a, b, c) = (x[0], x[k], x[k + 1]);
            let area = 0.5 * (b - a).cross(&(c - a)).norm();
            v += d * area / 3.0;
            first += (a + b + c) * (d * area / 12.0);
            for m in [(a + b) * 0.5, (b + c) * 0.5, (c + a) * 0.5] {
                second += m * m.transpose() * (d * area / 15.0);
            }
        }
    }
    let centroid = first / v;
    let about = second - centroid * centroid.transpose() * v;
    (v, centroid + o, Matrix3::identity() * about.trace() - about)
}

/// A quick packing of small rocks (soft law, short phases), for tests of the packed rockfill.
pub fn quick_packing() -> demsweep::polyhedra::settle::Packing {
    demsweep::polyhedra::settle::Packing {
        density: 2650.0,
        law: demsweep::polyhedra::Law { stiffness: 1e6, exponent: 1.0, shear_stiffness: 5e5, friction: 0.5, restitution: 0.3 },
        damping_per_s: 5.0,
        fraction: 0.5,
        lid_speed_mps: 0.5,
        lid_pressure_pa: 2e4,
        phase_s: 0.5,
    }
}
