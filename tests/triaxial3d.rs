//! A triaxial test on a dense packing of frictional spheres, with and without the moment
//! transfer law's rolling and twisting resistance (seed 004's reason for it: plain spheres roll
//! too easily, and a packing of them reaches a peak friction angle of about 25° whatever the
//! contact friction). A study (`cargo test --release --test triaxial3d -- --ignored
//! --nocapture`, run by `scripts/validation.sh`).
//!
//! The sample is a seeded dense random packing (no bonds) inside six walls of held spheres
//! (frictionless, no rolling resistance). The walls first close in on it until each carries
//! the confining stress σ3; then the top and bottom walls close at a constant slow speed while the
//! four side walls keep σ3 (a servo on each wall's speed). The friction angle at the peak of
//! σ1/σ3 is asin((σ1 − σ3)/(σ1 + σ3)).

use demsweep::kernel3d::law::{Class, rolling, twisting};
use demsweep::kernel3d::{Builder, Model};
use demsweep::packing3d::{self, Box3};

const R: f64 = 0.005;
const SIDE: f64 = 10.0 * R;
const SIGMA3: f64 = 100e3;
const KAPPA: f64 = 1e8;

fn sample(rolling_on: bool) -> (Model, [Vec<usize>; 6]) {
    let b = Box3 { x_min_m: 0.0, x_max_m: SIDE, y_min_m: 0.0, y_max_m: SIDE, z_min_m: 0.0, z_max_m: SIDE };
    let p = packing3d::random_dense(&b, R, 4, 0.0).unwrap();
    let grain = Class {
        bond_kn_pa: KAPPA,
        bond_ks_pa: 0.5 * KAPPA,
        bond_tension_pa: 0.0,
        bond_shear_pa: 0.0,
        bond_fracture_j_per_m2: 0.0,
        kn_pa: KAPPA,
        ks_pa: 0.5 * KAPPA,
        mu: 0.5,
        contact_damping_ratio: 0.0,
        crushed_shear_pa: f64::INFINITY,
        // k_r = k_s r² (eq 31), η = 0.3; twisting capped by eq 42 with the contact's φ.
        rolling: rolling_on.then_some(rolling::Params { kr_pa: 0.5 * KAPPA, eta: 0.3 }),
        twisting: rolling_on.then_some(twisting::Params { kt_pa: 0.25 * KAPPA, cap: twisting::Cap::MohrCoulomb { tan_phi: 0.5, cohesion_pa: 0.0 } }),
        rate: Default::default(),
        compaction: None,
    };
    let wall = Class { mu: 0.0, rolling: None, twisting: None, ..grain.clone() };
    let mut bld = Builder::new(2);
    bld.class(0, 0, grain);
    bld.class(0, 1, wall.clone());
    bld.class(1, 1, wall);
    bld.body("sample", &p.centres_m, &p.radii_m, 0, 2650.0);
    // Walls: a square grid of spheres of radius R at spacing R, one radius outside each face,
    // twice the side wide (they pass through each other as they move: held spheres feel nothing).
    let mut walls: [Vec<usize>; 6] = Default::default();
    let n = 21;
    for (w, (axis, side)) in [(0, 0.0), (0, 1.0), (1, 0.0), (1, 1.0), (2, 0.0), (2, 1.0)].into_iter().enumerate() {
        let mut centres = Vec::new();
        for a in 0..n {
            for c in 0..n {
                let (u, v) = (-SIDE / 2.0 + a as f64 * R, -SIDE / 2.0 + c as f64 * R);
                let off = if side == 0.0 { -R } else { SIDE + R };
                let mut x = [0.0; 3];
                x[axis] = off;
                x[(axis + 1) % 3] = u;
                x[(axis + 2) % 3] = v;
                centres.push(x);
            }
        }
        let range = bld.body(&format!("wall{w}"), &centres, &vec![R; centres.len()], 1, 2650.0);
        for e in range.clone() {
            bld.hold(e, [0.0; 3]);
        }
        walls[w] = range.collect();
    }
    bld.alpha_per_s = 50.0;
    (bld.build(&[]).unwrap(), walls)
}

/// The stress each wall carries (Pa, compression positive) and the sample's size between them.
fn wall_stresses(m: &Model, walls: &[Vec<usize>; 6]) -> ([f64; 6], [f64; 3]) {
    let pos = |w: usize| m.state.pos_m[walls[w][0]];
    let size: [f64; 3] = std::array::from_fn(|a| pos(2 * a + 1)[a] - pos(2 * a)[a] - 2.0 * R);
    let stresses = std::array::from_fn(|w| {
        let axis = w / 2;
        let f: f64 = walls[w].iter().map(|&e| m.state.force_n[e][axis]).sum();
        let area = size[(axis + 1) % 3] * size[(axis + 2) % 3];
        // The low wall is pushed toward −axis by a compressed sample.
        if w % 2 == 0 { -f / area } else { f / area }
    });
    (stresses, size)
}

/// Set each servoed wall's speed toward its target stress; the others keep theirs.
fn servo(m: &mut Model, walls: &[Vec<usize>; 6], stresses: &[f64; 6], servoed: &[usize], gain_mps_per_pa: f64, cap_mps: f64) {
    for &w in servoed {
        let axis = w / 2;
        // Inward when the wall carries less than σ3.
        let v = (gain_mps_per_pa * (SIGMA3 - stresses[w])).clamp(-cap_mps, cap_mps);
        let mut vel = [0.0; 3];
        vel[axis] = if w % 2 == 0 { v } else { -v };
        for &e in &walls[w] {
            m.spheres.prescribed_mps[e] = vel;
        }
    }
}

/// (peak friction angle °, the axial strain at it) of the test.
fn triaxial(rolling_on: bool) -> (f64, f64) {
    let (mut m, walls) = sample(rolling_on);
    let every = 20;
    let (gain, cap) = (2e-7, 0.05);
    // Isotropic compression to σ3.
    for _ in 0..4000 {
        m.run_steps(every).unwrap();
        let (s, _) = wall_stresses(&m, &walls);
        servo(&mut m, &walls, &s, &[0, 1, 2, 3, 4, 5], gain, cap);
        if m.time_s() > 0.05 && s.iter().all(|x| (x / SIGMA3 - 1.0).abs() < 0.02) {
            break;
        }
    }
    let (s, size0) = wall_stresses(&m, &walls);
    println!("rolling {rolling_on}: consolidated at {:?} kPa, size {:.4?} m after {:.3} s", s.map(|x| (x / 1e3).round()), size0, m.time_s());
    // Shear: the y walls close at 0.02 m/s; the x and z walls keep σ3.
    let v = 0.04;
    for e in &walls[2] {
        m.spheres.prescribed_mps[*e] = [0.0, v / 2.0, 0.0];
    }
    for e in &walls[3] {
        m.spheres.prescribed_mps[*e] = [0.0, -v / 2.0, 0.0];
    }
    let (mut peak, mut at) = (0.0f64, 0.0);
    loop {
        m.run_steps(every).unwrap();
        let (s, size) = wall_stresses(&m, &walls);
        servo(&mut m, &walls, &s, &[0, 1, 4, 5], gain, cap);
        let strain = 1.0 - size[1] / size0[1];
        let s3 = 0.25 * (s[0] + s[1] + s[4] + s[5]);
        let s1 = 0.5 * (s[2] + s[3]);
        let phi = ((s1 - s3) / (s1 + s3)).asin().to_degrees();
        if phi > peak {
            peak = phi;
            at = strain;
        }
        if strain > 0.12 {
            break;
        }
    }
    println!("rolling {rolling_on}: peak friction angle {peak:.1}° at axial strain {at:.3}");
    (peak, at)
}

#[test]
#[ignore]
fn rolling_resistance_raises_the_peak_friction_angle() {
    let (plain, _) = triaxial(false);
    let (mtl, _) = triaxial(true);
    println!("peak friction angle: {plain:.1}° plain spheres, {mtl:.1}° with the moment transfer law");
    assert!(mtl > plain, "{mtl} against {plain}");
}
