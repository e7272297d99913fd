//! What a 3D scene records: a quantity of the spheres whose centres start in a box, or of the
//! whole model, as a column of the run's series.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::kernel3d::Model;
use crate::packing3d::Box3;
use crate::simulation::{Measure, Simulation};

/// A quantity of a 3D scene.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity3 {
    /// Mean x displacement of the group, m.
    MeanDisplacementXM,
    /// Mean y displacement of the group, m.
    MeanDisplacementYM,
    /// Mean z displacement of the group, m.
    MeanDisplacementZM,
    /// Mean x velocity of the group, m/s.
    MeanVelocityXMps,
    /// Mean y velocity of the group, m/s.
    MeanVelocityYMps,
    /// Mean z velocity of the group, m/s.
    MeanVelocityZMps,
    /// Sum of the contact forces on the group along x (a held group's reaction), N.
    ForceXN,
    /// The same along y, N.
    ForceYN,
    /// The same along z, N.
    ForceZN,
    /// Kinetic energy of the model, J.
    KineticEnergyJ,
    /// Elastic energy in the contacts, J.
    StrainEnergyJ,
    /// Bonds broken so far.
    BondsBroken,
    /// Energy-balance residual, J.
    EnergyResidualJ,
}

impl Quantity3 {
    /// True when the quantity is of a group of spheres.
    pub fn needs_group(self) -> bool {
        !matches!(self, Self::KineticEnergyJ | Self::StrainEnergyJ | Self::BondsBroken | Self::EnergyResidualJ)
    }
}

/// `[[probe]]` of a 3D scene; once built, also the measure itself (its group resolved).
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Probe3 {
    /// Column name (with its unit, e.g. `top_uz_m`).
    pub name: String,
    /// What is measured.
    pub quantity: Quantity3,
    /// Spheres whose centres start in this box (group quantities only).
    #[serde(default, rename = "box", skip_serializing_if = "Option::is_none")]
    pub region: Option<Box3>,
    /// The group's spheres, resolved when the scene is built.
    #[serde(skip)]
    pub spheres: Vec<usize>,
}

impl Probe3 {
    /// Check the probe; `field` names it.
    pub fn validate(&self, field: &str) -> Result<()> {
        let unit = ["_m", "_mps", "_n", "_j", "broken"].iter().any(|u| self.name.ends_with(u));
        if self.name.is_empty() || !unit {
            return Err(Error::input(format!("{field}.name"), format!("{:?} must end in its unit (_m, _mps, _n, _j; or be a count ending in broken)", self.name)));
        }
        match (self.quantity.needs_group(), &self.region) {
            (true, None) => Err(Error::input(format!("{field}.box"), format!("{:?} is measured on the spheres in a box", self.quantity))),
            (false, Some(_)) => Err(Error::input(format!("{field}.box"), format!("{:?} is of the whole model: no box", self.quantity))),
            (true, Some(b)) => b.validate(&format!("{field}.box")),
            (false, None) => Ok(()),
        }
    }
}

impl Measure<Model> for Probe3 {
    fn name(&self) -> &str {
        &self.name
    }

    fn value(&self, m: &Model) -> f64 {
        let mean = |f: &dyn Fn(usize) -> f64| self.spheres.iter().map(|&e| f(e)).sum::<f64>() / self.spheres.len().max(1) as f64;
        // No step yet: no contact forces.
        let sum = |k: usize| self.spheres.iter().map(|&e| m.state.force_n.get(e).map_or(0.0, |f| f[k])).sum::<f64>();
        match self.quantity {
            Quantity3::MeanDisplacementXM => mean(&|e| m.displacement_m(e)[0]),
            Quantity3::MeanDisplacementYM => mean(&|e| m.displacement_m(e)[1]),
            Quantity3::MeanDisplacementZM => mean(&|e| m.displacement_m(e)[2]),
            Quantity3::MeanVelocityXMps => mean(&|e| m.state.vel_mps[e][0]),
            Quantity3::MeanVelocityYMps => mean(&|e| m.state.vel_mps[e][1]),
            Quantity3::MeanVelocityZMps => mean(&|e| m.state.vel_mps[e][2]),
            Quantity3::ForceXN => sum(0),
            Quantity3::ForceYN => sum(1),
            Quantity3::ForceZN => sum(2),
            Quantity3::KineticEnergyJ => m.kinetic_energy_j(),
            Quantity3::StrainEnergyJ => m.strain_energy_j(),
            Quantity3::BondsBroken => m.tally().bonds_broken as f64,
            Quantity3::EnergyResidualJ => m.tally().energy_residual_j,
        }
    }
}
