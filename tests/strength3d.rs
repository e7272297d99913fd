//! Tensile and compressive strength of a 3D random cube under slow loading, reported against
//! the bonds' tensile strength σ_t and the concrete's f'c — what the law gives, not tuned. A
//! study (`cargo test --release --test strength3d -- --ignored --nocapture`, run by
//! `scripts/validation.sh`): the cube's bottom 1.5 R is held, its top 1.5 R driven up (tension)
//! or down (compression) at a strain rate slow against the wave transit; the stress is the
//! driven layer's reaction over the cube's section.

use demsweep::kernel3d::law::{Class, rolling, twisting};
use demsweep::kernel3d::{Builder, stiffness};
use demsweep::packing3d::{self, Box3};

const R: f64 = 0.005;
const E: f64 = 30e9;
const NU: f64 = 0.2;
const RHO: f64 = 2400.0;
/// Bond tensile strength, Pa (about a concrete's f_t of 3 MPa).
const SIGMA_T: f64 = 3e6;
/// The concrete's compressive strength the seed's target has (5 000 psi), Pa.
const FC: f64 = 34.5e6;

/// Peak stress (Pa, tension positive) and the strain at it, driving the top at `sign` × ε̇.
fn cube(side_r: f64, sign: f64, strain_to: f64, transits: f64) -> (f64, f64) {
    let s = side_r * R;
    let b = Box3 { x_min_m: 0.0, x_max_m: s, y_min_m: 0.0, y_max_m: s, z_min_m: 0.0, z_max_m: s };
    let p = packing3d::random_dense(&b, R, 21, 0.1).unwrap();
    let inner = Box3 { x_min_m: 3.0 * R, x_max_m: s - 3.0 * R, y_min_m: 3.0 * R, y_max_m: s - 3.0 * R, z_min_m: 3.0 * R, z_max_m: s - 3.0 * R };
    let bd = stiffness::bond_density(&p.centres_m, &p.radii_m, &p.bonds, |x| inner.contains(x), inner.volume_m3());
    let (kappa, alpha) = stiffness::springs(E, NU, bd).unwrap();
    let class = Class {
        bond_kn_pa: kappa,
        bond_ks_pa: alpha * kappa,
        bond_tension_pa: SIGMA_T,
        bond_shear_pa: 2.0 * SIGMA_T,
        bond_fracture_j_per_m2: 100.0,
        kn_pa: kappa,
        ks_pa: alpha * kappa,
        mu: 0.5,
        contact_damping_ratio: 0.0,
        crushed_shear_pa: f64::INFINITY,
        rolling: Some(rolling::Params { kr_pa: alpha * kappa, eta: 0.1 }),
        twisting: Some(twisting::Params { kt_pa: 0.5 * alpha * kappa, cap: twisting::Cap::MohrCoulomb { tan_phi: 0.5, cohesion_pa: 0.0 } }),
        rate: Default::default(),
        compaction: None,
    };
    let mut bld = Builder::new(1);
    bld.class(0, 0, class);
    let all = bld.body("cube", &p.centres_m, &p.radii_m, 0, RHO);
    bld.mass_total(all.clone(), RHO * b.volume_m3());
    for &(i, j) in &p.bonds {
        bld.bond(i as usize, j as usize);
    }
    let c = (E / RHO).sqrt();
    // The whole strain range over `transits` wave transits of the cube (slow against them).
    let rate = strain_to / (transits * s / c);
    let top: Vec<usize> = all.clone().filter(|&e| p.centres_m[e][1] > s - 1.5 * R).collect();
    for e in all.clone() {
        if p.centres_m[e][1] < 1.5 * R {
            bld.hold(e, [0.0; 3]);
        }
    }
    for &e in &top {
        bld.hold(e, [0.0, sign * rate * s, 0.0]);
    }
    bld.alpha_per_s = 0.2 * std::f64::consts::PI * c / s;
    let mut m = bld.build(&[]).unwrap();
    let (mut peak, mut at) = (0.0f64, 0.0);
    let every = 50;
    while m.time_s() * rate < strain_to {
        m.run_steps(every).unwrap();
        // The contacts' pull on the driven layer, y, over the section: the layer's reaction.
        let f: f64 = top.iter().map(|&e| m.state.force_n[e][1]).sum();
        let stress = -f / (s * s);
        if sign * stress > sign * peak {
            peak = stress;
            at = m.time_s() * rate;
        }
    }
    println!("cube {side_r} R ({} spheres), {}: peak {:.3} MPa at strain {at:.3e} ({} of {} bonds broken)",
        m.spheres.len(), if sign > 0.0 { "tension" } else { "compression" }, peak / 1e6, m.state.ledger.contacts.broken, p.bonds.len());
    (peak, at)
}

#[test]
#[ignore]
fn the_tensile_and_compressive_strength_of_a_cube() {
    // Slow enough: the peaks at 300 and 1000 transits agree (printed).
    for transits in [300.0, 1000.0] {
        cube(16.0, 1.0, 0.006, transits);
    }
    let (t, _) = cube(16.0, 1.0, 0.006, 1000.0);
    println!("tension: {:.3} MPa = {:.3} σ_t (bonds) ", t / 1e6, t / SIGMA_T);
    let (c, _) = cube(16.0, -1.0, 0.01, 1000.0);
    println!("compression: {:.3} MPa = {:.3} f'c = {:.2} σ_t; compression over tension {:.2}", -c / 1e6, -c / FC, -c / SIGMA_T, -c / t);
    assert!(t > 0.0 && c < 0.0);
}
