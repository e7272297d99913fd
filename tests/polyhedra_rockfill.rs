//! The Voronoi rockfill: its sizes follow the asked grading, and a packed rockfill is the same
//! to the bit each time it is made from the same recipe and seed.

mod polyhedra_support;

use demsweep::polyhedra::rockfill::{Grading, rocks, size_of};
use demsweep::polyhedra::settle::{Packing, pack};
use nalgebra::Vector3;

const MEAN: f64 = 0.1;

fn grading(seed: u64) -> Grading {
    Grading { mean_m: MEAN, spread: 0.1, grade: 0.6, seed }
}

#[test]
fn rock_sizes_follow_the_asked_grading() {
    let (lo, hi) = (Vector3::zeros(), Vector3::new(1.0, 1.0, 1.0));
    let r = rocks(&grading(11), &lo, &hi).unwrap();
    let sizes: Vec<f64> = r.shapes.iter().map(|s| size_of(s.volume)).collect();
    let n = sizes.len() as f64;
    let mean = sizes.iter().sum::<f64>() / n;
    // The spread of the rocks that got their asked size (a capped cell gives a smaller rock).
    let free: Vec<f64> = sizes.iter().zip(&r.asked_m).filter(|(d, a)| (*d / *a - 1.0).abs() < 1e-9).map(|(d, _)| *d).collect();
    let free_mean = free.iter().sum::<f64>() / free.len() as f64;
    let sd = (free.iter().map(|d| (d - free_mean).powi(2)).sum::<f64>() / (free.len() as f64 - 1.0)).sqrt();
    let (lo_d, hi_d) = sizes.iter().fold((f64::INFINITY, 0.0f64), |(a, b), &d| (a.min(d), b.max(d)));
    // Eq 28's count: 1 m³ over the sphere of radius mean/(2 q̄).
    let expected = 1.0 / (4.0 / 3.0 * std::f64::consts::PI * (MEAN / 1.2f64).powi(3));
    println!(
        "{} rocks (eq 28: {expected:.1}), {} capped; size mean {:.5} m, sd {:.5} m (σ asked {:.5} cut at 2σ: {:.5}), range {lo_d:.4}–{hi_d:.4} m",
        sizes.len(),
        r.capped,
        mean,
        sd,
        0.05 * MEAN,
        0.05 * MEAN * 0.8796
    );
    assert!((sizes.len() as f64 - expected).abs() <= 1.0, "count");
    assert!(free.len() + r.capped == sizes.len() && r.capped * 20 < sizes.len(), "{} capped", r.capped);
    // The standard error of the mean is sd/√n ≈ 0.4 % of the mean here: 1 % is 2.5 of them.
    assert!((mean / MEAN - 1.0).abs() < 0.01, "mean size {mean}");
    // A normal of σ cut at ±2σ has sd 0.880 σ.
    assert!((sd / (0.05 * MEAN * 0.8796) - 1.0).abs() < 0.15, "sd {sd}");
    // Those that got their size lie in ±10 % (the cut at 2σ); none is larger.
    assert!(free.iter().all(|&d| d >= 0.9 * MEAN * (1.0 - 1e-9) && d <= 1.1 * MEAN * (1.0 + 1e-9)), "a rock outside ±10 %");
    assert!(hi_d <= 1.1 * MEAN * (1.0 + 1e-9) && lo_d > 0.5 * MEAN, "range {lo_d}..{hi_d}");
}

fn packing() -> Packing {
    polyhedra_support::quick_packing()
}

#[test]
fn a_packed_rockfill_is_the_same_bits_each_time() {
    let (lo, hi) = (Vector3::zeros(), Vector3::new(0.4, 0.4, 0.6));
    let r = rocks(&grading(5), &lo, &hi).unwrap();
    let a = pack(&r, &lo, &hi, &packing()).unwrap();
    let b = pack(&rocks(&grading(5), &lo, &hi).unwrap(), &lo, &hi, &packing()).unwrap();
    println!(
        "{} rocks: fraction {:.4} under the lid at {:.4} m (capped by pressure: {}), {} steps in {:.2} s, kinetic left {:.2e} J",
        a.bodies.len(),
        a.fraction,
        a.top_m,
        a.pressure_capped,
        a.steps,
        a.wall_s,
        a.kinetic_j
    );
    let bits = |p: &demsweep::polyhedra::settle::Packed| -> Vec<u64> {
        p.bodies.iter().flat_map(|b| b.position.iter().chain(b.spin.orientation.coords.iter()).map(|x| x.to_bits()).collect::<Vec<_>>()).collect()
    };
    assert!(bits(&a) == bits(&b), "two packings differ");
    println!("packing springs {:.3e} J loaded, {:.3e} J unloaded", a.loaded_j, a.elastic_j);
    assert!(a.loaded_j > 0.0 && a.elastic_j < 1e-2 * a.loaded_j, "the packing is not unloaded");
    assert!(a.fraction >= 0.5 || a.pressure_capped, "compaction stopped short: {}", a.fraction);
    assert!(a.fraction < 0.75, "denser than rocks pack: {}", a.fraction);
    // Denser than the cells were cut: compacted.
    let cut: f64 = r.shapes.iter().map(|s| s.volume).sum::<f64>() / (0.4 * 0.4 * 0.6);
    println!("cut at a fraction {cut:.4}");
    assert!(a.fraction > 1.5 * cut, "not compacted: {} from {cut}", a.fraction);
    // Every rock in the box, under the lid.
    assert!(a.bodies.iter().all(|b| (0..3).all(|k| b.position[k] > lo[k] && b.position[k] < hi[k]) && b.position.z < a.top_m));
    // Another seed, another rockfill.
    let c = pack(&rocks(&grading(6), &lo, &hi).unwrap(), &lo, &hi, &packing()).unwrap();
    assert!(bits(&c) != bits(&a));
}
