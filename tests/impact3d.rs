//! A 3D impact through the run loop: a bonded block of spheres struck by a bonded steel cube at
//! 150 m/s, bonds breaking and new contacts sliding, rolling and twisting. What must hold: the
//! energy ledger closes within 1 % of the energy put in; a run resumed from a checkpoint ends
//! bit for bit as the run that never stopped; a NaN stops the run naming the sphere and the step.

use std::sync::Arc;

use demsweep::kernel3d::law::{Class, rolling, twisting};
use demsweep::kernel3d::{Builder, Model};
use demsweep::run::{self, Checkpointing, RunCheckpoint};
use demsweep::simulation::{Built, Measure, Simulation};

const R: f64 = 0.005;

fn concrete() -> Class {
    // Springs of 2e7 and 0.8e7 N/m at R = 5 mm.
    let (kn, ks) = (4e9, 1.6e9);
    Class {
        bond_kn_pa: kn,
        bond_ks_pa: ks,
        bond_tension_pa: 4e6,
        bond_shear_pa: 8e6,
        bond_fracture_j_per_m2: 100.0,
        kn_pa: kn,
        ks_pa: ks,
        mu: 0.5,
        contact_damping_ratio: 0.0,
        crushed_shear_pa: f64::INFINITY,
        rolling: Some(rolling::Params { kr_pa: ks, eta: 0.2 }),
        twisting: Some(twisting::Params { kt_pa: 0.5 * ks, cap: twisting::Cap::MohrCoulomb { tan_phi: 0.5, cohesion_pa: 0.0 } }),
        rate: Default::default(),
        compaction: None,
    }
}

fn steel() -> Class {
    Class { bond_tension_pa: f64::INFINITY, bond_shear_pa: f64::INFINITY, bond_fracture_j_per_m2: f64::INFINITY, ..concrete() }
}

fn cube(origin: [f64; 3], n: usize) -> Vec<[f64; 3]> {
    let mut c = Vec::new();
    for x in 0..n {
        for y in 0..n {
            for z in 0..n {
                c.push([origin[0] + 2.0 * R * x as f64, origin[1] + 2.0 * R * y as f64, origin[2] + 2.0 * R * z as f64]);
            }
        }
    }
    c
}

/// Bond every pair of a body's spheres that touch.
fn bond_touching(b: &mut Builder, centres: &[[f64; 3]], range: std::ops::Range<usize>) {
    for i in range.clone() {
        for j in i + 1..range.end {
            let (p, q) = (centres[i - range.start], centres[j - range.start]);
            let d = ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt();
            if d < 2.0 * R * 1.001 {
                b.bond(i, j);
            }
        }
    }
}

#[derive(Debug)]
struct KineticEnergy;

impl Measure<Model> for KineticEnergy {
    fn name(&self) -> &str {
        "kinetic_energy_j"
    }
    fn value(&self, m: &Model) -> f64 {
        m.kinetic_energy_j()
    }
}

fn impact() -> Built<Model> {
    let mut b = Builder::new(2);
    b.class(0, 0, concrete());
    b.class(0, 1, concrete());
    b.class(1, 1, steel());
    let block = cube([0.0; 3], 8);
    let target = b.body("target", &block, &vec![R; block.len()], 0, 2400.0);
    bond_touching(&mut b, &block, target.clone());
    // The block's bottom layer is held.
    for e in target.clone().filter(|&e| block[e][1] < R) {
        b.hold(e, [0.0; 3]);
    }
    let striker = cube([5.0 * R, 16.0 * R + 0.2 * R, 5.0 * R], 3);
    let projectile = b.body("projectile", &striker, &vec![R; striker.len()], 1, 7800.0);
    bond_touching(&mut b, &striker, projectile.clone());
    let model = b.build(&[(projectile, [0.0, -150.0, 0.0])]).unwrap();
    let probes: Vec<Arc<dyn Measure<Model>>> = vec![Arc::new(KineticEnergy)];
    Built { name: "impact3d".into(), model, probes, duration_s: 6e-4, every_steps: 200 }
}

#[test]
fn the_energy_ledger_of_a_3d_impact_closes_within_one_percent() {
    let r = run::run_with(impact(), run::Options::default()).unwrap();
    let s = &r.summary;
    println!("{} steps of {:.3e} s, {} bonds broken, KE {:.3} J, strain {:.3} J, dissipated {:.3} J, residual {:.3e} J ({:.3} %)",
        s.steps, s.dt_s, s.bonds_broken, s.kinetic_energy_j, s.strain_energy_j, s.dissipated_j, s.energy_residual_j, 100.0 * s.energy_error);
    println!("{:?}", s.contacts);
    assert!(s.bonds_broken > 20, "the impact breaks bonds: {}", s.bonds_broken);
    assert!(s.contacts.get("rolling_j").unwrap() > 0.0 && s.contacts.get("slip_j").unwrap() > 0.0);
    assert!(s.energy_error.abs() < 0.01, "residual {:.3} % of the energy put in", 100.0 * s.energy_error);
}

#[test]
fn a_3d_run_resumed_from_a_checkpoint_ends_bit_for_bit_as_the_run_that_never_stopped() {
    let straight = run::run_with(impact(), run::Options::default()).unwrap();
    let mut saved = Vec::new();
    let mut save = |c: &RunCheckpoint| {
        saved.push(c.to_bytes());
        Err(demsweep::Error::input("test", "killed"))
    };
    let options = run::Options { checkpointing: Some(Checkpointing { every_steps: 100, save: &mut save }), ..Default::default() };
    assert!(run::run_with(impact(), options).is_err());
    let checkpoint = RunCheckpoint::from_bytes(&saved[0]).unwrap();
    let resumed = run::run_with(impact(), run::Options { resume: Some(&checkpoint), ..Default::default() }).unwrap();
    assert_eq!(resumed.series, straight.series);
    assert_eq!(resumed.model.state, straight.model.state);
}

#[test]
fn a_nan_in_the_state_stops_the_run_naming_the_sphere_and_the_step() {
    let mut built = impact();
    built.model.run_steps(10).unwrap();
    built.model.state.vel_mps[77][2] = f64::NAN;
    let err = built.model.run_steps(5).unwrap_err();
    match err {
        demsweep::Error::BlowUp { step, element, .. } => assert_eq!((step, element), (10, 77)),
        other => panic!("{other:?}"),
    }
    assert!(built.model.checkpoint().len() > 8);
}

#[test]
fn a_3d_impact_is_bitwise_the_same_on_1_2_and_8_threads() {
    let on = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        let mut built = impact();
        // Every step on the pool, however few the contacts.
        built.model.parallel_min_contacts = 0;
        pool.install(|| run::run_with(built, run::Options::default())).unwrap()
    };
    let one = on(1);
    for threads in [2, 8] {
        let r = on(threads);
        assert_eq!(r.model.checkpoint(), one.model.checkpoint(), "{threads} threads");
        assert_eq!(r.series, one.series);
    }
}

#[test]
fn a_3d_model_is_written_to_vtk_as_spheres_with_their_radius_and_velocity() {
    let mut built = impact();
    built.model.run_steps(50).unwrap();
    let m = &built.model;
    let n = m.spheres.len();
    let bytes = demsweep::picture::vtk::unstructured(m, &vec![0.0; n], m.bodies[1].elements.clone()).unwrap();
    let text = String::from_utf8_lossy(&bytes);
    assert!(text.contains(&format!("NumberOfPoints=\"{n}\"")), "{}", &text[..400.min(text.len())]);
    for field in ["radius_m", "velocity_mps", "projectile", "supported", "damage"] {
        assert!(text.contains(&format!("Name=\"{field}\"")), "{field} missing");
    }
    // The striker moves down the y axis at 150 m/s: its spheres' velocities are in the file.
    let parsed = vtkio::Vtk::parse_xml(&bytes[..]).unwrap();
    let vtkio::model::DataSet::UnstructuredGrid { pieces, .. } = parsed.data else { panic!("an unstructured grid") };
    let vtkio::model::Piece::Inline(piece) = &pieces[0] else { panic!("inline") };
    let points: Vec<f64> = piece.points.clone().cast_into().unwrap();
    assert_eq!(points.len(), 3 * n);
    let e = m.bodies[1].elements.start;
    assert_eq!([points[3 * e], points[3 * e + 1], points[3 * e + 2]], m.state.pos_m[e]);
}
