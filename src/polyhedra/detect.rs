//! The narrow phase for one pair: GJK's test, then EPA's features if they overlap.

use super::epa::{Contact, epa};
use super::gjk::{Gjk, gjk};
use super::support::Placed;

/// The Minkowski contact features of `a` and `b`, or None when they are apart or just touch.
pub fn contact(a: &Placed, b: &Placed) -> Option<Contact> {
    match gjk(a, b) {
        Gjk::Separated => None,
        Gjk::Overlap(simplex) => Some(epa(a, b, simplex)),
    }
}
