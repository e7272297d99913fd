//! Material constants → contact parameters (seed 000, §1, §3, §5).
//!
//! The point of the source's method is that contact stiffness and strength follow from
//! E, ν, σ_ult, f'c and K_Ic and the element size, so a refined mesh needs no re-calibration.
//! Everything here is per unit of the model's out-of-plane thickness `t` (the caller passes it).

pub mod compaction_spec;
pub mod rate_spec;

pub use compaction_spec::CompactionSpec;
pub use rate_spec::{CompressiveRate, RateSpec};

use crate::error::{Error, Result};

/// 2D idealisation of the out-of-plane direction (seed eq 1.4–1.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Plane {
    /// σ_zz = 0: E* = E, ν* = ν.
    Stress,
    /// ε_zz = 0: E* = E/(1−ν²), ν* = ν/(1−ν).
    Strain,
}

/// The irregular packing (`lattice::irregular`, bond gap 0.35) measured on patch tests
/// (`tests/elasticity_patch.rs`): springs from eq 3.1–3.2 at the Poisson ratio ν_in (first
/// column) give the packing the ratio ν* (second) and the modulus E*/E*_wanted (third). The
/// close-packed formulas, which the source applies to irregular assemblies, leave it 28–34 %
/// too soft (fewer bonds, about 5 per element against 6, longer on average) and its ν* up to
/// 0.05 too high (a disordered network relaxes non-affinely, which springs of a fixed ratio
/// cannot follow). Means of four patches (seeds 1–3 at 120 R, seed 4 at 200 R; plane stress,
/// interior 40 % of the side); patch to patch they scatter by ±4 % in E and ±0.015 in ν*.
const IRREGULAR_POISSON: [(f64, f64, f64); 5] =
    [(0.0, 0.0493, 0.7223), (0.1, 0.1310, 0.7243), (0.2, 0.2257, 0.7127), (0.25, 0.2825, 0.6952), (0.3, 0.3539, 0.6579)];

/// The correction of the irregular packing: the ν_in that gives it `nu_star`, and its modulus
/// ratio there (springs are divided by it), by linear interpolation in [`IRREGULAR_POISSON`];
/// None outside the measured range.
pub fn irregular_correction(nu_star: f64) -> Option<(f64, f64)> {
    IRREGULAR_POISSON.windows(2).find(|w| nu_star >= w[0].1 && nu_star <= w[1].1).map(|w| {
        let t = (nu_star - w[0].1) / (w[1].1 - w[0].1);
        (w[0].0 + t * (w[1].0 - w[0].0), w[0].2 + t * (w[1].2 - w[0].2))
    })
}

/// Element arrangement; it decides which stiffness formulas apply.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Arrangement {
    /// Square lattice, 4 bonded neighbours (eq 1.1: Kn = Kt = E* t).
    SimpleCubic,
    /// Hexagonal lattice, 6 bonded neighbours (eq 3.1–3.2).
    ClosePacked,
    /// Seeded random packing; the source uses the close-packed formulas for it (eq 1.2–1.3);
    /// here they are corrected by a measured relation ([`irregular_correction`]).
    Irregular,
}

/// Which bond failure law a material uses (SPEC §2, the three criteria of the source).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FailureCriterion {
    /// Bonds never break.
    None,
    /// Brittle at f_ult = σ_ult (2R) t (eq 3.5).
    TensileStrength,
    /// Brittle at f_ult = 2 K_Ic t √(R/π) (eq 3.10).
    FractureToughness,
    /// Linear to f_n^crit, f_t^crit (eq 5.5–5.6), then plastic until the normal
    /// stress–opening area reaches G_f = K_Ic²/E* (eq 5.3, 5.7–5.9).
    StrengthEnergy,
}

/// What to do when ν* > 1/3 on a close-packed or irregular lattice, where eq 3.2 gives Kt < 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum PoissonPolicy {
    /// Refuse the material with an error (the default: a negative spring is never silently made).
    #[default]
    Refuse,
    /// Use ν* = 1/3 (Kt = 0), the largest ratio a hexagonal lattice of central-plus-shear
    /// springs can represent, keeping E*. The model's Poisson ratio is then 1/3, not ν*:
    /// acceptable for a body whose lateral strain does not matter (e.g. a projectile that
    /// does not fail).
    ClampToOneThird,
}

/// A material as the scene gives it (`[[material]]`), in SI. The scene file deserialises into
/// this struct directly, so a new constant is one field here (with its default) and the law part
/// that reads it.
#[derive(Debug, Clone, PartialEq, serde::Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Name, referred to by bodies and used in messages.
    pub name: String,
    /// Mass density, kg/m³.
    pub density_kg_per_m3: f64,
    /// Young's modulus E, Pa.
    pub youngs_modulus_pa: f64,
    /// Poisson's ratio ν.
    pub poisson_ratio: f64,
    /// Quasi-static tensile strength σ_ult, Pa (unused for `FailureCriterion::None`).
    #[serde(default)]
    pub tensile_strength_pa: f64,
    /// Quasi-static compressive strength f'c, Pa (the compaction law, eq 6.11).
    #[serde(default)]
    pub compressive_strength_pa: f64,
    /// Fracture toughness K_Ic, Pa·√m.
    #[serde(default)]
    pub fracture_toughness_pa_sqrt_m: f64,
    /// Coulomb friction coefficient μ of frictional contacts (eq 2.1).
    #[serde(default = "default_friction")]
    pub friction_coefficient: f64,
    /// Cohesion c of frictional contacts (eq 2.1), N per metre of thickness.
    #[serde(default)]
    pub cohesion_n_per_m: f64,
    /// Bond failure law.
    #[serde(default = "default_failure")]
    pub failure: FailureCriterion,
    /// Policy for ν* > 1/3 on hexagonal/irregular lattices.
    #[serde(default)]
    pub poisson_policy: PoissonPolicy,
    /// Strain-rate effects on this material's bonds (seed §6, eq 6.6–6.15); off when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rate: Option<RateSpec>,
    /// Compaction of this material's bonds in compression (eq 6.11, Fig 6.1); off when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub compaction: Option<CompactionSpec>,
}

fn default_friction() -> f64 {
    0.5
}

fn default_failure() -> FailureCriterion {
    FailureCriterion::None
}

/// Effective in-plane constants (eq 1.4–1.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Effective {
    /// E*, Pa.
    pub modulus_pa: f64,
    /// ν*.
    pub poisson: f64,
}

/// Elastic contact stiffness of a bond between two elements of one material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stiffness {
    /// Normal stiffness Kn, N/m.
    pub kn_n_per_m: f64,
    /// Tangential stiffness Kt, N/m.
    pub kt_n_per_m: f64,
}

/// Bond strength parameters in the form the bond law uses for all three criteria:
/// a tensile plateau force, a shear plateau force, and the plastic opening at which the bond
/// breaks. The brittle criteria are the special case `plastic_opening_at_break_m = 0`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Deserialize, serde::Serialize)]
pub struct Strength {
    /// Normal force at which the tensile plateau starts, N (∞: never).
    pub normal_force_n: f64,
    /// Shear force of the plastic plateau, N (∞: elastic shear).
    pub shear_force_n: f64,
    /// Plastic normal opening at which the bond breaks, m (0: brittle at `normal_force_n`).
    pub plastic_opening_at_break_m: f64,
}

impl Strength {
    /// A bond that never yields or breaks.
    pub const UNBREAKABLE: Strength = Strength {
        normal_force_n: f64::INFINITY,
        shear_force_n: f64::INFINITY,
        plastic_opening_at_break_m: f64::INFINITY,
    };
}

impl Material {
    /// An elastic material that never breaks, with no optional law: μ = 0.5, no cohesion,
    /// strengths 0 (unused without a failure criterion), ν* > 1/3 refused.
    pub fn elastic(name: &str, youngs_modulus_pa: f64, poisson_ratio: f64, density_kg_per_m3: f64) -> Material {
        Material {
            name: name.to_string(),
            density_kg_per_m3,
            youngs_modulus_pa,
            poisson_ratio,
            tensile_strength_pa: 0.0,
            compressive_strength_pa: 0.0,
            fracture_toughness_pa_sqrt_m: 0.0,
            friction_coefficient: default_friction(),
            cohesion_n_per_m: 0.0,
            failure: FailureCriterion::None,
            poisson_policy: PoissonPolicy::Refuse,
            rate: None,
            compaction: None,
        }
    }

    /// E*, ν* for the given plane idealisation (eq 1.4–1.5).
    pub fn effective(&self, plane: Plane) -> Effective {
        let (e, nu) = (self.youngs_modulus_pa, self.poisson_ratio);
        match plane {
            Plane::Stress => Effective { modulus_pa: e, poisson: nu },
            Plane::Strain => Effective { modulus_pa: e / (1.0 - nu * nu), poisson: nu / (1.0 - nu) },
        }
    }

    /// ν* used by the stiffness formulas, after the Poisson policy; refuses ν* > 1/3 on
    /// hexagonal/irregular lattices unless the material names the fallback.
    pub fn lattice_poisson(&self, plane: Plane, arrangement: Arrangement) -> Result<f64> {
        let nu_star = self.effective(plane).poisson;
        if arrangement == Arrangement::SimpleCubic || nu_star <= 1.0 / 3.0 {
            return Ok(nu_star);
        }
        match self.poisson_policy {
            PoissonPolicy::ClampToOneThird => Ok(1.0 / 3.0),
            PoissonPolicy::Refuse => Err(Error::Material {
                material: self.name.clone(),
                message: format!(
                    "ν* = {nu_star:.4} (ν = {}, plane {}) exceeds 1/3: a {} lattice would need a \
                     negative shear spring Kt = Kn (1−3ν*)/(1+ν*) (seed eq 3.2). Use plane stress, \
                     a material with ν* ≤ 1/3, or set poisson_policy = \"clamp_to_one_third\" \
                     (Kt = 0, model Poisson ratio 1/3)",
                    self.poisson_ratio,
                    match plane {
                        Plane::Stress => "stress",
                        Plane::Strain => "strain",
                    },
                    match arrangement {
                        Arrangement::ClosePacked => "close-packed",
                        _ => "irregular",
                    }
                ),
            }),
        }
    }

    /// Contact stiffness for this material's bonds (eq 1.1 for simple cubic, eq 3.1–3.2 otherwise).
    pub fn stiffness(&self, plane: Plane, arrangement: Arrangement, thickness_m: f64) -> Result<Stiffness> {
        let e_star = self.effective(plane).modulus_pa;
        Ok(match arrangement {
            Arrangement::SimpleCubic => {
                let k = e_star * thickness_m;
                Stiffness { kn_n_per_m: k, kt_n_per_m: k }
            }
            Arrangement::ClosePacked => {
                let nu = self.lattice_poisson(plane, arrangement)?;
                let kn = e_star * thickness_m / (3f64.sqrt() * (1.0 - nu));
                Stiffness { kn_n_per_m: kn, kt_n_per_m: kn * (1.0 - 3.0 * nu) / (1.0 + nu) }
            }
            Arrangement::Irregular => {
                let nu_star = self.effective(plane).poisson;
                let (nu_in, e_ratio) = irregular_correction(nu_star).ok_or_else(|| Error::Material {
                    material: self.name.clone(),
                    message: format!(
                        "ν* = {nu_star:.4} lies outside what the irregular packing's springs can represent ({:.3} ≤ ν* ≤ {:.3}: a disordered network of central and shear springs is never below the first, and its shear spring vanishes at the second); use a close-packed lattice, or plane stress/strain to bring ν* inside",
                        IRREGULAR_POISSON[0].1,
                        IRREGULAR_POISSON[IRREGULAR_POISSON.len() - 1].1
                    ),
                })?;
                let kn = e_star * thickness_m / (3f64.sqrt() * (1.0 - nu_in)) / e_ratio;
                Stiffness { kn_n_per_m: kn, kt_n_per_m: kn * (1.0 - 3.0 * nu_in) / (1.0 + nu_in) }
            }
        })
    }

    /// Fracture energy G_f = K_Ic²/E*, J/m² (eq 5.3).

    pub fn fracture_energy_j_per_m2(&self, plane: Plane) -> f64 {
        self.fracture_toughness_pa_sqrt_m.powi(2) / self.effective(plane).modulus_pa
    }

    /// Bond strength for elements of radius `radius_m` (the mean radius for unequal pairs).
    ///
    /// For simple cubic lattices eq 5.5–5.6 do not apply (they come from the hexagonal unit
    /// cell); the energy criterion then uses the square cell's uniaxial bond force
    /// σ_ult (2R) t for the plateau and no shear plateau (a square cell under uniaxial stress
    /// carries no bond shear), and the same G_f area rule.
    pub fn strength(&self, plane: Plane, arrangement: Arrangement, radius_m: f64, thickness_m: f64) -> Result<Strength> {
        let (r, t) = (radius_m, thickness_m);
        let sigma = self.tensile_strength_pa;
        Ok(match self.failure {
            FailureCriterion::None => Strength::UNBREAKABLE,
            FailureCriterion::TensileStrength => Strength {
                normal_force_n: sigma * 2.0 * r * t,
                shear_force_n: f64::INFINITY,
                plastic_opening_at_break_m: 0.0,
            },
            FailureCriterion::FractureToughness => Strength {
                normal_force_n: 2.0 * self.fracture_toughness_pa_sqrt_m * t * (r / std::f64::consts::PI).sqrt(),
                shear_force_n: f64::INFINITY,
                plastic_opening_at_break_m: 0.0,
            },
            FailureCriterion::StrengthEnergy => {
                let kn = self.stiffness(plane, arrangement, t)?.kn_n_per_m;
                let (f_n, f_t) = match arrangement {
                    Arrangement::SimpleCubic => (sigma * 2.0 * r * t, f64::INFINITY),
                    _ => {
                        let nu = self.lattice_poisson(plane, arrangement)?;
                        let base = r * t * sigma / (2.0 * (1.0 - nu));
                        (base * (3f64.sqrt() - nu / 3f64.sqrt()), base * (1.0 - 3.0 * nu))
                    }
                };
                // Area under the normal force–opening curve = G_f × crack area (2R t):
                // f δ_crit / 2 + f δ_p = G_f 2 R t  (eq 5.7 with σ_n^crit = f/(2Rt), eq 5.8–5.9).
                let delta_crit = f_n / kn;
                let delta_p = self.fracture_energy_j_per_m2(plane) * 2.0 * r * t / f_n - delta_crit / 2.0;
                if delta_p < 0.0 {
                    return Err(Error::Material {
                        material: self.name.clone(),
                        message: format!(
                            "fracture energy G_f = K_Ic²/E* = {:.4e} J/m² is less than the elastic energy \
                             stored at the strength plateau for R = {r:.4e} m: the energy law (eq 5.7) would \
                             break the bond before it reaches σ_ult; use larger K_Ic or smaller elements",
                            self.fracture_energy_j_per_m2(plane)
                        ),
                    });
                }
                Strength { normal_force_n: f_n, shear_force_n: f_t, plastic_opening_at_break_m: delta_p }
            }
        })
    }

    /// Check every constant is physical; `prefix` is the dotted field path for messages.
    pub fn validate(&self, prefix: &str) -> Result<()> {
        let pos = |name: &str, v: f64| -> Result<()> {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(Error::input(format!("{prefix}.{name}"), format!("must be a finite number > 0, got {v}")))
            }
        };
        let nonneg = |name: &str, v: f64| -> Result<()> {
            if v.is_finite() && v >= 0.0 {
                Ok(())
            } else {
                Err(Error::input(format!("{prefix}.{name}"), format!("must be a finite number ≥ 0, got {v}")))
            }
        };
        pos("density_kg_per_m3", self.density_kg_per_m3)?;
        pos("youngs_modulus_pa", self.youngs_modulus_pa)?;
        if !(self.poisson_ratio.is_finite() && (0.0..0.5).contains(&self.poisson_ratio)) {
            return Err(Error::input(
                format!("{prefix}.poisson_ratio"),
                format!("must lie in [0, 0.5), got {}", self.poisson_ratio),
            ));
        }
        nonneg("friction_coefficient", self.friction_coefficient)?;
        nonneg("cohesion_n_per_m", self.cohesion_n_per_m)?;
        match self.failure {
            FailureCriterion::None => {}
            FailureCriterion::TensileStrength => pos("tensile_strength_pa", self.tensile_strength_pa)?,
            FailureCriterion::FractureToughness => {
                pos("fracture_toughness_pa_sqrt_m", self.fracture_toughness_pa_sqrt_m)?
            }
            FailureCriterion::StrengthEnergy => {
                pos("tensile_strength_pa", self.tensile_strength_pa)?;
                pos("fracture_toughness_pa_sqrt_m", self.fracture_toughness_pa_sqrt_m)?;
            }
        }
        if let Some(r) = &self.rate {
            r.validate(&format!("{prefix}.rate"))?;
            if self.failure != FailureCriterion::None {
                pos("tensile_strength_pa", self.tensile_strength_pa)?;
            }
        }
        if let Some(c) = &self.compaction {
            c.validate(&format!("{prefix}.compaction"))?;
            pos("compressive_strength_pa", self.compressive_strength_pa)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The seed's concrete (§5, Table 5.1), as the cracked plate uses it, read as a scene file
    /// gives a material.
    fn concrete() -> Material {
        let text = "name = \"concrete\"\ndensity_kg_per_m3 = 2400.0\nyoungs_modulus_pa = 29.7e9\npoisson_ratio = 0.3\n\
                    tensile_strength_pa = 3.44e6\ncompressive_strength_pa = 34.4e6\nfracture_toughness_pa_sqrt_m = 1.0e6\n\
                    friction_coefficient = 0.5\nfailure = \"strength_energy\"\n";
        toml::from_str(text).expect("a material")
    }

    #[test]
    fn plane_strain_constants() {
        let m = Material { poisson_ratio: 0.2, ..concrete() };
        let e = m.effective(Plane::Strain);
        assert!((e.poisson - 0.25).abs() < 1e-15);
        assert!((e.modulus_pa - 29.7e9 / 0.96).abs() < 1e-3);
    }

    #[test]
    fn close_packed_stiffness_eq_3_1_3_2() {
        let k = concrete().stiffness(Plane::Stress, Arrangement::ClosePacked, 2.0).unwrap();
        let kn = 29.7e9 * 2.0 / (3f64.sqrt() * 0.7);
        assert!((k.kn_n_per_m / kn - 1.0).abs() < 1e-14);
        assert!((k.kt_n_per_m / (kn * 0.1 / 1.3) - 1.0).abs() < 1e-14);
    }

    #[test]
    fn steel_in_plane_strain_is_refused_with_the_fallback_named() {
        let steel = Material { name: "steel".into(), youngs_modulus_pa: 200e9, ..concrete() };
        let err = steel.stiffness(Plane::Strain, Arrangement::ClosePacked, 1.0).unwrap_err();
        let msg = err.to_string();
        assert!(msg.contains("steel") && msg.contains("0.4286") && msg.contains("clamp_to_one_third"), "{msg}");
        let clamped = Material { poisson_policy: PoissonPolicy::ClampToOneThird, ..steel };
        let k = clamped.stiffness(Plane::Strain, Arrangement::ClosePacked, 1.0).unwrap();
        assert_eq!(k.kt_n_per_m, 0.0);
        assert!(k.kn_n_per_m > 0.0);
    }

    #[test]
    fn energy_criterion_matches_eq_5_7_to_5_9() {
        let m = concrete();
        let (r, t) = (0.002, 1.0);
        let s = m.strength(Plane::Stress, Arrangement::ClosePacked, r, t).unwrap();
        let nu: f64 = 0.3;
        let kn = m.stiffness(Plane::Stress, Arrangement::ClosePacked, t).unwrap().kn_n_per_m;
        // eq 5.9: δ_crit = R σ (3 − ν*)/(2 E*)
        let delta_crit = r * 3.44e6 * (3.0 - nu) / (2.0 * 29.7e9);
        assert!((s.normal_force_n / kn / delta_crit - 1.0).abs() < 1e-12);
        // eq 5.8, 5.7
        let sigma_crit = s.normal_force_n / (2.0 * r * t);
        let delta_max = 1e12 / (sigma_crit * 29.7e9) + delta_crit / 2.0;
        assert!(((delta_crit + s.plastic_opening_at_break_m) / delta_max - 1.0).abs() < 1e-12);
    }

    #[test]
    fn brittle_criteria_eq_3_5_and_3_10() {
        let (r, t) = (0.01, 0.5);
        let m = Material { failure: FailureCriterion::TensileStrength, ..concrete() };
        let s = m.strength(Plane::Stress, Arrangement::SimpleCubic, r, t).unwrap();
        assert_eq!(s.normal_force_n, 3.44e6 * 2.0 * r * t);
        assert_eq!(s.plastic_opening_at_break_m, 0.0);
        let m = Material { failure: FailureCriterion::FractureToughness, ..concrete() };
        let s = m.strength(Plane::Stress, Arrangement::SimpleCubic, r, t).unwrap();
        assert!((s.normal_force_n - 2.0 * 1e6 * t * (r / std::f64::consts::PI).sqrt()).abs() < 1e-9);
    }

    #[test]
    fn validation_names_the_field() {
        let m = Material { poisson_ratio: 0.6, ..concrete() };
        let e = m.validate("material.concrete").unwrap_err().to_string();
        assert!(e.contains("material.concrete.poisson_ratio") && e.contains("[0, 0.5)"), "{e}");
    }
}
