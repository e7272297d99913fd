//! One pair's interaction: the contact features, the law's force, and the force and torque on
//! each body.

use nalgebra::Vector3;

use super::body::Body;
use super::detect::contact;
use super::law::{Act, Law};
use super::patch::contact_centre;
use super::shape::Polyhedron;

/// What a pair in contact does to its bodies: force (N) and torque about the centroid (N·m).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Push {
    /// Force on A, N.
    pub force_a: Vector3<f64>,
    /// Torque on A about its centroid, N·m.
    pub torque_a: Vector3<f64>,
    /// Force on B, N (−force_a).
    pub force_b: Vector3<f64>,
    /// Torque on B about its centroid, N·m.
    pub torque_b: Vector3<f64>,
}

/// The push between bodies `a` (of shape `sa`) and `b` (of `sb`), or None when apart, which also
/// clears the pair's tangential spring `shear` (m).
pub fn interact(law: &Law, a: (&Body, &Polyhedron), b: (&Body, &Polyhedron), shear: &mut Vector3<f64>, dt: f64) -> Option<Push> {
    interact_act(law, a, b, shear, dt).map(|(push, _)| push)
}

/// [`interact`] with the law's energies of the step ([`Act`]).
pub fn interact_act(law: &Law, (a, sa): (&Body, &Polyhedron), (b, sb): (&Body, &Polyhedron), shear: &mut Vector3<f64>, dt: f64) -> Option<(Push, Act)> {
    let (pa, pb) = (a.placed(sa), b.placed(sb));
    let Some(c) = contact(&pa, &pb) else {
        *shear = Vector3::zeros();
        return None;
    };
    let point = contact_centre(&pa, &pb, &c);
    let approach = b.point_velocity(&point) - a.point_velocity(&point);
    let act = law.act(&c, &approach, reduced_mass(a.mass, b.mass), shear, dt);
    let f = act.force;
    Some((Push { force_a: -f, torque_a: (point - a.position).cross(&-f), force_b: f, torque_b: (point - b.position).cross(&f) }, act))
}

/// The pair's reduced mass, kg; a held body (infinite mass) leaves the other's.
fn reduced_mass(a: f64, b: f64) -> f64 {
    match (a.is_finite(), b.is_finite()) {
        (true, true) => a * b / (a + b),
        (false, true) => b,
        (true, false) => a,
        (false, false) => f64::INFINITY,
    }
}
