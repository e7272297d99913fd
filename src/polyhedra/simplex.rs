//! GJK's sub-algorithm: the point of a simplex (1–4 points) nearest the origin, and the smallest
//! face of it that holds that point (Ericson, Real-Time Collision Detection §5.1.5–5.1.6).

use nalgebra::Vector3;

use super::support::Vertex;

/// Shrinks `simplex` to the vertices of its face nearest the origin and returns the nearest
/// point, m (zero when a tetrahedron holds the origin).
pub fn nearest(simplex: &mut Vec<Vertex>) -> Vector3<f64> {
    let (point, keep) = match simplex.len() {
        1 => (simplex[0].w, vec![0]),
        2 => segment(simplex, [0, 1]),
        3 => triangle(simplex, [0, 1, 2]),
        _ => tetrahedron(simplex),
    };
    *simplex = keep.iter().map(|&k| simplex[k]).collect();
    point
}

/// Nearest point of the simplex's segment [i, j] and the vertices it needs.
fn segment(simplex: &[Vertex], [i, j]: [usize; 2]) -> (Vector3<f64>, Vec<usize>) {
    let (p, e) = (simplex[i].w, simplex[j].w - simplex[i].w);
    let t = -p.dot(&e) / e.norm_squared();
    if t <= 0.0 || !t.is_finite() {
        (p, vec![i])
    } else if t >= 1.0 {
        (simplex[j].w, vec![j])
    } else {
        (p + e * t, vec![i, j])
    }
}

/// Nearest point of the simplex's triangle [i, j, k], by its Voronoi regions (Ericson's routine).
fn triangle(simplex: &[Vertex], [i, j, k]: [usize; 3]) -> (Vector3<f64>, Vec<usize>) {
    let (a, b, c) = (simplex[i].w, simplex[j].w, simplex[k].w);
    let (ab, ac) = (b - a, c - a);
    // Each corner's projections on the two edges out of a (with the origin as the point).
    let [d1, d2, d3, d4, d5, d6] = [-ab.dot(&a), -ac.dot(&a), -ab.dot(&b), -ac.dot(&b), -ab.dot(&c), -ac.dot(&c)];
    let (va, vb, vc) = (d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2);
    // The corners' regions (each test stands alone), then the edges', then the inside.
    if d1 <= 0.0 && d2 <= 0.0 {
        (a, vec![i])
    } else if d3 >= 0.0 && d4 <= d3 {
        (b, vec![j])
    } else if d6 >= 0.0 && d5 <= d6 {
        (c, vec![k])
    } else if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        (a + ab * (d1 / (d1 - d3)), vec![i, j])
    } else if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        (a + ac * (d2 / (d2 - d6)), vec![i, k])
    } else if va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0 {
        (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))), vec![j, k])
    } else if va + vb + vc > 0.0 {
        let scale = 1.0 / (va + vb + vc);
        (a + ab * (vb * scale) + ac * (vc * scale), vec![i, j, k])
    } else {
        // A triangle flattened to a line by rounding: its nearest edge.
        [segment(simplex, [i, j]), segment(simplex, [i, k]), segment(simplex, [j, k])].into_iter().min_by(|x, y| x.0.norm_squared().total_cmp(&y.0.norm_squared())).unwrap()
    }
}

/// Nearest point of the tetrahedron: the origin itself if inside, else the nearest of the faces
/// the origin lies outside of.
fn tetrahedron(simplex: &[Vertex]) -> (Vector3<f64>, Vec<usize>) {
    let mut best: Option<(Vector3<f64>, Vec<usize>)> = None;
    for (face, opposite) in [([0, 1, 2], 3), ([0, 1, 3], 2), ([0, 2, 3], 1), ([1, 2, 3], 0)] {
        let [i, j, k] = face;
        let n = (simplex[j].w - simplex[i].w).cross(&(simplex[k].w - simplex[i].w));
        // The origin beyond this face's plane, seen from the opposite corner.
        let (origin_side, corner_side) = (-n.dot(&simplex[i].w), n.dot(&(simplex[opposite].w - simplex[i].w)));
        if origin_side * corner_side < 0.0 {
            let found = triangle(simplex, face);
            if best.as_ref().is_none_or(|b| found.0.norm_squared() < b.0.norm_squared()) {
                best = Some(found);
            }
        }
    }
    best.unwrap_or((Vector3::zeros(), vec![0, 1, 2, 3]))
}
