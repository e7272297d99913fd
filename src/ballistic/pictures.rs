//! The report's pictures of a ballistic sweep: the first packing's slowest run that scabbed and
//! slowest that perforated, made again (runs are deterministic) and drawn at the moment of the
//! outcome, into `<out>/pictures/` (`first_scabbing_850fps_seed1_12.3ms.png`).

use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::penetration::{Finished, Hooks, PenetrationScene, Row};
use crate::picture::Moment;
use crate::scene::overrides::Override;
use crate::scene_file::SceneFile;
use crate::simulation::Simulation;
use crate::table::Table;

/// Simulated time between looks for the moment, s.
const LOOK_EVERY_S: f64 = 1e-4;

/// Draw both pictures for the runs of `runs` (the sweep's table) of `scene`; returns the files.
pub fn draw(scene: &Path, runs: &Table, out: &Path) -> Result<Vec<PathBuf>> {
    let dir = out.join("pictures");
    std::fs::create_dir_all(&dir).map_err(|e| Error::io(&dir, e))?;
    // Pictures of an earlier sweep in this folder would show other runs.
    for old in std::fs::read_dir(&dir).map_err(|e| Error::io(&dir, e))?.filter_map(|e| e.ok()).map(|e| e.path()) {
        if old.file_name().and_then(|n| n.to_str()).is_some_and(|n| n.starts_with("first_") && n.ends_with(".png")) {
            std::fs::remove_file(&old).map_err(|e| Error::io(&old, e))?;
        }
    }
    let cell = |r: usize, c: &str| runs.get(r, c).unwrap_or("").to_string();
    let seed = |r: usize| cell(r, "run_id").split(';').find_map(|o| o.strip_prefix("target.seed=").map(String::from));
    let first_packing = (0..runs.rows.len()).filter_map(seed).min_by_key(|s| s.parse::<u64>().unwrap_or(u64::MAX));
    let mut drawn = Vec::new();
    for (outcome, time, label) in [("scabbed", "scab_time_s", "first_scabbing"), ("perforated", "perforation_time_s", "first_perforation")] {
        let slowest = (0..runs.rows.len())
            .filter(|&r| seed(r) == first_packing && cell(r, outcome) == "true")
            .min_by(|&a, &b| cell(a, "v0_fps").parse::<f64>().unwrap_or(f64::INFINITY).total_cmp(&cell(b, "v0_fps").parse().unwrap_or(f64::INFINITY)));
        let Some(r) = slowest else { continue };
        let at_s: f64 = cell(r, time).parse().map_err(|_| Error::input("runs.csv", format!("run {} has no {time}", cell(r, "run_id"))))?;
        let overrides = cell(r, "run_id").split(';').filter(|s| !s.is_empty()).map(Override::parse).collect::<Result<Vec<_>>>()?;
        let SceneFile::Penetration(s) = crate::scene_file::load(scene, &overrides)? else {
            return Err(Error::input("--scene", "pictures are drawn of penetration scenes"));
        };
        let v0: f64 = cell(r, "v0_fps").parse().unwrap_or_default();
        let tag = first_packing.as_ref().map(|s| format!("_seed{s}")).unwrap_or_default();
        let path = dir.join(format!("{label}_{v0:.0}fps{tag}_{:.1}ms.png", at_s * 1e3));
        let (moment, again) = match s.penetration.dim {
            3 => picture(&s, &path, at_s, crate::penetration::run3)?,
            _ => picture(&s, &path, at_s, crate::penetration::run)?,
        };
        // The run made again must be the table's: another build's physics would picture
        // another event under this one's name.
        let again_s = match outcome {
            "scabbed" => again.outcome.scab_time_s,
            _ => again.outcome.perforation_time_s,
        };
        if again_s.is_none_or(|t| (t - at_s).abs() > 1e-6 * at_s) {
            let _ = std::fs::remove_file(&path);
            return Err(Error::input(
                "runs.csv",
                format!(
                    "run {} made again gives {time} = {again_s:?}, not the table's {at_s:e} (the table's build is {}, this is {}): make the sweep again",
                    cell(r, "run_id"),
                    cell(r, "build"),
                    crate::provenance::build_id()
                ),
            ));
        }
        if moment.drawn_s().is_some() {
            drawn.push(path);
        }
    }
    Ok(drawn)
}

/// Run `scene` with `run`, drawing it at `at_s` into `path`.
fn picture<M: Simulation>(scene: &PenetrationScene, path: &Path, at_s: f64, run: impl FnOnce(&PenetrationScene, Hooks<'_, M>) -> Result<Finished<M>>) -> Result<(Moment, Row)> {
    let mut moment = Moment::new(path, scene, at_s)?;
    let mut look = |m: &M| moment.frame(m);
    let finished = run(scene, Hooks { each_record: Some(&mut look), record_every_s: LOOK_EVERY_S, ..Default::default() })?;
    Ok((moment, finished.row))
}
