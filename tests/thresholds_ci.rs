//! The CI scene's ballistic sweep against its committed tables (`scripts/thresholds_ci.sh`):
//! the same sweep rerun here (its arguments from `results/thresholds_ci_sweep.toml`) must give
//! every run's outcome exactly (the kernel is deterministic), both V50s to the table's precision
//! and every packing's bisected thresholds within the sweep's tolerance.

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
    // Each threshold's estimate beside the committed row of the same method: with several
    // packings the V50 (a function of the runs' outcomes, which are the same, so equal to the
    // table's printed precision) and every packing's bisection (within the sweep's tolerance).
    let golden = committed("thresholds_ci.csv");
    let row = |threshold: &str, method: &str| -> f64 {
        let r = (0..golden.rows.len())
            .find(|&r| golden.get(r, "threshold") == Some(threshold) && golden.get(r, "method") == Some(method))
            .unwrap_or_else(|| panic!("no committed row {threshold} / {method}"));
        golden.get(r, "v_est_fps").unwrap().parse().unwrap()
    };
    let mut compared = 0;
    if let Some((scab, perf)) = &report.v50 {
        assert_eq!(report.packings.len(), m.packings as usize);
        let method = format!("v50 (90 % interval, {} packings)", m.packings);
        for (name, v) in [("scabbing", scab), ("perforation", perf)] {
            let live = v.as_ref().expect("both V50s are estimated in the CI range").v50_fps;
            let v = row(name, &method);
            assert!((live - v).abs() <= 1e-3, "{name} V50: live {live}, committed {v}");
            compared += 1;
        }
        for p in &report.packings {
            for (name, f) in [("scabbing", &p.scabbing), ("perforation", &p.perforation)] {
                let live = f.estimate_fps().expect("every packing brackets both thresholds in the CI range");
                let v = row(name, &format!("bisection seed {}", p.seed));
                assert!((live - v).abs() <= m.tol_fps, "{name}, seed {}: live {live}, committed {v}", p.seed);
                compared += 1;
            }
        }
    } else {
        for (name, f) in [("scabbing", &report.scabbing), ("perforation", &report.perforation)] {
            let live = f.estimate_fps().expect("both thresholds are bracketed in the CI range");
            let v = row(name, "bisection");
            assert!((live - v).abs() <= m.tol_fps, "{name}: live {live}, committed {v}");
            compared += 1;
        }
    }
    assert!(compared >= 2, "{compared} thresholds compared");
    std::fs::remove_dir_all(out).unwrap();
}
