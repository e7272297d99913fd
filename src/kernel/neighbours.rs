//! When and how far ahead the candidate pairs are looked for.
//!
//! Each element gets a margin m_e at every rebuild, at least half its skin (a fraction of its
//! radius); a pair is a candidate while its gap is below m_i + m_j, and the list stays complete
//! until some element has moved further than its own margin, which triggers the next rebuild
//! (Verlet's skin, per element). A fixed margin
//! sized for the slow bulk would make a fast projectile trigger a rebuild of the whole model
//! nearly every step (at 1500 ft/s and a step near the stability limit it moves half the skin
//! per step); so an element's margin also covers [`Settings::lookahead_steps`] steps of its
//! present motion, v T + a T²/2 with T that many steps (the acceleration matters for the
//! elements the projectile is just setting in motion), capped at [`Settings::max_margin_m`].
//! Only fast elements get wide margins, and only their candidate lists grow. When only a few
//! elements have drifted past their margins, only they get new margins and reference positions
//! and only their pairs are looked for again (a local update); the others' lists stay valid,
//! since they have not moved past theirs. Which pairs are candidates never changes the physics
//! (`contacts::Contacts::merge_candidates`), only the cost.

use serde::{Deserialize, Serialize};

use super::state::Elements;

/// Neighbour-search settings (configuration).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Settings {
    /// Skin as a fraction of each element's radius: an element's margin is at least half of
    /// its skin. In an intact close-packed lattice the second neighbours are 1.46 R further
    /// away than the first, so a skin below that adds no candidate pair there.
    pub skin_ratio: f64,
    /// Steps of motion an element's margin covers.
    pub lookahead_steps: f64,
    /// Largest margin, m.
    pub max_margin_m: f64,
}

/// Default [`Settings::lookahead_steps`]: a steadily moving element triggers an update about
/// every twenty steps (on the impact benchmark 10 steps gave 1.5 times the updates for 20 %
/// fewer candidate pairs, 30 steps 25 % more pairs for few fewer updates).
pub const LOOKAHEAD_STEPS: f64 = 20.0;

/// Default skin ratio.
pub const SKIN_RATIO: f64 = 1.0;

impl Settings {
    /// Settings for a skin of `skin_ratio` × each radius, the largest radius `r_max_m`
    /// (margins are capped at twice it: wider ones would search cells far beyond the usual
    /// stencil for a motion that may not last).
    pub fn new(skin_ratio: f64, r_max_m: f64) -> Settings {
        Settings { skin_ratio, lookahead_steps: LOOKAHEAD_STEPS, max_margin_m: (2.0 * r_max_m).max(0.5 * skin_ratio * r_max_m) }
    }

    /// The smallest margin of an element of radius `radius_m`, m.
    pub fn base_margin_m(&self, radius_m: f64) -> f64 {
        0.5 * self.skin_ratio * radius_m
    }

    /// The reach r + m of an element of the largest radius `r_max_m` at rest: the broad
    /// phase's cells are sized for it.
    pub fn usual_reach_m(&self, r_max_m: f64) -> f64 {
        r_max_m + self.base_margin_m(r_max_m)
    }

    /// Element `e`'s margin for its velocity `v`, its force `f` and the step `dt_s`, m.
    #[inline]
    pub fn margin_m(&self, el: &Elements, e: usize, v: [f64; 3], f: [f64; 3], dt_s: f64) -> f64 {
        let ahead = self.lookahead_steps * dt_s;
        let travel = ahead * (v[0] * v[0] + v[1] * v[1]).sqrt() + 0.5 * ahead * ahead * (f[0] * f[0] + f[1] * f[1]).sqrt() * el.inv_mass[e];
        let base = self.base_margin_m(el.radius[e]);
        travel.clamp(base, self.max_margin_m.max(base))
    }

    /// Each element's margin for the velocities `vel`, the forces `force` and the step `dt_s`,
    /// written to `out`.
    pub fn margins(&self, el: &Elements, vel: &[[f64; 3]], force: &[[f64; 3]], dt_s: f64, out: &mut Vec<f64>) {
        out.clear();
        out.extend((0..el.len()).map(|e| self.margin_m(el, e, vel[e], force[e], dt_s)));
    }

    /// Whether a local update (only the elements that drifted past their margins) is cheaper
    /// than a full rebuild: while they are fewer than an eighth of the elements.
    pub fn local(&self, movers: usize, elements: usize) -> bool {
        8 * movers < elements
    }
}
