//! The build id: a hash of everything the program is built from here (the sources under `src`,
//! `Cargo.toml`, `Cargo.lock`), given to the crate as `DEMSWEEP_BUILD`. A sweep folder keeps the
//! id of the program that made each run and reuses a run only under the same id: after any
//! change of the program, its runs are made again instead of read back (`sweep::store`).

#[path = "src/fnv.rs"]
mod fnv;

use std::path::{Path, PathBuf};

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir).expect("src is readable").map(|e| e.expect("a directory entry").path()).collect();
    entries.sort();
    for p in entries {
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
}
