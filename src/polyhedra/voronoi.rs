//! Voronoi cells in a box (seed eqs 26–27): each seed's cell is the box cut by the planes
//! bisecting it and each other seed, nearest first, until the next seed is farther than twice
//! the cell's reach (its bisector then misses the cell). Our own half-space cutting, no crate:
//! the cells come out as the polygon faces the mass integrals and the contact want.

use nalgebra::Vector3;

use super::clip::cut;
use super::hull::Hull;

/// The Voronoi cell of each of `seeds` (m) inside the box from `lo` to `hi` (m), in the seeds'
/// order; `tol` (m) as in [`cut`]. A seed outside the box, or on another seed, gets no cell.
pub fn cells(seeds: &[Vector3<f64>], lo: &Vector3<f64>, hi: &Vector3<f64>, tol: f64) -> Vec<Option<Hull>> {
    let corners: Vec<Vector3<f64>> = (0..8).map(|k| Vector3::new([lo.x, hi.x][k & 1], [lo.y, hi.y][(k >> 1) & 1], [lo.z, hi.z][(k >> 2) & 1])).collect();
    // Faces counter-clockwise seen from outside: −x, +x, −y, +y, −z, +z.
    let faces = vec![vec![0, 4, 6, 2], vec![1, 3, 7, 5], vec![0, 1, 5, 4], vec![2, 6, 7, 3], vec![0, 2, 3, 1], vec![4, 5, 7, 6]];
    let block = Hull { vertices: corners, faces };
    seeds
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let mut others: Vec<(f64, usize)> = seeds.iter().enumerate().filter(|&(j, _)| j != i).map(|(j, t)| ((t - s).norm(), j)).collect();
            others.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
            let mut cell = block.clone();
            for (distance, j) in others {
                let reach = cell.vertices.iter().map(|v| (v - s).norm()).fold(0.0, f64::max);
                if distance > 2.0 * reach {
                    break;
                }
                if distance <= tol {
                    return None;
                }
                let normal = (seeds[j] - s) / distance;
                cell = cut(&cell, &normal, normal.dot(&((s + seeds[j]) * 0.5)), tol)?;
            }
            // A seed outside the box: its cell, if any, does not hold it.
            (s.iter().zip(lo.iter().zip(hi.iter())).all(|(x, (l, h))| l <= x && x <= h)).then_some(cell)
        })
        .collect()
}

/// Corners (m) moved towards `seed` (m) by the factor `q` (seed eq 29's shrinking: each vector
/// from the seed to a corner times q), so the cell keeps its shape and convexity.
pub fn shrink(cell: &Hull, seed: &Vector3<f64>, q: f64) -> Hull {
    Hull { vertices: cell.vertices.iter().map(|v| seed + (v - seed) * q).collect(), faces: cell.faces.clone() }
}
