//! The P-wave speed of a 3D random block against the continuum's
//! √(E (1 − ν) / (ρ (1 + ν)(1 − 2ν))), for springs made for E and ν by `kernel3d::stiffness` and
//! masses giving the block the density ρ. One face of a block 30 R deep and 40 R wide is driven
//! into it at a small speed v0 from rest: a plane step front travels in; along the block's axis
//! it is in uniaxial strain until the sides' release arrives (after the sensors read). The front
//! passes a sensor when the sensor's mean velocity reaches v0/2; the speed is the distance between
//! two sensors over the time between them (the source's rise time drops out).

use demsweep::kernel3d::law::Class;
use demsweep::kernel3d::stiffness;
use demsweep::kernel3d::Builder;
use demsweep::packing3d::{self, Box3};

const E: f64 = 30e9;
const NU: f64 = 0.2;
const RHO: f64 = 2400.0;
const R: f64 = 0.005;

#[test]
fn a_random_block_carries_a_p_wave_at_the_continuums_speed() {
    let (depth, width) = (30.0 * R, 40.0 * R);
    let b = Box3 { x_min_m: 0.0, x_max_m: depth, y_min_m: -width / 2.0, y_max_m: width / 2.0, z_min_m: -width / 2.0, z_max_m: width / 2.0 };
    let p = packing3d::random_dense(&b, R, 11, 0.1).unwrap();
    let inner = Box3 { x_min_m: 4.0 * R, x_max_m: depth - 4.0 * R, y_min_m: -width / 2.0 + 4.0 * R, y_max_m: width / 2.0 - 4.0 * R, z_min_m: -width / 2.0 + 4.0 * R, z_max_m: width / 2.0 - 4.0 * R };
    let bd = stiffness::bond_density(&p.centres_m, &p.radii_m, &p.bonds, |x| inner.contains(x), inner.volume_m3());
    let (kappa, alpha) = stiffness::springs(E, NU, bd).unwrap();
    let class = Class::elastic(kappa, alpha, 0.5);
    let mut bld = Builder::new(1);
    bld.class(0, 0, class);
    let all = bld.body("block", &p.centres_m, &p.radii_m, 0, RHO);
    bld.mass_total(all.clone(), RHO * b.volume_m3());
    for &(i, j) in &p.bonds {
        bld.bond(i as usize, j as usize);
    }
    let v0 = 0.1;
    for e in all.clone().filter(|&e| p.centres_m[e][0] < 1.5 * R) {
        bld.hold(e, [v0, 0.0, 0.0]);
    }
    let mut m = bld.build(&[]).unwrap();
    let c_p = (E * (1.0 - NU) / (RHO * (1.0 + NU) * (1.0 - 2.0 * NU))).sqrt();
    // Sensors: spheres within 4 R of the axis, within R of depths 8 R and 18 R.
    let sensor = |d: f64| -> Vec<usize> {
        all.clone().filter(|&e| {
            let x = p.centres_m[e];
            (x[0] - d).abs() < R && x[1].hypot(x[2]) < 4.0 * R
        }).collect()
    };
    let sensors = [sensor(8.0 * R), sensor(18.0 * R)];
    assert!(sensors.iter().all(|s| s.len() >= 10), "sensor sizes {:?}", sensors.iter().map(Vec::len).collect::<Vec<_>>());
    let mean_vx = |m: &demsweep::kernel3d::Model, s: &[usize]| s.iter().map(|&e| m.state.vel_mps[e][0]).sum::<f64>() / s.len() as f64;
    let mut passed = [None, None];
    let (mut last, dt) = ([0.0, 0.0], m.motion.dt_s);
    while passed[1].is_none() && m.time_s() < 25.0 * R / c_p {
        m.step().unwrap();
        for k in 0..2 {
            let v = mean_vx(&m, &sensors[k]);
            if passed[k].is_none() && v >= 0.5 * v0 {
                // Interpolated within the step (velocities at the half step: t − Δt/2).
                let t = m.time_s() - 0.5 * dt - dt * (v - 0.5 * v0) / (v - last[k]);
                passed[k] = Some(t);
            }
            last[k] = v;
        }
    }
    let (t1, t2) = (passed[0].expect("the front reached 8 R"), passed[1].expect("the front reached 18 R"));
    let c = 10.0 * R / (t2 - t1);
    println!("{} spheres, Δt {dt:.3e} s: front at 8 R {t1:.4e} s, at 18 R {t2:.4e} s: {c:.1} m/s against {c_p:.1} m/s ({:+.2} %)", m.spheres.len(), 100.0 * (c / c_p - 1.0));
    assert!((c / c_p - 1.0).abs() < 0.03, "{c:.1} m/s against {c_p:.1}");
}
