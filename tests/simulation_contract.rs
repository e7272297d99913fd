//! The contract of `demsweep::simulation`: a kernel other than the 2D one plugs into the run
//! loop and the penetration outcome without either knowing it. The kernel here is a ghost: its
//! elements fly at their initial velocities, the held ones stay, nothing touches — so a
//! projectile crosses the target untouched, and when the outcome says it went through, and at
//! what speed, follows from its flight alone.

use std::ops::Range;
use std::sync::Arc;

use demsweep::kernel::Model;
use demsweep::penetration::scene::PenetrationScene;
use demsweep::penetration::{self, Hooks};
use demsweep::run::{self, Checkpointing, RunCheckpoint};
use demsweep::simulation::{Bodies, Built, Measure, Simulation, Tally, Threading};
use demsweep::units::{M_PER_IN, mps_to_fps};

/// Elements in free flight (3D, z = 0 here), copied from a built 2D model.
#[derive(Debug, Clone)]
struct Ghost {
    dt_s: f64,
    steps: u64,
    bodies: Vec<(String, Range<usize>)>,
    initial: Vec<[f64; 3]>,
    pos: Vec<[f64; 3]>,
    vel: Vec<[f64; 3]>,
    radius: Vec<f64>,
    mass: Vec<f64>,
    held: Vec<bool>,
    bonds: Vec<(usize, usize)>,
    threading: Threading,
}

impl Ghost {
    fn from_model(m: &Model) -> Ghost {
        let n = m.el.len();
        Ghost {
            dt_s: m.dt_s(),
            steps: 0,
            bodies: m.bodies.iter().map(|b| (b.name.clone(), b.elements.clone())).collect(),
            initial: (0..n).map(|e| m.initial_m(e)).collect(),
            pos: (0..n).map(|e| m.position_m(e)).collect(),
            vel: (0..n).map(|e| m.velocity_mps(e)).collect(),
            radius: m.el.radius.clone(),
            mass: m.el.mass.clone(),
            held: (0..n).map(|e| m.el.is_fully_prescribed(e)).collect(),
            bonds: {
                let mut b = Vec::new();
                m.each_bond(&mut |i, j| b.push((i, j)));
                b
            },
            threading: Threading::Pool,
        }
    }
}

impl Bodies for Ghost {
    fn time_s(&self) -> f64 {
        self.steps as f64 * self.dt_s
    }
    fn body(&self, name: &str) -> Option<Range<usize>> {
        self.bodies.iter().find(|b| b.0 == name).map(|b| b.1.clone())
    }
    fn element_count(&self) -> usize {
        self.pos.len()
    }
    fn initial_m(&self, e: usize) -> [f64; 3] {
        self.initial[e]
    }
    fn position_m(&self, e: usize) -> [f64; 3] {
        self.pos[e]
    }
    fn velocity_mps(&self, e: usize) -> [f64; 3] {
        self.vel[e]
    }
    fn radius_m(&self, e: usize) -> f64 {
        self.radius[e]
    }
    fn mass_kg(&self, e: usize) -> f64 {
        self.mass[e]
    }
    fn held(&self, e: usize) -> bool {
        self.held[e]
    }
    fn each_bond(&self, f: &mut dyn FnMut(usize, usize)) {
        self.bonds.iter().for_each(|&(i, j)| f(i, j));
    }
}

impl Simulation for Ghost {
    fn dt_s(&self) -> f64 {
        self.dt_s
    }
    fn steps(&self) -> u64 {
        self.steps
    }
    fn run_steps(&mut self, n: u64) -> demsweep::Result<()> {
        for _ in 0..n {
            for e in (0..self.pos.len()).filter(|&e| !self.held[e]) {
                for d in 0..3 {
                    self.pos[e][d] += self.vel[e][d] * self.dt_s;
                }
            }
            self.steps += 1;
        }
        Ok(())
    }
    fn threading(&self) -> Threading {
        self.threading
    }
    fn set_threading(&mut self, threading: Threading) {
        self.threading = threading;
    }
    fn checkpoint(&self) -> Vec<u8> {
        let mut out = self.steps.to_le_bytes().to_vec();
        self.pos.iter().flatten().for_each(|x| out.extend(x.to_le_bytes()));
        out
    }
    fn restore(&mut self, bytes: &[u8]) -> demsweep::Result<()> {
        let word = |k: usize| <[u8; 8]>::try_from(&bytes[8 * k..8 * k + 8]).unwrap();
        self.steps = u64::from_le_bytes(word(0));
        for (k, x) in self.pos.iter_mut().flatten().enumerate() {
            *x = f64::from_le_bytes(word(k + 1));
        }
        Ok(())
    }
    fn contact_count(&self) -> u64 {
        self.bonds.len() as u64
    }
    fn bond_count(&self) -> u64 {
        self.bonds.len() as u64
    }
    fn tally(&self) -> Tally {
        let ke = (0..self.pos.len()).map(|e| 0.5 * self.mass[e] * self.vel[e].iter().map(|v| v * v).sum::<f64>()).sum();
        Tally {
            elements: self.pos.len() as u64,
            bonds_broken: 0,
            dt_s: self.dt_s,
            dt_bound_s: self.dt_s,
            omega_bound_rad_per_s: 0.0,
            dt_limit: "ghost".into(),
            kinetic_energy_j: ke,
            strain_energy_j: 0.0,
            external_work_j: 0.0,
            mass_damping_j: 0.0,
            contacts_j: Vec::new(),
            dissipated_j: 0.0,
            energy_residual_j: 0.0,
            energy_in_j: ke,
            neighbour_rebuilds: 0,
            neighbour_local_updates: 0,
        }
    }
}

/// The projectile's lowest point, m.
#[derive(Debug)]
struct Tip;

impl Measure<Ghost> for Tip {
    fn name(&self) -> &str {
        "tip_y_m"
    }
    fn value(&self, g: &Ghost) -> f64 {
        g.body("projectile").unwrap().map(|e| g.pos[e][1] - g.radius[e]).fold(f64::INFINITY, f64::min)
    }
}

/// A thin target at level 0, and the ghost of its model with the tip probe.
fn ghost_scene() -> (PenetrationScene, Built<Ghost>, demsweep::penetration::scene::Layout) {
    let mut s = PenetrationScene::with_name("ghost");
    s.penetration.level = 0;
    s.target.length_in = 24.0;
    s.target.depth_in = 6.0;
    s.projectile.standoff_in = 1.0;
    s.projectile.v0_fps = 1000.0;
    let (scene, layout) = s.to_scene().unwrap();
    let b = scene.build().unwrap();
    let ghost = Ghost::from_model(&b.model);
    let probes: Vec<Arc<dyn Measure<Ghost>>> = vec![Arc::new(Tip)];
    (s, Built { name: b.name, model: ghost, probes, duration_s: b.duration_s, every_steps: 50 }, layout)
}

#[test]
fn a_second_kernel_runs_through_the_run_loop_and_the_outcome_detector_untouched() {
    let (scene, built, layout) = ghost_scene();
    let g = &built.model;
    let projectile = g.body("projectile").unwrap();
    let v0 = -g.vel[projectile.start][1];
    assert!((mps_to_fps(v0) - 1000.0).abs() < 1e-9, "the ghost starts at the scene's speed: {v0} m/s");
    // The projectile's rear passes the target's lowest attached point at t*: through at the
    // first look after it.
    let rear0 = projectile.clone().map(|e| g.pos[e][1] + g.radius[e]).fold(f64::NEG_INFINITY, f64::max);
    let target = g.body("target").unwrap();
    let bottom = target.clone().map(|e| g.pos[e][1] - g.radius[e]).fold(f64::INFINITY, f64::min);
    let t_through = (rear0 - bottom) / v0;
    let look = scene.outcome.check_every_steps as f64 * g.dt_s;
    let f = penetration::run_on(&scene, built, layout, Hooks::default()).unwrap();
    let o = &f.row.outcome;
    assert!(o.perforated && o.scabbed, "{o:?}");
    let t = o.perforation_time_s.unwrap();
    assert!(t >= t_through && t <= t_through + look + 1e-12, "through at {t} s, the flight says {t_through}..{} s", t_through + look);
    assert!((o.v_residual_fps - 1000.0).abs() < 1e-6, "an untouched projectile keeps its speed: {} ft/s", o.v_residual_fps);
    assert_eq!(f.row.run.end_reason, "perforated");
    // The depth is the tip's travel below the front face at the last look.
    let depth = (layout_front(&scene) - f.row.run.probes.get("tip_y_m_final").unwrap()) / M_PER_IN;
    assert!((o.depth_in - depth).abs() < 1e-9, "depth {} in, the probe says {depth} in", o.depth_in);
    // The row carries the ghost's tally.
    assert_eq!((f.row.run.dt_limit.as_str(), f.row.run.elements), ("ghost", f.model.pos.len() as u64));
}

fn layout_front(scene: &PenetrationScene) -> f64 {
    scene.to_scene().unwrap().1.front_y_m
}

#[test]
fn a_second_kernel_resumed_from_its_checkpoint_ends_as_the_run_that_never_stopped() {
    let straight = run::run_with(ghost_scene().1, run::Options { threading: Threading::Serial, ..Default::default() }).unwrap();
    let mut saved = Vec::new();
    let mut save = |c: &RunCheckpoint| {
        saved.push(c.clone());
        Err(demsweep::Error::input("test", "killed"))
    };
    let options = run::Options { checkpointing: Some(Checkpointing { every_steps: 400, save: &mut save }), ..Default::default() };
    assert!(run::run_with(ghost_scene().1, options).is_err());
    let resumed = run::run_with(ghost_scene().1, run::Options { resume: Some(&saved[0]), ..Default::default() }).unwrap();
    assert_eq!(resumed.series, straight.series);
    assert_eq!(resumed.model.pos, straight.model.pos);
}
