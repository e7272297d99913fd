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
use crate::material::CompactionSpec;
use crate::material::RateSpec;
use crate::kernel::{Model, ModelBuilder};
use crate::lattice::{self, Rect};
use crate::material::{Arrangement, Material, Plane};
use crate::shape::{Nose, Projectile};
use crate::units::{fps_to_mps, in_to_m, lb_to_kg};

pub mod block3d;
pub mod impact3d;
pub mod simple;

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
    /// The 3D kernel: a vibrating fcc block of bonded spheres (`block3d`).
    Block3d,
    /// The 3D kernel: the example impact, `sweeps/impact3d.toml` (`impact3d`).
    Impact3d,
}

fn block_rect(columns: usize, rows: usize) -> (Rect, f64) {
    let r = 0.00635;
    (Rect { x_min_m: 0.0, x_max_m: 2.0 * r * columns as f64, y_min_m: 0.0, y_max_m: 2.0 * r + 3f64.sqrt() * r * (rows as f64 - 0.5) }, r)
}

/// The optional law parts the block workload turns on (each costs only when on).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Laws {
    /// Coulomb friction (μ = 0.5) on frictional contacts (the block has none touching: its cost
    /// is the branch alone).
    pub friction: bool,
    /// Stiffness-proportional dashpots, β = 1e-8 s (0.9 % of critical at the block's top mode).
    pub damping: bool,
    /// The rate laws (CEB moduli, Klepaczko tension, CEB compression), defaults of `RateSpec`.
    pub rate: bool,
    /// Compaction (HJC constants of the penetration scene: K_c = 0.5 Kn, full at 5 %).
    pub compaction: bool,
}

impl Laws {
    /// Every optional part on.
    pub const ALL: Laws = Laws { friction: true, damping: true, rate: true, compaction: true };

    /// A short name: "none", "all" or the parts joined by '+'.
    pub fn name(&self) -> String {
        let on: Vec<&str> = [(self.friction, "friction"), (self.damping, "damping"), (self.rate, "rate"), (self.compaction, "compaction")]
            .iter()
            .filter(|p| p.0)
            .map(|p| p.1)
            .collect();
        match on.len() {
            0 => "none".into(),
            4 => "all".into(),
            _ => on.join("+"),
        }
    }
}

/// The block workload: concrete-like close-packed block, R = 6.35 mm (the source's 0.25 in),
/// plane strain, bonds that do not break, pseudo-random initial velocities of order 1 m/s; μ = 0.5
/// (friction on, as in every scene with frictional contacts).
pub fn workload(columns: usize, rows: usize) -> Result<Model> {
    workload_with(columns, rows, Laws { friction: true, ..Laws::default() })
}

/// The block workload with the optional law parts `laws` on.
pub fn workload_with(columns: usize, rows: usize, laws: Laws) -> Result<Model> {
    let (rect, r) = block_rect(columns, rows);
    let lat = lattice::close_packed(&rect, r)?;
    let mut b = ModelBuilder::new(Plane::Strain, THICKNESS_M);
    let concrete = Material {
        tensile_strength_pa: 2.07e6,
        compressive_strength_pa: 20.7e6,
        fracture_toughness_pa_sqrt_m: 1.0e6,
        friction_coefficient: if laws.friction { 0.5 } else { 0.0 },
        rate: laws.rate.then(RateSpec::default),
        compaction: laws.compaction.then_some(CompactionSpec { stiffness_ratio: 0.5, full_strain: 0.05 }),
        ..Material::elastic("concrete", 21.5e9, 0.2, 2320.0)
    };
    if laws.damping {
        b.beta_s = 1e-8;
    }
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
#[derive(Debug, Clone, PartialEq)]
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
    /// Each round's wall time per step, in round order, s.
    pub rounds_s: Vec<f64>,
}

impl Figures {
    /// How many times faster this is than `other` (the same workload on another number of
    /// threads, measured in the same rounds): the median of the rounds' own ratios.
    pub fn speed_up_over(&self, other: &Figures) -> f64 {
        median_ratio(&other.rounds_s, &self.rounds_s)
    }
}

/// The median of the ratios a[k] / b[k] (the upper middle one of an even count, as the
/// figures' medians).
fn median_ratio(a: &[f64], b: &[f64]) -> f64 {
    let mut r: Vec<f64> = a.iter().zip(b).map(|(a, b)| a / b).collect();
    r.sort_by(f64::total_cmp);
    r.get(r.len() / 2).copied().unwrap_or(f64::NAN)
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

/// Run `repeats` rounds of workload `w` (`steps` steps for the block; the impact runs its own
/// count), each round timing one repeat on a pool of each of `threads` threads in turn (the order
/// reversed every other round), with the other workers looking for work between the stages as a
/// single run's do (`kernel::awake`); one [`Figures`] per entry of `threads`. A round takes
/// under a second here, so a thread count's time against another's within it shares the
/// machine's spell ([`Figures::speed_up_over`]); timed one thread count after the other, the
/// two-thread speed-up of the impact moved between 0.85× and 1.34× from one spell to the next.
pub fn measure(w: Workload, columns: usize, rows: usize, steps: u64, repeats: usize, threads: &[usize]) -> Result<Vec<Figures>> {
    let pools: Vec<rayon::ThreadPool> = threads.iter().map(|&t| rayon::ThreadPoolBuilder::new().num_threads(t).build().expect("thread pool")).collect();
    let timed = |pool: &rayon::ThreadPool, model: &mut Model, n: u64| pool.install(|| crate::kernel::exec::awake::while_running(|| time_steps(model, n)));
    // The block: one model per pool, warmed (caches, allocator) and then kept vibrating; the
    // impact: a fresh copy for every repeat, since it changes as it runs.
    let (mut kept, fresh, n) = match w {
        Workload::Block3d | Workload::Impact3d => {
            return Err(crate::error::Error::input("--workload", "the 3D workloads are measured by bench::block3d and bench::impact3d"));
        }
        Workload::Block => {
            let built = workload(columns, rows)?;
            let mut kept = Vec::with_capacity(pools.len());
            for pool in &pools {
                let mut m = built.clone();
                timed(pool, &mut m, steps.min(200))?;
                kept.push(m);
            }
            (kept, None, steps)
        }
        Workload::Impact => {
            let (model, n) = impact_workload(columns, rows)?;
            (Vec::new(), Some(model), n)
        }
    };
    let mut runs = vec![Vec::with_capacity(repeats); pools.len()];
    for round in 0..repeats {
        let mut order: Vec<usize> = (0..pools.len()).collect();
        if round % 2 == 1 {
            order.reverse();
        }
        for k in order {
            let run = match &fresh {
                Some(model) => timed(&pools[k], &mut model.clone(), n)?,
                None => timed(&pools[k], &mut kept[k], n)?,
            };
            runs[k].push(run);
        }
    }
    let elements = fresh.as_ref().or(kept.first()).map_or(0, |m| m.el.len());
    Ok(threads.iter().zip(runs).map(|(&t, runs)| figures(elements, n, t, runs)).collect())
}

/// The figures of `runs` (seconds, contact-steps, full rebuilds, local updates; in round order)
/// of `steps` steps each on `threads` threads.
fn figures(elements: usize, steps: u64, threads: usize, mut runs: Vec<(f64, f64, u64, u64)>) -> Figures {
    let rounds_s: Vec<f64> = runs.iter().map(|r| r.0 / steps as f64).collect();
    let mut per = runs.iter().map(|r| r.0 / r.1 * 1e9).collect::<Vec<_>>();
    per.sort_by(f64::total_cmp);
    runs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (wall, contact_steps, rebuilds, local) = runs[runs.len() / 2];
    let step_s = wall / steps as f64;
    Figures {
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
        rounds_s,
    }
}

/// One row of the optional-law benchmark.
#[derive(Debug, Clone)]
pub struct LawFigures {
    /// "none", "all", the parts on, `"<parts>, one at a time"` (`Model::four_lanes` off) or
    /// "simple" (the simple kernel of [`simple`]).
    pub name: String,
    /// Contacts stepped.
    pub contacts: usize,
    /// Median wall time per step, s.
    pub step_s: f64,
    /// Fastest and slowest repeat, s per step.
    pub range_s: (f64, f64),
    /// Each round's time per step, in round order, s.
    pub rounds_s: Vec<f64>,
}

impl LawFigures {
    /// This variant's time against `other`'s: the median of the rounds' own ratios (the upper
    /// middle one of an even count, as `step_s`). A round times every variant within a second or
    /// two, so the ratio within it shares the machine's spell; the ratio of the two medians need
    /// not (the spells here move a variant's time by up to 1.5× between rounds).
    pub fn ratio_to(&self, other: &LawFigures) -> f64 {
        median_ratio(&self.rounds_s, &other.rounds_s)
    }
}

/// The block on one thread with each set of optional parts in `sets`, the first set again
/// with its bonds one at a time (`Model::four_lanes` off, named `"<set>, one at a time"`), and the
/// simple kernel, timed round-robin (each round times every variant once, so that the machine's
/// drift is shared) for `repeats` rounds of `steps` steps.
pub fn measure_laws(sets: &[Laws], columns: usize, rows: usize, steps: u64, repeats: usize) -> Result<Vec<LawFigures>> {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("thread pool");
    pool.install(|| {
        let mut models = sets.iter().map(|&l| workload_with(columns, rows, l)).collect::<Result<Vec<_>>>()?;
        let mut names: Vec<String> = sets.iter().map(Laws::name).collect();
        if let Some(first) = sets.first() {
            let mut scalar = workload_with(columns, rows, *first)?;
            scalar.four_lanes = false;
            models.push(scalar);
            names.push(format!("{}, one at a time", first.name()));
        }
        let mut plain = simple::Simple::from_model(&workload_with(columns, rows, Laws::default())?);
        for m in &mut models {
            m.run_steps(steps.min(200))?;
        }
        for _ in 0..steps.min(200) {
            plain.step();
        }
        let mut times = vec![Vec::with_capacity(repeats); models.len() + 1];
        for _ in 0..repeats {
            for (m, t) in models.iter_mut().zip(times.iter_mut()) {
                let t0 = Instant::now();
                m.run_steps(steps)?;
                t.push(t0.elapsed().as_secs_f64() / steps as f64);
            }
            let t0 = Instant::now();
            for _ in 0..steps {
                plain.step();
            }
            times[models.len()].push(t0.elapsed().as_secs_f64() / steps as f64);
        }
        let mut out = Vec::new();
        for (k, rounds_s) in times.into_iter().enumerate() {
            let mut t = rounds_s.clone();
            t.sort_by(f64::total_cmp);
            let (name, contacts) = match models.get(k) {
                Some(m) => (names[k].clone(), m.state.contacts.len()),
                None => ("simple".to_string(), plain.bonds()),
            };
            out.push(LawFigures { name, contacts, step_s: t[t.len() / 2], range_s: (t[0], t[t.len() - 1]), rounds_s });
        }
        Ok(out)
    })
}

/// Memory a model's stepping arrays take: (bytes per element, bytes per contact). Per element:
/// the constants of `Elements`, the state (positions, velocities, forces, neighbour reference
/// and margin) and stage 1's force sums; per contact: the contact with its history, the
/// optional parts' slot (when on) and the force (stored when asked for). The broad phase's
/// grid is transient and not counted.
pub fn footprint(model: &Model) -> (f64, f64) {
    use std::mem::size_of;
    use crate::kernel::contact::{Contact, ContactForce};
    use crate::kernel::law::Extra;
    let n = model.el.len().max(1);
    let el = &model.el;
    let constants = el.radius.len() * 5 * size_of::<f64>()
        + el.prescribed.len()
        + (el.kind.len() + el.body.len() + el.motion.len() + el.load.len()) * size_of::<u16>()
        + el.initial.len() * size_of::<[f64; 2]>()
        + el.initial_velocity.len() * size_of::<[f64; 3]>();
    let st = &model.state;
    let state = (st.pos.len() + st.vel.len() + st.force.len()) * size_of::<[f64; 3]>()
        + st.rebuild_pos.len() * size_of::<[f64; 2]>()
        + st.margin_m.len() * size_of::<f64>();
    // Stage 1's force sum.
    let per_element = (constants + state) as f64 / n as f64 + size_of::<[f64; 3]>() as f64;
    let cs = &st.contacts;
    let per_contact = size_of::<Contact>() as f64
        + if cs.extra.is_empty() { 0.0 } else { size_of::<Extra>() as f64 }
        + size_of::<ContactForce>() as f64;
    (per_element, per_contact)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The timing harness reports the work it ran, on one thread and on a pool of two with its
    /// other worker looking for work: the block's elements and bonds as built, the steps asked
    /// for, and figures consistent with one another. (Its timings themselves are not asserted:
    /// speed is measured by the benchmarks, not by tests.)
    #[test]
    fn measure_reports_the_block_it_ran_on_one_thread_and_on_two() {
        let (columns, rows, steps) = (24, 14, 40);
        let built = workload(columns, rows).unwrap();
        let (elements, contacts) = (built.el.len(), built.state.contacts.len());
        let figures = measure(Workload::Block, columns, rows, steps, 3, &[1, 2]).unwrap();
        assert_eq!(figures.len(), 2);
        for (f, threads) in figures.iter().zip([1, 2]) {
            assert_eq!((f.elements, f.steps, f.threads), (elements, steps, threads));
            assert_eq!(f.rounds_s.len(), 3, "{threads} threads: one time per round");
            assert!(f.rounds_s.iter().all(|&t| t > 0.0 && t.is_finite()), "{threads} threads: round times {:?}", f.rounds_s);
            assert_eq!(f.contacts, contacts as f64, "{threads} threads: the intact block keeps its bonds and meets no one");
            assert_eq!((f.rebuilds_per_1000, f.local_updates_per_1000), (0.0, 0.0), "{threads} threads: the block's elements never leave their margins");
            assert!(f.step_s > 0.0 && f.step_s.is_finite(), "{threads} threads: step time {}", f.step_s);
            assert!(f.range_ns.0 <= f.ns_per_contact_step && f.ns_per_contact_step <= f.range_ns.1, "{threads} threads: the median outside its range");
            let rel = (f.element_steps_per_s * f.step_s / elements as f64 - 1.0).abs();
            assert!(rel < 1e-12, "{threads} threads: element-steps per second off by {rel:e}");
        }
    }

    fn law_rounds(rounds_s: &[f64]) -> LawFigures {
        LawFigures { name: String::new(), contacts: 0, step_s: 0.0, range_s: (0.0, 0.0), rounds_s: rounds_s.to_vec() }
    }

    /// The speed-up on more threads pairs the rounds too, and reads as "times faster": the
    /// other's time over this one's, round by round (here 2, 3 and 1: median 2, where the ratio
    /// of the medians is 1.5).
    #[test]
    fn speed_ups_pair_the_rounds() {
        let f = |threads, rounds_s: &[f64]| Figures {
            elements: 1,
            contacts: 1.0,
            steps: 1,
            threads,
            step_s: 0.0,
            ns_per_contact_step: 0.0,
            element_steps_per_s: 0.0,
            range_ns: (0.0, 0.0),
            rebuilds_per_1000: 0.0,
            local_updates_per_1000: 0.0,
            rounds_s: rounds_s.to_vec(),
        };
        let (one, two) = (f(1, &[2.0, 6.0, 3.0]), f(2, &[1.0, 2.0, 3.0]));
        assert_eq!(two.speed_up_over(&one), 2.0);
        assert_eq!(one.speed_up_over(&two), 0.5);
    }

    /// Paired by round: a spell that slows both variants in one round leaves their ratio alone,
    /// where the ratio of the medians takes it (here 2 against the rounds' 1, 1.5 and 2).
    #[test]
    fn law_ratios_pair_the_rounds() {
        let a = law_rounds(&[1.0, 0.75, 1.0]);
        let b = law_rounds(&[1.0, 0.5, 0.5]);
        assert_eq!(a.ratio_to(&b), 1.5);
        assert_eq!(law_rounds(&[2.0, 3.0, 9.0, 4.0]).ratio_to(&law_rounds(&[1.0, 1.0, 3.0, 2.0])), 3.0);
        assert!(law_rounds(&[]).ratio_to(&law_rounds(&[])).is_nan());
    }
}
