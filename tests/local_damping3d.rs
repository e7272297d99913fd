//! Local damping of the 3D kernel (`kernel3d::integrate::local`) against its analytic answers: a
//! sphere on one bond to a held sphere loses the fraction 4λ of its energy a cycle, its amplitude
//! falling by (1 − λ)/(1 + λ) a cycle at any frequency; a sphere in free flight loses nothing;
//! the ledger books what the damping took.

use demsweep::kernel3d::law::Class;
use demsweep::kernel3d::{Builder, Model};
use demsweep::simulation::Simulation;

const R: f64 = 0.005;

/// Sphere 1 on a bond to the held sphere 0 along x, set moving at 1 m/s along the bond (one
/// mode: across it, the shear spring couples its translation to its spin), its motion damped
/// at `ratio` of critical; the step a fiftieth of the bound, so the discrete oscillator is close
/// to the continuous one.
fn oscillator(ratio: f64, kappa_pa: f64) -> Model {
    let mut b = Builder::new(1);
    b.class(0, 0, Class::elastic(kappa_pa, 0.5, 0.5));
    let body = b.body("pair", &[[0.0; 3], [2.0 * R, 0.0, 0.0]], &[R, R], 0, 2400.0);
    b.bond(0, 1);
    b.hold(0, [0.0; 3]);
    b.damp_locally(body.start + 1..body.end, ratio);
    let probe = {
        let mut p = Builder::new(1);
        p.class(0, 0, Class::elastic(kappa_pa, 0.5, 0.5));
        p.body("pair", &[[0.0; 3], [2.0 * R, 0.0, 0.0]], &[R, R], 0, 2400.0);
        p.bond(0, 1);
        p.hold(0, [0.0; 3]);
        p.build(&[]).unwrap().dt_bound_s
    };
    b.dt_s = Some(probe / 50.0);
    b.build(&[(body.start + 1..body.end, [1.0, 0.0, 0.0])]).unwrap()
}

/// The displacement of sphere 1 along x at its successive maxima (one a cycle), m.
fn peaks(m: &mut Model, cycles: usize) -> Vec<f64> {
    let x0 = m.state.pos_m[1][0];
    let (mut out, mut last, mut rising) = (Vec::new(), 0.0, true);
    while out.len() < cycles {
        m.step().unwrap();
        let u = m.state.pos_m[1][0] - x0;
        if rising && u < last && last > 0.0 {
            out.push(last);
        }
        rising = u >= last;
        last = u;
    }
    out
}

#[test]
fn a_bonded_sphere_loses_amplitude_by_one_less_lambda_over_one_plus_lambda_a_cycle() {
    for (ratio, kappa) in [(0.02, 30e9), (0.05, 30e9), (0.05, 3e9)] {
        let lambda = std::f64::consts::PI * ratio;
        let want = (1.0 - lambda) / (1.0 + lambda);
        let mut m = oscillator(ratio, kappa);
        let p = peaks(&mut m, 6);
        let per_cycle = (p[5] / p[0]).powf(1.0 / 5.0);
        eprintln!("ζ {ratio}, κ {kappa:.0e} Pa: amplitude ratio a cycle {per_cycle:.5}, (1 − λ)/(1 + λ) = {want:.5}, viscous e^(−2πζ) = {:.5}", (-2.0 * std::f64::consts::PI * ratio).exp());
        assert!((per_cycle / want - 1.0).abs() < 2e-3, "ζ {ratio}: {per_cycle} a cycle against {want}");
        // What the motion lost is in the ledger's local damping: it closes.
        let t = m.tally();
        let lost = t.contacts_j.iter().find(|(k, _)| k == "local_damping_j").unwrap().1;
        eprintln!("  booked {lost:.4e} J of {:.4e} J, residual {:.2e} J", t.energy_in_j, t.energy_residual_j);
        assert!(lost > 0.5 * t.energy_in_j, "booked {lost} J of {} J after six cycles", t.energy_in_j);
        assert!(t.energy_residual_j.abs() < 1e-3 * t.energy_in_j, "ledger off by {} of {} J", t.energy_residual_j, t.energy_in_j);
    }
}

#[test]
fn an_undamped_bond_keeps_its_amplitude() {
    let mut m = oscillator(0.0, 30e9);
    let p = peaks(&mut m, 6);
    assert!((p[5] / p[0] - 1.0).abs() < 1e-3, "undamped amplitude moved: {p:?}");
}

#[test]
fn a_sphere_in_free_flight_is_not_dragged() {
    let mut b = Builder::new(1);
    b.class(0, 0, Class::elastic(30e9, 0.5, 0.5));
    let body = b.body("pair", &[[0.0; 3], [10.0 * R, 0.0, 0.0], [0.0, 20.0 * R, 0.0]], &[R, R, R], 0, 2400.0);
    b.bond(0, 1);
    b.damp_locally(body.clone(), 0.05);
    let mut m = b.build(&[(2..3, [3.0, -2.0, 1.0])]).unwrap();
    m.run_steps(1000).unwrap();
    assert_eq!(m.state.vel_mps[2], [3.0, -2.0, 1.0], "a free sphere's velocity changed");
    let t = m.tally();
    assert_eq!(t.contacts_j.iter().find(|(k, _)| k == "local_damping_j").unwrap().1, 0.0);
}
