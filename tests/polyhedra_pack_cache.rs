//! Packed rockfills built once (`polyhedra::settle::cached`, on `demsweep::keep`): the kept
//! packing is the built one bit for bit, a damaged file is rebuilt, and the key changes with
//! every part of the recipe.

mod polyhedra_support;

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

use demsweep::keep::cached_in;
use demsweep::polyhedra::Law;
use demsweep::polyhedra::rockfill::{Grading, rocks};
use demsweep::polyhedra::settle::{KIND, Packed, Packing, pack, recipe};
use nalgebra::Vector3;

fn grading() -> Grading {
    Grading { mean_m: 0.1, spread: 0.1, grade: 0.6, seed: 5 }
}

fn packing() -> Packing {
    polyhedra_support::quick_packing()
}

fn the_box() -> (Vector3<f64>, Vector3<f64>) {
    (Vector3::zeros(), Vector3::new(0.3, 0.3, 0.5))
}

fn fresh() -> Packed {
    let (lo, hi) = the_box();
    pack(&rocks(&grading(), &lo, &hi).unwrap(), &lo, &hi, &packing()).unwrap()
}

/// Every number of a packed rockfill as bits, but its wall time (a measurement of the build).
fn bits(p: &Packed) -> Vec<u64> {
    let mut out = Vec::new();
    for s in &p.shapes {
        let vectors = s.vertices.iter().chain(&s.normals).chain([&s.principal, &s.rest_position]);
        out.extend(vectors.flat_map(|v| v.iter().map(|x| x.to_bits())));
        out.extend(s.rest_orientation.coords.iter().map(|x| x.to_bits()));
        out.extend(s.faces.iter().flat_map(|f| f.iter().map(|&k| k as u64).chain([u64::MAX])));
        out.extend(s.edges.iter().flat_map(|&(a, b)| [a as u64, b as u64]));
        out.push(s.volume.to_bits());
    }
    for b in &p.bodies {
        out.extend([b.mass].iter().chain(&b.inertia).chain(&b.position).chain(&b.velocity).chain(&b.spin.momentum).map(|x| x.to_bits()));
        out.extend(b.spin.orientation.coords.iter().map(|x| x.to_bits()));
    }
    out.extend([p.top_m, p.fraction, p.kinetic_j, p.loaded_j, p.elastic_j].map(f64::to_bits));
    out.extend([p.steps, p.pressure_capped as u64]);
    out
}

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("demsweep-rockfill-cache-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn files(d: &Path) -> Vec<PathBuf> {
    let mut f: Vec<_> = std::fs::read_dir(d).unwrap().map(|e| e.unwrap().path()).collect();
    f.sort();
    f
}

#[test]
fn a_kept_rockfill_is_the_built_one_bit_for_bit_and_a_damaged_file_is_rebuilt() {
    let dir = scratch("kept");
    let (lo, hi) = the_box();
    let key = recipe(&grading(), &lo, &hi, &packing());
    let builds = AtomicUsize::new(0);
    let make = || {
        builds.fetch_add(1, Ordering::SeqCst);
        Ok(fresh())
    };
    let built = std::time::Instant::now();
    let first = cached_in(Some(&dir), &KIND, &key, make).unwrap();
    let built = built.elapsed().as_secs_f64();
    let read = std::time::Instant::now();
    let kept: Packed = cached_in(Some(&dir), &KIND, &key, make).unwrap();
    let read = read.elapsed().as_secs_f64();
    println!("{} rocks: built and kept in {built:.3} s, read back in {read:.4} s", first.bodies.len());
    assert_eq!(builds.load(Ordering::SeqCst), 1, "the second ask reads the file");
    assert!(first.bodies.len() > 10, "{} rocks", first.bodies.len());
    assert!(bits(&kept) == bits(&first), "the kept packing differs from the built one");
    assert_eq!(kept.wall_s.to_bits(), first.wall_s.to_bits(), "the kept build time");
    // A second build, not kept, is the same bits (the packing is a function of its recipe).
    let again = fresh();
    assert!(bits(&again) == bits(&kept), "a rebuilt packing differs from the kept one");
    assert_eq!(files(&dir).len(), 1);
    // A bit flipped in the middle of the file, or the file cut short: not used, rebuilt and
    // rewritten whole.
    for (damage, n) in [("flipped", 2), ("cut", 3)] {
        let f = &files(&dir)[0];
        let mut b = std::fs::read(f).unwrap();
        if damage == "flipped" {
            let mid = b.len() / 2;
            b[mid] ^= 1;
        } else {
            b.truncate(b.len() - 9);
        }
        std::fs::write(f, b).unwrap();
        let rebuilt = cached_in(Some(&dir), &KIND, &key, make).unwrap();
        assert_eq!(builds.load(Ordering::SeqCst), n, "{damage}: rebuilt");
        assert!(bits(&rebuilt) == bits(&first), "{damage}");
        let reread = cached_in(Some(&dir), &KIND, &key, || panic!("{damage}: the rewritten file should have been read")).unwrap();
        assert!(bits(&reread) == bits(&first), "{damage}: the rewritten file");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_key_changes_with_every_part_of_the_recipe() {
    let (lo, hi) = the_box();
    let base = KIND.key(&recipe(&grading(), &lo, &hi, &packing()));
    assert_eq!(base, KIND.key(&recipe(&grading(), &lo, &hi, &packing())));
    let mut changed = Vec::new();
    for g in [Grading { seed: 6, ..grading() }, Grading { mean_m: 0.1 * (1.0 + f64::EPSILON), ..grading() }, Grading { spread: 0.09, ..grading() }, Grading { grade: 0.61, ..grading() }] {
        changed.push(recipe(&g, &lo, &hi, &packing()));
    }
    let mut wider = hi;
    wider.x = f64::from_bits(hi.x.to_bits() + 1);
    changed.push(recipe(&grading(), &lo, &wider, &packing()));
    changed.push(recipe(&grading(), &Vector3::new(0.0, 0.0, -0.1), &hi, &packing()));
    let p = packing();
    for q in [
        Packing { density: 2651.0, ..p },
        Packing { law: Law { stiffness: 2e6, ..p.law }, ..p },
        Packing { law: Law { friction: 0.6, ..p.law }, ..p },
        Packing { law: Law { restitution: 0.4, ..p.law }, ..p },
        Packing { damping_per_s: 4.0, ..p },
        Packing { fraction: 0.55, ..p },
        Packing { lid_speed_mps: 1.0, ..p },
        Packing { lid_pressure_pa: 3e4, ..p },
        Packing { phase_s: 1.0, ..p },
    ] {
        changed.push(recipe(&grading(), &lo, &hi, &q));
    }
    for (k, r) in changed.iter().enumerate() {
        assert_ne!(KIND.key(r), base, "change {k} left the key as it was");
    }
    // Another kind of kept value under the same recipe text is another key.
    assert_ne!(demsweep::packing3d::cache::KIND.key(&recipe(&grading(), &lo, &hi, &packing())), base);
}
