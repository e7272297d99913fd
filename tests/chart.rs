//! `demsweep chart` on the small fast scene (`tests/data/tiny_beam.toml`): each thickness is the
//! scene with only its thickness changed, both thresholds rise with the thickness as the
//! formulas' do, the chart's rows are its folders' thresholds, a rerun makes nothing, and bad
//! thicknesses are refused before any run.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use demsweep::scene::overrides::Override;
use demsweep::sweep::job::Base;
use demsweep::table::Table;

const BIN: &str = env!("CARGO_BIN_EXE_demsweep");
const SCENE: &str = "tests/data/tiny_beam.toml";

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("demsweep-chart-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn chart(out: &Path, thicknesses: &str) -> Output {
    Command::new(BIN)
        .current_dir(root())
        .args(["chart", "--scene", SCENE, "--thickness-in", thicknesses, "--v0", "200..1400", "--step", "100", "--tol-fps", "10", "--quiet", "--out"])
        .arg(out)
        .output()
        .expect("the binary runs")
}

fn num(t: &Table, r: usize, c: &str) -> f64 {
    t.get(r, c).unwrap().parse().unwrap_or_else(|_| panic!("row {r} {c}: {:?}", t.get(r, c)))
}

#[test]
fn thresholds_rise_with_thickness_and_the_chart_holds_its_folders_thresholds() {
    let out = tmp("rise");
    let o = chart(&out, "6,10");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // Each thickness's scene is the base scene with target.depth_in alone changed.
    for t in [6.0, 10.0] {
        let derived = Base::load(&out.join(format!("h{t}in/scene.toml"))).unwrap();
        let base = std::fs::read_to_string(root().join(SCENE)).unwrap();
        let set = Override { field: "target.depth_in".into(), value: toml::Value::Float(t) };
        let expected = demsweep::scene_file::load_text(&base, Path::new(SCENE), &[set]).unwrap();
        assert_eq!(derived.hash, demsweep::sweep::hash::scene_hash(&expected), "{t} in");
    }
    let c = Table::read_csv(&out.join("chart.csv")).unwrap();
    assert_eq!(c.rows.len(), 4, "two thicknesses × two thresholds");
    for r in 0..4 {
        let t = num(&c, r, "thickness_in");
        let th = Table::read_csv(&out.join(format!("h{t}in/thresholds.csv"))).unwrap();
        let mine = (0..th.rows.len()).find(|&k| th.get(k, "threshold") == c.get(r, "threshold") && th.get(k, "method") == c.get(r, "method")).unwrap();
        for col in ["v_est_fps", "v_low_fps", "v_high_fps", "band_min_fps", "band_max_fps"] {
            let (a, b) = (num(&c, r, col), num(&th, mine, col));
            assert!((a - b).abs() <= 1e-6 * b.abs(), "{t} in {col}: chart {a}, thresholds.csv {b}");
        }
    }
    // Thicker walls need faster projectiles, ours as the formulas'.
    for threshold in ["scabbing", "perforation"] {
        let rows: Vec<usize> = (0..4).filter(|&r| c.get(r, "threshold") == Some(threshold)).collect();
        let (thin, thick) = (rows[0], rows[1]);
        assert!(num(&c, thin, "thickness_in") < num(&c, thick, "thickness_in"));
        assert!(num(&c, thick, "v_est_fps") > num(&c, thin, "v_est_fps") + 10.0, "{threshold}: {:?} then {:?}", c.rows[thin], c.rows[thick]);
        assert!(num(&c, thick, "band_min_fps") > num(&c, thin, "band_min_fps"), "{threshold}: the formulas' band is the thickness's own");
    }
    let png = std::fs::read(out.join("chart.png")).unwrap();
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    assert_eq!((u32::from_be_bytes(png[16..20].try_into().unwrap()), u32::from_be_bytes(png[20..24].try_into().unwrap())), (1600, 800));
    let page = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(page.contains("design chart") && page.contains(c.get(0, "v_est_fps").unwrap()));
    // A rerun finds every run done.
    let again = chart(&out, "6,10");
    assert!(again.status.success() && String::from_utf8_lossy(&again.stdout).contains("0 runs made"), "{}", String::from_utf8_lossy(&again.stdout));
    assert_eq!(Table::read_csv(&out.join("chart.csv")).unwrap(), c);
    std::fs::remove_dir_all(out).unwrap();
}

#[test]
fn bad_thicknesses_are_refused_before_any_run() {
    for (given, says) in [("10", "at least two"), ("6,-1", "must be > 0"), ("6,6", "given twice"), ("6,1e9", "--thickness-in 1000000000"), ("6,x", "--thickness-in")] {
        let out = tmp("bad");
        let o = chart(&out, given);
        let msg = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success() && msg.contains(says), "{given}: {msg}");
        assert!(!out.join("h6in/runs.csv").exists(), "{given}: no run made");
        let _ = std::fs::remove_dir_all(out);
    }
}
