//! The 3D kernel's impact workload: the example scene `sweeps/impact3d.toml` (a steel projectile
//! at 150 m/s into a bonded concrete slab, the moment transfer law on, bonds breaking and new
//! contacts forming), timed from its first step per contact-step and per sphere-step on each
//! thread count. Each round starts again from the built scene, so every round does the same work.

use std::path::Path;
use std::time::Instant;

use crate::error::{Error, Result};
use crate::kernel3d::Model;
use crate::scene_file::{SceneFile, load_text};

/// The scene, built into the binary so the bench runs from any folder.
pub const SCENE: &str = include_str!("../../sweeps/impact3d.toml");

/// The built example scene's model.
pub fn workload() -> Result<Model> {
    match load_text(SCENE, Path::new("sweeps/impact3d.toml"), &[])? {
        SceneFile::Kernel3(s) => Ok(s.build()?.model),
        _ => Err(Error::input("sweeps/impact3d.toml", "is not a 3D scene")),
    }
}

/// One thread count's figures.
#[derive(Debug, Clone)]
pub struct Figures {
    /// Threads.
    pub threads: usize,
    /// Median ns per contact-step (contacts counted at every step).
    pub ns_per_contact_step: f64,
    /// Fastest and slowest round, ns per contact-step.
    pub range_ns: (f64, f64),
    /// Mean contacts over the steps.
    pub mean_contacts: f64,
    /// Bonds broken by the end of the steps.
    pub bonds_broken: u64,
}

/// Time `steps` steps from the start `repeats` times on each thread count (in turn within a
/// round).
pub fn measure(steps: u64, repeats: usize, threads: &[usize]) -> Result<Vec<Figures>> {
    let built = workload()?;
    let mut per: Vec<Vec<f64>> = vec![Vec::new(); threads.len()];
    let mut last: Vec<(f64, u64)> = vec![(0.0, 0); threads.len()];
    for _ in 0..repeats {
        for (k, &t) in threads.iter().enumerate() {
            let pool = rayon::ThreadPoolBuilder::new().num_threads(t).build().expect("thread pool");
            let mut m = built.clone();
            let mut contacts = 0usize;
            let t0 = Instant::now();
            pool.install(|| -> Result<()> {
                for _ in 0..steps {
                    contacts += m.state.contacts.len();
                    m.step()?;
                }
                Ok(())
            })?;
            per[k].push(t0.elapsed().as_secs_f64() * 1e9 / contacts as f64);
            last[k] = (contacts as f64 / steps as f64, m.state.ledger.bonds_broken());
        }
    }
    Ok(threads
        .iter()
        .enumerate()
        .map(|(k, &t)| {
            let mut v = per[k].clone();
            v.sort_by(f64::total_cmp);
            Figures { threads: t, ns_per_contact_step: v[v.len() / 2], range_ns: (v[0], v[v.len() - 1]), mean_contacts: last[k].0, bonds_broken: last[k].1 }
        })
        .collect())
}
