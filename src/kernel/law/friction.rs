//! Frictional contacts (seed eq 2.1, Fig 2.4): every pair that touches without a bond, new
//! contacts (fragments, the projectile) and broken bonds alike. Compression-only normal spring,
//! a tangential spring capped by Coulomb's −μ Fn + c.
//!
//! **Their springs** do not come from a bond's Kt (which is zero for a hexagonal lattice with
//! ν* ≥ 1/3, e.g. steel in plane strain, and would leave such a body frictionless). Each
//! element contributes a normal half-spring 2·Kn of its material, Kn its bond's normal stiffness
//! (eq 1.1 or 3.1, from E*; between two elements of one material the contact is exactly as
//! stiff in compression as the bond it may replace, so a closed crack carries compression as the
//! intact lattice does); the halves act in series. The tangential spring is Kn/3: for uniform
//! disks (I = m r²/2, lever arm r) a sticking contact's tangential oscillation then has the
//! frequency of its normal one, ω_t² = Kt (1/m_i + 1/m_j + r_i²/I_i + r_j²/I_j) = 3 Kt (1/m_i +
//! 1/m_j) = ω_n², whatever the two elements (Schäfer, Dippel & Wolf 1996 give the same rule,
//! 2/7, for spheres). Friction thus adds no faster mode to a collision, and a packing of
//! fragments in stick is no stiffer, for the time step, than a lattice with Kt/Kn = 1/3.
//!
//! **Touching** is d < d0*, the contact's rest length: r_i + r_j for a new pair; a broken bond's
//! rest length (its initial distance, moved in by compaction) while it still touches. A pair
//! that is apart forgets: its shear spring releases what it held, and its rest length relaxes
//! to min(r_i + r_j, d), so a compacted pair that separates never springs back into an overlap,
//! and a pair that moves apart beyond r_i + r_j is exactly a new pair. This happens in the
//! contact loop, so the physics does not depend on when the neighbour list is rebuilt.

use serde::{Deserialize, Serialize};

use super::{ContactClass, Dissipation, Kinematics, PartSet, Springs, damping, force, normal, tangential};
use crate::kernel::contact::{Contact, ContactForce};
use crate::kernel::lanes::{Mask, Real};
use crate::material::Material;

/// Springs and Coulomb constants of a contact class's frictional contacts.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct Params {
    /// Normal and tangential stiffness, N/m.
    pub springs: Springs,
    /// Coulomb coefficient μ.
    pub mu: f64,
    /// Cohesion c, N.
    pub cohesion_n: f64,
}

/// Tangential to normal stiffness of a frictional contact (equal normal and tangential
/// frequencies for disks, see the module documentation).
pub const TANGENTIAL_RATIO: f64 = 1.0 / 3.0;

/// Two half-springs in series, each twice its element's `x`, `y`: equal halves give x.
pub fn series(x: f64, y: f64) -> f64 {
    if x + y > 0.0 { 2.0 * x * y / (x + y) } else { 0.0 }
}

impl Params {
    /// Between elements of materials `a` and `b` whose bonds have normal stiffness `kn_a`,
    /// `kn_b` (N/m); μ is the mean of the two, the cohesion the smaller, per `thickness_m`.
    pub fn between(a: &Material, kn_a: f64, b: &Material, kn_b: f64, thickness_m: f64) -> Params {
        let kn = series(kn_a, kn_b);
        Params {
            springs: Springs { kn_n_per_m: kn, kt_n_per_m: TANGENTIAL_RATIO * kn },
            mu: 0.5 * (a.friction_coefficient + b.friction_coefficient),
            cohesion_n: a.cohesion_n_per_m.min(b.cohesion_n_per_m) * thickness_m,
        }
    }

    /// True when the contacts can carry a tangential force.
    pub fn has_friction(&self) -> bool {
        self.mu > 0.0 || self.cohesion_n > 0.0
    }
}

/// A touching frictional contact: update its shear spring and return its force.
#[inline(always)]
pub fn touching<P: PartSet>(c: &mut Contact, k: &ContactClass, g: &Kinematics, dt_s: f64, diss: &mut Dissipation) -> ContactForce {
    let opening = g.d_m - c.rest_m;
    let s = &k.contact.springs;
    let mut f_n = normal::frictional(opening, s.kn_n_per_m);
    let (mut f_t, mut slid) = (0.0, false);
    if P::FRICTION {
        let limit = coulomb(f_n, k.contact.mu, k.contact.cohesion_n);
        let (ft, ut, w) = tangential::capped_spring(c.ut_m, g.vt_mps * dt_s, s.kt_n_per_m, s.kt_n_per_m, limit);
        c.ut_m = ut;
        diss.friction_j += w;
        f_t = ft;
        slid = w != 0.0;
    }
    if P::DAMPING {
        // A frictional contact never pulls, and a sliding one has no tangential dashpot.
        let (dn, dt) = damping::dashpot(k.damping.contact_n, k.damping.contact_t, g.vn_mps, g.vt_mps);
        let fn_damped = (f_n + dn).min(0.0);
        diss.contact_damping_j += (fn_damped - f_n) * g.vn_mps * dt_s;
        f_n = fn_damped;
        if P::FRICTION && !slid {
            f_t += dt;
            diss.contact_damping_j += dt * g.vt_mps * dt_s;
        }
    }
    force(g, f_n, f_t)
}

/// Coulomb's limit on the tangential force, −μ Fn + c, N, of normal force `f_n` (N, tension
/// positive), coefficient `mu` and cohesion `cohesion_n` (N).
#[inline(always)]
pub fn coulomb<R: Real>(f_n: R, mu: R, cohesion_n: R) -> R {
    mu * (-f_n) + cohesion_n
}

/// A frictional contact that is apart (distance² `d2_m2` ≥ rest²): it forgets its shear
/// spring (booking what it held as friction) and its rest length relaxes toward r_i + r_j.
#[inline(always)]
pub fn apart(c: &mut Contact, k: &ContactClass, d2_m2: f64, diss: &mut Dissipation) {
    let (ut, rest, w) = forget(c.ut_m, c.rest_m, 0.5 * k.contact.springs.kt_n_per_m, k.radius_sum_m, || d2_m2.sqrt());
    diss.friction_j += w;
    (c.ut_m, c.rest_m) = (ut, rest);
}

/// [`apart`] over any [`Real`]: from shear spring `ut_m` and rest length `rest_m` (m), with half
/// the tangential stiffness `half_kt` (N/m), r_i + r_j `radius_sum_m` and the centre distance
/// `d_m()` (m, asked only where the rest length moves), the new shear spring (0), the new rest
/// length min(d, r_i + r_j) and the energy the spring held, J (+0 where it held none).
#[inline(always)]
pub fn forget<R: Real>(ut_m: R, rest_m: R, half_kt: R, radius_sum_m: R, d_m: impl FnOnce() -> R) -> (R, R, R) {
    let (ut, w) = ut_m.eq(R::zero()).blend((ut_m, R::zero()), #[inline(always)] || (R::zero(), half_kt * ut_m * ut_m));
    let rest = rest_m.eq(radius_sum_m).blend(rest_m, #[inline(always)] || d_m().min(radius_sum_m));
    (ut, rest, w)
}

/// True where a frictional pair of rest length `rest_m` (m) at squared distance `d2_m2` (m²)
/// does not touch: its centres at least the rest length apart.
#[inline(always)]
pub fn is_apart<R: Real>(d2_m2: R, rest_m: R) -> R::Mask {
    d2_m2.ge(rest_m * rest_m)
}

/// True where a frictional pair is apart with no shear spring (`ut_m`, m) and its rest length
/// back at r_i + r_j (`radius_sum_m`): [`apart`] would change nothing, so the contact loop skips
/// it.
#[inline(always)]
pub fn idle<R: Real>(ut_m: R, rest_m: R, radius_sum_m: R, d2_m2: R) -> R::Mask {
    ut_m.eq(R::zero()) & rest_m.eq(radius_sum_m) & is_apart(d2_m2, rest_m)
}
