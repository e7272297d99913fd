//! GJK (Gilbert, Johnson & Keerthi 1988) as the contact test: walks the Minkowski difference
//! A ⊖ B towards the origin. Separation is only ever reported with a certificate, a direction
//! along which all of A ⊖ B lies strictly on one side of the origin.

use super::simplex::nearest;
use super::support::{Placed, Vertex, support};

/// GJK's verdict.
#[derive(Clone, Debug)]
pub enum Gjk {
    /// Apart (or just touching): no overlap.
    Separated,
    /// Overlapping: a simplex of A ⊖ B holding the origin (inside or on its boundary), EPA's start.
    Overlap(Vec<Vertex>),
}

/// Iterations before GJK gives up; each adds a new vertex of A ⊖ B, so a polytope ends sooner.
const MAX_ITERATIONS: usize = 128;

/// Whether `a` and `b` overlap.
pub fn gjk(a: &Placed, b: &Placed) -> Gjk {
    let scale = a.shape.radius() + b.shape.radius();
    let mut start = a.position - b.position;
    if start.norm_squared() == 0.0 {
        start.x = 1.0;
    }
    let mut simplex = vec![support(a, b, &start)];
    let mut v = simplex[0].w;
    for _ in 0..MAX_ITERATIONS {
        // The origin on the simplex (to rounding): they touch or overlap.
        if v.norm() <= 1e-14 * scale {
            return Gjk::Overlap(simplex);
        }
        let p = support(a, b, &-v);
        // Nothing of A ⊖ B is past the origin along −v: a separating plane.
        if v.dot(&p.w) >= 0.0 {
            return Gjk::Separated;
        }
        simplex.push(p);
        v = nearest(&mut simplex);
        if simplex.len() == 4 {
            return Gjk::Overlap(simplex);
        }
    }
    // Not reached for polytopes (each step is strict progress); the last simplex is the best.
    Gjk::Overlap(simplex)
}
