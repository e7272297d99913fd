//! Formulas on the impact factor I = M N V²/(d³ fc) (dimensionless; SI here; N the NDRC nose
//! factor): Haldar & Hamieh (1984) and Adeli & Amin (1985), FORMULAS §3.12–3.13.
//!
//! Haldar & Hamieh — x only; fits discontinuous at I = 4 (0.870 → 0.901) and I = 21
//! (1.865 → 1.815) as recalled. Validity 0.3 ≤ I ≤ 455. Confidence: Medium–Low.
//! ```text
//! x/d = −0.0308 + 0.2251 I    0.3 ≤ I ≤ 4
//! x/d =  0.6740 + 0.0567 I    4 < I ≤ 21
//! x/d =  1.1875 + 0.0299 I    21 < I ≤ 455
//! ```
//! Adeli & Amin — x, h_s, h_p, the thicknesses direct in I (not chained on x). Validity
//! 0.3 ≤ I ≤ 21; beyond I = 21 the fits are not defined (the cubic and quadratics fold back), so
//! nothing is returned there. Which quadratic is h_s and which h_p is chosen so that h_s > h_p
//! (unverified). Maxima: h_s/d = 5.44 at I = 17.7, h_p/d = 3.34 at I = 15.2, x/d peaks at
//! I = 19.1: these curves are not monotone inside their range. Confidence: Medium–Low (x), Low
//! (h_s, h_p).
//! ```text
//! x/d   = 0.0416 + 0.1698 I − 0.0045 I²                 0.3 ≤ I ≤ 4
//! x/d   = 0.0123 + 0.196 I − 0.008 I² + 0.0001 I³       4 < I ≤ 21
//! h_s/d = 1.8685 + 0.4035 I − 0.0114 I²                 0.3 ≤ I ≤ 21
//! h_p/d = 0.9060 + 0.3214 I − 0.0106 I²                 0.3 ≤ I ≤ 21
//! ```

use super::{Missile, Target, Validity};
use crate::units;

/// Upper end of the Adeli–Amin fits.
pub const ADELI_AMIN_MAX_I: f64 = 21.0;
/// Upper end of the Haldar–Hamieh fits.
pub const HALDAR_HAMIEH_MAX_I: f64 = 455.0;
/// Lower end of both fits.
pub const MIN_I: f64 = 0.3;

/// Impact factor I = M N V²/(d³ fc).
pub fn impact_factor(m: &Missile, t: &Target, v_fps: f64) -> f64 {
    let v = units::fps_to_mps(v_fps);
    m.mass_kg() * m.nose.ndrc_factor() * v * v / (m.diameter_m().powi(3) * t.fc_pa())
}

/// Haldar–Hamieh penetration ratio x/d.
pub fn haldar_hamieh_xd(i: f64) -> f64 {
    if i <= 4.0 {
        -0.0308 + 0.2251 * i
    } else if i <= 21.0 {
        0.6740 + 0.0567 * i
    } else {
        1.1875 + 0.0299 * i
    }
}

/// Adeli–Amin penetration ratio x/d (`None` beyond I = 21).
pub fn adeli_amin_xd(i: f64) -> Option<f64> {
    if i > ADELI_AMIN_MAX_I {
        None
    } else if i <= 4.0 {
        Some(0.0416 + 0.1698 * i - 0.0045 * i * i)
    } else {
        Some(0.0123 + 0.196 * i - 0.008 * i * i + 0.0001 * i * i * i)
    }
}

/// Adeli–Amin scabbing ratio h_s/d (`None` beyond I = 21).
pub fn adeli_amin_hs_over_d(i: f64) -> Option<f64> {
    (i <= ADELI_AMIN_MAX_I).then_some(1.8685 + 0.4035 * i - 0.0114 * i * i)
}

/// Adeli–Amin perforation ratio h_p/d (`None` beyond I = 21).
pub fn adeli_amin_hp_over_d(i: f64) -> Option<f64> {
    (i <= ADELI_AMIN_MAX_I).then_some(0.9060 + 0.3214 * i - 0.0106 * i * i)
}

/// Validity of a fit on `MIN_I ≤ I ≤ max_i`.
pub fn validity(i: f64, max_i: f64) -> Validity {
    Validity::range("I", i, MIN_I, max_i, "")
}
