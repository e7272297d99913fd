//! The source's penetration materials and projectile (seed 000 §7, Tables 7.1 and 7.2; SPEC
//! §4), in SI, in one place: the penetration scene, the impact benchmark and the tests build on
//! these.

use crate::material::{FailureCriterion, Material, PoissonPolicy};
use crate::units::{in_to_m, lbs2_per_in4_to_kg_per_m3, psi_sqrt_in_to_pa_sqrt_m, psi_to_pa};

/// Concrete element radius R, m (Table 7.1: 0.25 in).
pub fn concrete_radius_m() -> f64 {
    in_to_m(0.25)
}

/// Projectile element radius, m (Table 7.2: 0.15544 in).
pub fn projectile_radius_m() -> f64 {
    in_to_m(0.15544)
}

/// Projectile width (diameter) D, m (Table 7.2: 3.5 in).
pub fn projectile_width_m() -> f64 {
    in_to_m(3.5)
}

/// Projectile weight, lb (Table 7.2: 15 lb).
pub const PROJECTILE_WEIGHT_LB: f64 = 15.0;

/// The effective density of the projectile, lb·s²/in⁴ (Table 7.2).
pub const PROJECTILE_EFFECTIVE_DENSITY_LBS2_PER_IN4: f64 = 2.43e-3;

/// The target's concrete (Table 7.1): ρ = 2.17e-4 lb·s²/in⁴, E = 3122 ksi, ν = 0.2,
/// σ_ult = 300 psi, f'c = 3000 psi, K_Ic = 910 psi·√in (the table's "psi-s^1/2" is a misprint),
/// the energy criterion (seed §5, the one used for penetration), μ = 0.5; no rate effects or
/// compaction (a scene switches them on).
pub fn concrete() -> Material {
    Material {
        name: "concrete".into(),
        density_kg_per_m3: lbs2_per_in4_to_kg_per_m3(2.17e-4),
        youngs_modulus_pa: psi_to_pa(3122e3),
        poisson_ratio: 0.2,
        tensile_strength_pa: psi_to_pa(300.0),
        compressive_strength_pa: psi_to_pa(3000.0),
        fracture_toughness_pa_sqrt_m: psi_sqrt_in_to_pa_sqrt_m(910.0),
        friction_coefficient: 0.5,
        cohesion_n_per_m: 0.0,
        failure: FailureCriterion::StrengthEnergy,
        poisson_policy: PoissonPolicy::Refuse,
        rate: None,
        compaction: None,
    }
}

/// The projectile's steel (Table 7.2): E = 29 000 ksi, ν = 0.3, no failure; the density is
/// Table 7.2's effective one (the penetration scene sets it from the weight and the 2D
/// mapping). In plane strain ν* = 0.43 > 1/3: the close-packed lattice takes ν* = 1/3 (Kt = 0
/// in its bonds; the projectile does not fail, so its Poisson effect barely matters).
pub fn steel() -> Material {
    Material {
        name: "steel".into(),
        density_kg_per_m3: lbs2_per_in4_to_kg_per_m3(PROJECTILE_EFFECTIVE_DENSITY_LBS2_PER_IN4),
        youngs_modulus_pa: psi_to_pa(29_000e3),
        poisson_ratio: 0.3,
        tensile_strength_pa: 0.0,
        compressive_strength_pa: 0.0,
        fracture_toughness_pa_sqrt_m: 0.0,
        friction_coefficient: 0.5,
        cohesion_n_per_m: 0.0,
        failure: FailureCriterion::None,
        poisson_policy: PoissonPolicy::ClampToOneThird,
        rate: None,
        compaction: None,
    }
}
