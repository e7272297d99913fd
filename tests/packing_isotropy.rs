//! No preferred crack direction ([1/5]): a square specimen cut from a packing turned by θ and
//! pulled apart along x at a slow constant rate, its strength the peak force carried across its
//! mid-section. The close-packed lattice's strength depends on θ (its bonds lie at 0°, ±60°; the
//! lattice repeats every 60°), the irregular packing's does not, beyond the scatter of its
//! packings, which the test averages over three seeds per angle. The packing statistics the
//! irregular target reports (coordination, packing fraction, fabric) are checked beside.

mod common;

use demsweep::kernel::ModelBuilder;
use demsweep::kernel::boundary::{MotionGroup, Profile};
use demsweep::lattice::{self, Lattice, Rect};
use demsweep::material::{Arrangement, FailureCriterion, Plane};

const R: f64 = 0.005;
/// The specimen's side, m.
const SIDE: f64 = 60.0 * R;

/// A packing of `arrangement` turned by `theta_deg` about the specimen's centre, cut to the
/// specimen: made over a square √2 larger, turned, and the elements inside kept with the bonds
/// between them.
fn specimen(arrangement: Arrangement, theta_deg: f64, seed: u64) -> Lattice {
    let big = SIDE * 1.5;
    let c = 0.5 * big;
    let rect = Rect { x_min_m: 0.0, x_max_m: big, y_min_m: 0.0, y_max_m: big };
    let l = match arrangement {
        Arrangement::Irregular => lattice::irregular(&rect, R, seed, lattice::IRREGULAR_BOND_GAP).unwrap(),
        _ => lattice::close_packed(&rect, R).unwrap(),
    };
    let (s, co) = theta_deg.to_radians().sin_cos();
    let turned: Vec<[f64; 2]> = l.centres.iter().map(|p| [co * (p[0] - c) - s * (p[1] - c), s * (p[0] - c) + co * (p[1] - c)]).collect();
    let half = 0.5 * SIDE - R;
    let keep: Vec<Option<u32>> = {
        let mut next = 0u32;
        turned
            .iter()
            .map(|p| {
                (p[0].abs() <= half && p[1].abs() <= half).then(|| {
                    next += 1;
                    next - 1
                })
            })
            .collect()
    };
    let centres = turned.iter().zip(&keep).filter(|(_, k)| k.is_some()).map(|(p, _)| [p[0] + 0.5 * SIDE, p[1] + 0.5 * SIDE]).collect();
    let bonds = l.bonds.iter().filter_map(|&(i, j)| Some((keep[i as usize]?, keep[j as usize]?))).collect();
    Lattice { centres, radius_m: R, area_per_element_m2: l.area_per_element_m2, bonds }
}

/// The specimen's strength, Pa: the peak of the x-force carried across x = SIDE/2, over the
/// section's height, with the elements within 2.5 R of the left and right edges held and
/// driven apart.
fn strength(arrangement: Arrangement, theta_deg: f64, seed: u64) -> f64 {
    let lat = specimen(arrangement, theta_deg, seed);
    let material = common::plate_concrete(FailureCriterion::StrengthEnergy);
    let (e, sigma, rho) = (material.youngs_modulus_pa, material.tensile_strength_pa, material.density_kg_per_m3);
    let mut b = ModelBuilder::new(Plane::Stress, 1.0);
    let m = b.add_material(material);
    let n = lat.centres.len();
    b.add_body("specimen", &lat, arrangement, m, &[], [0.0; 3]);
    let left: Vec<usize> = (0..n).filter(|&k| lat.centres[k][0] < 2.5 * R).collect();
    let right: Vec<usize> = (0..n).filter(|&k| lat.centres[k][0] > SIDE - 2.5 * R).collect();
    // Quasi-static: the specimen fails after about 30 wave transits.
    let c = (e / rho).sqrt();
    let rate = 3.0 * sigma / e * SIDE / (30.0 * SIDE / c);
    b.add_motion(MotionGroup::all("left", [-0.5 * rate, 0.0, 0.0], Profile::Constant), &left);
    b.add_motion(MotionGroup::all("right", [0.5 * rate, 0.0, 0.0], Profile::Constant), &right);
    b.alpha_per_s = std::f64::consts::PI * c / SIDE;
    let mut model = b.build().unwrap();
    model.record_contact_forces = true;
    let mid = 0.5 * SIDE;
    let steps = (30.0 * SIDE / c / model.dt_s()) as u64;
    let mut peak = 0.0f64;
    for _ in 0..steps / 10 {
        model.run_steps(10).unwrap();
        // Contact force on i is f; a contact with i left of the cut and j right of it carries
        // −f_x from right to left (tension positive).
        let carried: f64 = model
            .state
            .contacts
            .list
            .iter()
            .zip(&model.state.contacts.force)
            .map(|(ct, f)| {
                let (xi, xj) = (model.state.pos[ct.i as usize][0], model.state.pos[ct.j as usize][0]);
                if xi < mid && xj >= mid {
                    f.fx
                } else if xj < mid && xi >= mid {
                    -f.fx
                } else {
                    0.0
                }
            })
            .sum();
        peak = peak.max(carried);
    }
    peak / (SIDE - 2.0 * R)
}

#[test]
fn the_irregular_packing_has_no_preferred_crack_direction_where_the_close_packed_one_has() {
    let angles = [0.0, 30.0, 60.0, 90.0];
    let spread = |s: &[f64]| s.iter().cloned().fold(f64::NEG_INFINITY, f64::max) / s.iter().cloned().fold(f64::INFINITY, f64::min) - 1.0;
    let hex: Vec<f64> = angles.iter().map(|&a| strength(Arrangement::ClosePacked, a, 0)).collect();
    const SEEDS: u64 = 10;
    let per_seed: Vec<Vec<f64>> = angles.iter().map(|&a| (1..=SEEDS).map(|s| strength(Arrangement::Irregular, a, s)).collect()).collect();
    let irr: Vec<f64> = per_seed.iter().map(|v| v.iter().sum::<f64>() / SEEDS as f64).collect();
    // The scatter of one specimen, and so the standard error of an angle's mean.
    let all: Vec<f64> = per_seed.iter().flatten().copied().collect();
    let mean = all.iter().sum::<f64>() / all.len() as f64;
    let sd = (all.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (all.len() - 1) as f64).sqrt();
    eprintln!("irregular: one specimen scatters by {:.1} % (sd); an angle's mean of {SEEDS} by {:.1} %", 100.0 * sd / mean, 100.0 * sd / mean / (SEEDS as f64).sqrt());
    eprintln!("strength at 0/30/60/90°: close-packed {:?} MPa (spread {:.1} %), irregular (mean of 10 seeds) {:?} MPa (spread {:.1} %)",
        hex.iter().map(|s| s / 1e6).collect::<Vec<_>>(), 100.0 * spread(&hex), irr.iter().map(|s| s / 1e6).collect::<Vec<_>>(), 100.0 * spread(&irr));
    // The lattice repeats every 60°: 0° and 60° alike, 30° and 90° alike, and the two differ.
    assert!((hex[0] / hex[2] - 1.0).abs() < 0.03 && (hex[1] / hex[3] - 1.0).abs() < 0.03, "close-packed: {hex:?}");
    assert!(spread(&hex) > 0.10, "the close-packed lattice is expected to show its lattice planes: {hex:?}");
    assert!(spread(&irr) < 0.05, "the irregular packing's strength depends on the direction: {irr:?}");
}

#[test]
fn the_irregular_packing_reports_isotropic_fabric_coordination_and_density() {
    let rect = Rect { x_min_m: 0.0, x_max_m: 100.0 * R, y_min_m: 0.0, y_max_m: 100.0 * R };
    for seed in 1..=3 {
        let l = lattice::irregular(&rect, R, seed, lattice::IRREGULAR_BOND_GAP).unwrap();
        let (mut fxx, mut fxy, mut fyy) = (0.0, 0.0, 0.0);
        for &(i, j) in &l.bonds {
            let (p, q) = (l.centres[i as usize], l.centres[j as usize]);
            let d = ((q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2)).sqrt();
            let (nx, ny) = ((q[0] - p[0]) / d, (q[1] - p[1]) / d);
            fxx += nx * nx;
            fxy += nx * ny;
            fyy += ny * ny;
        }
        let nb = l.bonds.len() as f64;
        let (a, b, c) = (fxx / nb, fxy / nb, fyy / nb);
        // Eigenvalues of the 2 × 2 fabric tensor.
        let (m, d) = (0.5 * (a + c), (0.25 * (a - c).powi(2) + b * b).sqrt());
        let ratio = (m - d) / (m + d);
        let coordination = 2.0 * nb / l.centres.len() as f64;
        let fraction = l.centres.len() as f64 * std::f64::consts::PI * R * R / rect.area_m2();
        eprintln!("irregular seed {seed}: {} elements, fabric eigenvalue ratio {ratio:.3}, coordination {coordination:.2}, packing fraction {fraction:.3}", l.centres.len());
        assert!(ratio > 0.95, "fabric eigenvalue ratio {ratio}");
        assert!((4.5..6.0).contains(&coordination), "coordination {coordination}");
        // The generator fills to about 0.82 of close packing (0.907; `lattice::irregular`): a
        // looser packing than a jammed random one (0.82-0.84), held together by its bonds up
        // to 1.35 diameters long; each element's mass is the rectangle's over the count.
        assert!((fraction / (0.82 * 0.9069) - 1.0).abs() < 0.03, "packing fraction {fraction}");
    }
}
