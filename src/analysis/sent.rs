//! Handbook critical stress of a single-edge-notch tension (SENT) plate: the reference for the
//! cracked-plate convergence study (seed 000 eq 4.3, SPEC §3).
//!
//! The geometry factor is the least-squares fit to boundary-collocation results of Gross, Srawley
//! and Brown (1964–66) as quoted by Tada, Paris & Irwin, *The Stress Analysis of Cracks Handbook*:
//! accurate to 0.5 % for a/c ≤ 0.6. The seed prints it as `K_Ic/√(πa) · [F]^(1/2)` with rounded
//! coefficients; both are misprints (SPEC §3): the stress is K_Ic / (√(πa) F), which is what
//! reproduces the seed's own 2.61 MPa (the printed form gives 2.89 MPa).

/// Largest crack-to-width ratio a/c for which the fit holds.
pub const SENT_MAX_CRACK_RATIO: f64 = 0.6;

/// The fit's accuracy within its range, as a fraction (0.5 %).
pub const SENT_FIT_ACCURACY_FRACTION: f64 = 0.005;

/// Geometry factor F(a/c) = 1.12 − 0.231 x + 10.55 x² − 21.72 x³ + 30.39 x⁴, x = a/c
/// (dimensionless), so that K_I = σ √(πa) F.
pub fn sent_geometry_factor(crack_ratio: f64) -> f64 {
    let x = crack_ratio;
    1.12 + x * (-0.231 + x * (10.55 + x * (-21.72 + x * 30.39)))
}

/// Far-field tension σ_F = K_Ic / (√(πa) F(a/c)) at which an edge crack of length
/// `crack_length_m` in a plate of width `width_m` grows unstably.
///
/// # Panics
/// If a, c or K_Ic is not positive and finite, or a/c > [`SENT_MAX_CRACK_RATIO`]: outside the
/// fit's range the polynomial is not a handbook value, and a reference must not pretend to be one.
/// Check inputs that come from a user against the constant first.
pub fn sent_critical_stress_pa(k_ic_pa_sqrt_m: f64, crack_length_m: f64, width_m: f64) -> f64 {
    let positive = |v: f64| v > 0.0 && v.is_finite();
    assert!(
        positive(k_ic_pa_sqrt_m) && positive(crack_length_m) && positive(width_m),
        "SENT: K_Ic = {k_ic_pa_sqrt_m} Pa√m, a = {crack_length_m} m, c = {width_m} m must be positive"
    );
    let ratio = crack_length_m / width_m;
    assert!(
        ratio <= SENT_MAX_CRACK_RATIO,
        "SENT: a/c = {ratio} is outside the fit's range a/c ≤ {SENT_MAX_CRACK_RATIO}"
    );
    k_ic_pa_sqrt_m / ((std::f64::consts::PI * crack_length_m).sqrt() * sent_geometry_factor(ratio))
}

#[cfg(test)]
mod tests {
    use super::*;

    // The seed's cracked plate (section 4): K_Ic = 1 MPa√m, a = 0.03125 m, a/c = 1/8.
    const K_IC: f64 = 1.0e6;
    const A: f64 = 0.03125;
    const C: f64 = 0.25;

    #[test]
    fn seed_plate_gives_the_printed_2_61_mpa() {
        let sigma = sent_critical_stress_pa(K_IC, A, C);
        assert_eq!((sigma / 1e4).round(), 261.0, "{sigma} Pa");
        // And to more digits, worked by hand: F(1/8) = 1.2209663, σ = 2.613945 MPa.
        assert!((sigma - 2.613_945e6).abs() < 1.0, "{sigma} Pa");
    }

    #[test]
    fn the_misprinted_square_root_form_gives_2_89_mpa() {
        let printed =
            K_IC / ((std::f64::consts::PI * A).sqrt() * sent_geometry_factor(A / C).sqrt());
        assert_eq!((printed / 1e4).round(), 289.0, "{printed} Pa");
    }

    #[test]
    fn the_seeds_rounded_coefficients_agree_to_the_printed_digits() {
        let x: f64 = A / C;
        let rounded = 1.12 - 0.23 * x + 10.6 * x * x - 21.7 * x.powi(3) + 30.4 * x.powi(4);
        let sigma = K_IC / ((std::f64::consts::PI * A).sqrt() * rounded);
        assert_eq!((sigma / 1e4).round(), 261.0);
        assert!(
            (sigma / sent_critical_stress_pa(K_IC, A, C) - 1.0).abs() < SENT_FIT_ACCURACY_FRACTION
        );
    }

    #[test]
    fn short_cracks_approach_the_edge_crack_factor_1_12() {
        assert_eq!(sent_geometry_factor(0.0), 1.12);
        let sigma = sent_critical_stress_pa(K_IC, 1e-6, 1.0);
        let edge = K_IC / (1.12 * (std::f64::consts::PI * 1e-6).sqrt());
        assert!((sigma / edge - 1.0).abs() < 1e-6);
    }

    #[test]
    #[should_panic(expected = "outside the fit's range")]
    fn deep_cracks_are_refused() {
        sent_critical_stress_pa(K_IC, 0.61, 1.0);
    }

    #[test]
    #[should_panic(expected = "must be positive")]
    fn non_positive_inputs_are_refused() {
        sent_critical_stress_pa(K_IC, 0.0, 1.0);
    }
}
