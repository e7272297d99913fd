//! The CI scenes (`sweeps/penetration_ci.toml` and `sweeps/penetration3d_ci.toml`, the calibrated
//! scenes one level down) against their committed outcomes (`results/penetration/outcomes_ci.csv`
//! and `outcomes3d_ci.csv`, written by `scripts/penetration_ci_table.sh`, never by hand). The kernel is deterministic, so the
//! classification and the counts must be exactly as committed and every number to 1e-9. The
//! energy ledger closes within 2 % of the impact energy on the coarse CI scene: the ledger's
//! error is first order in the step (1.25 % → 0.63 % at half the step, level 0, 1500 ft/s),
//! and the CI scene's step is twice the full scene's.

use std::path::Path;

use demsweep::penetration::scene::PenetrationScene;
use demsweep::penetration::{Hooks, row, run};
use demsweep::scene_file::{SceneFile, load};
use demsweep::simulation::Threading;
use demsweep::table::{Table, row::cells};

fn load_scene(path: &str) -> PenetrationScene {
    match load(&Path::new(env!("CARGO_MANIFEST_DIR")).join(path), &[]).unwrap() {
        SceneFile::Penetration(p) => p,
        _ => panic!("{path} is a penetration scene"),
    }
}

fn scene() -> PenetrationScene {
    load_scene("sweeps/penetration_ci.toml")
}

#[test]
fn the_ci_scene_is_the_calibrated_scene_one_level_down() {
    one_level_down("sweeps/penetration.toml", "sweeps/penetration_ci.toml");
}

#[test]
fn the_3d_ci_scene_is_the_calibrated_slab_one_level_down() {
    one_level_down("sweeps/penetration3d.toml", "sweeps/penetration3d_ci.toml");
}

#[test]
fn the_ci_scene_reproduces_its_committed_outcomes() {
    reproduces("sweeps/penetration_ci.toml", "results/penetration/outcomes_ci.csv");
}

#[test]
fn the_3d_ci_scene_reproduces_its_committed_outcomes() {
    reproduces("sweeps/penetration3d_ci.toml", "results/penetration/outcomes3d_ci.csv");
}

fn one_level_down(full: &str, ci: &str) {
    let (full, ci) = (load_scene(full), load_scene(ci));
    assert_eq!((full.penetration.level, ci.penetration.level), (1, 0));
    let mut same = ci.clone();
    same.penetration.level = 1;
    same.penetration.name = full.penetration.name.clone();
    assert_eq!(same, full, "only the level and the name differ");
    assert!(full.concrete.strength_factor != 1.0, "calibrated");
}

/// Each committed row of `table` rerun on `scene` at its velocity.
fn reproduces(scene: &str, table: &str) {
    let golden = Table::read_csv(&Path::new(env!("CARGO_MANIFEST_DIR")).join(table)).unwrap();
    assert!(golden.rows.len() >= 4, "a few velocities");
    let exact = ["v0_fps", "level", "scabbed", "perforated", "scab_fragments", "spall_fragments", "end_reason", "steps", "bonds_broken", "elements"];
    let close = ["depth_in", "depth_rel_in", "scab_mass_lb", "v_residual_fps", "spall_mass_lb", "dt_s", "simulated_s", "energy_error"];
    for r in 0..golden.rows.len() {
        let v0: f64 = golden.get(r, "v0_fps").unwrap().parse().unwrap();
        let mut s = load_scene(scene);
        s.projectile.v0_fps = v0;
        let row = row(&s, Threading::default(), None).unwrap();
        let live: Vec<(String, String)> = cells(&row).unwrap().into_iter().map(|(k, v)| (k, v.text())).collect();
        let get = |name: &str| live.iter().find(|c| c.0 == name).map(|c| c.1.clone()).unwrap_or_else(|| panic!("no column {name}"));
        for name in exact {
            assert_eq!(get(name), golden.get(r, name).unwrap(), "{v0} ft/s: {name}");
        }
        for name in close {
            let (a, b) = (get(name), golden.get(r, name).unwrap().to_string());
            if a.is_empty() || b.is_empty() {
                assert_eq!(a, b, "{v0} ft/s: {name}");
                continue;
            }
            let (a, b): (f64, f64) = (a.parse().unwrap(), b.parse().unwrap());
            assert!((a - b).abs() <= 1e-9 * b.abs().max(1e-12), "{v0} ft/s: {name} live {a:e}, committed {b:e}");
        }
        let e: f64 = get("energy_error").parse().unwrap();
        assert!(e.abs() < 0.02, "{v0} ft/s: the coarse scene's ledger must close within 2 % of the impact energy: {e}");
    }
}

/// Under the default mapping (sectional density) every projectile field acts on the physics it
/// names: twice the weight, twice the mass per unit thickness, goes deeper at 500 ft/s. Under the
/// source's effective density the slice grows with the weight, so the field could not act: it is
/// refused, saying why.
#[test]
fn doubling_the_weight_deepens_the_penetration_and_the_seed_mapping_refuses_it() {
    let mut s = scene();
    s.projectile.v0_fps = 500.0;
    let light = run(&s, Hooks::default()).unwrap().row.outcome.depth_in;
    s.projectile.weight_lb *= 2.0;
    let heavy = run(&s, Hooks::default()).unwrap().row.outcome.depth_in;
    eprintln!("depth at 500 ft/s: {light:.3} in at 15 lb, {heavy:.3} in at 30 lb");
    assert!(heavy > 1.2 * light, "30 lb {heavy} in, 15 lb {light} in");
    s.mapping.rule = demsweep::penetration::scene::MappingRule::SeedEffectiveDensity;
    let e = run(&s, Hooks::default()).err().expect("refused").to_string();
    assert!(e.contains("projectile.weight_lb") && e.contains("seed_effective_density"), "{e}");
}
