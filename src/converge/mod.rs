//! `demsweep converge`: a case at successive refinements, its observed order, Richardson
//! extrapolate and GCI (eq 4.1; Celik et al. 2008 where the ratios differ), its convergence
//! class, and what each digit costs (error against wall time).
//!
//! Cases: the cantilever's tip amplitude and the cracked plate's critical far-field stress
//! (energy criterion, close-packed, the seed's roller grips) — the validation studies of [1/5] —
//! and the penetration depth at a velocity (the calibrated scene, its level varied through the
//! sweep engine, so the levels run in parallel, one thread each, and a rerun reuses them). On an
//! irregular target a level's depth can be the mean over several packings, as the calibration
//! takes it, so that a change between levels can be told from the packings' spread.

pub mod plot;

use std::path::PathBuf;

use crate::analysis::{Convergence, NotConvergent, celik, richardson};
use crate::cases::cracked_plate::{self, Grips, Setup, Study};
use crate::cases::{cantilever, study};
use crate::error::{Error, Result};
use crate::scene::overrides::Override;
use crate::sweep::job::{Base, Job};
use crate::sweep::{Engine, Store};
use crate::table::Table;

/// Which case.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Case {
    /// Cantilever tip amplitude (refines by 3 per level).
    Cantilever,
    /// Cracked plate critical far-field stress, energy criterion (refines by 2).
    CrackedPlate,
    /// Penetration depth at `--v0` (refines by 2: each level halves every element radius).
    Penetration,
}

impl Case {
    /// Name in file names.
    pub fn name(self) -> &'static str {
        match self {
            Case::Cantilever => "cantilever",
            Case::CrackedPlate => "cracked_plate",
            Case::Penetration => "penetration",
        }
    }

    /// The element-size ratio between levels the case is built with.
    pub fn ratio(self) -> f64 {
        match self {
            Case::Cantilever => cantilever::REFINEMENT,
            Case::CrackedPlate => cracked_plate::REFINEMENT,
            Case::Penetration => 2.0,
        }
    }

    /// The quantity's column.
    pub fn quantity(self) -> &'static str {
        match self {
            Case::Cantilever => "tip_amplitude_m",
            Case::CrackedPlate => "peak_stress_pa",
            Case::Penetration => "depth_in",
        }
    }
}

/// One level's result.
#[derive(Debug, Clone, PartialEq)]
pub struct Level {
    /// Refinement level.
    pub level: u32,
    /// Elements.
    pub elements: usize,
    /// Element radius, m.
    pub h_m: f64,
    /// Steps.
    pub steps: u64,
    /// Time step, s.
    pub dt_s: f64,
    /// Wall time, s (over the level's packings: what its figure cost).
    pub wall_s: f64,
    /// The quantity (over several packings, their mean).
    pub value: f64,
    /// Packings the level's figure is the mean over (1: one run).
    pub packings: usize,
    /// The quantity's sample standard deviation over the packings (none for one).
    pub spread: Option<f64>,
    /// What the run ended as (penetration: scabbed / perforated, and `time_cap` if it never
    /// settled; over packings that end differently, each way with its count), empty otherwise.
    pub outcome: String,
}

/// How the three finest levels converge.
#[derive(Debug, Clone, PartialEq)]
pub enum Class {
    /// Monotone: an order, an extrapolate, a GCI (eq 4.1 and Celik's form).
    Monotone {
        /// Eq 4.1 with the case's constant ratio.
        eq41: Convergence,
        /// Celik et al. 2008 from the element sizes.
        celik: Convergence,
    },
    /// No order: why (oscillatory, divergent, indeterminate).
    None(NotConvergent),
    /// Fewer than three levels.
    TooFew,
    /// The levels' runs end in different outcomes (one perforates, another rebounds): their
    /// figures are of different events, and an order read off them would be a number where
    /// there is none.
    OutcomeChanges(String),
}

impl Class {
    /// Word for the table.
    pub fn word(&self) -> &'static str {
        match self {
            Class::Monotone { .. } => "monotone",
            Class::None(NotConvergent::Oscillatory { .. }) => "oscillatory",
            Class::None(NotConvergent::Divergent { .. }) => "divergent",
            Class::None(_) => "indeterminate",
            Class::TooFew => "too few levels",
            Class::OutcomeChanges(_) => "outcome changes with level",
        }
    }
}

/// A finished study.
#[derive(Debug, Clone)]
pub struct Report {
    /// The case.
    pub case: Case,
    /// Levels, coarse to fine.
    pub levels: Vec<Level>,
    /// The class of the three finest.
    pub class: Class,
}

/// Classify the three finest levels.
pub fn classify(levels: &[Level], ratio: f64) -> Class {
    let n = levels.len();
    if n < 3 {
        return Class::TooFew;
    }
    let l = &levels[n - 3..];
    let outcomes: Vec<&str> = l.iter().map(|x| x.outcome.as_str()).collect();
    if outcomes.iter().any(|o| *o != outcomes[0]) {
        let list: Vec<String> = l.iter().map(|x| format!("level {}: {}", x.level, x.outcome)).collect();
        return Class::OutcomeChanges(list.join("; "));
    }
    let phi = [l[0].value, l[1].value, l[2].value];
    match (richardson(phi, ratio), celik(phi, [l[0].h_m, l[1].h_m, l[2].h_m])) {
        (Ok(eq41), Ok(c)) => Class::Monotone { eq41, celik: c },
        (Err(e), _) | (_, Err(e)) => Class::None(e),
    }
}

/// Arguments of a study.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The case.
    pub case: Case,
    /// Number of levels (from level 0).
    pub mesh: u32,
    /// Ratio asked for (must be the case's).
    pub ratio: f64,
    /// Penetration: the scene and the velocity, ft/s.
    pub scene: PathBuf,
    /// Impact velocity, ft/s.
    pub v0_fps: f64,
    /// Penetration: packings per level (target seeds from the scene's on; 1: the scene's own).
    pub packings: u32,
    /// Output folder.
    pub out: PathBuf,
    /// Threads (penetration levels in parallel).
    pub threads: usize,
    /// No progress display.
    pub quiet: bool,
    /// What to do with the penetration runs already in the folder.
    pub reuse: crate::sweep::Reuse,
}

/// Run the study; writes `<case>.csv`, `<case>_summary.csv` and `<case>_speed.png` under `out`.
pub fn run(plan: &Plan) -> Result<Report> {
    if plan.mesh < 2 {
        return Err(Error::input("--mesh", format!("needs at least 2 levels (3 for an observed order), got {}", plan.mesh)));
    }
    if plan.mesh > 4 {
        return Err(Error::input("--mesh", format!("at most 4 levels here (the fourth penetration level has 870 000 elements), got {}", plan.mesh)));
    }
    if plan.packings != 1 && plan.case != Case::Penetration {
        return Err(Error::input("--packings", format!("only the penetration case has packings; the {} case has one mesh per level", plan.case.name())));
    }
    if (plan.ratio - plan.case.ratio()).abs() > 1e-12 {
        return Err(Error::input(
            "--ratio",
            format!("the {} case refines by {} per level (its meshes are built so); got {}", plan.case.name(), plan.case.ratio(), plan.ratio),
        ));
    }
    let levels = match plan.case {
        Case::Cantilever => (0..plan.mesh)
            .map(|l| {
                let lv = study::timed(l, || {
                    let (a, r) = cantilever::run(l)?;
                    Ok((cantilever::columns(l) * cantilever::rows(l), a, r))
                })?;
                Ok(Level { level: l, elements: lv.elements, h_m: cantilever::radius_m(l), steps: lv.steps, dt_s: lv.dt_s, wall_s: lv.wall_s, value: lv.value, packings: 1, spread: None, outcome: String::new() })
            })
            .collect::<Result<Vec<_>>>()?,
        Case::CrackedPlate => {
            let setup = Setup::with_grips(Grips::Rollers);
            (0..plan.mesh)
                .map(|l| {
                    let lv = study::timed(l, || {
                        let (p, r) = cracked_plate::run(Study::EnergyClosePacked, l, true, &setup)?;
                        Ok((p.elements, p.stress_pa, r))
                    })?;
                    let h_m = Study::EnergyClosePacked.radius_m(l);
                    Ok(Level { level: l, elements: lv.elements, h_m, steps: lv.steps, dt_s: lv.dt_s, wall_s: lv.wall_s, value: lv.value, packings: 1, spread: None, outcome: String::new() })
                })
                .collect::<Result<Vec<_>>>()?
        }
        Case::Penetration => penetration(plan)?,
    };
    let class = classify(&levels, plan.ratio);
    let report = Report { case: plan.case, levels, class };
    let (levels_table, summary) = tables(&report);
    levels_table.write_csv(&plan.out.join(format!("{}.csv", plan.case.name())))?;
    summary.write_csv(&plan.out.join(format!("{}_summary.csv", plan.case.name())))?;
    plot::draw(&plan.out.join(format!("{}_speed.png", plan.case.name())), &report)?;
    Ok(report)
}

fn penetration(plan: &Plan) -> Result<Vec<Level>> {
    let base = Base::load(&plan.scene)?;
    let crate::scene_file::SceneFile::Penetration(scene) = &base.scene else {
        return Err(Error::input(plan.scene.display().to_string(), "converge --case penetration needs a penetration scene"));
    };
    let r0_m = {
        let mut s = scene.clone();
        s.penetration.level = 0;
        s.concrete_radius_m()
    };
    // One packing keeps the runs' names of a study without packings (its folder stays usable).
    let packings = crate::ballistic::packing_overrides(&base, plan.packings)?;
    let levels: Vec<Vec<Job>> = (0..plan.mesh)
        .map(|l| {
            packings
                .iter()
                .map(|seed| Job {
                    overrides: [
                        Override { field: "penetration.level".into(), value: toml::Value::Integer(l as i64) },
                        Override { field: crate::ballistic::V0_FIELD.into(), value: toml::Value::Float(plan.v0_fps) },
                    ]
                    .into_iter()
                    .chain(seed.iter().cloned())
                    .collect(),
                    purpose: "converge".into(),
                })
                .collect()
        })
        .collect();
    let dir = plan.out.join("penetration_runs");
    let mut store = Store::open(&dir, &base, plan.reuse)?;
    let engine = Engine::new(&base, plan.threads, plan.quiet);
    engine.run(&levels.concat(), &mut store)?.check()?;
    levels
        .iter()
        .enumerate()
        .map(|(l, jobs)| {
            let runs = jobs
                .iter()
                .map(|j| {
                    let f = |c: &str| -> Result<f64> {
                        store.get(j, c).and_then(|v| v.parse().ok()).ok_or_else(|| Error::input(dir.display().to_string(), format!("run {} has no {c}", j.id())))
                    };
                    Ok(PackingRun {
                        elements: f("elements")?,
                        steps: f("steps")?,
                        dt_s: f("dt_s")?,
                        wall_s: f("wall_s")?,
                        depth_in: f("depth_in")?,
                        // Embedded and rebounded are one outcome (held); a run cut at its time
                        // cap never settled, which is another.
                        outcome: format!(
                            "scabbed={} perforated={}{}",
                            store.get(j, "scabbed").unwrap_or(""),
                            store.get(j, "perforated").unwrap_or(""),
                            if store.get(j, "end_reason") == Some("time_cap") { " time_cap" } else { "" }
                        ),
                    })
                })
                .collect::<Result<Vec<_>>>()?;
            Ok(over_packings(l as u32, r0_m * 0.5f64.powi(l as i32), &runs))
        })
        .collect()
}

/// One packing's run at a level: what its summary row says.
#[derive(Debug, Clone, PartialEq)]
pub struct PackingRun {
    /// Elements.
    pub elements: f64,
    /// Steps.
    pub steps: f64,
    /// Time step, s.
    pub dt_s: f64,
    /// Wall time, s.
    pub wall_s: f64,
    /// Peak depth, in.
    pub depth_in: f64,
    /// How it ended (`penetration` above).
    pub outcome: String,
}

/// A level's figures over its packings' runs: the mean depth and its sample standard
/// deviation, the mean size and step, the summed cost, and the outcomes with their counts
/// where the packings end differently. `h_m` is the level's element radius, m.
pub fn over_packings(level: u32, h_m: f64, runs: &[PackingRun]) -> Level {
    let n = runs.len() as f64;
    let mean = |f: &dyn Fn(&PackingRun) -> f64| runs.iter().map(f).sum::<f64>() / n;
    let value = mean(&|r| r.depth_in);
    let spread = (runs.len() > 1).then(|| (runs.iter().map(|r| (r.depth_in - value).powi(2)).sum::<f64>() / (n - 1.0)).sqrt());
    let mut ways: Vec<(&str, usize)> = Vec::new();
    for r in runs {
        match ways.iter_mut().find(|w| w.0 == r.outcome) {
            Some(w) => w.1 += 1,
            None => ways.push((&r.outcome, 1)),
        }
    }
    let outcome = if ways.len() == 1 { ways[0].0.to_string() } else { ways.iter().map(|(o, k)| format!("{o} ×{k}")).collect::<Vec<_>>().join("; ") };
    Level {
        level,
        elements: mean(&|r| r.elements).round() as usize,
        h_m,
        steps: mean(&|r| r.steps).round() as u64,
        dt_s: mean(&|r| r.dt_s),
        wall_s: runs.iter().map(|r| r.wall_s).sum(),
        value,
        packings: runs.len(),
        spread,
        outcome,
    }
}

/// The reference the errors are taken against: the extrapolate where the levels converge
/// monotonically, otherwise the finest level (and the table says so).
pub fn reference(r: &Report) -> (f64, &'static str) {
    match &r.class {
        Class::Monotone { eq41, .. } => (eq41.extrapolate, "richardson extrapolate"),
        _ => (r.levels.last().map_or(f64::NAN, |l| l.value), "finest level (no extrapolate: not monotone)"),
    }
}

/// The levels table (with each level's error against the reference) and the summary.
pub fn tables(r: &Report) -> (Table, Table) {
    let (reference, against) = reference(r);
    let q = r.case.quantity();
    let sd = format!("{q}_sd");
    let header: Vec<String> =
        ["level", "elements", "h_m", "steps", "dt_s", "element_steps", "wall_s", q, "error_rel", "error_against", "outcome", "packings", sd.as_str()].iter().map(|s| s.to_string()).collect();
    let rows = r
        .levels
        .iter()
        .map(|l| {
            vec![
                l.level.to_string(),
                l.elements.to_string(),
                format!("{:.6e}", l.h_m),
                l.steps.to_string(),
                format!("{:.6e}", l.dt_s),
                format!("{:.4e}", l.elements as f64 * l.steps as f64),
                format!("{:.3}", l.wall_s),
                format!("{:.9e}", l.value),
                format!("{:.4e}", (l.value - reference) / reference),
                against.to_string(),
                l.outcome.clone(),
                l.packings.to_string(),
                l.spread.map_or(String::new(), |s| format!("{s:.4e}")),
            ]
        })
        .collect();
    let levels = Table { header, rows };
    let sh: Vec<String> = ["case", "quantity", "ratio", "class", "R", "order_eq41", "order_celik", "extrapolate", "gci_fine_pct", "note"].iter().map(|s| s.to_string()).collect();
    let blank = String::new;
    let row = match &r.class {
        Class::Monotone { eq41, celik } => vec![
            r.case.name().into(),
            q.into(),
            r.case.ratio().to_string(),
            r.class.word().into(),
            format!("{:.6}", eq41.ratio),
            format!("{:.4}", eq41.order),
            format!("{:.4}", celik.order),
            format!("{:.9e}", eq41.extrapolate),
            format!("{:.4}", 100.0 * eq41.gci_fine),
            "three finest levels".into(),
        ],
        Class::None(why) => vec![r.case.name().into(), q.into(), r.case.ratio().to_string(), r.class.word().into(), blank(), blank(), blank(), blank(), blank(), why.to_string()],
        Class::OutcomeChanges(why) => vec![r.case.name().into(), q.into(), r.case.ratio().to_string(), r.class.word().into(), blank(), blank(), blank(), blank(), blank(), why.clone()],
        Class::TooFew => vec![r.case.name().into(), q.into(), r.case.ratio().to_string(), r.class.word().into(), blank(), blank(), blank(), blank(), blank(), "three levels give an order".into()],
    };
    (levels, Table { header: sh, rows: vec![row] })
}


#[cfg(test)]
mod tests {
    use super::*;

    fn levels(values: [f64; 3], outcomes: [&str; 3]) -> Vec<Level> {
        (0..3)
            .map(|k| Level {
                level: k as u32,
                elements: 100 << (2 * k),
                h_m: 0.5f64.powi(k as i32),
                steps: 10 << k,
                dt_s: 1e-6,
                wall_s: 1.0 * 8f64.powi(k as i32),
                value: values[k],
                packings: 1,
                spread: None,
                outcome: outcomes[k].to_string(),
            })
            .collect()
    }

    #[test]
    fn a_power_law_is_monotone_with_its_order_and_limit() {
        let v = [0, 1, 2].map(|k| 3.0 + 0.8 * 0.5f64.powi(2 * k));
        match classify(&levels(v, ["", "", ""]), 2.0) {
            Class::Monotone { eq41, celik } => {
                assert!((eq41.order - 2.0).abs() < 1e-12 && (celik.order - 2.0).abs() < 1e-9);
                assert!((eq41.extrapolate - 3.0).abs() < 1e-12);
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn a_level_over_packings_is_their_mean_with_its_sample_spread_and_each_outcome_counted() {
        let run = |depth_in: f64, wall_s: f64, outcome: &str| PackingRun { elements: 100.0, steps: 10.0, dt_s: 1e-6, wall_s, depth_in, outcome: outcome.into() };
        let l = over_packings(2, 0.5, &[run(4.0, 1.0, "held"), run(5.0, 2.0, "held"), run(6.0, 4.0, "scabbed")]);
        assert_eq!((l.value, l.packings, l.wall_s), (5.0, 3, 7.0), "mean depth, count, the level's summed cost");
        assert!((l.spread.unwrap() - 1.0).abs() < 1e-15, "sample standard deviation (n − 1)");
        assert_eq!(l.outcome, "held ×2; scabbed ×1");
        let one = over_packings(0, 1.0, &[run(4.5, 3.0, "held")]);
        assert_eq!((one.value, one.spread, one.outcome.as_str()), (4.5, None, "held"), "one packing: the run itself");
    }

    #[test]
    fn no_order_is_read_off_levels_that_end_differently_or_oscillate() {
        let v = [37.4, 4.94, 3.22];
        assert!(matches!(classify(&levels(v, ["perforated", "rebounded", "rebounded"]), 2.0), Class::OutcomeChanges(_)));
        assert!(matches!(classify(&levels([1.0, 1.2, 1.1], ["", "", ""]), 2.0), Class::None(NotConvergent::Oscillatory { .. })));
        assert_eq!(classify(&levels(v, ["", "", ""])[..2], 2.0), Class::TooFew);
        let r = Report { case: Case::Penetration, levels: levels(v, ["a", "b", "b"]), class: Class::OutcomeChanges("x".into()) };
        let (t, s) = tables(&r);
        assert_eq!(t.get(2, "error_against"), Some("finest level (no extrapolate: not monotone)"));
        assert_eq!(s.get(0, "order_eq41"), Some(""), "never a number where there is none");
    }
}
