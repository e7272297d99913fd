//! The one place that knows SIMD. The laws and the integrator update are written once, generic
//! over [`Real`]: `f64` is one contact or element at a time, a four-lane type four at a time
//! (as LAMMPS's granular kernel header and rapier's `SimdReal` do). Each lane runs the scalar
//! operations in their order — IEEE add, subtract, multiply, divide and square root are exact
//! per lane, nothing is fused into a multiply–add, and `min`, `abs`, `copysign` and the
//! comparisons are the same selections — so a lane's bits are the scalar bits.
//!
//! Two four-lane types: AVX's (`avx`, the only code here with `unsafe` and intrinsics), taken
//! when the processor has AVX, and a portable `[f64; 4]` ([`Portable`]) otherwise; the tests run
//! both against the scalar path on any machine that has them. A kernel that runs on lanes is a
//! [`Task`], started by [`run`] with the widest type the processor has: the AVX one is only
//! ever named inside this module, and only given to a task once AVX is found, which is what
//! makes its safe methods sound.
//!
//! No crate: `wide` picks its backend when it is compiled (`cfg(target_feature)`), so a build
//! for baseline x86-64 gets SSE2 pairs, not AVX, unless a second binary is shipped; `pulp`
//! dispatches at run time as [`run`] does, but its vector width follows the processor's level
//! (its x86 levels ask AVX2 and FMA for four f64 lanes and give eight on AVX-512), where the
//! contact groups here are four contacts on anything with AVX, and the bits must not depend on
//! the level; `std::simd` is not stable. The trait and the two types here are some 700 lines,
//! most of them one-line methods.

#[cfg(target_arch = "x86_64")]
mod avx;
mod portable;

use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

pub use portable::Portable;

/// A real number of the laws: one `f64`, or several in lanes.
pub trait Real: Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self> + Neg<Output = Self> {
    /// A truth value per lane.
    type Mask: Mask;
    /// Numbers held.
    const LANES: usize;
    /// `x` in every lane.
    fn splat(x: f64) -> Self;
    /// √x (IEEE, correctly rounded).
    fn sqrt(self) -> Self;
    /// |x|.
    fn abs(self) -> Self;
    /// `f64::min(self, o)` with this operand order: `self < o ? self : o`, so `o` where either is
    /// NaN (x86's `minpd`; the same as `f64::min` whenever `o` is not NaN).
    fn min(self, o: Self) -> Self;
    /// The magnitude of `self` with the sign of `sign`.
    fn copysign(self, sign: Self) -> Self;
    /// `self <= o` (false on NaN).
    fn le(self, o: Self) -> Self::Mask;
    /// `self >= o` (false on NaN).
    fn ge(self, o: Self) -> Self::Mask;
    /// `self > o` (false on NaN).
    fn gt(self, o: Self) -> Self::Mask;
    /// `self == o` (false on NaN).
    fn eq(self, o: Self) -> Self::Mask;
    /// `self != o` (true on NaN).
    fn ne(self, o: Self) -> Self::Mask;
    /// `a` where `m`, else `b`.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;
    /// `self` where `m`, else +0.
    fn keep(self, m: Self::Mask) -> Self;
    /// `LANES` consecutive numbers from the front of `a`.
    fn load(a: &[f64]) -> Self;
    /// The lanes into the front of `a`.
    fn store(self, a: &mut [f64]);
    /// `LANES` rows `[x, y, θ]` held as three values of their components in order (for four:
    /// `[x0 y0 θ0 x1]`, `[y1 θ1 x2 y2]`, `[θ2 x3 y3 θ3]`) put into lanes: (x, y, θ), lane l row l.
    fn columns(a: Self, b: Self, c: Self) -> (Self, Self, Self);
    /// The rows `[x, y]` at the front of `a` in lanes: (x, y), lane l row l.
    fn rows_xy(a: &[[f64; 2]]) -> (Self, Self);
    /// +0.
    #[inline(always)]
    fn zero() -> Self {
        Self::splat(0.0)
    }
}

/// A truth value per lane.
pub trait Mask: Copy + BitAnd<Output = Self> + BitOr<Output = Self> + Not<Output = Self> {
    /// True in every lane.
    fn all(self) -> bool;
    /// True in some lane.
    fn any(self) -> bool;
    /// True in every lane where `m` is.
    #[inline(always)]
    fn all_where(self, m: Self) -> bool {
        (self | !m).all()
    }
    /// `keep` where the mask holds, `other()` elsewhere; `other` is computed only when some lane
    /// needs it (for one `f64`: an `if`), so a law keeps its cheap branch cheap.
    #[inline(always)]
    fn when<T: Select<Self>>(self, keep: T, other: impl FnOnce() -> T) -> T {
        if self.all() { keep } else { T::select(self, keep, other()) }
    }
    /// As [`Mask::when`] for an `other` so cheap that lanes compute it always (no test; for one
    /// `f64` still an `if`).
    #[inline(always)]
    fn blend<T: Select<Self>>(self, keep: T, other: impl FnOnce() -> T) -> T {
        T::select(self, keep, other())
    }
}

/// Values that can be chosen lane by lane.
pub trait Select<M>: Sized {
    /// `a` where `m`, else `b`.
    fn select(m: M, a: Self, b: Self) -> Self;
}

impl<R: Real> Select<R::Mask> for R {
    #[inline(always)]
    fn select(m: R::Mask, a: R, b: R) -> R {
        <R as Real>::select(m, a, b)
    }
}

impl<M: Copy, A: Select<M>, B: Select<M>> Select<M> for (A, B) {
    #[inline(always)]
    fn select(m: M, a: Self, b: Self) -> Self {
        (A::select(m, a.0, b.0), B::select(m, a.1, b.1))
    }
}

impl<M: Copy, A: Select<M>, B: Select<M>, C: Select<M>> Select<M> for (A, B, C) {
    #[inline(always)]
    fn select(m: M, a: Self, b: Self) -> Self {
        (A::select(m, a.0, b.0), B::select(m, a.1, b.1), C::select(m, a.2, b.2))
    }
}

/// Four lanes, with what a group of four contacts needs besides arithmetic.
pub trait Lanes: Real {
    /// Lane l is `f(l)`.
    fn gather(f: impl Fn(usize) -> f64) -> Self;
    /// The first two components of rows of `a`, lane l from row `row(l)`: (x, y).
    fn xy(a: &[[f64; 3]], row: impl Fn(usize) -> usize) -> (Self, Self);
    /// Lane l true where `f(l)`.
    fn mask(f: impl Fn(usize) -> bool) -> Self::Mask;
    /// The lanes, lane l at index l.
    fn to_array(self) -> [f64; 4];
}

impl Mask for bool {
    #[inline(always)]
    fn all(self) -> bool {
        self
    }
    #[inline(always)]
    fn any(self) -> bool {
        self
    }
    #[inline(always)]
    fn when<T: Select<Self>>(self, keep: T, other: impl FnOnce() -> T) -> T {
        if self { keep } else { other() }
    }
    #[inline(always)]
    fn blend<T: Select<Self>>(self, keep: T, other: impl FnOnce() -> T) -> T {
        if self { keep } else { other() }
    }
}

impl Real for f64 {
    type Mask = bool;
    const LANES: usize = 1;
    #[inline(always)]
    fn splat(x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn abs(self) -> f64 {
        f64::abs(self)
    }
    #[inline(always)]
    fn min(self, o: f64) -> f64 {
        f64::min(self, o)
    }
    #[inline(always)]
    fn copysign(self, sign: f64) -> f64 {
        f64::copysign(self, sign)
    }
    #[inline(always)]
    fn le(self, o: f64) -> bool {
        self <= o
    }
    #[inline(always)]
    fn ge(self, o: f64) -> bool {
        self >= o
    }
    #[inline(always)]
    fn gt(self, o: f64) -> bool {
        self > o
    }
    #[inline(always)]
    fn eq(self, o: f64) -> bool {
        self == o
    }
    #[inline(always)]
    fn ne(self, o: f64) -> bool {
        self != o
    }
    #[inline(always)]
    fn select(m: bool, a: f64, b: f64) -> f64 {
        if m { a } else { b }
    }
    #[inline(always)]
    fn keep(self, m: bool) -> f64 {
        if m { self } else { 0.0 }
    }
    #[inline(always)]
    fn load(a: &[f64]) -> f64 {
        a[0]
    }
    #[inline(always)]
    fn store(self, a: &mut [f64]) {
        a[0] = self;
    }
    #[inline(always)]
    fn columns(a: f64, b: f64, c: f64) -> (f64, f64, f64) {
        (a, b, c)
    }
    #[inline(always)]
    fn rows_xy(a: &[[f64; 2]]) -> (f64, f64) {
        (a[0][0], a[0][1])
    }
}

/// A kernel that runs on some four-lane type.
pub trait Task {
    /// What it returns.
    type Output;
    /// Run on lanes `L`. Mark it `#[inline(always)]`: it is compiled into the caller that
    /// [`run`] picks (for AVX, a function compiled for AVX), and so is everything it inlines.
    fn run<L: Lanes>(self) -> Self::Output;
}

/// A four-lane type, as a value to choose by.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Width {
    /// [`Portable`]: `[f64; 4]`, on any processor.
    Portable,
    /// AVX's `__m256d` (x86-64 with AVX).
    Avx,
}

/// True when this processor has AVX (its lanes are the ones [`run`] takes).
#[inline]
pub fn has_avx() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        avx::available()
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// The four-lane types this processor runs, narrowest first.
pub fn widths() -> Vec<Width> {
    if has_avx() { vec![Width::Portable, Width::Avx] } else { vec![Width::Portable] }
}

/// The widest lanes this processor has.
#[inline]
pub fn widest() -> Width {
    if has_avx() { Width::Avx } else { Width::Portable }
}

/// Run `t` on the widest lanes this processor has.
#[inline(always)]
pub fn run<T: Task>(t: T) -> T::Output {
    run_as(widest(), t)
}

/// Run `t` on lanes `w` (AVX only where the processor has it: else the portable ones).
#[inline(always)]
pub fn run_as<T: Task>(w: Width, t: T) -> T::Output {
    #[cfg(target_arch = "x86_64")]
    if w == Width::Avx {
        return avx::run(t);
    }
    let _ = w;
    t.run::<Portable>()
}
