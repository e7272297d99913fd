//! Packings built once: a packing is a pure function of its recipe (the walls, the grading, the
//! radius, the seed, the bond rule) and of the code that makes it, so it is kept, in memory for
//! the rest of the process (a sweep's events share it) and on disk for the machine, keyed by a
//! hash of the recipe and of this module's sources. A file is used only when it names the same
//! recipe and sources and its checksum holds; anything else is rebuilt and rewritten. Files are
//! written whole and renamed into place, so two runs asking at once both get a whole packing.
//!
//! Where: `DEMSWEEP_PACKING_CACHE` (a directory; `off` for no disk cache), else
//! `$XDG_CACHE_HOME/demsweep/packings`, else `$HOME/.cache/demsweep/packings`.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};

use super::Packing;
use crate::error::Result;
use crate::fnv::{fnv1a, fnv1a_from};

/// The file's first line: the format.
const MAGIC: &[u8] = b"demsweep packing 1\n";

/// The code the packings come from: a change to any of it makes every kept packing stale.
fn sources_hash() -> u64 {
    static H: OnceLock<u64> = OnceLock::new();
    *H.get_or_init(|| {
        [include_str!("mod.rs"), include_str!("graded.rs"), include_str!("../lattice.rs"), include_str!("../shape3d.rs")]
            .iter()
            .fold(fnv1a(b"packing sources"), |h, s| fnv1a_from(h, s.as_bytes()))
    })
}

/// Whether packings are kept at all: `DEMSWEEP_PACKING_CACHE=off` builds every one afresh.
fn off() -> bool {
    std::env::var_os("DEMSWEEP_PACKING_CACHE").is_some_and(|d| d == "off")
}

/// The disk cache's directory, if any.
pub fn directory() -> Option<PathBuf> {
    match std::env::var_os("DEMSWEEP_PACKING_CACHE") {
        Some(d) if d == "off" => None,
        Some(d) if !d.is_empty() => Some(PathBuf::from(d)),
        _ => std::env::var_os("XDG_CACHE_HOME")
            .filter(|d| !d.is_empty())
            .map(PathBuf::from)
            .or_else(|| std::env::var_os("HOME").filter(|d| !d.is_empty()).map(|h| PathBuf::from(h).join(".cache")))
            .map(|d| d.join("demsweep").join("packings")),
    }
}

/// The packing `make` builds for `recipe` (a complete, exact description of its inputs: f64s
/// by their `Debug`, which round-trips), from memory, from the disk cache, or built and kept.
pub fn cached(recipe: &str, make: impl FnOnce() -> Result<Packing>) -> Result<Packing> {
    static MEMORY: OnceLock<Mutex<HashMap<String, Arc<Packing>>>> = OnceLock::new();
    if off() {
        return make();
    }
    let memory = MEMORY.get_or_init(Default::default);
    if let Some(p) = memory.lock().unwrap_or_else(|e| e.into_inner()).get(recipe) {
        return Ok(Packing::clone(p));
    }
    let packing = cached_in(directory().as_deref(), recipe, make)?;
    memory.lock().unwrap_or_else(|e| e.into_inner()).insert(recipe.to_string(), Arc::new(packing.clone()));
    Ok(packing)
}

/// [`cached`] with the disk cache in `dir` (none: built) and nothing kept in memory.
pub fn cached_in(dir: Option<&Path>, recipe: &str, make: impl FnOnce() -> Result<Packing>) -> Result<Packing> {
    let key = format!("{recipe}\nsources {:016x}", sources_hash());
    let file = dir.map(|d| d.join(format!("{:016x}.bin", fnv1a(key.as_bytes()))));
    if let Some(p) = file.as_ref().and_then(|f| read(f, &key)) {
        return Ok(p);
    }
    let p = make()?;
    if let Some(f) = &file {
        // A cache that cannot be written costs the next run a rebuild, nothing else.
        let _ = write(f, &key, &p);
    }
    Ok(p)
}

/// The file's bytes for `packing` made by `key`: the magic, the key's length and text, the
/// counts, the numbers as little-endian bits, and a checksum of all before it.
fn encode(key: &str, p: &Packing) -> Vec<u8> {
    let mut b = MAGIC.to_vec();
    let n = |b: &mut Vec<u8>, x: u64| b.extend_from_slice(&x.to_le_bytes());
    n(&mut b, key.len() as u64);
    b.extend_from_slice(key.as_bytes());
    n(&mut b, p.centres_m.len() as u64);
    n(&mut b, p.bonds.len() as u64);
    for (c, r) in p.centres_m.iter().zip(&p.radii_m) {
        for x in c.iter().chain([r]) {
            n(&mut b, x.to_bits());
        }
    }
    for &(i, j) in &p.bonds {
        b.extend_from_slice(&i.to_le_bytes());
        b.extend_from_slice(&j.to_le_bytes());
    }
    n(&mut b, p.volume_m3.to_bits());
    let sum = fnv1a(&b);
    n(&mut b, sum);
    b
}

/// Bytes read from the front.
struct Reader<'a>(&'a [u8]);

impl<'a> Reader<'a> {
    fn take(&mut self, k: usize) -> Option<&'a [u8]> {
        let (head, tail) = self.0.split_at_checked(k)?;
        self.0 = tail;
        Some(head)
    }
    fn u64(&mut self) -> Option<u64> {
        Some(u64::from_le_bytes(self.take(8)?.try_into().ok()?))
    }
    fn u32(&mut self) -> Option<u32> {
        Some(u32::from_le_bytes(self.take(4)?.try_into().ok()?))
    }
    fn f64(&mut self) -> Option<f64> {
        self.u64().map(f64::from_bits)
    }
}

/// The packing in `bytes` if they are a whole file made by `key`.
fn decode(bytes: &[u8], key: &str) -> Option<Packing> {
    let (body, sum) = bytes.split_at(bytes.len().checked_sub(8)?);
    if u64::from_le_bytes(sum.try_into().ok()?) != fnv1a(body) {
        return None;
    }
    let mut r = Reader(body.strip_prefix(MAGIC)?);
    let len = r.u64()? as usize;
    if r.take(len)? != key.as_bytes() {
        return None;
    }
    let (spheres, bonds) = (r.u64()? as usize, r.u64()? as usize);
    // Counts a damaged file could make absurd are checked against its length before any
    // allocation: 32 bytes a sphere, 8 a bond, 8 the volume.
    if spheres.checked_mul(32)?.checked_add(bonds.checked_mul(8)?)?.checked_add(8)? != r.0.len() {
        return None;
    }
    let mut p = Packing { centres_m: Vec::with_capacity(spheres), radii_m: Vec::with_capacity(spheres), bonds: Vec::with_capacity(bonds), volume_m3: 0.0 };
    for _ in 0..spheres {
        p.centres_m.push([r.f64()?, r.f64()?, r.f64()?]);
        p.radii_m.push(r.f64()?);
    }
    for _ in 0..bonds {
        p.bonds.push((r.u32()?, r.u32()?));
    }
    p.volume_m3 = r.f64()?;
    r.0.is_empty().then_some(p)
}

/// The packing kept in `file` for `key`, if it is there and whole.
fn read(file: &Path, key: &str) -> Option<Packing> {
    decode(&std::fs::read(file).ok()?, key)
}

/// Keep `p` in `file`: written whole beside it, then renamed into place.
fn write(file: &Path, key: &str, p: &Packing) -> std::io::Result<()> {
    let dir = file.parent().unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir)?;
    static SERIAL: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let serial = SERIAL.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let tmp = dir.join(format!(".{}.{}.{serial}.tmp", file.file_name().and_then(|n| n.to_str()).unwrap_or("packing"), std::process::id()));
    std::fs::write(&tmp, encode(key, p))?;
    std::fs::rename(&tmp, file).inspect_err(|_| {
        let _ = std::fs::remove_file(&tmp);
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Packing {
        Packing { centres_m: vec![[0.1, -0.2, 1.0 / 3.0], [1e-300, f64::MAX, 0.0]], radii_m: vec![0.01, 0.02], bonds: vec![(0, 1)], volume_m3: 0.5 }
    }

    #[test]
    fn a_file_gives_back_the_packing_bit_for_bit() {
        let p = sample();
        assert_eq!(decode(&encode("k", &p), "k"), Some(p));
    }

    #[test]
    fn a_file_of_another_recipe_or_damaged_or_cut_is_not_used() {
        let bytes = encode("k", &sample());
        assert_eq!(decode(&bytes, "other"), None);
        for at in [0, MAGIC.len() + 3, bytes.len() / 2, bytes.len() - 1] {
            let mut b = bytes.clone();
            b[at] ^= 0x10;
            assert_eq!(decode(&b, "k"), None, "a flipped bit at {at}");
        }
        for len in [0, 7, bytes.len() - 1] {
            assert_eq!(decode(&bytes[..len], "k"), None, "cut at {len}");
        }
    }
}
