//! The CI scenes' ballistic sweeps (2D and 3D) against their committed tables
//! (`scripts/thresholds_ci.sh [3d]`):
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
    check("thresholds_ci", "sweeps/penetration_ci.toml");
}

#[test]
fn the_3d_ci_sweep_reproduces_its_committed_thresholds() {
    check("thresholds3d_ci", "sweeps/penetration3d_ci.toml");
}

/// Rerun the sweep of `results/<stem>_sweep.toml` (on `scene`) and compare with
/// `results/<stem>.csv` and `results/<stem>_runs.csv`. A threshold the committed sweep did not
/// bound (no V50, or a packing's bisection not bracketed) must stay unbounded.
fn check(stem: &str, scene: &str) {
    let text = std::fs::read_to_string(root().join(format!("results/{stem}_sweep.toml"))).unwrap();
    let m: Manifest = toml::from_str(&text).unwrap();
    assert_eq!(m.scene, Path::new(scene));
    let out = std::env::temp_dir().join(format!("demsweep-{stem}-{}", std::process::id()));
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
        reuse: demsweep::sweep::Reuse::SameCommit,
        shard: None,
        packings: m.packings,
    };
    let report = run(&plan).unwrap();
    let live_runs = Table::read_csv(&out.join("runs.csv")).unwrap();
    let golden_runs = committed(&format!("{stem}_runs.csv"));
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
    let golden = committed(&format!("{stem}.csv"));
    let row = |threshold: &str, method: &str| -> Option<f64> {
        let r = (0..golden.rows.len())
            .find(|&r| golden.get(r, "threshold") == Some(threshold) && golden.get(r, "method") == Some(method))
            .unwrap_or_else(|| panic!("no committed row {threshold} / {method}"));
        golden.get(r, "v_est_fps").filter(|v| !v.is_empty()).map(|v| v.parse().unwrap())
    };
    let mut compared = 0;
    if let Some((scab, perf)) = &report.v50 {
        assert_eq!(report.packings.len(), m.packings as usize);
        let method = format!("v50 (90 % interval, {} packings)", m.packings);
        for (name, v) in [("scabbing", scab), ("perforation", perf)] {
            match (v.as_ref().map(|v| v.v50_fps), row(name, &method)) {
                (Some(live), Some(v)) => assert!((live - v).abs() <= 1e-3, "{name} V50: live {live}, committed {v}"),
                (live, v) => assert_eq!(live, v, "{name} V50: live and committed"),
            }
            compared += 1;
        }
        for p in &report.packings {
            for (name, f) in [("scabbing", &p.scabbing), ("perforation", &p.perforation)] {
                match (f.estimate_fps(), row(name, &format!("bisection seed {}", p.seed))) {
                    (Some(live), Some(v)) => assert!((live - v).abs() <= m.tol_fps, "{name}, seed {}: live {live}, committed {v}", p.seed),
                    (live, v) => assert_eq!(live, v, "{name}, seed {}: bounded live and committed alike", p.seed),
                }
                compared += 1;
            }
        }
    } else {
        for (name, f) in [("scabbing", &report.scabbing), ("perforation", &report.perforation)] {
            match (f.estimate_fps(), row(name, "bisection")) {
                (Some(live), Some(v)) => assert!((live - v).abs() <= m.tol_fps, "{name}: live {live}, committed {v}"),
                (live, v) => assert_eq!(live, v, "{name}: bounded live and committed alike"),
            }
            compared += 1;
        }
    }
    assert!(compared >= 2, "{compared} thresholds compared");
    std::fs::remove_dir_all(out).unwrap();
}
