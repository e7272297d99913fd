//! Bond springs from E and ν for a random isotropic packing (the 3D counterpart of seed 000's
//! eqs 3.1–3.2), by the affine (Voigt) argument: under a uniform strain ε each bond of length l
//! and direction n stretches by l n·ε·n and shears by l (ε n − (n·ε·n) n). With k_n = κ_n r̄ and
//! k_s = α k_n per bond and bond directions spread isotropically (⟨n_i n_j n_k n_l⟩ =
//! (δ_ij δ_kl + δ_ik δ_jl + δ_il δ_jk)/15), the strain energy density is that of an isotropic
//! solid with
//!   λ = κ_n B (1 − α) / 15,   μ = κ_n B (2 + 3α) / 30,   B = Σ_bonds r̄ l² / V,
//! so ν = (1 − α) / (4 + α) and E = μ (3λ + 2μ) / (λ + μ) = κ_n B (2 + 3α) / (3 (4 + α)).
//! B is the packing's bond density, dimensionless and fixed by its geometry (coordination,
//! packing fraction, size spread), not by its size: a finer packing of the same kind gives the
//! same E without recalibration.
//!
//! Central and shear springs reach ν = (1 − α)/(4 + α) ∈ (−1, 1/4] for α ≥ 0: a ν above 1/4
//! (α < 0, a negative shear spring) cannot be represented and is refused.
//! The affine assumption ignores the spheres' own relaxation (non-affine motion), which
//! softens a random packing; `tests/elastic3d.rs` measures how much.

use crate::error::{Error, Result};

/// The largest ν central and shear springs can give (α = 0).
pub const NU_MAX: f64 = 0.25;

/// α = k_s / k_n for Poisson's ratio `nu`; refuses ν outside (−1, 1/4] naming `field`.
pub fn shear_ratio(nu: f64, field: &str) -> Result<f64> {
    if !(nu > -1.0 && nu <= NU_MAX) {
        return Err(Error::input(
            field,
            format!("Poisson's ratio {nu} cannot be represented by a packing of bonded spheres with normal and shear springs: allowed (−1, {NU_MAX}] (ν = (1 − α)/(4 + α) for k_s = α k_n ≥ 0)"),
        ));
    }
    Ok((1.0 - 4.0 * nu) / (1.0 + nu))
}

/// The affine Lamé constants (λ, μ) over κ_n B for shear ratio α.
pub fn lame_over_kappa_b(alpha: f64) -> (f64, f64) {
    ((1.0 - alpha) / 15.0, (2.0 + 3.0 * alpha) / 30.0)
}

/// (E, ν) of the affine estimate for κ_n (Pa), α and bond density B.
pub fn affine_moduli(kappa_n_pa: f64, alpha: f64, bond_density: f64) -> (f64, f64) {
    let (l, m) = lame_over_kappa_b(alpha);
    let (l, m) = (l * kappa_n_pa * bond_density, m * kappa_n_pa * bond_density);
    (m * (3.0 * l + 2.0 * m) / (l + m), l / (2.0 * (l + m)))
}

/// κ_n (Pa) and α that give E (`e_pa`) and ν (`nu`) on a packing of bond density B, by the
/// affine estimate.
pub fn springs(e_pa: f64, nu: f64, bond_density: f64) -> Result<(f64, f64)> {
    if !(e_pa > 0.0 && e_pa.is_finite()) {
        return Err(Error::input("youngs_modulus_pa", format!("{e_pa} Pa: must be positive and finite")));
    }
    let alpha = shear_ratio(nu, "poisson_ratio")?;
    let (e1, _) = affine_moduli(1.0, alpha, bond_density);
    Ok((e_pa / e1, alpha))
}

/// B = Σ_bonds r̄ l² / V of bonds (i, j) among spheres at `centres_m` of `radii_m` whose first
/// sphere's centre lies in `inside` (a region of volume `volume_m3` away from the walls).
pub fn bond_density(centres_m: &[[f64; 3]], radii_m: &[f64], bonds: &[(u32, u32)], inside: impl Fn([f64; 3]) -> bool, volume_m3: f64) -> f64 {
    let mut sum = 0.0;
    for &(i, j) in bonds {
        let (p, q) = (centres_m[i as usize], centres_m[j as usize]);
        // Each bond counted once at each end that is inside, weighted ½.
        let ends = u8::from(inside(p)) + u8::from(inside(q));
        if ends > 0 {
            let l2 = (0..3).map(|d| (q[d] - p[d]).powi(2)).sum::<f64>();
            sum += 0.5 * f64::from(ends) * 0.5 * (radii_m[i as usize] + radii_m[j as usize]) * l2;
        }
    }
    sum / volume_m3
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_affine_moduli_give_back_the_e_and_nu_asked_for() {
        for nu in [-0.5, 0.0, 0.1, 0.2, 0.25] {
            let (kappa, alpha) = springs(30e9, nu, 1.7).unwrap();
            let (e, n) = affine_moduli(kappa, alpha, 1.7);
            assert!((e / 30e9 - 1.0).abs() < 1e-12 && (n - nu).abs() < 1e-12, "ν {nu}: {e} {n}");
        }
    }

    #[test]
    fn a_poisson_ratio_above_a_quarter_is_refused_naming_the_field() {
        let err = springs(30e9, 0.3, 1.7).unwrap_err().to_string();
        assert!(err.contains("poisson_ratio") && err.contains("0.25"), "{err}");
    }
}
