//! Typed inputs: the missile and the target, each field named with its unit.
//!
//! The constructors are the only place inputs are checked, so every formula can assume positive,
//! finite values. Errors name the field (`weight_lb`, …); the CLI maps them to its flags.

use crate::error::{Error, Result};
use crate::units;

/// Nose shape of the missile (FORMULAS §2). The NDRC labels follow Kennedy (1976) and Li et al.
/// (2005); several code bases call 0.84 "hemispherical", the numbers are the same.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Nose {
    /// Flat-faced: N = 0.72, N_h = 1.00.
    Flat,
    /// Blunt: N = 0.84, N_h = 1.12.
    Blunt,
    /// Average bullet-nosed, spherical end: N = 1.00, N_h = 1.26.
    Spherical,
    /// Very sharp: N = 1.14, N_h = 1.39.
    VerySharp,
}

impl Nose {
    /// Every nose shape, bluntest first.
    pub const ALL: [Nose; 4] = [Nose::Flat, Nose::Blunt, Nose::Spherical, Nose::VerySharp];

    /// NDRC nose-shape factor N (used by NDRC, Kar, UKAEA, Ammann & Whitney, Haldar–Hamieh,
    /// Adeli–Amin).
    pub fn ndrc_factor(self) -> f64 {
        match self {
            Nose::Flat => 0.72,
            Nose::Blunt => 0.84,
            Nose::Spherical => 1.00,
            Nose::VerySharp => 1.14,
        }
    }

    /// Hughes nose-shape factor N_h.
    pub fn hughes_factor(self) -> f64 {
        match self {
            Nose::Flat => 1.00,
            Nose::Blunt => 1.12,
            Nose::Spherical => 1.26,
            Nose::VerySharp => 1.39,
        }
    }

    /// The name used on the command line and in file names.
    pub fn name(self) -> &'static str {
        match self {
            Nose::Flat => "flat",
            Nose::Blunt => "blunt",
            Nose::Spherical => "spherical",
            Nose::VerySharp => "very-sharp",
        }
    }

    /// Parse a command-line name; the error (on field `nose`) lists the accepted names.
    pub fn parse(text: &str) -> Result<Nose> {
        Nose::ALL.into_iter().find(|n| n.name() == text).ok_or_else(|| {
            let names: Vec<&str> = Nose::ALL.iter().map(|n| n.name()).collect();
            Error::input("nose", format!("unknown nose `{text}`; expected one of {}", names.join(", ")))
        })
    }
}

/// Mild-steel Young's modulus, psi: Kar's reference E_s and the default missile modulus
/// (the source's projectile, Table 7.2: 29 000 ksi).
pub const MILD_STEEL_MODULUS_PSI: f64 = 29.0e6;

/// The missile: rigid, normal impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Missile {
    /// Weight W, lb.
    pub weight_lb: f64,
    /// Diameter D, in.
    pub diameter_in: f64,
    /// Nose shape.
    pub nose: Nose,
    /// Young's modulus E of the missile material, psi (Kar only).
    pub modulus_psi: f64,
}

/// The target: a plain-concrete wall.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Target {
    /// Uniaxial compressive strength f'c, psi.
    pub fc_psi: f64,
    /// Tensile strength f_t, psi (Hughes, variant "f_t given").
    pub ft_psi: f64,
    /// Density ρ_c, lb/ft³ (CEA-EDF).
    pub density_pcf: f64,
    /// Wall thickness h, in.
    pub thickness_in: f64,
    /// Maximum aggregate size, in (Whiffen's c; Kar's a is half of it).
    pub aggregate_in: f64,
}

/// `value` must be finite and > 0; the error names `field`.
fn positive(field: &str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::input(field, format!("must be > 0, got {value}")))
    }
}

impl Missile {
    /// A checked missile: weight, diameter and modulus must be finite and positive.
    pub fn new(weight_lb: f64, diameter_in: f64, nose: Nose, modulus_psi: f64) -> Result<Missile> {
        Ok(Missile {
            weight_lb: positive("weight_lb", weight_lb)?,
            diameter_in: positive("diameter_in", diameter_in)?,
            nose,
            modulus_psi: positive("modulus_psi", modulus_psi)?,
        })
    }

    /// Mass M, kg.
    pub fn mass_kg(&self) -> f64 {
        units::lb_to_kg(self.weight_lb)
    }

    /// Diameter d, m.
    pub fn diameter_m(&self) -> f64 {
        units::in_to_m(self.diameter_in)
    }

    /// The source report's projectile (SPEC §4): 15 lb, 3.5 in, steel, with the given nose.
    pub fn report(nose: Nose) -> Missile {
        Missile { weight_lb: 15.0, diameter_in: 3.5, nose, modulus_psi: MILD_STEEL_MODULUS_PSI }
    }
}

impl Target {
    /// A checked target: every field must be finite and positive.
    pub fn new(fc_psi: f64, ft_psi: f64, density_pcf: f64, thickness_in: f64, aggregate_in: f64) -> Result<Target> {
        Ok(Target {
            fc_psi: positive("fc_psi", fc_psi)?,
            ft_psi: positive("ft_psi", ft_psi)?,
            density_pcf: positive("density_pcf", density_pcf)?,
            thickness_in: positive("thickness_in", thickness_in)?,
            aggregate_in: positive("aggregate_in", aggregate_in)?,
        })
    }

    /// f'c, Pa.
    pub fn fc_pa(&self) -> f64 {
        units::psi_to_pa(self.fc_psi)
    }

    /// ρ_c, kg/m³.
    pub fn density_kg_per_m3(&self) -> f64 {
        units::pcf_to_kg_per_m3(self.density_pcf)
    }

    /// The source report's wall (SPEC §4, FORMULAS §6): f'c = 3000 psi, f_t = 300 psi,
    /// 145 lb/ft³, 30 in thick; the 0.75 in maximum aggregate is an assumption (not in the report).
    pub fn report() -> Target {
        Target { fc_psi: 3000.0, ft_psi: 300.0, density_pcf: 145.0, thickness_in: 30.0, aggregate_in: 0.75 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rejects_non_positive_and_names_the_field() {
        let e = Missile::new(-1.0, 3.5, Nose::Flat, MILD_STEEL_MODULUS_PSI).unwrap_err();
        assert_eq!(e.to_string(), "`weight_lb`: must be > 0, got -1");
        let e = Target::new(3000.0, 300.0, 145.0, f64::NAN, 0.75).unwrap_err();
        assert!(e.to_string().starts_with("`thickness_in`"), "{e}");
        assert!(Target::new(0.0, 300.0, 145.0, 30.0, 0.75).is_err());
    }

    #[test]
    fn nose_names_round_trip() {
        for n in Nose::ALL {
            assert_eq!(Nose::parse(n.name()).unwrap(), n);
        }
        let e = Nose::parse("ogive").unwrap_err().to_string();
        assert!(e.contains("ogive") && e.contains("very-sharp"), "{e}");
    }
}
