//! Steady-state tip response of a clamped–free beam to a tip force F sin ωt with mass-proportional
//! damping C = αM: the modal reference of the cantilever validation case (seed 000 section 4,
//! SPEC §3), in Euler–Bernoulli or Timoshenko theory (Han, Benaroya & Wei 1999).
//!
//! The continuous beam is replaced by a converged 1D finite-element model (`beam_element.rs`)
//! and its modes. C = αM is classical damping, so the modes decouple and mode k has damping ratio
//! ξ_k = α/(2ω_k); the tip receptance is the modal sum Σ φ_k(tip)²/(ω_k² − ω² + 2iξ_kω_kω), with
//! every mode of the model kept, so the sum is the model's exact receptance and the static limit is
//! exact (the elements' stiffness is). The SDOF estimate of the seed is in [`super::sdof`].
//!
//! Why the eigenproblem is posed on the stiffness: K x = λ M x is solved as
//! L⁻¹ M L⁻ᵀ q = (1/λ) q with K = L Lᵀ. A symmetric eigensolver gets each eigenvalue to about
//! ε × the largest one, and the fundamental is the largest 1/λ, so it comes out to round-off;
//! posed on M (Cholesky of M), the fundamental would be the smallest λ and carry ε λ_max/λ₁ ≈ ε N⁴
//! of error (1e-7 at 128 Euler–Bernoulli elements). The modes come out K-normalised, so
//! φ(tip)² is directly the mode's share of the static tip flexibility.

use nalgebra::{DMatrix, DVector, SymmetricEigen};

use super::beam::{Beam, Theory};
use super::beam_element::element;
use crate::error::Result;

/// Euler–Bernoulli elements of the default model: Hermite cubics converge as N⁻⁴, and 48 put
/// ω₁–ω₃ within 1e-6 and the tip amplitude up to 3ω₁ within 1e-7 of the continuum (tested), while
/// the N⁴ conditioning of K keeps round-off near 1e-10. A lightly damped higher resonance needs
/// more (ξ = 1 % on ω₂: 3e-6 with 48, 2e-7 with 96).
pub const EULER_BERNOULLI_ELEMENTS: usize = 48;

/// Timoshenko elements of the default model: the interdependent-interpolation element converges
/// only as N⁻² (its shear strain is constant per element). With 256, the sample beam of the tests
/// (depth/length 0.096) has ω₁ within 2e-8 of the continuum and a Richardson GCI below 1e-6 on the
/// tip amplitude up to 3ω₁; the error grows with depth (at depth/length 0.3, ω₁ within 2e-7 but
/// 1.3e-6 at 1.5ω₁ with 1 % damping, measured against the continuum with the Python prototype of
/// `scripts/cantilever_exact.py`). Use [`CantileverModes::with_elements`] for more.
pub const TIMOSHENKO_ELEMENTS: usize = 256;

/// The default element count of `theory`.
pub fn default_elements(theory: Theory) -> usize {
    match theory {
        Theory::EulerBernoulli => EULER_BERNOULLI_ELEMENTS,
        Theory::Timoshenko => TIMOSHENKO_ELEMENTS,
    }
}

/// One mode of the cantilever.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mode {
    /// Undamped natural frequency ω_k, rad/s.
    pub omega_rad_per_s: f64,
    /// The mode's share of the static tip flexibility, φ_k(tip)²/ω_k² (mass-normalised φ), m/N.
    /// The shares of all modes add up to the static tip flexibility.
    pub tip_flexibility_m_per_n: f64,
}

/// The modes of one beam in one theory, computed once; each frequency of a sweep is then a sum.
#[derive(Debug, Clone, PartialEq)]
pub struct CantileverModes {
    theory: Theory,
    elements: usize,
    modes: Vec<Mode>,
}

impl CantileverModes {
    /// The modes of the default model of `theory`.
    pub fn new(beam: &Beam, theory: Theory) -> Result<CantileverModes> {
        CantileverModes::with_elements(beam, theory, default_elements(theory))
    }

    /// The modes of a model of `elements` equal elements (at least 1).
    pub fn with_elements(beam: &Beam, theory: Theory, elements: usize) -> Result<CantileverModes> {
        beam.validate()?;
        if elements == 0 {
            return Err(crate::Error::input("elements", "a beam model needs at least one element"));
        }
        let (stiffness, mass) = assemble(beam, theory, elements);
        let n = stiffness.nrows();
        let l = stiffness
            .cholesky()
            .expect("a clamped elastic beam has a positive definite stiffness")
            .l();
        let solve =
            |b: &DMatrix<f64>| l.solve_lower_triangular(b).expect("L has a positive diagonal");
        let lm = solve(&mass); // L⁻¹ M
        let b = solve(&lm.transpose()); // L⁻¹ M L⁻ᵀ, symmetric up to round-off
        let b = (&b + b.transpose()) * 0.5;
        let mut tip = DVector::zeros(n);
        tip[n - 2] = 1.0;
        let tip = l.solve_lower_triangular(&tip).expect("L has a positive diagonal"); // L⁻¹ e_tip

        let eigen = SymmetricEigen::new(b);
        let mut modes: Vec<Mode> = eigen
            .eigenvalues
            .iter()
            .zip(eigen.eigenvectors.column_iter())
            .map(|(&compliance, q)| {
                assert!(compliance > 0.0, "a non-positive eigenvalue 1/ω² = {compliance:e}");
                Mode {
                    omega_rad_per_s: compliance.sqrt().recip(),
                    tip_flexibility_m_per_n: tip.dot(&q).powi(2),
                }
            })
            .collect();
        modes.sort_by(|a, b| a.omega_rad_per_s.total_cmp(&b.omega_rad_per_s));
        Ok(CantileverModes { theory, elements, modes })
    }

    /// The theory the modes were computed in.
    pub fn theory(&self) -> Theory {
        self.theory
    }

    /// The model's element count.
    pub fn elements(&self) -> usize {
        self.elements
    }

    /// All modes of the model, lowest frequency first.
    pub fn modes(&self) -> &[Mode] {
        &self.modes
    }

    /// The fundamental natural frequency ω₁, rad/s.
    pub fn fundamental_rad_per_s(&self) -> f64 {
        self.modes[0].omega_rad_per_s
    }

    /// Steady-state tip-deflection amplitude under F sin ωt with C = αM, m (all modes).
    pub fn tip_amplitude_m(
        &self,
        force_amplitude_n: f64,
        omega_rad_per_s: f64,
        alpha_per_s: f64,
    ) -> f64 {
        modal_tip_amplitude_m(&self.modes, force_amplitude_n, omega_rad_per_s, alpha_per_s)
    }
}

/// Tip amplitude F |Σ_k φ_k(tip)²/(ω_k² − ω² + iαω)|, m, over the given modes: all of
/// [`CantileverModes::modes`] for the reference, or the first few to see what truncation costs.
/// Infinite at an undamped resonance.
pub fn modal_tip_amplitude_m(
    modes: &[Mode],
    force_amplitude_n: f64,
    omega_rad_per_s: f64,
    alpha_per_s: f64,
) -> f64 {
    let damping = alpha_per_s * omega_rad_per_s; // 2 ξ_k ω_k ω, the same for every mode
    let (mut re, mut im) = (0.0, 0.0);
    for m in modes {
        let w2 = m.omega_rad_per_s * m.omega_rad_per_s;
        let detuning = w2 - omega_rad_per_s * omega_rad_per_s;
        let gain = m.tip_flexibility_m_per_n * w2 / (detuning * detuning + damping * damping);
        re += gain * detuning;
        im -= gain * damping;
    }
    force_amplitude_n * re.hypot(im)
}

/// Tip amplitude of the default model, m. Builds the modes on every call: for a sweep over
/// frequency build a [`CantileverModes`] once.
///
/// # Panics
/// If the beam fails [`Beam::validate`].
pub fn tip_amplitude_m(
    beam: &Beam,
    theory: Theory,
    force_amplitude_n: f64,
    omega_rad_per_s: f64,
    alpha_per_s: f64,
) -> f64 {
    default_modes(beam, theory).tip_amplitude_m(force_amplitude_n, omega_rad_per_s, alpha_per_s)
}

/// Fundamental natural frequency of the default model, rad/s.
///
/// # Panics
/// If the beam fails [`Beam::validate`].
pub fn fundamental_rad_per_s(beam: &Beam, theory: Theory) -> f64 {
    default_modes(beam, theory).fundamental_rad_per_s()
}

fn default_modes(beam: &Beam, theory: Theory) -> CantileverModes {
    CantileverModes::new(beam, theory).unwrap_or_else(|e| panic!("{e}"))
}

/// Global stiffness and mass with the clamped node removed: node i ≥ 1 owns rows 2(i−1) (w) and
/// 2(i−1)+1 (ψ), so the tip deflection is row 2N−2.
fn assemble(beam: &Beam, theory: Theory, elements: usize) -> (DMatrix<f64>, DMatrix<f64>) {
    let n = 2 * elements;
    let e = element(beam, theory, beam.length_m / elements as f64);
    let (mut stiffness, mut mass) = (DMatrix::zeros(n, n), DMatrix::zeros(n, n));
    for first in 0..elements {
        // Local row j sits at global row 2·first + j − 2; rows below 0 are the clamp.
        let global = |j: usize| (2 * first + j).checked_sub(2);
        for i in 0..4 {
            for j in 0..4 {
                if let (Some(gi), Some(gj)) = (global(i), global(j)) {
                    stiffness[(gi, gj)] += e.stiffness[i][j];
                    mass[(gi, gj)] += e.mass[i][j];
                }
            }
        }
    }
    (stiffness, mass)
}

#[cfg(test)]
#[path = "timoshenko_tests.rs"]
mod tests;
