//! Bad input and numerical failure: each class gets a clear message naming the field (or the
//! element and the step), a non-zero exit, and nothing already written is lost.

use std::path::{Path, PathBuf};
use std::process::Command;

use demsweep::Error;
use demsweep::scene::Scene;

const BASE: &str = r#"
[scene]
name = "block"
plane = "strain"
thickness_m = 1.0
duration_s = 2e-4

[[material]]
name = "concrete"
density_kg_per_m3 = 2400.0
youngs_modulus_pa = 30e9
poisson_ratio = 0.2
tensile_strength_pa = 3e6
fracture_toughness_pa_sqrt_m = 1e6
failure = "strength_energy"

[[body]]
name = "block"
material = "concrete"
lattice = "close_packed"
element_radius_m = 0.01
velocity_mps = [0.0, -5.0]
rect = { x_min_m = 0.0, x_max_m = 0.2, y_min_m = 0.0, y_max_m = 0.2 }

[[fix]]
name = "base"
rect = { x_min_m = -1.0, x_max_m = 1.0, y_min_m = -1.0, y_max_m = 0.015 }

[[probe]]
name = "kinetic_energy_j"
quantity = "kinetic_energy_j"
"#;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("demsweep-cli-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn run_scene(dir: &Path, text: &str) -> (i32, String) {
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_demsweep"))
        .args(["run", "--quiet", "--out"])
        .arg(dir.join("out"))
        .arg(&scene)
        .output()
        .unwrap();
    (out.status.code().unwrap_or(-1), String::from_utf8_lossy(&out.stderr).into_owned())
}

#[test]
fn a_good_scene_runs_and_writes_its_tables() {
    let dir = scratch("good");
    let (code, err) = run_scene(&dir, BASE);
    assert_eq!(code, 0, "{err}");
    assert!(dir.join("out/block/summary.csv").exists() && dir.join("out/block/series.csv").exists());
}

#[test]
fn bad_field_names_file_field_and_range() {
    let dir = scratch("field");
    let (code, err) = run_scene(&dir, &BASE.replace("poisson_ratio = 0.2", "poisson_ratio = 0.7"));
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("scene.toml") && err.contains("material.concrete.poisson_ratio") && err.contains("[0, 0.5)"), "{err}");
    let (code, err) = run_scene(&dir, &BASE.replace("element_radius_m = 0.01", "element_radius_m = \"big\""));
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("body.element_radius_m"), "{err}");
    let (code, err) = run_scene(&dir, &BASE.replace("thickness_m = 1.0", "thickness_m = 1.0\ncolour = \"red\""));
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("colour"), "{err}");
    let (code, err) = run_scene(&dir, &BASE.replace("element_radius_m = 0.01", "element_radius_m = -0.01"));
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("body[0].element_radius_m") && err.contains("> 0"), "{err}");
    assert!(!dir.join("out").exists(), "nothing may be written for a refused scene");
}

#[test]
fn poisson_above_one_third_on_a_hexagonal_lattice_is_refused() {
    let dir = scratch("poisson");
    // Plane strain, ν = 0.3: ν* = 0.43.
    let (code, err) = run_scene(&dir, &BASE.replace("poisson_ratio = 0.2", "poisson_ratio = 0.3"));
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("concrete") && err.contains("0.4286") && err.contains("exceeds 1/3") && err.contains("clamp_to_one_third"), "{err}");
    // The named fallback is accepted.
    let (code, err) = run_scene(
        &dir,
        &BASE.replace("poisson_ratio = 0.2", "poisson_ratio = 0.3\npoisson_policy = \"clamp_to_one_third\""),
    );
    assert_eq!(code, 0, "{err}");
}

#[test]
fn a_step_above_the_bound_is_refused_with_the_bound() {
    let dir = scratch("step");
    let (code, err) = run_scene(&dir, &format!("{BASE}\n[time_step]\ndt_s = 1e-5\n").replace("[[probe]]", "[[probe]]"));
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("exceeds the stability bound") && err.contains("1.000000e-5"), "{err}");
}

#[test]
fn forced_unstable_step_is_caught_and_nothing_is_overwritten() {
    let dir = scratch("blowup");
    // A good run first: its tables must survive the failed one.
    let (code, err) = run_scene(&dir, BASE);
    assert_eq!(code, 0, "{err}");
    let summary = dir.join("out/block/summary.csv");
    let before = std::fs::read(&summary).unwrap();
    // Elastic bonds: with breakable ones the growing modes tear the block apart instead (the
    // plateau caps the forces), which is why the step is refused in the first place.
    let forced = BASE
        .replace("failure = \"strength_energy\"", "failure = \"none\"")
        .replace("duration_s = 2e-4", "duration_s = 2e-3")
        .replace("[[probe]]", "[time_step]\ndt_s = 8e-6\nrefuse_unstable = false\n\n[[probe]]");
    let (code, err) = run_scene(&dir, &forced);
    assert_eq!(code, 3, "{err}");
    assert!(err.contains("blow-up at step") && err.contains("element") && err.contains("stability bound"), "{err}");
    assert_eq!(std::fs::read(&summary).unwrap(), before, "the earlier table was changed");
    let leftovers: Vec<_> = std::fs::read_dir(dir.join("out/block")).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(leftovers.len(), 2, "no temporary files: {leftovers:?}");
}

#[test]
fn nan_injected_into_the_state_names_the_element_and_the_step() {
    let scene = Scene::from_toml(BASE, Path::new("inline.toml")).unwrap();
    let mut built = scene.build().unwrap();
    let m = &mut built.model;
    m.run_steps(10).unwrap();
    m.state.vel[37][1] = f64::NAN;
    match m.step() {
        Err(e @ Error::BlowUp { step: 10, element: 37, .. }) => {
            assert!(e.to_string().contains("step 10") && e.to_string().contains("element 37"), "{e}");
            assert_eq!(e.exit_code(), 3);
        }
        other => panic!("expected a blow-up at step 10, element 37; got {other:?}"),
    }
}
