//! Four consecutive contacts of one class at once, whatever their kinds: intact bonds on the
//! elastic branch of the bond law, frictional pairs touching (sticking or sliding) or apart
//! (forgetting, or with nothing to forget). A cracked body's contact list mixes the kinds at
//! random, so the scalar loop's kind tests are guessed wrong about half the time; here every
//! lane computes every kind and keeps its own, with one test per group (does some bond leave
//! the elastic branch?) that is almost never true. A group of four pairs apart with nothing to
//! forget, whose lanes would all come out as they went in, is let through before the laws.
//!
//! The law is [`super::law::bonded`]'s elastic branch and [`super::law::friction`]'s
//! `touching` and `apart` with no rate, compaction or damping part; each operation is the
//! scalar one's, in its order, on four lanes (IEEE add, multiply, divide and square root are
//! exact per lane, nothing is fused, `min` and `copysign` are the same selections), so forces,
//! shear springs and rest lengths are bitwise those of four scalar calls. The friction the
//! group dissipates is added to the ledger lane by lane in contact order, as the scalar loop
//! adds it; the lanes that dissipate nothing add zero, which leaves a sum that starts at +0
//! unchanged (it is never −0). A group where some bond leaves the elastic branch yields
//! nothing and changes nothing: the caller takes its contacts one by one with the full law.

use super::bonds4::{self, LANES};
use super::contacts::{Bond, Contact, ContactForce};
#[cfg(target_arch = "x86_64")]
use super::geometry::Four;
use super::law::{ContactClass, Dissipation, PartSet};

/// True when the four contacts are of one class (the lanes share its constants).
#[inline(always)]
pub fn one_class(cs: &[Contact; LANES]) -> bool {
    let k0 = cs[0].class;
    (cs[1].class == k0) & (cs[2].class == k0) & (cs[3].class == k0)
}

/// The four contacts `cs` ([`one_class`], class `k`) of geometry `geo` (`geometry::four`) at
/// half-step velocities `vel` over `dt_s`, with the parts `P` (no rate, compaction or damping part):
/// their forces, with their history updated and the friction they dissipate added to `d`, if
/// every intact bond among them stays elastic; else None, with nothing changed.
///
/// # Safety
/// The processor must have AVX ([`bonds4::available`]); call it from a function compiled for
/// AVX, into which it is inlined with its intrinsics.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub unsafe fn evaluate<P: PartSet>(
    geo: &Four,
    vel: &[[f64; 3]],
    cs: &mut [Contact; LANES],
    k: &ContactClass,
    dt_s: f64,
    d: &mut Dissipation,
) -> Option<[ContactForce; LANES]> {
    use std::arch::x86_64::*;

    use super::geometry::lanes;
    debug_assert!(!P::RATE && !P::COMPACTION && !P::DAMPING);
    // SAFETY: AVX is there (the caller's contract); the rest is arithmetic and bounds-checked
    // indexing.
    unsafe {
        let splat = _mm256_set1_pd;
        let (zero, sign) = (_mm256_setzero_pd(), splat(-0.0));
        let intact = _mm256_cmp_pd::<_CMP_EQ_OQ>(lanes!(cs, |c| (c.bond == Bond::Intact) as u8 as f64), splat(1.0));
        let (rest, ut0) = (lanes!(cs, |c| c.rest_m), lanes!(cs, |c| c.ut_m));
        let rs = splat(k.radius_sum_m);
        // Four frictional pairs apart with nothing to forget (no shear spring, the rest length
        // back at r_i + r_j: `forces::apart_with_nothing_to_forget` in every lane): what the
        // lanes below would give them — no force, nothing written, +0 booked — without their
        // kinematics and laws. A sixth of the groups at the end of the peers' beam, which has
        // broken three quarters of its bonds: the beam on one thread 0.986× the time (five
        // alternating pairs, the same summaries).
        let nothing = _mm256_andnot_pd(
            intact,
            _mm256_and_pd(
                _mm256_and_pd(_mm256_cmp_pd::<_CMP_EQ_OQ>(ut0, zero), _mm256_cmp_pd::<_CMP_EQ_OQ>(rest, rs)),
                _mm256_cmp_pd::<_CMP_GE_OQ>(geo.d2_m2, _mm256_mul_pd(rest, rest)),
            ),
        );
        if _mm256_movemask_pd(nothing) == 0b1111 {
            return Some([ContactForce::default(); LANES]);
        }
        let g = bonds4::kinematics(geo, vel, cs, k);
        // Bonds: the elastic branch, as `bonds4::elastic` takes it. Its trial shear spring,
        // ut_prev + vt·Δt, is the frictional law's too.
        let bond = bonds4::elastic_branch(&g, cs, k, dt_s);
        // Some intact lane not elastic (`vtestpd` of the two masks' sign bits).
        if _mm256_testc_pd(bond.elastic, intact) == 0 {
            return None;
        }
        let (ut_trial, opening) = (bond.ut_m, _mm256_sub_pd(g.dist, rest));

        // Frictional pairs (`friction::touching`, `normal::frictional`, `capped_spring` with
        // kt_last = kt): touching is "not apart", apart is d² ≥ rest² (`forces::apart`).
        let s = &k.contact.springs;
        let touching = _mm256_cmp_pd::<_CMP_NGE_UQ>(g.d2_m2, _mm256_mul_pd(rest, rest));
        let fn_fric = _mm256_mul_pd(splat(s.kn_n_per_m), _mm256_min_pd(opening, zero));
        let (ft_fric, ut_touch, w_touch) = if P::FRICTION {
            let limit = _mm256_add_pd(_mm256_mul_pd(splat(k.contact.mu), _mm256_xor_pd(fn_fric, sign)), splat(k.contact.cohesion_n));
            let f = _mm256_mul_pd(splat(s.kt_n_per_m), ut_trial);
            let stick = _mm256_cmp_pd::<_CMP_LE_OQ>(_mm256_andnot_pd(sign, f), limit);
            let capped = _mm256_or_pd(_mm256_andnot_pd(sign, limit), _mm256_and_pd(sign, f));
            let ut_capped = _mm256_div_pd(capped, splat(s.kt_n_per_m));
            let last = _mm256_add_pd(_mm256_mul_pd(splat(s.kt_n_per_m), ut0), capped);
            let w = _mm256_mul_pd(_mm256_mul_pd(splat(0.5), last), _mm256_sub_pd(ut_trial, ut_capped));
            (_mm256_blendv_pd(capped, f, stick), _mm256_blendv_pd(ut_capped, ut_trial, stick), _mm256_andnot_pd(stick, w))
        } else {
            (zero, ut0, zero)
        };
        // Apart (`friction::apart`): the shear spring released and booked, the rest length
        // relaxed to min(r_i + r_j, d) (`f64::min` as `minpd` with the operands this way round:
        // d < r ? d : r).
        let holds_ut = _mm256_cmp_pd::<_CMP_NEQ_UQ>(ut0, zero);
        let w_apart = _mm256_and_pd(holds_ut, _mm256_mul_pd(_mm256_mul_pd(splat(0.5 * s.kt_n_per_m), ut0), ut0));
        let ut_apart = _mm256_andnot_pd(holds_ut, ut0);
        let rest_moves = _mm256_cmp_pd::<_CMP_NEQ_UQ>(rest, rs);
        let rest_apart = _mm256_blendv_pd(rest, _mm256_min_pd(g.dist, rs), rest_moves);

        // Each lane keeps its own kind's outcome.
        let pushing = _mm256_or_pd(intact, touching);
        let f_n = _mm256_blendv_pd(fn_fric, bond.f_n, intact);
        let f_t = _mm256_blendv_pd(ft_fric, bond.f_t, intact);
        let force = bonds4::force(&g, f_n, f_t, pushing);
        let ut = bonds4::out(_mm256_blendv_pd(_mm256_blendv_pd(ut_apart, ut_touch, touching), ut_trial, intact));
        let rest = bonds4::out(_mm256_blendv_pd(rest_apart, rest, pushing));
        let w = bonds4::out(_mm256_andnot_pd(intact, _mm256_blendv_pd(w_apart, w_touch, touching)));
        for (l, c) in cs.iter_mut().enumerate() {
            c.ut_m = ut[l];
            c.rest_m = rest[l];
            d.friction_j += w[l];
        }
        Some(force)
    }
}
