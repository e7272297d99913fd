//! The moment transfer law on one contact (seed 004): two spheres pressed together, one spun
//! against the other, step by step through `kernel3d::law::act`. The rolling moment grows as
//! k_r θ_r (eq 15) up to η r |F_n| (eq 16), stays there while the spin goes on, and when the
//! spin reverses unloads at once along k_r from the cap (θ_r was reset to it, eqs 18–20: the
//! rolling past the cap is irreversible). The twisting moment does the same about the normal,
//! capped by Mohr–Coulomb over the contact disc (eq 42).

use demsweep::kernel3d::contact::{Bond, Contact};
use demsweep::kernel3d::law::{self, Class, Dissipation, Pair, rolling, twisting};

const R: f64 = 0.01;
const KN: f64 = 1e7;
const OVERLAP: f64 = 1e-5;
const DT: f64 = 1e-6;

/// Springs of KN (N/m) at spheres of radius R.
fn class(rolling: Option<rolling::Params>, twisting: Option<twisting::Params>) -> Class {
    Class {
        bond_kn_pa: KN / R,
        bond_ks_pa: KN / R,
        bond_tension_pa: f64::INFINITY,
        bond_shear_pa: f64::INFINITY,
        bond_fracture_j_per_m2: 0.0,
        kn_pa: KN / R,
        ks_pa: KN / R,
        mu: 0.5,
        contact_damping_ratio: 0.0,
        crushed_shear_pa: f64::INFINITY,
        rolling,
        twisting,
        rate: Default::default(),
        compaction: None,
    }
}

/// Sphere j at +x, pressed into i by OVERLAP; i spins at `w_i`.
fn pair(w_i: [f64; 3]) -> Pair {
    Pair { r: [R, R], dx_m: [2.0 * R - OVERLAP, 0.0, 0.0], v: [[0.0; 3]; 2], w: [w_i, [0.0; 3]], m: [1.0, 1.0] }
}

#[test]
fn the_rolling_moment_is_capped_at_eta_r_fn_and_unloads_from_the_cap() {
    const KR: f64 = 50.0;
    let p = rolling::Params { kr_pa: KR / R.powi(3), eta: 0.3 };
    let k = class(Some(p), None);
    let mut c = Contact::new(0, 1, 0, Bond::Frictional, 2.0 * R, [1.0, 0.0, 0.0]);
    let mut d = Dissipation::default();
    let cap = 0.3 * R * KN * OVERLAP;
    let omega = 10.0;
    // Each step rolls by half the relative spin: dθ = ω Δt / 2, about z.
    let dtheta = 0.5 * omega * DT;
    // (one short of the cap: the step that would land on it may round past it)
    let elastic_steps = (cap / (KR * dtheta)).floor() as usize - 1;
    assert!(elastic_steps > 10, "{elastic_steps}");
    for s in 1..=elastic_steps {
        law::act(&mut c, &k, &pair([0.0, 0.0, omega]), DT, &mut d);
        let want = KR * dtheta * s as f64;
        assert!((c.rolling_nm[2] - want).abs() < 1e-9 * cap, "step {s}: {} against k_r θ = {want}", c.rolling_nm[2]);
    }
    assert_eq!(d.rolling_j, 0.0, "below the cap nothing is dissipated");
    // Past the cap: held there, and each step dissipates 2 M_cap dθ (the moment acts on both
    // spheres over half their relative turn).
    for _ in 0..3 {
        law::act(&mut c, &k, &pair([0.0, 0.0, omega]), DT, &mut d);
    }
    let before = d.rolling_j;
    for _ in 0..20 {
        let a = law::act(&mut c, &k, &pair([0.0, 0.0, omega]), DT, &mut d);
        assert!((c.rolling_nm[2] - cap).abs() < 1e-12 * cap, "{} against the cap {cap}", c.rolling_nm[2]);
        assert_eq!([c.rolling_nm[0], c.rolling_nm[1]], [0.0, 0.0]);
        // The moment on j carries +M_r, on i −M_r (beside the shear force's moments, which
        // are equal on both spheres of equal size).
        assert!(((a.moment_j_nm[2] - a.moment_i_nm[2]) - 2.0 * cap).abs() < 1e-9 * cap);
    }
    let per_step = (d.rolling_j - before) / 20.0;
    assert!((per_step / (2.0 * cap * dtheta) - 1.0).abs() < 1e-9, "{per_step} J per step");
    // Reversed: the moment leaves the cap at once, along k_r.
    for s in 1..=5 {
        law::act(&mut c, &k, &pair([0.0, 0.0, -omega]), DT, &mut d);
        let want = cap - KR * dtheta * s as f64;
        assert!((c.rolling_nm[2] - want).abs() < 1e-9 * cap, "unloading step {s}: {} against {want}", c.rolling_nm[2]);
    }
}

#[test]
fn the_twisting_moment_is_capped_by_mohr_coulomb_over_the_contact_disc() {
    let (tan_phi, cohesion) = (0.6, 2e4);
    const KT: f64 = 20.0;
    let p = twisting::Params { kt_pa: KT / R.powi(3), cap: twisting::Cap::MohrCoulomb { tan_phi, cohesion_pa: cohesion } };
    let k = class(None, Some(p));
    let mut c = Contact::new(0, 1, 0, Bond::Frictional, 2.0 * R, [1.0, 0.0, 0.0]);
    let mut d = Dissipation::default();
    let f_n = KN * OVERLAP;
    let cap = 2.0 / 3.0 * (R * f_n * tan_phi + std::f64::consts::PI * R.powi(3) * cohesion);
    let omega = 40.0;
    for _ in 0..20_000 {
        law::act(&mut c, &k, &pair([omega, 0.0, 0.0]), DT, &mut d);
    }
    // i spins about +n: the moment T = k_t (ω_i − ω_j)·n Δt / 2 per step, capped.
    assert!((c.twisting_nm - cap).abs() < 1e-12 * cap, "{} against eq 42's {cap}", c.twisting_nm);
    assert!(d.twisting_j > 0.0);
    law::act(&mut c, &k, &pair([-omega, 0.0, 0.0]), DT, &mut d);
    let want = cap - KT * 0.5 * omega * DT;
    assert!((c.twisting_nm - want).abs() < 1e-9 * cap, "unloads from the cap: {} against {want}", c.twisting_nm);
}
