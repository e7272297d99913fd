//! A rigid convex polyhedron in its body frame: origin at the centroid, axes along the principal
//! axes of inertia (moments ascending), so the rotation update works on a diagonal inertia.

use nalgebra::{Matrix3, Rotation3, UnitQuaternion, Vector3};

use super::hull::{Hull, hull};
use super::mass::mass_properties;
use crate::Result;

/// A convex polyhedron in its body frame.
#[derive(Clone, Debug)]
pub struct Polyhedron {
    /// Corners in the body frame, m.
    pub vertices: Vec<Vector3<f64>>,
    /// Faces as loops of vertex indices, counter-clockwise seen from outside.
    pub faces: Vec<Vec<usize>>,
    /// Outward unit normal of each face, body frame.
    pub normals: Vec<Vector3<f64>>,
    /// Each edge once, as (lower, higher) vertex index.
    pub edges: Vec<(usize, usize)>,
    /// Volume, m³.
    pub volume: f64,
    /// Principal moments of inertia per unit density, ascending, m⁵ (× density → kg·m²).
    pub principal: Vector3<f64>,
    /// Where the body frame sat in the frame the vertices were given in: input point =
    /// `rest_position` + `rest_orientation` × body point. Position in m.
    pub rest_position: Vector3<f64>,
    /// The body frame's orientation in the input frame.
    pub rest_orientation: UnitQuaternion<f64>,
}

impl Polyhedron {
    /// The hull of `points` (m); `tol` (m) how far off a plane a point still lies on it.
    pub fn from_points(points: &[Vector3<f64>], tol: f64) -> Result<Self> {
        let Hull { vertices, faces } = hull(points, tol)?;
        Ok(Self::from_faces(&vertices, faces))
    }

    /// A polyhedron from its corners (m) and faces (loops, counter-clockwise seen from outside;
    /// the caller vouches that they bound a convex solid).
    pub fn from_faces(vertices: &[Vector3<f64>], faces: Vec<Vec<usize>>) -> Self {
        let props = mass_properties(vertices, &faces);
        let (axes, principal) = principal_axes(&props.inertia);
        let rest_orientation = UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(axes));
        let body: Vec<Vector3<f64>> = vertices.iter().map(|v| rest_orientation.inverse_transform_vector(&(v - props.centroid))).collect();
        let normals = faces.iter().map(|f| face_normal(&body, f)).collect();
        let mut edges: Vec<(usize, usize)> =
            faces.iter().flat_map(|f| (0..f.len()).map(move |k| (f[k].min(f[(k + 1) % f.len()]), f[k].max(f[(k + 1) % f.len()])))).collect();
        edges.sort_unstable();
        edges.dedup();
        Polyhedron { vertices: body, faces, normals, edges, volume: props.volume, principal, rest_position: props.centroid, rest_orientation }
    }

    /// A rectangular block of edges `size` (m) along x, y, z.
    pub fn cuboid(size: &Vector3<f64>) -> Self {
        let half = size * 0.5;
        let corner = |k: usize| Vector3::new([-half.x, half.x][k & 1], [-half.y, half.y][(k >> 1) & 1], [-half.z, half.z][(k >> 2) & 1]);
        // Faces counter-clockwise seen from outside: −x, +x, −y, +y, −z, +z.
        let faces = vec![vec![0, 4, 6, 2], vec![1, 3, 7, 5], vec![0, 1, 5, 4], vec![2, 6, 7, 3], vec![0, 2, 3, 1], vec![4, 5, 7, 6]];
        Self::from_faces(&(0..8).map(corner).collect::<Vec<_>>(), faces)
    }

    /// The largest distance of a corner from the centroid, m (the bounding sphere's radius).
    pub fn radius(&self) -> f64 {
        self.vertices.iter().map(|v| v.norm()).fold(0.0, f64::max)
    }
}

/// Principal axes (columns, right-handed) and moments (ascending) of a symmetric inertia tensor.
fn principal_axes(inertia: &Matrix3<f64>) -> (Matrix3<f64>, Vector3<f64>) {
    let eigen = inertia.symmetric_eigen();
    let mut order = [0, 1, 2];
    order.sort_by(|&a, &b| eigen.eigenvalues[a].total_cmp(&eigen.eigenvalues[b]));
    let mut axes = Matrix3::from_columns(&order.map(|k| eigen.eigenvectors.column(k).into_owned()));
    if axes.determinant() < 0.0 {
        axes.set_column(2, &(-axes.column(2)));
    }
    (axes, Vector3::from(order.map(|k| eigen.eigenvalues[k])))
}

/// The outward unit normal of a planar face loop, from Newell's sum (robust for any convex loop).
fn face_normal(vertices: &[Vector3<f64>], face: &[usize]) -> Vector3<f64> {
    let n: Vector3<f64> = (0..face.len()).map(|k| vertices[face[k]].cross(&vertices[face[(k + 1) % face.len()]])).sum();
    n.normalize()
}
