//! Scenes as files: a TOML description of bodies, materials, boundary groups, probes and run
//! length, every field carrying its unit in its name. `Scene::from_file` parses and validates
//! (errors name the file, the field and the allowed range); `Scene::build` makes the model.
//!
//! Data flows one way: scene → [`crate::kernel::Model`] → [`crate::run::RunResult`] → tables.

mod build;
pub mod overrides;
pub mod switch;
mod validate;

pub use build::{Built, Probe, ProbeQuantity};

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::kernel::boundary::{Profile, Servo};
use crate::lattice::Rect;
use crate::material::{Arrangement, Material, Plane};

/// A whole scene file.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// General settings.
    pub scene: General,
    /// Time-step choice (defaults: 0.9 of the stability limit).
    #[serde(default)]
    pub time_step: TimeStep,
    /// Rayleigh damping (default: none).
    #[serde(default)]
    pub damping: Damping,
    /// Materials, referred to by name.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub material: Vec<Material>,
    /// Bodies: a lattice filling a rectangle.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub body: Vec<BodySpec>,
    /// Pre-existing cracks: bonds crossing each segment are removed.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub crack: Vec<CrackSpec>,
    /// Kinematic groups: elements in a rectangle moving with a prescribed velocity (fixed if 0).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub fix: Vec<FixSpec>,
    /// Loads: a force shared by the free elements in a rectangle.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub load: Vec<LoadSpec>,
    /// Probes recorded as time series.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub probe: Vec<ProbeSpec>,
    /// Output settings.
    #[serde(default)]
    pub output: OutputSpec,
}

/// `[scene]`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct General {
    /// Name, used for output files.
    pub name: String,
    /// "stress" or "strain".
    pub plane: Plane,
    /// Out-of-plane thickness, m.
    pub thickness_m: f64,
    /// Simulated time, s.
    pub duration_s: f64,
    /// Gravity [gx, gy], m/s² (default none).
    #[serde(default)]
    pub gravity_mps2: [f64; 2],
}

/// `[time_step]`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct TimeStep {
    /// Fraction of the stability limit (ignored when `dt_s` is given).
    #[serde(default = "default_safety")]
    pub safety: f64,
    /// A fixed step, s; refused if above the stability limit.
    #[serde(default)]
    pub dt_s: Option<f64>,
    /// Resolve the shortest binary collision with at least this many steps.
    #[serde(default)]
    pub collision_steps: Option<f64>,
    /// Neighbour-list skin as a fraction of each element's radius (it changes the cost, never
    /// the result).
    #[serde(default = "default_skin")]
    pub skin_ratio: f64,
    /// Refuse a `dt_s` above the stability limit (default). `false` forces it through, for
    /// experiments on the instability itself: the blow-up detector then stops the run.
    #[serde(default = "yes")]
    pub refuse_unstable: bool,
}

fn yes() -> bool {
    true
}

fn default_safety() -> f64 {
    0.9
}

fn default_skin() -> f64 {
    crate::kernel::neighbours::SKIN_RATIO
}

impl Default for TimeStep {
    fn default() -> Self {
        TimeStep { safety: default_safety(), dt_s: None, collision_steps: None, skin_ratio: default_skin(), refuse_unstable: true }
    }
}

/// `[damping]`: Rayleigh damping C = αM + βK, given directly or as critical-damping ratios at
/// one frequency (mass-proportional only) or two frequencies (both terms).
#[derive(Debug, Clone, PartialEq, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Damping {
    /// Mass-proportional coefficient α, 1/s.
    #[serde(default)]
    pub alpha_per_s: Option<f64>,
    /// Stiffness-proportional coefficient β, s.
    #[serde(default)]
    pub beta_s: Option<f64>,
    /// One or two (frequency, ratio) points.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub points: Vec<DampingPoint>,
    /// Mass-proportional damping acts on velocities relative to each body's rigid motion, so
    /// free bodies translate and rotate undamped (for quasi-static loading).
    #[serde(default)]
    pub relative_to_rigid_motion: bool,
}

/// Fraction of critical damping at a circular frequency.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct DampingPoint {
    /// ω, rad/s.
    pub omega_rad_per_s: f64,
    /// ξ, fraction of critical.
    pub ratio: f64,
}

/// `[[body]]`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// Name.
    pub name: String,
    /// Material name.
    pub material: String,
    /// Element arrangement.
    pub lattice: Arrangement,
    /// Element radius, m.
    pub element_radius_m: f64,
    /// The rectangle the lattice fills (or give a `shape`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rect: Option<Rect>,
    /// A projectile outline the lattice fills (or give a `rect`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shape: Option<crate::shape::Projectile>,
    /// Initial velocity [vx, vy], m/s.
    #[serde(default)]
    pub velocity_mps: [f64; 2],
    /// Seed of the irregular packing.
    #[serde(default)]
    pub seed: u64,
    /// Bond gap ratio of the irregular packing.
    #[serde(default)]
    pub bond_gap_ratio: Option<f64>,
    /// Material overrides inside rectangles.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub region: Vec<RegionSpec>,
}

/// `[[body.region]]`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RegionSpec {
    /// Where.
    pub rect: Rect,
    /// Material name.
    pub material: String,
}

/// `[[crack]]`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct CrackSpec {
    /// Start point, m.
    pub from_m: [f64; 2],
    /// End point, m.
    pub to_m: [f64; 2],
}

/// `[[fix]]`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FixSpec {
    /// Name.
    pub name: String,
    /// Elements whose centres lie in this rectangle.
    pub rect: Rect,
    /// Velocity [vx, vy], m/s (default 0: fixed).
    #[serde(default)]
    pub velocity_mps: [f64; 2],
    /// Time variation.
    #[serde(default = "constant")]
    pub profile: Profile,
    /// Prescribed dofs, of "x", "y", "rotation" (default all three; ["y"] is a roller).
    #[serde(default = "all_dofs")]
    pub dofs: Vec<Dof>,
}

/// A degree of freedom of an element.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Dof {
    /// Translation x.
    X,
    /// Translation y.
    Y,
    /// Rotation.
    Rotation,
}

/// All three dofs.
pub fn all_dofs() -> Vec<Dof> {
    vec![Dof::X, Dof::Y, Dof::Rotation]
}

fn constant() -> Profile {
    Profile::Constant
}

/// `[[load]]`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct LoadSpec {
    /// Name.
    pub name: String,
    /// Free elements whose centres lie in this rectangle share the force.
    pub rect: Rect,
    /// Total force [Fx, Fy], N (ignored with a servo).
    #[serde(default)]
    pub force_n: [f64; 2],
    /// Time variation.
    #[serde(default = "constant")]
    pub profile: Profile,
    /// Displacement-controlled grip instead of a given force.
    #[serde(default)]
    pub servo: Option<Servo>,
}

/// `[[probe]]`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ProbeSpec {
    /// Column name in the series (must carry its unit, e.g. `tip_uy_m`).
    pub name: String,
    /// What is measured.
    pub quantity: ProbeQuantity,
    /// Elements whose centres lie in this rectangle (not needed for global quantities).
    #[serde(default)]
    pub rect: Option<Rect>,
    /// Load group name, for `applied_load_*` quantities.
    #[serde(default)]
    pub load: Option<String>,
}

/// `[output]`.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSpec {
    /// Record probes every this many steps.
    #[serde(default = "default_every")]
    pub every_steps: u64,
}

fn default_every() -> u64 {
    100
}

impl Default for OutputSpec {
    fn default() -> Self {
        OutputSpec { every_steps: default_every() }
    }
}

/// The dotted key at byte `at` of a TOML text: the enclosing table header plus the key of
/// the line (TOML errors carry a span, not a path).
fn field_at(text: &str, at: usize) -> String {
    let at = char_floor(text, at);
    let line_start = text[..at].rfind('\n').map_or(0, |k| k + 1);
    let line = text[line_start..].lines().next().unwrap_or("").trim();
    let key = line.split('=').next().unwrap_or("").trim().trim_start_matches('[').trim_end_matches(']').to_string();
    let table = text[..line_start]
        .lines()
        .rev()
        .map(str::trim)
        .find(|l| l.starts_with('['))
        .map(|l| l.trim_matches(|c| c == '[' || c == ']').to_string());
    match table {
        Some(t) if !line.starts_with('[') && !key.is_empty() => format!("{t}.{key}"),
        Some(t) if key.is_empty() => t,
        _ if key.is_empty() => "(syntax)".to_string(),
        _ => key,
    }
}

/// Deserialise `text` as `T`; errors name the file and the dotted field (and, for an unknown
/// field given in the wrong unit, the field meant).
pub fn parse<T: serde::de::DeserializeOwned>(text: &str, origin: &Path) -> Result<T> {
    toml::from_str(text).map_err(|e| {
        let message = e.message().trim().to_string();
        let hint = overrides::unit_hint(&message).map(|h| format!("; {h}")).unwrap_or_default();
        let (field, at) = match e.span() {
            Some(s) => {
                let (line, column) = line_column(text, s.start);
                (field_at(text, s.start), format!("line {line}, column {column}: "))
            }
            None => ("(syntax)".into(), String::new()),
        };
        Error::Input { file: Some(origin.to_path_buf()), field, message: format!("{at}{message}{hint}") }
    })
}

/// The largest char boundary of `text` at or before byte `at`.
fn char_floor(text: &str, at: usize) -> usize {
    let mut at = at.min(text.len());
    while !text.is_char_boundary(at) {
        at -= 1;
    }
    at
}

/// Line and column (both from 1, the column in characters) of byte `at` of `text`.
fn line_column(text: &str, at: usize) -> (usize, usize) {
    let before = &text[..char_floor(text, at)];
    let line_start = before.rfind('\n').map_or(0, |k| k + 1);
    (before.matches('\n').count() + 1, before[line_start..].chars().count() + 1)
}

/// `message` without the "line L, column C: " that [`parse`] puts first: for text the program
/// wrote itself (a scene with `--set` applied), whose lines are not the file's.
pub fn without_location(message: &str) -> &str {
    let rest = message.strip_prefix("line ").and_then(|m| m.split_once(", column ")).and_then(|(l, m)| {
        let (c, m) = m.split_once(": ")?;
        (l.bytes().all(|b| b.is_ascii_digit()) && c.bytes().all(|b| b.is_ascii_digit())).then_some(m)
    });
    rest.unwrap_or(message)
}

impl Scene {
    /// Parse TOML text; `origin` names the file in messages.
    pub fn from_toml(text: &str, origin: &Path) -> Result<Scene> {
        let scene: Scene = parse(text, origin)?;
        scene.validate().map_err(|e| e.in_file(origin))?;
        Ok(scene)
    }

    /// Read and parse a scene file.
    pub fn from_file(path: &Path) -> Result<Scene> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        Scene::from_toml(&text, path)
    }

    /// Serialise back to TOML (for writing generated scenes).
    pub fn to_toml(&self) -> String {
        toml::to_string(self).expect("a scene always serialises")
    }
}
