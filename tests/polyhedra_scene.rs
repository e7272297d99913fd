//! The rockfill scene: each bad field refused by name, and the reduced layer run through the
//! run loop — the projectile slowed and not sped up, its ledger closed, the same bits on a
//! resumed run as on one that never stopped.

use std::path::Path;

use demsweep::Error;
use demsweep::run::{Options, RunCheckpoint, run_with};
use demsweep::scene::overrides::Override;
use demsweep::scene_file::{SceneFile, load};
use demsweep::simulation::Simulation;

fn small(overrides: &[&str]) -> demsweep::Result<SceneFile> {
    let o: Vec<Override> = overrides.iter().map(|s| Override::parse(s).unwrap()).collect();
    load(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/sweeps/rockfill_small.toml")), &o)
}

#[test]
fn both_scene_files_load_and_each_bad_field_is_refused_by_name() {
    assert!(matches!(small(&[]).unwrap(), SceneFile::Rockfill(_)));
    assert!(matches!(load(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/sweeps/rockfill.toml")), &[]).unwrap(), SceneFile::Rockfill(_)));
    for (set, field) in [
        ("rockfill.duration_s=-1", "rockfill.duration_s"),
        ("rockfill.dt_fraction=1.5", "rockfill.dt_fraction"),
        ("rockfill.every_steps=0", "rockfill.every_steps"),
        ("rockfill.layer.mean_size_m=0", "rockfill.layer.mean_size_m"),
        ("rockfill.layer.spread=0.7", "rockfill.layer.spread"),
        ("rockfill.layer.grade=1.2", "rockfill.layer.grade"),
        ("rockfill.layer.density_kg_per_m3=-2650", "rockfill.layer.density_kg_per_m3"),
        ("rockfill.packing.fraction=0.95", "rockfill.packing.fraction"),
        ("rockfill.packing.lid_pressure_pa=0", "rockfill.packing.lid_pressure_pa"),
        ("rockfill.rock_law.restitution=1.5", "rockfill.rock_law.restitution"),
        ("rockfill.rock_law.friction=-0.1", "rockfill.rock_law.friction"),
        ("rockfill.projectile_law.stiffness=0", "rockfill.projectile_law.stiffness"),
        ("rockfill.projectile_law.exponent=0.5", "rockfill.projectile_law.exponent"),
        ("rockfill.projectile.calibre_m=0", "rockfill.projectile.calibre_m"),
        ("rockfill.projectile.length_m=0.1", "rockfill.projectile.length_m"),
        ("rockfill.projectile.around=2", "rockfill.projectile.around"),
        ("rockfill.projectile.mass_kg=0", "rockfill.projectile.mass_kg"),
        ("rockfill.projectile.speed_mps=-1200", "rockfill.projectile.speed_mps"),
        ("rockfill.projectile.standoff_m=-0.1", "rockfill.projectile.standoff_m"),
    ] {
        match small(&[set]) {
            Err(Error::Input { field: f, message, .. }) => assert_eq!(f, field, "--set {set}: {message}"),
            other => panic!("--set {set} accepted: {other:?}"),
        }
    }
    // An unknown field is named too.
    match small(&["rockfill.projectile.spin_rps=3"]) {
        Err(Error::Input { field, message, .. }) => assert!(field.contains("projectile") || message.contains("spin_rps"), "{field}: {message}"),
        other => panic!("an unknown field accepted: {other:?}"),
    }
}

#[test]
fn the_reduced_layer_slows_the_projectile_and_a_resumed_run_is_the_same() {
    let SceneFile::Rockfill(scene) = small(&[]).unwrap() else { unreachable!() };
    let packed = scene.pack().unwrap();
    let whole = run_with(scene.build_on(&packed).unwrap(), Options::default()).unwrap();
    let s = &whole.summary;
    let get = |k: &str| s.probes.get(k).unwrap();
    println!(
        "{} rocks, fraction {:.3}: residual {:.1} m/s, deflection {:.2}°, yaw {:.2}°, exit {:.3e} s, peak resistance {:.3e} N; \
         {} steps of {:.3e} s in {:.2} s; energy error {:.2e}",
        packed.bodies.len(),
        packed.fraction,
        get("projectile_speed_mps_final"),
        get("deflection_deg_final"),
        get("yaw_deg_final"),
        get("exit_time_s_min"),
        get("resistance_n_max"),
        s.steps,
        s.dt_s,
        s.wall_s,
        s.energy_error
    );
    let v = get("projectile_speed_mps_final");
    assert!(v > 0.0 && v < 1200.0, "residual {v}");
    assert!(get("projectile_speed_mps_max") <= 1200.0 * (1.0 + 1e-9), "sped up");
    assert!(s.energy_error.abs() < 2e-2, "ledger {}", s.energy_error);
    // No walls and no gravity in the event: the momentum the projectile brought is all there
    // is, shared with the rocks, to rounding.
    let bodies = &whole.model.state.bodies;
    let momentum: nalgebra::Vector3<f64> = bodies.iter().map(|b| b.velocity * b.mass).sum();
    let brought = scene.rockfill.projectile.mass_kg * scene.rockfill.projectile.speed_mps;
    let drift = (momentum - nalgebra::Vector3::new(brought, 0.0, 0.0)).norm() / brought;
    println!("momentum: {drift:.1e} of the projectile's off what it brought");
    assert!(drift < 1e-12, "momentum {drift:e}");
    // Stopped at a checkpoint half way and resumed: the same tables.
    let mut saved = None;
    let mut save = |c: &RunCheckpoint| {
        if saved.is_none() {
            saved = Some(c.to_bytes());
        }
        Ok(())
    };
    let half = s.steps / 2;
    let checkpointing = Some(demsweep::run::Checkpointing { every_steps: half, save: &mut save });
    run_with(scene.build_on(&packed).unwrap(), Options { checkpointing, ..Default::default() }).unwrap();
    let c = RunCheckpoint::from_bytes(&saved.unwrap()).unwrap();
    let resumed = run_with(scene.build_on(&packed).unwrap(), Options { resume: Some(&c), ..Default::default() }).unwrap();
    assert!(resumed.values.iter().flatten().zip(whole.values.iter().flatten()).all(|(a, b)| a.to_bits() == b.to_bits()), "the resumed series differs");
    assert_eq!(resumed.model.checkpoint(), whole.model.checkpoint());
}
