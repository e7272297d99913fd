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
//! The affine assumption ignores the spheres' own relaxation (non-affine motion). Measured on
//! `packing3d::random_dense` blocks (`tests/elastic3d.rs`), it is far off: at α = 0.25 the block
//! has E = 0.168 κ_n B against the affine 0.216 (−22 %) and ν = 0.206 against 0.176; at α = 0,
//! ν = 0.356, beyond the affine bound of 1/4. So [`springs`] uses the measured relation
//! [`MEASURED`] (E / (κ_n B) and ν against α, interpolated linearly), and the affine one stays
//! here as the theory it is compared with. The range of ν it can give is the table's,
//! [0.047, 0.356] (α from 1 down to 0); other values are refused.

use crate::error::{Error, Result};

/// The measured relation: (α, E / (κ_n B), ν) of a dense random block (`packing3d::random_dense`,
/// seed 1, side 32 R, bonds where the gap is below R/10, rolling and twisting
/// off), its outer 2 R driven along an affine strain of 10⁻⁵ and its interior relaxed; the
/// moduli from the virial stress 4 R inside the faces. Measured by
/// `cargo test --release --test elastic3d -- --ignored --nocapture measure_the_relation`
/// (relaxation converged to five digits; the 24 R block differs by +0.7 % in E and −2 % in ν).
pub const MEASURED: [(f64, f64, f64); 12] = [
    (0.0, 0.06879, 0.35640),
    (0.05, 0.10570, 0.29946),
    (0.1, 0.12690, 0.26778),
    (0.15, 0.14275, 0.24377),
    (0.2, 0.15675, 0.22379),
    (0.25, 0.16823, 0.20636),
    (0.3, 0.17906, 0.19074),
    (0.35, 0.18877, 0.17646),
    (0.4, 0.19769, 0.16325),
    (0.5, 0.21413, 0.13928),
    (0.75, 0.24860, 0.08898),
    (1.0, 0.27713, 0.04740),
];

/// α = k_s / k_n for Poisson's ratio `nu` by the measured relation; refuses a ν outside its
/// range naming `field`.
pub fn shear_ratio(nu: f64, field: &str) -> Result<f64> {
    let (hi, lo) = (MEASURED[0].2, MEASURED[MEASURED.len() - 1].2);
    if !(nu >= lo && nu <= hi) {
        return Err(Error::input(
            field,
            format!(
                "Poisson's ratio {nu} cannot be represented by a random packing of bonded spheres with normal and shear springs \
                 (measured, kernel3d::stiffness::MEASURED): allowed [{lo}, {hi}] (k_s / k_n from 1 down to 0)"
            ),
        ));
    }
    // ν falls as α grows: find the interval and interpolate.
    let k = MEASURED.windows(2).position(|w| nu <= w[0].2 && nu >= w[1].2).expect("within the table");
    let (a, b) = (MEASURED[k], MEASURED[k + 1]);
    Ok(a.0 + (b.0 - a.0) * (nu - a.2) / (b.2 - a.2))
}

/// E / (κ_n B) of the measured relation at α (interpolated linearly).
pub fn measured_stiffness(alpha: f64) -> f64 {
    let k = MEASURED.windows(2).position(|w| alpha >= w[0].0 && alpha <= w[1].0).unwrap_or(MEASURED.len() - 2);
    let (a, b) = (MEASURED[k], MEASURED[k + 1]);
    a.1 + (b.1 - a.1) * (alpha - a.0) / (b.0 - a.0)
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
/// measured relation.
pub fn springs(e_pa: f64, nu: f64, bond_density: f64) -> Result<(f64, f64)> {
    if !(e_pa > 0.0 && e_pa.is_finite()) {
        return Err(Error::input("youngs_modulus_pa", format!("{e_pa} Pa: must be positive and finite")));
    }
    let alpha = shear_ratio(nu, "poisson_ratio")?;
    Ok((e_pa / (measured_stiffness(alpha) * bond_density), alpha))
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
    fn the_affine_moduli_are_the_closed_forms() {
        for alpha in [0.0, 0.25, 1.0, 3.0] {
            let (e, nu) = affine_moduli(1.0, alpha, 1.0);
            assert!((e - (2.0 + 3.0 * alpha) / (3.0 * (4.0 + alpha))).abs() < 1e-15, "E at α {alpha}: {e}");
            assert!((nu - (1.0 - alpha) / (4.0 + alpha)).abs() < 1e-15, "ν at α {alpha}: {nu}");
        }
    }

    #[test]
    fn the_measured_relation_gives_back_its_own_points() {
        for &(alpha, e, nu) in &MEASURED {
            let a = shear_ratio(nu, "nu").unwrap();
            assert!((a - alpha).abs() < 1e-12 && (measured_stiffness(a) - e).abs() < 1e-12, "α {alpha}: {a}");
        }
    }

    #[test]
    fn a_poisson_ratio_the_packing_cannot_reach_is_refused_naming_the_field() {
        for nu in [0.4, 0.01] {
            let err = springs(30e9, nu, 1.7).unwrap_err().to_string();
            assert!(err.contains("poisson_ratio") && err.contains("0.0474") && err.contains("0.3564"), "{err}");
        }
    }
}
