//! The seed's single-degree-of-freedom estimate of the cantilever's tip response (seed 000
//! section 4): the closed form it draws beside the DEM, kept to show what the modal reference
//! ([`super::timoshenko`]) adds.
//!
//! What it assumes, exactly:
//! - Euler–Bernoulli bending only: no shear flexibility, no rotary inertia (κ of the beam is
//!   ignored);
//! - one mode: the natural frequency is the beam's fundamental, ω_n = 3.52 √(EI/(M L³)) with
//!   M = ρAL the total mass; 3.52 is (1.875104)² = 3.51602 rounded, so ω_n is 0.11 % high;
//! - the stiffness is the static tip stiffness k = 3EI/L³, so the static limit is exact in
//!   Euler–Bernoulli theory and the implied mass is k/ω_n² = 0.242 M; the higher modes, which
//!   carry 2.9 % of the static tip flexibility (1 − 12/(1.875104)⁴), are thereby lumped into the
//!   fundamental and move with its dynamic amplification;
//! - damping ξ = α/(2ω_n): the mass-proportional damping C = αM of the reference, read at ω_n.
//!
//! Amplitude (F/k)/√((1 − r²)² + (2ξr)²), r = ω/ω_n.

use super::beam::Beam;

/// The seed's frequency coefficient, ω_n = 3.52 √(EI/(M L³)).
pub const SDOF_FREQUENCY_COEFFICIENT: f64 = 3.52;

/// ω_n = 3.52 √(EI/(M L³)), rad/s.
pub fn sdof_natural_rad_per_s(beam: &Beam) -> f64 {
    SDOF_FREQUENCY_COEFFICIENT
        * (beam.bending_rigidity_n_m2() / (beam.mass_kg() * beam.length_m.powi(3))).sqrt()
}

/// k = 3EI/L³, N/m.
pub fn sdof_stiffness_n_per_m(beam: &Beam) -> f64 {
    3.0 * beam.bending_rigidity_n_m2() / beam.length_m.powi(3)
}

/// Steady-state tip amplitude of the SDOF model under F sin ωt with C = αM, m.
pub fn sdof_tip_amplitude_m(
    beam: &Beam,
    force_amplitude_n: f64,
    omega_rad_per_s: f64,
    alpha_per_s: f64,
) -> f64 {
    let omega_n = sdof_natural_rad_per_s(beam);
    let r = omega_rad_per_s / omega_n;
    let xi = alpha_per_s / (2.0 * omega_n);
    force_amplitude_n
        / sdof_stiffness_n_per_m(beam)
        / ((1.0 - r * r).powi(2) + (2.0 * xi * r).powi(2)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::beam::Theory;

    fn beam() -> Beam {
        Beam::rectangular(10.0, 10.0 * 3f64.sqrt() / 18.0, 1.0, 1.2e9, 0.3, 2000.0)
    }

    #[test]
    fn static_limit_is_the_euler_bernoulli_tip_deflection() {
        let b = beam();
        let exact = b.static_tip_deflection_m(Theory::EulerBernoulli, 1e3);
        assert!((sdof_tip_amplitude_m(&b, 1e3, 0.0, 0.0) / exact - 1.0).abs() < 1e-14);
    }

    #[test]
    fn frequency_is_the_rounded_euler_bernoulli_fundamental() {
        let b = beam();
        let exact = 1.875_104_068_711_961_f64.powi(2)
            * (b.bending_rigidity_n_m2() / (b.mass_per_length_kg_per_m() * b.length_m.powi(4)))
                .sqrt();
        let ratio = sdof_natural_rad_per_s(&b) / exact;
        assert!((ratio - 3.52 / 1.875_104_068_711_961_f64.powi(2)).abs() < 1e-14, "{ratio}");
        assert!((ratio - 1.001_133).abs() < 1e-6, "{ratio}"); // the 0.11 % of the module doc
    }

    #[test]
    fn resonance_is_limited_by_the_damping_ratio() {
        let b = beam();
        let wn = sdof_natural_rad_per_s(&b);
        let alpha = 2.0 * 0.05 * wn; // ξ = 5 % at ω_n
        let static_m = 1e3 / sdof_stiffness_n_per_m(&b);
        let peak = sdof_tip_amplitude_m(&b, 1e3, wn, alpha);
        assert!((peak / static_m - 10.0).abs() < 1e-12, "{}", peak / static_m);
    }
}
