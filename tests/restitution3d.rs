//! The 3D law's restitution dashpot (`kernel3d::law`, a frictional contact's normal damping set
//! from a coefficient of restitution e): two unbonded spheres meeting head-on part at e times
//! their approach speed, for equal and unequal masses, and the ledger books the kinetic energy
//! lost as `collision_j`.

use demsweep::kernel3d::law::Class;
use demsweep::kernel3d::Builder;
use demsweep::simulation::Simulation;

const R: f64 = 0.005;
const RHO: f64 = 2400.0;

/// Spheres of radii `r` approaching head-on along x at 1 m/s each, apart by a tenth of R,
/// through contacts of restitution `e`. Returns (approach speed, parting speed), m/s, and the
/// energy the ledger booked as `collision_j`, the kinetic energy lost and the kinetic energy
/// before, J.
fn collide(e: f64, r: [f64; 2]) -> ((f64, f64), (f64, f64, f64)) {
    let mut class = Class::elastic(30e9, 0.5, 0.0);
    class.contact_damping_ratio = demsweep::kernel3d::law::restitution_damping_ratio(e);
    let mut b = Builder::new(1);
    b.class(0, 0, class);
    let gap = 0.1 * R;
    let left = b.body("left", &[[-r[0] - gap / 2.0, 0.0, 0.0]], &[r[0]], 0, RHO);
    let right = b.body("right", &[[r[1] + gap / 2.0, 0.0, 0.0]], &[r[1]], 0, RHO);
    // The step a hundredth of the contact's own period.
    b.dt_s = Some(1e-8);
    let mut m = b.build(&[(left, [1.0, 0.0, 0.0]), (right, [-1.0, 0.0, 0.0])]).unwrap();
    let ke0 = m.kinetic_energy_j();
    let mut touched = false;
    loop {
        m.run_steps(1).unwrap();
        let apart = m.state.pos_m[1][0] - m.state.pos_m[0][0] > r[0] + r[1];
        touched |= !apart;
        if touched && apart {
            break;
        }
    }
    let parting = m.state.vel_mps[1][0] - m.state.vel_mps[0][0];
    let t = m.tally();
    let booked = t.contacts_j.iter().find(|(k, _)| k == "collision_j").unwrap().1;
    ((2.0, parting), (booked, ke0 - t.kinetic_energy_j, ke0))
}

#[test]
fn two_spheres_meeting_head_on_part_at_e_times_their_approach_speed() {
    for (e, r) in [(0.5, [R, R]), (0.2, [R, R]), (0.5, [R, 1.6 * R]), (1.0, [R, R])] {
        let ((approach, parting), (booked, lost, ke0)) = collide(e, r);
        let got = parting / approach;
        eprintln!("e {e}, radii {r:?}: parting/approach {got:.5}; collision_j {booked:.4e} J against {lost:.4e} J of kinetic energy lost");
        // The dashpot reads the half-step velocity: an error of order ω Δt, under 1 % here.
        assert!((got - e).abs() < 0.01, "e {e}: parted at {got}");
        // What e² leaves: the kinetic energy lost is (1 − e²) of the relative motion's.
        assert!((booked - lost).abs() <= 0.01 * ke0, "booked {booked} J, lost {lost} J of {ke0} J");
    }
}
