//! The polyhedral kernel under the `simulation` contract: the same bits on one and two threads,
//! a restored run continues as the uninterrupted one, a frictionless elastic pile keeps its
//! energy through the kernel's ledger, and a block on an incline slides at tan θ = μ.

mod polyhedra_support;

use demsweep::polyhedra::container::{as_given, walls};
use demsweep::polyhedra::kernel::{Model, ModelBuilder};
use demsweep::polyhedra::{Body, Law, Polyhedron};
use demsweep::simulation::{Simulation, Threading};
use nalgebra::Vector3;
use polyhedra_support::Draw;

/// Granite, kg/m³.
const DENSITY: f64 = 2600.0;

fn law(friction: f64, restitution: f64) -> Law {
    Law { stiffness: 1e6, exponent: 1.0, shear_stiffness: 5e5, friction, restitution }
}

/// Eight random rocks (bounding radius ≤ 5 cm) on a 2 × 2 × 2 grid, 12 cm apart, dropped into
/// a 0.3 m square box of held walls; each rock spun and thrown a little so they collide on
/// every axis.
fn pile(law: Law, seed: u64) -> Model {
    pile_at(law, seed, 0.25)
}

/// [`pile`] at `fraction` of the stability limit.
fn pile_at(law: Law, seed: u64, fraction: f64) -> Model {
    let mut draw = Draw(seed);
    let mut b = ModelBuilder::new(1, vec![law]).unwrap();
    b.gravity = Vector3::new(0.0, 0.0, -9.81);
    for k in 0..8 {
        let points: Vec<Vector3<f64>> = (0..12).map(|_| draw.in_ball(0.05)).collect();
        let shape = Polyhedron::from_points(&points, 1e-12).unwrap();
        let at = Vector3::new(0.09 + 0.12 * (k & 1) as f64, 0.09 + 0.12 * ((k >> 1) & 1) as f64, 0.06 + 0.12 * (k >> 2) as f64);
        let mut body = Body::new(&shape, DENSITY, at, draw.orientation());
        body.velocity = draw.in_ball(0.5);
        body.set_angular_velocity(&draw.in_ball(5.0));
        let s = b.shape(shape);
        b.body(s, 0, body);
    }
    b.group("target", 0);
    let start = b.len();
    walls(&mut b, 0, &Vector3::zeros(), &Vector3::new(0.3, 0.3, 0.3), 0.4, 0.0);
    b.group("walls", start);
    let dt = fraction * b.dt_bound_s();
    b.build(dt).unwrap()
}

#[test]
fn one_and_two_threads_and_serial_give_the_same_bits() {
    let mut runs = Vec::new();
    for (threads, threading) in [(1, Threading::Pool), (2, Threading::Pool), (2, Threading::Serial)] {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        let mut m = pile(law(0.5, 0.5), 3);
        m.set_threading(threading);
        pool.install(|| m.run_steps(20_000)).unwrap();
        runs.push((m.checkpoint(), m.contact_count()));
    }
    println!("contacts at the end {}; checkpoint {} bytes", runs[0].1, runs[0].0.len());
    assert!(runs[0].1 >= 4, "the pile touches: {} contacts", runs[0].1);
    assert!(runs[1] == runs[0] && runs[2] == runs[0], "threads changed the bits");
}

#[test]
fn a_restored_run_continues_bit_for_bit() {
    let mut whole = pile(law(0.5, 0.5), 4);
    whole.run_steps(3000).unwrap();
    let saved = whole.checkpoint();
    whole.run_steps(3000).unwrap();
    let mut resumed = pile(law(0.5, 0.5), 4);
    resumed.run_steps(10).unwrap(); // a state to be overwritten
    resumed.restore(&saved).unwrap();
    resumed.run_steps(3000).unwrap();
    assert_eq!(resumed.steps(), 6000);
    assert!(resumed.checkpoint() == whole.checkpoint(), "the resumed run differs");
    assert!(resumed.tally() == whole.tally());
    // A checkpoint of another scene is refused by what does not fit.
    let mut other = pile(law(0.5, 0.5), 4);
    let err = other.restore(&saved[..saved.len() / 2]).unwrap_err().to_string();
    assert!(err.contains("checkpoint"), "{err}");
}

/// Runs the pile for 0.5 s at `fraction` of the stability limit; the worst |residual| over the
/// energy put in, at 400 looks, the tally at the end and the looks that found contacts.
fn ledger(law: Law, fraction: f64) -> (f64, demsweep::simulation::Tally, usize) {
    let mut m = pile_at(law, 5, fraction);
    let steps = (0.5 / m.dt_s) as u64 / 400;
    let (mut worst, mut touching) = (0.0f64, 0);
    for _ in 0..400 {
        m.run_steps(steps).unwrap();
        let t = m.tally();
        worst = worst.max(t.energy_residual_j.abs() / t.energy_in_j);
        touching += usize::from(m.contact_count() > 0);
    }
    (worst, m.tally(), touching)
}

#[test]
fn a_frictionless_elastic_pile_keeps_its_energy_to_the_steps_error() {
    let (coarse, _, _) = ledger(law(0.0, 1.0), 0.125);
    let (fine, t, touching) = ledger(law(0.0, 1.0), 0.0625);
    println!(
        "e = 1, μ = 0, 0.5 s: in {:.4e} J, gravity's work {:.4e} J, kinetic {:.4e} J; worst |residual|/in {coarse:.2e} at 1/8 of the limit, \
         {fine:.2e} at 1/16; {touching} of 400 looks in contact",
        t.energy_in_j, t.external_work_j, t.kinetic_energy_j
    );
    assert!(touching > 20 && t.external_work_j > 0.1 * t.energy_in_j, "the rocks must fall and meet");
    assert!(t.dissipated_j == 0.0, "nothing to dissipate: {}", t.dissipated_j);
    assert!(fine < 1e-3, "energy drift {fine:e}");
    // The drift is the step's error: it falls as the step does.
    assert!(coarse > 2.0 * fine, "drift {coarse:e} then {fine:e}: not the step's");
}

#[test]
fn a_damped_pile_counts_its_losses_and_its_ledger_closes() {
    let (worst, t, touching) = ledger(law(0.5, 0.5), 0.0625);
    let (damping, sliding) = (t.contacts_j[0].1, t.contacts_j[1].1);
    println!(
        "e = 0.5, μ = 0.5, 0.5 s: in {:.4e} J, kinetic {:.3e} J, elastic {:.3e} J, dashpots {damping:.4e} J, sliding {sliding:.4e} J; \
         worst |residual|/in {worst:.2e}; {touching} of 400 looks in contact",
        t.energy_in_j, t.kinetic_energy_j, t.strain_energy_j
    );
    // In contact at most looks and at rest at the end. (Was: in contact at more than 300 of
    // the 400 looks, 315 on the pair's reduced mass; with the dashpot on the contact's
    // effective mass an off-centre contact is no longer over-damped and the pile bounces
    // longer, 272 looks, but ends stiller: kinetic 2.4e-4 of the energy in, 1.7e-3 before.)
    assert!(touching > 200, "the pile is in contact at {touching} of 400 looks");
    assert!(t.kinetic_energy_j < 1e-3 * t.energy_in_j, "the pile has not settled: kinetic {:e} J", t.kinetic_energy_j);
    assert!(t.dissipated_j > 0.5 * t.energy_in_j && damping > 0.0 && sliding > 0.0, "losses {}", t.dissipated_j);
    assert!(worst < 1e-2, "ledger residual {worst:e}");
}

/// A 0.1 m cube on a held slab under gravity tilted by θ (the slope seen from the slab): settled
/// flat for 0.05 s, tilted over 0.1 s, then held 0.2 s. Its speed down the slope at the start and
/// at the end of the hold, m/s.
fn on_incline(theta: f64, mu: f64) -> (f64, f64) {
    let mut b = ModelBuilder::new(1, vec![law(mu, 0.3)]).unwrap();
    let block = Polyhedron::cuboid(&Vector3::new(0.1, 0.1, 0.1));
    let body = Body::new(&block, DENSITY, Vector3::new(0.0, 0.0, 0.05), block.rest_orientation);
    let s = b.shape(block);
    b.body(s, 0, body);
    b.group("target", 0);
    let slab = Polyhedron::cuboid(&Vector3::new(20.0, 2.0, 0.2));
    let floor = as_given(&slab, 1.0);
    let mut floor = floor;
    floor.position = Vector3::new(0.0, 0.0, -0.1);
    let s = b.shape(slab);
    b.held(s, 0, floor, Vector3::zeros());
    let mut m = b.build(1e-5).unwrap();
    let mut held_speed = 0.0;
    for n in 1..=350u64 {
        let ramp = ((n as f64 * 1e-3 - 0.05) / 0.1).clamp(0.0, 1.0);
        let tilt = theta * 0.5 * (1.0 - (std::f64::consts::PI * ramp).cos());
        m.gravity = Vector3::new(tilt.sin(), 0.0, -tilt.cos()) * 9.81;
        m.run_steps(100).unwrap();
        if n == 150 {
            held_speed = m.state.bodies[0].velocity.x;
        }
    }
    (held_speed, m.state.bodies[0].velocity.x)
}

#[test]
fn a_block_on_an_incline_slides_through_the_kernel_at_tan_theta_mu() {
    let mu: f64 = 0.5;
    for offset in [-2.0f64, 2.0, 5.0] {
        let theta = mu.atan() + offset.to_radians();
        let (v0, v1) = on_incline(theta, mu);
        let a = (v1 - v0) / 0.2;
        let expected = (9.81 * (theta.sin() - mu * theta.cos())).max(0.0);
        println!("θ = atan μ {offset:+}°: acceleration in the hold {a:.4} m/s², Coulomb {expected:.4} m/s²");
        if offset < 0.0 {
            assert!(a.abs() < 0.01 && v1.abs() < 1e-3, "held below atan μ: a {a}, v {v1}");
        } else {
            assert!((a / expected - 1.0).abs() < 0.03, "sliding at {a}, Coulomb {expected}");
        }
    }
}




