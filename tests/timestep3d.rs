//! The 3D kernel's step against the top frequency it must resolve, measured. On a bonded random
//! block with rolling and twisting on, the top eigenvalue of M⁻¹K is found by power iteration on
//! the linearised contacts (assembled here from the law's springs, independently of the
//! kernel's Gershgorin bound). What must hold: the bound is at or above it; the kernel, run
//! undamped from a small random disturbance, stays bounded at 0.95 of the measured limit 2/ω
//! and blows up at 1.1 of it — the measured top frequency is the one its dynamics have.

use demsweep::kernel3d::contact::Bond;
use demsweep::kernel3d::law::{Class, rolling, twisting};
use demsweep::kernel3d::vec3::{V3, add, cross, dot, norm, scale, sub};
use demsweep::kernel3d::{Builder, Model};
use demsweep::packing3d::{self, Box3};

const R: f64 = 0.005;

fn class() -> Class {
    let kappa = 60e9;
    Class {
        rolling: Some(rolling::Params { kr_pa: 0.3 * kappa, eta: f64::INFINITY }),
        twisting: Some(twisting::Params { kt_pa: 0.15 * kappa, cap: twisting::Cap::None }),
        ..Class::elastic(kappa, 0.3, 0.5)
    }
}

fn block(dt_s: Option<f64>) -> Model {
    let s = 10.0 * R;
    let b = Box3 { x_min_m: 0.0, x_max_m: s, y_min_m: 0.0, y_max_m: s, z_min_m: 0.0, z_max_m: s };
    let p = packing3d::random_dense(&b, R, 5, 0.1).unwrap();
    let mut bld = Builder::new(1);
    bld.class(0, 0, class());
    bld.body("block", &p.centres_m, &p.radii_m, 0, 2400.0);
    for &(i, j) in &p.bonds {
        bld.bond(i as usize, j as usize);
    }
    bld.dt_s = dt_s;
    bld.build(&[]).unwrap()
}

/// K q for generalised displacements q (per sphere: translation, rotation), from the bonds'
/// linearised springs: the energy ½ k_n (u·n)² + ½ k_s |u_t|² + k_r |θ_r|² + k_t θ_t², with u the
/// contact points' relative displacement and θ_r, θ_t half the relative rotation across and
/// about n (the moments act on both spheres: `kernel3d::law::moments_j`).
fn k_times(m: &Model, q: &[[V3; 2]]) -> Vec<[V3; 2]> {
    let mut out = vec![[[0.0; 3]; 2]; q.len()];
    // The bonds: the frictional candidates within the skin do not touch at rest.
    for c in m.contacts().iter().filter(|c| c.bond == Bond::Intact) {
        let (i, j) = (c.i as usize, c.j as usize);
        let (ri, rj) = (m.spheres.radius_m[i], m.spheres.radius_m[j]);
        let dx = sub(m.state.pos_m[j], m.state.pos_m[i]);
        let d = norm(dx);
        let n = scale(1.0 / d, dx);
        let (li, lj) = (d * ri / (ri + rj), d * rj / (ri + rj));
        let k = m.classes[c.class as usize].at(0.5 * (ri + rj));
        let u = sub(add(q[j][0], cross(q[j][1], scale(-lj, n))), add(q[i][0], cross(q[i][1], scale(li, n))));
        let un = dot(u, n);
        let ut = sub(u, scale(un, n));
        // The force on j; i takes its opposite; both act at the contact point.
        let f = scale(-1.0, add(scale(k.bond_kn * un, n), scale(k.bond_ks, ut)));
        let rel = sub(q[i][1], q[j][1]);
        let twist = 0.5 * dot(rel, n);
        let roll = scale(0.5, sub(rel, scale(2.0 * twist, n)));
        let moment = add(scale(k.kr, roll), scale(k.kt * twist, n));
        // K q is minus the restoring forces.
        out[j][0] = sub(out[j][0], f);
        out[i][0] = add(out[i][0], f);
        out[j][1] = sub(out[j][1], cross(scale(-lj, n), f));
        out[i][1] = sub(out[i][1], cross(scale(li, n), scale(-1.0, f)));
        out[i][1] = add(out[i][1], moment);
        out[j][1] = sub(out[j][1], moment);
    }
    out
}

/// The top eigenvalue of M⁻¹K (ω², rad²/s²) by power iteration on M^-½ K M^-½.
fn omega_top(m: &Model) -> f64 {
    let n = m.spheres.len();
    let w = |e: usize| [1.0 / m.spheres.mass_kg[e].sqrt(), 1.0 / m.spheres.inertia_kg_m2[e].sqrt()];
    let mut x: Vec<[V3; 2]> = (0..n).map(|e| [[(e % 7) as f64 - 3.0, (e % 5) as f64 - 2.0, (e % 3) as f64 - 1.0], [(e % 11) as f64 - 5.0, 1.0, -1.0]]).collect();
    let mut lambda = 0.0;
    for _ in 0..3000 {
        let q: Vec<[V3; 2]> = (0..n).map(|e| [scale(w(e)[0], x[e][0]), scale(w(e)[1], x[e][1])]).collect();
        let kq = k_times(m, &q);
        let y: Vec<[V3; 2]> = (0..n).map(|e| [scale(w(e)[0], kq[e][0]), scale(w(e)[1], kq[e][1])]).collect();
        let dot_all = |a: &[[V3; 2]], b: &[[V3; 2]]| a.iter().zip(b).map(|(p, q)| dot(p[0], q[0]) + dot(p[1], q[1])).sum::<f64>();
        lambda = dot_all(&x, &y) / dot_all(&x, &x);
        let size = dot_all(&y, &y).sqrt();
        x = y.iter().map(|p| [scale(1.0 / size, p[0]), scale(1.0 / size, p[1])]).collect();
    }
    lambda
}

/// Kinetic energy after `steps` undamped steps from a small random disturbance, over the start's.
fn growth(mut m: Model, steps: u64) -> f64 {
    for e in 0..m.spheres.len() {
        m.state.vel_mps[e] = [1e-3 * ((e * 37 % 17) as f64 - 8.0), 1e-3 * ((e * 11 % 13) as f64 - 6.0), 1e-3 * ((e * 5 % 7) as f64 - 3.0)];
        m.state.spin_rad_per_s[e] = [0.1 * ((e % 3) as f64 - 1.0), 0.0, 0.1 * ((e % 5) as f64 - 2.0)];
    }
    let ke0 = m.kinetic_energy_j();
    match m.run_steps(steps) {
        Ok(()) => m.kinetic_energy_j() / ke0,
        Err(_) => f64::INFINITY,
    }
}

#[test]
fn the_step_bound_lies_above_the_measured_top_frequency_and_the_kernel_goes_unstable_past_it() {
    let m = block(None);
    let omega_p = omega_top(&m).sqrt();
    let omega_g = m.omega_bound_rad_per_s;
    println!("{} spheres, {} bonds: bound {omega_g:.4e} rad/s, power iteration {omega_p:.4e} rad/s, ratio {:.3}", m.spheres.len(), m.intact_bonds(), omega_g / omega_p);
    assert!(omega_g >= omega_p, "the bound {omega_g:.4e} lies below the measured {omega_p:.4e}");
    // The bound counts every candidate within the skin as a contact that can form, at the
    // stiffer of its bond and frictional springs: cautious, and what it costs in steps is its
    // ratio to the measured.
    assert!(omega_g < 2.0 * omega_p, "the bound is {:.2} times the measured: too cautious", omega_g / omega_p);
    let limit = 2.0 / omega_p;
    let below = growth(block(Some(0.95 * limit)), 4000);
    let above = growth(block(Some(1.1 * limit)), 4000);
    println!("kinetic energy after 4000 steps over the start's: {below:.3} at 0.95 of 2/ω, {above:.3e} at 1.1");
    assert!(below < 10.0, "stable at 0.95 of the measured limit: {below}");
    assert!(above > 1e6, "unstable at 1.1 of the measured limit: {above}");
}

