//! Unit conversions at the edges. Internal units are SI: m, kg, s, N, Pa.
//!
//! The source documents work in inch, pound-force, second; the empirical formulas in
//! customary units. Exact factors (SPEC §1, FORMULAS §1).

/// Metres per inch (exact).
pub const M_PER_IN: f64 = 0.0254;
/// Metres per foot (exact).
pub const M_PER_FT: f64 = 0.3048;
/// Kilograms per pound mass (exact).
pub const KG_PER_LB: f64 = 0.453_592_37;
/// Standard gravity, m/s² (exact).
pub const G_MPS2: f64 = 9.806_65;
/// Newtons per pound-force (exact: lb × g).
pub const N_PER_LBF: f64 = KG_PER_LB * G_MPS2;
/// Pascals per psi (lbf/in²).
pub const PA_PER_PSI: f64 = N_PER_LBF / (M_PER_IN * M_PER_IN);
/// kg/m³ per lb/ft³.
pub const KG_PER_M3_PER_PCF: f64 = KG_PER_LB / (M_PER_FT * M_PER_FT * M_PER_FT);

/// ft/s → m/s.
pub fn fps_to_mps(v_fps: f64) -> f64 {
    v_fps * M_PER_FT
}
/// m/s → ft/s.
pub fn mps_to_fps(v_mps: f64) -> f64 {
    v_mps / M_PER_FT
}
/// in → m.
pub fn in_to_m(x_in: f64) -> f64 {
    x_in * M_PER_IN
}
/// m → in.
pub fn m_to_in(x_m: f64) -> f64 {
    x_m / M_PER_IN
}
/// psi → Pa.
pub fn psi_to_pa(p_psi: f64) -> f64 {
    p_psi * PA_PER_PSI
}
/// Pa → psi.
pub fn pa_to_psi(p_pa: f64) -> f64 {
    p_pa / PA_PER_PSI
}
/// lb (mass) → kg.
pub fn lb_to_kg(m_lb: f64) -> f64 {
    m_lb * KG_PER_LB
}
/// lb/ft³ → kg/m³.
pub fn pcf_to_kg_per_m3(rho_pcf: f64) -> f64 {
    rho_pcf * KG_PER_M3_PER_PCF
}
/// psi·√in → Pa·√m (fracture toughness).
pub fn psi_sqrt_in_to_pa_sqrt_m(k: f64) -> f64 {
    psi_to_pa(k) * M_PER_IN.sqrt()
}
/// lbf → N.
pub fn lbf_to_n(f_lbf: f64) -> f64 {
    f_lbf * N_PER_LBF
}
/// kg → lb (mass).
pub fn kg_to_lb(m_kg: f64) -> f64 {
    m_kg / KG_PER_LB
}
/// Mass density lb·s²/in⁴ (the source's inch-pound-second unit) → kg/m³.
pub fn lbs2_per_in4_to_kg_per_m3(rho: f64) -> f64 {
    rho * N_PER_LBF / M_PER_IN.powi(4)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn psi_matches_spec_factor() {
        // SPEC §1: 1 psi = 6894.757 Pa; FORMULAS §1: 6894.757293168 Pa.
        assert!((PA_PER_PSI - 6_894.757_293_168).abs() < 1e-6);
    }

    #[test]
    fn round_trips() {
        for x in [0.0, 1.0, 1234.5] {
            assert!((mps_to_fps(fps_to_mps(x)) - x).abs() <= 1e-12 * x.max(1.0));
            assert!((m_to_in(in_to_m(x)) - x).abs() <= 1e-12 * x.max(1.0));
            assert!((pa_to_psi(psi_to_pa(x)) - x).abs() <= 1e-12 * x.max(1.0));
        }
    }

    #[test]
    fn pcf_matches_formulas_factor() {
        // FORMULAS §1: 1 lb/ft³ = 16.01846337 kg/m³.
        assert!((pcf_to_kg_per_m3(1.0) - 16.018_463_37).abs() < 1e-8);
    }

    #[test]
    fn source_toughness_is_one_mpa_root_metre() {
        // Table 7.1: 910 psi·√in (the table prints "psi-s^1/2", a misprint).
        assert!((psi_sqrt_in_to_pa_sqrt_m(910.0) / 1.0e6 - 1.0).abs() < 2e-3);
    }

    #[test]
    fn source_concrete_density() {
        // Table 7.1: 2.17e-4 lb·s²/in⁴ ≈ 2319 kg/m³ (≈ 145 pcf).
        let rho = lbs2_per_in4_to_kg_per_m3(2.17e-4);
        assert!((rho - 2319.4).abs() < 1.0, "{rho}");
    }
}
