//! Values built once and kept: a value that is a pure function of its recipe and of the code
//! that makes it (a sphere packing, a packed rockfill) is kept, in memory for the rest of the
//! process (a sweep's events share it) and on disk for the machine, keyed by a hash of the
//! recipe, of the value's kind and of its code's sources. A file is used only when it names the
//! same kind, recipe and sources and its checksum holds; anything else is rebuilt and
//! rewritten. Files are written whole and renamed into place, so two runs asking at once both
//! get a whole value. The value's bytes are its serde form in postcard (floats as their bits,
//! so what is read is what was built, bit for bit).
//!
//! Where: `DEMSWEEP_PACKING_CACHE` (a directory; `off` for no disk cache and no memory), else
//! `$XDG_CACHE_HOME/demsweep/packings`, else `$HOME/.cache/demsweep/packings`.

use std::any::Any;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, OnceLock};

use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::error::Result;
use crate::fnv::{fnv1a, fnv1a_from};

/// A kind of kept value: its name (the file's first line) and the code it comes from.
pub struct Kind {
    /// The format's name and version, e.g. `demsweep packing 2`.
    pub name: &'static str,
    /// The texts of the code that makes the value (`include_str!`): a change to any of them
    /// makes every kept value of the kind stale.
    pub sources: fn() -> &'static [&'static str],
}

impl Kind {
    /// The key a value of this kind made by `recipe` is kept under.
    pub fn key(&self, recipe: &str) -> String {
        let sources = (self.sources)().iter().fold(fnv1a(b"sources"), |h, s| fnv1a_from(h, s.as_bytes()));
        format!("{}\n{recipe}\nsources {sources:016x}", self.name)
    }
}

/// Whether values are kept at all: `DEMSWEEP_PACKING_CACHE=off` builds every one afresh.
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

/// The value of `kind` that `make` builds for `recipe` (a complete, exact description of its
/// inputs: f64s by their `Debug`, which round-trips), from memory, from the disk cache, or
/// built and kept.
pub fn cached<T>(kind: &Kind, recipe: &str, make: impl FnOnce() -> Result<T>) -> Result<T>
where
    T: Serialize + DeserializeOwned + Clone + Send + Sync + 'static,
{
    static MEMORY: OnceLock<Mutex<HashMap<String, Arc<dyn Any + Send + Sync>>>> = OnceLock::new();
    if off() {
        return make();
    }
    let memory = MEMORY.get_or_init(Default::default);
    let key = kind.key(recipe);
    let known = memory.lock().unwrap_or_else(|e| e.into_inner()).get(&key).cloned();
    if let Some(v) = known.as_deref().and_then(|v| v.downcast_ref::<T>()) {
        return Ok(v.clone());
    }
    let value = cached_in(directory().as_deref(), kind, recipe, make)?;
    memory.lock().unwrap_or_else(|e| e.into_inner()).insert(key, Arc::new(value.clone()));
    Ok(value)
}

/// [`cached`] with the disk cache in `dir` (none: built) and nothing kept in memory.
pub fn cached_in<T: Serialize + DeserializeOwned>(dir: Option<&Path>, kind: &Kind, recipe: &str, make: impl FnOnce() -> Result<T>) -> Result<T> {
    let key = kind.key(recipe);
    let file = dir.map(|d| d.join(format!("{:016x}.bin", fnv1a(key.as_bytes()))));
    if let Some(v) = file.as_ref().and_then(|f| read(f, &key)) {
        return Ok(v);
    }
    let v = make()?;
    if let Some(f) = &file {
        // A cache that cannot be written costs the next run a rebuild, nothing else.
        let _ = write(f, &key, &v);
    }
    Ok(v)
}

/// The file's bytes for `value` made by `key`: the key's length and text (its first line the
/// kind), the value in postcard, and a checksum of all before it.
pub fn encode<T: Serialize>(key: &str, value: &T) -> Vec<u8> {
    let mut b = (key.len() as u64).to_le_bytes().to_vec();
    b.extend_from_slice(key.as_bytes());
    b.extend(postcard::to_stdvec(value).expect("a kept value serialises"));
    let sum = fnv1a(&b);
    b.extend_from_slice(&sum.to_le_bytes());
    b
}

/// The value in `bytes` if they are a whole file made by `key`.
pub fn decode<T: DeserializeOwned>(bytes: &[u8], key: &str) -> Option<T> {
    let (body, sum) = bytes.split_at(bytes.len().checked_sub(8)?);
    if u64::from_le_bytes(sum.try_into().ok()?) != fnv1a(body) {
        return None;
    }
    let (len, rest) = body.split_at_checked(8)?;
    let (k, value) = rest.split_at_checked(usize::try_from(u64::from_le_bytes(len.try_into().ok()?)).ok()?)?;
    if k != key.as_bytes() {
        return None;
    }
    // The value fills the rest exactly, or the file is not one we wrote.
    match postcard::take_from_bytes::<T>(value) {
        Ok((v, [])) => Some(v),
        _ => None,
    }
}

/// The value kept in `file` for `key`, if it is there and whole.
fn read<T: DeserializeOwned>(file: &Path, key: &str) -> Option<T> {
    decode(&std::fs::read(file).ok()?, key)
}

/// Keep `value` in `file`: written whole beside it, then renamed into place.
fn write<T: Serialize>(file: &Path, key: &str, value: &T) -> std::io::Result<()> {
    let dir = file.parent().unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir)?;
    static SERIAL: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let serial = SERIAL.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let tmp = dir.join(format!(".{}.{}.{serial}.tmp", file.file_name().and_then(|n| n.to_str()).unwrap_or("kept"), std::process::id()));
    std::fs::write(&tmp, encode(key, value))?;
    std::fs::rename(&tmp, file).inspect_err(|_| {
        let _ = std::fs::remove_file(&tmp);
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const SOURCES: &[&str] = &["fn a() {}"];
    const KIND: Kind = Kind { name: "test 1", sources: || SOURCES };
    const OTHER: Kind = Kind { name: "test 2", sources: || SOURCES };

    fn sample() -> (Vec<[f64; 3]>, Vec<(u32, u32)>, f64) {
        (vec![[0.1, -0.2, 1.0 / 3.0], [1e-300, f64::MAX, -0.0]], vec![(0, 1)], f64::NAN)
    }

    fn bits(v: &(Vec<[f64; 3]>, Vec<(u32, u32)>, f64)) -> (Vec<u64>, Vec<(u32, u32)>, u64) {
        (v.0.iter().flatten().map(|x| x.to_bits()).collect(), v.1.clone(), v.2.to_bits())
    }

    #[test]
    fn a_file_gives_back_the_value_bit_for_bit() {
        let key = KIND.key("r");
        let back: (Vec<[f64; 3]>, Vec<(u32, u32)>, f64) = decode(&encode(&key, &sample()), &key).unwrap();
        assert_eq!(bits(&back), bits(&sample()));
    }

    #[test]
    fn the_key_changes_with_the_recipe_the_kind_and_the_sources() {
        const CHANGED: Kind = Kind { name: "test 1", sources: || &["fn a() { }"] };
        let keys = [KIND.key("r"), KIND.key("r2"), OTHER.key("r"), CHANGED.key("r")];
        for a in 0..keys.len() {
            for b in a + 1..keys.len() {
                assert_ne!(keys[a], keys[b]);
            }
        }
        assert_eq!(KIND.key("r"), KIND.key("r"));
    }

    #[test]
    fn a_file_of_another_recipe_or_damaged_or_cut_is_not_used() {
        let key = KIND.key("k");
        let bytes = encode(&key, &sample());
        type V = (Vec<[f64; 3]>, Vec<(u32, u32)>, f64);
        assert!(decode::<V>(&bytes, &KIND.key("other")).is_none());
        for at in [0, 3, 9, bytes.len() / 2, bytes.len() - 1] {
            let mut b = bytes.clone();
            b[at] ^= 0x10;
            assert!(decode::<V>(&b, &key).is_none(), "a flipped bit at {at}");
        }
        for len in [0, 7, 8, bytes.len() - 1] {
            assert!(decode::<V>(&bytes[..len], &key).is_none(), "cut at {len}");
        }
    }
}
