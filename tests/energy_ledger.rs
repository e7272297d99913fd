//! The energy ledger closes: kinetic + strain energy = initial + external work − dissipated,
//! with the dissipation booked per mechanism, on a violent impact where bonds yield and break
//! and fragments slide under friction. Central differences keep velocities at half steps, so
//! the balance holds to O(Δt): the residual must be small and shrink with the step.

mod common;

use common::impact;

/// |residual| / initial energy after the impact has run its course (500 steps at the chosen
/// step: the projectile has stopped and the debris slides).
fn residual_after_impact(step_factor: f64) -> (f64, f64) {
    let dt = impact::model().dt_s() * step_factor;
    let mut m = impact::with_step(Some(dt));
    m.run_steps((500.0 / step_factor).round() as u64).unwrap();
    (m.energy_residual_j() / m.ledger.initial_j, m.ledger.friction_j / m.ledger.initial_j)
}

#[test]
fn friction_booked_on_the_new_force_alone_left_energy_out_of_the_ledger() {
    let (coarse, friction) = residual_after_impact(1.0);
    let (fine, _) = residual_after_impact(0.5);
    eprintln!(
        "residual {:+.3} % at the chosen step, {:+.3} % at half of it; friction {:.2} % of the impact energy",
        100.0 * coarse,
        100.0 * fine,
        100.0 * friction
    );
    // Friction must matter here for the test to mean anything (it takes about 6 %).
    assert!(friction > 0.03, "friction {friction}");
    // Booking the cap's new force alone gave −1.18 % and −1.00 %: biased, hardly converging.
    assert!(coarse.abs() < 0.005, "residual {coarse} of the initial energy");
    assert!(fine.abs() < 0.5 * coarse.abs(), "residual {coarse} → {fine} when the step is halved");
}
