//! Scenes of the 3D kernel as files (`[scene] dim = 3`): materials, bodies of spheres filling a
//! box or a projectile's solid, fixed or driven groups, loads and probes, every field carrying
//! its unit in its name. `Scene3::from_toml` parses and validates (errors name the file and the
//! field); `Scene3::build` makes the model.
//!
//! Data flows one way: scene → [`crate::kernel3d::Model`] → [`crate::run::RunResult`] → tables.

mod absorb;
mod build;
mod probe;

pub use absorb::{Absorb3, Axis3, wave_speeds_mps};
pub use build::{REFERENCE_MARGIN_R, REFERENCE_SIDE_R, recipe_bond_density};
pub use probe::{Probe3, Quantity3};

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::kernel3d::solid::Solid;
use crate::packing3d::{Box3, Grading};
use crate::scene::{OutputSpec, parse};
use crate::shape3d::Projectile3;

/// A whole 3D scene file.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Scene3 {
    /// General settings.
    pub scene: General3,
    /// Time-step choice (default: 0.9 of the stability limit).
    #[serde(default)]
    pub time_step: TimeStep3,
    /// Mass-proportional damping (default: none).
    #[serde(default)]
    pub damping: Damping3,
    /// Materials, referred to by name.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub material: Vec<Solid>,
    /// Bodies of spheres.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub body: Vec<Body3>,
    /// Spheres in a box moving with a prescribed velocity, without spin (fixed if 0).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub fix: Vec<Fix3>,
    /// Faces through which waves leave the model (viscous boundaries).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub absorb: Vec<Absorb3>,
    /// A force shared by the free spheres in a box.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub load: Vec<Load3>,
    /// Probes recorded as time series.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub probe: Vec<Probe3>,
    /// Symmetry planes (one per axis at most): the scene is the part on the high side of each
    /// of a mirror-symmetric whole, its bodies packed against them (`kernel3d::mirror`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub mirror: Vec<Mirror3>,
    /// Output settings.
    #[serde(default)]
    pub output: OutputSpec,
}

/// `[scene]` of a 3D scene.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct General3 {
    /// Name, used for output files.
    pub name: String,
    /// Dimension: 3 (a scene without `dim` is a 2D one).
    pub dim: u8,
    /// Simulated time, s.
    pub duration_s: f64,
}

/// `[time_step]` of a 3D scene.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct TimeStep3 {
    /// Fraction of the stability bound (ignored when `dt_s` is given).
    #[serde(default = "default_safety")]
    pub safety: f64,
    /// A fixed step, s; refused if above the stability bound.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dt_s: Option<f64>,
    /// Neighbour skin over the mean radius (it changes the cost, never the result).
    #[serde(default = "default_skin")]
    pub skin_ratio: f64,
}

fn default_safety() -> f64 {
    0.9
}

fn default_skin() -> f64 {
    0.3
}

impl Default for TimeStep3 {
    fn default() -> Self {
        TimeStep3 { safety: default_safety(), dt_s: None, skin_ratio: default_skin() }
    }
}

/// `[damping]` of a 3D scene: mass-proportional, on the spheres' absolute velocities.
#[derive(Debug, Clone, PartialEq, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Damping3 {
    /// α, 1/s.
    #[serde(default)]
    pub alpha_per_s: f64,
}

/// How a body's spheres are arranged.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Packing3 {
    /// A seeded, isotropic dense random packing (`packing3d::random_dense`), the one the
    /// stiffness relation was measured on.
    #[default]
    RandomDense,
}

/// `[[body]]` of a 3D scene.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Body3 {
    /// Name (`target` and `projectile` are what a penetration outcome looks for).
    pub name: String,
    /// Material name.
    pub material: String,
    /// Mean sphere radius R, m.
    pub element_radius_m: f64,
    /// Arrangement of the spheres.
    #[serde(default)]
    pub packing: Packing3,
    /// Seed of the random packing.
    #[serde(default)]
    pub seed: u64,
    /// Pairs whose gap is below this × R are bonded.
    #[serde(default = "default_gap")]
    pub bond_gap_ratio: f64,
    /// The box the packing fills (or give a `shape`).
    #[serde(default, rename = "box", skip_serializing_if = "Option::is_none")]
    pub region: Option<Box3>,
    /// A projectile's solid the packing fills (or give a `box`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shape: Option<Projectile3>,
    /// Sphere sizes graded about an axis (`packing3d::random_dense_graded`), its finest radius
    /// `element_radius_m`; absent: R everywhere.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grading: Option<Grading>,
    /// Initial velocity, m/s.
    #[serde(default)]
    pub velocity_mps: [f64; 3],
    /// The material's own damping, as local damping at this fraction of critical
    /// (`kernel3d::integrate::local`; dimensionless, 0: none).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub local_damping_ratio: f64,
}

/// Serde's test for a field left out when 0.
pub(crate) fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

/// A local damping ratio, checked for the field `field`: λ = π ζ must stay below 1, or the
/// damping would turn a force around.
pub(crate) fn check_local_damping_ratio(field: &str, ratio: f64) -> Result<()> {
    if !(ratio.is_finite() && (0.0..0.3).contains(&ratio)) {
        return Err(Error::input(field, format!("must lie in [0, 0.3), got {ratio}")));
    }
    Ok(())
}

fn default_gap() -> f64 {
    0.1
}

/// `[[fix]]` of a 3D scene.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Fix3 {
    /// Name.
    pub name: String,
    /// Spheres whose centres lie in this box.
    #[serde(rename = "box")]
    pub region: Box3,
    /// Velocity, m/s (default 0: fixed).
    #[serde(default)]
    pub velocity_mps: [f64; 3],
}

/// `[[load]]` of a 3D scene.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Load3 {
    /// Name.
    pub name: String,
    /// Free spheres whose centres lie in this box share the force equally.
    #[serde(rename = "box")]
    pub region: Box3,
    /// Total force, N, constant.
    pub force_n: [f64; 3],
}

/// `[[mirror]]`: a symmetry plane of a 3D scene.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Mirror3 {
    /// The plane's normal.
    pub normal: Axis3,
    /// Where it lies along its normal, m.
    pub at_m: f64,
}

impl Scene3 {
    /// The kernel's symmetry planes.
    pub fn mirrors(&self) -> crate::kernel3d::mirror::Mirrors {
        let axis = |a: Axis3| match a {
            Axis3::X => 0,
            Axis3::Y => 1,
            Axis3::Z => 2,
        };
        crate::kernel3d::mirror::Mirrors(self.mirror.iter().map(|m| crate::kernel3d::mirror::Mirror { axis: axis(m.normal), at_m: m.at_m }).collect())
    }

    /// Parse TOML text; `origin` names the file in messages.
    pub fn from_toml(text: &str, origin: &Path) -> Result<Scene3> {
        let scene: Scene3 = parse(text, origin)?;
        scene.validate().map_err(|e| e.in_file(origin))?;
        Ok(scene)
    }

    /// Serialise back to TOML.
    pub fn to_toml(&self) -> String {
        toml::to_string(self).expect("a scene always serialises")
    }

    /// Check what parsing cannot: names resolve, numbers are physical, each body has one region.
    pub fn validate(&self) -> Result<()> {
        let g = &self.scene;
        if g.dim != 3 {
            return Err(Error::input("scene.dim", format!("a 3D scene has dim = 3, got {} (a 2D scene has no dim)", g.dim)));
        }
        if g.name.is_empty() || g.name.contains(['/', '\\']) {
            return Err(Error::input("scene.name", format!("must be a non-empty file name, got {:?}", g.name)));
        }
        if !(g.duration_s.is_finite() && g.duration_s > 0.0) {
            return Err(Error::input("scene.duration_s", format!("must be a finite number > 0, got {}", g.duration_s)));
        }
        let t = &self.time_step;
        if !(t.safety > 0.0 && t.safety <= 1.0) {
            return Err(Error::input("time_step.safety", format!("must lie in (0, 1], got {}", t.safety)));
        }
        if let Some(dt) = t.dt_s
            && !(dt.is_finite() && dt > 0.0)
        {
            return Err(Error::input("time_step.dt_s", format!("must be a finite number > 0, got {dt}")));
        }
        if !(t.skin_ratio.is_finite() && t.skin_ratio > 0.0) {
            return Err(Error::input("time_step.skin_ratio", format!("must be a finite number > 0, got {}", t.skin_ratio)));
        }
        for (k, m) in self.mirror.iter().enumerate() {
            if self.mirror[..k].iter().any(|o| o.normal == m.normal) {
                return Err(Error::input(format!("mirror[{k}].normal"), "one plane per axis"));
            }
            if !m.at_m.is_finite() {
                return Err(Error::input(format!("mirror[{k}].at_m"), format!("must be finite, got {}", m.at_m)));
            }
        }
        if !(self.damping.alpha_per_s.is_finite() && self.damping.alpha_per_s >= 0.0) {
            return Err(Error::input("damping.alpha_per_s", format!("must be a finite number ≥ 0, got {}", self.damping.alpha_per_s)));
        }
        if self.output.every_steps == 0 {
            return Err(Error::input("output.every_steps", "must be at least 1"));
        }
        for (k, m) in self.material.iter().enumerate() {
            m.validate(&format!("material[{k}]"))?;
            if self.material[..k].iter().any(|o| o.name == m.name) {
                return Err(Error::input(format!("material[{k}].name"), format!("{:?} is given twice", m.name)));
            }
        }
        if self.body.is_empty() {
            return Err(Error::input("body", "a scene needs at least one [[body]]"));
        }
        for (k, b) in self.body.iter().enumerate() {
            let f = format!("body[{k}]");
            if !self.material.iter().any(|m| m.name == b.material) {
                return Err(Error::input(format!("{f}.material"), format!("no [[material]] is named {:?}", b.material)));
            }
            if !(b.element_radius_m.is_finite() && b.element_radius_m > 0.0) {
                return Err(Error::input(format!("{f}.element_radius_m"), format!("must be a finite number > 0, got {}", b.element_radius_m)));
            }
            if !(b.bond_gap_ratio.is_finite() && (0.0..=1.0).contains(&b.bond_gap_ratio)) {
                return Err(Error::input(format!("{f}.bond_gap_ratio"), format!("must lie in [0, 1], got {}", b.bond_gap_ratio)));
            }
            check_local_damping_ratio(&format!("{f}.local_damping_ratio"), b.local_damping_ratio)?;
            if !b.velocity_mps.iter().all(|v| v.is_finite()) {
                return Err(Error::input(format!("{f}.velocity_mps"), format!("must be finite, got {:?}", b.velocity_mps)));
            }
            if let Some(g) = &b.grading {
                g.validate(&format!("{f}.grading"), b.element_radius_m)?;
                if b.region.is_none() {
                    return Err(Error::input(format!("{f}.grading"), "a graded packing fills a box, not a shape"));
                }
            }
            match (&b.region, &b.shape) {
                (Some(r), None) => r.validate(&format!("{f}.box"))?,
                (None, Some(s)) => s.validate(&format!("{f}.shape"))?,
                _ => return Err(Error::input(f, "give either a box or a shape")),
            }
            if self.body[..k].iter().any(|o| o.name == b.name) {
                return Err(Error::input(format!("{f}.name"), format!("{:?} is given twice", b.name)));
            }
        }
        for (k, x) in self.fix.iter().enumerate() {
            x.region.validate(&format!("fix[{k}].box"))?;
            if !x.velocity_mps.iter().all(|v| v.is_finite()) {
                return Err(Error::input(format!("fix[{k}].velocity_mps"), format!("must be finite, got {:?}", x.velocity_mps)));
            }
        }
        for (k, a) in self.absorb.iter().enumerate() {
            a.validate(&format!("absorb[{k}]"))?;
        }
        for (k, l) in self.load.iter().enumerate() {
            l.region.validate(&format!("load[{k}].box"))?;
            if !l.force_n.iter().all(|v| v.is_finite()) {
                return Err(Error::input(format!("load[{k}].force_n"), format!("must be finite, got {:?}", l.force_n)));
            }
        }
        for (k, p) in self.probe.iter().enumerate() {
            p.validate(&format!("probe[{k}]"))?;
        }
        Ok(())
    }
}
