//! The scene hash: FNV-1a (64 bit) over the canonical text of the scene as read (every default
//! filled in, comments and layout gone) and the crate's version, so that two files that mean
//! the same scene share a hash and a changed value never does. Which program made a run is the
//! [`build_id`], kept beside it (a new build reruns a scene's runs; it does not make the scene
//! another one).

use crate::fnv::fnv1a;
use crate::scene::SceneFile;

/// The id of this build of demsweep (16 hex digits): a hash of its sources and locked
/// dependencies (`build.rs`). Two binaries with the same id come from the same code.
pub fn build_id() -> &'static str {
    env!("DEMSWEEP_BUILD")
}

/// The canonical text of a scene.
pub fn canonical(scene: &SceneFile) -> String {
    match scene {
        SceneFile::Kernel(s) => s.to_toml(),
        SceneFile::Penetration(p) => toml::to_string(p).expect("a penetration scene serialises"),
    }
}

/// The hash of a scene, as 16 hex digits.
pub fn scene_hash(scene: &SceneFile) -> String {
    let text = format!("demsweep {}\n{}", env!("CARGO_PKG_VERSION"), canonical(scene));
    format!("{:016x}", fnv1a(text.as_bytes()))
}
