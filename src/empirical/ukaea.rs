//! UKAEA (Barr 1990): the small-penetration modification of NDRC, FORMULAS §3.9.
//!
//! ```text
//! G as Modified NDRC (with N)
//! x/d = 0.275 − (0.0756 − G)^0.5     G ≤ 0.0726
//! x/d = (4G − 0.242)^0.5             0.0726 ≤ G ≤ 1.0605
//! x/d = G + 0.9395                   G ≥ 1.0605
//! ```
//! Continuous at both joints (0.2202/0.2200, 2.000/2.000) and x → 0 as G → 0. Defines x only
//! (Barr's h_s/h_p were not found; the UKAEA route for perforation is CEA-EDF). Validity
//! (recollection, unverified): 25–300 m/s, f'c 22–44 MPa. Confidence: Medium–High.

use super::{Missile, Target, Validity, ndrc};
use crate::units;

/// First joint of the fit, in G.
pub const G_LOW: f64 = 0.0726;
/// Second joint of the fit, in G.
pub const G_HIGH: f64 = 1.0605;

/// Penetration ratio x/d from G.
pub fn xd_from_g(g: f64) -> f64 {
    if g <= G_LOW {
        0.275 - (0.0756 - g).sqrt()
    } else if g <= G_HIGH {
        (4.0 * g - 0.242).sqrt()
    } else {
        g + 0.9395
    }
}

/// Penetration ratio x/d at `v_fps`.
pub fn penetration_ratio(m: &Missile, t: &Target, v_fps: f64) -> f64 {
    xd_from_g(ndrc::g_function(m, t, v_fps, 1.0))
}

/// Validity (recollected ranges).
pub fn validity(t: &Target, v_fps: f64) -> Validity {
    Validity::all([
        Validity::range("V", units::fps_to_mps(v_fps), 25.0, 300.0, "m/s"),
        Validity::range("f'c", t.fc_pa() / 1e6, 22.0, 44.0, "MPa"),
    ])
}
