//! Failure part: when a bond breaks and what it releases.
//!
//! All three criteria of the source reduce to one rule on the plastic opening δ_p of the
//! tensile plateau: the brittle criteria (eq 3.5, 3.10) break as soon as the plateau is reached
//! (δ_p,max = 0); the energy criterion (eq 5.7) when the area under the normal force–opening
//! curve reaches G_f × 2Rt, i.e. δ_p > δ_max − δ_crit.

use crate::kernel::lanes::Real;

/// True where a bond with plastic opening `dp_m` (m) must break.
#[inline(always)]
pub fn breaks<R: Real>(dp_m: R, plastic_opening_at_break_m: R) -> R::Mask {
    dp_m.gt(plastic_opening_at_break_m)
}

/// Elastic energy stored in the bond's springs, released when it breaks, J.
#[inline(always)]
pub fn released_energy_j(fn_n: f64, ft_n: f64, kn: f64, kt: f64) -> f64 {
    let shear = if kt > 0.0 { ft_n * ft_n / (2.0 * kt) } else { 0.0 };
    fn_n * fn_n / (2.0 * kn) + shear
}
