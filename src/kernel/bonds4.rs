//! Four consecutive intact bonds of one class at once, when each stays on the elastic branch of
//! the bond law (below both plateaus, not breaking): nearly every contact-step of a lattice
//! that is loaded but not failing (the benchmark block; the peers' beam until it cracks). The
//! law is [`super::law::bonded`] with no rate, compaction or damping part; each operation is the
//! scalar one's, in its order, on four lanes (IEEE add, multiply, divide and square root are
//! exact per lane, and nothing is fused into a multiply–add), so the forces and shear springs
//! are bitwise those of four scalar calls. A group where some lane leaves the elastic branch
//! yields nothing and changes nothing: the caller evaluates its contacts one by one with the
//! full law.
//!
//! Taken only when the processor has AVX (four f64 lanes, [`available`]); elsewhere the contact
//! stage is the scalar loop alone. Frictional pairs are left to the scalar loop: taking the
//! ones that are apart in lanes too (zero force, nothing to change) was measured slower on the
//! cracked beam, where the in-line scalar test settles each in a few instructions.

use super::contacts::{Bond, Contact, ContactForce};
use super::law::{ContactClass, rate};

/// Contacts per group.
pub const LANES: usize = 4;

/// A group's outcome when every bond stayed elastic, in contact order.
pub struct Group {
    /// Forces of the four bonds.
    pub force: [ContactForce; LANES],
    /// New elastic shear displacement u_t of each, m.
    pub ut_m: [f64; LANES],
}

/// True when this processor runs the four-lane path.
#[inline]
pub fn available() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::arch::is_x86_feature_detected!("avx")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// True when the four contacts are intact bonds of one class (one branch for the four: on a
/// cracked body the answer changes from group to group).
#[inline(always)]
pub fn eligible(cs: &[Contact; LANES]) -> bool {
    let key = |c: &Contact| ((c.class as u32) << 8) | c.bond as u32;
    let k0 = key(&cs[0]);
    (k0 & 0xff == Bond::Intact as u32) & (key(&cs[1]) == k0) & (key(&cs[2]) == k0) & (key(&cs[3]) == k0)
}

/// The four bonds `cs` ([`eligible`], class `k`) at positions `pos` and half-step velocities
/// `vel` over `dt_s`: their forces and new shear springs if all four stay elastic, else None.
/// The contacts are not written (the caller stores `ut_m`).
///
/// # Safety
/// The processor must have AVX ([`available`]); call it from a function compiled for AVX
/// (`#[target_feature(enable = "avx")]`), into which it is inlined with its intrinsics.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub unsafe fn elastic(pos: &[[f64; 3]], vel: &[[f64; 3]], cs: &[Contact; LANES], k: &ContactClass, dt_s: f64) -> Option<Group> {
    use std::arch::x86_64::*;
    // SAFETY: AVX is there (the caller's contract); the rest is arithmetic and bounds-checked
    // indexing.
    unsafe {
        // Lane l holds contact l (`_mm256_set_pd` takes the highest lane first).
        macro_rules! lanes {
            (|$c:ident| $e:expr) => {
                _mm256_set_pd({ let $c = &cs[3]; $e }, { let $c = &cs[2]; $e }, { let $c = &cs[1]; $e }, { let $c = &cs[0]; $e })
            };
        }
        let (pi, pj) = (|c: &Contact| pos[c.i as usize], |c: &Contact| pos[c.j as usize]);
        let (vi, vj) = (|c: &Contact| vel[c.i as usize], |c: &Contact| vel[c.j as usize]);
        let splat = _mm256_set1_pd;

        // Geometry and relative velocity (`forces::separation`, `forces::along`).
        let dx = _mm256_sub_pd(lanes!(|c| pj(c)[0]), lanes!(|c| pi(c)[0]));
        let dy = _mm256_sub_pd(lanes!(|c| pj(c)[1]), lanes!(|c| pi(c)[1]));
        let dist = _mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)));
        let inv = _mm256_div_pd(splat(1.0), dist);
        let (nx, ny) = (_mm256_mul_pd(dx, inv), _mm256_mul_pd(dy, inv));
        let dvx = _mm256_sub_pd(lanes!(|c| vj(c)[0]), lanes!(|c| vi(c)[0]));
        let dvy = _mm256_sub_pd(lanes!(|c| vj(c)[1]), lanes!(|c| vi(c)[1]));
        let li = _mm256_mul_pd(dist, splat(k.lever_i));
        let lj = _mm256_mul_pd(dist, splat(k.lever_j));
        // −dvx·ny + dvy·nx − li·ωi − lj·ωj, left to right (the normal velocity is not read: no
        // damping or rate part).
        let neg_dvx = _mm256_xor_pd(dvx, splat(-0.0));
        let vt = _mm256_sub_pd(
            _mm256_sub_pd(_mm256_add_pd(_mm256_mul_pd(neg_dvx, ny), _mm256_mul_pd(dvy, nx)), _mm256_mul_pd(li, lanes!(|c| vi(c)[2]))),
            _mm256_mul_pd(lj, lanes!(|c| vj(c)[2])),
        );

        // The elastic branch (`law::bonded`, `normal::bonded`, `tangential::capped_spring`,
        // `failure::breaks`).
        let xi = rate::STATIC[2];
        let dp = lanes!(|c| c.dp_m);
        let f_n = _mm256_mul_pd(splat(k.bond.kn_n_per_m), _mm256_sub_pd(_mm256_sub_pd(dist, lanes!(|c| c.rest_m)), dp));
        let ut = _mm256_add_pd(lanes!(|c| c.ut_m), _mm256_mul_pd(vt, splat(dt_s)));
        let f_t = _mm256_mul_pd(splat(k.bond.kt_n_per_m), ut);
        let below_plateau = _mm256_cmp_pd::<_CMP_LE_OQ>(f_n, splat(k.strength.normal_force_n * xi));
        let below_cap = _mm256_cmp_pd::<_CMP_LE_OQ>(_mm256_andnot_pd(splat(-0.0), f_t), splat(k.strength.shear_force_n * xi));
        let holds = _mm256_cmp_pd::<_CMP_NGT_UQ>(dp, splat(k.strength.plastic_opening_at_break_m));
        if _mm256_movemask_pd(_mm256_and_pd(_mm256_and_pd(below_plateau, below_cap), holds)) != 0b1111 {
            return None;
        }

        // `law::force`.
        let fx = _mm256_sub_pd(_mm256_mul_pd(f_n, nx), _mm256_mul_pd(f_t, ny));
        let fy = _mm256_add_pd(_mm256_mul_pd(f_n, ny), _mm256_mul_pd(f_t, nx));
        let (ti, tj) = (_mm256_mul_pd(li, f_t), _mm256_mul_pd(lj, f_t));
        let out = |v: __m256d| {
            let mut a = [0.0; LANES];
            _mm256_storeu_pd(a.as_mut_ptr(), v);
            a
        };
        let (fx, fy, ti, tj, ut_m) = (out(fx), out(fy), out(ti), out(tj), out(ut));
        Some(Group { force: std::array::from_fn(|l| ContactForce { fx: fx[l], fy: fy[l], ti: ti[l], tj: tj[l] }), ut_m })
    }
}
