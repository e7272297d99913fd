//! Contact geometry (YADE's Ig2 stage), apart from the law: from two centres, the squared
//! distance, the distance and the unit normal, one contact at a time ([`separation`], then
//! [`of`] only where the law needs more than d²) or four at a time in AVX lanes ([`four`], each
//! lane the scalar operations in their order: bitwise the same values).

use super::contacts::Contact;

/// Lane l holds contact l of `$cs` (`_mm256_set_pd` takes the highest lane first).
#[cfg(target_arch = "x86_64")]
macro_rules! lanes {
    ($cs:expr, |$c:ident| $e:expr) => {
        std::arch::x86_64::_mm256_set_pd({ let $c = &$cs[3]; $e }, { let $c = &$cs[2]; $e }, { let $c = &$cs[1]; $e }, { let $c = &$cs[0]; $e })
    };
}
#[cfg(target_arch = "x86_64")]
pub(crate) use lanes;

/// The geometry of one contact.
#[derive(Debug, Clone, Copy)]
pub struct Geometry {
    /// Centre distance d, m.
    pub d_m: f64,
    /// Unit normal from i's centre to j's, x.
    pub nx: f64,
    /// Its y.
    pub ny: f64,
}

/// From i's centre to j's: (dx m, dy m) and the squared distance (m²), which alone tells a
/// frictional pair that is apart (the scalar loop stops there).
#[derive(Clone, Copy)]
pub struct Separation {
    /// x of j's centre less i's, m.
    pub dx_m: f64,
    /// y of j's centre less i's, m.
    pub dy_m: f64,
    /// dx² + dy², m².
    pub d2_m2: f64,
}

/// The separation of contact `c` at positions `pos` [x m, y m, θ rad].
#[inline(always)]
pub fn separation(pos: &[[f64; 3]], c: &Contact) -> Separation {
    let (pi, pj) = (pos[c.i as usize], pos[c.j as usize]);
    let (dx_m, dy_m) = (pj[0] - pi[0], pj[1] - pi[1]);
    Separation { dx_m, dy_m, d2_m2: dx_m * dx_m + dy_m * dy_m }
}

/// The geometry of a separation: d = √d², n = (dx, dy) × (1/d).
#[inline(always)]
pub fn of(s: Separation) -> Geometry {
    let d_m = s.d2_m2.sqrt();
    let inv = 1.0 / d_m;
    Geometry { d_m, nx: s.dx_m * inv, ny: s.dy_m * inv }
}

/// [`Geometry`] of four contacts with their squared distance (a frictional pair's touching
/// test), lane l contact l.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
pub struct Four {
    /// d², m².
    pub d2_m2: std::arch::x86_64::__m256d,
    /// d, m.
    pub d_m: std::arch::x86_64::__m256d,
    /// Unit normal, x.
    pub nx: std::arch::x86_64::__m256d,
    /// Unit normal, y.
    pub ny: std::arch::x86_64::__m256d,
}

/// The first two components of rows `rows` of `a` as two vectors, lane l from row `rows[l]`:
/// each row's pair read at once (16 of its 24 bytes) and the four pairs transposed, in fewer
/// instructions than eight loads put into lanes one by one (for the positions and the
/// velocities, 6.3 fewer per contact-step on the benchmark block, by cachegrind).
///
/// # Safety
/// As [`four`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) unsafe fn xy(a: &[[f64; 3]], rows: [usize; 4]) -> (std::arch::x86_64::__m256d, std::arch::x86_64::__m256d) {
    use std::arch::x86_64::*;
    // SAFETY: AVX (the caller's contract); each load reads the first two f64 of a row that the
    // bounds-checked index hands out.
    unsafe {
        let pair = |r: usize| _mm_loadu_pd(a[r].as_ptr());
        // [x0 y0 x2 y2] and [x1 y1 x3 y3]: the lows and highs of their lanes' pairs are x and y.
        let ac = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(pair(rows[0])), pair(rows[2]));
        let bd = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(pair(rows[1])), pair(rows[3]));
        (_mm256_unpacklo_pd(ac, bd), _mm256_unpackhi_pd(ac, bd))
    }
}

/// A placeholder geometry (all lanes zero), to fill a buffer before it is written.
///
/// # Safety
/// As [`four`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) unsafe fn four_zero() -> Four {
    use std::arch::x86_64::*;
    // SAFETY: AVX (the caller's contract).
    unsafe { Four { d2_m2: _mm256_setzero_pd(), d_m: _mm256_setzero_pd(), nx: _mm256_setzero_pd(), ny: _mm256_setzero_pd() } }
}

/// The geometry of the four contacts `cs` at `pos` ([`of`] in each lane).
///
/// # Safety
/// The processor must have AVX; call it from a function compiled for AVX, into which it is
/// inlined with its intrinsics.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub unsafe fn four(pos: &[[f64; 3]], cs: &[Contact; 4]) -> Four {
    use std::arch::x86_64::*;
    // SAFETY: AVX (the caller's contract); the rest is arithmetic and bounds-checked indexing.
    unsafe {
        let (xi, yi) = xy(pos, cs.map(|c| c.i as usize));
        let (xj, yj) = xy(pos, cs.map(|c| c.j as usize));
        let (dx, dy) = (_mm256_sub_pd(xj, xi), _mm256_sub_pd(yj, yi));
        let d2_m2 = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
        let d_m = _mm256_sqrt_pd(d2_m2);
        let inv = _mm256_div_pd(_mm256_set1_pd(1.0), d_m);
        Four { d2_m2, d_m, nx: _mm256_mul_pd(dx, inv), ny: _mm256_mul_pd(dy, inv) }
    }
}
