//! A 3D random block's elastic moduli against the E and ν its springs were made for
//! (`kernel3d::stiffness`, the affine estimate). The block is a seeded dense random packing,
//! bonded where the gap is below a tenth of the radius; its outer layer (within 2 R of a face)
//! is driven along an affine velocity field ε̇ x, then stopped and the interior relaxed
//! (dynamic relaxation). The stress in the interior is the contacts' virial
//! σ = −(1/V) Σ f_j ⊗ l over the bonds with an end in it (½ per end); an isotropic strain gives
//! K = tr σ / (9 e), a pure shear (ε_xx = −ε_yy = e) gives μ = (σ_xx − σ_yy) / (4 e).

use demsweep::kernel3d::contact::Bond;
use demsweep::kernel3d::law::Class;
use demsweep::kernel3d::stiffness;
use demsweep::kernel3d::{Builder, Model};
use demsweep::packing3d::{self, Box3, Packing};

const E: f64 = 30e9;
const NU: f64 = 0.2;
const R: f64 = 0.005;
const RHO: f64 = 2400.0;
/// Relaxation after the load, in loading times (`RELAX` in the environment; 4 by default: the
/// moduli agree with 10 and 30 to four digits).
static RELAX: std::sync::LazyLock<f64> = std::sync::LazyLock::new(|| std::env::var("RELAX").ok().and_then(|v| v.parse().ok()).unwrap_or(4.0));

struct Block {
    model: Model,
    inner: Box3,
    bond_density: f64,
}

fn inner_of(b: &Box3, margin: f64) -> Box3 {
    Box3 { x_min_m: b.x_min_m + margin, x_max_m: b.x_max_m - margin, y_min_m: b.y_min_m + margin, y_max_m: b.y_max_m - margin, z_min_m: b.z_min_m + margin, z_max_m: b.z_max_m - margin }
}

/// The block of side `side_r` × R, driven by strain `strain` (a symmetric 3×3) over one pass.
fn block(b: &Box3, p: &Packing, strain: [[f64; 3]; 3], springs: Option<(f64, f64)>) -> Block {
    let s = b.x_max_m - b.x_min_m;
    let inner = inner_of(b, 4.0 * R);
    let bond_density = stiffness::bond_density(&p.centres_m, &p.radii_m, &p.bonds, |x| inner.contains(x), inner.volume_m3());
    let (kappa, alpha) = springs.unwrap_or_else(|| stiffness::springs(E, NU, bond_density).unwrap());
    let class = Class::elastic(kappa, alpha, 0.5);
    let mut bld = Builder::new(1);
    bld.class(0, 0, class);
    let all = bld.body("block", &p.centres_m, &p.radii_m, 0, RHO);
    for &(i, j) in &p.bonds {
        bld.bond(i as usize, j as usize);
    }
    // Strain e over time T: the outer layer moves at ε x / T.
    let c = (E / RHO).sqrt();
    let t_load = 20.0 * s / c;
    let velocity = |x: [f64; 3]| std::array::from_fn(|k| (0..3).map(|m| strain[k][m] * x[m]).sum::<f64>() / t_load);
    let outer = inner_of(b, 2.0 * R);
    let mut driven = Vec::new();
    for e in all.clone() {
        if !outer.contains(p.centres_m[e]) {
            bld.hold(e, velocity(p.centres_m[e]));
            driven.push(e);
        }
    }
    // Damping near critical for the block's lowest mode (ω ≈ π c / s).
    bld.alpha_per_s = 2.0 * std::f64::consts::PI * c / s;
    let mut model = bld.build(&[]).unwrap();
    let dt = model.motion.dt_s;
    model.run_steps((t_load / dt).round() as u64).unwrap();
    for &e in &driven {
        model.spheres.prescribed_mps[e] = [0.0; 3];
    }
    model.run_steps((*RELAX * t_load / dt).round() as u64).unwrap();
    Block { model, inner, bond_density }
}

/// The virial stress over the interior, Pa (tension positive).
fn stress(b: &Block) -> [[f64; 3]; 3] {
    let m = &b.model;
    let mut sigma = [[0.0; 3]; 3];
    // Forces of the last step's contacts, recomputed from the state: the springs' forces.
    for c in m.contacts() {
        let (i, j) = (c.i as usize, c.j as usize);
        let (p, q) = (m.state.pos_m[i], m.state.pos_m[j]);
        let ends = u8::from(b.inner.contains(p)) + u8::from(b.inner.contains(q));
        if ends == 0 {
            continue;
        }
        let l: [f64; 3] = std::array::from_fn(|k| q[k] - p[k]);
        let d = (l[0] * l[0] + l[1] * l[1] + l[2] * l[2]).sqrt();
        let n: [f64; 3] = std::array::from_fn(|k| l[k] / d);
        let k = m.classes[c.class as usize].at(0.5 * (m.spheres.radius_m[i] + m.spheres.radius_m[j]));
        let f_n = match c.bond {
            Bond::Intact => k.bond_kn * (d - c.rest_m - c.plastic_opening_m),
            Bond::Frictional => k.kn * (d - c.rest_m).min(0.0),
        };
        // Force on j: −F_n n + the shear spring's force.
        let f: [f64; 3] = std::array::from_fn(|k| -f_n * n[k] + c.shear_n[k]);
        for a in 0..3 {
            for bb in 0..3 {
                sigma[a][bb] -= 0.5 * f64::from(ends) * f[a] * l[bb];
            }
        }
    }
    let v = b.inner.volume_m3();
    sigma.map(|row| row.map(|x| x / v))
}

/// (E Pa, ν, B) of the block of side `side_r` R from packing `seed`, with `springs` (κ_n Pa, α)
/// or, without, those `stiffness::springs` gives for E and ν.
fn moduli(side_r: f64, seed: u64, springs: Option<(f64, f64)>) -> (f64, f64, f64) {
    let e = 1e-5;
    let s = side_r * R;
    let b = Box3 { x_min_m: -s / 2.0, x_max_m: s / 2.0, y_min_m: -s / 2.0, y_max_m: s / 2.0, z_min_m: -s / 2.0, z_max_m: s / 2.0 };
    let p = packing3d::random_dense(&b, R, seed, 0.1).unwrap();
    let iso = block(&b, &p, [[e, 0.0, 0.0], [0.0, e, 0.0], [0.0, 0.0, e]], springs);
    let s = stress(&iso);
    let k = (s[0][0] + s[1][1] + s[2][2]) / (9.0 * e);
    let shear = block(&b, &p, [[e, 0.0, 0.0], [0.0, -e, 0.0], [0.0, 0.0, 0.0]], springs);
    let s = stress(&shear);
    let mu = (s[0][0] - s[1][1]) / (4.0 * e);
    let young = 9.0 * k * mu / (3.0 * k + mu);
    let nu = (3.0 * k - 2.0 * mu) / (2.0 * (3.0 * k + mu));
    println!("block {side_r} R ({} spheres, B = {:.4}): K {:.4e} Pa, μ {:.4e} Pa, E {:.4e} Pa ({:+.2} %), ν {:.4} (target {NU})",
        iso.model.spheres.len(), iso.bond_density, k, mu, young, 100.0 * (young / E - 1.0), nu);
    (young, nu, iso.bond_density)
}

/// On packings the relation was not measured on (seed 3, sides 20 R and 24 R).
#[test]
fn a_random_block_has_the_e_and_nu_its_springs_were_made_for() {
    for side in [20.0, 24.0] {
        let (young, nu, _) = moduli(side, 3, None);
        assert!((young / E - 1.0).abs() < 0.03, "E {young:.4e} Pa against {E:.4e}");
        assert!((nu - NU).abs() < 0.03 * NU, "ν {nu:.4} against {NU}");
    }
}

/// The measured relation `kernel3d::stiffness` uses: E / (κ_n B) and ν against α on packing
/// seed 1, side 32 R (`cargo test --release --test elastic3d -- --ignored --nocapture`).
#[test]
#[ignore]
fn measure_the_relation() {
    let only: Option<Vec<f64>> = std::env::var("ALPHAS").ok().map(|v| v.split(',').map(|a| a.parse().unwrap()).collect());
    for alpha in only.unwrap_or(vec![0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.35, 0.4, 0.5, 0.75, 1.0]) {
        let t = std::time::Instant::now();
        let (young, nu, b) = moduli(32.0, 1, Some((1e9, alpha)));
        println!("alpha {alpha:.3}  E/(kappa B) {:.5}  nu {nu:.5}  (affine {:.5}, {:.5})  {:.1} s", young / (1e9 * b),
            stiffness::affine_moduli(1.0, alpha, 1.0).0, stiffness::affine_moduli(1.0, alpha, 1.0).1, t.elapsed().as_secs_f64());
    }
}

