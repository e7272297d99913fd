//! The kernel benchmark workload (issue [1/5]): a close-packed block of about 12 000 elements
//! with every bond intact, set vibrating so that all contacts stay active, stepped undamped.
//! Figures: nanoseconds per contact-step and element-steps per second, median of repeats.

use std::time::Instant;

use crate::error::Result;
use crate::kernel::{Model, ModelBuilder};
use crate::lattice::{self, Rect};
use crate::material::{Arrangement, Material, Plane};

/// Elements per row of the benchmark block.
pub const COLUMNS: usize = 120;
/// Rows of the block.
pub const ROWS: usize = 100;

/// The benchmark model: concrete-like close-packed block, R = 6.35 mm (the source's 0.25 in),
/// plane strain, bonds that do not break, pseudo-random initial velocities of order 1 m/s.
pub fn workload(columns: usize, rows: usize) -> Result<Model> {
    let r = 0.00635;
    let rect = Rect {
        x_min_m: 0.0,
        x_max_m: 2.0 * r * columns as f64,
        y_min_m: 0.0,
        y_max_m: 2.0 * r + 3f64.sqrt() * r * (rows as f64 - 0.5),
    };
    let lat = lattice::close_packed(&rect, r)?;
    let mut b = ModelBuilder::new(Plane::Strain, 0.0176);
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

/// One benchmark measurement.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Figures {
    /// Elements.
    pub elements: usize,
    /// Contacts.
    pub contacts: usize,
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
}

/// Run `repeats` timings of `steps` steps each on a pool of `threads` threads.
pub fn measure(columns: usize, rows: usize, steps: u64, repeats: usize, threads: usize) -> Result<Figures> {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("thread pool");
    pool.install(|| {
        let mut model = workload(columns, rows)?;
        model.run_steps(steps.min(200))?; // warm caches and the allocator
        let mut times = Vec::with_capacity(repeats);
        for _ in 0..repeats {
            let t0 = Instant::now();
            model.run_steps(steps)?;
            times.push(t0.elapsed().as_secs_f64() / steps as f64);
        }
        times.sort_by(f64::total_cmp);
        let median = times[times.len() / 2];
        let (n, c) = (model.el.len(), model.state.contacts.len());
        Ok(Figures {
            elements: n,
            contacts: c,
            steps,
            threads,
            step_s: median,
            ns_per_contact_step: median * 1e9 / c as f64,
            element_steps_per_s: n as f64 / median,
            range_ns: (times[0] * 1e9 / c as f64, times[times.len() - 1] * 1e9 / c as f64),
        })
    })
}
