//! A small steel-into-concrete impact at 250 m/s: bonds break, fragments touch and slide, two
//! materials meet. The kernel tests that need "everything happening at once" use it.

use demsweep::kernel::{Model, ModelBuilder, StepChoice};
use demsweep::lattice::{self, Rect};
use demsweep::material::{Arrangement, FailureCriterion, Plane, PoissonPolicy};

/// The model, with stage 1 forced onto the parallel path whatever its size.
pub fn model() -> Model {
    with_step(None)
}

/// The model at `dt_s` instead of the step the kernel chooses.
pub fn with_step(dt_s: Option<f64>) -> Model {
    with(dt_s, 0.0, 0.0)
}

/// The model with Rayleigh damping C = αM + βK (α 1/s, β s).
pub fn damped(alpha_per_s: f64, beta_s: f64) -> Model {
    with(None, alpha_per_s, beta_s)
}

/// The same at a given step.
pub fn damped_at(alpha_per_s: f64, beta_s: f64, dt_s: f64) -> Model {
    with(Some(dt_s), alpha_per_s, beta_s)
}

/// The model with both ends of the target held (every dof, zero velocity), as the peers' beam
/// is: every row of the lattice then has a kinematic element at each end.
pub fn held_ends() -> Model {
    build(None, 0.0, 0.0, true)
}

/// The model with elements of half the radius (four times as many, ~12 000 contacts).
pub fn fine() -> Model {
    build_at(0.002, None, 0.0, 0.0, false)
}

fn with(dt_s: Option<f64>, alpha_per_s: f64, beta_s: f64) -> Model {
    build(dt_s, alpha_per_s, beta_s, false)
}

fn build(dt_s: Option<f64>, alpha_per_s: f64, beta_s: f64, held: bool) -> Model {
    build_at(0.004, dt_s, alpha_per_s, beta_s, held)
}

fn build_at(r: f64, dt_s: Option<f64>, alpha_per_s: f64, beta_s: f64, held: bool) -> Model {
    let mut b = ModelBuilder::new(Plane::Strain, 0.05);
    let mut concrete = super::plate_concrete(FailureCriterion::StrengthEnergy);
    concrete.poisson_ratio = 0.2;
    let c = b.add_material(concrete);
    let mut steel = super::elastic(200e9, 0.3, 7850.0);
    steel.poisson_policy = PoissonPolicy::ClampToOneThird;
    let s = b.add_material(steel);
    let target = lattice::close_packed(&Rect { x_min_m: 0.0, x_max_m: 0.4, y_min_m: 0.0, y_max_m: 0.12 }, r).unwrap();
    let projectile = lattice::close_packed(&Rect { x_min_m: 0.18, x_max_m: 0.22, y_min_m: 0.1205, y_max_m: 0.2 }, r).unwrap();
    b.add_body("target", &target, Arrangement::ClosePacked, c, &[], [0.0; 3]);
    b.add_body("projectile", &projectile, Arrangement::ClosePacked, s, &[], [0.0, -250.0, 0.0]);
    if held {
        let ends: Vec<usize> = (0..target.centres.len()).filter(|&e| target.centres[e][0] < 0.01 || target.centres[e][0] > 0.39).collect();
        assert!(ends.len() > 20, "{} held elements", ends.len());
        b.add_motion(demsweep::kernel::boundary::MotionGroup::all("ends", [0.0; 3], demsweep::kernel::boundary::Profile::Constant), &ends);
    }
    if let Some(dt_s) = dt_s {
        b.step = StepChoice::Fixed { dt_s };
    }
    b.alpha_per_s = alpha_per_s;
    b.beta_s = beta_s;
    let mut m = b.build().unwrap();
    m.parallel_min_contacts = 0;
    m
}

/// Every bit a step can change: element state, contacts with their history, the ledger and
/// the counters.
pub fn state_bits(m: &Model) -> Vec<u64> {
    let mut bits = Vec::new();
    for e in 0..m.el.len() {
        bits.extend(m.state.pos[e].iter().chain(&m.state.vel[e]).chain(&m.state.force[e]).map(|v| v.to_bits()));
    }
    for c in &m.state.contacts.list {
        bits.extend([c.i as u64, c.j as u64, c.class as u64, c.bond as u64, c.rest_m.to_bits(), c.ut_m.to_bits(), c.dp_m.to_bits()]);
    }
    let l = m.state.ledger;
    bits.extend(
        [l.external_j, l.mass_damping_j, l.initial_j, m.time_s()].into_iter().chain(l.contacts.terms().into_iter().map(|t| t.1)).map(f64::to_bits),
    );
    bits.extend([l.bonds_broken(), m.steps(), m.state.rebuilds]);
    bits
}
