//! Closed-form scabbing velocities and ballistic limits where FORMULAS §5 gives them: a
//! cross-check on the bracketing inverse ([`super::inverse`]), never its replacement.

use super::{
    BrlScabbing, CeaEdfForm, Formula, Missile, Quantity, Target, ace, bechtel, brl, cea_edf, chang,
    degen, kar, kennedy, ndrc, petry, stone_webster,
};

/// The velocity, ft/s, at which `f`'s quantity `q` equals `h_in`, where §5 gives a closed form
/// (`None` otherwise: Hughes, the impact-factor fits, x-only formulas).
pub fn velocity_fps(f: Formula, q: Quantity, m: &Missile, t: &Target, h_in: f64) -> Option<f64> {
    use Quantity::*;
    let d = m.diameter_in;
    match (f, q) {
        (Formula::Brl(scab), Scabbing | Perforation) => {
            let x = match (q, scab) {
                (Perforation, _) => h_in / 1.3,
                (_, BrlScabbing::TwicePerforation) => h_in / 2.6,
                (_, BrlScabbing::TwicePenetration) => h_in / 2.0,
            };
            let per = x * t.fc_psi.sqrt() * d.powf(brl::DIAMETER_EXPONENT) / (brl::COEFFICIENT * m.weight_lb);
            Some(1000.0 * per.powf(1.0 / brl::VELOCITY_EXPONENT))
        }
        (Formula::Petry(class), Scabbing | Perforation) => {
            let x = if q == Perforation { h_in / 2.0 } else { h_in / 2.2 };
            let e = x / (12.0 * class.kp_ft3_per_lb() * petry::sectional_pressure_psf(m));
            Some((petry::V2_SCALE_FPS2 * (10f64.powf(e) - 1.0)).sqrt())
        }
        (Formula::Ace, Scabbing | Perforation) => {
            let xd = kennedy_xd(q, h_in / d);
            let per = (xd - ace::OFFSET_XD) * t.fc_psi.sqrt() * d.powf(ace::DIAMETER_EXPONENT)
                / (ace::COEFFICIENT * m.weight_lb);
            // ACE's x/d never falls below 0.5: thinner walls are breached at any velocity.
            (per >= 0.0).then(|| 1000.0 * per.powf(1.0 / ace::VELOCITY_EXPONENT))
        }
        (Formula::Ndrc, Scabbing | Perforation) => {
            Some(ndrc::velocity_for_g_fps(m, t, ndrc::g_from_xd(kennedy_xd(q, h_in / d)), 1.0))
        }
        (Formula::Degen, Perforation) => {
            Some(ndrc::velocity_for_g_fps(m, t, ndrc::g_from_xd(degen::xd_for_hp(h_in / d)), 1.0))
        }
        (Formula::Kar, Scabbing | Perforation) => {
            let xd = kennedy_xd(q, kar::kennedy_ratio(m, t, h_in));
            Some(ndrc::velocity_for_g_fps(m, t, ndrc::g_from_xd(xd), kar::modulus_ratio(m)))
        }
        (Formula::CeaEdf(CeaEdfForm::Base), Perforation) => Some(cea_edf::ballistic_limit_fps(m, t, h_in)),
        (Formula::CeaEdf(CeaEdfForm::ExtensionPlain), Perforation) => {
            Some(cea_edf::extension_ballistic_limit_fps(m, t, h_in, cea_edf::Reinforcement::PLAIN))
        }
        (Formula::Chang, Perforation) => Some(chang::ballistic_limit_fps(m, t, h_in)),
        (Formula::Chang, Scabbing) => Some(chang::scabbing_velocity_fps(m, t, h_in)),
        (Formula::Bechtel, Scabbing) => Some(bechtel::scabbing_velocity_fps(m, t, h_in)),
        (Formula::StoneWebster(c), Scabbing) => Some(stone_webster::scabbing_velocity_fps(m, h_in, c.value())),
        _ => None,
    }
}

fn kennedy_xd(q: Quantity, hd: f64) -> f64 {
    if q == Quantity::Scabbing { kennedy::xd_for_hs(hd) } else { kennedy::xd_for_hp(hd) }
}
