//! One pair's interaction: the contact features, the law's force, and the force and torque on
//! each body.

use nalgebra::Vector3;

use super::body::Body;
use super::detect::contact;
use super::law::Law;
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
pub fn interact(law: &Law, (a, sa): (&Body, &Polyhedron), (b, sb): (&Body, &Polyhedron), shear: &mut Vector3<f64>, dt: f64) -> Option<Push> {
    let (pa, pb) = (a.placed(sa), b.placed(sb));
    let Some(c) = contact(&pa, &pb) else {
        *shear = Vector3::zeros();
        return None;
    };
    let point = contact_centre(&pa, &pb, &c);
    let approach = b.point_velocity(&point) - a.point_velocity(&point);
    let mass = a.mass * b.mass / (a.mass + b.mass);
    let f = law.force(&c, &approach, mass, shear, dt);
    Some(Push { force_a: -f, torque_a: (point - a.position).cross(&-f), force_b: f, torque_b: (point - b.position).cross(&f) })
}
