//! A material for the 3D kernel as a scene gives it (`[[material]]` of a `dim = 3` scene): the
//! continuum's constants, from which a contact class follows without calibration.
//!
//! - Springs: κ_n and α = k_s/k_n from E and ν on the packing's bond density
//!   (`kernel3d::stiffness::springs`, the measured relation).
//! - Bond failure (seed 000 §5 on a bond's area π r̄²): a tensile plateau σ_t π r̄² and a
//!   shear plateau τ π r̄², then plastic opening until the normal force's work reaches
//!   G_f π r̄², with G_f = K_Ic² (1 − ν²) / E, the energy release rate of a mode I crack
//!   front in plane strain (the 3D crack's front is long against the opening).
//! - Frictional contacts: the bond's springs and Coulomb's μ (eq 2.1).
//! - The moment transfer law, where the material asks for it: rolling with k_r = k_s r̄²
//!   (seed 004 eq 31, on the mean radius r̄ where eq 32 takes the smaller) and the elastic
//!   limit η of eq 16; twisting with k_t = k_s r̄² / 2 (a uniform contact disc of radius r̄ whose
//!   shear springs give k_s: its polar moment is half its radius squared times its area; the
//!   seed gives k_t only for a beam, eq 41) capped by eq 42 with tan φ = μ and cohesion c.
//!
//! Two materials meet through half-springs in series and the mean μ, their bonds (none between
//! bodies) at the smaller strength, as in 2D (`kernel::law::ContactClass::between`).

use serde::{Deserialize, Serialize};

use super::law::{Class, Compaction, restitution_damping_ratio, rolling, twisting};
use super::stiffness;
use crate::error::{Error, Result};
use crate::kernel::law::friction::series;
use crate::kernel::law::rate;
use crate::material::{CompactionSpec, FailureCriterion, RateSpec};

/// `[[material]]` of a 3D scene, SI units.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Solid {
    /// Name, referred to by bodies and used in messages.
    pub name: String,
    /// Mass density, kg/m³ (the solid's: a body's spheres together weigh density × its volume).
    pub density_kg_per_m3: f64,
    /// Young's modulus E, Pa.
    pub youngs_modulus_pa: f64,
    /// Poisson's ratio ν (a random packing of springs represents [0.047, 0.356]).
    pub poisson_ratio: f64,
    /// Bond failure law: `none` or `strength_energy`.
    #[serde(default = "no_failure")]
    pub failure: FailureCriterion,
    /// Bond tensile strength σ_t, Pa.
    #[serde(default)]
    pub tensile_strength_pa: f64,
    /// Bond shear strength τ, Pa (default: σ_t).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shear_strength_pa: Option<f64>,
    /// Fracture toughness K_Ic, Pa·√m.
    #[serde(default)]
    pub fracture_toughness_pa_sqrt_m: f64,
    /// Coulomb friction coefficient μ of frictional contacts (eq 2.1).
    #[serde(default = "default_friction")]
    pub friction_coefficient: f64,
    /// Rolling resistance of the moment transfer law (off when absent).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rolling: Option<RollingSpec>,
    /// Twisting resistance of the moment transfer law (off when absent).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub twisting: Option<TwistingSpec>,
    /// Quasi-static compressive strength f'c, Pa: the rate law's compressive ratio and
    /// compaction's critical stress on the bond's area.
    #[serde(default)]
    pub compressive_strength_pa: f64,
    /// Strain-rate effects on the bonds (seed 000 §6, the 2D kernel's laws; off when absent).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub rate: Option<RateSpec>,
    /// Compaction of the bonds in compression (seed 000 eq 6.11; off when absent).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub compaction: Option<CompactionSpec>,
    /// Coefficient of restitution e of its frictional (unbonded) contacts: two fragments meeting
    /// head-on part at e times their approach speed (a normal dashpot, `law`). Absent: elastic
    /// (e = 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub restitution: Option<f64>,
    /// The most shear stress any of its contacts carries, Pa, bonded or broken, on π r̄²: the
    /// limit of crushed concrete's strength (Holmquist, Johnson & Cook 1993's S_max) that
    /// unbreakable grains lack, whose friction otherwise grows with pressure without end.
    /// Absent: none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crushed_shear_strength_pa: Option<f64>,
}

/// What a class's rate part needs of the scene: the fastest speed in it and the mean radius of
/// the body's spheres (the default rate cap: the speed over one bond).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RateContext {
    /// Fastest initial or prescribed speed, m/s.
    pub max_speed_mps: f64,
    /// Mean sphere radius R, m.
    pub radius_m: f64,
}

/// `[material.rolling]`.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RollingSpec {
    /// Elastic limit η of eq 16: the rolling moment is capped at η r̄ |F_n|.
    pub eta: f64,
}

/// `[material.twisting]`.
#[derive(Debug, Clone, Copy, PartialEq, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct TwistingSpec {
    /// Local cohesion c of eq 42, Pa.
    #[serde(default)]
    pub cohesion_pa: f64,
}

fn no_failure() -> FailureCriterion {
    FailureCriterion::None
}

fn default_friction() -> f64 {
    0.5
}

impl Solid {
    /// Check every constant is physical; `prefix` is the dotted field path for messages.
    pub fn validate(&self, prefix: &str) -> Result<()> {
        let check = |name: &str, v: f64, zero_ok: bool| -> Result<()> {
            if v.is_finite() && (v > 0.0 || (zero_ok && v == 0.0)) {
                Ok(())
            } else {
                Err(Error::input(format!("{prefix}.{name}"), format!("must be a finite number {} 0, got {v}", if zero_ok { "≥" } else { ">" })))
            }
        };
        check("density_kg_per_m3", self.density_kg_per_m3, false)?;
        check("youngs_modulus_pa", self.youngs_modulus_pa, false)?;
        stiffness::shear_ratio(self.poisson_ratio, &format!("{prefix}.poisson_ratio"))?;
        check("friction_coefficient", self.friction_coefficient, true)?;
        match self.failure {
            FailureCriterion::None => {}
            FailureCriterion::StrengthEnergy => {
                check("tensile_strength_pa", self.tensile_strength_pa, false)?;
                check("shear_strength_pa", self.shear_strength_pa.unwrap_or(self.tensile_strength_pa), false)?;
                check("fracture_toughness_pa_sqrt_m", self.fracture_toughness_pa_sqrt_m, false)?;
            }
            other => {
                return Err(Error::input(
                    format!("{prefix}.failure"),
                    format!("{other:?} is a 2D lattice criterion; the 3D kernel has \"none\" and \"strength_energy\""),
                ));
            }
        }
        if let Some(r) = self.rolling {
            check("rolling.eta", r.eta, true)?;
        }
        if let Some(t) = self.twisting {
            check("twisting.cohesion_pa", t.cohesion_pa, true)?;
        }
        check("compressive_strength_pa", self.compressive_strength_pa, true)?;
        if let Some(r) = &self.rate {
            r.validate(&format!("{prefix}.rate"))?;
            if self.failure != FailureCriterion::None {
                check("tensile_strength_pa", self.tensile_strength_pa, false)?;
            }
        }
        if let Some(c) = &self.compaction {
            c.validate(&format!("{prefix}.compaction"))?;
            check("compressive_strength_pa", self.compressive_strength_pa, false)?;
        }
        if let Some(e) = self.restitution
            && !(e > 0.0 && e <= 1.0)
        {
            return Err(Error::input(format!("{prefix}.restitution"), format!("must lie in (0, 1], got {e}")));
        }
        if let Some(t) = self.crushed_shear_strength_pa
            && !(t > 0.0 && t.is_finite())
        {
            return Err(Error::input(format!("{prefix}.crushed_shear_strength_pa"), format!("must be positive and finite, got {t}")));
        }
        Ok(())
    }

    /// What the rate laws read of this material (None: no rate law).
    pub fn rate_source(&self) -> Option<rate::Source<'_>> {
        self.rate.as_ref().map(|spec| rate::Source {
            youngs_modulus_pa: self.youngs_modulus_pa,
            tensile_strength_pa: self.tensile_strength_pa,
            compressive_strength_pa: self.compressive_strength_pa,
            spec,
        })
    }

    /// Fracture energy G_f = K_Ic² (1 − ν²) / E, J/m².
    pub fn fracture_energy_j_per_m2(&self) -> f64 {
        self.fracture_toughness_pa_sqrt_m.powi(2) * (1.0 - self.poisson_ratio.powi(2)) / self.youngs_modulus_pa
    }

    /// The contact class of this material on a packing of bond density `bond_density`
    /// (`stiffness::bond_density`), checked for bonds of mean radius up to `r_max_m` (m): the
    /// energy law needs G_f π r̄² above the elastic energy stored at the plateau.
    pub fn class(&self, bond_density: f64, r_max_m: f64, ctx: RateContext) -> Result<Class> {
        let (kappa, alpha) = stiffness::springs(self.youngs_modulus_pa, self.poisson_ratio, bond_density)?;
        let ks = alpha * kappa;
        let breaks = self.failure == FailureCriterion::StrengthEnergy;
        let class = Class {
            bond_kn_pa: kappa,
            bond_ks_pa: ks,
            bond_tension_pa: if breaks { self.tensile_strength_pa } else { f64::INFINITY },
            bond_shear_pa: if breaks { self.shear_strength_pa.unwrap_or(self.tensile_strength_pa) } else { f64::INFINITY },
            bond_fracture_j_per_m2: if breaks { self.fracture_energy_j_per_m2() } else { f64::INFINITY },
            kn_pa: kappa,
            ks_pa: ks,
            mu: self.friction_coefficient,
            contact_damping_ratio: self.restitution.map_or(0.0, restitution_damping_ratio),
            crushed_shear_pa: self.crushed_shear_strength_pa.unwrap_or(f64::INFINITY),
            rolling: self.rolling.map(|r| rolling::Params { kr_pa: ks, eta: r.eta }),
            twisting: self.twisting.map(|t| twisting::Params {
                kt_pa: 0.5 * ks,
                cap: twisting::Cap::MohrCoulomb { tan_phi: self.friction_coefficient, cohesion_pa: t.cohesion_pa },
            }),
            // The dynamic opening at break is taken at each contact (G_f π r̄²): no class area.
            rate: rate::Params::between(self.rate_source(), self.rate_source(), 2.0 * ctx.radius_m, ctx.max_speed_mps, 0.0),
            compaction: self.compaction.map(|law| Compaction { critical_pa: self.compressive_strength_pa, law }),
        };
        if breaks {
            // G_f A ≥ F_t² / (2 k_n) with A = π r̄², F_t = σ_t A, k_n = κ r̄: r̄ ≤ 2 κ G_f / (π σ_t²).
            let r_limit = 2.0 * kappa * class.bond_fracture_j_per_m2 / (std::f64::consts::PI * self.tensile_strength_pa.powi(2));
            if r_max_m > r_limit {
                return Err(Error::Material {
                    material: self.name.clone(),
                    message: format!(
                        "fracture energy G_f = K_Ic²(1 − ν²)/E = {:.4e} J/m² is less than the elastic energy a bond stores \
                         at its tensile plateau for spheres of radius {r_max_m:.4e} m (the limit is {r_limit:.4e} m): \
                         the energy law would break bonds before they reach σ_t; use larger K_Ic or smaller spheres",
                        class.bond_fracture_j_per_m2
                    ),
                });
            }
        }
        Ok(class)
    }
}

/// The class between spheres of two materials and their classes: springs as half-springs in
/// series, the mean μ, the smaller strengths and η; rolling, twisting, rate and compaction only
/// where both have them (the rate ratios the smaller of the two, as in 2D).
pub fn between((sa, a): (&Solid, &Class), (sb, b): (&Solid, &Class), ctx: RateContext) -> Class {
    Class {
        rate: rate::Params::between(sa.rate_source(), sb.rate_source(), 2.0 * ctx.radius_m, ctx.max_speed_mps, 0.0),
        compaction: match (a.compaction, b.compaction) {
            (Some(x), Some(y)) => Some(Compaction {
                critical_pa: x.critical_pa.min(y.critical_pa),
                law: CompactionSpec { stiffness_ratio: x.law.stiffness_ratio.min(y.law.stiffness_ratio), full_strain: x.law.full_strain.min(y.law.full_strain) },
            }),
            _ => None,
        },
        bond_kn_pa: series(a.bond_kn_pa, b.bond_kn_pa),
        bond_ks_pa: series(a.bond_ks_pa, b.bond_ks_pa),
        bond_tension_pa: a.bond_tension_pa.min(b.bond_tension_pa),
        bond_shear_pa: a.bond_shear_pa.min(b.bond_shear_pa),
        bond_fracture_j_per_m2: a.bond_fracture_j_per_m2.min(b.bond_fracture_j_per_m2),
        kn_pa: series(a.kn_pa, b.kn_pa),
        ks_pa: series(a.ks_pa, b.ks_pa),
        mu: 0.5 * (a.mu + b.mu),
        // The less elastic of the two (a fragment is no bouncier on steel than on itself).
        contact_damping_ratio: a.contact_damping_ratio.max(b.contact_damping_ratio),
        // Crushed concrete on steel slides within the concrete: the weaker limit.
        crushed_shear_pa: a.crushed_shear_pa.min(b.crushed_shear_pa),
        rolling: match (a.rolling, b.rolling) {
            (Some(x), Some(y)) => Some(rolling::Params { kr_pa: series(x.kr_pa, y.kr_pa), eta: x.eta.min(y.eta) }),
            _ => None,
        },
        twisting: match (a.twisting, b.twisting) {
            (Some(x), Some(y)) => Some(twisting::Params {
                kt_pa: series(x.kt_pa, y.kt_pa),
                cap: match (x.cap, y.cap) {
                    (twisting::Cap::MohrCoulomb { cohesion_pa: ca, .. }, twisting::Cap::MohrCoulomb { cohesion_pa: cb, .. }) => {
                        twisting::Cap::MohrCoulomb { tan_phi: 0.5 * (a.mu + b.mu), cohesion_pa: ca.min(cb) }
                    }
                    _ => twisting::Cap::None,
                },
            }),
            _ => None,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const CTX: RateContext = RateContext { max_speed_mps: 100.0, radius_m: 0.005 };

    fn concrete() -> Solid {
        toml::from_str(
            "name = \"concrete\"\ndensity_kg_per_m3 = 2400.0\nyoungs_modulus_pa = 30e9\npoisson_ratio = 0.2\n\
             failure = \"strength_energy\"\ntensile_strength_pa = 3e6\nfracture_toughness_pa_sqrt_m = 1e6\n\
             [rolling]\neta = 0.1\n[twisting]\n",
        )
        .expect("a material")
    }

    #[test]
    fn the_class_follows_from_the_constants() {
        let s = concrete();
        s.validate("material[0]").unwrap();
        let b = 4.0;
        let c = s.class(b, 0.005, CTX).unwrap();
        let (kappa, alpha) = stiffness::springs(30e9, 0.2, b).unwrap();
        assert_eq!((c.bond_kn_pa, c.bond_ks_pa, c.kn_pa), (kappa, alpha * kappa, kappa));
        assert_eq!((c.bond_tension_pa, c.bond_shear_pa), (3e6, 3e6));
        assert!((c.bond_fracture_j_per_m2 - 1e12 * 0.96 / 30e9).abs() < 1e-12);
        assert_eq!(c.rolling, Some(rolling::Params { kr_pa: alpha * kappa, eta: 0.1 }));
        assert_eq!(c.twisting.map(|t| t.kt_pa), Some(0.5 * alpha * kappa));
        // The energy law's limit on the radius: G_f π r̄² = F_t²/(2 k_n) exactly there, and a
        // bond's plastic opening at break is zero.
        let r_limit = 2.0 * kappa * c.bond_fracture_j_per_m2 / (std::f64::consts::PI * 9e12);
        assert!(c.at(r_limit).at_break_m.abs() < 1e-9 * r_limit);
        let e = s.class(b, 1.01 * r_limit, CTX).unwrap_err().to_string();
        assert!(e.contains("concrete") && e.contains("K_Ic"), "{e}");
    }

    #[test]
    fn impossible_materials_are_refused_naming_the_field() {
        let bad = |s: Solid| s.validate("material[1]").unwrap_err().to_string();
        assert!(bad(Solid { poisson_ratio: 0.45, ..concrete() }).contains("material[1].poisson_ratio"));
        assert!(bad(Solid { tensile_strength_pa: 0.0, ..concrete() }).contains("material[1].tensile_strength_pa"));
        assert!(bad(Solid { failure: FailureCriterion::TensileStrength, ..concrete() }).contains("material[1].failure"));
        assert!(bad(Solid { density_kg_per_m3: f64::NAN, ..concrete() }).contains("material[1].density_kg_per_m3"));
    }

    #[test]
    fn two_materials_meet_through_springs_in_series() {
        let s = concrete();
        let c = s.class(4.0, 0.005, CTX).unwrap();
        let same = between((&s, &c), (&s, &c), CTX);
        assert!((same.kn_pa / c.kn_pa - 1.0).abs() < 1e-15 && same.mu == c.mu && same.rolling == c.rolling);
        let stiff = Class { kn_pa: 3.0 * c.kn_pa, rolling: None, ..c.clone() };
        let m = between((&s, &c), (&s, &stiff), CTX);
        assert!((m.kn_pa / (1.5 * c.kn_pa) - 1.0).abs() < 1e-15 && m.rolling.is_none());
    }
}
