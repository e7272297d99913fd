//! Cantilever under a sinusoidal tip load (seed 000 §4): the steady tip amplitude converges
//! monotonically and its Richardson extrapolate lies within 1 % of our Timoshenko modal
//! solution. Levels 0 and 1 run here against the golden table (results/validation/, written by
//! `demsweep validate cantilever`); the convergence test runs level 2 (6561 elements) too, so it
//! is `#[ignore]`d in CI and runs in scripts/validation.sh.

mod common;

use common::golden;
use demsweep::cases::cantilever;

#[test]
fn coarse_meshes_reproduce_their_golden_rows() {
    let g = golden::levels(&golden::table("cantilever"), "tip_amplitude_m");
    for level in [0u32, 1] {
        let (a, _) = cantilever::run(level).unwrap();
        golden::assert_matches(a, g[level as usize].1, &format!("cantilever level {level}"));
    }
}

#[test]
fn the_golden_table_holds_todays_timoshenko_reference() {
    let t = golden::table("cantilever");
    let r = cantilever::reference().unwrap();
    let rc = t.column("reference").unwrap();
    let stored: f64 = t.rows[0][rc].parse().unwrap();
    assert!((stored / r.timoshenko_m - 1.0).abs() < 1e-9, "reference {stored} vs {}", r.timoshenko_m);
}

#[test]
#[ignore = "runs level 2: scripts/validation.sh"]
fn amplitude_converges_monotonically_to_the_timoshenko_solution() {
    let r = cantilever::reference().unwrap();
    let v = golden::live_levels(|l| cantilever::run(l).unwrap().0);
    let err: Vec<f64> = v.iter().map(|(_, a)| a - r.timoshenko_m).collect();
    assert!(err[0].abs() > err[1].abs() && err[1].abs() > err[2].abs(), "errors {err:?}");
    assert!(err.iter().all(|e| e.signum() == err[0].signum()), "not monotone: {err:?}");
    let (ext, order) = golden::richardson_of(&v, cantilever::REFINEMENT);
    eprintln!("extrapolate {ext:.7e} m ({:+.3} % from Timoshenko), observed order {order:.3}", 100.0 * (ext / r.timoshenko_m - 1.0));
    assert!((ext / r.timoshenko_m - 1.0).abs() < 0.01);
}
