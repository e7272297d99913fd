//! Golden tables under results/validation/, written by `demsweep validate` (never by hand).
#![allow(dead_code)]

use std::path::Path;

use demsweep::analysis::richardson;
use demsweep::table::Table;

/// Read a golden table.
pub fn table(name: &str) -> Table {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("results/validation").join(format!("{name}.csv"));
    Table::read_csv(&path).unwrap_or_else(|e| panic!("golden table {}: {e}", path.display()))
}

/// The figure of each level row (column `figure`), in level order.
pub fn levels(t: &Table, figure: &str) -> Vec<(u32, f64)> {
    let (l, f) = (t.column("level").unwrap(), t.column(figure).unwrap());
    t.rows.iter().filter_map(|r| Some((r[l].parse().ok()?, r[f].parse().unwrap()))).collect()
}

/// The Richardson row's extrapolate and order, checked against a recomputation from the level
/// rows (a hand-edited table fails here).
pub fn richardson_row(t: &Table, figure: &str, alpha: f64) -> (f64, f64) {
    let (l, f, w) = (t.column("level").unwrap(), t.column(figure).unwrap(), t.column("wall_s").unwrap());
    let row = t.rows.iter().find(|r| r[l] == "richardson").expect("richardson row");
    let ext: f64 = row[f].parse().unwrap();
    let order: f64 = row[w].trim_start_matches("order=").parse().unwrap();
    let v = levels(t, figure);
    assert_eq!(v.len(), 3, "three levels");
    let c = richardson([v[0].1, v[1].1, v[2].1], alpha).expect("convergent");
    assert!((c.extrapolate / ext - 1.0).abs() < 1e-8 && (c.order - order).abs() < 1e-3, "richardson row does not follow from the levels");
    (ext, order)
}

/// Relative agreement of a live figure with its golden row.
pub fn assert_matches(live: f64, golden: f64, what: &str) {
    assert!((live / golden - 1.0).abs() < 1e-6, "{what}: live {live:.9e} vs golden {golden:.9e}");
}

/// A figure at levels 0, 1 and 2, run now (level 2 is too slow for CI: the tests that call
/// this are `#[ignore]`d and run in `scripts/validation.sh`).
pub fn live_levels(figure_at: impl Fn(u32) -> f64) -> Vec<(u32, f64)> {
    (0..=2).map(|l| (l, figure_at(l))).collect()
}

/// The Richardson extrapolate and observed order of three levels refined by `alpha`.
pub fn richardson_of(v: &[(u32, f64)], alpha: f64) -> (f64, f64) {
    assert_eq!(v.len(), 3, "three levels");
    let c = richardson([v[0].1, v[1].1, v[2].1], alpha).expect("convergent");
    (c.extrapolate, c.order)
}
