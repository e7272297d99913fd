//! The convex hull of a small point set as polygon faces, by brute force over the planes through
//! three of the points: O(n⁴), but a face whose points are coplanar comes out as one polygon (a
//! cube's face is one square), which the separating-axis reference and the mass integrals want.
//! Meant for rock cells of tens of vertices; a body with hundreds (the projectile) gives its faces.

use nalgebra::Vector3;

use crate::{Error, Result};

/// A hull: its vertices (m) and its faces, each a loop of indices into `vertices`,
/// counter-clockwise seen from outside.
#[derive(Clone, Debug)]
pub struct Hull {
    /// Corner points (m), only those on the hull, no two within the tolerance.
    pub vertices: Vec<Vector3<f64>>,
    /// Each face a loop of vertex indices, counter-clockwise seen from outside.
    pub faces: Vec<Vec<usize>>,
}

/// The convex hull of `points`; `tol` (m) is how far from a plane a point still lies on it.
/// Refused when the points span no volume.
pub fn hull(points: &[Vector3<f64>], tol: f64) -> Result<Hull> {
    let n = points.len();
    let mut loops: Vec<Vec<usize>> = Vec::new();
    let mut seen = std::collections::BTreeSet::new();
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                let normal = (points[j] - points[i]).cross(&(points[k] - points[i]));
                // Three points nearly on a line fix no plane.
                if normal.norm() <= tol * (points[j] - points[i]).norm().max((points[k] - points[i]).norm()) {
                    continue;
                }
                let mut normal = normal.normalize();
                let side: Vec<f64> = points.iter().map(|p| normal.dot(&(p - points[i]))).collect();
                let outward = if side.iter().all(|&s| s <= tol) {
                    1.0
                } else if side.iter().all(|&s| s >= -tol) {
                    -1.0
                } else {
                    continue;
                };
                normal *= outward;
                let on: Vec<usize> = (0..n).filter(|&m| side[m].abs() <= tol).collect();
                if on.len() == n {
                    return Err(Error::input("polyhedron.vertices", "the points lie in one plane"));
                }
                if seen.insert(on.clone()) {
                    loops.push(ring(points, &on, normal, tol));
                }
            }
        }
    }
    if loops.is_empty() {
        return Err(Error::input("polyhedron.vertices", "fewer than four points off one plane"));
    }
    // Keep only the points some face uses, renumbered in their first order.
    let mut index = vec![usize::MAX; n];
    let mut vertices = Vec::new();
    for &p in loops.iter().flatten() {
        if index[p] == usize::MAX {
            index[p] = vertices.len();
            vertices.push(points[p]);
        }
    }
    let faces = loops.into_iter().map(|f| f.into_iter().map(|p| index[p]).collect()).collect();
    Ok(Hull { vertices, faces })
}

/// The points `on` one face plane (outward `normal`) as the face's corner loop, counter-clockwise
/// seen from outside: their 2D hull in the plane, dropping points inside or on an edge.
pub(super) fn ring(points: &[Vector3<f64>], on: &[usize], normal: Vector3<f64>, tol: f64) -> Vec<usize> {
    let centre = on.iter().map(|&p| points[p]).sum::<Vector3<f64>>() / on.len() as f64;
    let u = (points[on[0]] - centre).normalize();
    let w = normal.cross(&u);
    let flat = |p: usize| {
        let d = points[p] - centre;
        (d.dot(&u), d.dot(&w))
    };
    // Andrew's monotone chain, counter-clockwise in (u, w), i.e. about the outward normal.
    let mut sorted: Vec<usize> = on.to_vec();
    sorted.sort_by(|&a, &b| {
        let (pa, pb) = (flat(a), flat(b));
        pa.0.total_cmp(&pb.0).then(pa.1.total_cmp(&pb.1))
    });
    let turn = |o: usize, a: usize, b: usize| {
        let (po, pa, pb) = (flat(o), flat(a), flat(b));
        (pa.0 - po.0) * (pb.1 - po.1) - (pa.1 - po.1) * (pb.0 - po.0)
    };
    let mut chain: Vec<usize> = Vec::new();
    for pass in [sorted.clone(), sorted.into_iter().rev().collect()] {
        let start = chain.len();
        for p in pass {
            // A left turn smaller than tol × length keeps a point on an edge out.
            while chain.len() >= start + 2 {
                let (o, a) = (chain[chain.len() - 2], chain[chain.len() - 1]);
                if turn(o, a, p) > tol * (points[p] - points[o]).norm() {
                    break;
                }
                chain.pop();
            }
            chain.push(p);
        }
        chain.pop();
    }
    chain
}
