//! Symmetry planes (`kernel3d::mirror`): a quarter model moves as its quarter of the whole.
//!
//! A concrete block (rate over a length and compaction on, so the smoothed velocity field is
//! mirrored too) struck by a steel block at 200 m/s, as the quarter x > 0, z > 0 with two
//! mirror planes (the block cut at them, the projectile packed against them), and as the whole made of that quarter and its three mirror images (the same
//! spheres, the bonds of the whole found by brute force). Every sphere of the quarter follows
//! its twin of the whole to rounding, and the whole's energies are four times the quarter's.

use std::path::Path;

use demsweep::kernel3d::Model;
use demsweep::packing3d::{self, Box3, Packing};
use demsweep::scene_file::{SceneFile, load_text};
use demsweep::simulation::Simulation;

const R: f64 = 0.0025;
const HALF: f64 = 0.03;
const THICK: f64 = 0.03;
const PROJ: f64 = 0.012;

fn materials() -> &'static str {
    r#"
[[material]]
name = "concrete"
density_kg_per_m3 = 2400.0
youngs_modulus_pa = 30.0e9
poisson_ratio = 0.2
failure = "strength_energy"
tensile_strength_pa = 3.0e6
shear_strength_pa = 6.0e6
fracture_toughness_pa_sqrt_m = 1.0e6
friction_coefficient = 0.5
rolling = { eta = 0.1 }
twisting = { cohesion_pa = 0.0 }
compressive_strength_pa = 34.5e6
rate = { averaging_length_m = 0.01 }
compaction = {}

[[material]]
name = "steel"
density_kg_per_m3 = 7850.0
youngs_modulus_pa = 200.0e9
poisson_ratio = 0.3
friction_coefficient = 0.3
"#
}

/// The scene: the whole (x and z from -HALF) or the quarter with its two planes (from 0).
fn scene(quarter: bool) -> demsweep::scene3d::Scene3 {
    let lo = if quarter { 0.0 } else { -HALF };
    let plo = if quarter { 0.0 } else { -PROJ };
    let band = 0.006;
    let mut text = format!(
        r#"
[scene]
name = "mirror"
dim = 3
duration_s = 1.0e-4
{mat}
[[body]]
name = "target"
material = "concrete"
element_radius_m = {R}
seed = 3
box = {{ x_min_m = {lo}, x_max_m = {HALF}, y_min_m = {ny}, y_max_m = 0.0, z_min_m = {lo}, z_max_m = {HALF} }}

[[body]]
name = "projectile"
material = "steel"
element_radius_m = {R}
seed = 4
velocity_mps = [0.0, -200.0, 0.0]
box = {{ x_min_m = {plo}, x_max_m = {PROJ}, y_min_m = 0.0002, y_max_m = 0.02, z_min_m = {plo}, z_max_m = {PROJ} }}

[[fix]]
name = "x_high"
box = {{ x_min_m = {xb}, x_max_m = 1.0, y_min_m = -1.0, y_max_m = 0.0, z_min_m = -1.0, z_max_m = 1.0 }}
[[fix]]
name = "z_high"
box = {{ x_min_m = -1.0, x_max_m = 1.0, y_min_m = -1.0, y_max_m = 0.0, z_min_m = {xb}, z_max_m = 1.0 }}
"#,
        mat = materials(),
        ny = -THICK,
        xb = HALF - band,
    );
    if quarter {
        text += "\n[[mirror]]\nnormal = \"x\"\nat_m = 0.0\n[[mirror]]\nnormal = \"z\"\nat_m = 0.0\n";
    } else {
        text += &format!(
            r#"
[[fix]]
name = "x_low"
box = {{ x_min_m = -1.0, x_max_m = {xl}, y_min_m = -1.0, y_max_m = 0.0, z_min_m = -1.0, z_max_m = 1.0 }}
[[fix]]
name = "z_low"
box = {{ x_min_m = -1.0, x_max_m = 1.0, y_min_m = -1.0, y_max_m = 0.0, z_min_m = -1.0, z_max_m = {xl} }}
"#,
            xl = -HALF + band
        );
    }
    let SceneFile::Kernel3(s) = load_text(&text, Path::new("mirror.toml"), &[]).unwrap() else { panic!("a 3D scene") };
    s
}

/// The whole made of a quarter packing and its images through x = 0, z = 0 (the quarter's
/// spheres first, in order), bonded where the gap is below 0.1 R (the packing's rule).
fn whole(q: &Packing) -> Packing {
    let mut centres = Vec::new();
    for [sx, sz] in [[1.0, 1.0], [-1.0, 1.0], [1.0, -1.0], [-1.0, -1.0]] {
        centres.extend(q.centres_m.iter().map(|c| [sx * c[0], c[1], sz * c[2]]));
    }
    let radii: Vec<f64> = (0..4).flat_map(|_| q.radii_m.iter().copied()).collect();
    let mut bonds = Vec::new();
    for i in 0..centres.len() {
        for j in i + 1..centres.len() {
            let d = (0..3).map(|k| (centres[j][k] - centres[i][k]).powi(2)).sum::<f64>().sqrt();
            if d - radii[i] - radii[j] < 0.1 * R {
                bonds.push((i as u32, j as u32));
            }
        }
    }
    Packing { centres_m: centres, radii_m: radii, bonds, volume_m3: 4.0 * q.volume_m3 }
}

#[test]
fn a_quarter_with_two_mirror_planes_moves_as_its_quarter_of_the_whole() {
    let quarter = scene(true);
    // The target cut from a larger packing at the planes (spheres lie across them, some on
    // their own images, many beside their neighbours'); the projectile packed against them.
    let larger = packing3d::random_dense(&Box3 { x_min_m: -0.01, x_max_m: HALF, y_min_m: -THICK, y_max_m: 0.0, z_min_m: -0.01, z_max_m: HALF }, R, 3, 0.1).unwrap();
    let target = larger.keep(|c, _| c[0] >= 0.0 && c[2] >= 0.0, HALF * HALF * THICK);
    let projectile = packing3d::random_dense(&Box3 { x_min_m: 0.0, x_max_m: PROJ, y_min_m: 0.0002, y_max_m: 0.02, z_min_m: 0.0, z_max_m: PROJ }, R, 4, 0.1).unwrap();
    let (nt, np) = (target.centres_m.len(), projectile.centres_m.len());
    let mut q = quarter.build_with(vec![Some(target.clone()), Some(projectile.clone())]).unwrap().model;
    let mut full_scene = scene(false);
    full_scene.time_step.dt_s = Some(q.motion.dt_s);
    let mut f = full_scene.build_with(vec![Some(whole(&target)), Some(whole(&projectile))]).unwrap().model;
    // The whole's smoothed field on the quarter's grid lines (a layer of nodes on each plane).
    f.rate_field.align(0, 0.0);
    f.rate_field.align(2, 0.0);
    // The twin of quarter sphere e in image k of the whole: body by body, each body's quarter
    // first and then its images.
    let twin = |e: usize, k: usize| if e < nt { e + k * nt } else { 4 * nt + (e - nt) + k * np };
    // Each sphere of the whole weighs its twin's in the quarter (a sphere the planes cut
    // weighs its share on the quarter's side, and so does each of its images).
    for k in 0..4 {
        for e in 0..nt + np {
            f.spheres.mass_kg[twin(e, k)] = q.spheres.mass_kg[e];
            f.spheres.inertia_kg_m2[twin(e, k)] = q.spheres.inertia_kg_m2[e];
        }
    }
    f.state.ledger.initial_j = f.kinetic_energy_j() + f.strain_energy_j();
    let own = q.contacts().iter().filter(|c| c.image != 0 && c.i == c.j).count();
    let beside = q.contacts().iter().filter(|c| c.image != 0 && c.i != c.j).count();
    assert!(own > 20 && beside > 20, "{own} spheres bonded to their own images, {beside} to a neighbour's");
    assert_eq!(q.mirrors.copies(), 4.0);
    // 500 steps: the nose 13 mm in and bonds breaking; rounding grows as the pieces part
    // (off by 1e-16 m at 200 steps, 1e-13 m at 500, 3e-7 m at 1500).
    let steps = 500;
    q.run_steps(steps).unwrap();
    f.run_steps(steps).unwrap();
    let moved = (0..nt + np).map(|e| (0..3).map(|k| (q.state.pos_m[e][k] - q.spheres.initial_m[e][k]).abs()).fold(0.0, f64::max)).fold(0.0, f64::max);
    let off = (0..nt + np).map(|e| (0..3).map(|k| (q.state.pos_m[e][k] - f.state.pos_m[twin(e, 0)][k]).abs()).fold(0.0, f64::max)).fold(0.0, f64::max);
    let (tq, tf) = (q.tally(), f.tally());
    println!("{nt} + {np} spheres in the quarter; image contacts at the start: {own} own, {beside} a neighbour's; moved up to {moved:.3e} m, off the whole by {off:.3e} m");
    println!("bonds broken: quarter {} (whole {}); kinetic {:.6e} J × 4 against {:.6e} J", tq.bonds_broken, tf.bonds_broken, q.kinetic_energy_j(), f.kinetic_energy_j());
    assert!(tf.bonds_broken > 50, "the impact breaks bonds ({})", tf.bonds_broken);
    assert!(moved > 1e-4, "the projectile moved {moved} m");
    assert!(off < 1e-9 * moved.max(R), "a sphere of the quarter is {off:.3e} m off its twin in the whole");
    let energy_in = f.state.ledger.initial_j;
    assert!((4.0 * q.state.ledger.initial_j / energy_in - 1.0).abs() < 1e-12);
    let pairs = [
        ("kinetic", q.kinetic_energy_j(), f.kinetic_energy_j()),
        ("strain", q.strain_energy_j(), f.strain_energy_j()),
        ("contacts", q.state.ledger.contacts.total_j(), f.state.ledger.contacts.total_j()),
        ("compaction", q.state.ledger.contacts.compaction_j, f.state.ledger.contacts.compaction_j),
        ("slip", q.state.ledger.contacts.slip_j, f.state.ledger.contacts.slip_j),
    ];
    for (name, a, b) in pairs {
        println!("{name}: 4 × {a:.9e} J against {b:.9e} J");
        assert!((4.0 * a - b).abs() < 1e-8 * energy_in, "{name}: 4 × {a} J against the whole's {b} J");
    }
    assert!(q.state.ledger.contacts.compaction_j > 0.0 && q.state.ledger.contacts.rate_j != 0.0);
}

#[test]
fn a_quarter_model_steps_to_the_same_bits_on_one_and_two_threads() {
    let built = scene(true).build().unwrap();
    let run = |threads: usize| -> Model {
        let mut m = built.model.clone();
        m.parallel_min_contacts = 1;
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        pool.install(|| m.run_steps(300)).unwrap();
        m
    };
    let (one, two) = (run(1), run(2));
    assert!(one.contacts().iter().any(|c| c.image != 0));
    assert_eq!(one.checkpoint(), two.checkpoint(), "1 and 2 threads differ");
}
