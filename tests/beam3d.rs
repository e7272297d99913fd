//! Seed 004's beam: one line of N spheres bonded with the moment transfer law, k_r = E I_f / r
//! (eq 38), as a cantilever clamped at the first sphere, relaxed to rest (dynamic relaxation,
//! mass-proportional damping critical for the first bending mode).
//! * Under a tip load its deflection converges to Euler–Bernoulli's F L³ / (3 E I) as N grows:
//!   the spheres are the beam's section (I = π r⁴/4, r = L / (2(N − 1))), and both the
//!   quadrature of the curvature and the shear springs' deflection fall as (r/L)², so the
//!   observed order is 2.
//! * Under a tip torque it twists by T L / (G I_t) for any N with k_t = G I_t / r; with eq 41 as
//!   printed (2 G I_t / r) by half that: the misprint `kernel3d::law::twisting` corrects.

use std::f64::consts::PI;

use demsweep::kernel3d::law::{Class, rolling, twisting};
use demsweep::kernel3d::{Builder, Model};

const E: f64 = 30e9;
const NU: f64 = 0.25;
const RHO: f64 = 2400.0;
const L: f64 = 1.0;

fn g() -> f64 {
    E / (2.0 * (1.0 + NU))
}

/// The beam's class: at spheres of radius r, axial and shear springs of the cylinder of length
/// 2r (E A / 2r = E π r / 2, G π r / 2), rolling E I_f / r = E π r³ / 4 (eq 38), twisting
/// `kt_pa` × r³.
fn class(kt_pa: f64) -> Class {
    Class {
        bond_kn_pa: E * PI / 2.0,
        bond_ks_pa: g() * PI / 2.0,
        bond_tension_pa: f64::INFINITY,
        bond_shear_pa: f64::INFINITY,
        bond_fracture_j_per_m2: f64::INFINITY,
        kn_pa: E * PI / 2.0,
        ks_pa: g() * PI / 2.0,
        mu: 0.5,
        contact_damping_ratio: 0.0,
        crushed_shear_pa: f64::INFINITY,
        rolling: Some(rolling::Params { kr_pa: E * PI / 4.0, eta: f64::INFINITY }),
        twisting: Some(twisting::Params { kt_pa, cap: twisting::Cap::None }),
        rate: Default::default(),
        compaction: None,
    }
}

/// The cantilever of `n` spheres with a tip force and moment, relaxed; returns the model.
fn cantilever(n: usize, kt_pa: f64, tip_force: [f64; 3], tip_moment: [f64; 3]) -> Model {
    let r = L / (2.0 * (n - 1) as f64);
    let centres: Vec<[f64; 3]> = (0..n).map(|k| [2.0 * r * k as f64, 0.0, 0.0]).collect();
    let mut b = Builder::new(1);
    b.class(0, 0, class(kt_pa));
    let beam = b.body("beam", &centres, &vec![r; n], 0, RHO);
    // The cylinder's mass per sphere, and its inertia about the beam's axis.
    let m = RHO * PI * r * r * 2.0 * r;
    for e in beam.clone() {
        b.mass(e, m, 0.5 * m * r * r);
    }
    for k in 0..n - 1 {
        b.bond(k, k + 1);
    }
    b.hold(0, [0.0; 3]);
    b.load(n - 1, tip_force, tip_moment);
    // Critical damping of the first bending mode: ω1 = 1.875² √(E I / (ρ A L⁴)) = 3.516 c r / (2 L²).
    let c = (E / RHO).sqrt();
    let omega1 = 1.875f64.powi(2) * c * r / (2.0 * L * L);
    b.alpha_per_s = 2.0 * omega1;
    let mut model = b.build(&[]).unwrap();
    // The slowest mode decays as e^(−α t / 2); twenty time constants leave 2e-9 of the start.
    let steps = (20.0 / omega1 / model.motion.dt_s).ceil() as u64;
    model.run_steps(steps).unwrap();
    model
}

#[test]
fn a_line_of_spheres_bends_like_an_euler_bernoulli_cantilever_at_second_order() {
    let mut errors = Vec::new();
    for n in [6, 11, 21, 41] {
        let r = L / (2.0 * (n - 1) as f64);
        // A load that bends each beam by 10⁻⁴ L (small deflection: the theory is linear).
        let ei = E * PI * r.powi(4) / 4.0;
        let f = 3.0 * ei * 1e-4 / (L * L);
        let m = cantilever(n, twisting::beam_kt_pa(g()), [0.0, -f, 0.0], [0.0; 3]);
        let exact = f * L.powi(3) / (3.0 * ei);
        let tip = -m.displacement_m(n - 1)[1];
        let err = tip / exact - 1.0;
        println!("N = {n:3}: tip {tip:.6e} m, Euler–Bernoulli {exact:.6e} m, error {:+.4} %", 100.0 * err);
        errors.push(err);
    }
    // Spacing halves from one N to the next (N − 1 = 5, 10, 20, 40).
    let orders: Vec<f64> = errors.windows(2).map(|w| (w[0] / w[1]).abs().log2()).collect();
    println!("observed orders {orders:.3?}");
    assert!(errors.last().unwrap().abs() < 0.01, "finest N: {:+.3} %", 100.0 * errors.last().unwrap());
    for p in &orders[1..] {
        assert!((p - 2.0).abs() < 0.3, "observed order {p:.3}, expected 2 (errors {errors:?})");
    }
    // The leading term, derived: the trapezoidal sum of the curvature gives −1/4 (N − 1)⁻², the
    // shear springs' deflection F (N − 1) / k_s adds 3E/(16G) (N − 1)⁻² (r = L / 2(N − 1)).
    let coefficient = errors.last().unwrap() * 40.0 * 40.0;
    let derived = -0.25 + 3.0 * E / (16.0 * g());
    println!("error × (N − 1)² at N = 41: {coefficient:.4}, derived {derived:.4}");
    assert!((coefficient / derived - 1.0).abs() < 0.03, "{coefficient} against {derived}");
}

#[test]
fn a_line_of_spheres_twists_like_a_circular_shaft_and_eq_41_as_printed_by_half() {
    let t = 50.0;
    for n in [6, 21] {
        let r = L / (2.0 * (n - 1) as f64);
        let it = PI * r.powi(4) / 2.0;
        let exact = t * L / (g() * it);
        // The twist of the tip sphere about x: its spin integrated is not kept; read it from the
        // twisting moments instead (each contact carries T = k_t × half the relative twist of
        // sphere i less sphere j's, so the tip turning positively gives negative moments).
        let twist = |m: &Model, kt: f64| -m.contacts().iter().map(|c| 2.0 * c.twisting_nm / kt).sum::<f64>();
        let kt = twisting::beam_kt_pa(g());
        let m = cantilever(n, kt, [0.0; 3], [t, 0.0, 0.0]);
        let phi = twist(&m, kt * r.powi(3));
        println!("N = {n}: twist {phi:.6e} rad, T L / (G I_t) {exact:.6e} rad");
        assert!((phi / exact - 1.0).abs() < 0.01, "N = {n}: {:+.3} %", 100.0 * (phi / exact - 1.0));
        let printed = 2.0 * g() * it / r;
        let m = cantilever(n, printed / r.powi(3), [0.0; 3], [t, 0.0, 0.0]);
        let ratio = twist(&m, printed) / exact;
        assert!((ratio - 0.5).abs() < 0.005, "eq 41 as printed twists by {ratio:.4} of the shaft");
    }
}
