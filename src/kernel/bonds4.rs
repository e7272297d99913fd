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
//! stage is the scalar loop alone. A group with frictional pairs in it goes to
//! [`super::mixed4`], which computes every kind in every lane: on the all-bonded groups this
//! path, which computes only the bonds, is faster (1.06–1.20× over the peers' beam's first
//! 1 000 steps), so the contact loop keeps both. The lanes' kinematics, elastic branch and
//! force (`kinematics`, `elastic_branch`, `force`, crate-private) serve both.

use super::contacts::{Bond, Contact, ContactForce};
#[cfg(target_arch = "x86_64")]
use super::geometry::{Four, lanes, xy};
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
    // Bits that differ from the first class, and any bond that is not intact (`Intact` is 0):
    // one test of the ORs instead of four keys compared.
    const { assert!(Bond::Intact as u8 == 0) };
    let k0 = cs[0].class;
    let classes = (cs[1].class ^ k0) | (cs[2].class ^ k0) | (cs[3].class ^ k0);
    let bonds = cs[0].bond as u8 | cs[1].bond as u8 | cs[2].bond as u8 | cs[3].bond as u8;
    (classes == 0) & (bonds == 0)
}

/// The four bonds `cs` ([`eligible`], class `k`) of geometry `geo` (`geometry::four`) at
/// half-step velocities `vel` over `dt_s`: their forces and new shear springs if all four stay
/// elastic, else None. The contacts are not written (the caller stores `ut_m`).
///
/// # Safety
/// The processor must have AVX ([`available`]); call it from a function compiled for AVX
/// (`#[target_feature(enable = "avx")]`), into which it is inlined with its intrinsics.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub unsafe fn elastic(geo: &Four, vel: &[[f64; 3]], cs: &[Contact; LANES], k: &ContactClass, dt_s: f64) -> Option<Group> {
    use std::arch::x86_64::*;
    // SAFETY: AVX is there (the caller's contract); the rest is arithmetic and bounds-checked
    // indexing.
    unsafe {
        let g = kinematics(geo, vel, cs, k);
        let b = elastic_branch(&g, cs, k, dt_s);
        // Every lane's sign bit set (`vtestpd`: one instruction, where the movemask's compare
        // took five).
        if _mm256_testc_pd(b.elastic, _mm256_castsi256_pd(_mm256_set1_epi64x(-1))) == 0 {
            return None;
        }
        Some(Group { force: force(&g, b.f_n, b.f_t, _mm256_castsi256_pd(_mm256_set1_epi64x(-1))), ut_m: out(b.ut_m) })
    }
}

/// The bond law's elastic branch on four lanes (`law::bonded`, `normal::bonded`,
/// `tangential::capped_spring`, `failure::breaks`, no optional part).
#[cfg(target_arch = "x86_64")]
pub(crate) struct Branch4 {
    /// Normal force Kn (d − d0 − δ_p), N (tension positive).
    pub f_n: std::arch::x86_64::__m256d,
    /// Shear force Kt u_t, N.
    pub f_t: std::arch::x86_64::__m256d,
    /// The trial shear spring u_t + v_t Δt, m (a frictional pair's increment too).
    pub ut_m: std::arch::x86_64::__m256d,
    /// All bits set in the lanes where the bond stays elastic (below both plateaus, holding).
    pub elastic: std::arch::x86_64::__m256d,
}

/// [`Branch4`] of the four contacts `cs` (class `k`) at `g` over `dt_s`, taken as bonds.
///
/// # Safety
/// As [`elastic`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) unsafe fn elastic_branch(g: &Kinematics4, cs: &[Contact; LANES], k: &ContactClass, dt_s: f64) -> Branch4 {
    use std::arch::x86_64::*;
    // SAFETY: AVX (the caller's contract).
    unsafe {
        let splat = _mm256_set1_pd;
        let xi = rate::STATIC[2];
        let dp = lanes!(cs, |c| c.dp_m);
        let f_n = _mm256_mul_pd(splat(k.bond.kn_n_per_m), _mm256_sub_pd(_mm256_sub_pd(g.dist, lanes!(cs, |c| c.rest_m)), dp));
        let ut_m = _mm256_add_pd(lanes!(cs, |c| c.ut_m), _mm256_mul_pd(g.vt, splat(dt_s)));
        let f_t = _mm256_mul_pd(splat(k.bond.kt_n_per_m), ut_m);
        let below_plateau = _mm256_cmp_pd::<_CMP_LE_OQ>(f_n, splat(k.strength.normal_force_n * xi));
        let below_cap = _mm256_cmp_pd::<_CMP_LE_OQ>(_mm256_andnot_pd(splat(-0.0), f_t), splat(k.strength.shear_force_n * xi));
        let holds = _mm256_cmp_pd::<_CMP_NGT_UQ>(dp, splat(k.strength.plastic_opening_at_break_m));
        Branch4 { f_n, f_t, ut_m, elastic: _mm256_and_pd(_mm256_and_pd(below_plateau, below_cap), holds) }
    }
}

/// Geometry and relative velocity of four contacts, lane l contact l: `geometry::four` and
/// `forces::along`, operation for operation (the normal velocity is not formed: no part that
/// reads it takes the lanes).
#[cfg(target_arch = "x86_64")]
pub(crate) struct Kinematics4 {
    /// Squared centre distance, m².
    pub d2_m2: std::arch::x86_64::__m256d,
    /// Centre distance d, m.
    pub dist: std::arch::x86_64::__m256d,
    /// Unit normal from i to j.
    pub nx: std::arch::x86_64::__m256d,
    pub ny: std::arch::x86_64::__m256d,
    /// Lever arms d·r_i/(r_i + r_j) and d·r_j/(r_i + r_j), m.
    pub li: std::arch::x86_64::__m256d,
    pub lj: std::arch::x86_64::__m256d,
    /// Relative tangential velocity at the contact point, m/s.
    pub vt: std::arch::x86_64::__m256d,
}

/// [`Kinematics4`] of `cs` (all of class `k`, geometry `geo`) at half-step velocities `vel`.
///
/// # Safety
/// As [`elastic`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) unsafe fn kinematics(geo: &Four, vel: &[[f64; 3]], cs: &[Contact; LANES], k: &ContactClass) -> Kinematics4 {
    use std::arch::x86_64::*;
    // SAFETY: AVX is there (the caller's contract); the rest is arithmetic and bounds-checked
    // indexing.
    unsafe {
        let (vi, vj) = (|c: &Contact| vel[c.i as usize], |c: &Contact| vel[c.j as usize]);
        let splat = _mm256_set1_pd;
        let Four { d2_m2, d_m: dist, nx, ny } = *geo;
        let (vxi, vyi) = xy(vel, cs.map(|c| c.i as usize));
        let (vxj, vyj) = xy(vel, cs.map(|c| c.j as usize));
        let (dvx, dvy) = (_mm256_sub_pd(vxj, vxi), _mm256_sub_pd(vyj, vyi));
        let li = _mm256_mul_pd(dist, splat(k.lever_i));
        let lj = _mm256_mul_pd(dist, splat(k.lever_j));
        // −dvx·ny + dvy·nx − li·ωi − lj·ωj, left to right.
        let neg_dvx = _mm256_xor_pd(dvx, splat(-0.0));
        let vt = _mm256_sub_pd(
            _mm256_sub_pd(_mm256_add_pd(_mm256_mul_pd(neg_dvx, ny), _mm256_mul_pd(dvy, nx)), _mm256_mul_pd(li, lanes!(cs, |c| vi(c)[2]))),
            _mm256_mul_pd(lj, lanes!(cs, |c| vj(c)[2])),
        );
        Kinematics4 { d2_m2, dist, nx, ny, li, lj, vt }
    }
}

/// The four lanes of `v`, lane l at index l.
///
/// # Safety
/// As [`elastic`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) unsafe fn out(v: std::arch::x86_64::__m256d) -> [f64; LANES] {
    let mut a = [0.0; LANES];
    // SAFETY: AVX (the caller's contract); `a` holds four f64.
    unsafe { std::arch::x86_64::_mm256_storeu_pd(a.as_mut_ptr(), v) };
    a
}

/// `law::force` on four lanes: the forces of normal force `f_n` and shear force `f_t` (N) at
/// `g`, lane by lane, and +0 in the lanes outside `keep` (all bits set: keep).
///
/// # Safety
/// As [`elastic`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) unsafe fn force(g: &Kinematics4, f_n: std::arch::x86_64::__m256d, f_t: std::arch::x86_64::__m256d, keep: std::arch::x86_64::__m256d) -> [ContactForce; LANES] {
    use std::arch::x86_64::*;
    // SAFETY: AVX (the caller's contract).
    unsafe {
        let fx = _mm256_and_pd(keep, _mm256_sub_pd(_mm256_mul_pd(f_n, g.nx), _mm256_mul_pd(f_t, g.ny)));
        let fy = _mm256_and_pd(keep, _mm256_add_pd(_mm256_mul_pd(f_n, g.ny), _mm256_mul_pd(f_t, g.nx)));
        let ti = _mm256_and_pd(keep, _mm256_mul_pd(g.li, f_t));
        let tj = _mm256_and_pd(keep, _mm256_mul_pd(g.lj, f_t));
        let (fx, fy, ti, tj) = (out(fx), out(fy), out(ti), out(tj));
        std::array::from_fn(|l| ContactForce { fx: fx[l], fy: fy[l], ti: ti[l], tj: tj[l] })
    }
}
