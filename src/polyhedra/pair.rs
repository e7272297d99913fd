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
    let act = law.act(&c, &approach, effective_mass(a, b, &point, &c.normal), shear, dt);
    let f = act.force;
    Some((Push { force_a: -f, torque_a: (point - a.position).cross(&-f), force_b: f, torque_b: (point - b.position).cross(&f) }, act))
}

/// The pair's effective mass along the normal `n` at the contact point `x` (m), kg: the m in
/// "an impulse J along n changes the normal approach at x by J/m", 1/m = 1/m_a + 1/m_b +
/// Σ (r × n)·J⁻¹(r × n), r from each centroid to x. A dashpot 2ζ√(m k) on it makes the
/// contact rebound at e however far off the line of centres the contact lies; the pair's
/// reduced mass (the translation alone) over-damps an off-centre contact, whose bodies turn
/// as well as move (tests/polyhedra_impact.rs: a 30 kg cube struck by the 70 kg projectile
/// 5 cm off its face's centre at e = 0.6 rebounded at 0.565 on the reduced mass, 0.595 on
/// this one, the rest the step's). A held body (infinite mass and inertia) adds nothing.
pub fn effective_mass(a: &Body, b: &Body, x: &Vector3<f64>, n: &Vector3<f64>) -> f64 {
    let compliance = |body: &Body| {
        if !body.mass.is_finite() {
            return 0.0;
        }
        let u = body.spin.orientation.inverse_transform_vector(&(x - body.position).cross(n));
        1.0 / body.mass + u.component_mul(&u).component_div(&body.inertia).sum()
    };
    1.0 / (compliance(a) + compliance(b))
}
