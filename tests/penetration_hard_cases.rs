//! The penetration scene at its edges: very fast and oblique impacts, a projectile released at
//! the surface or inside the target, a target one element thick, a fragment that flies far
//! away, and bad overrides from the command line. Each is cheap (level 0, short beams) and each
//! asserts what must hold, not only that nothing crashed.

use std::path::PathBuf;
use std::process::Command;

use demsweep::penetration::scene::PenetrationScene;
use demsweep::kernel::contact::Bond;
use demsweep::penetration::outcome::Detector;
use demsweep::penetration::{Finished, Hooks, run};
use demsweep::units::{M_PER_IN, fps_to_mps};

fn scene(length_in: f64, depth_in: f64, v0_fps: f64) -> PenetrationScene {
    let mut s = PenetrationScene::with_name("hard");
    s.penetration.level = 0;
    // Rows of the regular lattice (one element thick means one row).
    s.target.arrangement = demsweep::material::Arrangement::ClosePacked;
    s.target.length_in = length_in;
    s.target.depth_in = depth_in;
    s.projectile.v0_fps = v0_fps;
    s.concrete.strength_factor = 20.0;
    s
}

fn finite(f: &Finished<demsweep::kernel::Model>) -> bool {
    f.model.state.pos.iter().chain(&f.model.state.vel).all(|v| v.iter().all(|x| x.is_finite()))
}

#[test]
fn at_3000_fps_the_projectile_perforates_without_tunnelling_or_nan() {
    // At a third of the usual step: the ledger's error is first order in the distance a
    // contact closes per step, which at 3000 ft/s on this coarse mesh is 0.3 R at 0.9 of the
    // limit (with projectile elements as large as the concrete's the limit is the concrete's,
    // and 1.21 % at half of it).
    let mut s = scene(48.0, 12.0, 3000.0);
    s.penetration.safety = 0.3;
    let f = run(&s, Hooks::default()).unwrap();
    let (o, r) = (&f.row.outcome, &f.row.run);
    assert!(finite(&f));
    assert!(o.perforated, "{o:?}");
    assert_eq!(r.end_reason, "perforated");
    // It went through the material, not past it: it lost speed and broke the bonds on its path
    // (at least one per row it crossed: 12 in of R = 0.5 in rows is 13 rows).
    assert!(o.v_residual_fps < 0.97 * 3000.0 && o.v_residual_fps > 0.0, "residual {} ft/s", o.v_residual_fps);
    assert!(r.bonds_broken > 13, "{} bonds broken", r.bonds_broken);
    assert!(r.energy_error.abs() < 0.01, "energy error {}", r.energy_error);
}

#[test]
fn an_oblique_impact_at_45_degrees_runs_to_a_settled_outcome_with_the_ledger_closed() {
    let mut s = scene(48.0, 18.0, 1000.0);
    s.projectile.angle_deg = 45.0;
    let f = run(&s, Hooks::default()).unwrap();
    let (o, r) = (&f.row.outcome, &f.row.run);
    assert!(finite(&f));
    assert_ne!(r.end_reason, "time_cap", "{o:?}");
    assert!(o.depth_in > 0.5, "it went in: {o:?}");
    // The ledger's error is first order in Δt (contacts switching on and off within a step):
    // above the 1 % line at the default step (1.14 % at half of it since the projectile's
    // elements are as large as the concrete's, which lets the step grow to the concrete's
    // limit), at half the step at half that. A ledger that missed a mechanism would not shrink
    // with the step: both are asserted, at half and a quarter of the default.
    s.penetration.safety = 0.45;
    let f = run(&s, Hooks::default()).unwrap();
    let (o, r) = (&f.row.outcome, &f.row.run);
    let mut half = s.clone();
    half.penetration.safety = 0.225;
    let h = run(&half, Hooks::default()).unwrap();
    let (e1, e2) = (r.energy_error.abs(), h.row.run.energy_error.abs());
    assert!(e2 < 0.01, "energy error at half the step {e2}");
    assert!((1.5..2.5).contains(&(e1 / e2)), "energy error {e1} at the default step, {e2} at half: not first order");
    assert_eq!(h.row.outcome.perforated, o.perforated, "the outcome changed with the step");
    // The tip was placed on the front face at mid-span, the axis 45° from the normal.
    let axis = f.detector.layout.axis;
    assert!((axis[0] - (0.5f64).sqrt()).abs() < 1e-12 && (axis[1] + (0.5f64).sqrt()).abs() < 1e-12);
    assert!((f.detector.layout.impact_x_m - 24.0 * M_PER_IN).abs() < 1e-12);
}

#[test]
fn a_projectile_released_exactly_at_the_surface_runs() {
    let mut s = scene(36.0, 12.0, 500.0);
    s.projectile.standoff_in = 0.0;
    let f = run(&s, Hooks::default()).unwrap();
    assert!(finite(&f));
    assert!(f.row.outcome.depth_in > 0.0);
    assert!(f.row.run.energy_error.abs() < 0.01);
}

#[test]
fn a_projectile_starting_inside_the_target_is_refused_naming_both_bodies() {
    let mut s = scene(36.0, 12.0, 500.0);
    s.projectile.standoff_in = -1.0;
    let e = run(&s, Hooks::default()).unwrap_err().to_string();
    assert!(e.contains("\"target\"") && e.contains("\"projectile\"") && e.contains("overlap"), "{e}");
}

#[test]
fn a_target_one_element_thick_is_perforated() {
    let s = scene(36.0, 1.0, 500.0);
    let (_, layout) = s.to_scene().unwrap();
    let (kernel, _) = s.to_scene().unwrap();
    let built = kernel.build().unwrap();
    let t = built.model.body("target").unwrap().elements.clone();
    let rows: std::collections::BTreeSet<i64> = t.clone().map(|e| (built.model.el.initial[e][1] * 1e6).round() as i64).collect();
    assert_eq!(rows.len(), 1, "one row of elements");
    assert!(layout.front_y_m - layout.back_y_m < 1.01 * M_PER_IN);
    let f = run(&s, Hooks::default()).unwrap();
    assert!(f.row.outcome.perforated, "{:?}", f.row.outcome);
    assert!(f.row.outcome.v_residual_fps > 300.0, "a single row barely slows a 15 lb projectile: {:?}", f.row.outcome);
    assert!(f.row.run.energy_error.abs() < 0.01);
}

#[test]
fn a_fragment_flying_far_outside_the_initial_bounds_is_followed_exactly() {
    let s = scene(24.0, 6.0, 500.0);
    let (kernel, layout) = s.to_scene().unwrap();
    let mut m = kernel.build().unwrap().model;
    let det = Detector::new(&m, layout, s.outcome.clone()).unwrap();
    // A back-face element at mid-span, cut loose and fired down at 2 km/s.
    let t = m.body("target").unwrap().elements.clone();
    let e = t.clone().filter(|&e| m.el.initial[e][1] < 0.6 * M_PER_IN).min_by(|&a, &b| (m.el.initial[a][0] - 12.0 * M_PER_IN).abs().total_cmp(&(m.el.initial[b][0] - 12.0 * M_PER_IN).abs())).unwrap();
    for c in m.state.contacts.list.iter_mut() {
        if c.i as usize == e || c.j as usize == e {
            c.bond = Bond::Frictional;
        }
    }
    m.state.vel[e] = [0.0, -2000.0, 0.0];
    let y0 = m.state.pos[e][1];
    let steps = 2000;
    m.run_steps(steps).unwrap();
    let flown = y0 - m.state.pos[e][1];
    let expected = 2000.0 * steps as f64 * m.dt_s();
    assert!(expected > 5.0, "it must leave the 24 in beam far behind: {expected} m");
    assert!((flown - expected).abs() < 1e-9 * expected, "free flight: {flown} m, expected {expected} m");
    let l = det.look(&m);
    assert!(l.scab.0 >= 1, "the far element is a scab fragment");
    // The broad phase has no grid to blow up; rebuilds stay few (the fast element has a wide
    // margin of its own).
    assert!(m.state.rebuilds < steps / 10, "{} full rebuilds in {steps} steps", m.state.rebuilds);
    let _ = fps_to_mps(0.0);
}

// ---- bad overrides on the command line ----

const TINY: &str = "[penetration]\nname = \"tiny\"\nlevel = 0\nmax_time_s = 2e-4\n\n[target]\nlength_in = 12.0\ndepth_in = 3.0\n\n[concrete]\nstrength_factor = 10.0\n";

fn demsweep(dir: &std::path::Path, set: &[&str]) -> (i32, String) {
    let mut c = Command::new(env!("CARGO_BIN_EXE_demsweep"));
    c.args(["run", "--quiet", "--out"]).arg(dir.join("out")).arg(dir.join("tiny.toml"));
    for s in set {
        c.args(["--set", s]);
    }
    let out = c.output().unwrap();
    (out.status.code().unwrap_or(-1), String::from_utf8_lossy(&out.stderr).into_owned())
}

fn scratch() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("demsweep-hard-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("tiny.toml"), TINY).unwrap();
    dir
}

#[test]
fn bad_overrides_are_refused_with_the_field_and_nothing_written_is_touched() {
    let dir = scratch();
    let (code, err) = demsweep(&dir, &["projectile.v0_fps=800"]);
    assert_eq!(code, 0, "{err}");
    let summary = dir.join("out/tiny/summary.csv");
    let before = std::fs::read(&summary).unwrap();
    assert!(String::from_utf8_lossy(&before).contains("8.000000000e2"), "the override took effect");
    let cases: [(&str, &[&str]); 5] = [
        ("projectile.speed_fps=900", &["projectile.speed_fps", "unknown field"]),
        ("projectile.v0_mps=250", &["v0_mps", "did you mean `v0_fps`"]),
        ("projectile.angle_deg=95", &["projectile.angle_deg", "(−80, 80)"]),
        ("projectile.v0_fps=fast", &["projectile.v0_fps", "given by --set"]),
        ("penetration.level=9", &["penetration.level", "0..=4"]),
    ];
    for (set, needles) in cases {
        let (code, err) = demsweep(&dir, &[set]);
        assert_ne!(code, 0, "--set {set} must fail");
        for n in needles {
            assert!(err.contains(n), "--set {set}: message lacks {n:?}: {err}");
        }
        assert_eq!(std::fs::read(&summary).unwrap(), before, "--set {set} touched the earlier summary");
    }
    let (code, err) = demsweep(&dir, &["novalue"]);
    assert_ne!(code, 0);
    assert!(err.contains("FIELD=VALUE"), "{err}");
    let leftovers: Vec<_> = std::fs::read_dir(dir.join("out/tiny")).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(leftovers.len(), 1, "only the summary: {leftovers:?}");
}
