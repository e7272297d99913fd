//! The broad phase: each body's axis-aligned bounding box, and the pairs whose boxes overlap,
//! by sort and sweep along x. Remade every step (a box costs a pass over the body's corners),
//! so no skin and no rebuild rule; the pairs come out sorted, which the step's order needs.

use nalgebra::Vector3;

use super::super::support::Placed;

/// An axis-aligned box, m.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    /// Least corner, m.
    pub lo: Vector3<f64>,
    /// Greatest corner, m.
    pub hi: Vector3<f64>,
}

impl Aabb {
    /// The box of a placed polyhedron, from its corners turned into the world.
    pub fn of(p: &Placed) -> Self {
        let r = p.orientation.to_rotation_matrix();
        let (mut lo, mut hi) = (Vector3::repeat(f64::INFINITY), Vector3::repeat(f64::NEG_INFINITY));
        for v in &p.shape.vertices {
            let w = r * v;
            lo = lo.inf(&w);
            hi = hi.sup(&w);
        }
        Aabb { lo: lo + p.position, hi: hi + p.position }
    }

    /// Whether two boxes overlap (touching counts).
    pub fn meets(&self, other: &Aabb) -> bool {
        (0..3).all(|k| self.lo[k] <= other.hi[k] && other.lo[k] <= self.hi[k])
    }
}

/// The pairs (i < j) of boxes that overlap, sorted, leaving out pairs where `skip(i, j)`
/// (two held bodies).
pub fn pairs(boxes: &[Aabb], skip: impl Fn(usize, usize) -> bool) -> Vec<(u32, u32)> {
    let mut order: Vec<usize> = (0..boxes.len()).collect();
    order.sort_by(|&a, &b| boxes[a].lo.x.total_cmp(&boxes[b].lo.x).then(a.cmp(&b)));
    let mut out = Vec::new();
    for (k, &a) in order.iter().enumerate() {
        for &b in &order[k + 1..] {
            if boxes[b].lo.x > boxes[a].hi.x {
                break;
            }
            if boxes[a].meets(&boxes[b]) && !skip(a, b) {
                out.push((a.min(b) as u32, a.max(b) as u32));
            }
        }
    }
    out.sort_unstable();
    out
}
