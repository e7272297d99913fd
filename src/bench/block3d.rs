//! The 3D kernel's benchmark workload: an fcc block of bonded spheres (every touching pair
//! bonded, rolling and twisting on), set vibrating by a seeded random velocity field and left
//! undamped, so every bond stays in the loop; timed per bond-step on one thread and on all.

use std::time::Instant;

use crate::error::Result;
use crate::kernel3d::law::{Class, rolling, twisting};
use crate::kernel3d::{Builder, Model};
use crate::packing3d::{self, Box3};

/// Sphere radius of the block, m.
pub const RADIUS_M: f64 = 0.005;

/// The block of side `side_r` radii: concrete-like springs (κ_n = 60 GPa, k_s/k_n = 0.25),
/// unbreakable bonds, MTL rolling and twisting.
pub fn workload(side_r: f64) -> Result<Model> {
    let s = side_r * RADIUS_M;
    let b = Box3 { x_min_m: 0.0, x_max_m: s, y_min_m: 0.0, y_max_m: s, z_min_m: 0.0, z_max_m: s };
    let p = packing3d::fcc(&b, RADIUS_M)?;
    let kappa = 60e9;
    let class = Class {
        rolling: Some(rolling::Params { kr_pa: 0.25 * kappa, eta: f64::INFINITY }),
        twisting: Some(twisting::Params { kt_pa: 0.125 * kappa, cap: twisting::Cap::None }),
        ..Class::elastic(kappa, 0.25, 0.5)
    };
    let mut bld = Builder::new(1);
    bld.class(0, 0, class);
    let all = bld.body("block", &p.centres_m, &p.radii_m, 0, 2400.0);
    for &(i, j) in &p.bonds {
        bld.bond(i as usize, j as usize);
    }
    let mut m = bld.build(&[])?;
    // A seeded velocity field of 0.1 m/s.
    let mut s64 = 0x3D_B10Cu64;
    let mut rnd = || {
        s64 = s64.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (s64 >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    for e in all {
        m.state.vel_mps[e] = [0.2 * rnd(), 0.2 * rnd(), 0.2 * rnd()];
    }
    Ok(m)
}

/// One thread count's figures.
#[derive(Debug, Clone)]
pub struct Figures {
    /// Threads.
    pub threads: usize,
    /// Spheres.
    pub spheres: usize,
    /// Intact bonds.
    pub bonds: usize,
    /// Median ns per bond-step.
    pub ns_per_bond_step: f64,
    /// Fastest and slowest round, ns per bond-step.
    pub range_ns: (f64, f64),
}

/// Time `steps` steps of the block `repeats` times on each thread count (in turn within a round).
pub fn measure(side_r: f64, steps: u64, repeats: usize, threads: &[usize]) -> Result<Vec<Figures>> {
    let built = workload(side_r)?;
    let mut out = Vec::new();
    let mut per: Vec<Vec<f64>> = vec![Vec::new(); threads.len()];
    let mut models: Vec<Model> = threads.iter().map(|_| built.clone()).collect();
    for _ in 0..repeats {
        for (k, &t) in threads.iter().enumerate() {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(t).build().expect("thread pool");
            let m = &mut models[k];
            let bonds = m.intact_bonds() as f64;
            let t0 = Instant::now();
            pool.install(|| m.run_steps(steps))?;
            per[k].push(t0.elapsed().as_secs_f64() * 1e9 / (bonds * steps as f64));
        }
    }
    for (k, &t) in threads.iter().enumerate() {
        let mut v = per[k].clone();
        v.sort_by(f64::total_cmp);
        out.push(Figures { threads: t, spheres: built.spheres.len(), bonds: built.intact_bonds(), ns_per_bond_step: v[v.len() / 2], range_ns: (v[0], v[v.len() - 1]) });
    }
    Ok(out)
}
