//! Exact mass properties of a closed polyhedron by tetrahedral decomposition (Tonon 2004): each
//! face fanned into triangles, each triangle with a reference point a tetrahedron whose volume,
//! first and second moments have closed forms; no quadrature, so exact up to rounding.

use nalgebra::{Matrix3, Vector3};

/// Volume, centroid and inertia of a uniform solid of unit density.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MassProperties {
    /// Volume, m³.
    pub volume: f64,
    /// Centroid, m (in the frame of the vertices given).
    pub centroid: Vector3<f64>,
    /// Inertia tensor about the centroid per unit density, m⁵ (× density in kg/m³ → kg·m²).
    pub inertia: Matrix3<f64>,
}

/// Mass properties of the solid bounded by `faces` (loops of indices into `vertices` (m),
/// counter-clockwise seen from outside; the surface closed).
pub fn mass_properties(vertices: &[Vector3<f64>], faces: &[Vec<usize>]) -> MassProperties {
    // Moments about a point inside the body (the vertex mean) keep the centroid shift small.
    let r = vertices.iter().sum::<Vector3<f64>>() / vertices.len() as f64;
    let (mut volume, mut first, mut second) = (0.0, Vector3::zeros(), Matrix3::zeros());
    for face in faces {
        for k in 1..face.len() - 1 {
            let (a, b, c) = (vertices[face[0]] - r, vertices[face[k]] - r, vertices[face[k + 1]] - r);
            // det = 6 × the signed volume of the tetrahedron (r, a, b, c).
            let det = a.dot(&b.cross(&c));
            let sum = a + b + c;
            volume += det / 6.0;
            first += sum * (det / 24.0);
            // ∫ x xᵀ dV = V/20 (Σ xᵢ xᵢᵀ + (Σ xᵢ)(Σ xᵢ)ᵀ) over the four corners, one at r.
            second += (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose()) * (det / 120.0);
        }
    }
    let shift = first / volume;
    let about_centroid = second - shift * shift.transpose() * volume;
    MassProperties { volume, centroid: r + shift, inertia: Matrix3::identity() * about_centroid.trace() - about_centroid }
}
