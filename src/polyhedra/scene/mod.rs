//! The rockfill scene (seed §4.2): a packed Voronoi rockfill layer and the Fig. 5 projectile
//! fired into the centre of its face, as a TOML document (`[rockfill]`) that `demsweep run`
//! builds into a polyhedral model ([`build`]) and records ([`probe`]).

pub mod build;
pub mod probe;

use serde::{Deserialize, Serialize};

use super::law::Law;
use super::projectile::Ogive;
use super::rockfill::Grading;
use crate::error::{Error, Result};

/// A rockfill scene file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RockfillScene {
    /// The scene.
    pub rockfill: Rockfill,
}

/// The scene's fields.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Rockfill {
    /// Scene name (the output folder).
    pub name: String,
    /// Simulated time of the event, s.
    pub duration_s: f64,
    /// Steps between records.
    pub every_steps: u64,
    /// Time step as a fraction of the stability limit.
    pub dt_fraction: f64,
    /// The layer and its rocks.
    pub layer: Layer,
    /// How the layer is packed.
    pub packing: PackingFields,
    /// The law between rocks.
    pub rock_law: LawFields,
    /// The law between a rock and the projectile.
    pub projectile_law: LawFields,
    /// The projectile.
    pub projectile: ProjectileFields,
}

/// The layer.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Layer {
    /// Thickness along the path, width, height (L × W × H), m.
    pub size_m: [f64; 3],
    /// Mean rock size (equivalent-sphere diameter), m.
    pub mean_size_m: f64,
    /// Half-width of the size range over the mean (0.1: ±10 %).
    pub spread: f64,
    /// Mean shrink factor of the Voronoi cells (eq 29's q).
    pub grade: f64,
    /// Seed of the rockfill's draws.
    pub seed: u64,
    /// Rock density, kg/m³.
    pub density_kg_per_m3: f64,
}

/// The packing: drop, compaction by the lid, rest.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PackingFields {
    /// Packing fraction to compact to (rock volume over the box below the lid).
    pub fraction: f64,
    /// Normal stiffness while packing, N/m (softer than the event's: fewer steps).
    pub stiffness_n_per_m: f64,
    /// Lid pressure at which compaction stops short of the fraction, Pa.
    pub lid_pressure_pa: f64,
    /// Lid speed, m/s.
    pub lid_speed_mps: f64,
    /// Viscous damping rate of eq 6 while packing, 1/s.
    pub damping_per_s: f64,
    /// Simulated time allowed for each phase (drop, compaction, rest), s.
    pub phase_s: f64,
}

/// A contact law's fields (seed eqs 4–5, Table 1).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LawFields {
    /// k_n, N/m^n.
    pub stiffness: f64,
    /// n: 1 linear, 1.5 Hertz-type.
    pub exponent: f64,
    /// k_s, N/m.
    pub shear_stiffness: f64,
    /// Coulomb friction coefficient.
    pub friction: f64,
    /// Coefficient of restitution.
    pub restitution: f64,
}

impl LawFields {
    /// As a law.
    pub fn law(&self) -> Law {
        Law { stiffness: self.stiffness, exponent: self.exponent, shear_stiffness: self.shear_stiffness, friction: self.friction, restitution: self.restitution }
    }
}

/// The projectile (seed Fig. 5).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProjectileFields {
    /// Overall length H, m.
    pub length_m: f64,
    /// Ogive radius R, m.
    pub ogive_radius_m: f64,
    /// Calibre D, m.
    pub calibre_m: f64,
    /// Divisions of the nose's arc.
    pub head_divisions: usize,
    /// Sectors round the axis.
    pub around: usize,
    /// Mass, kg (the seed does not print it; its inertia is the outline's, scaled to this mass).
    pub mass_kg: f64,
    /// Striking speed, m/s, along +x into the centre of the layer's face x = 0.
    pub speed_mps: f64,
    /// Gap between the nose and the face at the start, m.
    pub standoff_m: f64,
}

impl ProjectileFields {
    /// The outline.
    pub fn ogive(&self) -> Ogive {
        Ogive { length: self.length_m, ogive_radius: self.ogive_radius_m, calibre: self.calibre_m, head_divisions: self.head_divisions, around: self.around }
    }
}

impl RockfillScene {
    /// Refuses each bad field by name (`rockfill.layer.size_m`, …).
    pub fn validate(&self) -> Result<()> {
        let r = &self.rockfill;
        let positive = |field: &str, v: f64, unit: &str| -> Result<()> {
            if v > 0.0 && v.is_finite() { Ok(()) } else { Err(Error::input(format!("rockfill.{field}"), format!("must be positive and finite ({unit}), got {v}"))) }
        };
        if r.name.trim().is_empty() {
            return Err(Error::input("rockfill.name", "must not be empty"));
        }
        positive("duration_s", r.duration_s, "s")?;
        if r.every_steps == 0 {
            return Err(Error::input("rockfill.every_steps", "must be at least 1"));
        }
        if !(r.dt_fraction > 0.0 && r.dt_fraction <= 1.0) {
            return Err(Error::input("rockfill.dt_fraction", format!("must be in (0, 1], got {}", r.dt_fraction)));
        }
        for (k, v) in r.layer.size_m.iter().enumerate() {
            positive(&format!("layer.size_m[{k}]"), *v, "m")?;
        }
        self.grading().check("rockfill.layer")?;
        positive("layer.density_kg_per_m3", r.layer.density_kg_per_m3, "kg/m³")?;
        let p = &r.packing;
        if !(p.fraction > 0.0 && p.fraction < 0.9) {
            return Err(Error::input("rockfill.packing.fraction", format!("must be in (0, 0.9), got {}", p.fraction)));
        }
        positive("packing.stiffness_n_per_m", p.stiffness_n_per_m, "N/m")?;
        positive("packing.lid_pressure_pa", p.lid_pressure_pa, "Pa")?;
        positive("packing.lid_speed_mps", p.lid_speed_mps, "m/s")?;
        positive("packing.phase_s", p.phase_s, "s")?;
        if !(p.damping_per_s >= 0.0 && p.damping_per_s.is_finite()) {
            return Err(Error::input("rockfill.packing.damping_per_s", "must be zero or positive (1/s)"));
        }
        r.rock_law.law().check("rockfill.rock_law")?;
        r.projectile_law.law().check("rockfill.projectile_law")?;
        let q = &r.projectile;
        // The outline's checks name its fields without their units: give them the file's names.
        q.ogive().check("rockfill.projectile").map_err(|e| match e {
            Error::Input { file, field, message } => {
                let field = if field.ends_with("head_divisions") || field.ends_with("around") { field } else { format!("{field}_m") };
                Error::Input { file, field, message }
            }
            other => other,
        })?;
        positive("projectile.mass_kg", q.mass_kg, "kg")?;
        positive("projectile.speed_mps", q.speed_mps, "m/s")?;
        if !(q.standoff_m >= 0.0 && q.standoff_m.is_finite()) {
            return Err(Error::input("rockfill.projectile.standoff_m", "must be zero or positive (m)"));
        }
        Ok(())
    }

    /// The layer's grading.
    pub fn grading(&self) -> Grading {
        let l = &self.rockfill.layer;
        Grading { mean_m: l.mean_size_m, spread: l.spread, grade: l.grade, seed: l.seed }
    }
}
