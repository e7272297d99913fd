//! Sphere packings built once (`crate::keep`): a packing is a pure function of its recipe (the
//! walls, the grading, the radius, the seed, the bond rule) and of the code that makes it, so it
//! is kept in memory for the process and on disk for the machine (`DEMSWEEP_PACKING_CACHE`).

use std::path::Path;

use super::Packing;
use crate::error::Result;
use crate::keep::Kind;

/// Sphere packings, from this module's code.
pub const KIND: Kind = Kind {
    name: "demsweep packing 2",
    sources: || &[include_str!("mod.rs"), include_str!("graded.rs"), include_str!("../lattice.rs"), include_str!("../shape3d.rs")],
};

/// The packing `make` builds for `recipe`, from memory, from the disk cache, or built and kept.
pub fn cached(recipe: &str, make: impl FnOnce() -> Result<Packing>) -> Result<Packing> {
    crate::keep::cached(&KIND, recipe, make)
}

/// [`cached`] with the disk cache in `dir` (none: built) and nothing kept in memory.
pub fn cached_in(dir: Option<&Path>, recipe: &str, make: impl FnOnce() -> Result<Packing>) -> Result<Packing> {
    crate::keep::cached_in(dir, &KIND, recipe, make)
}
