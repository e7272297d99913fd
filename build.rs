//! The build id: a hash of what a run's result is built from (the sources under `src` but those
//! in [`READERS`], `Cargo.toml`, `Cargo.lock`), given to the crate as `DEMSWEEP_BUILD`. A sweep
//! folder keeps the id of the program that made each run and reuses a run only under the same
//! id: after a change of the physics, the scene, the run or its row, its runs are made again
//! instead of read back (`sweep::store`); after a change that only reads or draws them, not.

#[path = "src/fnv.rs"]
mod fnv;

use std::path::{Path, PathBuf};

/// Sources that only read or draw runs (the command line, pictures, the empirical formulas, the
/// fits and tables made from rows, the calibration's and the convergence study's searches, the
/// benchmarks): a change to them leaves every run as it was. When in doubt a file stays out of
/// this list: hashing too much only costs a rerun.
const READERS: &[&str] = &[
    "src/main.rs",
    "src/cli",
    "src/picture",
    "src/empirical",
    "src/bench",
    "src/converge",
    "src/calibrate.rs",
    "src/provenance.rs",
    "src/ballistic/plot.rs",
    "src/ballistic/v50.rs",
    "src/ballistic/thresholds.rs",
    "src/ballistic/fit.rs",
    "src/ballistic/pictures.rs",
    "src/report",
];

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir).expect("src is readable").map(|e| e.expect("a directory entry").path()).collect();
    entries.sort();
    for p in entries {
        let name = p.to_string_lossy().replace('\\', "/");
        if READERS.contains(&name.as_str()) {
            continue;
        }
        if p.is_dir() {
            files(&p, out);
        } else {
            out.push(p);
        }
    }
}

fn main() {
    let mut paths = Vec::new();
    files(Path::new("src"), &mut paths);
    paths.extend(["Cargo.toml", "Cargo.lock"].map(PathBuf::from));
    let mut h = fnv::fnv1a(b"demsweep build");
    for p in &paths {
        // Paths with '/' on every platform, so a checkout anywhere has the same id.
        let name = p.to_string_lossy().replace('\\', "/");
        h = fnv::fnv1a_from(h, name.as_bytes());
        h = fnv::fnv1a_from(h, &[0]);
        if let Ok(bytes) = std::fs::read(p) {
            h = fnv::fnv1a_from(h, &bytes);
        }
        h = fnv::fnv1a_from(h, &[0]);
    }
    println!("cargo:rerun-if-changed=src");
    println!("cargo:rerun-if-changed=Cargo.toml");
    println!("cargo:rerun-if-changed=Cargo.lock");
    println!("cargo:rustc-env=DEMSWEEP_BUILD={h:016x}");
    commit();
}

/// The commit checked out when this was built (`DEMSWEEP_COMMIT`: 12 hex digits, `-dirty` when
/// tracked files differed from it then; `unknown` outside a git checkout), for provenance only:
/// a run is reused by its build id, which a commit of documentation alone leaves as it was.
fn commit() {
    let git = |args: &[&str]| std::process::Command::new("git").args(args).output().ok().filter(|o| o.status.success()).map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string());
    let commit = match git(&["rev-parse", "--short=12", "HEAD"]) {
        Some(c) if !c.is_empty() => {
            let dirty = git(&["status", "--porcelain", "--untracked-files=no"]).is_some_and(|s| !s.is_empty());
            format!("{c}{}", if dirty { "-dirty" } else { "" })
        }
        _ => "unknown".to_string(),
    };
    println!("cargo:rustc-env=DEMSWEEP_COMMIT={commit}");
    // A new commit moves HEAD or the branch it names.
    println!("cargo:rerun-if-changed=.git/HEAD");
    if let Some(branch) = std::fs::read_to_string(".git/HEAD").ok().and_then(|h| h.strip_prefix("ref: ").map(|r| r.trim().to_string())) {
        println!("cargo:rerun-if-changed=.git/{branch}");
        println!("cargo:rerun-if-changed=.git/packed-refs");
    }
}
