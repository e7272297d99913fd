//! `rate = { ... }` of a material: the constants of the rate laws as a scene file gives them,
//! plain data below both the material and the law (`crate::kernel::law::rate`) that reads them.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

/// Which compressive-strength law.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CompressiveRate {
    /// CEB 1990, continuous at its switch (30 s⁻¹).
    #[default]
    Ceb,
    /// The seed's printed eq 6.12–6.15, discontinuous at its switch (10 s⁻¹).
    SeedPrinted,
}

/// `rate = { ... }` of a material: strain-rate effects on its bonds.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RateSpec {
    /// Klepaczko's exponent α (wet concrete, Brara et al. 2001: 0.95).
    #[serde(default = "default_alpha")]
    pub alpha: f64,
    /// Klepaczko's critical time t_c0, s (Brara et al. 2001: 50 µs).
    #[serde(default = "default_critical_time")]
    pub critical_time_s: f64,
    /// Compressive-strength law.
    #[serde(default)]
    pub compressive: CompressiveRate,
    /// Memory τ of the held rate that sets the strengths, s (default: t_c0).
    #[serde(default)]
    pub memory_s: Option<f64>,
    /// Time constant of the mean rate that sets the moduli, s (default: t_c0).
    #[serde(default)]
    pub modulus_filter_s: Option<f64>,
    /// Highest rate a bond can see, 1/s (default: the fastest initial speed in the scene over
    /// the bond's radius sum, the rate of the impact velocity over one element; over ℓ/2 with
    /// an averaging length).
    #[serde(default)]
    pub cap_per_s: Option<f64>,
    /// Length ℓ over which the strain rate is measured, m (`rate_field`): the bond's relative
    /// velocity is read from the velocity field smoothed over ℓ, so the rate at a front is
    /// Δv/ℓ at any element size. None or 0: the bond's own |v·n| / L0 (eq 6.7 as printed),
    /// which grows as the elements shrink.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub averaging_length_m: Option<f64>,
}

fn default_alpha() -> f64 {
    0.95
}

fn default_critical_time() -> f64 {
    50e-6
}

impl Default for RateSpec {
    fn default() -> Self {
        RateSpec {
            alpha: default_alpha(),
            critical_time_s: default_critical_time(),
            compressive: CompressiveRate::Ceb,
            memory_s: None,
            modulus_filter_s: None,
            cap_per_s: None,
            averaging_length_m: None,
        }
    }
}

impl RateSpec {
    /// Check the constants; `prefix` names the table in messages.
    pub fn validate(&self, prefix: &str) -> Result<()> {
        let positive = |name: &str, v: f64| {
            if v.is_finite() && v > 0.0 { Ok(()) } else { Err(Error::input(format!("{prefix}.{name}"), format!("must be a finite number > 0, got {v}"))) }
        };
        positive("alpha", self.alpha)?;
        positive("critical_time_s", self.critical_time_s)?;
        if let Some(m) = self.memory_s {
            positive("memory_s", m)?;
        }
        if let Some(m) = self.modulus_filter_s {
            positive("modulus_filter_s", m)?;
        }
        if let Some(c) = self.cap_per_s {
            positive("cap_per_s", c)?;
        }
        if let Some(l) = self.averaging_length_m
            && !(l.is_finite() && l >= 0.0)
        {
            return Err(Error::input(format!("{prefix}.averaging_length_m"), format!("must be a finite length ≥ 0 m (0: the bond's own length), got {l}")));
        }
        Ok(())
    }

    /// The averaging length ℓ, m, when the rate is measured over one (`rate_field`).
    pub fn averaging_length(&self) -> Option<f64> {
        self.averaging_length_m.filter(|&l| l > 0.0)
    }

    /// Memory τ of the held rate, s.
    pub fn memory(&self) -> f64 {
        self.memory_s.unwrap_or(self.critical_time_s)
    }

    /// Time constant of the mean rate, s.
    pub fn modulus_filter(&self) -> f64 {
        self.modulus_filter_s.unwrap_or(self.critical_time_s)
    }
}
