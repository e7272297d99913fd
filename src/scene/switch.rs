//! An optional law in a scene file: a table of its constants turns it on, `true` turns it on
//! with the defaults, `false` turns it off (`concrete.compaction = false`, also as
//! `--set concrete.compaction=false`). Used with `#[serde(with = "crate::scene::switch")]`.

use serde::{Deserialize, Deserializer, Serialize, Serializer};

#[derive(Deserialize)]
#[serde(untagged)]
enum OnOff<T> {
    Flag(bool),
    Table(T),
}

/// Read `true`, `false` or a table.
pub fn deserialize<'de, D: Deserializer<'de>, T: Deserialize<'de> + Default>(d: D) -> Result<Option<T>, D::Error> {
    Ok(match OnOff::<T>::deserialize(d)? {
        OnOff::Flag(false) => None,
        OnOff::Flag(true) => Some(T::default()),
        OnOff::Table(t) => Some(t),
    })
}

/// Write `false` or the table.
pub fn serialize<S: Serializer, T: Serialize>(v: &Option<T>, s: S) -> Result<S::Ok, S::Error> {
    match v {
        None => false.serialize(s),
        Some(t) => t.serialize(s),
    }
}
