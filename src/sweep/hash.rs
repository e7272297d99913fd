//! The scene hash: FNV-1a (64 bit) over the canonical text of the scene as read (every default
//! filled in, comments and layout gone) and the program version, so that two files that mean
//! the same scene share a hash and a changed value or a new program never does.

use crate::scene::SceneFile;

/// FNV-1a, 64 bit.
pub fn fnv1a(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= b as u64;
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv_reference_values() {
        // The published FNV-1a test vectors.
        assert_eq!(fnv1a(b""), 0xcbf29ce484222325);
        assert_eq!(fnv1a(b"a"), 0xaf63dc4c8601ec8c);
        assert_eq!(fnv1a(b"foobar"), 0x85944171f73967e8);
    }
}
