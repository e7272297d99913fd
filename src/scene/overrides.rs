//! `--set FIELD=VALUE`: change one field of a scene document before it is read, so that
//! scripts and sweeps never copy a scene file to change one number. FIELD is dotted
//! (`projectile.v0_fps`, `body[1].velocity_mps`); VALUE is TOML (`850`, `"ogive"`, `[0.0, -1.0]`,
//! `true`; anything else is taken as a string). The changed document is then read and checked
//! exactly like a file, so a bad override gets the message a bad file would.

use crate::error::{Error, Result};

/// One override.
#[derive(Debug, Clone, PartialEq)]
pub struct Override {
    /// Dotted path.
    pub field: String,
    /// The new value.
    pub value: toml::Value,
}

impl Override {
    /// Parse `FIELD=VALUE`.
    pub fn parse(text: &str) -> Result<Override> {
        let (field, value) = text
            .split_once('=')
            .ok_or_else(|| Error::input("--set", format!("`{text}` is not FIELD=VALUE (e.g. projectile.v0_fps=850)")))?;
        let field = field.trim().to_string();
        if field.is_empty() || field.split('.').any(|p| p.is_empty()) {
            return Err(Error::input("--set", format!("`{text}`: the field is not a dotted path")));
        }
        let raw = value.trim();
        let value = toml::from_str::<toml::Table>(&format!("v = {raw}"))
            .ok()
            .and_then(|mut t| t.remove("v"))
            .unwrap_or_else(|| toml::Value::String(raw.to_string()));
        Ok(Override { field, value })
    }
}

/// One step of a dotted path: a key, and an array index (`body[1]`).
fn steps(field: &str) -> Result<Vec<(String, Option<usize>)>> {
    field
        .split('.')
        .map(|part| match part.split_once('[') {
            None => Ok((part.to_string(), None)),
            Some((key, rest)) => {
                let index = rest.strip_suffix(']').and_then(|i| i.parse().ok());
                match index {
                    Some(i) => Ok((key.to_string(), Some(i))),
                    None => Err(Error::input(format!("--set {field}"), format!("`{part}` is neither a key nor key[index]"))),
                }
            }
        })
        .collect()
}

/// Apply `o` to the document `doc`, creating tables on the way where they are missing.
pub fn apply(doc: &mut toml::Table, o: &Override) -> Result<()> {
    let path = steps(&o.field)?;
    let mut table = doc;
    for (n, (key, index)) in path.iter().enumerate() {
        let last = n + 1 == path.len();
        match index {
            None if last => {
                table.insert(key.clone(), o.value.clone());
                return Ok(());
            }
            None => {
                let next = table.entry(key.clone()).or_insert_with(|| toml::Value::Table(Default::default()));
                table = next
                    .as_table_mut()
                    .ok_or_else(|| Error::input(format!("--set {}", o.field), format!("`{key}` is a value, not a table")))?;
            }
            Some(i) => {
                let array = table
                    .get_mut(key)
                    .and_then(toml::Value::as_array_mut)
                    .ok_or_else(|| Error::input(format!("--set {}", o.field), format!("`{key}` is not a list in this scene")))?;
                let len = array.len();
                let item = array.get_mut(*i).ok_or_else(|| {
                    Error::input(format!("--set {}", o.field), format!("`{key}` has {len} entries, there is no [{i}]"))
                })?;
                if last {
                    *item = o.value.clone();
                    return Ok(());
                }
                table = item
                    .as_table_mut()
                    .ok_or_else(|| Error::input(format!("--set {}", o.field), format!("`{key}[{i}]` is not a table")))?;
            }
        }
    }
    Ok(())
}

/// For an "unknown field `x`, expected one of …" message: the expected field with the same
/// name before its unit, if there is one (a field given in the wrong unit).
pub fn unit_hint(message: &str) -> Option<String> {
    let unknown = message.split('`').nth(1)?;
    let stem = |f: &str| f.rsplit_once('_').map_or(f.to_string(), |(s, _)| s.to_string());
    let expected: Vec<&str> = message.split("expected").nth(1)?.split('`').skip(1).step_by(2).collect();
    let same = expected.iter().find(|e| stem(e) == stem(unknown) && **e != unknown)?;
    Some(format!("fields carry their unit: did you mean `{same}`?"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sets_nested_and_indexed_fields_and_parses_toml_values() {
        let mut doc: toml::Table = toml::from_str("a = 1\n[[body]]\nname = \"x\"\n[[body]]\nname = \"y\"\n").unwrap();
        for o in ["b.c=2.5", "body[1].name=\"z\"", "s=ogive", "v=[0.0, -1.0]"] {
            apply(&mut doc, &Override::parse(o).unwrap()).unwrap();
        }
        assert_eq!(doc["b"]["c"].as_float(), Some(2.5));
        assert_eq!(doc["body"][1]["name"].as_str(), Some("z"));
        assert_eq!(doc["s"].as_str(), Some("ogive"));
        assert_eq!(doc["v"].as_array().unwrap().len(), 2);
        assert!(apply(&mut doc, &Override::parse("body[5].name=1").unwrap()).unwrap_err().to_string().contains("has 2 entries"));
        assert!(Override::parse("no_equals").is_err());
    }

    #[test]
    fn a_field_in_the_wrong_unit_gets_a_hint() {
        let m = "unknown field `v0_mps`, expected one of `v0_fps`, `angle_deg`";
        assert_eq!(unit_hint(m).unwrap(), "fields carry their unit: did you mean `v0_fps`?");
        assert_eq!(unit_hint("unknown field `colour`, expected one of `name`"), None);
    }
}
