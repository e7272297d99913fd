//! The golden tables in `results/empirical/` (written by `scripts/empirical_golden.sh`, our own
//! numbers, not FORMULAS.md figures) are recomputed cell by cell.

use demsweep::empirical::{Missile, Nose, Quantity, Target, inverse::Threshold, table};

/// Lengths are printed to 6 decimals: rounding is ≤ 5e-7 in, the rest is slack for libm.
const LENGTH_TOLERANCE_IN: f64 = 1e-6;
/// Velocities are printed to 3 decimals.
const VELOCITY_TOLERANCE_FPS: f64 = 1e-3;

fn read(name: &str) -> Vec<csv::StringRecord> {
    let path = format!("{}/results/empirical/{name}", env!("CARGO_MANIFEST_DIR"));
    let mut reader = csv::Reader::from_path(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    reader.records().map(|r| r.unwrap()).collect()
}

fn close(golden: &str, computed: Option<f64>, tolerance: f64) -> bool {
    match computed {
        None => golden.is_empty(),
        Some(v) => golden.parse::<f64>().is_ok_and(|g| (g - v).abs() <= tolerance),
    }
}

#[test]
fn sweeps_match_the_golden_files() {
    let velocities: Vec<f64> = (0..=20).map(|k| 500.0 + 50.0 * k as f64).collect();
    for nose in Nose::ALL {
        let golden = read(&format!("sweep_{}.csv", nose.name()));
        let rows = table::sweep(&Missile::report(nose), &Target::report(), &velocities);
        assert_eq!(golden.len(), rows.len(), "{}: row count", nose.name());
        for (g, r) in golden.iter().zip(&rows) {
            let at = format!("{} {} {} {}", nose.name(), r.formula.id(), r.formula.variant(), r.v0_fps);
            assert_eq!((&g[0], &g[1]), (r.formula.id(), r.formula.variant()), "{at}");
            assert_eq!(g[2].parse::<f64>().unwrap(), r.v0_fps, "{at}");
            for (k, q) in Quantity::ALL.into_iter().enumerate() {
                let value = r.prediction.get(q);
                assert!(close(&g[3 + k], value, LENGTH_TOLERANCE_IN), "{at} {}: golden `{}`, now {value:?}", q.symbol(), &g[3 + k]);
            }
            assert_eq!(&g[6], r.prediction.validity.cell(), "{at}");
        }
    }
}

#[test]
fn thresholds_match_the_golden_file() {
    let golden = read("thresholds_spherical.csv");
    let rows = table::thresholds(&Missile::report(Nose::Spherical), &Target::report());
    assert_eq!(golden.len(), rows.len());
    for (g, r) in golden.iter().zip(&rows) {
        let at = format!("{} {}", r.formula.id(), r.formula.variant());
        assert_eq!((&g[0], &g[1]), (r.formula.id(), r.formula.variant()), "{at}");
        for (cell, th) in [(&g[2], &r.scabbing), (&g[3], &r.perforation)] {
            match th {
                Threshold::Velocity { v_fps, .. } => assert!(close(cell, Some(*v_fps), VELOCITY_TOLERANCE_FPS), "{at}: {cell} vs {v_fps}"),
                other => assert_eq!(cell, other.cell(3), "{at}"),
            }
        }
        assert_eq!(&g[4], r.validity().cell(), "{at}");
    }
}
