//! Packings built once (`packing3d::cache`): a kept packing is the built one bit for bit, a run
//! that reads it gives the row a fresh build gives, a damaged file is rebuilt, and runs that ask
//! at once all get a whole packing.

use std::path::Path;
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

use demsweep::packing3d::cache::cached_in;
use demsweep::packing3d::{Box3, Packing, random_dense};

const BIN: &str = env!("CARGO_BIN_EXE_demsweep");

fn fresh() -> Packing {
    let b = Box3 { x_min_m: 0.0, x_max_m: 0.1, y_min_m: 0.0, y_max_m: 0.08, z_min_m: 0.0, z_max_m: 0.06 };
    random_dense(&b, 0.006, 7, 0.1).unwrap()
}

fn bits(p: &Packing) -> Vec<u64> {
    let centres = p.centres_m.iter().flatten().chain(&p.radii_m).chain([&p.volume_m3]).map(|x| x.to_bits());
    centres.chain(p.bonds.iter().map(|&(i, j)| (i as u64) << 32 | j as u64)).collect()
}

fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("demsweep-packing-cache-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

fn files(d: &Path) -> Vec<std::path::PathBuf> {
    let mut f: Vec<_> = std::fs::read_dir(d).unwrap().map(|e| e.unwrap().path()).collect();
    f.sort();
    f
}

#[test]
fn a_kept_packing_is_the_built_one_and_a_damaged_file_is_rebuilt() {
    let dir = scratch("damaged");
    let builds = AtomicUsize::new(0);
    let make = || {
        builds.fetch_add(1, Ordering::SeqCst);
        Ok(fresh())
    };
    let first = cached_in(Some(&dir), "box 7", make).unwrap();
    let kept = cached_in(Some(&dir), "box 7", make).unwrap();
    assert_eq!(builds.load(Ordering::SeqCst), 1, "the second ask reads the file");
    assert_eq!(bits(&kept), bits(&fresh()));
    assert_eq!(bits(&first), bits(&fresh()));
    // Another recipe is another file.
    cached_in(Some(&dir), "box 8", make).unwrap();
    assert_eq!((builds.load(Ordering::SeqCst), files(&dir).len()), (2, 2));
    // A bit flipped in the middle of a file: not used, rebuilt, rewritten whole.
    for f in files(&dir) {
        let mut b = std::fs::read(&f).unwrap();
        let mid = b.len() / 2;
        b[mid] ^= 1;
        std::fs::write(&f, b).unwrap();
    }
    let again = cached_in(Some(&dir), "box 7", make).unwrap();
    assert_eq!(builds.load(Ordering::SeqCst), 3);
    assert_eq!(bits(&again), bits(&fresh()));
    cached_in(Some(&dir), "box 7", make).unwrap();
    assert_eq!(builds.load(Ordering::SeqCst), 3, "the rewritten file is whole");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn runs_that_ask_at_once_all_get_the_whole_packing() {
    let dir = scratch("together");
    let got: Vec<Packing> = std::thread::scope(|s| {
        let asks: Vec<_> = (0..4).map(|_| s.spawn(|| cached_in(Some(&dir), "box together", || Ok(fresh())).unwrap())).collect();
        asks.into_iter().map(|h| h.join().unwrap()).collect()
    });
    for p in &got {
        assert_eq!(bits(p), bits(&fresh()));
    }
    // One file, no temporary left behind, and it reads back.
    assert_eq!(files(&dir).len(), 1, "{:?}", files(&dir));
    let read = cached_in(Some(&dir), "box together", || panic!("the file should have been read")).unwrap();
    assert_eq!(bits(&read), bits(&fresh()));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The summary row of a 3D run of the CI slab stopped at 20 µs, without its wall time.
fn row(cache: &str, out: &Path) -> String {
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("sweeps/penetration3d_ci.toml");
    let status = Command::new(BIN)
        .args(["run", scene.to_str().unwrap(), "--set", "penetration.max_time_s=2e-5", "--quiet", "--out", out.to_str().unwrap()])
        .env("DEMSWEEP_PACKING_CACHE", cache)
        .output()
        .unwrap();
    assert!(status.status.success(), "{}", String::from_utf8_lossy(&status.stderr));
    let text = std::fs::read_to_string(out.join("penetration3d_ci/summary.csv")).unwrap();
    let mut lines = text.lines();
    let (head, values) = (lines.next().unwrap(), lines.next().unwrap());
    head.split(',').zip(values.split(',')).filter(|(k, _)| !k.contains("wall_s") && !k.contains("per_s")).map(|(k, v)| format!("{k}={v}\n")).collect()
}

#[test]
fn a_run_on_a_kept_packing_is_the_run_on_a_fresh_one() {
    let dir = scratch("run");
    let fresh = row("off", &dir.join("off"));
    let building = row(dir.join("cache").to_str().unwrap(), &dir.join("a"));
    assert_eq!(files(&dir.join("cache")).len(), 1, "the slab's packing kept");
    let reading = row(dir.join("cache").to_str().unwrap(), &dir.join("b"));
    assert!(fresh.contains("steps="), "{fresh}");
    assert_eq!(building, fresh);
    assert_eq!(reading, fresh);
    std::fs::remove_dir_all(&dir).unwrap();
}
