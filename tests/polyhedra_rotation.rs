//! The seed's rotation update (eqs 18–25) on a torque-free asymmetric body: energy and angular
//! momentum over 10⁵ steps, and the intermediate-axis (Dzhanibekov) flips against the closed
//! form (Jacobi elliptic functions, Landau & Lifshitz §37), beside explicit Euler at the same step.

use demsweep::polyhedra::Spin;
use nalgebra::{Quaternion, UnitQuaternion, Vector3};

/// Principal moments, kg·m²: a 0.1 × 0.25 × 0.4 m box of density 2600 kg/m³ (granite), whose
/// moments tests/polyhedra_mass.rs checks.
fn inertia() -> Vector3<f64> {
    let (a, b, c, rho) = (0.1, 0.25, 0.4, 2600.0);
    let m = rho * a * b * c;
    Vector3::new(m * (a * a + b * b) / 12.0, m * (a * a + c * c) / 12.0, m * (b * b + c * c) / 12.0)
}

/// The start: spinning at 20 rad/s about the intermediate axis, nudged by 1 % about the others.
fn start(j: &Vector3<f64>) -> Spin {
    let omega = Vector3::new(0.2, 20.0, 0.2);
    Spin { orientation: UnitQuaternion::identity(), momentum: omega.component_mul(j) }
}

const DT: f64 = 1e-4;
const STEPS: usize = 100_000;

/// Complete elliptic integral of the first kind K(k), by the arithmetic-geometric mean.
fn elliptic_k(k2: f64) -> f64 {
    let (mut a, mut g) = (1.0, (1.0 - k2).sqrt());
    while (a - g).abs() > 1e-16 * a {
        (a, g) = (0.5 * (a + g), (a * g).sqrt());
    }
    std::f64::consts::PI / (2.0 * a)
}

/// The time between sign changes of ω₂ (ω₂ ∝ sn(λt, k), so 2K(k)/λ), s, for J₁ < J₂ < J₃.
fn flip_interval(j: &Vector3<f64>, s: &Spin) -> f64 {
    let (j1, j2, j3) = (j[0], j[1], j[2]);
    let (e2, m2) = (2.0 * s.energy(j), s.momentum.norm_squared());
    let (lambda, k2) = if m2 > e2 * j2 {
        (((j3 - j2) * (m2 - e2 * j1) / (j1 * j2 * j3)).sqrt(), (j2 - j1) * (e2 * j3 - m2) / ((j3 - j2) * (m2 - e2 * j1)))
    } else {
        (((j2 - j1) * (e2 * j3 - m2) / (j1 * j2 * j3)).sqrt(), (j3 - j2) * (m2 - e2 * j1) / ((j2 - j1) * (e2 * j3 - m2)))
    };
    2.0 * elliptic_k(k2) / lambda
}

/// What a run measured.
struct Run {
    /// Largest |E − E₀|/E₀ over the run.
    energy: f64,
    /// Largest |L − L₀|/|L₀| of the world angular momentum over the run.
    momentum: f64,
    /// Largest |‖q‖ − 1| over the run.
    unit: f64,
    /// Times ω₂ changed sign, s (linear interpolation within the step).
    flips: Vec<f64>,
}

fn run(j: &Vector3<f64>, dt: f64, steps: usize, step: impl Fn(&mut Spin, f64)) -> Run {
    let mut s = start(j);
    let (e0, l0) = (s.energy(j), s.world_momentum());
    let mut out = Run { energy: 0.0, momentum: 0.0, unit: 0.0, flips: Vec::new() };
    for n in 0..steps {
        let before = s.momentum[1];
        step(&mut s, dt);
        let after = s.momentum[1];
        if before * after < 0.0 {
            out.flips.push((n as f64 + before / (before - after)) * dt);
        }
        out.energy = out.energy.max((s.energy(j) - e0).abs() / e0);
        out.momentum = out.momentum.max((s.world_momentum() - l0).norm() / l0.norm());
        out.unit = out.unit.max((s.orientation.into_inner().norm() - 1.0).abs());
    }
    out
}

/// The mean time between flips, s.
fn mean_interval(flips: &[f64]) -> f64 {
    (flips[flips.len() - 1] - flips[0]) / (flips.len() - 1) as f64
}

/// The torque-free rigid body: dL̄/dt = L̄ × ω̄, dq/dt = ½ q (0, ω̄).
fn derivative(j: &Vector3<f64>, q: &Quaternion<f64>, l: &Vector3<f64>) -> (Quaternion<f64>, Vector3<f64>) {
    let w = l.component_div(j);
    (q * Quaternion::from_imag(w) * 0.5, l.cross(&w))
}

/// Classical fourth-order Runge–Kutta on (q, L̄), q renormalised after each step.
fn rk4(j: &Vector3<f64>, s: &mut Spin, dt: f64) {
    let (q, l) = (s.orientation.into_inner(), s.momentum);
    let (q1, l1) = derivative(j, &q, &l);
    let (q2, l2) = derivative(j, &(q + q1 * (0.5 * dt)), &(l + l1 * (0.5 * dt)));
    let (q3, l3) = derivative(j, &(q + q2 * (0.5 * dt)), &(l + l2 * (0.5 * dt)));
    let (q4, l4) = derivative(j, &(q + q3 * dt), &(l + l3 * dt));
    s.orientation = UnitQuaternion::from_quaternion(q + (q1 + q2 * 2.0 + q3 * 2.0 + q4) * (dt / 6.0));
    s.momentum = l + (l1 + l2 * 2.0 + l3 * 2.0 + l4) * (dt / 6.0);
}

/// A plain scheme: explicit Euler on L̄ and q, q renormalised after each step.
fn euler(j: &Vector3<f64>, s: &mut Spin, dt: f64) {
    let (dq, dl) = derivative(j, &s.orientation.into_inner(), &s.momentum);
    s.orientation = UnitQuaternion::from_quaternion(s.orientation.into_inner() + dq * dt);
    s.momentum += dl * dt;
}

#[test]
fn the_closed_form_flip_interval_matches_a_fine_runge_kutta() {
    // The reference itself checked: RK4 at a tenth of the step over the same span.
    let j = inertia();
    let exact = flip_interval(&j, &start(&j));
    let fine = run(&j, DT / 10.0, STEPS * 10, |s, dt| rk4(&j, s, dt));
    let measured = mean_interval(&fine.flips);
    println!("closed form {exact:.9} s, RK4 at {:e} s {measured:.9} s ({:+.1e}) over {} flips", DT / 10.0, measured / exact - 1.0, fine.flips.len());
    assert!(fine.flips.len() >= 4, "too few flips to time: {}", fine.flips.len());
    assert!((measured / exact - 1.0).abs() < 1e-7, "closed form against RK4: {:e}", measured / exact - 1.0);
}

#[test]
fn the_seed_scheme_keeps_energy_and_momentum_and_times_the_flips() {
    let j = inertia();
    let exact = flip_interval(&j, &start(&j));
    let seed = run(&j, DT, STEPS, |s, dt| s.step(&j, &Vector3::zeros(), dt));
    let plain = run(&j, DT, STEPS, |s, dt| euler(&j, s, dt));
    let (seed_period, plain_period) = (mean_interval(&seed.flips), mean_interval(&plain.flips));
    println!(
        "seed scheme over {STEPS} steps of {DT:e} s: energy drift {:.2e}, world momentum drift {:.2e}, |q|−1 {:.1e}, {} flips, \
         interval {seed_period:.6} s against {exact:.6} s ({:+.2e})",
        seed.energy, seed.momentum, seed.unit, seed.flips.len(), seed_period / exact - 1.0
    );
    println!(
        "explicit Euler: energy drift {:.2e}, world momentum drift {:.2e}, {} flips, interval {plain_period:.6} s ({:+.2e})",
        plain.energy, plain.momentum, plain.flips.len(), plain_period / exact - 1.0
    );
    assert!(seed.flips.len() >= 4, "too few flips to time: {}", seed.flips.len());
    // Every sub-step turns body and L̄ together: the world momentum is kept to rounding.
    assert!(seed.momentum < 1e-11, "world angular momentum drifted {:e}", seed.momentum);
    // Second order and symplectic: the energy error stays bounded, O((ω dt)²) = O(4e-6) at most.
    assert!(seed.energy < 1e-6, "energy drifted {:e}", seed.energy);
    assert!((seed_period / exact - 1.0).abs() < 1e-6, "flip interval off by {:e}", seed_period / exact - 1.0);
    // The plain scheme at the same step does far worse on both counts.
    assert!(plain.energy > 100.0 * seed.energy, "Euler's energy drift {:e} not far above {:e}", plain.energy, seed.energy);
    assert!(plain.momentum > 100.0 * seed.momentum.max(1e-14));
    assert!((plain_period / exact - 1.0).abs() > 10.0 * (seed_period / exact - 1.0).abs(), "Euler's flips timed as well as the seed's");
}

#[test]
fn a_spin_about_one_axis_turns_by_the_cayley_angle() {
    // L̄ along axis 3 only: each step is the one sub-rotation about axis 3 with φ = ω dt/2
    // (eq 21), a turn of 4 atan(φ/2), the Cayley angle, not ω dt exactly.
    let j = inertia();
    let omega = 30.0;
    let mut s = Spin { orientation: UnitQuaternion::identity(), momentum: Vector3::new(0.0, 0.0, omega * j[2]) };
    let (dt, steps) = (1e-3, 1000);
    for _ in 0..steps {
        s.step(&j, &Vector3::zeros(), dt);
    }
    let per_step = 4.0 * (0.25 * omega * dt).atan();
    let expected = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), per_step * steps as f64);
    let angle = s.orientation.angle_to(&expected);
    println!("spin about axis 3: {angle:.1e} rad off the Cayley angle; the exact angle is {:.3e} rad away", (omega * dt - per_step) * steps as f64);
    assert!(angle < 1e-11, "{angle:e}");
}

#[test]
fn a_torque_adds_its_impulse_to_the_world_momentum() {
    // Eq 18: whatever the body does, L_{n+1} = L_n + Δt p_n in the world.
    let j = inertia();
    let torque = Vector3::new(0.3, -1.2, 0.7);
    let mut s = start(&j);
    let l0 = s.world_momentum();
    let (dt, steps) = (1e-4, 20_000);
    for _ in 0..steps {
        s.step(&j, &torque, dt);
    }
    let expected = l0 + torque * (dt * steps as f64);
    let err = (s.world_momentum() - expected).norm() / expected.norm();
    println!("constant torque over {steps} steps: world momentum off by {err:.1e}");
    assert!(err < 1e-11, "{err:e}");
}
