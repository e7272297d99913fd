//! The sweep engine from the command line, on a small fast scene (`tests/data/tiny_beam.toml`):
//! the same tables for any thread count, after a kill -9 and a rerun, and from shards merged;
//! a run two bisections ask for at once made once;
//! a changed scene never mixed with old rows, and runs of another build made again, not read
//! back; bad input refused with a clear message and no
//! table written; the Parquet file the same table as the CSV.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use demsweep::table::Table;

const BIN: &str = env!("CARGO_BIN_EXE_demsweep");
/// Columns that measure the machine or record the engine, not the run.
const TIMING: [&str; 3] = ["wall_s", "element_steps_per_s", "threads"];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("demsweep-sweep-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn demsweep(args: &[&str]) -> Output {
    Command::new(BIN).current_dir(root()).args(args).output().expect("the binary runs")
}

fn ok(args: &[&str]) -> Output {
    let o = demsweep(args);
    assert!(o.status.success(), "{args:?}: {}", String::from_utf8_lossy(&o.stderr));
    o
}

/// A table without its timing columns.
fn untimed(path: &Path) -> Table {
    let mut t = Table::read_csv(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let keep: Vec<usize> = (0..t.header.len()).filter(|&k| !TIMING.contains(&t.header[k].as_str())).collect();
    t.header = keep.iter().map(|&k| t.header[k].clone()).collect();
    t.rows = t.rows.iter().map(|r| keep.iter().map(|&k| r[k].clone()).collect()).collect();
    t
}

fn ballistic(out: &Path, threads: &str, extra: &[&str]) -> Output {
    let mut args = vec!["ballistic", "--scene", "tests/data/tiny_beam.toml", "--v0", "300..900", "--step", "100", "--tol-fps", "5", "--quiet", "--threads", threads, "--out"];
    let out = out.to_str().unwrap().to_string();
    args.push(&out);
    args.extend_from_slice(extra);
    ok(&args)
}

fn same_tables(a: &Path, b: &Path) {
    assert_eq!(untimed(&a.join("runs.csv")), untimed(&b.join("runs.csv")), "runs of {} and {}", a.display(), b.display());
    assert_eq!(
        std::fs::read_to_string(a.join("thresholds.csv")).unwrap(),
        std::fs::read_to_string(b.join("thresholds.csv")).unwrap(),
        "thresholds of {} and {}",
        a.display(),
        b.display()
    );
}

#[test]
fn the_tables_are_the_same_on_one_thread_and_on_two() {
    let (one, two) = (tmp("one"), tmp("two"));
    ballistic(&one, "1", &[]);
    ballistic(&two, "2", &[]);
    same_tables(&one, &two);
    // Every row names what made it: its packing seed, the engine's threads, the program.
    for (dir, threads) in [(&one, "1"), (&two, "2")] {
        let runs = Table::read_csv(&dir.join("runs.csv")).unwrap();
        for r in 0..runs.rows.len() {
            assert_eq!(runs.get(r, "threads"), Some(threads));
            assert_eq!(runs.get(r, "seed"), Some(""), "the tiny beam is a regular lattice: no packing seed");
            assert_eq!(runs.get(r, "version"), Some(env!("CARGO_PKG_VERSION")));
            assert_eq!(runs.get(r, "commit"), Some(demsweep::provenance::commit()));
            assert_eq!(runs.get(r, "build"), Some(demsweep::provenance::build_id()));
        }
    }
    // Both thresholds were bisected to the tolerance, scabbing not above perforation.
    let t = Table::read_csv(&one.join("thresholds.csv")).unwrap();
    let f = |r: usize, c: &str| -> f64 { t.get(r, c).unwrap().parse().unwrap() };
    for r in 0..2 {
        assert_eq!(t.get(r, "method"), Some("bisection"));
        assert!(f(r, "v_high_fps") - f(r, "v_low_fps") <= 5.0 && f(r, "v_low_fps") < f(r, "v_est_fps"));
    }
    assert!(f(0, "v_est_fps") <= f(1, "v_est_fps"));
    for d in [one, two] {
        std::fs::remove_dir_all(d).unwrap();
    }
}

/// The tiny beam's two thresholds lie in one grid interval (it perforates as soon as it scabs),
/// so its two bisections ask for the same velocity at every step; on two threads each made it
/// beside the other (17 runs made for the table's 12, every bisection run twice).
#[test]
fn two_bisections_asking_for_one_velocity_make_it_once() {
    let two = tmp("shared-velocity");
    let o = ballistic(&two, "2", &[]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    let line = stdout.lines().find(|l| l.contains(" runs made, ")).expect("the sweep reports the runs it made");
    let count = |word: &str| -> usize {
        let words: Vec<&str> = line.split_whitespace().collect();
        let k = words.iter().position(|w| *w == word).expect(word);
        words[k - 1].trim_end_matches(',').parse().expect("a count")
    };
    let rows = Table::read_csv(&two.join("runs.csv")).unwrap().rows.len();
    assert_eq!(count("runs"), rows, "each run of the table made once: {line}");
    assert!(count("found") > 0, "the bisections shared a velocity, as this scene makes them: {line}");
    std::fs::remove_dir_all(two).unwrap();
}

#[test]
fn a_sweep_killed_with_sigkill_and_rerun_ends_with_the_tables_of_one_that_never_stopped() {
    let (whole, killed) = (tmp("whole"), tmp("killed"));
    ballistic(&whole, "1", &[]);
    let mut child = Command::new(BIN)
        .current_dir(root())
        .args(["ballistic", "--scene", "tests/data/tiny_beam.toml", "--v0", "300..900", "--step", "100", "--tol-fps", "5", "--quiet", "--threads", "1", "--out"])
        .arg(&killed)
        .spawn()
        .unwrap();
    // Kill it as soon as some but not all runs are on disk.
    let runs = killed.join("runs.csv");
    let t0 = std::time::Instant::now();
    loop {
        let n = std::fs::read_to_string(&runs).map(|s| s.lines().count()).unwrap_or(0);
        if n >= 3 || t0.elapsed().as_secs() > 60 {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    child.kill().unwrap(); // SIGKILL
    child.wait().unwrap();
    let before = Table::read_csv(&runs).expect("the table on disk is whole after a kill");
    assert!(!before.rows.is_empty() && before.rows.len() < 15, "killed mid-sweep: {} rows", before.rows.len());
    let rerun = ballistic(&killed, "1", &[]);
    assert!(String::from_utf8_lossy(&rerun.stdout).contains("found done"));
    same_tables(&whole, &killed);
    for d in [whole, killed] {
        std::fs::remove_dir_all(d).unwrap();
    }
}

#[test]
fn two_shards_merged_give_the_tables_of_the_unsharded_sweep() {
    let (whole, s1, s2, merged) = (tmp("unsharded"), tmp("shard1"), tmp("shard2"), tmp("merged"));
    ballistic(&whole, "2", &[]);
    ballistic(&s1, "1", &["--shard", "1/2"]);
    ballistic(&s2, "1", &["--shard", "2/2"]);
    let (n1, n2) = (Table::read_csv(&s1.join("runs.csv")).unwrap().rows.len(), Table::read_csv(&s2.join("runs.csv")).unwrap().rows.len());
    assert_eq!((n1, n2), (4, 3), "7 grid velocities dealt out alternately, no bisection in a shard");
    ok(&["merge", s1.to_str().unwrap(), s2.to_str().unwrap(), "--out", merged.to_str().unwrap(), "--bisect", "--quiet"]);
    same_tables(&whole, &merged);
    for d in [whole, s1, s2, merged] {
        std::fs::remove_dir_all(d).unwrap();
    }
}

#[test]
fn the_parquet_file_holds_the_csv_table_typed() {
    let out = tmp("parquet");
    ok(&["sweep", "tests/data/tiny_beam.toml", "--vary", "projectile.v0_fps=300..500:100", "--out", out.to_str().unwrap(), "--quiet"]);
    let csv = Table::read_csv(&out.join("runs.csv")).unwrap();
    let df = demsweep::sweep::parquet::read(&out.join("runs.parquet")).unwrap();
    assert_eq!(df.height(), 3);
    assert_eq!(df.width(), csv.header.len());
    let v0 = df.column("v0_fps").unwrap().f64().unwrap().into_no_null_iter().collect::<Vec<_>>();
    assert_eq!(v0, vec![300.0, 400.0, 500.0]);
    let steps = df.column("steps").unwrap().i64().unwrap().into_no_null_iter().collect::<Vec<_>>();
    let csv_steps: Vec<i64> = (0..3).map(|r| csv.get(r, "steps").unwrap().parse().unwrap()).collect();
    assert_eq!(steps, csv_steps);
    let perforated_column = df.column("perforated").unwrap().bool().unwrap().clone();
    let perforated = (0..3).map(|i| perforated_column.get(i).unwrap()).collect::<Vec<_>>();
    assert_eq!(perforated, (0..3).map(|r| csv.get(r, "perforated") == Some("true")).collect::<Vec<_>>());
    std::fs::remove_dir_all(out).unwrap();
}

#[test]
fn a_grid_and_a_parameter_table_of_the_same_runs_give_the_same_rows() {
    let (g, t) = (tmp("grid"), tmp("table"));
    ok(&["sweep", "tests/data/tiny_beam.toml", "--vary", "projectile.v0_fps=300,400", "--vary", "projectile.angle_deg=0..10:10", "--out", g.to_str().unwrap(), "--quiet"]);
    std::fs::create_dir_all(&t).unwrap();
    let params = t.join("params.csv");
    std::fs::write(&params, "projectile.v0_fps,projectile.angle_deg\n400,10.0\n300,0.0\n300,10.0\n400,0.0\n").unwrap();
    ok(&["sweep", "tests/data/tiny_beam.toml", "--table", params.to_str().unwrap(), "--out", t.to_str().unwrap(), "--quiet"]);
    let (a, mut b) = (untimed(&g.join("runs.csv")), untimed(&t.join("runs.csv")));
    let purpose = b.column("purpose").unwrap();
    for r in &mut b.rows {
        assert_eq!(r[purpose], "table");
        r[purpose] = "grid".into();
    }
    assert_eq!(a, b);
    assert_eq!(a.rows.len(), 4);
    assert_eq!(a.get(1, "run_id"), Some("projectile.v0_fps=300;projectile.angle_deg=10"));
    for d in [g, t] {
        std::fs::remove_dir_all(d).unwrap();
    }
}

#[test]
fn a_changed_scene_is_never_mixed_with_old_rows() {
    let out = tmp("changed");
    ok(&["sweep", "tests/data/tiny_beam.toml", "--vary", "projectile.v0_fps=300", "--out", out.to_str().unwrap(), "--quiet"]);
    let changed = out.join("changed.toml");
    let text = std::fs::read_to_string(root().join("tests/data/tiny_beam.toml")).unwrap().replace("strength_factor = 60.0", "strength_factor = 61.0");
    std::fs::write(&changed, text).unwrap();
    let before = std::fs::read(out.join("runs.csv")).unwrap();
    let o = demsweep(&["sweep", changed.to_str().unwrap(), "--vary", "projectile.v0_fps=300", "--out", out.to_str().unwrap(), "--quiet"]);
    let msg = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && msg.contains("another scene") && msg.contains("--fresh"), "{msg}");
    assert_eq!(std::fs::read(out.join("runs.csv")).unwrap(), before, "the old table untouched");
    ok(&["sweep", changed.to_str().unwrap(), "--vary", "projectile.v0_fps=300", "--out", out.to_str().unwrap(), "--quiet", "--fresh"]);
    let t = Table::read_csv(&out.join("runs.csv")).unwrap();
    assert_eq!(t.rows.len(), 1);
    assert_eq!(t.get(0, "strength_factor").unwrap().parse::<f64>().unwrap(), 61.0);
    std::fs::remove_dir_all(out).unwrap();
}

/// `path`'s table with every cell of column `name` set to `value`, or the column dropped.
fn rewrite_column(path: &Path, name: &str, value: Option<&str>) {
    let mut t = Table::read_csv(path).unwrap();
    let k = t.column(name).unwrap();
    match value {
        Some(v) => t.rows.iter_mut().for_each(|r| r[k] = v.to_string()),
        None => {
            t.header.remove(k);
            t.rows.iter_mut().for_each(|r| {
                r.remove(k);
            });
        }
    }
    t.write_csv(path).unwrap();
}

// The bug: a sweep folder kept its runs under the scene's hash alone, which a new build of the
// program did not change, so a changed kernel read back the runs of the old one as its own (the
// README's main job "ran" in 0.2 s on a fresh clone, from the committed table).
#[test]
fn runs_of_another_build_are_made_again_not_read_back() {
    let out = tmp("build");
    let o = out.to_str().unwrap();
    let sweep = || demsweep(&["sweep", "tests/data/tiny_beam.toml", "--vary", "projectile.v0_fps=300..400:100", "--out", o]);
    assert!(sweep().status.success());
    let fresh = untimed(&out.join("runs.csv"));
    let build = fresh.get(0, "build").unwrap().to_string();
    assert_eq!(build.len(), 16, "a build id of 16 hex digits, not {build:?}");
    let again = sweep();
    assert!(String::from_utf8_lossy(&again.stderr).contains("0 runs made, 2 found done"), "this build's runs are reused");
    // The same rows as if another build had made them, and, apart, as a build before the column.
    for (other, value) in [("00000000000000ff", Some("00000000000000ff")), ("unknown", None)] {
        rewrite_column(&out.join("runs.csv"), "build", value);
        let old = std::fs::read(out.join("runs.csv")).unwrap();
        let o2 = sweep();
        let msg = String::from_utf8_lossy(&o2.stderr);
        assert!(o2.status.success(), "{msg}");
        assert!(msg.contains(&format!("2 runs of another build of demsweep (build {other}")) && msg.contains("2 runs made, 0 found done"), "{msg}");
        let aside = out.join(format!("runs-build-{other}.csv"));
        assert_eq!(std::fs::read(&aside).unwrap(), old, "the old rows kept whole in {}", aside.display());
        assert_eq!(untimed(&out.join("runs.csv")), fresh, "made again by this build: the rows of a fresh sweep");
    }
    // Set aside again under a taken name: beside the first, which stays as it was.
    let first = std::fs::read(out.join("runs-build-00000000000000ff.csv")).unwrap();
    rewrite_column(&out.join("runs.csv"), "build", Some("00000000000000ff"));
    let old = std::fs::read(out.join("runs.csv")).unwrap();
    assert!(sweep().status.success());
    assert_eq!(std::fs::read(out.join("runs-build-00000000000000ff.csv")).unwrap(), first);
    assert_eq!(std::fs::read(out.join("runs-build-00000000000000ff.2.csv")).unwrap(), old);
    std::fs::remove_dir_all(out).unwrap();
}

// Issue 47: a resumed sweep must not mix rows of another commit into its table silently; the
// user says what to do with them (--reuse-older keeps this build's, --fresh none).
#[test]
fn rows_of_another_commit_are_refused_unless_told() {
    let out = tmp("commit");
    let o = out.to_str().unwrap();
    let sweep = |extra: &[&str]| {
        let mut args = vec!["sweep", "tests/data/tiny_beam.toml", "--vary", "projectile.v0_fps=300..400:100", "--out", o];
        args.extend_from_slice(extra);
        demsweep(&args)
    };
    assert!(sweep(&[]).status.success());
    let fresh = untimed(&out.join("runs.csv"));
    let ours = fresh.get(0, "commit").unwrap().to_string();
    assert!(!ours.is_empty() && ours != "0123456789ab");
    rewrite_column(&out.join("runs.csv"), "commit", Some("0123456789ab"));
    let old = std::fs::read(out.join("runs.csv")).unwrap();
    let refused = sweep(&[]);
    let msg = String::from_utf8_lossy(&refused.stderr);
    assert!(!refused.status.success(), "{msg}");
    for part in ["another commit", "2 made by commit 0123456789ab", &format!("this is commit {ours}"), "--reuse-older", "--fresh"] {
        assert!(msg.contains(part), "{part:?} in {msg}");
    }
    assert_eq!(std::fs::read(out.join("runs.csv")).unwrap(), old, "the table left as it was");
    assert!(!sweep(&["--fresh", "--reuse-older"]).status.success(), "the two flags exclude each other");
    // Told: the same build's rows are kept, and still name the commit that made them.
    let kept = sweep(&["--reuse-older"]);
    assert!(String::from_utf8_lossy(&kept.stderr).contains("0 runs made, 2 found done"), "{}", String::from_utf8_lossy(&kept.stderr));
    assert_eq!(untimed(&out.join("runs.csv")).get(1, "commit"), Some("0123456789ab"));
    // Another commit of another build: set aside and made again even when told to reuse.
    rewrite_column(&out.join("runs.csv"), "build", Some("00000000000000ff"));
    let remade = sweep(&["--reuse-older"]);
    assert!(String::from_utf8_lossy(&remade.stderr).contains("2 runs made, 0 found done"));
    assert_eq!(untimed(&out.join("runs.csv")), fresh);
    // --fresh: every run made again by this commit.
    rewrite_column(&out.join("runs.csv"), "commit", Some("0123456789ab"));
    assert!(String::from_utf8_lossy(&sweep(&["--fresh"]).stderr).contains("2 runs made, 0 found done"));
    assert_eq!(untimed(&out.join("runs.csv")), fresh);
    std::fs::remove_dir_all(out).unwrap();
}

#[test]
fn shards_of_different_commits_are_merged_only_when_told() {
    let (a, b, out) = (tmp("commit-shard-1"), tmp("commit-shard-2"), tmp("commit-merged"));
    ballistic(&a, "1", &["--shard", "1/2"]);
    ballistic(&b, "1", &["--shard", "2/2"]);
    rewrite_column(&b.join("runs.csv"), "commit", Some("0123456789ab"));
    let merge = |extra: &[&str]| {
        let mut args = vec!["merge", a.to_str().unwrap(), b.to_str().unwrap(), "--out", out.to_str().unwrap()];
        args.extend_from_slice(extra);
        demsweep(&args)
    };
    let o = merge(&[]);
    let msg = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && msg.contains("several commits") && msg.contains("0123456789ab") && msg.contains("--reuse-older"), "{msg}");
    assert!(!out.join("runs.csv").exists(), "no table written");
    // Both of one other commit: joined, but bisected by this one only when told.
    rewrite_column(&a.join("runs.csv"), "commit", Some("0123456789ab"));
    assert!(merge(&[]).status.success());
    let o = merge(&["--bisect"]);
    assert!(!o.status.success() && String::from_utf8_lossy(&o.stderr).contains("another commit"), "{}", String::from_utf8_lossy(&o.stderr));
    let o = merge(&["--bisect", "--reuse-older"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(out.join("thresholds.csv").exists());
    for d in [a, b, out] {
        std::fs::remove_dir_all(d).unwrap();
    }
}

// Issue 47: a run that fails (an unstable step refused, a blow-up) is a row with its status and
// message, its summary cells empty; the other runs go on, the report lists the failures, the
// exit says so, and a rerun makes the failed runs again.
#[test]
fn a_failed_run_is_a_row_with_its_message_and_the_others_go_on() {
    let out = tmp("failed");
    let o = out.to_str().unwrap();
    // The cantilever's stability bound is 3.95e-4 s: 1e-3 s is refused, or forced through and
    // blows up.
    let sweep = || {
        demsweep(&[
            "sweep", "sweeps/cantilever.toml", "--vary", "scene.duration_s=0.05", "--vary", "time_step.refuse_unstable=true,false",
            "--vary", "time_step.dt_s=1e-4,1e-3", "--out", o, "--quiet",
        ])
    };
    let first = sweep();
    let msg = String::from_utf8_lossy(&first.stderr);
    assert!(!first.status.success() && msg.contains("2 run(s) failed"), "{msg}");
    let t = Table::read_csv(&out.join("runs.csv")).unwrap();
    let before = untimed(&out.join("runs.csv"));
    assert_eq!(t.rows.len(), 4, "every run is a row");
    for r in 0..4 {
        let (id, status, message, steps) = (t.get(r, "run_id").unwrap(), t.get(r, "status").unwrap(), t.get(r, "message").unwrap(), t.get(r, "steps").unwrap());
        if id.ends_with("dt_s=0.0001") {
            assert_eq!((status, message, steps), ("ok", "", "500"), "{id}");
        } else {
            let why = if id.contains("refuse_unstable=true") { "exceeds the stability bound" } else { "numerical blow-up at step" };
            assert_eq!(status, "failed", "{id}");
            assert!(message.contains(why) && msg.contains(&format!("{id}: {message}")), "{id}: {message}");
            assert_eq!(steps, "", "{id}: no outcome");
        }
    }
    let page = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(page.contains("Failed runs (2)") && page.contains("numerical blow-up at step") && page.contains("exceeds the stability bound"));
    let df = demsweep::sweep::parquet::read(&out.join("runs.parquet")).unwrap();
    let status = df.column("status").unwrap().str().unwrap().clone();
    assert_eq!((0..status.len()).filter(|&i| status.get(i) == Some("failed")).count(), 2);
    // Rerun: the finished runs skipped, the failed ones made again (and failing again).
    let again = sweep();
    let msg = String::from_utf8_lossy(&again.stderr);
    assert!(!again.status.success() && msg.contains("0 runs made, 2 found done") && msg.contains("2 run(s) failed"), "{msg}");
    assert_eq!(untimed(&out.join("runs.csv")), before, "the same rows, the failures replaced by their like");
    std::fs::remove_dir_all(out).unwrap();
}

#[test]
fn shards_of_different_builds_are_not_merged() {
    let (a, b, out) = (tmp("build-shard-1"), tmp("build-shard-2"), tmp("build-merged"));
    ballistic(&a, "1", &["--shard", "1/2"]);
    ballistic(&b, "1", &["--shard", "2/2"]);
    rewrite_column(&b.join("runs.csv"), "build", Some("00000000000000ff"));
    let o = demsweep(&["merge", a.to_str().unwrap(), b.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let msg = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && msg.contains("another build") && msg.contains("00000000000000ff"), "{msg}");
    assert!(!out.join("runs.csv").exists(), "no table written");
    // Both of the other build: merged, but not bisected by this one.
    rewrite_column(&a.join("runs.csv"), "build", Some("00000000000000ff"));
    ok(&["merge", a.to_str().unwrap(), b.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    let o = demsweep(&["merge", a.to_str().unwrap(), b.to_str().unwrap(), "--out", out.to_str().unwrap(), "--bisect"]);
    let msg = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && msg.contains("another build of demsweep (build 00000000000000ff"), "{msg}");
    for d in [a, b, out] {
        std::fs::remove_dir_all(d).unwrap();
    }
}

#[test]
fn bad_input_is_refused_with_a_clear_message_and_no_table() {
    let out = tmp("bad");
    let o = out.to_str().unwrap();
    let other = tmp("bad-other-shard");
    // A shard of another scene, to merge with a shard of this one.
    let changed = std::env::temp_dir().join(format!("demsweep-changed-{}.toml", std::process::id()));
    std::fs::write(&changed, std::fs::read_to_string(root().join("tests/data/tiny_beam.toml")).unwrap().replace("strength_factor = 60.0", "strength_factor = 70.0")).unwrap();
    let (s_this, s_other) = (tmp("bad-this-shard"), other.clone());
    ballistic(&s_this, "1", &["--shard", "1/2"]);
    ok(&["ballistic", "--scene", changed.to_str().unwrap(), "--v0", "300..900", "--step", "100", "--quiet", "--shard", "2/2", "--out", s_other.to_str().unwrap()]);
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["ballistic", "--scene", "tests/data/tiny_beam.toml", "--v0", "1500..500", "--out", o], "reversed"),
        (vec!["ballistic", "--scene", "tests/data/tiny_beam.toml", "--step", "0", "--out", o], "--step"),
        (vec!["ballistic", "--scene", "tests/data/tiny_beam.toml", "--step=-50", "--out", o], "--step"),
        (vec!["ballistic", "--scene", "tests/data/tiny_beam.toml", "--tol-fps", "0", "--out", o], "--tol-fps"),
        (vec!["ballistic", "--scene", "tests/data/missing.toml", "--out", o], "missing.toml"),
        (vec!["ballistic", "--scene", "tests/data/tiny_beam.toml", "--shard", "3/2", "--out", o], "--shard"),
        (vec!["ballistic", "--scene", "tests/data/tiny_beam.toml", "--shard", "0/2", "--out", o], "--shard"),
        (vec!["sweep", "tests/data/tiny_beam.toml", "--vary", "projectile.v0_fpz=300..400:100", "--out", o], "v0_fpz"),
        (vec!["sweep", "tests/data/tiny_beam.toml", "--vary", "projectile.v0_fps=-100..400:100", "--out", o], "v0_fps"),
        (vec!["sweep", "tests/data/tiny_beam.toml", "--vary", "projectile.v0_fps=500..400:100", "--out", o], "reversed"),
        (vec!["sweep", "tests/data/tiny_beam.toml", "--out", o], "nothing to vary"),
        (vec!["converge", "--case", "sphere", "--out", o], "sphere"),
        (vec!["converge", "--mesh", "1", "--out", o], "--mesh"),
        (vec!["converge", "--case", "cantilever", "--ratio", "2", "--out", o], "refines by 3"),
        (vec!["converge", "--case", "cantilever", "--packings", "2", "--out", o], "--packings"),
        (vec!["converge", "--scene", "tests/data/tiny_beam.toml", "--mesh", "2", "--packings", "2", "--out", o], "irregular"),
        (vec!["merge", s_this.to_str().unwrap(), s_other.to_str().unwrap(), "--out", o], "another scene"),
    ];
    for (args, says) in cases {
        let r = demsweep(&args);
        let msg = String::from_utf8_lossy(&r.stderr);
        assert!(!r.status.success(), "{args:?} should fail");
        assert!(msg.contains(says), "{args:?}: expected `{says}` in: {msg}");
        let written: Vec<_> = std::fs::read_dir(&out).map(|d| d.filter_map(|e| e.ok()).map(|e| e.file_name()).collect()).unwrap_or_default();
        assert!(!written.iter().any(|n| n.to_string_lossy().ends_with(".csv") || n.to_string_lossy().ends_with(".parquet")), "{args:?} wrote {written:?}");
    }
    for d in [s_this, s_other] {
        std::fs::remove_dir_all(d).unwrap();
    }
    let _ = std::fs::remove_dir_all(out);
    std::fs::remove_file(changed).unwrap();
}

/// Several packings: every packing's grid and bisections, the same tables on one thread and on
/// two, a V50 row per threshold whose interval holds its estimate, and a bisection row per
/// packing and threshold.
#[test]
fn a_sweep_over_packings_reports_v50s_and_each_packing_the_same_on_any_thread_count() {
    let (one, two) = (tmp("packings-one"), tmp("packings-two"));
    let args = |out: &Path, threads: &str| {
        let o = out.to_str().unwrap().to_string();
        ok(&["ballistic", "--scene", "tests/data/tiny_irregular.toml", "--v0", "300..900", "--step", "200", "--tol-fps", "50", "--packings", "3", "--quiet", "--threads", threads, "--out", &o])
    };
    args(&one, "1");
    let stdout = String::from_utf8_lossy(&args(&two, "2").stdout).to_string();
    same_tables(&one, &two);
    assert!(stdout.contains("scabbing V50") && stdout.contains("seed 3"), "{stdout}");
    let runs = Table::read_csv(&one.join("runs.csv")).unwrap();
    for seed in 1..=3 {
        let grid = (0..runs.rows.len()).filter(|&r| runs.get(r, "run_id").unwrap().starts_with(&format!("target.seed={seed};")) && runs.get(r, "purpose").unwrap().contains("grid")).count();
        assert_eq!(grid, 4, "packing {seed}: the grid 300, 500, 700, 900");
    }
    let t = Table::read_csv(&one.join("thresholds.csv")).unwrap();
    let f = |r: usize, c: &str| -> Option<f64> { t.get(r, c).unwrap().parse().ok() };
    for (r, name) in [(0, "scabbing"), (1, "perforation")] {
        assert_eq!(t.get(r, "threshold"), Some(name));
        assert!(t.get(r, "method").unwrap().starts_with("v50"), "{:?}", t.rows[r]);
        let v = f(r, "v_est_fps").expect("a V50");
        assert!(f(r, "v_low_fps").is_none_or(|lo| lo < v) && f(r, "v_high_fps").is_none_or(|hi| hi > v), "{:?}", t.rows[r]);
    }
    let per_seed = (0..t.rows.len()).filter(|&r| t.get(r, "method").unwrap().starts_with("bisection seed")).count();
    assert_eq!(per_seed, 6, "three packings, two thresholds each");
    // A regular lattice has one packing.
    let bad = tmp("packings-regular");
    let o = demsweep(&["ballistic", "--scene", "tests/data/tiny_beam.toml", "--packings", "2", "--quiet", "--out", bad.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success() && err.contains("--packings") && err.contains("irregular"), "{err}");
    assert!(!bad.join("runs.csv").exists(), "nothing written");
    for d in [one, two] {
        std::fs::remove_dir_all(d).unwrap();
    }
}

/// `converge --packings`: each level's depth is the mean of its packings' runs (the rows the
/// study stored, seeds from the scene's on), with their sample standard deviation; one packing
/// keeps the run names of a study without packings.
#[test]
fn a_mesh_study_over_packings_reports_each_level_as_the_mean_of_its_packings() {
    let out = tmp("converge-packings");
    let o = out.to_str().unwrap().to_string();
    ok(&["converge", "--scene", "tests/data/tiny_irregular.toml", "--mesh", "2", "--packings", "3", "--quiet", "--out", &o]);
    let levels = Table::read_csv(&out.join("penetration.csv")).unwrap();
    let runs = Table::read_csv(&out.join("penetration_runs/runs.csv")).unwrap();
    assert_eq!(levels.rows.len(), 2);
    for l in 0..2 {
        let depths: Vec<f64> = (0..runs.rows.len())
            .filter(|&r| runs.get(r, "run_id").unwrap().starts_with(&format!("penetration.level={l};")))
            .map(|r| runs.get(r, "depth_in").unwrap().parse().unwrap())
            .collect();
        assert_eq!(depths.len(), 3, "level {l}: one run per packing");
        let seeds = (1..=3).filter(|s| (0..runs.rows.len()).any(|r| runs.get(r, "run_id").unwrap() == format!("penetration.level={l};projectile.v0_fps=500;target.seed={s}"))).count();
        assert_eq!(seeds, 3, "level {l}: seeds 1, 2 and 3");
        let mean = depths.iter().sum::<f64>() / 3.0;
        let sd = (depths.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / 2.0).sqrt();
        let f = |c: &str| -> f64 { levels.get(l, c).unwrap().parse().unwrap() };
        assert!((f("depth_in") - mean).abs() <= 1e-8 * mean, "level {l}: {} against the runs' mean {mean}", f("depth_in"));
        assert!((f("depth_in_sd") - sd).abs() <= 1e-3 * sd.max(1e-9), "level {l}: sd {} against {sd}", f("depth_in_sd"));
        assert_eq!(levels.get(l, "packings"), Some("3"));
    }
    std::fs::remove_dir_all(&out).unwrap();
    // One packing: the scene's own, named as before packings came in.
    ok(&["converge", "--scene", "tests/data/tiny_irregular.toml", "--mesh", "2", "--quiet", "--out", &o]);
    let runs = Table::read_csv(&out.join("penetration_runs/runs.csv")).unwrap();
    assert_eq!(runs.get(0, "run_id"), Some("penetration.level=0;projectile.v0_fps=500"));
    let levels = Table::read_csv(&out.join("penetration.csv")).unwrap();
    assert_eq!((levels.get(0, "packings"), levels.get(0, "depth_in_sd")), (Some("1"), Some("")));
    std::fs::remove_dir_all(out).unwrap();
}
