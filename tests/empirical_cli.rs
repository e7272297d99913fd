//! `demsweep empirical` as a user runs it: CSV columns, thresholds, the readable table, and a
//! clear error naming the argument (exit code 2) for each class of bad input.

use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_demsweep")).arg("empirical").args(args).output().expect("binary runs")
}

fn stdout(out: &Output) -> String {
    assert!(out.status.success(), "failed: {}", String::from_utf8_lossy(&out.stderr));
    String::from_utf8(out.stdout.clone()).unwrap()
}

const SCENARIO: &[&str] = &[
    "--weight-lb", "15", "--diameter-in", "3.5", "--fc-psi", "3000", "--ft-psi", "300", "--density-pcf", "145",
    "--thickness-in", "30", "--nose", "spherical", "--aggregate-in", "0.75", "--v0", "500..1500", "--step", "50",
];

#[test]
fn csv_sweep_columns_and_cells() {
    let text = stdout(&run(&[SCENARIO, &["--format", "csv"]].concat()));
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("formula,variant,v0_fps,x_in,hs_in,hp_in,valid"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert!(rows.iter().all(|r| r.len() == 7));
    assert_eq!(rows.len(), 22 * 21, "22 formula/variant pairs × 21 velocities");
    let find = |f: &str, v: &str, v0: &str| rows.iter().find(|r| r[0] == f && r[1] == v && r[2] == v0).unwrap().clone();
    // BRL x(500) = 4.88 in (FORMULAS §6), h_p = 1.3x, h_s = 2h_p.
    assert_eq!(find("brl", "hs=2hp", "500"), ["brl", "hs=2hp", "500", "4.878273", "12.683511", "6.341755", "unstated"]);
    // Degen defines only h_p; Bechtel only h_s; x-only formulas leave both thicknesses empty.
    let degen = find("degen", "standard", "1000");
    assert_eq!((degen[3], degen[4], degen[6]), ("", "", "false"));
    assert!(!degen[5].is_empty());
    let bechtel = find("bechtel", "standard", "750");
    assert_eq!((bechtel[3], bechtel[5]), ("", ""));
    let whiffen = find("whiffen", "standard", "1500");
    assert_eq!((whiffen[4], whiffen[5], whiffen[6]), ("", "", "true"));
    // Adeli–Amin has no value beyond I = 21 (here above ~700 ft/s): empty, and out of range.
    assert_eq!(&find("adeli-amin", "standard", "1500")[3..], ["", "", "", "false"]);
    let velocities: Vec<&str> = rows.iter().filter(|r| r[0] == "ace").map(|r| r[2]).collect();
    assert_eq!(velocities.first(), Some(&"500"));
    assert_eq!(velocities.last(), Some(&"1500"));
}

#[test]
fn csv_thresholds() {
    let text = stdout(&run(&[SCENARIO, &["--format", "csv", "--thresholds"]].concat()));
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("formula,variant,v_scab_fps,v_perf_fps,valid"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 18, "every formula/variant defining h_s or h_p");
    let get = |f: &str, v: &str| rows.iter().find(|r| r[0] == f && r[1] == v).unwrap().clone();
    assert_eq!(get("adeli-amin", "standard")[2..4], ["not reachable", "not reachable"]);
    assert_eq!(get("bechtel", "standard")[3], "");
    assert_eq!(get("degen", "standard")[2], "");
    let hughes = get("hughes", "ft-given");
    let vs: f64 = hughes[2].parse().unwrap();
    let vp: f64 = hughes[3].parse().unwrap();
    assert_eq!((vs.round(), vp.round(), hughes[4]), (1117.0, 1320.0, "true"));
    assert_eq!(get("chang", "standard")[4], "false");
    assert_eq!(get("petry", "plain")[4], "unstated");
}

#[test]
fn defaults_are_the_report_scenario() {
    let defaults = stdout(&run(&["--format", "csv", "--thresholds"]));
    let explicit = stdout(&run(&[SCENARIO, &["--format", "csv", "--thresholds"]].concat()));
    assert_eq!(defaults, explicit);
}

#[test]
fn nose_changes_the_nose_dependent_formulas_only() {
    let flat = stdout(&run(&["--format", "csv", "--thresholds", "--nose", "flat"]));
    let ndrc = flat.lines().find(|l| l.starts_with("ndrc,")).unwrap();
    assert!(ndrc.starts_with("ndrc,standard,2012."), "{ndrc}");
    let brl = flat.lines().find(|l| l.starts_with("brl,hs=2hp,")).unwrap();
    assert!(brl.starts_with("brl,hs=2hp,955."), "{brl}");
}

#[test]
fn readable_tables() {
    let sweep = stdout(&run(&["--v0", "500..600"]));
    assert!(sweep.contains("f'c = 3000 psi"));
    assert!(sweep.lines().any(|l| l.starts_with("formula") && l.contains("h_s in") && l.contains("valid")));
    let brl = sweep.lines().find(|l| l.starts_with("brl") && l.contains("hs=2hp")).unwrap();
    assert!(brl.contains("4.88") && brl.contains("12.68"), "{brl}");
    let th = stdout(&run(&["--thresholds"]));
    let chang = th.lines().find(|l| l.starts_with("chang")).unwrap();
    assert!(chang.contains("1428") && chang.contains("2425") && chang.contains("no (V = "), "{chang}");
    assert!(th.lines().any(|l| l.starts_with("adeli-amin") && l.contains("not reachable")));
}

/// Non-zero exit (2, bad input) and a message naming the argument.
fn rejects(args: &[&str], argument: &str, needle: &str) {
    let out = run(args);
    assert_eq!(out.status.code(), Some(2), "{args:?} should exit 2");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains(argument) && err.contains(needle), "{args:?}: {err}");
    assert!(out.stdout.is_empty(), "{args:?} printed a table before failing");
}

#[test]
fn non_positive_inputs_name_the_argument() {
    rejects(&["--weight-lb", "-1"], "`--weight-lb`", "must be > 0, got -1");
    rejects(&["--weight-lb", "0"], "`--weight-lb`", "must be > 0, got 0");
    rejects(&["--diameter-in", "0"], "`--diameter-in`", "must be > 0");
    rejects(&["--fc-psi", "-3000"], "`--fc-psi`", "must be > 0, got -3000");
    rejects(&["--ft-psi", "0"], "`--ft-psi`", "must be > 0");
    rejects(&["--thickness-in", "-30"], "`--thickness-in`", "must be > 0");
    rejects(&["--density-pcf", "0"], "`--density-pcf`", "must be > 0");
    rejects(&["--aggregate-in", "0"], "`--aggregate-in`", "must be > 0");
    rejects(&["--weight-lb", "nan"], "`--weight-lb`", "must be > 0, got NaN");
}

#[test]
fn unknown_nose() {
    rejects(&["--nose", "ogival"], "`--nose`", "unknown nose `ogival`; expected one of flat, blunt, spherical, very-sharp");
}

#[test]
fn bad_ranges() {
    rejects(&["--v0", "1500..500"], "`--v0`", "reversed range 1500..500");
    rejects(&["--v0", "fast"], "`--v0`", "not a range");
    rejects(&["--v0", "-500..1500"], "`--v0`", "must be > 0");
    rejects(&["--step", "0"], "`--step`", "must be > 0, got 0");
}

#[test]
fn unparsable_number_is_a_usage_error() {
    rejects(&["--weight-lb", "heavy"], "--weight-lb", "heavy");
    rejects(&["--format", "xml"], "--format", "xml");
}
