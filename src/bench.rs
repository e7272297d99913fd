//! The kernel benchmark workloads. Figures: nanoseconds per contact-step, element-steps per
//! second and neighbour rebuilds per 1000 steps, medians of repeats.
//!
//! * **block** (issue [1/5]): a close-packed block of about 12 000 elements with every bond
//!   intact, set vibrating so that all contacts stay active, stepped undamped;
//! * **impact** (issue [3/6]): the same block, breakable (the seed's concrete, energy
//!   criterion), struck by the seed's steel projectile (3.5 in wide, hemispherical nose, 15 lb)
//!   at 1500 ft/s, run while the nose goes through the first 20 % of the block's depth: bonds
//!   break, fragments touch, and the projectile outruns any fixed neighbour skin.

use std::time::Instant;

use crate::cases::seed;
use crate::error::Result;
use crate::kernel::{Model, ModelBuilder};
use crate::lattice::{self, Rect};
use crate::material::{Arrangement, Material, Plane};
use crate::shape::{Nose, Projectile};
use crate::units::{fps_to_mps, in_to_m, lb_to_kg};

/// Elements per row of the benchmark block.
pub const COLUMNS: usize = 120;
/// Rows of the block.
pub const ROWS: usize = 100;
/// Out-of-plane thickness of the benchmark models, m.
pub const THICKNESS_M: f64 = 0.0176;
/// Impact speed of the impact workload, ft/s.
pub const IMPACT_FPS: f64 = 1500.0;
/// Fraction of the block's depth the impact workload runs through.
pub const IMPACT_DEPTH_FRACTION: f64 = 0.2;

/// Which workload.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Workload {
    /// All-bonded vibrating block.
    Block,
    /// Steel projectile at 1500 ft/s into the breakable block.
    Impact,
}

fn block_rect(columns: usize, rows: usize) -> (Rect, f64) {
    let r = 0.00635;
    (Rect { x_min_m: 0.0, x_max_m: 2.0 * r * columns as f64, y_min_m: 0.0, y_max_m: 2.0 * r + 3f64.sqrt() * r * (rows as f64 - 0.5) }, r)
}

/// The block workload: concrete-like close-packed block, R = 6.35 mm (the source's 0.25 in),
/// plane strain, bonds that do not break, pseudo-random initial velocities of order 1 m/s.
pub fn workload(columns: usize, rows: usize) -> Result<Model> {
    let (rect, r) = block_rect(columns, rows);
    let lat = lattice::close_packed(&rect, r)?;
    let mut b = ModelBuilder::new(Plane::Strain, THICKNESS_M);
    let concrete = Material {
        tensile_strength_pa: 2.07e6,
        compressive_strength_pa: 20.7e6,
        fracture_toughness_pa_sqrt_m: 1.0e6,
        ..Material::elastic("concrete", 21.5e9, 0.2, 2320.0)
    };
    let m = b.add_material(concrete);
    let body = b.add_body("block", &lat, Arrangement::ClosePacked, m, &[], [0.0; 3]);
    // Velocities are set before the model is built, so the integrator is primed with them.
    let mut s = 0x9E37_79B9_7F4A_7C15u64;
    for e in body {
        let mut v = [0.0; 3];
        for c in v.iter_mut().take(2) {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            *c = (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
        }
        b.set_velocity(e, v);
    }
    b.build()
}

/// The impact workload and the number of steps it runs (the nose through the first
/// [`IMPACT_DEPTH_FRACTION`] of the block at the impact speed).
pub fn impact_workload(columns: usize, rows: usize) -> Result<(Model, u64)> {
    let (rect, r) = block_rect(columns, rows);
    let lat = lattice::close_packed(&rect, r)?;
    let mut b = ModelBuilder::new(Plane::Strain, THICKNESS_M);
    let c = b.add_material(seed::concrete());
    let rp = seed::projectile_radius_m();
    let mut outline = Projectile {
        tail_m: [0.5 * rect.x_max_m, 0.0],
        axis: [0.0, -1.0],
        width_m: seed::projectile_width_m(),
        length_m: in_to_m(8.77),
        nose: Nose::Hemispherical,
        crh: None,
    };
    outline.tail_m[1] = rect.y_max_m + 0.0005 + outline.length_m;
    let proj = outline.lattice(Arrangement::ClosePacked, rp, 0, 0.0)?;
    // The steel's density gives the 15 lb at this thickness.
    let mut steel = seed::steel();
    steel.density_kg_per_m3 = lb_to_kg(seed::PROJECTILE_WEIGHT_LB) / (proj.centres.len() as f64 * proj.area_per_element_m2 * THICKNESS_M);
    let s = b.add_material(steel);
    b.add_body("block", &lat, Arrangement::ClosePacked, c, &[], [0.0; 3]);
    let v = fps_to_mps(IMPACT_FPS);
    b.add_body("projectile", &proj, Arrangement::ClosePacked, s, &[], [0.0, -v, 0.0]);
    let model = b.build()?;
    let steps = (IMPACT_DEPTH_FRACTION * rect.y_max_m / (v * model.dt_s())).ceil() as u64;
    Ok((model, steps))
}

/// One benchmark measurement.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Figures {
    /// Elements.
    pub elements: usize,
    /// Mean contacts per step.
    pub contacts: f64,
    /// Steps per repeat.
    pub steps: u64,
    /// Threads of the pool.
    pub threads: usize,
    /// Median wall time per step, s.
    pub step_s: f64,
    /// Median ns per contact-step.
    pub ns_per_contact_step: f64,
    /// Median element-steps per second.
    pub element_steps_per_s: f64,
    /// Fastest and slowest repeat, ns per contact-step.
    pub range_ns: (f64, f64),
    /// Full neighbour rebuilds per 1000 steps.
    pub rebuilds_per_1000: f64,
    /// Local neighbour updates per 1000 steps.
    pub local_updates_per_1000: f64,
}

/// Time `steps` steps of `model` (a fresh copy each repeat for the impact, which changes as it
/// runs; the block keeps vibrating); returns (seconds, contact-steps, full rebuilds, local
/// updates).
fn time_steps(model: &mut Model, steps: u64) -> Result<(f64, f64, u64, u64)> {
    let (rebuilds, local) = (model.state.rebuilds, model.state.local_updates);
    let mut contact_steps = 0.0;
    let t0 = Instant::now();
    for _ in 0..steps {
        contact_steps += model.state.contacts.len() as f64;
        model.step()?;
    }
    Ok((t0.elapsed().as_secs_f64(), contact_steps, model.state.rebuilds - rebuilds, model.state.local_updates - local))
}

/// Run `repeats` timings of workload `w` on a pool of `threads` threads (`steps` steps for
/// the block; the impact runs its own count).
pub fn measure(w: Workload, columns: usize, rows: usize, steps: u64, repeats: usize, threads: usize) -> Result<Figures> {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("thread pool");
    pool.install(|| {
        let mut runs = Vec::with_capacity(repeats);
        let (elements, steps) = match w {
            Workload::Block => {
                let mut model = workload(columns, rows)?;
                model.run_steps(steps.min(200))?; // warm caches and the allocator
                for _ in 0..repeats {
                    runs.push(time_steps(&mut model, steps)?);
                }
                (model.el.len(), steps)
            }
            Workload::Impact => {
                let (model, n) = impact_workload(columns, rows)?;
                for _ in 0..repeats {
                    let mut m = model.clone();
                    runs.push(time_steps(&mut m, n)?);
                }
                (model.el.len(), n)
            }
        };
        let mut per = runs.iter().map(|r| r.0 / r.1 * 1e9).collect::<Vec<_>>();
        per.sort_by(f64::total_cmp);
        runs.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (wall, contact_steps, rebuilds, local) = runs[runs.len() / 2];
        let step_s = wall / steps as f64;
        Ok(Figures {
            elements,
            contacts: contact_steps / steps as f64,
            steps,
            threads,
            step_s,
            ns_per_contact_step: per[per.len() / 2],
            element_steps_per_s: elements as f64 / step_s,
            range_ns: (per[0], per[per.len() - 1]),
            rebuilds_per_1000: 1000.0 * rebuilds as f64 / steps as f64,
            local_updates_per_1000: 1000.0 * local as f64 / steps as f64,
        })
    })
}
