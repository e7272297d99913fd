//! When and how far ahead the candidate pairs are looked for.
//!
//! Each element gets a margin m_e at every rebuild; a pair is a candidate while its gap is
//! below m_i + m_j, and the list stays complete until some element has moved further than its
//! own margin, which triggers the next rebuild (Verlet's skin, per element). A fixed margin
//! sized for the slow bulk would make a fast projectile trigger a rebuild of the whole model
//! nearly every step (at 1500 ft/s and a step near the stability limit it moves half the skin
//! per step); so an element's margin also covers [`Settings::lookahead_steps`] steps at its
//! present speed, capped at [`Settings::max_margin_m`]. Only fast elements get wide margins,
//! and only their candidate lists grow. Which pairs are candidates never changes the physics
//! (`contacts::Contacts::merge_candidates`), only the cost.

use serde::{Deserialize, Serialize};

use super::state::Elements;

/// Neighbour-search settings (configuration).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Settings {
    /// Smallest margin of any element, m (half the scene's skin: skin_ratio × the smallest
    /// radius).
    pub base_margin_m: f64,
    /// Steps of motion at its present speed an element's margin covers.
    pub lookahead_steps: f64,
    /// Largest margin, m.
    pub max_margin_m: f64,
}

/// Default [`Settings::lookahead_steps`]: a fast element triggers a rebuild about every ten
/// steps, and a rebuild costs about two steps of contact processing.
pub const LOOKAHEAD_STEPS: f64 = 10.0;

impl Settings {
    /// Settings for a skin of `skin_ratio` × the smallest radius `r_min_m`, the largest radius
    /// `r_max_m` (margins are capped at it: wider ones would search cells far beyond the usual
    /// stencil for a speed that may not last).
    pub fn new(skin_ratio: f64, r_min_m: f64, r_max_m: f64) -> Settings {
        let base = 0.5 * skin_ratio * r_min_m;
        Settings { base_margin_m: base, lookahead_steps: LOOKAHEAD_STEPS, max_margin_m: r_max_m.max(base) }
    }

    /// Each element's margin for the velocities `vel` and the step `dt_s`, written to `out`.
    pub fn margins(&self, el: &Elements, vel: &[[f64; 3]], dt_s: f64, out: &mut Vec<f64>) {
        out.clear();
        let ahead = self.lookahead_steps * dt_s;
        out.extend((0..el.len()).map(|e| {
            let v = vel[e];
            (ahead * v[0].hypot(v[1])).clamp(self.base_margin_m, self.max_margin_m)
        }));
    }
}
