//! `compaction = { ... }` of a material: the constants of the compaction law as a scene file
//! gives them, plain data below both the material and the law (`crate::kernel::law::compaction`).

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

/// `compaction = { ... }` of a material.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CompactionSpec {
    /// Slope of the yield line K_c as a fraction of the bond's Kn (0: perfectly plastic).
    #[serde(default)]
    pub stiffness_ratio: f64,
    /// Plastic strain (L0 − d0*)/L0 at full compaction (seed: d0* = R, i.e. 0.5).
    #[serde(default = "default_full_strain")]
    pub full_strain: f64,
}

fn default_full_strain() -> f64 {
    0.5
}

impl Default for CompactionSpec {
    fn default() -> Self {
        CompactionSpec { stiffness_ratio: 0.0, full_strain: default_full_strain() }
    }
}

impl CompactionSpec {
    /// Check the constants; `prefix` names the table in messages.
    pub fn validate(&self, prefix: &str) -> Result<()> {
        if !(self.stiffness_ratio.is_finite() && (0.0..=1.0).contains(&self.stiffness_ratio)) {
            return Err(Error::input(format!("{prefix}.stiffness_ratio"), format!("must lie in [0, 1], got {}", self.stiffness_ratio)));
        }
        if !(self.full_strain.is_finite() && self.full_strain > 0.0 && self.full_strain < 1.0) {
            return Err(Error::input(format!("{prefix}.full_strain"), format!("must lie in (0, 1), got {}", self.full_strain)));
        }
        Ok(())
    }
}
