//! The seed's projectile (Fig. 5) as a polyhedron: a tangent-ogive nose on a cylinder, the nose's
//! arc cut into equal angles and the round into equal sectors (12 × 36 in the seed), so the
//! same polyhedral contact takes it. Its mass properties are the polyhedron's at one density;
//! the seed's inner cavity is not modelled here (the scene sets the mass it wants).

use nalgebra::Vector3;

use super::shape::Polyhedron;
use crate::{Error, Result};

/// The projectile's outline (seed Fig. 5), read as overall length H, ogive radius R, calibre D.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ogive {
    /// Overall length H, tip to base, m (the seed: 0.8).
    pub length: f64,
    /// Radius R of the ogive's arc, m (the seed: 0.5).
    pub ogive_radius: f64,
    /// Calibre D, m (the seed: 0.15).
    pub calibre: f64,
    /// Divisions of the nose's arc (the seed: 12).
    pub head_divisions: usize,
    /// Sectors round the axis (the seed: 36).
    pub around: usize,
}

impl Ogive {
    /// The seed's projectile.
    pub fn seed() -> Self {
        Ogive { length: 0.8, ogive_radius: 0.5, calibre: 0.15, head_divisions: 12, around: 36 }
    }

    /// Refuses each bad field by name.
    pub fn check(&self, field: &str) -> Result<()> {
        let bad = |name: &str, message: &str| Err(Error::input(format!("{field}.{name}"), message));
        if !(self.calibre > 0.0 && self.calibre.is_finite()) {
            return bad("calibre", "must be positive (m)");
        }
        if !(self.ogive_radius >= 0.5 * self.calibre && self.ogive_radius.is_finite()) {
            return bad("ogive_radius", "must be at least half the calibre (m)");
        }
        if !(self.length > self.nose_length() && self.length.is_finite()) {
            return bad("length", "must exceed the nose's length √(R² − (R − D/2)²) (m)");
        }
        if self.head_divisions < 1 {
            return bad("head_divisions", "must be at least 1");
        }
        if self.around < 3 {
            return bad("around", "must be at least 3");
        }
        Ok(())
    }

    /// The nose's length, m: where the arc of radius R meets the cylinder tangentially.
    pub fn nose_length(&self) -> f64 {
        let (r, half) = (self.ogive_radius, 0.5 * self.calibre);
        (r * r - (r - half) * (r - half)).sqrt()
    }

    /// The outline's corners from the tip, as (distance from the tip, radius), m: the tip, the
    /// ends of the nose's divisions (equal angles of its arc), and the base.
    pub fn profile(&self) -> Vec<(f64, f64)> {
        let (r, half, nose) = (self.ogive_radius, 0.5 * self.calibre, self.nose_length());
        let arc = (nose / r).asin();
        let mut out: Vec<(f64, f64)> = (0..=self.head_divisions)
            .map(|k| {
                let beta = arc * (1.0 - k as f64 / self.head_divisions as f64);
                (nose - r * beta.sin(), r * beta.cos() - (r - half))
            })
            .collect();
        // The tip exactly on the axis, the shoulder exactly at the calibre.
        out[0] = (0.0, 0.0);
        out[self.head_divisions] = (nose, half);
        out.push((self.length, half));
        out
    }

    /// The polyhedron, axis along x before its principal frame is taken (the axis is then its
    /// first principal axis, the least moment).
    pub fn polyhedron(&self) -> Polyhedron {
        let profile = self.profile();
        let n = self.around;
        let mut vertices = vec![Vector3::zeros()];
        for &(x, radius) in &profile[1..] {
            for j in 0..n {
                let angle = std::f64::consts::TAU * j as f64 / n as f64;
                vertices.push(Vector3::new(x, radius * angle.cos(), radius * angle.sin()));
            }
        }
        let ring = |k: usize, j: usize| 1 + (k - 1) * n + j % n;
        let mut faces: Vec<Vec<usize>> = (0..n).map(|j| vec![0, ring(1, j), ring(1, j + 1)]).collect();
        for k in 1..profile.len() - 1 {
            faces.extend((0..n).map(|j| vec![ring(k, j), ring(k + 1, j), ring(k + 1, j + 1), ring(k, j + 1)]));
        }
        faces.push((0..n).map(|j| ring(profile.len() - 1, j)).collect());
        // Each loop turned to run counter-clockwise seen from outside (the axis is inside).
        let inside = Vector3::new(0.5 * self.length, 0.0, 0.0);
        for f in &mut faces {
            let normal: Vector3<f64> = (0..f.len()).map(|k| vertices[f[k]].cross(&vertices[f[(k + 1) % f.len()]])).sum();
            if normal.dot(&(vertices[f[0]] - inside)) < 0.0 {
                f.reverse();
            }
        }
        Polyhedron::from_faces(&vertices, faces)
    }
}
