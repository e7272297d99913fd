//! The penetration scene in 3D (`penetration.dim = 3`): the projectile is the cylinder of steel
//! its weight makes, the slab and its supports are where the fields say, the runs end in an
//! outcome at the edges of the scene's range (3000 ft/s, 30° obliquity, a slab two spheres
//! thick, a projectile released touching the face), bit for bit on one and two threads, and
//! every bad field is refused by name; a graded slab is fine under the impact and coarse at its
//! edges. Each run is cheap: level 0 (spheres of 1 in under the impact, 4 in away from it, or
//! a uniform 2 in) on a narrow slab.

use demsweep::penetration::scene::PenetrationScene;
use demsweep::penetration::slab::{Edges, Slab};
use demsweep::penetration::{Finished, Hooks, run3};
use demsweep::simulation::{Bodies, Simulation, Threading};
use demsweep::units::M_PER_IN;

/// A 3D scene of the defaults at level 0 on a `side_in` square slab.
fn scene(side_in: f64, depth_in: f64, v0_fps: f64) -> PenetrationScene {
    let mut s = PenetrationScene::with_name("hard3d");
    s.penetration.dim = 3;
    s.penetration.level = 0;
    s.target.length_in = side_in;
    s.target.depth_in = depth_in;
    s.projectile.v0_fps = v0_fps;
    s.concrete.strength_factor = 2.0;
    s
}

/// `s` with a uniform slab of 2 in spheres at level 0 (1 in at level 1).
fn uniform(mut s: PenetrationScene) -> PenetrationScene {
    s.slab = Some(Slab { element_radius_in: 1.0, max_element_radius_in: 1.0, ..Slab::default() });
    s
}

fn finite(f: &Finished<demsweep::kernel3d::Model>) -> bool {
    let m = &f.model;
    (0..m.element_count()).all(|e| m.position_m(e).iter().chain(&m.velocity_mps(e)).all(|x| x.is_finite()))
}

#[test]
fn the_projectile_is_the_steel_cylinder_its_weight_makes() {
    let s = scene(40.0, 30.0, 500.0);
    // Independently: 15 lb of steel at 7.33e-4 lb·s²/in⁴ (g = 386.0886 in/s²: 0.2830 lb/in³)
    // is 53.00 in³; a 3.5 in calibre with a hemispherical nose holds (2/3)π a³ in the nose and
    // π a² per inch behind it.
    let a = 1.75f64;
    let volume = 15.0 / (7.33e-4 * 386.0886);
    let nose = 2.0 / 3.0 * std::f64::consts::PI * a.powi(3);
    let length = a + (volume - nose) / (std::f64::consts::PI * a * a);
    let got = s.projectile_length3_in().unwrap();
    // (g to 7 digits: 2.5e-7 in apart from the code's conversion.)
    assert!((got - length).abs() < 1e-5, "length {got} in against {length} in");
    assert!((got - 6.09).abs() < 0.01, "{got}");
    let (kernel, layout) = s.to_scene3().unwrap();
    let built = kernel.build().unwrap();
    let m = &built.model;
    let p = m.body("projectile").unwrap();
    let mass: f64 = p.clone().map(|e| m.mass_kg(e)).sum();
    assert!((mass / 0.45359237 - 15.0).abs() < 1e-9, "{} lb", mass / 0.45359237);
    // Released above the face by its standoff (0.01 in), tip first, at the slab's centre.
    let lowest = p.clone().map(|e| m.position_m(e)[1] - m.radius_m(e)).fold(f64::INFINITY, f64::min);
    assert!((lowest - layout.front_y_m - 0.01 * M_PER_IN).abs() < 1e-9, "{lowest} against {}", layout.front_y_m);
    assert!((layout.impact_x_m - 20.0 * M_PER_IN).abs() < 1e-12 && (layout.impact_z_m - 20.0 * M_PER_IN).abs() < 1e-12);
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for e in p {
        let x = m.position_m(e);
        for k in 0..3 {
            lo[k] = lo[k].min(x[k]);
            hi[k] = hi[k].max(x[k]);
        }
    }
    let centre = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[2] + hi[2])];
    assert!((centre[0] - layout.impact_x_m).abs() < 1.0 * M_PER_IN && (centre[1] - layout.impact_z_m).abs() < 1.0 * M_PER_IN, "{centre:?}");
    // The front face is the top of the slab's top spheres, within a radius of 30 in.
    assert!((layout.front_y_m / M_PER_IN - 30.0).abs() < 2.0, "{}", layout.front_y_m / M_PER_IN);
}

#[test]
fn clamped_edges_hold_the_side_bands_and_simple_supports_the_back_edges_only() {
    let count = |edges: Edges| {
        let mut s = scene(40.0, 30.0, 500.0);
        s.slab = Some(Slab { edges, element_radius_in: 1.0, max_element_radius_in: 1.0, ..Slab::default() });
        let built = s.to_scene3().unwrap().0.build().unwrap();
        let m = built.model;
        let t = m.body("target").unwrap();
        let held: Vec<usize> = t.filter(|&e| m.held(e)).collect();
        for &e in &held {
            let x = m.initial_m(e).map(|v| v / M_PER_IN);
            // Within the band (1 in) plus a mean radius (2 in) of a side face.
            let near_side = x[0] < 3.0 + 1e-6 || x[0] > 37.0 - 1e-6 || x[2] < 3.0 + 1e-6 || x[2] > 37.0 - 1e-6;
            assert!(near_side, "{x:?} is held but not at a side face");
            if edges == Edges::SimplySupported {
                assert!(x[1] < 3.0 + 1e-6, "{x:?} is held but not at the back face");
            }
        }
        held.len()
    };
    let (clamped, supported) = (count(Edges::Clamped), count(Edges::SimplySupported));
    assert!(supported > 0 && clamped > 3 * supported, "clamped {clamped}, supported {supported}");
}

#[test]
fn at_3000_fps_the_projectile_perforates_without_tunnelling_or_nan() {
    let f = run3(&scene(40.0, 16.0, 3000.0), Hooks::default()).unwrap();
    let (o, r) = (&f.row.outcome, &f.row.run);
    assert!(finite(&f));
    assert!(o.perforated, "{o:?}");
    // Once through, the run ends when it is clear of the back face or when the debris it pushes
    // no longer slows it.
    assert!(["perforated", "unresisted"].contains(&r.end_reason.as_str()), "{}: {o:?}", r.end_reason);
    // Through the material, not past it: it slowed and broke the bonds on its path (at least
    // one per layer of the 16 in: 4 layers of 4 in spheres).
    assert!(o.v_residual_fps > 0.0 && o.v_residual_fps < 0.97 * 3000.0, "residual {} ft/s", o.v_residual_fps);
    assert!(r.bonds_broken > 4, "{} bonds broken", r.bonds_broken);
    assert!(r.energy_error.abs() < 0.01, "energy error {}", r.energy_error);
}

#[test]
fn a_30_degree_oblique_impact_runs_to_a_settled_outcome_with_the_ledger_closed() {
    let mut s = scene(40.0, 30.0, 1000.0);
    s.projectile.angle_deg = 30.0;
    let f = run3(&s, Hooks::default()).unwrap();
    let (o, r) = (&f.row.outcome, &f.row.run);
    assert!(finite(&f));
    assert_ne!(r.end_reason, "time_cap", "{o:?}");
    assert!(o.depth_in > 0.2, "it went in: {o:?}");
    assert!(r.energy_error.abs() < 0.01, "energy error {}", r.energy_error);
    assert_eq!(f.row.angle_deg, 30.0);
}

#[test]
fn a_slab_two_spheres_thick_is_perforated_at_1000_fps() {
    // Two mean diameters of R = 2 in: 8 in.
    let f = run3(&uniform(scene(40.0, 8.0, 1000.0)), Hooks::default()).unwrap();
    let (o, r) = (&f.row.outcome, &f.row.run);
    assert!(finite(&f));
    assert!(o.perforated && o.scabbed, "{o:?}");
    assert!(o.v_residual_fps > 0.0 && o.v_residual_fps < 1000.0, "{o:?}");
    assert!(r.energy_error.abs() < 0.01, "energy error {}", r.energy_error);
}

#[test]
fn a_projectile_released_touching_the_face_runs_and_one_inside_is_refused() {
    let mut s = scene(40.0, 30.0, 500.0);
    s.projectile.standoff_in = 0.0;
    let f = run3(&s, Hooks::default()).unwrap();
    assert!(finite(&f));
    assert!(f.row.outcome.depth_in > 0.0, "{:?}", f.row.outcome);
    assert!(f.row.run.energy_error.abs() < 0.01, "energy error {}", f.row.run.energy_error);
    s.projectile.standoff_in = -6.0;
    let e = run3(&s, Hooks::default()).unwrap_err().to_string();
    assert!(e.contains("projectile.standoff_in") && e.contains("overlap"), "{e}");
}

#[test]
fn one_and_two_threads_give_the_same_bits() {
    let s = scene(40.0, 30.0, 1000.0);
    let one = run3(&s, Hooks { threading: Threading::Serial, ..Default::default() }).unwrap();
    let two = rayon::ThreadPoolBuilder::new().num_threads(2).build().unwrap().install(|| run3(&s, Hooks { threading: Threading::Pool, ..Default::default() }).unwrap());
    assert_eq!(one.row.outcome, two.row.outcome);
    assert_eq!(one.row.run.steps, two.row.run.steps);
    assert_eq!(one.model.checkpoint(), two.model.checkpoint());
}

#[test]
fn bad_fields_are_refused_by_name() {
    let refused = |edit: &dyn Fn(&mut PenetrationScene), field: &str| {
        let mut s = scene(40.0, 30.0, 500.0);
        edit(&mut s);
        let e = s.to_scene3().map(|_| ()).unwrap_err().to_string();
        assert!(e.contains(field), "expected {field} in: {e}");
    };
    refused(&|s| s.penetration.dim = 4, "penetration.dim");
    refused(&|s| s.penetration.level = 4, "penetration.level");
    refused(&|s| s.mapping.rule = demsweep::penetration::scene::MappingRule::Thickness, "mapping");
    refused(&|s| s.projectile.element_radius_in = 0.5, "projectile.element_radius_in");
    refused(&|s| s.slab = Some(Slab { element_radius_in: 0.0, ..Slab::default() }), "slab.element_radius_in");
    refused(&|s| s.slab = Some(Slab { projectile_element_radius_in: Some(3.0), ..Slab::default() }), "slab.projectile_element_radius_in");
    refused(&|s| s.slab = Some(Slab { steel_density_lbs2_per_in4: -1.0, ..Slab::default() }), "slab.steel_density_lbs2_per_in4");
    refused(&|s| s.slab = Some(Slab { max_element_radius_in: 0.4, ..Slab::default() }), "slab.max_element_radius_in");
    refused(&|s| s.slab = Some(Slab { fine_radius_in: -1.0, ..Slab::default() }), "slab.fine_radius_in");
    refused(&|s| s.slab = Some(Slab { radius_growth: f64::NAN, ..Slab::default() }), "slab.radius_growth");
    refused(&|s| s.slab = Some(Slab { damping_ratio: 0.5, ..Slab::default() }), "slab.damping_ratio");
    refused(&|s| s.slab = Some(Slab { damping_ratio: -0.01, ..Slab::default() }), "slab.damping_ratio");
    refused(&|s| s.projectile.weight_lb = 0.5, "projectile.weight_lb");
    refused(&|s| s.target.depth_in = 6.0, "target.depth_in");
    refused(&|s| s.target.length_in = 10.0, "target.length_in");
    refused(&|s| s.concrete.poisson_ratio = 0.45, "poisson_ratio");
    // A 2D scene does not read [slab].
    let mut s = scene(40.0, 30.0, 500.0);
    s.penetration.dim = 2;
    s.slab = Some(Slab::default());
    assert!(s.validate().unwrap_err().to_string().contains("slab"));
    // An unknown edge condition is refused by the file's parser, naming the field.
    let text = "[penetration]\nname = \"x\"\ndim = 3\n[slab]\nedges = \"hinged\"\n";
    let e = demsweep::scene_file::load_text(text, std::path::Path::new("x.toml"), &[]).unwrap_err().to_string();
    assert!(e.contains("edges") || e.contains("hinged"), "{e}");
}

#[test]
fn the_default_projectile_is_made_of_enough_spheres_at_every_level() {
    for level in 0..=1 {
        let mut s = scene(40.0, 30.0, 500.0);
        s.penetration.level = level;
        let built = s.to_scene3().unwrap().0.build().unwrap();
        let n = built.model.body("projectile").unwrap().len();
        eprintln!("level {level}: {n} projectile spheres of {} in", s.projectile_radius3_in());
        assert!(n >= 8, "level {level}: {n}");
    }
}

#[test]
fn the_graded_slab_is_fine_under_the_impact_and_coarse_away_from_it() {
    // Level 0 of the defaults: 1 in spheres within 7 in of the impact axis, growing by 0.2 in
    // per inch to 4 in.
    let s = scene(60.0, 30.0, 500.0);
    let built = s.to_scene3().unwrap().0.build().unwrap();
    let m = built.model;
    let (x0, z0) = (30.0, 30.0);
    let (mut core, mut far) = (Vec::new(), Vec::new());
    for e in m.body("target").unwrap() {
        let x = m.initial_m(e).map(|v| v / M_PER_IN);
        let off = (x[0] - x0).hypot(x[2] - z0);
        let r = m.radius_m(e) / M_PER_IN;
        if off < 5.0 {
            core.push(r);
        } else if off > 28.0 {
            far.push(r);
        }
    }
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    // Radii uniform in ±20 % of the field's: means within a few per cent of 1 in and 4 in.
    assert!(core.len() > 100 && (mean(&core) - 1.0).abs() < 0.05, "core: {} spheres of mean {} in", core.len(), mean(&core));
    assert!(far.len() > 10 && (mean(&far) - 4.0).abs() < 0.25, "edges: {} spheres of mean {} in", far.len(), mean(&far));
    assert!(core.iter().all(|&r| (0.79..=1.21).contains(&r)), "core radii {:?}", core.iter().fold((f64::MAX, 0.0f64), |a, &r| (a.0.min(r), a.1.max(r))));
    // The target weighs its concrete: 60 × 60 × 30 in³ at the default density.
    let mass: f64 = m.body("target").unwrap().map(|e| m.mass_kg(e)).sum();
    let want = 60.0 * 60.0 * 30.0 * s.concrete.density_lbs2_per_in4 * 386.0886 * 0.45359237;
    assert!((mass / want - 1.0).abs() < 1e-6, "target {mass} kg against {want} kg");
}
