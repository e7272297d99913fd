//! The outcome definitions of `demsweep::penetration::outcome` on hand-built 3D states: a slab of
//! bonded spheres (thickness along y, the face across x and z, its rim held) and a projectile
//! above it, moved and cut by hand, read by the same detector as the 2D slice. What must hold:
//! the depth, a scab and its mass, spall, perforation, and the back face's deflection under the
//! impact point as the definitions say, with "under the impact point" and "within the
//! projectile's width" measured across the face in x and z.

use std::path::Path;

use demsweep::kernel3d::Model;
use demsweep::kernel3d::contact::Bond;
use demsweep::penetration::outcome::Detector;
use demsweep::penetration::scene::{Layout, OutcomeSpec};
use demsweep::scene_file::{SceneFile, load_text};
use demsweep::simulation::Bodies;

const R: f64 = 0.004;
const STANDOFF: f64 = 0.005;

/// A slab 120 × 40 × 120 mm (x, y, z) of spheres of R = 4 mm, its rim 8 mm wide held, and a
/// flat-nosed projectile 20 mm across and 30 mm long along −y, its tip 5 mm above the slab.
fn small() -> (Model, Detector, Layout) {
    let text = format!(
        r#"
[scene]
name = "outcomes3d"
dim = 3
duration_s = 1e-4
[[material]]
name = "concrete"
density_kg_per_m3 = 2400.0
youngs_modulus_pa = 30.0e9
poisson_ratio = 0.2
[[material]]
name = "steel"
density_kg_per_m3 = 7850.0
youngs_modulus_pa = 200.0e9
poisson_ratio = 0.3
[[body]]
name = "target"
material = "concrete"
element_radius_m = {R}
seed = 2
box = {{ x_min_m = -0.06, x_max_m = 0.06, y_min_m = 0.0, y_max_m = 0.04, z_min_m = -0.06, z_max_m = 0.06 }}
[[body]]
name = "projectile"
material = "steel"
element_radius_m = {R}
seed = 3
velocity_mps = [0.0, -100.0, 0.0]
shape = {{ tail_m = [0.0, {tail}, 0.0], axis = [0.0, -1.0, 0.0], diameter_m = 0.02, length_m = 0.03, nose = "flat" }}
[[fix]]
name = "rim_x"
box = {{ x_min_m = -1.0, x_max_m = -0.052, y_min_m = -1.0, y_max_m = 0.041, z_min_m = -1.0, z_max_m = 1.0 }}
[[fix]]
name = "rim_x2"
box = {{ x_min_m = 0.052, x_max_m = 1.0, y_min_m = -1.0, y_max_m = 0.041, z_min_m = -1.0, z_max_m = 1.0 }}
[[fix]]
name = "rim_z"
box = {{ x_min_m = -1.0, x_max_m = 1.0, y_min_m = -1.0, y_max_m = 0.041, z_min_m = -1.0, z_max_m = -0.052 }}
[[fix]]
name = "rim_z2"
box = {{ x_min_m = -1.0, x_max_m = 1.0, y_min_m = -1.0, y_max_m = 0.041, z_min_m = 0.052, z_max_m = 1.0 }}
"#,
        tail = 0.04 + STANDOFF + 0.03
    );
    let SceneFile::Kernel3(scene) = load_text(&text, Path::new("outcomes3d.toml"), &[]).unwrap() else { panic!("a 3D scene") };
    let m = scene.build().unwrap().model;
    let target = m.body("target").unwrap();
    let front = target.clone().map(|e| m.initial_m(e)[1] + m.radius_m(e)).fold(f64::NEG_INFINITY, f64::max);
    let layout = Layout {
        front_y_m: front,
        back_y_m: 0.0,
        impact_x_m: 0.0,
        impact_z_m: 0.0,
        projectile_width_m: 0.02,
        projectile_length_m: 0.03,
        axis: [0.0, -1.0, 0.0],
        v0_mps: 100.0,
        thickness_m: 1.0,
        concrete_radius_m: R,
        mirror_axes: vec![],
    };
    let det = Detector::new(&m, layout.clone(), OutcomeSpec::default()).unwrap();
    (m, det, layout)
}

/// Break every bond with exactly one end in `inside`.
fn cut(m: &mut Model, inside: &dyn Fn(usize) -> bool) -> usize {
    let mut n = 0;
    for c in m.state.contacts.iter_mut() {
        if c.bond == Bond::Intact && inside(c.i as usize) != inside(c.j as usize) {
            c.bond = Bond::Frictional;
            n += 1;
        }
    }
    n
}

fn shift_projectile(m: &mut Model, dy_m: f64, vy_mps: f64) {
    for e in m.body("projectile").unwrap() {
        m.state.pos_m[e][1] += dy_m;
        m.state.vel_mps[e] = [0.0, vy_mps, 0.0];
    }
}

#[test]
fn at_rest_nothing_has_happened() {
    let (m, det, _) = small();
    let l = det.look(&m);
    // The tip is the lowest sphere's bottom: within a sphere's spread of the outline's tip.
    let tip = m.body("projectile").unwrap().map(|e| m.position_m(e)[1] - m.radius_m(e)).fold(f64::INFINITY, f64::min);
    assert!((l.depth_m - (det.layout.front_y_m - tip)).abs() < 1e-12);
    assert!(l.depth_m < -0.9 * STANDOFF, "the tip starts above the face: depth {} m", l.depth_m);
    assert_eq!((l.scab.0, l.spall.0), (0, 0));
    assert!(!l.through && l.deflection_m.abs() < 1e-15);
    assert!((l.v_axial_mps - 100.0).abs() < 1e-9 && (l.speed_mps - 100.0).abs() < 1e-9);
}

#[test]
fn a_lump_flying_off_the_back_is_a_scab_with_its_mass() {
    let (mut m, det, _) = small();
    let target = m.body("target").unwrap();
    // Back-face material under the impact point: 15 mm deep, 30 mm across in x and z.
    let members: Vec<usize> = target
        .clone()
        .filter(|&e| {
            let p = m.initial_m(e);
            p[1] < 0.015 && p[0].abs() < 0.015 && p[2].abs() < 0.015
        })
        .collect();
    assert!(members.len() > 10);
    let mass: f64 = members.iter().map(|&e| m.mass_kg(e)).sum();
    let set: std::collections::HashSet<usize> = members.iter().copied().collect();
    assert!(cut(&mut m, &|e| set.contains(&e)) > 0);
    assert_eq!(det.look(&m).scab.0, 0, "a detached piece at rest is not a scab");
    for &e in &members {
        m.state.vel_mps[e][1] = -2.0 * 0.3048;
    }
    assert_eq!(det.look(&m).scab.0, 0, "2 ft/s is below the separation speed");
    for &e in &members {
        m.state.vel_mps[e][1] = -10.0;
    }
    let l = det.look(&m);
    assert_eq!(l.scab.0, 1, "one scab fragment");
    assert!((l.scab.1 - mass).abs() <= 1e-12 * mass, "scab mass {} kg, lump {} kg", l.scab.1, mass);
    assert_eq!(l.spall.0, 0);
}

#[test]
fn the_back_face_bends_under_the_impact_point_across_x_and_z() {
    let (mut m, det, _) = small();
    let target = m.body("target").unwrap();
    // Push the back face down by 1 mm where it lies within 40 mm of the impact point in x but
    // more than 20 mm off it in z: beside the projectile, not under it.
    let aside: Vec<usize> = target.clone().filter(|&e| {
        let p = m.initial_m(e);
        p[1] - m.radius_m(e) < 2.0 * R && p[0].abs() < 0.04 && p[2].abs() > 0.02
    }).collect();
    assert!(!aside.is_empty());
    for &e in &aside {
        m.state.pos_m[e][1] -= 0.001;
    }
    assert!(det.look(&m).deflection_m.abs() < 1e-15, "material beside the impact point is not under it");
    // Now under it (within half the projectile's width of the impact point across the face).
    let under: Vec<usize> = target.clone().filter(|&e| {
        let p = m.initial_m(e);
        // The back face: spheres that started within a sphere diameter of it.
        p[1] - m.radius_m(e) < 2.0 * R && p[0].hypot(p[2]) <= 0.01
    }).collect();
    assert!(!under.is_empty());
    for &e in &under {
        m.state.pos_m[e][1] -= 0.001;
    }
    let l = det.look(&m);
    assert!((l.deflection_m - 0.001).abs() < 1e-12, "deflection {} m", l.deflection_m);
}

#[test]
fn a_projectile_through_a_hole_is_through_and_one_beside_the_slab_is_not_held_by_it() {
    let (mut m, det, lay) = small();
    let target = m.body("target").unwrap();
    // Half-way in: its depth, not through.
    shift_projectile(&mut m, -(STANDOFF + 0.5 * (lay.front_y_m - lay.back_y_m)), -50.0);
    let l = det.look(&m);
    assert!(!l.through && l.v_axial_mps > 0.0);
    // Wholly below the back face (through a hole it need not have made: the slab stays
    // where it was, above it).
    shift_projectile(&mut m, -0.06, -50.0);
    let l = det.look(&m);
    assert!(l.through, "below the back face, nothing attached under it");
    // Pull the spheres in its footprint down with it, still bonded to the rim (a bulge): it is
    // not through while attached material lies below its rear.
    let rear = m.body("projectile").unwrap().map(|e| m.position_m(e)[1] + m.radius_m(e)).fold(f64::NEG_INFINITY, f64::max);
    let footprint: Vec<usize> = target.clone().filter(|&e| m.initial_m(e)[0].hypot(m.initial_m(e)[2]) < 0.005).collect();
    assert!(!footprint.is_empty());
    for &e in &footprint {
        m.state.pos_m[e][1] = rear - 0.5 * R;
    }
    assert!(!det.look(&m).through, "attached material under its rear");
    // The same spheres moved 30 mm off in z: no longer in its footprint.
    for &e in &footprint {
        m.state.pos_m[e][2] += 0.03;
    }
    assert!(det.look(&m).through, "material beside its footprint does not hold it");
}

/// The back-face crater of a lump 30 mm square across the face (x, z): the diameter of the
/// circle of its area, 2 √(900 mm² / π) = 33.9 mm, as the lump's spheres' shares of the face
/// read it; one calibre (20 mm) and more, so a scab. One sphere flying off alone is a crater of
/// about its own diameter (8 mm), under a calibre: a scab fragment, no scab.
#[test]
fn a_back_face_crater_is_the_area_its_scabs_took_and_one_sphere_is_no_scab() {
    let (mut m, det, _) = small();
    let target = m.body("target").unwrap();
    let back = |e: usize| m.initial_m(e)[1] - m.radius_m(e) < 2.0 * R;
    // One back-face sphere under the impact point, cut loose and flying off.
    let one = target.clone().filter(|&e| back(e)).min_by(|&a, &b| {
        let d = |e: usize| m.initial_m(e)[0].hypot(m.initial_m(e)[2]);
        d(a).total_cmp(&d(b))
    }).unwrap();
    assert!(cut(&mut m, &|e| e == one) > 0);
    m.state.vel_mps[one][1] = -10.0;
    let l = det.look(&m);
    println!("one sphere of radius {:.2} mm: crater {:.2} mm", 1e3 * m.radius_m(one), 1e3 * l.back_crater_m);
    assert_eq!(l.scab.0, 1, "a scab fragment");
    assert!(!l.scabs, "one sphere is no scab: crater {} m", l.back_crater_m);
    assert!(l.back_crater_m > 1.0 * m.radius_m(one) && l.back_crater_m < 4.0 * m.radius_m(one), "crater {} m", l.back_crater_m);
    let (mut m, det, _) = small();
    let members: Vec<usize> = target.clone().filter(|&e| {
        let p = m.initial_m(e);
        p[1] < 0.015 && p[0].abs() < 0.015 && p[2].abs() < 0.015
    }).collect();
    let set: std::collections::HashSet<usize> = members.iter().copied().collect();
    assert!(cut(&mut m, &|e| set.contains(&e)) > 0);
    assert_eq!(det.look(&m).back_crater_m, 0.0, "a detached piece at rest takes no crater");
    for &e in &members {
        m.state.vel_mps[e][1] = -10.0;
    }
    let l = det.look(&m);
    let want = 2.0 * (0.03f64 * 0.03 / std::f64::consts::PI).sqrt();
    println!("lump 30 mm square: crater {:.2} mm against {:.2} mm", 1e3 * l.back_crater_m, 1e3 * want);
    assert!(l.scabs, "a crater of {} m is over a calibre", l.back_crater_m);
    assert!((l.back_crater_m / want - 1.0).abs() < 0.10, "crater {} m against {want} m", l.back_crater_m);
}
