//! Support mappings: the farthest point of a placed polyhedron along a direction, and of the
//! Minkowski difference A ⊖ B (eq 1), which GJK and EPA walk on.

use nalgebra::{UnitQuaternion, Vector3};

use super::shape::Polyhedron;

/// A polyhedron placed in the world.
#[derive(Clone, Copy, Debug)]
pub struct Placed<'a> {
    /// The shape, in its body frame.
    pub shape: &'a Polyhedron,
    /// Its centroid, m.
    pub position: Vector3<f64>,
    /// Its orientation: world vector = orientation × body vector.
    pub orientation: UnitQuaternion<f64>,
}

impl Placed<'_> {
    /// The corner farthest along world direction `d`, in world coordinates, m (the first of the
    /// farthest when several tie, so the answer is the same on every run).
    pub fn support(&self, d: &Vector3<f64>) -> Vector3<f64> {
        let local = self.orientation.inverse_transform_vector(d);
        let mut best = (f64::NEG_INFINITY, 0);
        for (k, v) in self.shape.vertices.iter().enumerate() {
            let h = v.dot(&local);
            if h > best.0 {
                best = (h, k);
            }
        }
        self.world(&self.shape.vertices[best.1])
    }

    /// A body-frame point in world coordinates, m.
    pub fn world(&self, body: &Vector3<f64>) -> Vector3<f64> {
        self.position + self.orientation.transform_vector(body)
    }
}

/// A point of A ⊖ B with the two corners it came from: `w` = `a` − `b`, all in m.
#[derive(Clone, Copy, Debug)]
pub struct Vertex {
    /// The point of the Minkowski difference.
    pub w: Vector3<f64>,
    /// Its corner on A.
    pub a: Vector3<f64>,
    /// Its corner on B.
    pub b: Vector3<f64>,
}

/// The point of A ⊖ B farthest along `d`.
pub fn support(a: &Placed, b: &Placed, d: &Vector3<f64>) -> Vertex {
    let (pa, pb) = (a.support(d), b.support(&-d));
    Vertex { w: pa - pb, a: pa, b: pb }
}
