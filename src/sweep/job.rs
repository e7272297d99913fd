//! One run of a sweep: the base scene with a list of overrides, run on the calling thread.

use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::simulation::Threading;
use crate::run::Lend;
use crate::scene::overrides::Override;
use crate::scene_file::{SceneFile, load_text};

/// The scene a sweep varies, read once.
#[derive(Debug, Clone)]
pub struct Base {
    /// Where it came from (messages).
    pub path: PathBuf,
    /// Its text (each run applies its overrides to this text, exactly as `run --set` does).
    pub text: String,
    /// The scene as read, without the sweep's overrides.
    pub scene: SceneFile,
    /// [`super::hash::scene_hash`] of it.
    pub hash: String,
}

impl Base {
    /// Read a scene file.
    pub fn load(path: &Path) -> Result<Base> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        let scene = load_text(&text, path, &[])?;
        let hash = super::hash::scene_hash(&scene);
        Ok(Base { path: path.to_path_buf(), text, scene, hash })
    }

    /// The refinement level of the scene (penetration scenes; empty for a kernel scene).
    pub fn level(&self) -> String {
        match &self.scene {
            SceneFile::Penetration(p) => p.penetration.level.to_string(),
            SceneFile::Kernel(_) | SceneFile::Kernel3(_) | SceneFile::Rockfill(_) => String::new(),
        }
    }
}

/// One run to do.
#[derive(Debug, Clone, PartialEq)]
pub struct Job {
    /// The overrides, in the order given.
    pub overrides: Vec<Override>,
    /// Why the run is made (`grid`, `bisect scabbing`, …): a column of the runs table.
    pub purpose: String,
}

impl Job {
    /// The run's identity: its overrides as `FIELD=VALUE` joined by `;` (`projectile.v0_fps=850`),
    /// numbers in their shortest form (10.0 and 10 are one run), so a grid and a parameter table
    /// name the same run alike.
    pub fn id(&self) -> String {
        let value = |v: &toml::Value| match v {
            toml::Value::Float(f) => format!("{f}"),
            other => other.to_string(),
        };
        self.overrides.iter().map(|o| format!("{}={}", o.field, value(&o.value))).collect::<Vec<_>>().join(";")
    }

    /// Check every override against the base scene without running (a bad field or value is
    /// reported before any run starts).
    pub fn check(&self, base: &Base) -> Result<()> {
        load_text(&base.text, &base.path, &self.overrides).map(|_| ())
    }
}

/// A run's summary row, as (column, text).
pub type Row = Vec<(String, String)>;

/// Run `job` on the calling thread, borrowing `lend`'s cores while they are idle; the row is
/// the run's summary row.
pub fn run_job(base: &Base, job: &Job, lend: Option<&dyn Lend>) -> Result<Row> {
    match load_text(&base.text, &base.path, &job.overrides)? {
        SceneFile::Penetration(scene) => {
            let row = crate::penetration::row(&scene, Threading::Serial, lend)?;
            let cells = crate::table::row::cells(&row).map_err(|e| Error::input("<row>", e))?;
            Ok(cells.into_iter().map(|(k, v)| (k, v.text())).collect())
        }
        SceneFile::Kernel(scene) => kernel_row(scene.build().map_err(|e| e.in_file(&base.path))?, lend),
        SceneFile::Kernel3(scene) => kernel_row(scene.build().map_err(|e| e.in_file(&base.path))?, lend),
        SceneFile::Rockfill(scene) => kernel_row(scene.build().map_err(|e| e.in_file(&base.path))?, lend),
    }
}

/// The summary row of a built kernel scene (either kernel), run to its duration.
fn kernel_row<M: crate::simulation::Simulation + Clone + Sync>(built: crate::simulation::Built<M>, lend: Option<&dyn Lend>) -> Result<Row> {
    let options = crate::run::Options { threading: Threading::Serial, lend, ..Default::default() };
    let t = crate::run::run_with(built, options)?.summary_table();
    Ok(t.header.into_iter().zip(t.rows.into_iter().next().unwrap_or_default()).collect())
}
