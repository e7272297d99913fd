//! A convex polyhedron cut by a plane: the part on the inner side, with the cut closed by a new
//! face. The Voronoi cells are a box cut by the bisecting planes of their neighbours (eq 26).

use nalgebra::Vector3;

use super::hull::{Hull, ring};

/// `solid` cut to the half-space n·x ≤ `offset` (`normal` n unit, `offset` in m); `tol` (m):
/// how near the plane a corner counts as on it. None when nothing is left.
pub fn cut(solid: &Hull, normal: &Vector3<f64>, offset: f64, tol: f64) -> Option<Hull> {
    let side: Vec<f64> = solid.vertices.iter().map(|v| normal.dot(v) - offset).collect();
    if side.iter().all(|&s| s <= tol) {
        return Some(solid.clone());
    }
    if side.iter().all(|&s| s >= -tol) {
        return None;
    }
    let mut vertices = solid.vertices.clone();
    // Each cut edge's new corner, made once and shared by the two faces along it.
    let mut made: std::collections::BTreeMap<(usize, usize), usize> = std::collections::BTreeMap::new();
    let mut faces = Vec::new();
    for face in &solid.faces {
        let mut kept = Vec::new();
        for k in 0..face.len() {
            let (a, b) = (face[k], face[(k + 1) % face.len()]);
            if side[a] <= tol {
                kept.push(a);
            }
            if (side[a] < -tol && side[b] > tol) || (side[a] > tol && side[b] < -tol) {
                let at = *made.entry((a.min(b), a.max(b))).or_insert_with(|| {
                    let (p, q) = (solid.vertices[a], solid.vertices[b]);
                    vertices.push(p + (q - p) * (side[a] / (side[a] - side[b])));
                    vertices.len() - 1
                });
                kept.push(at);
            }
        }
        if kept.len() >= 3 {
            faces.push(kept);
        }
    }
    // The new face: every corner now on the plane, in its loop about the outward normal.
    let on: Vec<usize> = (0..vertices.len()).filter(|&k| k >= side.len() || side[k].abs() <= tol).collect();
    if on.len() >= 3 {
        faces.push(ring(&vertices, &on, *normal, tol));
    }
    Some(compact(vertices, faces))
}

/// Drops the corners no face uses and renumbers the rest in order.
fn compact(vertices: Vec<Vector3<f64>>, faces: Vec<Vec<usize>>) -> Hull {
    let mut index = vec![usize::MAX; vertices.len()];
    let mut used = Vec::new();
    for &k in faces.iter().flatten() {
        if index[k] == usize::MAX {
            index[k] = used.len();
            used.push(vertices[k]);
        }
    }
    Hull { vertices: used, faces: faces.into_iter().map(|f| f.into_iter().map(|k| index[k]).collect()).collect() }
}
