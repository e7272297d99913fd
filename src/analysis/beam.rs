//! The 2D beam of the cantilever validation case (seed 000 section 4, SPEC §3): a rectangular
//! strip of the DEM's material, and the section constants both beam theories read from it.
//!
//! Plane stress or plane strain is the caller's choice of constants, as in the kernel (SPEC §2,
//! eq 1.4–1.5): pass E, ν for plane stress, E/(1−ν²), ν/(1−ν) for plane strain. The shear modulus
//! E/(2(1+ν)) of either pair is the material's own G, so one formula serves both.

use crate::error::{Error, Result};

/// Which beam theory the reference solves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Theory {
    /// Euler–Bernoulli: plane sections stay normal to the axis; no shear strain, no rotary inertia.
    EulerBernoulli,
    /// Timoshenko: shear strain with coefficient κ, and rotary inertia ρI (Han, Benaroya & Wei
    /// 1999, *J. Sound Vib.* 225(5)). The DEM lattice deforms in shear too, and at depth/length
    /// ≈ 0.1 shear moves the fundamental frequency by about 1 %.
    Timoshenko,
}

/// A straight prismatic beam of rectangular section.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Beam {
    /// Span from the clamp to the free tip, m.
    pub length_m: f64,
    /// Section depth (in the plane of bending), m.
    pub depth_m: f64,
    /// Out-of-plane thickness, m (1 m for quantities per unit thickness).
    pub thickness_m: f64,
    /// Young's modulus E (plane stress) or E/(1−ν²) (plane strain), Pa.
    pub modulus_pa: f64,
    /// Poisson's ratio ν (plane stress) or ν/(1−ν) (plane strain), dimensionless.
    pub poisson_ratio: f64,
    /// Mass density, kg/m³.
    pub density_kg_per_m3: f64,
    /// Shear coefficient κ (dimensionless); Timoshenko theory only.
    pub shear_coefficient: f64,
}

/// Cowper's (1966, *J. Appl. Mech.* 33) shear coefficient of a rectangle, κ = 10(1+ν)/(12+11ν):
/// derived from the exact elastic solution of a cantilever under tip load, which is the loading
/// of this validation case (5/6 at ν = 0, 0.850 at ν = 0.3).
pub fn cowper_rectangle(poisson_ratio: f64) -> f64 {
    10.0 * (1.0 + poisson_ratio) / (12.0 + 11.0 * poisson_ratio)
}

impl Beam {
    /// A rectangular beam with Cowper's shear coefficient.
    pub fn rectangular(
        length_m: f64,
        depth_m: f64,
        thickness_m: f64,
        modulus_pa: f64,
        poisson_ratio: f64,
        density_kg_per_m3: f64,
    ) -> Beam {
        Beam {
            length_m,
            depth_m,
            thickness_m,
            modulus_pa,
            poisson_ratio,
            density_kg_per_m3,
            shear_coefficient: cowper_rectangle(poisson_ratio),
        }
    }

    /// Refuses dimensions and constants that no elastic beam has.
    pub fn validate(&self) -> Result<()> {
        let positive = [
            ("beam.length_m", self.length_m),
            ("beam.depth_m", self.depth_m),
            ("beam.thickness_m", self.thickness_m),
            ("beam.modulus_pa", self.modulus_pa),
            ("beam.density_kg_per_m3", self.density_kg_per_m3),
            ("beam.shear_coefficient", self.shear_coefficient),
        ];
        for (field, v) in positive {
            if !(v > 0.0 && v.is_finite()) {
                return Err(Error::input(field, format!("{v} must be positive and finite")));
            }
        }
        if !(self.poisson_ratio > -1.0 && self.poisson_ratio < 0.5) {
            return Err(Error::input(
                "beam.poisson_ratio",
                format!("{} must lie in (−1, 0.5)", self.poisson_ratio),
            ));
        }
        Ok(())
    }

    /// Section area A, m².
    pub fn area_m2(&self) -> f64 {
        self.depth_m * self.thickness_m
    }

    /// Second moment of area I = t h³/12, m⁴.
    pub fn second_moment_m4(&self) -> f64 {
        self.thickness_m * self.depth_m.powi(3) / 12.0
    }

    /// Shear modulus G = E/(2(1+ν)), Pa.
    pub fn shear_modulus_pa(&self) -> f64 {
        self.modulus_pa / (2.0 * (1.0 + self.poisson_ratio))
    }

    /// Flexural rigidity EI, N·m².
    pub fn bending_rigidity_n_m2(&self) -> f64 {
        self.modulus_pa * self.second_moment_m4()
    }

    /// Shear rigidity κGA, N.
    pub fn shear_rigidity_n(&self) -> f64 {
        self.shear_coefficient * self.shear_modulus_pa() * self.area_m2()
    }

    /// Mass per unit length ρA, kg/m.
    pub fn mass_per_length_kg_per_m(&self) -> f64 {
        self.density_kg_per_m3 * self.area_m2()
    }

    /// Rotary inertia per unit length ρI, kg·m.
    pub fn rotary_inertia_kg_m(&self) -> f64 {
        self.density_kg_per_m3 * self.second_moment_m4()
    }

    /// Total mass ρAL, kg.
    pub fn mass_kg(&self) -> f64 {
        self.mass_per_length_kg_per_m() * self.length_m
    }

    /// Static tip deflection under a tip force, m: F L³/(3EI), plus F L/(κGA) in Timoshenko
    /// theory. The exact solution of either theory, and the anchor of every static-limit test.
    pub fn static_tip_deflection_m(&self, theory: Theory, force_n: f64) -> f64 {
        let bending = force_n * self.length_m.powi(3) / (3.0 * self.bending_rigidity_n_m2());
        match theory {
            Theory::EulerBernoulli => bending,
            Theory::Timoshenko => bending + force_n * self.length_m / self.shear_rigidity_n(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cowper_coefficient_of_a_rectangle() {
        assert_eq!(cowper_rectangle(0.0), 10.0 / 12.0);
        assert!((cowper_rectangle(0.3) - 13.0 / 15.3).abs() < 1e-15);
    }

    #[test]
    fn section_constants_of_a_unit_strip() {
        let b = Beam::rectangular(10.0, 0.6, 1.0, 1.2e9, 0.3, 2000.0);
        assert!((b.second_moment_m4() - 0.018).abs() < 1e-15);
        assert!((b.shear_modulus_pa() - 1.2e9 / 2.6).abs() < 1e-6);
        assert!((b.mass_kg() - 12_000.0).abs() < 1e-9);
        assert!(b.validate().is_ok());
    }

    #[test]
    fn impossible_beams_are_refused_by_field() {
        let mut b = Beam::rectangular(10.0, 0.6, 1.0, 1.2e9, 0.3, 2000.0);
        b.depth_m = 0.0;
        assert!(b.validate().unwrap_err().to_string().contains("beam.depth_m"));
        let mut b = Beam::rectangular(10.0, 0.6, 1.0, 1.2e9, 0.3, 2000.0);
        b.poisson_ratio = 0.5;
        assert!(b.validate().unwrap_err().to_string().contains("beam.poisson_ratio"));
    }
}
