//! The rate and compaction parts in 3D: the 2D kernel's laws (seed 000 §6) on a bond of spheres.
//! What must hold: a bond pulled at a strain rate ε̇ = v/L0 carries the tensile plateau
//! ξ(ε̇) σ_t π r̄² (Klepaczko, eq 6.5–6.6), stiffens by the CEB modulus ratio (eq 6.8–6.9) and
//! takes ξ G_f π r̄² to break (eq 6.10); a bond pushed past f'c π r̄² compacts along the yield
//! line and keeps its set (eq 6.11); and an impact with both parts on, the rate read from the
//! smoothed velocity field, closes its energy ledger, steps bit for bit alike on 1 and 2
//! threads, and breaks fewer bonds than without the rate part.

use std::path::Path;

use demsweep::kernel::law::rate;
use demsweep::kernel3d::solid::{RateContext, Solid};
use demsweep::kernel3d::{Builder, Model};
use demsweep::material::RateSpec;
use demsweep::scene_file::{SceneFile, load_text};
use demsweep::simulation::Simulation;

const R: f64 = 0.005;
const E: f64 = 30e9;
const SIGMA_T: f64 = 3e6;
const FC: f64 = 34.5e6;

fn concrete(extra: &str) -> Solid {
    toml::from_str(&format!(
        "name = \"concrete\"\ndensity_kg_per_m3 = 2400.0\nyoungs_modulus_pa = {E}\npoisson_ratio = 0.2\n\
         failure = \"strength_energy\"\ntensile_strength_pa = {SIGMA_T}\nfracture_toughness_pa_sqrt_m = 1.0e6\n\
         compressive_strength_pa = {FC}\n{extra}"
    ))
    .unwrap()
}

/// Two spheres of radius R bonded 2R apart, the first held, the second driven along x at `v`
/// (m/s).
fn pair(solid: &Solid, v: f64) -> Model {
    let class = solid.class(4.0, R, RateContext { max_speed_mps: v.abs(), radius_m: R }).unwrap();
    let mut b = Builder::new(1);
    b.class(0, 0, class);
    b.body("pair", &[[0.0; 3], [2.0 * R, 0.0, 0.0]], &[R, R], 0, 2400.0);
    b.bond(0, 1);
    b.hold(0, [0.0; 3]);
    b.hold(1, [v, 0.0, 0.0]);
    // Both spheres driven: no free motion bounds the step; a hundredth of the pair's period.
    let kn = b_kn(solid);
    b.dt_s = Some(0.01 * 2.0 * std::f64::consts::PI / (2.0 * kn / (2400.0 * 4.0 / 3.0 * std::f64::consts::PI * R.powi(3))).sqrt());
    b.build(&[]).unwrap()
}

/// The bond's normal stiffness, N/m.
fn b_kn(solid: &Solid) -> f64 {
    solid.class(4.0, R, RateContext { max_speed_mps: 1.0, radius_m: R }).unwrap().bond_kn_pa * R
}

/// The pull on the driven sphere (tension positive), N.
fn pull(m: &Model) -> f64 {
    -m.state.force_n[1][0]
}

#[test]
fn a_bond_pulled_fast_carries_klepaczkos_plateau_and_takes_xi_g_f_to_break() {
    // ε̇ = 1 m/s over L0 = 2R = 100 /s, a node of the rate table (its values there are exact).
    let v = 1.0;
    let spec = RateSpec { modulus_filter_s: Some(1e-12), cap_per_s: Some(1e4), ..RateSpec::default() };
    let solid = concrete("[rate]\nmodulus_filter_s = 1e-12\ncap_per_s = 1e4\n");
    let mut m = pair(&solid, v);
    let area = std::f64::consts::PI * R * R;
    let xi = rate::tensile_ratio(100.0, E, SIGMA_T, &spec);
    let modulus = rate::modulus_ratio_tension(100.0);
    let kn = m.classes[0].bond_kn_pa * R;
    let (mut peak, mut checked) = (0.0f64, false);
    while m.state.ledger.bonds_broken() == 0 {
        // The step's forces are taken at the positions it starts from.
        let opening = m.state.pos_m[1][0] - 2.0 * R;
        m.run_steps(1).unwrap();
        let f = pull(&m);
        // Elastic, two steps in (the centred rate has its full value): the secant modulus.
        if !checked && m.state.steps == 3 {
            assert!((f / (kn * modulus * opening) - 1.0).abs() < 1e-9, "secant stiffness {} against {}", f / opening, kn * modulus);
            checked = true;
        }
        peak = peak.max(f);
        assert!(m.state.steps < 100_000, "the bond never broke");
    }
    println!("ξ(100 /s) = {xi:.4}, modulus ratio {modulus:.4}; plateau {peak:.2} N against ξ σ_t π R² = {:.2} N", xi * SIGMA_T * area);
    assert!((peak / (xi * SIGMA_T * area) - 1.0).abs() < 1e-9);
    // The work to break: the plateau's plastic work and the elastic energy released, ξ G_f π R²
    // (eq 6.10), to within one step's opening at the plateau.
    let l = &m.state.ledger.contacts;
    let g_f = solid.fracture_energy_j_per_m2();
    let work = l.plastic_j + l.fracture_j;
    let one_step = xi * SIGMA_T * area * v * m.motion.dt_s;
    println!("work to break {work:.5e} J against ξ G_f π R² = {:.5e} J (one step at the plateau: {one_step:.1e} J)", xi * g_f * area);
    assert!((work - xi * g_f * area).abs() < one_step, "{work} against {}", xi * g_f * area);
}

#[test]
fn a_bond_pushed_past_fc_compacts_and_keeps_its_set() {
    let solid = concrete("[compaction]\n");
    let v = -0.01;
    let mut m = pair(&solid, v);
    let area = std::f64::consts::PI * R * R;
    let kn = m.classes[0].bond_kn_pa * R;
    let critical = FC * area;
    // Push until the bond has compacted by 1 % of its length.
    let target = 0.01 * 2.0 * R;
    while 2.0 * R - m.state.contacts[0].rest_m < target {
        m.run_steps(1).unwrap();
        let f = pull(&m);
        assert!(f >= -critical * (1.0 + 1e-12), "compression {f} N past the yield line {critical} N");
    }
    let p = 2.0 * R - m.state.contacts[0].rest_m;
    assert!((pull(&m) / -critical - 1.0).abs() < 1e-9, "on the yield line: {} N against {critical} N", pull(&m));
    // The work along the yield line: its force times the compaction (perfectly plastic).
    let w = m.state.ledger.contacts.compaction_j;
    assert!((w / (critical * p) - 1.0).abs() < 1e-3, "compaction work {w} J against {} J", critical * p);
    // Pull back: unloading at k_n from the moved rest length, so the force is nil at the set.
    m.spheres.prescribed_mps[1] = [-v, 0.0, 0.0];
    m.state.vel_mps[1] = [-v, 0.0, 0.0];
    let mut last = (m.state.pos_m[1][0], pull(&m));
    while pull(&m) < 0.0 {
        last = (m.state.pos_m[1][0], pull(&m));
        m.run_steps(1).unwrap();
    }
    let slope = (pull(&m) - last.1) / (m.state.pos_m[1][0] - last.0);
    assert!((slope / kn - 1.0).abs() < 1e-6, "unloading slope {slope} against k_n {kn}");
    let set = 2.0 * R - m.state.pos_m[1][0];
    println!("compacted by {p:.4e} m at {critical:.1} N; unloaded to zero force with a set of {set:.4e} m");
    assert!((set - p).abs() < v.abs() * m.motion.dt_s, "set {set} against compaction {p}");
}

/// The example impact with the concrete's rate (over a 1 cm averaging length) and compaction
/// on, or its rate off.
fn impact(rate_on: bool) -> demsweep::simulation::Built<Model> {
    let text = std::fs::read_to_string("sweeps/impact3d.toml").unwrap();
    let parts = if rate_on { "compressive_strength_pa = 34.5e6\nrate = { averaging_length_m = 0.01 }\ncompaction = {}\n" } else { "compressive_strength_pa = 34.5e6\ncompaction = {}\n" };
    let text = text.replacen("twisting = { cohesion_pa = 0.0 }\n", &format!("twisting = {{ cohesion_pa = 0.0 }}\n{parts}"), 1);
    let SceneFile::Kernel3(scene) = load_text(&text, Path::new("impact3d_rate.toml"), &[]).unwrap() else { panic!("a 3D scene") };
    scene.build().unwrap()
}

#[test]
fn an_impact_with_rate_and_compaction_closes_its_ledger_on_any_thread_count() {
    let built = impact(true);
    assert!(!built.model.rate_field.is_empty(), "the rate is read from the smoothed field");
    let steps = (built.duration_s / built.model.dt_s()).ceil() as u64;
    let run = |threads: usize| {
        let mut m = built.model.clone();
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        m.parallel_min_contacts = 1;
        pool.install(|| m.run_steps(steps)).unwrap();
        m
    };
    let mut off = impact(false).model;
    off.run_steps(steps).unwrap();
    println!("rate off: {} bonds broken, compaction {:.3} J, residual {:.3e} J of {:.1} J", off.tally().bonds_broken, off.state.ledger.contacts.compaction_j, off.tally().energy_residual_j, off.tally().energy_in_j);
    let (one, two) = (run(1), run(2));
    assert_eq!(one.checkpoint(), two.checkpoint(), "1 and 2 threads differ");
    let t = one.tally();
    let l = &one.state.ledger.contacts;
    println!(
        "rate on: {} bonds broken, rate work {:.3} J, compaction {:.3} J, residual {:.3e} J of {:.1} J ({:.3} %)",
        t.bonds_broken, l.rate_j, l.compaction_j, t.energy_residual_j, t.energy_in_j, 100.0 * t.energy_residual_j / t.energy_in_j
    );
    assert!(l.rate_j != 0.0 && l.compaction_j > 0.0);
    assert!((t.energy_residual_j / t.energy_in_j).abs() < 0.01);
    // The dynamic strength holds more bonds together than the static one.
    assert!(t.bonds_broken < off.tally().bonds_broken);
    assert!((off.tally().energy_residual_j / off.tally().energy_in_j).abs() < 0.01);
}
