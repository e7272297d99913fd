//! EPA (van den Bergen 2001): from GJK's simplex, grows a polytope inside A ⊖ B until its face
//! nearest the origin is a face of A ⊖ B; that face gives the Minkowski contact features
//! (eqs 2–3): overlap δ_M, normal n_M and the contact points.

use nalgebra::Vector3;

use super::support::{Placed, Vertex, support};

/// The Minkowski contact features of two overlapping polyhedra (seed eqs 2–3).
#[derive(Clone, Copy, Debug)]
pub struct Contact {
    /// Minkowski overlap δ_M, m: the shortest translation of B that brings the two to touch.
    pub depth: f64,
    /// Contact normal n_M (unit), pointing from A towards B: B moved by δ_M n_M just touches A.
    pub normal: Vector3<f64>,
    /// Contact point on A, c₁, m (world).
    pub on_a: Vector3<f64>,
    /// Contact point on B, c₂, m (world); c₁ − c₂ = δ_M n_M.
    pub on_b: Vector3<f64>,
}

impl Contact {
    /// The common contact point c_M = (c₁ + c₂)/2, m (eq 3).
    pub fn point(&self) -> Vector3<f64> {
        (self.on_a + self.on_b) * 0.5
    }
}

/// A face of the growing polytope, corners counter-clockwise seen from outside.
#[derive(Clone, Copy, Debug)]
struct Face {
    corners: [usize; 3],
    normal: Vector3<f64>,
    /// Distance of its plane from the origin, m (negative only by rounding).
    distance: f64,
}

/// Steps before EPA stops; each adds a vertex of A ⊖ B, which has at most |A|·|B| of them.
const MAX_ITERATIONS: usize = 256;

/// The contact features of `a` and `b`, which GJK found overlapping with `simplex`.
pub fn epa(a: &Placed, b: &Placed, simplex: Vec<Vertex>) -> Contact {
    let scale = a.shape.radius() + b.shape.radius();
    let tol = 1e-12 * scale;
    let mut points = simplex;
    if !fill(a, b, &mut points, tol) {
        // A ⊖ B is flat here only if a body is: report a touch at the one point known.
        return Contact { depth: 0.0, normal: Vector3::x(), on_a: points[0].a, on_b: points[0].b };
    }
    let inside = points.iter().map(|p| p.w).sum::<Vector3<f64>>() / 4.0;
    let mut faces: Vec<Face> = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]].iter().map(|&c| face(&points, c, &inside)).collect();
    let mut nearest = faces[0];
    for _ in 0..MAX_ITERATIONS {
        nearest = *faces.iter().min_by(|x, y| x.distance.total_cmp(&y.distance)).expect("a closed polytope");
        let p = support(a, b, &nearest.normal);
        if nearest.normal.dot(&p.w) - nearest.distance <= tol {
            break;
        }
        points.push(p);
        let new = points.len() - 1;
        // The faces the new point sees go; the loop of edges around them (the horizon) is
        // joined to the new point.
        let (seen, kept): (Vec<Face>, Vec<Face>) = faces.into_iter().partition(|f| f.normal.dot(&(p.w - points[f.corners[0]].w)) > tol);
        let edges: Vec<(usize, usize)> = seen.iter().flat_map(|f| [0, 1, 2].map(|k| (f.corners[k], f.corners[(k + 1) % 3]))).collect();
        faces = kept;
        for &(i, j) in edges.iter().filter(|(i, j)| !edges.contains(&(*j, *i))) {
            faces.push(face(&points, [i, j, new], &inside));
        }
    }
    features(&points, &nearest)
}

/// Adds vertices of A ⊖ B to a simplex of fewer than four until it spans a volume; false if none can.
fn fill(a: &Placed, b: &Placed, points: &mut Vec<Vertex>, tol: f64) -> bool {
    let axes = [Vector3::x(), Vector3::y(), Vector3::z()];
    while points.len() < 4 {
        let directions: Vec<Vector3<f64>> = match points.len() {
            1 => axes.to_vec(),
            2 => axes.iter().map(|e| e.cross(&(points[1].w - points[0].w))).collect(),
            _ => vec![(points[1].w - points[0].w).cross(&(points[2].w - points[0].w))],
        };
        let grows = directions.iter().filter(|d| d.norm() > 0.0).flat_map(|d| [*d, -d]).map(|d| support(a, b, &d)).find(|p| off(points, &p.w) > tol);
        match grows {
            Some(p) => points.push(p),
            None => return false,
        }
    }
    true
}

/// Distance of `w` from the affine hull of the simplex's points, m.
fn off(points: &[Vertex], w: &Vector3<f64>) -> f64 {
    let d = w - points[0].w;
    match points.len() {
        1 => d.norm(),
        2 => {
            let e = (points[1].w - points[0].w).normalize();
            (d - e * e.dot(&d)).norm()
        }
        _ => d.dot(&(points[1].w - points[0].w).cross(&(points[2].w - points[0].w)).normalize()).abs(),
    }
}

/// The face through `corners`, turned so its normal points away from `inside`.
fn face(points: &[Vertex], corners: [usize; 3], inside: &Vector3<f64>) -> Face {
    let [i, j, k] = corners;
    let n = (points[j].w - points[i].w).cross(&(points[k].w - points[i].w)).normalize();
    if n.dot(&(points[i].w - inside)) < 0.0 {
        return face(points, [i, k, j], inside);
    }
    Face { corners, normal: n, distance: n.dot(&points[i].w) }
}

/// The contact features from the face of A ⊖ B nearest the origin: the origin's foot on it in
/// barycentric coordinates, carried back to the corners on A and on B.
fn features(points: &[Vertex], f: &Face) -> Contact {
    let [p0, p1, p2] = f.corners.map(|k| points[k]);
    let foot = f.normal * f.distance;
    let (e1, e2, d) = (p1.w - p0.w, p2.w - p0.w, foot - p0.w);
    let (d11, d12, d22, d1, d2) = (e1.dot(&e1), e1.dot(&e2), e2.dot(&e2), d.dot(&e1), d.dot(&e2));
    let det = d11 * d22 - d12 * d12;
    let (u, v) = ((d22 * d1 - d12 * d2) / det, (d11 * d2 - d12 * d1) / det);
    let weights = [1.0 - u - v, u, v];
    let on_a = p0.a * weights[0] + p1.a * weights[1] + p2.a * weights[2];
    let on_b = p0.b * weights[0] + p1.b * weights[1] + p2.b * weights[2];
    Contact { depth: f.distance.max(0.0), normal: f.normal, on_a, on_b }
}
