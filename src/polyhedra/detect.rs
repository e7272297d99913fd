//! The narrow phase for one pair: GJK's test, then EPA's features if they overlap.

use super::epa::{Contact, epa};
use super::gjk::{Gjk, gjk};
use super::support::Placed;

/// The Minkowski contact features of `a` and `b`, or None when they are apart or just touch.
/// When the origin lies on the boundary of A ⊖ B (a touch to rounding), EPA can be left with a
/// face of no area and no normal: that is a touch too, with no force to give, so it is None
/// rather than a NaN that would spread through the model (seen in a settling pile).
pub fn contact(a: &Placed, b: &Placed) -> Option<Contact> {
    match gjk(a, b) {
        Gjk::Separated => None,
        Gjk::Overlap(simplex) => Some(epa(a, b, simplex)).filter(|c| c.normal.iter().chain(c.on_a.iter()).chain(c.on_b.iter()).all(|x| x.is_finite()) && c.depth.is_finite()),
    }
}
