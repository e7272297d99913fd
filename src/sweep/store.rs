//! The runs table of a sweep folder (`runs.csv`, and `runs.parquet` beside it): the finished
//! and failed runs of one scene, one row each, in a fixed order (by the runs' inputs), rewritten
//! whole and atomically after every run, so that a sweep killed at any moment loses at most the
//! runs in flight, and a rerun skips what is done.
//!
//! Each row keeps the [`build_id`] of the program that made it, and only this build's rows are
//! reused: the rows of another build (an older or newer demsweep, whose physics may differ) are
//! set aside whole in `runs-build-<id>.csv` beside the table, and their runs made again.
//!
//! And each row names the `commit` its program was built from: a folder holding rows of another
//! commit is refused unless the user says what to do with them ([`Reuse`]): make everything
//! again (`--fresh`), or keep those of this same build (`--reuse-older`; a commit that changed no
//! physics leaves the build unchanged). A table never mixes commits without being told to.
//!
//! A run that failed (a NaN, an unstable step, an impossible material) is a row too, with
//! `status = failed`, its message, and its summary cells empty: the table records what was
//! tried. It is not a finished run: a rerun makes it again, and its row is replaced.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use crate::provenance::build_id;
use super::job::{Base, Job};
use crate::error::{Error, Result};
use crate::table::Table;

/// The columns every row starts with, ahead of the run's own summary row: what the run is
/// (`run_id`, `purpose`, `level`, the packing `seed`), and what made it (`scene_hash`, `build`;
/// the engine's `threads`, the program's `version` and the `commit` it was built from, for the
/// record: a row is reused by its build, whatever its commit or thread count), and how it ended:
/// `status` (`ok`, or `failed` with the error in `message`).
pub const KEY_COLUMNS: [&str; 11] = ["run_id", "purpose", "scene_hash", "build", "level", "seed", "threads", "version", "commit", "status", "message"];

/// Index of `status` in [`KEY_COLUMNS`].
const STATUS: usize = 9;
/// Index of `message` in [`KEY_COLUMNS`].
const MESSAGE: usize = 10;
/// `status` of a run that ended with its outcome.
pub const OK: &str = "ok";
/// `status` of a run that failed.
pub const FAILED: &str = "failed";

/// Index of `level` in [`KEY_COLUMNS`].
const LEVEL: usize = 4;

/// Rows of a table written by a build without the `build` column.
const NO_BUILD: &str = "unknown";

/// What a sweep does with the rows its folder already holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Reuse {
    /// Keep the rows this commit's build made (a resumed sweep); refuse a folder that holds
    /// rows of another commit.
    SameCommit,
    /// Also keep rows another commit made with this same build (`--reuse-older`).
    SameBuild,
    /// Remove the folder's old tables first (`--fresh`).
    Nothing,
}

/// Rows of a table written before the `commit` column.
const NO_COMMIT: &str = "unknown";

/// The order of rows: each input value of the run id, numerically where it is a number.
fn order_key(run_id: &str) -> Vec<(f64, String)> {
    run_id
        .split(';')
        .map(|kv| {
            let v = kv.split_once('=').map_or(kv, |p| p.1);
            (v.parse::<f64>().unwrap_or(f64::NAN), v.to_string())
        })
        .collect()
}

fn compare(a: &str, b: &str) -> std::cmp::Ordering {
    let (ka, kb) = (order_key(a), order_key(b));
    for (x, y) in ka.iter().zip(&kb) {
        let o = match (x.0.is_nan(), y.0.is_nan()) {
            (false, false) => x.0.total_cmp(&y.0),
            _ => x.1.cmp(&y.1),
        };
        if o.is_ne() {
            return o;
        }
    }
    ka.len().cmp(&kb.len()).then_with(|| a.cmp(b))
}

/// The finished runs of a sweep folder.
#[derive(Debug, Clone)]
pub struct Store {
    /// The folder.
    pub dir: PathBuf,
    /// The scene hash every row must carry.
    pub hash: String,
    /// The build every row must carry: this program's for a store that runs, the rows' own for a
    /// shard read back.
    pub build: String,
    /// Rows of other builds found on opening, set aside: (build, rows, the file they went to).
    pub set_aside: Vec<(String, usize, PathBuf)>,
    /// Column names (the key columns, then the summary row's).
    pub header: Vec<String>,
    /// Rows by run id.
    rows: BTreeMap<String, Vec<String>>,
    /// Write `runs.parquet` beside the CSV with every update.
    pub parquet: bool,
    /// The scene's own packing seed (`target.seed`; empty for a scene without a random packing),
    /// for runs that do not set it.
    pub seed: String,
    /// Threads of the engine making the runs (its `--threads`, resolved).
    pub threads: usize,
}

impl Store {
    /// `DIR/runs.csv`.
    pub fn csv_path(dir: &Path) -> PathBuf {
        dir.join("runs.csv")
    }

    /// Open the runs of `dir` for `base`: the rows already there are kept and their runs
    /// skipped if this build made them; rows of other builds are set aside (`set_aside`). Rows of
    /// another scene are never mixed in: that is an error that says how to start afresh, unless
    /// [`Reuse::Nothing`], which removes the folder's old tables first. Rows of another commit are
    /// an error too, unless [`Reuse::SameBuild`].
    pub fn open(dir: &Path, base: &Base, reuse: Reuse) -> Result<Store> {
        if reuse == Reuse::Nothing {
            for name in ["runs.csv", "runs.parquet", "thresholds.csv"] {
                let p = dir.join(name);
                if p.exists() {
                    std::fs::remove_file(&p).map_err(|e| Error::io(&p, e))?;
                }
            }
        }
        let mut store = Self::open_as(dir, &base.hash, &base.path)?;
        // A regular lattice has no packing to seed.
        if let crate::scene_file::SceneFile::Penetration(p) = &base.scene
            && (p.penetration.dim == 3 || p.target.arrangement == crate::material::Arrangement::Irregular)
        {
            store.seed = p.target.seed.to_string();
        }
        if reuse == Reuse::SameCommit {
            store.refuse_other_commits(crate::provenance::commit())?;
        }
        let others: Vec<String> = store.rows_by_build().into_keys().filter(|b| b != build_id()).collect();
        for b in others {
            let rows: Vec<Vec<String>> = store.rows.values().filter(|r| store_build(&store.header, r) == b).cloned().collect();
            let path = unused(dir, &format!("runs-build-{b}"));
            Table { header: store.header.clone(), rows: rows.clone() }.write_csv(&path)?;
            store.rows.retain(|_, r| store_build(&store.header, r) != b);
            store.set_aside.push((b, rows.len(), path));
        }
        if let Some((b, _, _)) = store.set_aside.first() {
            // The thresholds were drawn from the rows set aside.
            let (from, to) = (dir.join("thresholds.csv"), unused(dir, &format!("thresholds-build-{b}")));
            if from.exists() {
                std::fs::rename(&from, &to).map_err(|e| Error::io(&from, e))?;
            }
            if store.rows.is_empty() {
                // Nothing of this build: the table starts afresh (the old header may lack `build`).
                store.header.clear();
            }
        }
        Ok(store)
    }

    /// The rows of `dir/runs.csv`, all of scene `hash` (an error otherwise), of whichever
    /// builds; the store's build is this one's.
    fn open_as(dir: &Path, hash: &str, scene: &Path) -> Result<Store> {
        let path = Self::csv_path(dir);
        let mut store = Store {
            dir: dir.to_path_buf(),
            hash: hash.to_string(),
            build: build_id().to_string(),
            set_aside: Vec::new(),
            header: Vec::new(),
            rows: BTreeMap::new(),
            parquet: true,
            seed: String::new(),
            threads: 0,
        };
        if path.exists() {
            let t = Table::read_csv(&path)?;
            let (Some(id), Some(h)) = (t.column("run_id"), t.column("scene_hash")) else {
                return Err(Error::input(path.display().to_string(), "not a runs table of demsweep (no run_id or scene_hash column)"));
            };
            for row in &t.rows {
                if row[h] != hash {
                    return Err(Error::input(
                        path.display().to_string(),
                        format!(
                            "holds runs of another scene (scene_hash {}; {} is {}): rerun with --fresh to start afresh, or give another --out",
                            row[h],
                            scene.display(),
                            hash
                        ),
                    ));
                }
                store.rows.insert(row[id].clone(), row.clone());
            }
            store.header = t.header;
        }
        Ok(store)
    }

    /// Row counts by the build that made them.
    fn rows_by_build(&self) -> BTreeMap<String, usize> {
        let mut n = BTreeMap::new();
        for r in self.rows.values() {
            *n.entry(store_build(&self.header, r).to_string()).or_insert(0) += 1;
        }
        n
    }

    /// Row counts by the commit that made them.
    pub fn rows_by_commit(&self) -> BTreeMap<String, usize> {
        let mut n = BTreeMap::new();
        let k = self.header.iter().position(|h| h == "commit");
        for r in self.rows.values() {
            *n.entry(k.map_or(NO_COMMIT, |k| r[k].as_str()).to_string()).or_insert(0) += 1;
        }
        n
    }

    /// An error naming the rows not made by `commit`, and what to do.
    pub fn refuse_other_commits(&self, commit: &str) -> Result<()> {
        let other: Vec<String> = self.rows_by_commit().into_iter().filter(|(c, _)| c != commit).map(|(c, n)| format!("{n} made by commit {c}")).collect();
        if other.is_empty() {
            return Ok(());
        }
        Err(Error::input(
            Self::csv_path(&self.dir).display().to_string(),
            format!(
                "holds runs of another commit of demsweep ({}; this is commit {commit}), and a table does not mix commits unless told: \
                 rerun with --reuse-older to keep the runs this same build made (a commit that changed no physics keeps the build; \
                 runs of other builds are set aside and made again), or with --fresh to make every run again",
                other.join(", ")
            ),
        ))
    }

    /// Read the runs of a sweep folder as they are (a shard, for `merge`); the scene hash and
    /// the build are the rows' (all rows must share them).
    pub fn read(dir: &Path) -> Result<Store> {
        let path = Self::csv_path(dir);
        if !path.exists() {
            return Err(Error::input(dir.display().to_string(), "holds no runs.csv: not a sweep folder (or the shard has not run)"));
        }
        let t = Table::read_csv(&path)?;
        let h = t.column("scene_hash").ok_or_else(|| Error::input(path.display().to_string(), "not a runs table of demsweep (no scene_hash column)"))?;
        let hash = t.rows.first().map(|r| r[h].clone()).unwrap_or_default();
        let mut store = Store::open_as(dir, &hash, &path)?;
        let builds = store.rows_by_build();
        match builds.len() {
            0 => {}
            1 => store.build = builds.into_keys().next().expect("one build"),
            _ => {
                let list: Vec<String> = builds.iter().map(|(b, n)| format!("{n} of build {b}")).collect();
                return Err(Error::input(path.display().to_string(), format!("holds runs of several builds of demsweep ({})", list.join(", "))));
            }
        }
        Ok(store)
    }

    /// Whether `job` has finished with its outcome (a failed run has not).
    pub fn has(&self, job: &Job) -> bool {
        self.rows.get(&job.id()).is_some_and(|r| self.is_ok(r))
    }

    /// Whether the table holds a row of `job`, finished or failed.
    pub fn holds(&self, job: &Job) -> bool {
        self.rows.contains_key(&job.id())
    }

    /// A row's status is `ok` (a table before the column held finished runs only).
    fn is_ok(&self, row: &[String]) -> bool {
        self.header.iter().position(|h| h == "status").is_none_or(|k| row.get(k).is_some_and(|s| s == OK))
    }

    /// The cell of column `name` of `job`'s row, if the run finished.
    pub fn get(&self, job: &Job, name: &str) -> Option<&str> {
        let k = self.header.iter().position(|h| h == name)?;
        let row = self.rows.get(&job.id()).filter(|r| self.is_ok(r))?;
        row.get(k).map(String::as_str)
    }

    /// The failed runs: (run id, message), in the table's order.
    pub fn failures(&self) -> Vec<(String, String)> {
        self.table().rows.into_iter().filter(|r| !self.is_ok(r)).map(|r| (r[0].clone(), r.get(MESSAGE).cloned().unwrap_or_default())).collect()
    }

    /// Number of rows.
    pub fn len(&self) -> usize {
        self.rows.len()
    }

    /// No rows yet.
    pub fn is_empty(&self) -> bool {
        self.rows.is_empty()
    }

    /// A run asked for again for another purpose (both bisections at one velocity): its
    /// purpose becomes both, sorted, whichever asked first, so the table does not depend on
    /// timing. Returns whether the row changed.
    pub fn add_purpose(&mut self, job: &Job) -> bool {
        let Some(k) = self.header.iter().position(|h| h == "purpose") else { return false };
        let Some(row) = self.rows.get_mut(&job.id()) else { return false };
        let mut all: Vec<&str> = row[k].split('+').chain(job.purpose.split('+')).collect();
        all.sort();
        all.dedup();
        let merged = all.join("+");
        let changed = merged != row[k];
        row[k] = merged;
        changed
    }

    /// The key cells of a row of `job` (status ok, no message).
    fn key_cells(&self, job: &Job, level: &str) -> Vec<String> {
        let seed = job.overrides.iter().find(|o| o.field == "target.seed").map_or_else(|| self.seed.clone(), |o| o.value.to_string());
        let (version, commit) = (env!("CARGO_PKG_VERSION").to_string(), crate::provenance::commit().to_string());
        vec![job.id(), job.purpose.clone(), self.hash.clone(), self.build.clone(), level.to_string(), seed, self.threads.to_string(), version, commit, OK.to_string(), String::new()]
    }

    /// Add a failed run: its key cells, `status = failed` and the message, the summary cells
    /// empty. It replaces an earlier failure of the run, never a finished run.
    pub fn insert_failed(&mut self, job: &Job, level: &str, message: &str) {
        if self.has(job) {
            return;
        }
        let mut cells = self.key_cells(job, level);
        cells[STATUS] = FAILED.to_string();
        // One line: a CSV cell a reader greps, and a table row in the report.
        cells[MESSAGE] = message.split_whitespace().collect::<Vec<_>>().join(" ");
        if self.header.is_empty() {
            self.header = KEY_COLUMNS.iter().map(|s| s.to_string()).collect();
        }
        cells.resize(self.header.len(), String::new());
        self.replace(job, cells);
    }

    /// Put `cells` as `job`'s row; the purposes of the row it replaces stay with the run.
    fn replace(&mut self, job: &Job, cells: Vec<String>) {
        if let Some(old) = self.rows.insert(job.id(), cells) {
            let k = self.header.iter().position(|h| h == "purpose").expect("a key column");
            self.add_purpose(&Job { purpose: old[k].clone(), ..job.clone() });
        }
        self.add_purpose(job);
    }

    /// Add a finished run's summary row (the key columns are put in front); it replaces the
    /// run's failed row if there is one.
    pub fn insert(&mut self, job: &Job, level: &str, row: &[(String, String)]) -> Result<()> {
        let mut header: Vec<String> = KEY_COLUMNS.iter().map(|s| s.to_string()).collect();
        let mut cells = self.key_cells(job, level);
        let row_level = row.iter().find(|c| c.0 == "level").map(|c| c.1.clone());
        if let Some(l) = row_level {
            cells[LEVEL] = l;
        }
        for (k, v) in row.iter().filter(|c| c.0 != "level") {
            header.push(k.clone());
            cells.push(v.clone());
        }
        if self.header.len() <= KEY_COLUMNS.len() && header.starts_with(&self.header) {
            // The first finished run: the failed rows before it get its (empty) columns.
            self.header = header;
            let n = self.header.len();
            self.rows.values_mut().for_each(|r| r.resize(n, String::new()));
        } else if self.header != header {
            return Err(Error::input(Self::csv_path(&self.dir).display().to_string(), "a run's row has other columns than the table's"));
        }
        if self.has(job) {
            self.add_purpose(job);
        } else {
            self.replace(job, cells);
        }
        Ok(())
    }

    /// The table, rows ordered by their inputs.
    pub fn table(&self) -> Table {
        let mut ids: Vec<&String> = self.rows.keys().collect();
        ids.sort_by(|a, b| compare(a, b));
        Table { header: self.header.clone(), rows: ids.into_iter().map(|id| self.rows[id].clone()).collect() }
    }

    /// Write `runs.csv` (and `runs.parquet`) atomically.
    pub fn write(&self) -> Result<()> {
        let t = self.table();
        t.write_csv(&Self::csv_path(&self.dir))?;
        if self.parquet {
            super::parquet::write(&t, &self.dir.join("runs.parquet"))?;
        }
        Ok(())
    }

    /// Merge the rows of another store of the same scene (shards).
    pub fn absorb(&mut self, other: Store) -> Result<()> {
        if other.hash != self.hash {
            return Err(Error::input(
                other.dir.display().to_string(),
                format!("is a sweep of another scene (scene_hash {}, not {}): shards of different scenes cannot be merged", other.hash, self.hash),
            ));
        }
        if !other.rows.is_empty() && !self.rows.is_empty() && other.build != self.build {
            return Err(Error::input(
                other.dir.display().to_string(),
                format!("was run by another build of demsweep (build {}, not {}): shards of different builds cannot be merged", other.build, self.build),
            ));
        }
        if self.rows.is_empty() {
            self.build = other.build.clone();
        }
        // A shard whose runs all failed has the key columns only: the other's summary columns
        // are empty in its rows.
        let (mine, theirs) = (self.header.len(), other.header.len());
        let wider = if mine >= theirs { &self.header } else { &other.header };
        let narrower = if mine >= theirs { &other.header } else { &self.header };
        if !(wider.starts_with(narrower) && (narrower.len() == wider.len() || narrower.len() <= KEY_COLUMNS.len())) {
            return Err(Error::input(other.dir.display().to_string(), "its runs table has other columns"));
        }
        self.header = wider.clone();
        self.rows.extend(other.rows);
        let n = self.header.len();
        self.rows.values_mut().for_each(|r| r.resize(n, String::new()));
        Ok(())
    }
}

/// `dir/STEM.csv`, or `dir/STEM.2.csv`, `.3`, … if taken: a set-aside table never replaces an
/// earlier one (which may hold runs the new one lacks).
fn unused(dir: &Path, stem: &str) -> PathBuf {
    (1..).map(|k| dir.join(if k == 1 { format!("{stem}.csv") } else { format!("{stem}.{k}.csv") })).find(|p| !p.exists()).expect("a free name")
}

/// The build that made a row (`NO_BUILD` for a table without the column).
fn store_build<'a>(header: &[String], row: &'a [String]) -> &'a str {
    header.iter().position(|h| h == "build").map_or(NO_BUILD, |k| row[k].as_str())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_failed_row_takes_the_summary_columns_later_and_gives_way_to_the_finished_run() {
        let dir = std::env::temp_dir().join(format!("demsweep-store-failed-{}", std::process::id()));
        let mut s = Store::open_as(&dir, "h", Path::new("scene.toml")).unwrap();
        let job = |v: i64| Job { overrides: vec![crate::scene::overrides::Override { field: "projectile.v0_fps".into(), value: toml::Value::Integer(v) }], purpose: "grid".into() };
        s.insert_failed(&job(1), "0", "blew up\n   at step 3");
        assert!(!s.has(&job(1)) && s.holds(&job(1)));
        assert_eq!(s.table().header, KEY_COLUMNS);
        let row = vec![("depth_in".to_string(), "1.5".to_string())];
        s.insert(&job(2), "0", &row).unwrap();
        let t = s.table();
        assert_eq!(t.header.last().map(String::as_str), Some("depth_in"));
        assert_eq!([t.get(0, "status"), t.get(0, "message"), t.get(0, "depth_in")], [Some(FAILED), Some("blew up at step 3"), Some("")]);
        assert_eq!(s.get(&job(1), "depth_in"), None, "a failed run has no outcome");
        assert_eq!(s.failures(), [("projectile.v0_fps=1".to_string(), "blew up at step 3".to_string())]);
        s.insert(&job(1), "0", &row).unwrap();
        assert_eq!((s.has(&job(1)), s.get(&job(1), "depth_in"), s.failures().len()), (true, Some("1.5"), 0));
        s.insert_failed(&job(1), "0", "again");
        assert!(s.has(&job(1)), "a failure never replaces a finished run");
    }

    #[test]
    fn rows_are_ordered_by_their_inputs_numerically() {
        let mut ids = vec!["v=1000", "v=550", "v=612.5", "v=50"];
        ids.sort_by(|a, b| compare(a, b));
        assert_eq!(ids, vec!["v=50", "v=550", "v=612.5", "v=1000"]);
        let mut ids = vec!["a=2;b=1", "a=10;b=0", "a=2;b=0"];
        ids.sort_by(|a, b| compare(a, b));
        assert_eq!(ids, vec!["a=2;b=0", "a=2;b=1", "a=10;b=0"]);
    }
}
