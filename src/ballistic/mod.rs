//! `demsweep ballistic`: the scabbing and perforation thresholds of a penetration scene. Every
//! velocity of the range in parallel (the sweep engine), then both thresholds bisected
//! concurrently ([`schedule`]: a free thread makes a run a bisection needs, or else guesses
//! the one it will need next) between the last velocity without and the first with the
//! outcome, to a tolerance; a Lambert–Jonas fit of the residual velocities
//! as a second estimate of the ballistic limit; the empirical formulas' thresholds for the same
//! wall beside them (`thresholds.csv`); a picture.
//!
//! **Packings** (`--packings N`, an irregular target): the grid and both bisections on each of
//! the scene's seed and the N − 1 after it, and per threshold a V50 over every run's binary
//! outcome (`v50`: logistic, Firth-penalised maximum likelihood, 90 % profile-likelihood
//! interval), as ballistic testing reports a limit: one packing is one specimen.
//!
//! Resumable: the runs table is the state. A rerun with the same arguments finds every
//! finished run (grid or bisection: the bisection's velocities follow from the runs, so they
//! are the same again) and ends with the same tables. `--shard i/n` runs every n-th grid
//! velocity only and leaves the bisection to `merge --bisect`.

pub mod bracket;
pub mod fit;
pub mod pictures;
pub mod plot;
pub mod schedule;
pub mod thresholds;
pub mod v50;

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::scene_file::SceneFile;
use crate::scene::overrides::Override;
use crate::provenance::build_id;
use crate::sweep::job::{Base, Job};
use crate::sweep::{Engine, Store};
use crate::table::{Table, write_atomic};
use bracket::{Bracket, Finding, Point};

/// The field a ballistic sweep varies.
pub const V0_FIELD: &str = "projectile.v0_fps";

/// What a ballistic sweep is: written as `sweep.toml` in its folder, so that shards can be
/// checked against each other and merged.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Manifest {
    /// The scene file.
    pub scene: PathBuf,
    /// Its hash.
    pub scene_hash: String,
    /// Lowest velocity, ft/s.
    pub v0_min_fps: f64,
    /// Highest velocity, ft/s.
    pub v0_max_fps: f64,
    /// Step, ft/s.
    pub step_fps: f64,
    /// Bisection tolerance, ft/s.
    pub tol_fps: f64,
    /// `i/n`, or empty for the whole sweep.
    pub shard: String,
    /// Packings swept (1: the scene's own).
    #[serde(default = "one_packing")]
    pub packings: u32,
}

fn one_packing() -> u32 {
    1
}

/// A shard `i/n`: the grid velocities k with k mod n = i − 1.
pub fn parse_shard(text: &str) -> Result<(usize, usize)> {
    let bad = || Error::input("--shard", format!("`{text}` is not i/n with 1 ≤ i ≤ n (e.g. 1/2, 2/2; Slurm: $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT)"));
    let (i, n) = text.split_once('/').ok_or_else(bad)?;
    let (i, n): (usize, usize) = (i.trim().parse().map_err(|_| bad())?, n.trim().parse().map_err(|_| bad())?);
    if i == 0 || n == 0 || i > n {
        return Err(bad());
    }
    Ok((i, n))
}

/// How to run a ballistic sweep.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The penetration scene.
    pub scene: PathBuf,
    /// Velocities, ft/s (inclusive), and the step.
    pub v0_min_fps: f64,
    /// Highest velocity, ft/s.
    pub v0_max_fps: f64,
    /// Step, ft/s.
    pub step_fps: f64,
    /// Bisection tolerance, ft/s.
    pub tol_fps: f64,
    /// Output folder.
    pub out: PathBuf,
    /// Threads (0: all cores).
    pub threads: usize,
    /// No progress display.
    pub quiet: bool,
    /// What to do with the runs already in the folder.
    pub reuse: crate::sweep::Reuse,
    /// Run one shard of the grid only (no bisection).
    pub shard: Option<(usize, usize)>,
    /// Packings (target seeds from the scene's on) to sweep; 1: the scene's own.
    pub packings: u32,
}

/// The default number of packings for a scene file: 5 on an irregular target, 1 on a regular
/// lattice (it has one).
pub fn default_packings(scene: &Path) -> Result<u32> {
    Ok(match &load_base(scene)?.scene {
        SceneFile::Penetration(p) if p.target.arrangement == crate::material::Arrangement::Irregular => 5,
        _ => 1,
    })
}

/// The field that picks a packing.
pub const SEED_FIELD: &str = "target.seed";

/// Each packing's overrides: none for one packing (the scene's own), else `target.seed` from
/// the scene's seed on. More than one packing needs an irregular target.
pub fn packing_overrides(base: &Base, packings: u32) -> Result<Vec<Vec<Override>>> {
    let SceneFile::Penetration(scene) = &base.scene else { unreachable!("checked at load") };
    if packings == 0 {
        return Err(Error::input("--packings", "must be ≥ 1"));
    }
    if packings == 1 {
        return Ok(vec![Vec::new()]);
    }
    if scene.target.arrangement != crate::material::Arrangement::Irregular {
        return Err(Error::input("--packings", format!("{packings} packings need target.arrangement = \"irregular\": a regular lattice has one packing")));
    }
    let first = scene.target.seed;
    Ok((0..packings as u64)
        .map(|k| vec![Override { field: SEED_FIELD.into(), value: toml::Value::Integer((first + k) as i64) }])
        .collect())
}

/// A velocity as the override value (an integer where it is one, so run ids read `850`).
fn value(v: f64) -> toml::Value {
    if v.fract() == 0.0 && v.abs() < 1e15 { toml::Value::Integer(v as i64) } else { toml::Value::Float(v) }
}

/// The run at velocity `v`.
pub fn job(v_fps: f64, purpose: &str) -> Job {
    Job { overrides: vec![Override { field: V0_FIELD.into(), value: value(v_fps) }], purpose: purpose.into() }
}

/// The result of a sweep.
#[derive(Debug, Clone)]
pub struct Report {
    /// Scabbing threshold.
    pub scabbing: Finding,
    /// Perforation threshold.
    pub perforation: Finding,
    /// Lambert–Jonas fit.
    pub lambert_jonas: Option<fit::Fit>,
    /// Recht–Ipson fit.
    pub recht_ipson: Option<fit::Fit>,
    /// The thresholds table (written as `thresholds.csv`).
    pub thresholds: Table,
    /// Runs made now / found done.
    pub ran: usize,
    /// Runs found done.
    pub skipped: usize,
    /// With several packings: each one's seed and bisected thresholds.
    pub packings: Vec<Packing>,
    /// With several packings: the V50 of scabbing and of perforation.
    pub v50: Option<(Option<v50::V50>, Option<v50::V50>)>,
    /// The runs that failed (rows with status failed): (run id, message). The thresholds are
    /// drawn without them; a bisection that needed one stopped at the bracket it had.
    pub failed: Vec<(String, String)>,
}

/// One packing's thresholds.
#[derive(Debug, Clone)]
pub struct Packing {
    /// Its seed.
    pub seed: i64,
    /// Scabbing.
    pub scabbing: Finding,
    /// Perforation.
    pub perforation: Finding,
}

impl Report {
    fn empty(ran: usize, skipped: usize) -> Report {
        let empty = Finding { bracket: Bracket::Empty, exceptions_fps: Vec::new() };
        Report {
            scabbing: empty.clone(),
            perforation: empty,
            lambert_jonas: None,
            recht_ipson: None,
            thresholds: Table::default(),
            ran,
            skipped,
            packings: Vec::new(),
            v50: None,
            failed: Vec::new(),
        }
    }
}

fn load_base(scene: &Path) -> Result<Base> {
    let base = Base::load(scene)?;
    if !matches!(base.scene, SceneFile::Penetration(_)) {
        return Err(Error::input(scene.display().to_string(), "ballistic needs a penetration scene (a file with [penetration])"));
    }
    Ok(base)
}

/// The grid velocities of a plan, checked.
pub fn velocities(v_min: f64, v_max: f64, step: f64) -> Result<Vec<f64>> {
    if v_min > v_max {
        return Err(Error::input("--v0", format!("reversed range {v_min}..{v_max}: the start must not exceed the end")));
    }
    crate::sweep::range::steps(v_min, v_max, step, "--step")
}

/// Run the plan.
pub fn run(plan: &Plan) -> Result<Report> {
    if !(plan.tol_fps.is_finite() && plan.tol_fps > 0.0) {
        return Err(Error::input("--tol-fps", format!("must be > 0, got {}", plan.tol_fps)));
    }
    let grid = velocities(plan.v0_min_fps, plan.v0_max_fps, plan.step_fps)?;
    let base = load_base(&plan.scene)?;
    let manifest = Manifest {
        scene: plan.scene.clone(),
        scene_hash: base.hash.clone(),
        v0_min_fps: plan.v0_min_fps,
        v0_max_fps: plan.v0_max_fps,
        step_fps: plan.step_fps,
        tol_fps: plan.tol_fps,
        shard: plan.shard.map_or(String::new(), |(i, n)| format!("{i}/{n}")),
        packings: plan.packings,
    };
    let packings = packing_overrides(&base, plan.packings)?;
    let mut store = Store::open(&plan.out, &base, plan.reuse)?;
    write_atomic(&plan.out.join("sweep.toml"), toml::to_string(&manifest).expect("a manifest serialises").as_bytes())?;
    let engine = Engine::new(&base, plan.threads, plan.quiet);
    let jobs: Vec<Job> = grid_jobs(&grid, &packings)
        .into_iter()
        .enumerate()
        .filter(|(k, _)| plan.shard.is_none_or(|(i, n)| k % n == i - 1))
        .map(|(_, j)| j)
        .collect();
    // A failed grid run is a row with its status: the bisections go on without its outcome.
    let done = engine.run(&jobs, &mut store)?;
    let (mut ran, mut skipped) = (done.ran, done.skipped);
    if plan.shard.is_some() {
        return Ok(Report { failed: store.failures(), ..Report::empty(ran, skipped) });
    }
    let report = bisect_and_report(&engine, &mut store, &grid, &packings, plan.tol_fps, &plan.out)?;
    ran += report.ran;
    skipped += report.skipped;
    Ok(Report { ran, skipped, ..report })
}

/// Every packing's grid runs, packing by packing.
fn grid_jobs(grid: &[f64], packings: &[Vec<Override>]) -> Vec<Job> {
    packings.iter().flat_map(|fixed| grid.iter().map(|&v| schedule::job_with(fixed, v, "grid"))).collect()
}

/// The points of every planned run held by `store`.
fn points(store: &Store, planned: &[Job], column: &str) -> Vec<Point> {
    planned
        .iter()
        .filter_map(|j| {
            let v = store.get(j, "v0_fps")?.parse().ok()?;
            Some(Point { v_fps: v, hit: store.get(j, column)? == "true" })
        })
        .collect()
}

/// Bisect both thresholds of every packing from the grid's runs, fit, and write
/// `thresholds.csv` and the plot.
pub fn bisect_and_report(engine: &Engine<'_>, store: &mut Store, grid: &[f64], packings: &[Vec<Override>], tol_fps: f64, out: &Path) -> Result<Report> {
    let mut planned = grid_jobs(grid, packings);
    if let Some(missing) = planned.iter().find(|j| !store.holds(j)) {
        return Err(Error::input(out.display().to_string(), format!("the grid run {} is missing: run every shard first", missing.id())));
    }
    // Two bisections a packing, all side by side on the engine's threads (`schedule`), each
    // bracket read from its packing's grid and its own runs only, so that its sequence of
    // velocities — and the tables — do not depend on which run finished first.
    let grid_of = |fixed: &Vec<Override>| grid_jobs(grid, std::slice::from_ref(fixed));
    let mut chains = Vec::new();
    for fixed in packings {
        let mine = grid_of(fixed);
        chains.push(schedule::Chain::new("scabbed", "bisect scabbing", points(store, &mine, "scabbed")).with_fixed(fixed.clone()));
        chains.push(schedule::Chain::new("perforated", "bisect perforation", points(store, &mine, "perforated")).with_fixed(fixed.clone()));
    }
    let level = engine.base.level();
    store.threads = engine.thread_count();
    let mut book = Kept { store: &mut *store, level: &level };
    let make = |j: &Job, wanted: &std::sync::atomic::AtomicBool| engine.run_one(j, wanted);
    let (chains, tally) = schedule::bisect(chains, &mut book, tol_fps, engine.thread_count(), engine.quiet, &make)?;
    let (ran, skipped) = (tally.ran, tally.skipped);
    for j in chains.iter().flat_map(|c| &c.runs) {
        if !planned.iter().any(|k| k.id() == j.id()) {
            planned.push(j.clone());
        }
    }
    // Each threshold's bracket from its own bisection; runs of its packing that contradict it
    // (an outcome missing above its first appearance) are reported as non-monotone.
    let mut found = Vec::new();
    for (fixed, pair) in packings.iter().zip(chains.chunks(2)) {
        let mut same_packing: Vec<Job> = grid_of(fixed).into_iter().chain(pair.iter().flat_map(|c| c.runs.iter().cloned())).collect();
        same_packing.sort_by_key(Job::id);
        same_packing.dedup_by_key(|j| j.id());
        let finding = |c: &schedule::Chain| {
            let own: Vec<Job> = grid_of(fixed).into_iter().chain(c.runs.iter().cloned()).collect();
            let mut f = bracket::find(&points(store, &own, &c.column));
            f.exceptions_fps = bracket::find(&points(store, &same_packing, &c.column)).exceptions_fps;
            f
        };
        let seed = fixed.first().and_then(|o| o.value.as_integer()).unwrap_or_default();
        found.push(Packing { seed, scabbing: finding(&pair[0]), perforation: finding(&pair[1]) });
    }
    let several = packings.len() > 1;
    let v50 = several.then(|| {
        let runs = |column: &str| -> Vec<(f64, bool)> { points(store, &planned, column).iter().map(|p| (p.v_fps, p.hit)).collect() };
        (v50::fit(&runs("scabbed"), v50::LEVEL), v50::fit(&runs("perforated"), v50::LEVEL))
    });
    // The perforation bracket over every packing bounds the ballistic limit of the fits.
    let (scabbing, perforation) = if several { (span(found.iter().map(|p| &p.scabbing)), span(found.iter().map(|p| &p.perforation))) } else { (found[0].scabbing.clone(), found[0].perforation.clone()) };
    let (lambert_jonas, recht_ipson) = fits(store, &planned, &perforation);
    let SceneFile::Penetration(scene) = &engine.base.scene else { unreachable!("checked at load") };
    let formulas = thresholds::empirical(scene)?;
    let counts = (points(store, &planned, "scabbed").len(), points(store, &planned, "perforated").len());
    let ours = thresholds::Ours { scabbing: &scabbing, perforation: &perforation, lambert_jonas, recht_ipson, packings: if several { &found } else { &[] }, v50: v50.as_ref() };
    let table = thresholds::table(&ours, &formulas, counts);
    table.write_csv(&out.join("thresholds.csv"))?;
    let runs = store.table();
    plot::draw(&out.join("ballistic.png"), &runs, &ours, &formulas, grid)?;
    let failed = store.failures();
    Ok(Report { scabbing, perforation, lambert_jonas, recht_ipson, thresholds: table, ran, skipped, packings: if several { found } else { Vec::new() }, v50, failed })
}

/// The bracket that holds every packing's: from the lowest velocity without the outcome to the
/// highest first velocity with it, and every packing's exceptions.
fn span<'a>(findings: impl Iterator<Item = &'a Finding>) -> Finding {
    let (mut lo, mut hi, mut ex, mut all_between) = (f64::INFINITY, f64::NEG_INFINITY, Vec::new(), true);
    for f in findings {
        match f.bracket {
            Bracket::Between { lo_fps, hi_fps } => {
                lo = lo.min(lo_fps);
                hi = hi.max(hi_fps);
            }
            _ => all_between = false,
        }
        ex.extend(f.exceptions_fps.iter().copied());
    }
    ex.sort_by(f64::total_cmp);
    ex.dedup();
    let bracket = if all_between && lo <= hi { Bracket::Between { lo_fps: lo, hi_fps: hi } } else { Bracket::Empty };
    Finding { bracket, exceptions_fps: ex }
}

/// The runs table as the bisections' book: a run is kept with the scene's level.
struct Kept<'a> {
    store: &'a mut Store,
    level: &'a str,
}

impl schedule::Book for Kept<'_> {
    fn outcome(&self, job: &Job, column: &str) -> Result<Option<bool>> {
        if !self.store.has(job) {
            return Ok(None);
        }
        let cell = self.store.get(job, column).ok_or_else(|| Error::input(self.store.dir.display().to_string(), format!("run {} has no column `{column}`", job.id())))?;
        Ok(Some(cell == "true"))
    }

    fn keep_failed(&mut self, job: &Job, message: &str) -> Result<()> {
        self.store.insert_failed(job, self.level, message);
        self.store.write()
    }

    fn keep(&mut self, job: &Job, row: Option<&schedule::Row>) -> Result<()> {
        match row {
            Some(r) => self.store.insert(job, self.level, r)?,
            // Written at once: a bisection that finds every run it asks for done makes no
            // insert that would write the table later, and its purpose would be lost on one
            // thread while two threads, interleaving inserts, kept it (regression test
            // `sweep_engine::the_tables_are_the_same_on_one_thread_and_on_two`).
            None if self.store.add_purpose(job) => {}
            None => return Ok(()),
        }
        self.store.write()
    }
}

/// The Lambert–Jonas and Recht–Ipson fits to the perforating runs, V_bl inside the bracket.
fn fits(store: &Store, planned: &[Job], perforation: &Finding) -> (Option<fit::Fit>, Option<fit::Fit>) {
    let Bracket::Between { lo_fps, hi_fps } = perforation.bracket else { return (None, None) };
    let data: Vec<(f64, f64)> = planned
        .iter()
        .filter(|j| store.get(j, "perforated") == Some("true"))
        .filter_map(|j| Some((store.get(j, "v0_fps")?.parse().ok()?, store.get(j, "v_residual_fps")?.parse().ok()?)))
        .filter(|&(v, _)| v >= hi_fps)
        .collect();
    (fit::fit(&data, lo_fps, hi_fps, None), fit::fit(&data, lo_fps, hi_fps, Some(2.0)))
}

/// `demsweep merge DIR… --out OUT [--bisect]`: the shards' runs as one table, checked to be
/// of one scene and one grid; with `bisect`, the bisection and the thresholds.
///
/// The shards must be of one commit, and with `bisect` of this program's commit (whose runs
/// join them), unless `reuse_older`: then of one build, this one's to bisect.
pub fn merge(dirs: &[PathBuf], out: &Path, bisect: bool, reuse_older: bool, threads: usize, quiet: bool) -> Result<Report> {
    if dirs.is_empty() {
        return Err(Error::input("merge", "give the shard folders"));
    }
    let read_manifest = |d: &Path| -> Result<Manifest> {
        let p = d.join("sweep.toml");
        let text = std::fs::read_to_string(&p).map_err(|e| Error::io(&p, e))?;
        crate::scene::parse(&text, &p)
    };
    let first = read_manifest(&dirs[0])?;
    let mut merged: Option<Store> = None;
    for d in dirs {
        let m = read_manifest(d)?;
        let same = |a: &Manifest, b: &Manifest| {
            a.scene_hash == b.scene_hash
                && a.v0_min_fps == b.v0_min_fps
                && a.v0_max_fps == b.v0_max_fps
                && a.step_fps == b.step_fps
                && a.tol_fps == b.tol_fps
                && a.packings == b.packings
        };
        if m.scene_hash != first.scene_hash {
            return Err(Error::input(
                d.display().to_string(),
                format!("is a sweep of another scene (scene_hash {}, not {} of {}): shards of different scenes cannot be merged", m.scene_hash, first.scene_hash, dirs[0].display()),
            ));
        }
        if !same(&m, &first) {
            return Err(Error::input(d.display().to_string(), format!("was swept over another grid, tolerance or set of packings than {}", dirs[0].display())));
        }
        let s = Store::read(d)?;
        match merged.as_mut() {
            None => merged = Some(s),
            Some(all) => all.absorb(s)?,
        }
    }
    let mut store = merged.expect("at least one shard");
    let base = load_base(&first.scene)?;
    if base.hash != first.scene_hash {
        return Err(Error::input(
            first.scene.display().to_string(),
            format!("has changed since the shards ran (scene_hash {} now, {} then): rerun the shards", base.hash, first.scene_hash),
        ));
    }
    store.dir = out.to_path_buf();
    if Store::csv_path(out).exists() {
        store.absorb(Store::read(out)?)?;
    }
    let grid = velocities(first.v0_min_fps, first.v0_max_fps, first.step_fps)?;
    let packings = packing_overrides(&base, first.packings)?;
    let missing: Vec<String> = grid_jobs(&grid, &packings).into_iter().filter(|j| !store.holds(j)).map(|j| j.id()).collect();
    if !missing.is_empty() {
        return Err(Error::input("merge", format!("the shards miss grid runs {}: run every shard first", missing.join(", "))));
    }
    if !reuse_older {
        let commits = store.rows_by_commit();
        if commits.len() > 1 {
            let list: Vec<String> = commits.iter().map(|(c, n)| format!("{n} of commit {c}")).collect();
            return Err(Error::input("merge", format!("the shards were run by several commits of demsweep ({}): rerun them with one, or merge with --reuse-older if their builds agree", list.join(", "))));
        }
        if bisect {
            store.refuse_other_commits(crate::provenance::commit())?;
        }
    }
    store.write()?;
    let manifest = Manifest { shard: String::new(), ..first.clone() };
    write_atomic(&out.join("sweep.toml"), toml::to_string(&manifest).expect("a manifest serialises").as_bytes())?;
    if !bisect {
        return Ok(Report { failed: store.failures(), ..Report::empty(0, store.len()) });
    }
    if store.build != build_id() {
        // The bisection's runs would be this build's, beside grid runs of another.
        return Err(Error::input(
            "merge --bisect",
            format!(
                "the shards were run by another build of demsweep (build {}; this is {}): bisect with that build, or rerun the shards with this one",
                store.build,
                build_id()
            ),
        ));
    }
    let engine = Engine::new(&base, threads, quiet);
    bisect_and_report(&engine, &mut store, &grid, &packings, first.tol_fps, out)
}
