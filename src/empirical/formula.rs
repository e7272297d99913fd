//! The registry: every formula and named variant of FORMULAS.md, what it defines and its
//! prediction with validity.

use super::{
    Missile, Quantity, Target, Validity, ace, ammann_whitney, bechtel, brl, cea_edf, chang, degen,
    hughes, impact_factor, kar, kennedy, ndrc, petry, stone_webster, ukaea, whiffen,
};
use crate::units;

/// Petry's concrete class (penetrability K_p).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PetryClass {
    /// Massive plain concrete, K_p = 0.00799 ft³/lb.
    Plain,
    /// Normally reinforced, K_p = 0.00426 ft³/lb.
    NormalRc,
    /// Specially reinforced, K_p = 0.00284 ft³/lb.
    SpecialRc,
}

impl PetryClass {
    /// K_p, ft³/lb.
    pub fn kp_ft3_per_lb(self) -> f64 {
        match self {
            PetryClass::Plain => petry::kp::PLAIN_FT3_PER_LB,
            PetryClass::NormalRc => petry::kp::NORMAL_RC_FT3_PER_LB,
            PetryClass::SpecialRc => petry::kp::SPECIAL_RC_FT3_PER_LB,
        }
    }
}

/// BRL's scabbing relation (no retrieved source states it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BrlScabbing {
    /// h_s = 2 h_p (default; the source report's reading).
    TwicePerforation,
    /// h_s = 2 x.
    TwicePenetration,
}

/// CEA-EDF base formula or its reinforcement extension with r = 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CeaEdfForm {
    /// Berriaud et al. (1978).
    Base,
    /// Fullard et al. (1991) extension, plain concrete (r = 0, c_r/h = 1/3).
    ExtensionPlain,
}

/// Which tensile strength Hughes uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum HughesTensile {
    /// The target's f_t as given (the report: 300 psi).
    Given,
    /// The modulus of rupture 0.63 √f'c (MPa) \[LEPP\].
    ModulusOfRupture,
}

/// Stone & Webster's coefficient C.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StoneWebsterC {
    /// C = 900.
    C900,
    /// C = 1900.
    C1900,
}

impl StoneWebsterC {
    /// The coefficient.
    pub fn value(self) -> f64 {
        match self {
            StoneWebsterC::C900 => 900.0,
            StoneWebsterC::C1900 => 1900.0,
        }
    }
}

/// One formula with its variant.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Formula {
    /// Modified Petry ([`petry`]).
    Petry(PetryClass),
    /// BRL ([`brl`]).
    Brl(BrlScabbing),
    /// ACE ([`ace`] with [`kennedy`]).
    Ace,
    /// Modified NDRC ([`ndrc`] with [`kennedy`]).
    Ndrc,
    /// Degen perforation on the NDRC depth ([`degen`]).
    Degen,
    /// Kar ([`kar`]).
    Kar,
    /// Ammann & Whitney ([`ammann_whitney`]).
    AmmannWhitney,
    /// Whiffen ([`whiffen`]).
    Whiffen,
    /// UKAEA ([`ukaea`]).
    Ukaea,
    /// CEA-EDF ([`cea_edf`]).
    CeaEdf(CeaEdfForm),
    /// Chang ([`chang`]).
    Chang,
    /// Haldar & Hamieh ([`impact_factor`]).
    HaldarHamieh,
    /// Adeli & Amin ([`impact_factor`]).
    AdeliAmin,
    /// Hughes ([`hughes`]).
    Hughes(HughesTensile),
    /// Bechtel ([`bechtel`]).
    Bechtel,
    /// Stone & Webster ([`stone_webster`]).
    StoneWebster(StoneWebsterC),
}

/// A forward prediction at one impact velocity: `None` where the formula does not define the
/// quantity.
#[derive(Debug, Clone, PartialEq)]
pub struct Prediction {
    /// Penetration depth x, in.
    pub x_in: Option<f64>,
    /// Scabbing thickness h_s, in.
    pub hs_in: Option<f64>,
    /// Perforation thickness h_p, in.
    pub hp_in: Option<f64>,
    /// Validity of the defined quantities together.
    pub validity: Validity,
}

impl Prediction {
    /// The value of quantity `q`.
    pub fn get(&self, q: Quantity) -> Option<f64> {
        match q {
            Quantity::Penetration => self.x_in,
            Quantity::Scabbing => self.hs_in,
            Quantity::Perforation => self.hp_in,
        }
    }
}

impl Formula {
    /// Every formula and variant, in FORMULAS §6's order, then the x-only ones.
    pub const ALL: [Formula; 22] = [
        Formula::Petry(PetryClass::Plain),
        Formula::Petry(PetryClass::NormalRc),
        Formula::Petry(PetryClass::SpecialRc),
        Formula::Brl(BrlScabbing::TwicePerforation),
        Formula::Brl(BrlScabbing::TwicePenetration),
        Formula::Ace,
        Formula::Ndrc,
        Formula::Degen,
        Formula::Kar,
        Formula::CeaEdf(CeaEdfForm::Base),
        Formula::CeaEdf(CeaEdfForm::ExtensionPlain),
        Formula::Chang,
        Formula::Hughes(HughesTensile::Given),
        Formula::Hughes(HughesTensile::ModulusOfRupture),
        Formula::Bechtel,
        Formula::StoneWebster(StoneWebsterC::C900),
        Formula::StoneWebster(StoneWebsterC::C1900),
        Formula::AdeliAmin,
        Formula::HaldarHamieh,
        Formula::Ukaea,
        Formula::Whiffen,
        Formula::AmmannWhitney,
    ];

    /// Machine name of the formula (CSV `formula` column).
    pub fn id(&self) -> &'static str {
        match self {
            Formula::Petry(_) => "petry",
            Formula::Brl(_) => "brl",
            Formula::Ace => "ace",
            Formula::Ndrc => "ndrc",
            Formula::Degen => "degen",
            Formula::Kar => "kar",
            Formula::AmmannWhitney => "ammann-whitney",
            Formula::Whiffen => "whiffen",
            Formula::Ukaea => "ukaea",
            Formula::CeaEdf(_) => "cea-edf",
            Formula::Chang => "chang",
            Formula::HaldarHamieh => "haldar-hamieh",
            Formula::AdeliAmin => "adeli-amin",
            Formula::Hughes(_) => "hughes",
            Formula::Bechtel => "bechtel",
            Formula::StoneWebster(_) => "stone-webster",
        }
    }

    /// Machine name of the variant (CSV `variant` column); `standard` where there is one form.
    pub fn variant(&self) -> &'static str {
        match self {
            Formula::Petry(PetryClass::Plain) => "plain",
            Formula::Petry(PetryClass::NormalRc) => "normal-rc",
            Formula::Petry(PetryClass::SpecialRc) => "special-rc",
            Formula::Brl(BrlScabbing::TwicePerforation) => "hs=2hp",
            Formula::Brl(BrlScabbing::TwicePenetration) => "hs=2x",
            Formula::CeaEdf(CeaEdfForm::Base) => "base",
            Formula::CeaEdf(CeaEdfForm::ExtensionPlain) => "ext-r0",
            Formula::Hughes(HughesTensile::Given) => "ft-given",
            Formula::Hughes(HughesTensile::ModulusOfRupture) => "ft-mor",
            Formula::StoneWebster(StoneWebsterC::C900) => "c900",
            Formula::StoneWebster(StoneWebsterC::C1900) => "c1900",
            _ => "standard",
        }
    }

    /// Whether the variant is for plain concrete (not Petry's reinforced-concrete classes): the
    /// formulas a plain wall is compared with.
    pub fn for_plain_concrete(&self) -> bool {
        !matches!(self, Formula::Petry(PetryClass::NormalRc | PetryClass::SpecialRc))
    }

    /// Human-readable name with citation year.
    pub fn title(&self) -> &'static str {
        match self {
            Formula::Petry(_) => "Modified Petry (1910/1950)",
            Formula::Brl(_) => "BRL (1941)",
            Formula::Ace => "ACE (1946)",
            Formula::Ndrc => "Modified NDRC (1946/1976)",
            Formula::Degen => "Degen (1980)",
            Formula::Kar => "Kar (1978)",
            Formula::AmmannWhitney => "Ammann & Whitney",
            Formula::Whiffen => "Whiffen (1943)",
            Formula::Ukaea => "UKAEA (Barr 1990)",
            Formula::CeaEdf(_) => "CEA-EDF (1978)",
            Formula::Chang => "Chang (1981)",
            Formula::HaldarHamieh => "Haldar & Hamieh (1984)",
            Formula::AdeliAmin => "Adeli & Amin (1985)",
            Formula::Hughes(_) => "Hughes (1984)",
            Formula::Bechtel => "Bechtel (1974)",
            Formula::StoneWebster(_) => "Stone & Webster",
        }
    }

    /// Whether the formula defines quantity `q` (FORMULAS §4).
    pub fn defines(&self, q: Quantity) -> bool {
        use Quantity::*;
        match self {
            Formula::Petry(_) | Formula::Brl(_) | Formula::Ace | Formula::Ndrc | Formula::Kar => true,
            Formula::Hughes(_) | Formula::AdeliAmin => true,
            Formula::Degen | Formula::CeaEdf(_) => q == Perforation,
            Formula::Chang => q != Penetration,
            Formula::Bechtel | Formula::StoneWebster(_) => q == Scabbing,
            Formula::AmmannWhitney | Formula::Whiffen | Formula::Ukaea | Formula::HaldarHamieh => {
                q == Penetration
            }
        }
    }

    /// Quantity `q`, in, at impact velocity `v_fps` (ft/s); `None` where the formula does not
    /// define it (including Adeli–Amin beyond I = 21).
    pub fn evaluate(&self, q: Quantity, m: &Missile, t: &Target, v_fps: f64) -> Option<f64> {
        use Quantity::*;
        if !self.defines(q) {
            return None;
        }
        let d = m.diameter_in;
        let value = match self {
            Formula::Petry(class) => {
                let x = petry::penetration_in(m, v_fps, class.kp_ft3_per_lb());
                match q {
                    Penetration => x,
                    Scabbing => petry::scabbing_in(x),
                    Perforation => petry::perforation_in(x),
                }
            }
            Formula::Brl(scab) => {
                let x = brl::penetration_in(m, t, v_fps);
                match (q, scab) {
                    (Penetration, _) => x,
                    (Perforation, _) => brl::perforation_in(x),
                    (Scabbing, BrlScabbing::TwicePerforation) => brl::scabbing_twice_perforation_in(x),
                    (Scabbing, BrlScabbing::TwicePenetration) => brl::scabbing_twice_penetration_in(x),
                }
            }
            Formula::Ace => kennedy_chain(q, d, ace::penetration_ratio(m, t, v_fps)),
            Formula::Ndrc => kennedy_chain(q, d, ndrc::penetration_ratio(m, t, v_fps)),
            Formula::Degen => d * degen::hp_over_d(ndrc::penetration_ratio(m, t, v_fps)),
            Formula::Kar => {
                let xd = kar::penetration_ratio(m, t, v_fps);
                match q {
                    Penetration => d * xd,
                    Scabbing => kar::scabbing_in(m, t, xd),
                    Perforation => kar::perforation_in(m, t, xd),
                }
            }
            Formula::AmmannWhitney => ammann_whitney::penetration_in(m, t, v_fps),
            Formula::Whiffen => whiffen::penetration_in(m, t, v_fps),
            Formula::Ukaea => d * ukaea::penetration_ratio(m, t, v_fps),
            Formula::CeaEdf(CeaEdfForm::Base) => cea_edf::perforation_in(m, t, v_fps),
            Formula::CeaEdf(CeaEdfForm::ExtensionPlain) => {
                cea_edf::extension_perforation_in(m, t, v_fps, cea_edf::Reinforcement::PLAIN)
            }
            Formula::Chang => match q {
                Scabbing => chang::scabbing_in(m, t, v_fps),
                _ => chang::perforation_in(m, t, v_fps),
            },
            Formula::HaldarHamieh => {
                d * impact_factor::haldar_hamieh_xd(impact_factor::impact_factor(m, t, v_fps))
            }
            Formula::AdeliAmin => {
                let i = impact_factor::impact_factor(m, t, v_fps);
                let ratio = match q {
                    Penetration => impact_factor::adeli_amin_xd(i),
                    Scabbing => impact_factor::adeli_amin_hs_over_d(i),
                    Perforation => impact_factor::adeli_amin_hp_over_d(i),
                };
                return ratio.map(|r| d * r);
            }
            Formula::Hughes(ft) => {
                let i = hughes::impact_factor(m, v_fps, hughes_ft_psi(*ft, t));
                let xd = hughes::xd_from_impact(i, m.nose.hughes_factor());
                d * match q {
                    Penetration => xd,
                    Scabbing => hughes::hs_over_d(xd),
                    Perforation => hughes::hp_over_d(xd),
                }
            }
            Formula::Bechtel => bechtel::scabbing_in(m, t, v_fps),
            Formula::StoneWebster(c) => stone_webster::scabbing_in(m, v_fps, c.value()),
        };
        Some(value)
    }

    /// Whether the inputs for quantity `q` at `v_fps` lie inside the formula's stated range.
    pub fn validity(&self, q: Quantity, m: &Missile, t: &Target, v_fps: f64) -> Validity {
        let fc_mpa = t.fc_pa() / 1e6;
        match self {
            Formula::Petry(_) | Formula::Brl(_) | Formula::AmmannWhitney | Formula::Bechtel => Validity::Unstated,
            Formula::Ace => kennedy_validity(q, ace::penetration_ratio(m, t, v_fps)),
            Formula::Ndrc => kennedy_validity(q, ndrc::penetration_ratio(m, t, v_fps)),
            Formula::Kar => kennedy_validity(q, kar::penetration_ratio(m, t, v_fps)),
            Formula::Degen => {
                let hd = degen::hp_over_d(ndrc::penetration_ratio(m, t, v_fps));
                degen::validity(units::fps_to_mps(v_fps), fc_mpa, hd)
            }
            Formula::Whiffen => whiffen::validity(m, t, v_fps),
            Formula::Ukaea => ukaea::validity(t, v_fps),
            Formula::CeaEdf(_) => cea_edf::validity(v_fps),
            Formula::Chang => chang::validity(m, t, v_fps),
            Formula::HaldarHamieh => impact_factor::validity(
                impact_factor::impact_factor(m, t, v_fps),
                impact_factor::HALDAR_HAMIEH_MAX_I,
            ),
            Formula::AdeliAmin => impact_factor::validity(
                impact_factor::impact_factor(m, t, v_fps),
                impact_factor::ADELI_AMIN_MAX_I,
            ),
            Formula::Hughes(ft) => hughes::validity(hughes::impact_factor(m, v_fps, hughes_ft_psi(*ft, t))),
            Formula::StoneWebster(_) => stone_webster::validity(m, t),
        }
    }

    /// x, h_s and h_p at `v_fps` with the validity of those defined.
    pub fn predict(&self, m: &Missile, t: &Target, v_fps: f64) -> Prediction {
        let value = |q| self.evaluate(q, m, t, v_fps);
        let validity = Validity::all(
            Quantity::ALL.into_iter().filter(|&q| self.defines(q)).map(|q| self.validity(q, m, t, v_fps)),
        );
        Prediction {
            x_in: value(Quantity::Penetration),
            hs_in: value(Quantity::Scabbing),
            hp_in: value(Quantity::Perforation),
            validity,
        }
    }
}

/// Hughes's f_t, psi, for the chosen variant.
pub(crate) fn hughes_ft_psi(ft: HughesTensile, t: &Target) -> f64 {
    match ft {
        HughesTensile::Given => t.ft_psi,
        HughesTensile::ModulusOfRupture => hughes::modulus_of_rupture_psi(t),
    }
}

/// x, h_s or h_p, in, from a penetration ratio through Kennedy's relations.
fn kennedy_chain(q: Quantity, d_in: f64, xd: f64) -> f64 {
    d_in * match q {
        Quantity::Penetration => xd,
        Quantity::Scabbing => kennedy::hs_over_d(xd),
        Quantity::Perforation => kennedy::hp_over_d(xd),
    }
}

/// Validity of a Kennedy-chained quantity: x has no stated range of its own.
fn kennedy_validity(q: Quantity, xd: f64) -> Validity {
    match q {
        Quantity::Penetration => Validity::Unstated,
        Quantity::Scabbing => kennedy::hs_validity(xd),
        Quantity::Perforation => kennedy::hp_validity(xd),
    }
}
