//! Where the force of a flat contact acts. The seed's c_M (eq 3) is unique for vertex–face and
//! edge–edge contacts, but when a face of one lies on a face (or an edge on a face) of the other,
//! every point of the shared patch is a pair (c₁, c₂) with c₁ − c₂ = δ_M n_M, and EPA picks a
//! corner of it by the order of its triangles: a block resting on a face then has its force jump
//! between corners. Here such a contact acts at the centre of its patch, which is still one of
//! the seed's points (so the elastic energy is kept), and the one symmetry asks for.

use nalgebra::Vector3;

use super::epa::Contact;
use super::hull::ring;
use super::support::Placed;

/// The contact point (m, world) of contact `c` between `a` and `b`: the centre of the patch
/// where A's extreme feature along n_M meets B's, or c_M when either feature is a corner.
pub fn contact_centre(a: &Placed, b: &Placed, c: &Contact) -> Vector3<f64> {
    let n = c.normal;
    let tol = 1e-9 * (a.shape.radius() + b.shape.radius());
    // Each body's corners in world, flattened onto the plane through the origin normal to n.
    let flat = |p: &Placed| -> (Vec<Vector3<f64>>, Vec<f64>) {
        p.shape.vertices.iter().map(|v| p.world(v)).map(|x| (x - n * n.dot(&x), n.dot(&x))).unzip()
    };
    let ((fa, ha), (fb, hb)) = (flat(a), flat(b));
    let (top, bottom) = (ha.iter().copied().fold(f64::NEG_INFINITY, f64::max), hb.iter().copied().fold(f64::INFINITY, f64::min));
    let on_a: Vec<usize> = (0..fa.len()).filter(|&k| ha[k] >= top - tol).collect();
    let on_b: Vec<usize> = (0..fb.len()).filter(|&k| hb[k] <= bottom + tol).collect();
    if on_a.len() < 2 || on_b.len() < 2 {
        return c.point();
    }
    let ra: Vec<Vector3<f64>> = ring(&fa, &on_a, n, tol).into_iter().map(|k| fa[k]).collect();
    let rb: Vec<Vector3<f64>> = ring(&fb, &on_b, n, tol).into_iter().map(|k| fb[k]).collect();
    // Clip the smaller feature by the larger (a polygon), or give up on two crossing edges.
    let region = match (ra.len() >= 3, rb.len() >= 3) {
        (_, true) => clip(&ra, &rb, &n, tol),
        (true, false) => clip(&rb, &ra, &n, tol),
        (false, false) => return c.point(),
    };
    match centre(&region, &n, tol) {
        Some(x) => x + n * (0.5 * (top + bottom)),
        None => c.point(),
    }
}

/// `subject` (a loop, or a segment as two points) cut to the inside of the convex loop `by`,
/// counter-clockwise about `n` (Sutherland–Hodgman).
fn clip(subject: &[Vector3<f64>], by: &[Vector3<f64>], n: &Vector3<f64>, tol: f64) -> Vec<Vector3<f64>> {
    let mut out = subject.to_vec();
    for k in 0..by.len() {
        let (p, q) = (by[k], by[(k + 1) % by.len()]);
        let edge = (q - p).normalize();
        let side = |x: &Vector3<f64>| n.dot(&edge.cross(&(x - p)));
        let input = std::mem::take(&mut out);
        for (i, cur) in input.iter().enumerate() {
            let prev = input[(i + input.len() - 1) % input.len()];
            let (sp, sc) = (side(&prev), side(cur));
            if sc >= -tol {
                if sp < -tol {
                    out.push(prev + (cur - prev) * (sp / (sp - sc)));
                }
                out.push(*cur);
            } else if sp >= -tol {
                out.push(prev + (cur - prev) * (sp / (sp - sc)));
            }
        }
    }
    out
}

/// The centre of a clipped region: its area centroid, or the middle of its longest chord when
/// it has no area (a segment), or None when nothing is left.
fn centre(region: &[Vector3<f64>], n: &Vector3<f64>, tol: f64) -> Option<Vector3<f64>> {
    let first = *region.first()?;
    let (mut area, mut moment) = (0.0, Vector3::zeros());
    for k in 1..region.len().saturating_sub(1) {
        let (p, q) = (region[k], region[k + 1]);
        let twice = n.dot(&(p - first).cross(&(q - first)));
        area += twice;
        moment += (first + p + q) * (twice / 3.0);
    }
    if area > tol * tol {
        return Some(moment / area);
    }
    let mut ends = (first, first);
    for p in region {
        for q in region {
            if (p - q).norm() > (ends.0 - ends.1).norm() {
                ends = (*p, *q);
            }
        }
    }
    Some((ends.0 + ends.1) * 0.5)
}
