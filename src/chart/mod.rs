//! `demsweep chart`: a design chart — the scabbing and perforation thresholds of a penetration
//! scene at several target thicknesses, drawn as thickness against impact velocity over the
//! empirical formulas' curves (the band of those valid for the scenario shaded), with the
//! intervals. The source could vary only the velocity: building a target of another thickness
//! was slow. Here each thickness is the scene with `target.depth_in` changed, swept by
//! `ballistic` into its own folder (`h<thickness>in/`: a full, resumable ballistic folder with
//! its runs, thresholds and report), and the chart is gathered from those folders' tables.

pub mod plot;

use std::path::{Path, PathBuf};

use crate::ballistic::{self, thresholds};
use crate::error::{Error, Result};
use crate::penetration::scene::PenetrationScene;
use crate::scene::overrides::{Override, apply};
use crate::scene_file::SceneFile;
use crate::sweep::Reuse;
use crate::table::{Table, write_atomic};

/// The field a chart varies: the target's thickness, in.
pub const THICKNESS_FIELD: &str = "target.depth_in";

/// How to draw a chart.
#[derive(Debug, Clone)]
pub struct Plan {
    /// The penetration scene (every thickness is it with `target.depth_in` changed).
    pub scene: PathBuf,
    /// Target thicknesses, in (each > 0, at least two).
    pub thicknesses_in: Vec<f64>,
    /// Lowest velocity of every thickness's grid, ft/s.
    pub v0_min_fps: f64,
    /// Highest velocity, ft/s.
    pub v0_max_fps: f64,
    /// Grid step, ft/s.
    pub step_fps: f64,
    /// Bisection tolerance, ft/s.
    pub tol_fps: f64,
    /// Packings per thickness.
    pub packings: u32,
    /// Output folder.
    pub out: PathBuf,
    /// Threads (0: all cores).
    pub threads: usize,
    /// No progress display.
    pub quiet: bool,
    /// What to do with the runs already in the thickness folders.
    pub reuse: Reuse,
}

/// What a chart is: written as `chart.toml` in its folder (the report reads the scene from it).
#[derive(Debug, Clone, serde::Serialize)]
struct Manifest<'a> {
    scene: &'a Path,
    thicknesses_in: &'a [f64],
    v0_min_fps: f64,
    v0_max_fps: f64,
    step_fps: f64,
    tol_fps: f64,
    packings: u32,
}

/// One threshold at one thickness: the chart's row.
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    /// Target thickness, in.
    pub thickness_in: f64,
    /// `scabbing` or `perforation`.
    pub threshold: String,
    /// Our estimate (V50 over packings, or the bisection's midpoint), ft/s; None where the range
    /// did not bracket it.
    pub v_est_fps: Option<f64>,
    /// Its interval (90 % over packings, or the bracket), ft/s.
    pub v_low_fps: Option<f64>,
    /// Upper end, ft/s.
    pub v_high_fps: Option<f64>,
    /// How it was estimated (`thresholds.csv`'s method).
    pub method: String,
    /// The band of the usable plain-concrete formulas at this thickness, ft/s.
    pub band_min_fps: Option<f64>,
    /// Upper end, ft/s.
    pub band_max_fps: Option<f64>,
    /// What `thresholds.csv` notes (not reached in the range, non-monotone runs).
    pub note: String,
}

/// The folder of one thickness.
pub fn folder(out: &Path, thickness_in: f64) -> PathBuf {
    out.join(format!("h{thickness_in}in"))
}

/// The scene text at `thickness_in`: the base scene with `target.depth_in` set, headed by a
/// comment saying so.
pub fn scene_text(base: &Path, thickness_in: f64) -> Result<String> {
    let text = std::fs::read_to_string(base).map_err(|e| Error::io(base, e))?;
    let mut doc: toml::Table = crate::scene::parse(&text, base)?;
    apply(&mut doc, &Override { field: THICKNESS_FIELD.into(), value: toml::Value::Float(thickness_in) }).map_err(|e| e.in_file(base))?;
    let body = toml::to_string(&doc).expect("a TOML table serialises");
    Ok(format!("# {} with {THICKNESS_FIELD} = {thickness_in} (written by demsweep chart; the comments are in the original)\n{body}", base.display()))
}

/// Check the plan and write every thickness's scene file (each read back and checked as a
/// scene is, so a thickness the scene cannot take is refused before any run); the base scene
/// as read, and the thicknesses' scene files.
fn prepare(plan: &Plan) -> Result<(PenetrationScene, Vec<PathBuf>)> {
    if plan.thicknesses_in.len() < 2 {
        return Err(Error::input("--thickness-in", format!("a chart needs at least two thicknesses, got {}", plan.thicknesses_in.len())));
    }
    let mut seen: Vec<f64> = Vec::new();
    for &t in &plan.thicknesses_in {
        if !(t.is_finite() && t > 0.0) {
            return Err(Error::input("--thickness-in", format!("every thickness must be > 0 in, got {t}")));
        }
        if seen.contains(&t) {
            return Err(Error::input("--thickness-in", format!("{t} in is given twice")));
        }
        seen.push(t);
    }
    let SceneFile::Penetration(base) = crate::scene_file::load(&plan.scene, &[])? else {
        return Err(Error::input(plan.scene.display().to_string(), "a chart needs a penetration scene (a file with [penetration])"));
    };
    let mut scenes = Vec::new();
    for &t in &plan.thicknesses_in {
        let text = scene_text(&plan.scene, t)?;
        let dir = folder(&plan.out, t);
        let path = dir.join("scene.toml");
        crate::scene_file::load_text(&text, &path, &[]).map_err(|e| match e {
            Error::Input { file, field, message } => Error::Input { file, field, message: format!("{message} (at --thickness-in {t})") },
            other => other,
        })?;
        std::fs::create_dir_all(&dir).map_err(|e| Error::io(&dir, e))?;
        // Rewritten only when changed: the scene's hash keys the folder's runs.
        if std::fs::read_to_string(&path).ok().as_deref() != Some(text.as_str()) {
            write_atomic(&path, text.as_bytes())?;
        }
        scenes.push(path);
    }
    Ok((base, scenes))
}

/// What a chart run did.
#[derive(Debug, Clone)]
pub struct Report {
    /// The chart's rows, thickness by thickness.
    pub points: Vec<Point>,
    /// Runs made now, found done.
    pub ran: usize,
    /// Runs found done.
    pub skipped: usize,
    /// Failed runs: (thickness folder, run id, message).
    pub failed: Vec<(PathBuf, String, String)>,
}

/// Sweep every thickness (`ballistic` into its folder), then gather `chart.csv` and draw
/// `chart.png`.
pub fn run(plan: &Plan) -> Result<Report> {
    let (base, scenes) = prepare(plan)?;
    let manifest = Manifest {
        scene: &plan.scene,
        thicknesses_in: &plan.thicknesses_in,
        v0_min_fps: plan.v0_min_fps,
        v0_max_fps: plan.v0_max_fps,
        step_fps: plan.step_fps,
        tol_fps: plan.tol_fps,
        packings: plan.packings,
    };
    write_atomic(&plan.out.join("chart.toml"), toml::to_string(&manifest).expect("a manifest serialises").as_bytes())?;
    let (mut ran, mut skipped, mut failed) = (0, 0, Vec::new());
    for (&t, scene) in plan.thicknesses_in.iter().zip(&scenes) {
        let dir = folder(&plan.out, t);
        if !plan.quiet {
            eprintln!("== thickness {t} in: {}", dir.display());
        }
        let r = ballistic::run(&ballistic::Plan {
            scene: scene.clone(),
            v0_min_fps: plan.v0_min_fps,
            v0_max_fps: plan.v0_max_fps,
            step_fps: plan.step_fps,
            tol_fps: plan.tol_fps,
            out: dir.clone(),
            threads: plan.threads,
            quiet: plan.quiet,
            reuse: plan.reuse,
            shard: None,
            packings: plan.packings,
        })?;
        ran += r.ran;
        skipped += r.skipped;
        failed.extend(r.failed.into_iter().map(|(id, m)| (dir.clone(), id, m)));
    }
    let points = gather(&plan.out, &plan.thicknesses_in)?;
    table(&points).write_csv(&plan.out.join("chart.csv"))?;
    let (m, target) = thresholds::empirical_inputs(&base)?;
    plot::draw(&plan.out.join("chart.png"), &points, &m, &target, (plan.v0_min_fps, plan.v0_max_fps))?;
    Ok(Report { points, ran, skipped, failed })
}

/// The chart's rows from each thickness folder's `thresholds.csv`.
pub fn gather(out: &Path, thicknesses_in: &[f64]) -> Result<Vec<Point>> {
    let mut points = Vec::new();
    for &t in thicknesses_in {
        let path = folder(out, t).join("thresholds.csv");
        let table = Table::read_csv(&path)?;
        for threshold in ["scabbing", "perforation"] {
            let r = thresholds::best_row(&table, threshold)
                .ok_or_else(|| Error::input(path.display().to_string(), format!("has no {threshold} estimate (neither a V50 nor a bisection row)")))?;
            let num = |c: &str| table.get(r, c).and_then(|x| x.parse::<f64>().ok());
            points.push(Point {
                thickness_in: t,
                threshold: threshold.to_string(),
                v_est_fps: num("v_est_fps"),
                v_low_fps: num("v_low_fps"),
                v_high_fps: num("v_high_fps"),
                method: table.get(r, "method").unwrap_or("").to_string(),
                band_min_fps: num("band_min_fps"),
                band_max_fps: num("band_max_fps"),
                note: table.get(r, "note").unwrap_or("").to_string(),
            });
        }
    }
    Ok(points)
}

/// `chart.csv`: one row per thickness and threshold.
pub fn table(points: &[Point]) -> Table {
    let f = |x: Option<f64>| x.map_or(String::new(), |v| format!("{v:.9e}"));
    Table {
        header: ["thickness_in", "threshold", "v_est_fps", "v_low_fps", "v_high_fps", "method", "band_min_fps", "band_max_fps", "note"].iter().map(|s| s.to_string()).collect(),
        rows: points
            .iter()
            .map(|p| vec![format!("{:.9e}", p.thickness_in), p.threshold.clone(), f(p.v_est_fps), f(p.v_low_fps), f(p.v_high_fps), p.method.clone(), f(p.band_min_fps), f(p.band_max_fps), p.note.clone()])
            .collect(),
    }
}
