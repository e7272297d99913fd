//! A scene file as read: a 2D kernel scene (`crate::scene`), a 3D one (`crate::scene3d`,
//! `[scene] dim = 3`) or a penetration scene (`crate::penetration`), told apart by its tables, with the command line's `--set` applied.
//! It sits above both, so that neither imports the other.

use std::path::Path;

use crate::error::{Error, Result};
use crate::penetration::PenetrationScene;
use crate::polyhedra::scene::RockfillScene;
use crate::scene::overrides::{Override, apply};
use crate::scene::{Scene, parse};
use crate::scene3d::Scene3;

/// What a scene file describes.
#[derive(Debug, Clone, PartialEq)]
pub enum SceneFile {
    /// A 2D kernel scene: materials, bodies, groups, probes.
    Kernel(Scene),
    /// A 3D kernel scene (`[scene] dim = 3`).
    Kernel3(Scene3),
    /// A penetration scene (`[penetration]`), which builds its own kernel scene.
    Penetration(PenetrationScene),
    /// A projectile through a rockfill of polyhedra (`[rockfill]`).
    Rockfill(RockfillScene),
}

/// Read a scene document from `text` with `overrides` applied (`--set`), as a file would be.
pub fn load_text(text: &str, origin: &Path, overrides: &[Override]) -> Result<SceneFile> {
    let mut doc: toml::Table = parse(text, origin)?;
    for o in overrides {
        apply(&mut doc, o).map_err(|e| e.in_file(origin))?;
    }
    // Read the changed document back from text, so that every error names its field.
    let text = if overrides.is_empty() { text.to_string() } else { toml::to_string(&doc).expect("a TOML table serialises") };
    let blame = |e: Error| match e {
        Error::Input { file, field, message } => {
            let set = overrides.iter().find(|o| field.starts_with(&o.field) || o.field.starts_with(&field));
            // Lines of the rewritten text are not the file's.
            let message = if overrides.is_empty() { message } else { crate::scene::without_location(&message).to_string() };
            let message = match set {
                Some(o) => format!("{message} (given by --set {}={})", o.field, o.value),
                None => message,
            };
            Error::Input { file, field, message }
        }
        other => other,
    };
    if doc.contains_key("rockfill") {
        let r: RockfillScene = parse(&text, origin).map_err(blame)?;
        r.validate().map_err(|e| blame(e.in_file(origin)))?;
        Ok(SceneFile::Rockfill(r))
    } else if doc.contains_key("penetration") {
        let mut p: PenetrationScene = parse(&text, origin).map_err(blame)?;
        p.resolve_defaults();
        p.validate().map_err(|e| blame(e.in_file(origin)))?;
        Ok(SceneFile::Penetration(p))
    } else if doc.get("scene").and_then(|g| g.get("dim")).is_some() {
        Ok(SceneFile::Kernel3(Scene3::from_toml(&text, origin).map_err(blame)?))
    } else {
        Ok(SceneFile::Kernel(Scene::from_toml(&text, origin).map_err(blame)?))
    }
}

/// Read a scene file with `overrides` applied.
pub fn load(path: &Path, overrides: &[Override]) -> Result<SceneFile> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
    load_text(&text, path, overrides)
}

