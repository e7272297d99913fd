//! The scene hash: FNV-1a (64 bit) over the canonical text of the scene as read (every default
//! filled in, comments and layout gone) and the crate's version, so that two files that mean
//! the same scene share a hash and a changed value never does. Which program made a run is the
//! build id, kept beside it (a new build reruns a scene's runs; it does not make the scene
//! another one; [`crate::provenance::build_id`]).

use crate::fnv::fnv1a;
use crate::scene_file::SceneFile;

/// The canonical text of a scene.
pub fn canonical(scene: &SceneFile) -> String {
    match scene {
        SceneFile::Kernel(s) => s.to_toml(),
        SceneFile::Kernel3(s) => s.to_toml(),
        SceneFile::Penetration(p) => toml::to_string(p).expect("a penetration scene serialises"),
        SceneFile::Rockfill(r) => toml::to_string(r).expect("a rockfill scene serialises"),
    }
}

/// The hash of a scene, as 16 hex digits.
pub fn scene_hash(scene: &SceneFile) -> String {
    let text = format!("demsweep {}\n{}", env!("CARGO_PKG_VERSION"), canonical(scene));
    format!("{:016x}", fnv1a(text.as_bytes()))
}
