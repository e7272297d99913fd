//! The AVX lanes: four f64 in a `__m256d`. The only code of the crate with `unsafe` and
//! intrinsics. [`Avx4`] is named nowhere outside the lanes module and reaches code only as the
//! type a [`Task`] runs on, after [`available`] found AVX: so its safe methods never run on a
//! processor without it. They are `#[inline(always)]` and compiled into the task's entry,
//! [`entry`], which is compiled for AVX (outside such a function an intrinsic is a call).

use std::arch::x86_64::*;
use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

use super::{Lanes, Mask, Real, Task};

/// Four f64 lanes; lane l is element l in memory order.
#[derive(Clone, Copy)]
pub struct Avx4(__m256d);

/// Four lanes' truth values: all bits set in a true lane.
#[derive(Clone, Copy)]
pub struct Mask4(__m256d);

/// True when this processor has AVX.
#[inline]
pub fn available() -> bool {
    std::arch::is_x86_feature_detected!("avx")
}

/// `t` on [`Avx4`] where the processor has AVX, else on the portable lanes.
#[inline(always)]
pub fn run<T: Task>(t: T) -> T::Output {
    if !available() {
        return t.run::<super::Portable>();
    }
    // SAFETY: the processor has AVX (just checked).
    unsafe { entry(t) }
}

/// # Safety
/// The processor must have AVX.
#[target_feature(enable = "avx")]
unsafe fn entry<T: Task>(t: T) -> T::Output {
    t.run::<Avx4>()
}

// SAFETY (every `unsafe` block below): an `Avx4` or `Mask4` exists only in code that `entry`
// runs, so the processor has AVX; the loads and stores read and write slices whose length the
// indexing checks first.

macro_rules! binary {
    ($($tr:ident $f:ident $op:ident),*) => {$(
        impl $tr for Avx4 {
            type Output = Avx4;
            #[inline(always)]
            fn $f(self, o: Avx4) -> Avx4 {
                unsafe { Avx4($op(self.0, o.0)) }
            }
        }
    )*};
}
binary!(Add add _mm256_add_pd, Sub sub _mm256_sub_pd, Mul mul _mm256_mul_pd, Div div _mm256_div_pd);

impl Neg for Avx4 {
    type Output = Avx4;
    #[inline(always)]
    fn neg(self) -> Avx4 {
        unsafe { Avx4(_mm256_xor_pd(self.0, _mm256_set1_pd(-0.0))) }
    }
}

impl BitAnd for Mask4 {
    type Output = Mask4;
    #[inline(always)]
    fn bitand(self, o: Mask4) -> Mask4 {
        unsafe { Mask4(_mm256_and_pd(self.0, o.0)) }
    }
}

impl BitOr for Mask4 {
    type Output = Mask4;
    #[inline(always)]
    fn bitor(self, o: Mask4) -> Mask4 {
        unsafe { Mask4(_mm256_or_pd(self.0, o.0)) }
    }
}

impl Not for Mask4 {
    type Output = Mask4;
    #[inline(always)]
    fn not(self) -> Mask4 {
        unsafe { Mask4(_mm256_xor_pd(self.0, ones())) }
    }
}

/// All bits set.
#[inline(always)]
unsafe fn ones() -> __m256d {
    unsafe { _mm256_castsi256_pd(_mm256_set1_epi64x(-1)) }
}

impl Mask for Mask4 {
    #[inline(always)]
    fn all(self) -> bool {
        // Every lane's sign bit set (`vtestpd`: one instruction, where a movemask's compare
        // takes more).
        unsafe { _mm256_testc_pd(self.0, ones()) != 0 }
    }
    #[inline(always)]
    fn any(self) -> bool {
        unsafe { _mm256_testz_pd(self.0, self.0) == 0 }
    }
    #[inline(always)]
    fn all_where(self, m: Mask4) -> bool {
        // No lane of `m` without `self` (`vtestpd` of the sign bits of !self & m).
        unsafe { _mm256_testc_pd(self.0, m.0) != 0 }
    }
}

impl Real for Avx4 {
    type Mask = Mask4;
    const LANES: usize = 4;
    #[inline(always)]
    fn splat(x: f64) -> Avx4 {
        unsafe { Avx4(_mm256_set1_pd(x)) }
    }
    #[inline(always)]
    fn zero() -> Avx4 {
        unsafe { Avx4(_mm256_setzero_pd()) }
    }
    #[inline(always)]
    fn sqrt(self) -> Avx4 {
        unsafe { Avx4(_mm256_sqrt_pd(self.0)) }
    }
    #[inline(always)]
    fn abs(self) -> Avx4 {
        unsafe { Avx4(_mm256_andnot_pd(_mm256_set1_pd(-0.0), self.0)) }
    }
    #[inline(always)]
    fn min(self, o: Avx4) -> Avx4 {
        unsafe { Avx4(_mm256_min_pd(self.0, o.0)) }
    }
    #[inline(always)]
    fn copysign(self, sign: Avx4) -> Avx4 {
        unsafe {
            let s = _mm256_set1_pd(-0.0);
            Avx4(_mm256_or_pd(_mm256_andnot_pd(s, self.0), _mm256_and_pd(s, sign.0)))
        }
    }
    #[inline(always)]
    fn le(self, o: Avx4) -> Mask4 {
        unsafe { Mask4(_mm256_cmp_pd::<_CMP_LE_OQ>(self.0, o.0)) }
    }
    #[inline(always)]
    fn ge(self, o: Avx4) -> Mask4 {
        unsafe { Mask4(_mm256_cmp_pd::<_CMP_GE_OQ>(self.0, o.0)) }
    }
    #[inline(always)]
    fn gt(self, o: Avx4) -> Mask4 {
        unsafe { Mask4(_mm256_cmp_pd::<_CMP_GT_OQ>(self.0, o.0)) }
    }
    #[inline(always)]
    fn eq(self, o: Avx4) -> Mask4 {
        unsafe { Mask4(_mm256_cmp_pd::<_CMP_EQ_OQ>(self.0, o.0)) }
    }
    #[inline(always)]
    fn ne(self, o: Avx4) -> Mask4 {
        unsafe { Mask4(_mm256_cmp_pd::<_CMP_NEQ_UQ>(self.0, o.0)) }
    }
    #[inline(always)]
    fn select(m: Mask4, a: Avx4, b: Avx4) -> Avx4 {
        unsafe { Avx4(_mm256_blendv_pd(b.0, a.0, m.0)) }
    }
    #[inline(always)]
    fn keep(self, m: Mask4) -> Avx4 {
        unsafe { Avx4(_mm256_and_pd(m.0, self.0)) }
    }
    #[inline(always)]
    fn load(a: &[f64]) -> Avx4 {
        let a = &a[..4];
        unsafe { Avx4(_mm256_loadu_pd(a.as_ptr())) }
    }
    #[inline(always)]
    fn store(self, a: &mut [f64]) {
        let a = &mut a[..4];
        unsafe { _mm256_storeu_pd(a.as_mut_ptr(), self.0) }
    }
    #[inline(always)]
    fn columns(a: Avx4, b: Avx4, c: Avx4) -> (Avx4, Avx4, Avx4) {
        let (a, b, c) = (a.0, b.0, c.0);
        unsafe {
            // [x0 y0 x2 y2], [θ0 x1 θ2 x3], [y1 θ1 y3 θ3]: each lane now holds its row's
            // component in one of two vectors.
            let xy = _mm256_permute2f128_pd::<0x30>(a, b);
            let tx = _mm256_permute2f128_pd::<0x21>(a, c);
            let yt = _mm256_permute2f128_pd::<0x30>(b, c);
            (Avx4(_mm256_blend_pd::<0b1010>(xy, tx)), Avx4(_mm256_shuffle_pd::<0b0101>(xy, yt)), Avx4(_mm256_blend_pd::<0b1010>(tx, yt)))
        }
    }
    #[inline(always)]
    fn rows_xy(a: &[[f64; 2]]) -> (Avx4, Avx4) {
        let a = &a[..4];
        unsafe {
            let (g01, g23) = (_mm256_loadu_pd(a[0..2].as_flattened().as_ptr()), _mm256_loadu_pd(a[2..4].as_flattened().as_ptr()));
            let (lo, hi) = (_mm256_permute2f128_pd::<0x20>(g01, g23), _mm256_permute2f128_pd::<0x31>(g01, g23));
            (Avx4(_mm256_unpacklo_pd(lo, hi)), Avx4(_mm256_unpackhi_pd(lo, hi)))
        }
    }
}

impl Lanes for Avx4 {
    #[inline(always)]
    fn gather(f: impl Fn(usize) -> f64) -> Avx4 {
        // `_mm256_set_pd` takes the highest lane first.
        unsafe { Avx4(_mm256_set_pd(f(3), f(2), f(1), f(0))) }
    }
    #[inline(always)]
    fn xy(a: &[[f64; 3]], row: impl Fn(usize) -> usize) -> (Avx4, Avx4) {
        // Each row's pair read at once (16 of its 24 bytes) and the four pairs transposed, in
        // fewer instructions than eight loads put into lanes one by one.
        unsafe {
            let pair = |l: usize| _mm_loadu_pd(a[row(l)][..2].as_ptr());
            // [x0 y0 x2 y2] and [x1 y1 x3 y3]: the lows and highs of their lanes' pairs.
            let ac = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(pair(0)), pair(2));
            let bd = _mm256_insertf128_pd::<1>(_mm256_castpd128_pd256(pair(1)), pair(3));
            (Avx4(_mm256_unpacklo_pd(ac, bd)), Avx4(_mm256_unpackhi_pd(ac, bd)))
        }
    }
    #[inline(always)]
    fn mask(f: impl Fn(usize) -> bool) -> Mask4 {
        let v = Avx4::gather(|l| f(l) as u8 as f64);
        unsafe { Mask4(_mm256_cmp_pd::<_CMP_EQ_OQ>(v.0, _mm256_set1_pd(1.0))) }
    }
    #[inline(always)]
    fn to_array(self) -> [f64; 4] {
        let mut a = [0.0; 4];
        self.store(&mut a);
        a
    }
}
