//! The CI scene's ballistic sweep against its committed tables (`scripts/thresholds_ci.sh`):
//! the same sweep rerun here (its arguments from `results/thresholds_ci_sweep.toml`) must give
//! every run's outcome exactly (the kernel is deterministic) and both bisected thresholds within
//! the sweep's tolerance.

use std::path::{Path, PathBuf};

use demsweep::ballistic::{Manifest, Plan, run};
use demsweep::table::Table;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn committed(name: &str) -> Table {
    Table::read_csv(&root().join("results").join(name)).unwrap()
}

#[test]
fn the_ci_sweep_reproduces_its_committed_thresholds() {
    let text = std::fs::read_to_string(root().join("results/thresholds_ci_sweep.toml")).unwrap();
    let m: Manifest = toml::from_str(&text).unwrap();
    assert_eq!(m.scene, Path::new("sweeps/penetration_ci.toml"));
    let out = std::env::temp_dir().join(format!("demsweep-thresholds-ci-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let plan = Plan {
        scene: root().join(&m.scene),
        v0_min_fps: m.v0_min_fps,
        v0_max_fps: m.v0_max_fps,
        step_fps: m.step_fps,
        tol_fps: m.tol_fps,
        out: out.clone(),
        threads: 0,
        quiet: true,
        fresh: false,
        shard: None,
        packings: m.packings,
    };
    let report = run(&plan).unwrap();
    let live_runs = Table::read_csv(&out.join("runs.csv")).unwrap();
    let golden_runs = committed("thresholds_ci_runs.csv");
    assert_eq!(live_runs.get(0, "scene_hash"), Some(m.scene_hash.as_str()), "the committed tables are of this scene and program version");
    let ids = |t: &Table| (0..t.rows.len()).map(|r| t.get(r, "run_id").unwrap().to_string()).collect::<Vec<_>>();
    assert_eq!(ids(&live_runs), ids(&golden_runs), "the same runs, grid and bisection");
    for r in 0..golden_runs.rows.len() {
        for c in ["scabbed", "perforated", "end_reason", "steps", "bonds_broken", "scab_fragments", "purpose"] {
            assert_eq!(live_runs.get(r, c), golden_runs.get(r, c), "{}: {c}", golden_runs.get(r, "run_id").unwrap());
        }
    }
    let golden = committed("thresholds_ci.csv");
    for (k, f) in [(0, &report.scabbing), (1, &report.perforation)] {
        assert_eq!(golden.get(k, "method"), Some("bisection"));
        let v: f64 = golden.get(k, "v_est_fps").unwrap().parse().unwrap();
        let live = f.estimate_fps().expect("both thresholds are bracketed in the CI range");
        assert!((live - v).abs() <= m.tol_fps, "{}: live {live}, committed {v}", golden.get(k, "threshold").unwrap());
    }
    std::fs::remove_dir_all(out).unwrap();
}
